//! The two analytic routes agree with each other and with finite
//! differences of the positions, on every fixture at 1° steps.

mod common;
use common::*;
use mechplan::analytic::Order;
use mechplan::analytic::constraint::{ConstraintSolver, Settings};
use mechplan::scene::InputSpec;

/// Route (a) (group contours, inside `run`) against route (b) (the
/// constraint solver, driven here by the test itself) to 1e-10, relative
/// to the largest magnitude of each kind at the position.
#[test]
fn routes_agree_on_every_fixture_at_360_positions() {
    for name in FIXTURES {
        let v = fixture(name);
        let scene = scene_with(v.clone(), sweep(name, &v));
        let (an, solved) = solve(scene);
        let m = &an.mech;
        let (rate, rate2) = m.scene.input.rates();
        let mut cs = ConstraintSolver::new(m, &an.include, Settings::default());
        let mut worst = 0.0f64;
        for s in &solved {
            cs.solve_positions(s.q).unwrap();
            let b = cs.solve_rates(rate, rate2, Order::Acceleration).unwrap();
            let (mut vmax, mut amax) = (0.0f64, 0.0f64);
            let mut diffs = Vec::new();
            for &p in &an.points {
                let l = an.carrier(p);
                let st = s.point(&an, p);
                let (va, aa) = st.rates.unwrap();
                let mb = b[l].unwrap();
                let pb = mb.pose.apply(m.local(l, p));
                let (vb, ab) = (mb.velocity(pb), mb.acceleration(pb));
                vmax = vmax.max(va.hypot());
                amax = amax.max(aa.hypot());
                assert!(
                    (st.at - pb).hypot() <= 1e-10 * m.size,
                    "{name}: position of {}",
                    m.point_name(p)
                );
                diffs.push((
                    (va - vb).hypot(),
                    (aa - ab).hypot(),
                    m.point_name(p).to_string(),
                ));
            }
            for (l, (x, y)) in s.motion.iter().zip(&b).enumerate() {
                if let (Some(x), Some(y)) = (x, y) {
                    vmax = vmax.max(x.omega.abs() * m.size);
                    amax = amax.max(x.epsilon.abs() * m.size);
                    diffs.push((
                        (x.omega - y.omega).abs() * m.size,
                        (x.epsilon - y.epsilon).abs() * m.size,
                        format!("link {}", m.link_id(l)),
                    ));
                }
            }
            for (dv, da, what) in diffs {
                let (rv, ra) = (dv / vmax, da / amax);
                worst = worst.max(rv).max(ra);
                assert!(
                    rv <= 1e-10 && ra <= 1e-10,
                    "{name} at q = {}: {what}: v {rv:e}, a {ra:e}",
                    s.q
                );
            }
            assert!(
                s.check.as_ref().unwrap().max_rel_diff <= 1e-10,
                "{name}: built-in cross-check"
            );
        }
        eprintln!(
            "{name}: {} positions, worst relative difference {worst:.1e}",
            solved.len()
        );
    }
}

