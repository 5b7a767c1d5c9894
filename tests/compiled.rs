//! Route (a) compiled per mechanism (`mechplan::compiled`) against the
//! interpreted route (`PositionSolver` + `contour::solve`): the same
//! numbers to the bit — every pose and every motion, compared by the
//! shortest text that round-trips each f64 — and the same errors, on every
//! fixture and every stress scene, over their own positions and over a
//! full turn (a slider's whole range), with accelerations, with velocities
//! only, and at unit input rate (the transfer functions).

use mechplan::analytic::{Coords, Drives, Order, contour};
use mechplan::compiled::Program;
use mechplan::positions::PositionSolver;
use mechplan::scene::InputSpec;
use mechplan::{Analysis, Scene};
use std::path::{Path, PathBuf};

fn scenes() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures");
    let mut v = Vec::new();
    for dir in [root.clone(), root.join("stress")] {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|e| e == "json") {
                v.push(p);
            }
        }
    }
    v.sort();
    v
}

/// The scene's own positions, then a full turn of every crank at 1° (a
/// slider over its positions' range and as far again each way, in 360
/// steps), the inputs moving together.
fn sweeps(an: &Analysis) -> Vec<Coords> {
    let own = an.input_coords().unwrap_or_default();
    let m = &an.mech;
    let w = m.scene.input_count();
    let start: Vec<f64> = match own.first() {
        Some(q) => q.to_vec(),
        None => vec![0.0; w],
    };
    let ranges: Vec<f64> = m
        .scene
        .inputs()
        .enumerate()
        .map(|(i, spec)| match spec {
            InputSpec::Crank { .. } => std::f64::consts::TAU,
            InputSpec::Slider { .. } => {
                let (lo, hi) = own
                    .iter()
                    .map(|q| q[i])
                    .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
                let span = if hi > lo { hi - lo } else { 0.1 * m.size };
                3.0 * span
            }
        })
        .collect();
    let turn = (0..=360).map(|k| {
        let q: Vec<f64> = start
            .iter()
            .zip(&ranges)
            .enumerate()
            .map(|(i, (&q0, &r))| match m.scene.input_at(i) {
                InputSpec::Crank { .. } => q0 + r * k as f64 / 360.0,
                InputSpec::Slider { .. } => q0 - r / 3.0 + r * k as f64 / 360.0,
            })
            .collect();
        Coords::new(&q)
    });
    own.iter().copied().chain(turn).collect()
}

fn w_one(an: &Analysis) -> bool {
    an.mech.scene.input_count() == 1
}

