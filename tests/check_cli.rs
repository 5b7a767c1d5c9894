//! The `check` command: exit status 0 right, 1 wrong, 2 bad input; the
//! overlay SVG is written only on success.

mod common;

fn files(tag: &str, answer: &serde_json::Value) -> (String, String, String) {
    let dir = std::env::temp_dir().join(format!("mechplan-check-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut scene: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(format!(
            "{}/fixtures/shaper_fig2_11.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    scene["positions"] = serde_json::json!({ "angles": [30] });
    let (s, a, o) = (
        dir.join("scene.json"),
        dir.join("answer.json"),
        dir.join("overlay.svg"),
    );
    std::fs::write(&s, scene.to_string()).unwrap();
    std::fs::write(&a, answer.to_string()).unwrap();
    let _ = std::fs::remove_file(&o);
    (
        s.display().to_string(),
        a.display().to_string(),
        o.display().to_string(),
    )
}

/// The correct answer (from `solve`) passes with status 0 and an overlay;
/// the same answer with the Coriolis point's relative line shifted fails
/// with status 1; a bad answer gets status 2.
#[test]
fn exit_status_follows_the_verdict() {
    // Expected values from solve --format json.
    let (s, _, _) = files("solve", &serde_json::json!({}));
    let (code, out, _) = common::run(&["solve", &s, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["acceleration"];
    let mu = plan["mu"].as_f64().unwrap();
    let d = &plan["points"]["d"];
    let good = serde_json::json!({ "plan": "acceleration", "mu": mu, "points": { "d": d, "b_3": plan["points"]["b_3"] } });
    let (s, a, o) = files("good", &good);
    let (code, out, err) = common::run(&["check", &s, &a, "--svg", &o]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("2 of 2 right"));
    assert!(std::path::Path::new(&o).exists());
    let overlay = std::fs::read_to_string(&o).unwrap();
    assert!(overlay.contains("student-d") && overlay.contains("#1f5fa8"));
    let mut bad = good.clone();
    bad["points"]["d"] = serde_json::json!([d[0].as_f64().unwrap() + 15.0, d[1]]);
    let (s, a, o) = files("wrong", &bad);
    let (code, out, _) = common::run(&["check", &s, &a, "--svg", &o, "--format", "json"]);
    assert_eq!(code, 1);
    let rep: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(rep["wrong"], 1);
    let (s, a, o) = files(
        "bad",
        &serde_json::json!({ "plan": "acceleration", "points": { "d": [1, 2] } }),
    );
    let (code, _, err) = common::run(&["check", &s, &a, "--svg", &o]);
    assert_eq!(code, 2);
    assert!(err.contains("/mu"), "{err}");
    assert!(
        !std::path::Path::new(&o).exists(),
        "nothing written on bad input"
    );
}

/// An item the construction cannot place within a fifth of the plan (the
/// class III group's accelerations near its lock) is "cannot be judged":
/// exit status 4, the reason printed, never "right".
#[test]
fn cannot_be_judged_has_its_own_status() {
    let dir = std::env::temp_dir().join(format!("mechplan-check-unjudged-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = format!("{}/fixtures/class3_004.json", env!("CARGO_MANIFEST_DIR"));
    let (code, out, _) = common::run(&["solve", &scene, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["acceleration"];
    let answer = serde_json::json!({
        "plan": "acceleration", "mu": plan["mu"], "points": { "d": plan["points"]["d"] }
    });
    let a = dir.join("answer.json");
    std::fs::write(&a, answer.to_string()).unwrap();
    let (code, out, err) = common::run(&["check", &scene, a.to_str().unwrap()]);
    assert_eq!(code, 4, "{out}{err}");
    assert!(
        out.contains("CANNOT BE JUDGED") && out.contains("exceeds a fifth of the plan"),
        "{out}"
    );
    let (code, out, _) = common::run(&["check", &scene, a.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 4);
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["status"], 4);
    assert_eq!(r["items"][0]["judgement"], "cannot be judged");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A plan drawn large (a fine μ_a) and a student's point far off: the
/// overlay still lies on its sheet, inside the frame, heading included
/// (a larger sheet, or the drawing reduced and saying so).
#[test]
fn the_overlay_stays_on_its_sheet() {
    let (s, _, _) = files("big-solve", &serde_json::json!({}));
    let (code, out, _) = common::run(&["solve", &s, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["acceleration"];
    let k = 8.0;
    let mu = plan["mu"].as_f64().unwrap() / k;
    let at = |key: &str| {
        let p = &plan["points"][key];
        serde_json::json!([p[0].as_f64().unwrap() * k, p[1].as_f64().unwrap() * k])
    };
    let d = at("d");
    let far = serde_json::json!([d[0].as_f64().unwrap() + 700.0, d[1]]);
    let answer = serde_json::json!({ "plan": "acceleration", "mu": mu, "points": { "d": far, "b_3": at("b_3") } });
    let (s, a, o) = files("big", &answer);
    let (code, out, err) = common::run(&["check", &s, &a, "--svg", &o]);
    assert_eq!(code, 1, "{out}{err}");
    let svg = std::fs::read_to_string(&o).unwrap();
    let tree = mechplan::drawing::tree(&svg).unwrap();
    let (w, h) = (tree.size().width() as f64, tree.size().height() as f64);
    let px = 96.0 / 25.4;
    let frame = kurbo::Rect::new(20.0 * px, 5.0 * px, w - 5.0 * px, h - 5.0 * px);
    fn walk(g: &usvg::Group, frame: kurbo::Rect, n: &mut usize) {
        for c in g.children() {
            match c {
                usvg::Node::Group(g) => walk(g, frame, n),
                _ => {
                    let b = c.abs_stroke_bounding_box();
                    let inside = b.left() as f64 >= frame.x0 - 1.0
                        && b.top() as f64 >= frame.y0 - 1.0
                        && b.right() as f64 <= frame.x1 + 1.0
                        && b.bottom() as f64 <= frame.y1 + 1.0;
                    // The frame itself and the white page are the frame.
                    if !inside && (b.width() as f64) < frame.width() {
                        *n += 1;
                    }
                }
            }
        }
    }
    let mut outside = 0;
    walk(tree.root(), frame, &mut outside);
    assert_eq!(outside, 0, "{outside} elements leave the frame");
    assert!(svg.contains("student-d"), "the student's point is drawn");
}
