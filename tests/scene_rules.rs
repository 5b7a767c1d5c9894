//! The contract's reading rules: units, the rigid-shape rule, offsets.

mod common;
use common::*;
use mechplan::Scene;
use serde_json::json;

/// The same four-bar in m/deg and in mm/rad gives the same SI results.
#[test]
fn units_mm_and_rad_give_the_same_results() {
    let v = fixture("four_bar");
    let (an1, s1) = solve(scene_with(v.clone(), json!({ "angles": [45, 100] })));
    let mut w = v.clone();
    w["units"] = json!({ "length": "mm", "angle": "rad" });
    for (_, p) in w["points"].as_object_mut().unwrap() {
        let a = p.as_array().unwrap();
        *p = json!([
            a[0].as_f64().unwrap() * 1000.0,
            a[1].as_f64().unwrap() * 1000.0
        ]);
    }
    for (_, l) in w["lengths"].as_object_mut().unwrap() {
        *l = json!(l.as_f64().unwrap() * 1000.0);
    }
    w["input"]["angle"] = json!(45f64.to_radians());
    let (an2, s2) = solve(scene_with(
        w,
        json!({ "angles": [45f64.to_radians(), 100f64.to_radians()] }),
    ));
    for k in 0..2 {
        for &p in &an1.points {
            let (a, b) = (s1[k].point(&an1, p), s2[k].point(&an2, p));
            assert!((a.at - b.at).hypot() < 1e-12);
            let ((va, aa), (vb, ab)) = (a.rates.unwrap(), b.rates.unwrap());
            assert!((va - vb).hypot() < 1e-12 && (aa - ab).hypot() < 1e-10);
        }
    }
}

/// A third point is placed by its `lengths` to two earlier points, on the
/// side of their line where the sketch draws it, even when the sketch's
/// distances are off; on the segment when the distances add up.
#[test]
fn rigid_shape_rule_places_points_from_lengths() {
    let text = r#"{
      "mechplan": 1,
      "points": { "O": [0, 0], "A": [0.1, 0], "B": [0.33, 0.21], "M": [0.2, 0.31], "N": [0.2, 0.1], "Q": [0.4, 0] },
      "links": {
        "0": { "points": ["O", "Q"] },
        "1": { "points": ["O", "A"] },
        "2": { "points": ["A", "B", "M", "N"] },
        "3": { "points": ["Q", "B"] }
      },
      "lengths": { "O-A": 0.1, "A-B": 0.3, "Q-B": 0.25, "M-B": 0.2, "M-A": 0.22, "N-A": 0.1, "N-B": 0.2 },
      "input": { "link": "1", "pivot": "O", "angle": 0, "omega": 1 }
    }"#;
    let an = mechplan::Analysis::new(Scene::from_json(text).unwrap()).unwrap();
    let link = &an.mech.links[2];
    let p = |n: &str| {
        link.local_of(an.mech.scene.point_index(n).unwrap())
            .unwrap()
    };
    assert!(((p("B") - p("A")).hypot() - 0.3).abs() < 1e-15);
    assert!(((p("M") - p("A")).hypot() - 0.22).abs() < 1e-15);
    assert!(((p("M") - p("B")).hypot() - 0.2).abs() < 1e-15);
    // M is drawn to the left of A→B: it stays there.
    assert!((p("B") - p("A")).cross(p("M") - p("A")) > 0.0);
    // N: 0.1 + 0.2 = AB, so N lies on the segment AB.
    assert!((p("B") - p("A")).cross(p("N") - p("A")).abs() < 1e-15);
    assert!(((p("N") - p("A")).hypot() - 0.1).abs() < 1e-15);
}

/// The guide's `offset` shifts the line to the left of its direction: an
/// offset slider-crank with offset −e keeps its slider at y = −e.
#[test]
fn guide_offset_shifts_to_the_left_of_the_direction() {
    let v = fixture("offset_slider_crank");
    let (an, s) = solve(scene_with(v, json!({ "angles": [0, 77, 190, 300] })));
    let b = an.mech.scene.point_index("B").unwrap();
    for st in &s {
        let p = st.point(&an, b);
        assert!((p.at.y + 0.030).abs() < 1e-15, "{:?}", p.at);
        let (vel, acc) = p.rates.unwrap();
        assert!(vel.y.abs() < 1e-12 && acc.y.abs() < 1e-9);
    }
}

/// Regression (found by the plan-law property test): a point placed on the
/// extension of its two reference points (|r1 − r2| = d) must lie exactly
/// on their line; tangent circles used to put it off by √ε of the length.
#[test]
fn collinear_point_beyond_its_references_stays_on_the_line() {
    for k in [1.0, 4.8820785639929785, 0.37] {
        let mut v = fixture("class3_004");
        for (_, p) in v["points"].as_object_mut().unwrap() {
            let a = p.as_array().unwrap();
            *p = json!([a[0].as_f64().unwrap() * k, a[1].as_f64().unwrap() * k]);
        }
        for (_, l) in v["lengths"].as_object_mut().unwrap() {
            *l = json!(l.as_f64().unwrap() * k);
        }
        let an = mechplan::Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
        let link = &an.mech.links[an.mech.scene.link_index("3").unwrap()];
        let d = link
            .local_of(an.mech.scene.point_index("D").unwrap())
            .unwrap();
        assert_eq!(d.y, 0.0, "D on the base line B→C at k = {k}");
        assert!((d.x - 2.0 * k).abs() <= 4.0 * f64::EPSILON * k);
    }
}