/// Transfer functions against central differences of the positions, and the
/// physical rates against the transfer functions (v = ω1·v_q,
/// a = ω1²·a_q + ε1·v_q).
#[test]
fn rates_match_finite_differences_of_positions() {
    for name in FIXTURES {
        let v = fixture(name);
        let base = scene_with(v.clone(), sweep(name, &v));
        let crank = matches!(base.input, InputSpec::Crank { .. });
        let unit = if crank {
            base.angle_unit
        } else {
            base.length_unit
        };
        let qs: Vec<f64> = match sweep(name, &v)
            .as_object()
            .unwrap()
            .values()
            .next()
            .unwrap()
        {
            serde_json::Value::Array(a) => a
                .iter()
                .step_by(17)
                .map(|x| x.as_f64().unwrap() * unit)
                .collect(),
            _ => unreachable!(),
        };
        // h1 for the first differences (truncation ~h1², rounding ~ε/h1),
        // h2 for the second (rounding ~ε/h2²).
        let (h1, h2) = if crank {
            (1e-6, 1e-4)
        } else {
            (
                1e-6 * base.length_unit.max(0.1),
                1e-4 * base.length_unit.max(0.1),
            )
        };
        for &q in &qs {
            let list: Vec<f64> = [q - h1, q, q + h1, q - h2, q + h2]
                .iter()
                .map(|x| x / unit)
                .collect();
            let key = if crank { "angles" } else { "s" };
            let (an, s) = solve(scene_with(v.clone(), serde_json::json!({ key: list })));
            let m = &an.mech;
            let (rate, rate2) = m.scene.input.rates();
            for &p in &an.points {
                let [a, b, c, a2, c2] = [0, 1, 2, 3, 4].map(|i| s[i].point(&an, p));
                let (vq, aq) = b.analogue.unwrap();
                let (vv, aa) = b.rates.unwrap();
                let d1 = (c.at - a.at) / (2.0 * h1);
                let d2 = (c2.at.to_vec2() - 2.0 * b.at.to_vec2() + a2.at.to_vec2()) / (h2 * h2);
                let scale1 = m.size.max(vq.hypot());
                let scale2 = m.size.max(aq.hypot());
                assert!(
                    (d1 - vq).hypot() <= 1e-8 * scale1,
                    "{name} {}: dp/dq {d1:?} vs v_q {vq:?}",
                    m.point_name(p)
                );
                assert!(
                    (d2 - aq).hypot() <= 1e-4 * scale2,
                    "{name} {}: d2p/dq2 {d2:?} vs a_q {aq:?}",
                    m.point_name(p)
                );
                // The physical rates are the transfer functions scaled by the input's rates.
                assert!((vv - vq * rate).hypot() <= 1e-12 * (scale1 * rate.abs()).max(1e-300));
                let a_expected = aq * (rate * rate) + vq * rate2;
                assert!(
                    (aa - a_expected).hypot()
                        <= 1e-11 * (scale2 * rate * rate + scale1 * rate2.abs()).max(1e-300)
                );
            }
            for l in 0..m.links.len() {
                if let (Some(a), Some(b), Some(c)) =
                    (s[0].motion[l], s[1].analogue[l], s[2].motion[l])
                {
                    let dth = mechplan::geom::wrap_pi(c.pose.angle - a.pose.angle) / (2.0 * h1);
                    assert!(
                        (dth - b.omega).abs() * m.size <= 1e-6 * m.size.max(b.omega.abs() * m.size),
                        "{name} link {}: dθ/dq {dth} vs φ' {}",
                        m.link_id(l),
                        b.omega
                    );
                }
            }
        }
    }
}

/// A crank that only rocks (a triple rocker: |φ| ≤ 101.07°, never near
/// 180°, where A and O3 are 0.75 m apart and the links reach 0.6 m). From
/// 100° to −100° the short way round (through 180°) does not assemble; the
/// mechanism goes back through 0°. Route (b) continues along the way the
/// mechanism assembles, so the sequence is solved, not refused, and both
/// routes agree at every position.
#[test]
fn a_rocking_crank_is_followed_the_way_it_assembles() {
    let scene = serde_json::json!({
        "mechplan": 1,
        "title": "Rocking crank: a triple rocker whose input link only rocks",
        "units": { "length": "m", "angle": "deg" },
        "points": {
            "O1": [0, 0],
            "A": [0.21650635094610968, 0.12499999999999999],
            "B": [0.4619023753811321, 0.29757111922765594],
            "O3": [0.5, 0]
        },
        "links": {
            "0": { "points": ["O1", "O3"] },
            "1": { "points": ["O1", "A"] },
            "2": { "points": ["A", "B"] },
            "3": { "points": ["O3", "B"] }
        },
        "lengths": { "O1-A": 0.25, "A-B": 0.3, "O3-B": 0.3 },
        "input": { "link": "1", "pivot": "O1", "angle": 30, "omega": 2, "epsilon": 0.5 },
        "positions": { "angles": [30, 100, -100, 0, 100, -95, 95] }
    });
    let scene = mechplan::Scene::from_json(&scene.to_string()).unwrap();
    let an = mechplan::Analysis::new(scene).unwrap();
    // The short way from 100° to −100° passes 180°, where it cannot assemble.
    let mut cs = ConstraintSolver::new(&an.mech, &an.include, Settings::default());
    cs.solve_positions(100f64.to_radians()).unwrap();
    assert!(cs.solve_positions((-100f64).to_radians()).is_err());
    let solved = an.run().unwrap();
    assert_eq!(solved.len(), 7);
    for s in &solved {
        let c = s.check.as_ref().unwrap();
        assert!(c.max_rel_diff < 1e-12, "at {}: {}", s.q, c.max_rel_diff);
    }
}
