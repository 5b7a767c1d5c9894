//! The student generator's solver (tests/student) against mechplan's
//! analytic results: on every fixture at three positions, every moving
//! link's ω and ε and every point's velocity and acceleration equal route
//! (a)'s (the `Solved` motions) to 1e-9 relative. The solver shares no
//! code with mechplan's kinematics: this proves the generator right
//! independently of the engine's construction kernel and grader.

mod student;

use student::rigid::{Model, Options};
use student::scenes;

#[test]
fn the_solver_equals_the_analytic_routes_on_every_fixture() {
    let mut compared = 0;
    for case in scenes::fixtures() {
        assert_eq!(case.solved.len(), 3, "{}", case.name);
        for (k, s) in case.solved.iter().enumerate() {
            let m = Model::new(&case.json, &case.an, s);
            let vel = m
                .velocities(&Options::default())
                .unwrap_or_else(|| panic!("{} position {}: velocities", case.name, k + 1));
            let acc = m
                .accelerations(&vel, &vel.omega, &Options::default())
                .unwrap_or_else(|| panic!("{} position {}: accelerations", case.name, k + 1));
            // Scales: the largest of each kind at this position.
            let (mut sv, mut sa, mut sw, mut se) = (0f64, 0f64, 0f64, 0f64);
            for (l, motion) in s.motion.iter().enumerate() {
                let Some(mo) = motion else { continue };
                sw = sw.max(mo.omega.abs());
                se = se.max(mo.epsilon.abs());
                for &p in &m.links[l].points {
                    sv = sv.max(mo.velocity(m.at[p]).hypot());
                    sa = sa.max(mo.acceleration(m.at[p]).hypot());
                }
            }
            // ε is on the scale of ω² (both rad/s²): where every ε is 0.
            se = se.max(sw * sw);
            let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-9 * scale.max(1e-12);
            for (l, motion) in s.motion.iter().enumerate() {
                let Some(mo) = motion else { continue };
                let what = format!("{} position {} link {}", case.name, k + 1, m.links[l].id);
                if l != m.frame {
                    assert!(
                        close(vel.omega[l], mo.omega, sw),
                        "{what}: ω {} against {}",
                        vel.omega[l],
                        mo.omega
                    );
                    assert!(
                        close(acc.epsilon[l], mo.epsilon, se),
                        "{what}: ε {} against {}",
                        acc.epsilon[l],
                        mo.epsilon
                    );
                }
                for &p in &m.links[l].points {
                    let (v, a) = (vel.at(&m, l, m.at[p]), acc.at(&m, l, m.at[p]));
                    let (ve, ae) = (mo.velocity(m.at[p]), mo.acceleration(m.at[p]));
                    assert!(
                        close(v.x, ve.x, sv) && close(v.y, ve.y, sv),
                        "{what} point {}: v {v:?} against {ve:?}",
                        m.names[p]
                    );
                    assert!(
                        close(a.x, ae.x, sa) && close(a.y, ae.y, sa),
                        "{what} point {}: a {a:?} against {ae:?}",
                        m.names[p]
                    );
                    compared += 1;
                }
            }
        }
    }
    eprintln!("{compared} points of links compared");
    assert!(compared > 200);
}
