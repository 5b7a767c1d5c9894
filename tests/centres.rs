//! Instant centres by Kennedy's theorem (positions only) against the
//! velocities of route (a) and of the velocity plan: for every fixture over
//! its sweep, every solved link j with ω_j ≠ 0 and every point M of it,
//! v_M = ω_j × (M − P_0j) (so |v_M| = |ω_j|·|MP_0j| and v_M ⊥ MP_0j); every
//! relative centre P_ij has one velocity as a point of link i and of link j;
//! the absolute centres equal M + k×v_M/ω_j.

mod common;
use common::*;
use kurbo::{Point, Vec2};
use mechplan::analytic::Motion;
use mechplan::centres::{self, Place};

fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// Velocity of the material point of a link at world point `p`.
fn vel(mo: &Motion, p: Point) -> Vec2 {
    mo.velocity(p)
}

#[test]
fn instant_centres_agree_with_the_velocities_on_every_fixture() {
    let mut worst = (0.0f64, String::new());
    let mut worst_plan = 0.0f64;
    let mut counted = (0usize, 0usize, 0usize);
    let mut undetermined = Vec::new();
    let mut positions = 0;
    for name in FIXTURES {
        let v = fixture(name);
        let (an, solved) = solve(scene_with(v.clone(), sweep(name, &v)));
        let m = &an.mech;
        let frame = m.frame();
        for s in &solved {
            positions += 1;
            let cs = centres::find(&an, &s.config);
            let n = cs.links.len();
            assert_eq!(
                cs.found.len() + cs.undetermined.len(),
                n * (n - 1) / 2,
                "{name}: every pair found or said undetermined"
            );
            if !cs.undetermined.is_empty() {
                // Kennedy's lines coincide: a special position (the shaper
                // with crank and rocker on one line).
                undetermined.push(format!("{name} at {:.1}°", s.q.to_degrees()));
            }
            // The scale of velocities at this position.
            let mut vs = f64::MIN_POSITIVE;
            for &l in &cs.links {
                let mo = s.motion[l].unwrap();
                vs = vs.max(mo.omega.abs() * m.size);
                for &p in &m.links[l].points {
                    vs = vs.max(vel(&mo, s.config.point(m, l, p)).hypot());
                }
            }
            let mut note = |d: f64, what: String| {
                if d > worst.0 {
                    worst = (d, what);
                }
            };
            for c in &cs.found {
                let (i, j) = c.links;
                let (mi, mj) = (s.motion[i].unwrap(), s.motion[j].unwrap());
                match c.place {
                    Place::At(p) => {
                        // One velocity as a point of either link.
                        let d = (vel(&mi, p) - vel(&mj, p)).hypot() / vs;
                        note(d, format!("{name} at {}: v of P{i}{j}", s.q));
                        counted.0 += 1;
                    }
                    Place::Infinity(dir) => {
                        // A relative translation perpendicular to `dir`.
                        let dw = (mi.omega - mj.omega).abs() * m.size / vs;
                        let o = s.config.point(m, j, m.links[j].points[0]);
                        let rel = vel(&mj, o) - vel(&mi, o);
                        let d = dw.max(rel.dot(dir).abs() / vs);
                        note(d, format!("{name} at {}: translation P{i}{j}", s.q));
                        counted.1 += 1;
                    }
                }
                // Absolute centres: every point's velocity from the centre.
                let l = match (i == frame, j == frame) {
                    (true, _) => j,
                    (_, true) => i,
                    _ => continue,
                };
                let mo = s.motion[l].unwrap();
                if let Place::At(p) = c.place {
                    for &q in &m.links[l].points {
                        let at = s.config.point(m, l, q);
                        let want = perp(at - p) * mo.omega;
                        let d = (vel(&mo, at) - want).hypot() / vs;
                        note(
                            d,
                            format!("{name} at {}: v of {} from P0{l}", s.q, m.point_name(q)),
                        );
                        counted.2 += 1;
                        // The velocity plan (segment × μ) gives the same.
                        let plan = &s.plans.as_ref().unwrap().velocity;
                        if let Some(got) = plan.value_of(q)
                            && an.carrier(q) == l
                        {
                            worst_plan = worst_plan.max((got - want).hypot() / vs);
                        }
                    }
                    if mo.omega.abs() * m.size > 1e-6 * vs {
                        // The analytic centre M + k×v/ω, from any point.
                        let at = s.config.point(m, l, m.links[l].points[0]);
                        let pc = at + perp(vel(&mo, at)) / mo.omega;
                        note(
                            (pc - p).hypot() * mo.omega.abs() / vs,
                            format!("{name}: P0{l}"),
                        );
                    }
                }
            }
        }
    }
    eprintln!(
        "instant centres: worst relative discrepancy {:.1e} ({}), velocity plan {:.1e}; {} finite centres, {} at infinity, {} absolute-centre velocities",
        worst.0, worst.1, worst_plan, counted.0, counted.1, counted.2
    );
    eprintln!("{positions} positions; with a centre Kennedy cannot place: {undetermined:?}");
    assert!(undetermined.len() * 100 <= positions, "{undetermined:?}");
    assert!(worst.0 <= 1e-9, "{}: {:e}", worst.1, worst.0);
    assert!(worst_plan <= 1e-9, "plan: {worst_plan:e}");
    assert!(counted.0 > 1000 && counted.1 > 100 && counted.2 > 1000);
}

