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

/// The student's switches do what they say, on every fixture at three
/// positions: a pair's relative velocity (acceleration) laid along the
/// line ⊥ its guide; a link drawn with its relative velocities ∥ its
/// radii; the stated ω in every normal component and Coriolis term; a
/// point given where the student drew it, the other links at it drawn
/// from there; and the drawings' own geometry (two arcs, the values read
/// off a plan, the answer file).
#[test]
fn the_students_switches_do_what_they_say() {
    use kurbo::Vec2;
    use student::drawing::{
        acceleration_plan, arcs, figure_points, read_value, significant, standard_mu, velocity_plan,
    };
    use student::rigid::perp;
    let near = |a: Vec2, b: Vec2, scale: f64| (a - b).hypot() <= 1e-9 * scale.max(1e-12);
    let (mut lines, mut parallels, mut givens) = (0, 0, 0);
    for case in scenes::fixtures() {
        for s in &case.solved {
            let m = Model::new(&case.json, &case.an, s);
            let vel = m.velocities(&Options::default()).unwrap();
            let acc = m
                .accelerations(&vel, &vel.omega, &Options::default())
                .unwrap();
            let sv = velocity_plan(&m, &vel).largest();
            let sa = acceleration_plan(&m, &acc).largest();
            for (k, q) in m.pairs.iter().enumerate() {
                let o = Options {
                    wrong_line: Some(k),
                    ..Options::default()
                };
                let Some(v) = m.velocities(&o) else { continue };
                let p = m.at[q.point];
                let rel = v.at(&m, q.slider, p) - v.at(&m, q.guide, p);
                assert!(
                    rel.dot(q.u).abs() <= 1e-9 * sv,
                    "{}: v_rel ∥ the guide",
                    case.name
                );
                if let Some(a) = m.accelerations(&vel, &vel.omega, &o) {
                    let rel = a.at(&m, q.slider, p) - a.at(&m, q.guide, p);
                    let w_g = if q.guide == m.frame {
                        0.0
                    } else {
                        vel.omega[q.guide]
                    };
                    let coriolis = perp(q.u * vel.v_rel[k]) * (2.0 * w_g);
                    assert!(
                        (rel - coriolis).dot(q.u).abs() <= 1e-9 * sa,
                        "{}: a_rel",
                        case.name
                    );
                }
                lines += 1;
            }
            for l in 0..m.links.len() {
                let pts = &m.links[l].points;
                if l == m.frame || pts.len() < 2 {
                    continue;
                }
                let o = Options {
                    parallel: Some(l),
                    ..Options::default()
                };
                if let Some(v) = m.velocities(&o) {
                    let (a, b) = (m.at[pts[0]], m.at[pts[1]]);
                    let rel = v.at(&m, l, b) - v.at(&m, l, a);
                    assert!(
                        rel.cross(b - a).abs() <= 1e-9 * sv * (b - a).hypot(),
                        "{}: ∥",
                        case.name
                    );
                    parallels += 1;
                }
            }
            // A stated ω: every normal component −ω²·r with it.
            let stated: Vec<f64> = vel.omega.iter().map(|w| 1.7 * w + 0.3).collect();
            if let Some(a) = m.accelerations(&vel, &stated, &Options::default()) {
                for (l, w) in stated.iter().enumerate() {
                    let pts = &m.links[l].points;
                    if l == m.frame || pts.len() < 2 {
                        continue;
                    }
                    let (p, q) = (m.at[pts[0]], m.at[pts[1]]);
                    let r = q - p;
                    let rel = a.at(&m, l, q) - a.at(&m, l, p);
                    let normal = -rel.dot(r) / r.hypot();
                    let want = w * w * r.hypot();
                    assert!(
                        (normal - want).abs() <= 1e-9 * (sa + want),
                        "{}: ω stated",
                        case.name
                    );
                }
            }
            // A point given where the student drew it: the links that take
            // it from there have it there; the plan stays solvable.
            for (x, l, ..) in figure_points(&m) {
                let at = Vec2::new(0.123, -0.456) * sv;
                let o = Options {
                    given: vec![(x, l, at)],
                    ..Options::default()
                };
                let v = m.velocities(&o).unwrap();
                for j in 0..m.links.len() {
                    if j != l && j != m.frame && m.links[j].points.contains(&x) {
                        assert!(near(v.at(&m, j, m.at[x]), at, sv), "{}: given", case.name);
                        givens += 1;
                    }
                }
                assert!(near(v.at(&m, l, m.at[x]), vel.at(&m, l, m.at[x]), sv));
            }
        }
    }
    assert!(
        lines >= 20 && parallels >= 20 && givens >= 5,
        "{lines} {parallels} {givens}"
    );
    // Two arcs: the crossing at the two radii, on the side asked.
    let (a, b) = (Vec2::new(1.0, 2.0), Vec2::new(11.0, 2.0));
    let x = arcs(a, 6.0, b, 7.0, 1.0).unwrap();
    assert!(((x - a).hypot() - 6.0).abs() < 1e-12 && ((x - b).hypot() - 7.0).abs() < 1e-12);
    assert!((b - a).cross(x - a) > 0.0);
    assert!((b - a).cross(arcs(a, 6.0, b, 7.0, -1.0).unwrap() - a) < 0.0);
    assert!(arcs(a, 3.0, b, 3.0, 1.0).is_none());
    // What a student writes.
    assert_eq!(significant(-3.40449, 3), -3.4);
    assert_eq!(significant(1234.5, 3), 1230.0);
    assert_eq!(read_value(103.523, 0.2), 103.52);
    assert_eq!(read_value(0.9971, 0.01), 0.997);
    assert_eq!(standard_mu(1.2), 0.01);
    assert_eq!(standard_mu(1.21), 0.02);
    assert_eq!(standard_mu(0.3), 0.0025);
}

