//! Route 3, Zhukovsky's lever (docs/kinetostatics.md): on every dynamics
//! fixture at every position the lever's balancing value, drawn on the
//! kernel's velocity plan, equals the links' equilibrium's; a wrong sign
//! of one inertia force unbalances it; the worked example's printed digits.

mod common;

use mechplan::construction::Naming;
use mechplan::kinetostatics::lever::{self, Lever, Part};
use mechplan::kinetostatics::{Load, Origin, loads};
use mechplan::scene::Scene;
use mechplan::{Analysis, Solved};

const FIXTURES: [&str; 5] = [
    "worked_slider_crank",
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "arm_two_cylinders",
];

fn analysis(name: &str) -> Analysis {
    let path = format!(
        "{}/fixtures/dynamics/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    Analysis::new(Scene::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()).unwrap()
}

fn solved(an: &Analysis) -> Vec<Solved> {
    an.run().unwrap()
}

/// The lever's moment sum with the balancing force, over the largest
/// single moment: zero when the lever balances.
fn unbalance(l: &Lever) -> f64 {
    let sum: f64 = l.forces.iter().map(|f| f.moment).sum::<f64>() + l.moment_b;
    let largest = l.forces.iter().map(|f| f.moment.abs()).fold(0.0, f64::max);
    sum.abs() / largest
}

#[test]
fn lever_equals_links_equilibrium_everywhere() {
    let mut worst: f64 = 0.0;
    let mut count = 0;
    for name in FIXTURES {
        let an = analysis(name);
        for (k, s) in solved(&an).iter().enumerate() {
            let d = s.dynamics.as_ref().expect("a dynamics fixture");
            let loads = loads::loads(&an, s, k);
            let levers = lever::levers(&an, s, &loads, Naming::NumbersOnly).unwrap();
            assert_eq!(
                levers.len(),
                d.balancing.len(),
                "{name}: one lever per input"
            );
            for (l, b) in levers.iter().zip(&d.balancing) {
                // The same kind of value (a moment on a crank, a force on
                // a slider), to 1e-10 of the largest power term.
                assert_eq!(
                    std::mem::discriminant(&l.balancing),
                    std::mem::discriminant(b)
                );
                let rel = (l.value() - b.value()).abs() / l.largest;
                assert!(
                    rel < 1e-10,
                    "{name} position {k} input {}: lever {} vs {} ({rel:.1e})",
                    l.input,
                    l.value(),
                    b.value()
                );
                worst = worst.max(rel);
                // The lever, as drawn, balances: Σ moments = 0.
                assert!(unbalance(l) < 1e-12, "{name} {k}");
                // Each force's point on the lever is its velocity turned
                // (route (a)'s, at the plan's drive: the placement is
                // right), and its arm the distance of its line from the pole.
                let rates = if s.drives.len() == 1 {
                    &s.motion
                } else {
                    s.analogue_of(l.input)
                };
                for f in &l.forces {
                    if let (Part::Force, Load::Force { at, .. }) = (f.part, loads[f.load]) {
                        let v = rates[f.link].unwrap().velocity(at) / l.mu_v;
                        let turned = kurbo::Vec2::new(-v.y, v.x);
                        assert!(
                            (turned - f.at).hypot() <= 1e-9 * (1.0 + v.hypot()),
                            "{name} {k}: {turned:?} {:?}",
                            f.at
                        );
                    }
                    let h = f.at.cross(f.f).abs() / f.f.hypot();
                    assert!((h - f.arm).abs() <= 1e-12 * f.at.hypot().max(1.0));
                }
                count += 1;
            }
            // The result's own check value is the lever's.
            for (a, l) in d.lever.iter().zip(&levers) {
                assert_eq!(*a, l.value());
            }
        }
    }
    eprintln!(
        "largest lever vs links' equilibrium: {worst:.2e} of the largest term over {count} levers"
    );
    assert!(count > 50);
}

/// The check can fail: one inertia force with its sign turned (the one
/// with the largest moment on the lever) leaves the lever unbalanced at the
/// equilibrium's M_b, and the analysis's check refuses the position.
#[test]
fn wrong_sign_of_an_inertia_force_does_not_balance() {
    for name in FIXTURES {
        let an = analysis(name);
        let mut caught = 0;
        for (k, s) in solved(&an).iter().enumerate() {
            let d = s.dynamics.as_ref().unwrap();
            let loads = loads::loads(&an, s, k);
            assert!(lever::check(&an, s, &loads, &d.balancing, &[0.0; 2]).is_ok());
            let good = lever::levers(&an, s, &loads, Naming::NumbersOnly).unwrap();
            for l in &good {
                let Some(f) = l
                    .forces
                    .iter()
                    .filter(|f| f.origin == Origin::Inertia && f.part == Part::Force)
                    .max_by(|a, b| a.moment.abs().total_cmp(&b.moment.abs()))
                else {
                    continue;
                };
                // Turned, it changes the sum by 2·|moment|.
                if 2.0 * f.moment.abs() < 1e-3 * l.largest * l.arm_b / (l.value() / l.f_b).abs() {
                    continue;
                }
                let mut wrong = loads.clone();
                if let Load::Force { f: v, .. } = &mut wrong[f.load] {
                    *v = -*v;
                }
                let bad = lever::lever(&an, s, &wrong, l.input, Naming::NumbersOnly).unwrap();
                // The equilibrium's M_b does not balance the wrong lever.
                let b = d.balancing[l.input].value();
                let sum = bad.forces.iter().map(|f| f.moment).sum::<f64>()
                    + bad.moment_b * b / bad.value();
                let largest = bad
                    .forces
                    .iter()
                    .map(|f| f.moment.abs())
                    .fold(0.0, f64::max);
                assert!(sum.abs() > 1e-3 * largest, "{name} {k}: {sum} of {largest}");
                assert!(lever::check(&an, s, &wrong, &d.balancing, &[0.0; 2]).is_err());
                caught += 1;
            }
        }
        assert!(
            caught > 0,
            "{name}: no inertia force with a moment on the lever"
        );
        eprintln!("{name}: a wrong sign caught at {caught} levers");
    }
}

/// `x` printed to `d` decimals is `printed`.
fn digits(x: f64, d: usize, printed: &str) {
    assert_eq!(format!("{x:.d$}"), printed);
}

/// docs/kinetostatics.md, "Route 3": the worked slider-crank at φ1 = 90°
/// on the lever, to the digits printed there.
#[test]
fn worked_example_digits() {
    let an = analysis("worked_slider_crank");
    let s = &solved(&an)[0];
    let loads = loads::loads(&an, s, 0);
    let l = lever::lever(&an, s, &loads, 0, Naming::Full).unwrap();
    digits(l.mu_v, 1, "0.1");
    // p_v a = p_v b = p_v s2 = 100 mm, turned onto the line x = 0 below
    // the pole.
    for name in ["a", "b", "s2"] {
        let p = l.plan.point(name).unwrap();
        digits(p.at.hypot(), 2, "100.00");
    }
    digits(l.at_b.y, 2, "-100.00");
    digits(l.arm_b, 2, "100.00");
    let name = |f: &lever::LeverForce| an.mech.point_name(f.point.unwrap()).to_string();
    let row = |origin: Origin, part: Part, point: &str| {
        l.forces
            .iter()
            .find(|f| f.origin == origin && f.part == part && name(f) == point)
            .unwrap_or_else(|| panic!("{origin:?} {part:?} at {point}"))
    };
    let f_in2 = row(Origin::Inertia, Part::Force, "S2");
    digits(f_in2.arm, 2, "25.00");
    digits(f_in2.moment, 1, "-25819.9");
    let f_in3 = row(Origin::Inertia, Part::Force, "B");
    digits(f_in3.arm, 2, "100.00");
    digits(f_in3.moment, 1, "-77459.7");
    let f = row(Origin::External, Part::Force, "B");
    digits(f.arm, 2, "100.00");
    digits(f.moment, 1, "200000.0");
    // M_in2 as ±M/l_AB at a and b: 193.65 N each, the same turned point,
    // so they cancel (ω2 = 0).
    let (p, q) = (
        row(Origin::Inertia, Part::Couple { at_p: true }, "A"),
        row(Origin::Inertia, Part::Couple { at_p: false }, "B"),
    );
    digits(p.f.hypot(), 2, "193.65");
    digits((p.moment + q.moment).abs(), 6, "0.000000");
    digits(p.moment, 1, "4841.2");
    // The weights are vertical, through the pole's line: no moment.
    for point in ["S2", "B"] {
        digits(
            row(Origin::Gravity, Part::Force, point).moment.abs(),
            6,
            "0.000000",
        );
    }
    digits(l.f_b, 2, "967.20");
    digits(l.value(), 2, "96.72");
    digits(l.err, 2, "5.83");
    assert!(matches!(
        l.balancing,
        mechplan::kinetostatics::Balancing::Moment(_)
    ));
}

/// The result file's `dynamics.check.lever` is the lever's value, shaped
/// as `balancing` (one object, or a list with several inputs).
#[test]
fn result_file_carries_the_lever() {
    for name in ["worked_slider_crank", "arm_two_cylinders"] {
        let an = analysis(name);
        for (k, s) in solved(&an).iter().enumerate() {
            let p = mechplan::report::position_json(&an, k, s);
            let check = &p["dynamics"]["check"];
            let d = s.dynamics.as_ref().unwrap();
            let key = |i: usize| {
                if an.mech.scene.input_at(i).is_crank() {
                    "M"
                } else {
                    "F"
                }
            };
            if d.lever.len() == 1 {
                assert_eq!(check["lever"][key(0)].as_f64().unwrap(), d.lever[0]);
            } else {
                for (i, &v) in d.lever.iter().enumerate() {
                    assert_eq!(check["lever"][i][key(i)].as_f64().unwrap(), v);
                }
            }
        }
    }
}

/// The lever's sheet: drawn by default with `dynamics` (one per input and
/// position), never without; its caption solves Σ M_p = 0 with the numbers
/// of the worked example.
#[test]
fn lever_sheets() {
    use common::sheets;
    use mechplan::drawing::DrawOptions;
    let names = |an: &Analysis| -> Vec<String> {
        let solved = solved(an);
        sheets(an, &solved, &DrawOptions::default())
            .into_iter()
            .map(|s| s.name)
            .collect()
    };
    let an = analysis("worked_slider_crank");
    let solved_w = solved(&an);
    let all = sheets(&an, &solved_w, &DrawOptions::default());
    let lever = all
        .iter()
        .find(|s| s.name == "lever_1")
        .expect("a lever sheet");
    assert_eq!(lever.scales, vec![("mu_v", 0.1), ("mu_F", 50.0)]);
    // The caption's numbers (the SVG writes subscripts apart: the numbers
    // are whole): the worked example's ΣM = 96 720 N·mm, F_b = 967.2 N and
    // M_b = 96.72 N·m to three significant digits, as the table.
    for text in [
        "96700 N·mm",
        "(−100) mm = 0",
        "= 967 N",
        "967·0.1 = 96.7 N·m",
    ] {
        assert!(lever.svg.contains(text), "{text} not on the sheet");
    }
    let arm = names(&analysis("arm_two_cylinders"));
    assert!(arm.iter().any(|n| n == "lever_1_1") && arm.iter().any(|n| n == "lever_9_2"));
    let path = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let plain =
        Analysis::new(Scene::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()).unwrap();
    assert!(!names(&plain).iter().any(|n| n.starts_with("lever")));
}

/// `want.drawings` may name the lever only with a `dynamics` object.
#[test]
fn lever_without_dynamics_is_refused() {
    let path = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let mut scene: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    scene["want"]["drawings"] = serde_json::json!(["mechanism", "lever"]);
    let err = Scene::from_json(&scene.to_string())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("/want/drawings/1") && err.contains("dynamics"),
        "{err}"
    );
    let mut with = serde_json::from_str::<serde_json::Value>(
        &std::fs::read_to_string(format!(
            "{}/fixtures/dynamics/worked_slider_crank.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    with["want"] = serde_json::json!({ "drawings": ["lever"] });
    let an = Analysis::new(Scene::from_json(&with.to_string()).unwrap()).unwrap();
    let solved = solved(&an);
    let names: Vec<String> =
        common::sheets(&an, &solved, &mechplan::drawing::DrawOptions::default())
            .into_iter()
            .map(|s| s.name)
            .collect();
    assert_eq!(names, vec!["lever_1".to_string()]);
}