/// A parallelogram four-bar (crank = rocker, coupler = frame): the coupler
/// translates, so Kennedy's lines for P02 are parallel and the centre is at
/// infinity, perpendicular to the common velocity; ω2 = 0. With the rocker
/// longer by 1e-9 the lines meet very far away (the sine of their angle
/// about 1e-9), and the velocities from that far centre still agree.
#[test]
fn a_translating_coupler_has_its_centre_at_infinity() {
    for (rocker, infinite) in [(0.1, true), (0.1 * (1.0 + 1e-9), false)] {
        let a = Point::new(0.1 * 0.5, 0.1 * 3f64.sqrt() / 2.0);
        let scene = serde_json::json!({
            "mechplan": 1,
            "title": "Parallelogram four-bar",
            "units": { "length": "m", "angle": "deg" },
            "points": {
                "O1": [0, 0], "A": [a.x, a.y], "B": [a.x + 0.4, a.y], "O3": [0.4, 0]
            },
            "links": {
                "0": { "points": ["O1", "O3"] },
                "1": { "points": ["O1", "A"] },
                "2": { "points": ["A", "B"] },
                "3": { "points": ["O3", "B"] }
            },
            "lengths": { "O1-A": 0.1, "A-B": 0.4, "O3-B": rocker },
            "input": { "link": "1", "pivot": "O1", "angle": 60, "omega": 10, "epsilon": 0 },
            "positions": { "angles": [60] }
        });
        let (an, solved) = solve(mechplan::Scene::from_json(&scene.to_string()).unwrap());
        let s = &solved[0];
        let cs = centres::find(&an, &s.config);
        assert!(cs.undetermined.is_empty(), "{:?}", cs.undetermined);
        let c = cs.get(0, 2).unwrap();
        let mo = s.motion[2].unwrap();
        let at_a = s
            .config
            .point(&an.mech, 2, an.mech.scene.point_index("A").unwrap());
        let va = mo.velocity(at_a);
        match (c.place, infinite) {
            (Place::Infinity(dir), true) => {
                assert!(mo.omega.abs() < 1e-12, "ω2 = {}", mo.omega);
                // At infinity perpendicular to the translation.
                assert!(dir.dot(va).abs() < 1e-12 * va.hypot(), "{dir:?} vs {va:?}");
            }
            (Place::At(p), false) => {
                assert!(c.sin_angle < 1e-8, "sin {:e}", c.sin_angle);
                assert!((p - at_a).hypot() > 1e6, "{p:?}");
                let want = perp(at_a - p) * mo.omega;
                // ω2 is a small difference (about 1e-9 of ω1): its own
                // rounding, δω ≈ 16ε·|v_A|/AB, is a relative error of
                // δω/|ω2| in the far centre's velocities.
                let d_omega = 16.0 * f64::EPSILON * va.hypot() / 0.4;
                assert!(
                    (va - want).hypot() < (1e-6 + d_omega / mo.omega.abs()) * va.hypot(),
                    "{va:?} vs {want:?} (ω2 = {:e})",
                    mo.omega
                );
            }
            other => panic!("rocker {rocker}: {other:?}"),
        }
    }
}

/// The command: JSON with every pair named P_ij, and a clear refusal of a
/// position the scene does not have.
#[test]
fn centres_command_prints_every_pair_and_refuses_a_missing_position() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let scene = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let out = std::process::Command::new(exe)
        .args(["centres", &scene, "--position", "2", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let c = &v["positions"][0]["centres"];
    for k in ["P01", "P02", "P03", "P12", "P13", "P23"] {
        assert!(c[k].is_object(), "{k} in {c}");
    }
    assert_eq!(c["P12"]["how"], "revolute pair A");
    let out = std::process::Command::new(exe)
        .args(["centres", &scene, "--position", "99"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--position"));
}