#[test]
fn compiled_route_gives_the_interpreted_numbers_to_the_bit() {
    let (mut positions, mut failures, mut files) = (0usize, 0usize, 0usize);
    for path in scenes() {
        let text = std::fs::read_to_string(&path).unwrap();
        let Ok(scene) = Scene::from_json(&text) else {
            continue;
        };
        let Ok(an) = Analysis::new(scene) else {
            continue;
        };
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let m = &an.mech;
        let ps = PositionSolver::new(m, &an.structure, an.need.clone());
        let prog = Program::new(m, &an.structure, &an.need);
        let (mut ps, prog) = match (ps, prog) {
            (Ok(ps), Ok(prog)) => (ps, prog),
            (Err(a), Err(b)) => {
                assert_eq!(a.to_string(), b.to_string(), "{name}");
                continue;
            }
            (a, b) => panic!("{name}: {:?} vs {:?}", a.err(), b.err()),
        };
        files += 1;
        let mut st = prog.state();
        // `solve_one` on its own state, for a single input.
        let mut one = (w_one(&an)).then(|| prog.state());
        let rates: Vec<(f64, f64)> = m.scene.inputs().map(|i| i.rates()).collect();
        for q in sweeps(&an) {
            let here = format!("{name} at {:?}", &*q);
            let c = ps.solve_coords(q);
            let d = prog.positions_coords(&mut st, q);
            let c = match (c, d) {
                (Ok(c), Ok(())) => c,
                (Err(a), Err(b)) => {
                    assert_eq!(a.to_string(), b.to_string(), "{here}");
                    failures += 1;
                    continue;
                }
                (a, b) => panic!("{here}: {:?} vs {:?}", a.err(), b.err()),
            };
            assert_eq!(
                format!("{:?}", c.poses),
                format!("{:?}", st.config.poses),
                "{here}: poses"
            );
            positions += 1;
            let drives = Drives::at(&q, &rates);
            if let Some(one) = one.as_mut() {
                let r = prog.solve_one(one, drives.first(), Order::Acceleration);
                let s = prog.rates(&mut st, drives, Order::Acceleration);
                match (r, s) {
                    (Ok(()), Ok(())) => {
                        assert_eq!(
                            format!("{:?}{:?}", one.config.poses, one.motion),
                            format!("{:?}{:?}", st.config.poses, st.motion),
                            "{here}: solve_one"
                        );
                    }
                    (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{here}"),
                    (a, b) => panic!("{here}: {:?} vs {:?}", a.err(), b.err()),
                }
            }
            for (d, order) in [
                (drives, Order::Acceleration),
                (drives, Order::Velocity),
                (drives.unit(0, None), Order::Acceleration),
            ] {
                let a = contour::solve(m, &an.structure, &an.need, &c, d, order);
                let b = prog.rates(&mut st, d, order);
                match (a, b) {
                    (Ok(a), Ok(())) => assert_eq!(
                        format!("{a:?}"),
                        format!("{:?}", st.motion),
                        "{here}: motions ({order:?})"
                    ),
                    (Err(a), Err(b)) => {
                        assert_eq!(a.to_string(), b.to_string(), "{here}");
                        failures += 1;
                    }
                    (a, b) => panic!("{here}: {:?} vs {:?}", a.err(), b.err()),
                }
            }
        }
    }
    eprintln!(
        "{files} scenes, {positions} positions the same to the bit, {failures} failures with the same message"
    );
    assert!(files >= 70 && positions > 20_000, "{files} {positions}");
}

/// The result of position `k` (from 0) without its wall times
/// (`crosscheck.time_s`).
fn untimed(an: &Analysis, k: usize, s: &mechplan::Solved) -> serde_json::Value {
    let mut v = mechplan::report::position_json(an, k, s);
    if let Some(c) = v.get_mut("crosscheck").and_then(|c| c.as_object_mut()) {
        c.remove("time_s");
    }
    v
}

/// Every position's result of `an` as it runs (route (a) compiled) and as
/// its reference twin runs (route (a) interpreted), or the same error.
fn same_run(name: &str, an: &mut Analysis) -> usize {
    an.reference = true;
    let old = an.run();
    an.reference = false;
    let new = an.run();
    match (old, new) {
        (Ok(a), Ok(b)) => {
            assert_eq!(a.len(), b.len(), "{name}");
            for (k, (a, b)) in a.iter().zip(&b).enumerate() {
                assert_eq!(
                    untimed(an, k, a).to_string(),
                    untimed(an, k, b).to_string(),
                    "{name}, position {}",
                    an.numbering.number(k)
                );
            }
            a.len()
        }
        (Err(a), Err(b)) => {
            assert_eq!(a.to_string(), b.to_string(), "{name}");
            0
        }
        (a, b) => panic!("{name}: {:?} vs {:?}", a.err(), b.err()),
    }
}

/// Issue 24: `solve` runs route (a) compiled: the whole result of every
/// fixture and stress scene, on the fast path (no plans; its own
/// positions and 360) and on the full path, is its reference twin's (route (a) interpreted) to the bit, the
/// errors too.
#[test]
fn the_analysis_runs_the_compiled_route_with_the_reference_results() {
    let (mut runs, mut positions) = (0usize, 0usize);
    for path in scenes() {
        let text = std::fs::read_to_string(&path).unwrap();
        let Ok(v) = serde_json::from_str::<serde_json::Value>(&text) else {
            continue;
        };
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let mut fast = v.clone();
        if let Some(want) = fast.get_mut("want").and_then(|w| w.as_object_mut()) {
            let rates = want
                .get("plans")
                .cloned()
                .unwrap_or(serde_json::json!(["velocity", "acceleration"]));
            want.insert("rates".into(), rates);
            want.insert("plans".into(), serde_json::json!([]));
        } else if let Some(o) = fast.as_object_mut() {
            o.insert(
                "want".into(),
                serde_json::json!({ "plans": [], "rates": ["velocity", "acceleration"] }),
            );
        }
        // And the fast path over a sweep of 360 positions, where route
        // (a) finds the positions in order (class III groups tracked).
        let mut sweep = fast.clone();
        sweep["positions"] = serde_json::json!({ "count": 360 });
        for (path, v) in [("full", v), ("fast", fast), ("fast, 360", sweep)] {
            let Ok(scene) = Scene::from_json(&v.to_string()) else {
                continue;
            };
            let Ok(mut an) = Analysis::new(scene) else {
                continue;
            };
            runs += 1;
            positions += same_run(&format!("{name} ({path} path)"), &mut an);
        }
    }
    eprintln!("{runs} runs, {positions} positions the same to the bit");
    assert!(runs >= 210 && positions > 10_000, "{runs} {positions}");
}
