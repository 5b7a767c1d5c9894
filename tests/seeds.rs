//! Values printed in the seeds, and exact properties of the fixtures.

mod common;
use common::*;
use serde_json::json;

/// Seed 004, Table 1: every velocity, acceleration, angular velocity and
/// angular acceleration it states, to 1e-12; at ω1 = 1 and, to catch a
/// confusion of ω1 with ω1², at ω1 = 3 (v, ω scale with ω1; a, ε with ω1²).
#[test]
fn class3_004_reproduces_table_1() {
    let table = serde_json::from_str::<serde_json::Value>(
        &std::fs::read_to_string(format!(
            "{}/fixtures/expected/004_table1.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    for w1 in [1.0f64, 3.0, -2.0] {
        let mut v = fixture("class3_004");
        v["input"]["omega"] = json!(w1);
        let (an, s) = solve(scene_with(v, json!({ "angles": [30] })));
        let sc = &an.mech.scene;
        let close = |got: f64, want: f64, what: &str| {
            assert!(
                (got - want).abs() <= 1e-12 * want.abs().max(1.0),
                "{what} at ω1 = {w1}: {got} vs {want}"
            );
        };
        for (name, e) in table["points"].as_object().unwrap() {
            let st = s[0].point(&an, sc.point_index(name).unwrap());
            let (vel, acc) = st.rates.unwrap();
            close(
                vel.hypot(),
                e["v"].as_f64().unwrap() * w1.abs(),
                &format!("|v_{name}|"),
            );
            close(
                acc.hypot(),
                e["a"].as_f64().unwrap() * w1 * w1,
                &format!("|a_{name}|"),
            );
        }
        for (id, e) in table["links"].as_object().unwrap() {
            let mo = s[0].motion[sc.link_index(id).unwrap()].unwrap();
            let w = e
                .get("omega_abs")
                .or(e.get("omega"))
                .unwrap()
                .as_f64()
                .unwrap()
                .abs();
            let eps = e
                .get("epsilon_abs")
                .or(e.get("epsilon"))
                .unwrap()
                .as_f64()
                .unwrap()
                .abs();
            close(mo.omega.abs(), w * w1.abs(), &format!("|ω{id}|"));
            close(mo.epsilon.abs(), eps * w1 * w1, &format!("|ε{id}|"));
        }
    }
}

/// The structure formula and group kinds of every fixture.
#[test]
fn fixtures_decompose_as_their_sources_say() {
    let expect = [
        ("four_bar", "I(0,1) -> II(2,3)", vec!["RRR"]),
        ("offset_slider_crank", "I(0,1) -> II(2,3)", vec!["RRP"]),
        (
            "six_link_fig2_10",
            "I(0,1) -> II(2,3) -> II(4,5)",
            vec!["RRR", "RRP"],
        ),
        (
            "shaper_fig2_11",
            "I(0,1) -> II(2,3) -> II(4,5)",
            vec!["RPR", "RPP"],
        ),
        (
            "compressor_fig2_12",
            "I(0,1) -> II(2,3) -> II(4,5)",
            vec!["RRP", "RRP"],
        ),
        ("rrp_rotating_guide_002", "I(0,1) -> II(2,3)", vec!["RRP"]),
        (
            "class3_004",
            "I(0,1) -> III(2,3,4,5)",
            vec!["three-leash RRRRRR"],
        ),
        ("prp_tangent_drive", "I(0,1) -> II(2,3)", vec!["PRP"]),
        ("slider_driven_rocker", "I(0,1) -> II(2,3)", vec!["RRR"]),
    ];
    for (name, formula, kinds) in expect {
        let an = mechplan::Analysis::new(
            mechplan::Scene::from_json(&fixture(name).to_string()).unwrap(),
        )
        .unwrap();
        assert_eq!(an.structure.dof, 1, "{name}");
        assert_eq!(an.structure.formula(&an.mech), formula, "{name}");
        let got: Vec<String> = an.structure.groups.iter().map(|g| g.kind()).collect();
        assert_eq!(got, kinds, "{name}");
    }
}

/// `positions.count` starts at the extreme position that begins the working
/// stroke, found exactly. For the six-link mechanism the slider's extremes
/// are where crank O1A and coupler AB are collinear (rocker 3 at its
/// extremes): |O1B| = AB ∓ O1A, computed here by plain geometry.
#[test]
fn count_starts_at_the_exact_extreme_of_the_working_stroke() {
    let v = fixture("six_link_fig2_10");
    let (an, s) = solve(scene_with(v, json!({ "count": 12 })));
    // Geometry: B on the circle about O2 (0.3, 0) of radius 0.25 at
    // distance AB − O1A = 0.2 from O1; the crank points away from B.
    let (d, r, c) = (0.2f64, 0.25f64, 0.3f64);
    let x = (d * d - r * r + c * c) / (2.0 * c);
    let y = (d * d - x * x).sqrt(); // B above the frame line, as in the sketch
    let crank = (y.atan2(x) + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU);
    // The other extreme (|O1B| = AB + O1A = 0.4).
    let d2 = 0.4f64;
    let x2 = (d2 * d2 - r * r + c * c) / (2.0 * c);
    let crank2 = ((d2 * d2 - x2 * x2).sqrt().atan2(x2)).rem_euclid(std::f64::consts::TAU);
    // ω1 < 0: the stroke from `crank` to `crank2` turning clockwise.
    let stroke = (crank - crank2).rem_euclid(std::f64::consts::TAU);
    let start = if stroke >= std::f64::consts::PI {
        crank
    } else {
        crank2
    };
    assert!(
        (s[0].q - start).abs() <= 1e-12,
        "start {} vs {}",
        s[0].q.to_degrees(),
        start.to_degrees()
    );
    let d_idx = an.mech.scene.point_index("D").unwrap();
    let (vq, _) = s[0].point(&an, d_idx).analogue.unwrap();
    assert!(
        vq.hypot() <= 1e-12 * an.mech.size,
        "the slider rests at the extreme: {vq:?}"
    );
    // Twelve equal steps in the sense of ω1 (clockwise).
    for k in 1..12 {
        let step = (s[k - 1].q - s[k].q).rem_euclid(std::f64::consts::TAU);
        assert!((step - std::f64::consts::TAU / 12.0).abs() < 1e-12);
    }
}

/// With `want.points`, only the groups those points need are solved and
/// reported; with only velocities wanted, no accelerations are computed.
#[test]
fn want_points_and_plans_limit_the_work() {
    let mut v = fixture("six_link_fig2_10");
    v["want"] = json!({ "points": ["S2"], "plans": ["velocity"] });
    let (an, s) = solve(scene_with(v, json!({ "angles": [60] })));
    let sc = &an.mech.scene;
    assert_eq!(
        an.need,
        vec![true, false],
        "group II(4,5) is not needed for S2"
    );
    assert!(!an.include[sc.link_index("4").unwrap()] && !an.include[sc.link_index("5").unwrap()]);
    assert_eq!(an.order, Some(mechplan::analytic::Order::Velocity));
    let doc = mechplan::report::to_json(&an, &s);
    let pos = &doc["positions"][0];
    assert_eq!(
        pos["points"]
            .as_object()
            .unwrap()
            .keys()
            .collect::<Vec<_>>(),
        vec!["S2"]
    );
    assert!(pos["points"]["S2"].get("a").is_none() && pos["points"]["S2"].get("v").is_some());
    assert!(pos["links"].get("4").is_none() && pos["links"]["2"].get("epsilon").is_none());
    // Velocities of S2 are those of the full solve.
    let (full_an, full) = solve(scene_with(
        fixture("six_link_fig2_10"),
        json!({ "angles": [60] }),
    ));
    let p = sc.point_index("S2").unwrap();
    let (a, b) = (
        s[0].point(&an, p).rates.unwrap().0,
        full[0].point(&full_an, p).rates.unwrap().0,
    );
    assert!((a - b).hypot() < 1e-15);
}