/// An answer written by the generator reads back as mechplan's answer
/// reader reads it: every point, value and the velocity plan's ω.
#[test]
fn the_answer_file_is_the_documented_one() {
    use kurbo::Vec2;
    use mechplan::PlanKind;
    use mechplan::check::answer::{Given, from_json};
    use student::drawing::AnswerFile;
    let a = AnswerFile {
        plan: PlanKind::Acceleration,
        position: 2,
        mu: 0.1,
        title: "six-link".into(),
        points: vec![
            ("b".into(), Vec2::new(88.09, 85.96)),
            ("s2".into(), Vec2::new(89.07, 64.72)),
        ],
        segments: vec![("p_a b".into(), 123.1)],
        angles: vec![("p_a b".into(), 44.3)],
        values: vec![("a_B".into(), 12.3), ("eps2".into(), -4.5)],
        velocity: Some((0.01, vec![("2".into(), -3.12), ("3".into(), 1.38)])),
    };
    let text = a.to_json();
    let r = from_json(&text).unwrap();
    assert_eq!(
        (r.plan, r.position, r.mu, r.delta, r.mu_v),
        (
            PlanKind::Acceleration,
            mechplan::check::position::StatedPosition::new(2),
            0.1,
            0.5,
            Some(0.01)
        )
    );
    let omegas: Vec<(String, f64, f64)> = r
        .stated
        .iter()
        .map(|s| match &s.quantity {
            mechplan::check::answer::StatedQuantity::Omega(id) => (id.clone(), s.value, s.rounding),
            q => panic!("{q:?}"),
        })
        .collect();
    assert_eq!(
        omegas,
        vec![
            ("2".to_string(), -3.12, 0.005),
            ("3".to_string(), 1.38, 0.005)
        ]
    );
    assert_eq!(r.items.len(), 6, "{text}");
    assert!(r.items.iter().any(
        |i| matches!(&i.given, Given::Point { name, at } if name == "s2" && *at == [89.07, 64.72])
            && (i.rounding - 0.005f64.hypot(0.005)).abs() < 1e-12
    ));
    assert!(
        r.items
            .iter()
            .any(|i| matches!(&i.given, Given::Value { value, .. } if *value == -4.5))
    );
}
