//! The `check` command: exit status 0 right, 1 wrong, 2 bad input; the
//! overlay SVG is written only on success.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

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
    let (code, out, _) = run(&["solve", &s, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["acceleration"];
    let mu = plan["mu"].as_f64().unwrap();
    let d = &plan["points"]["d"];
    let good = serde_json::json!({ "plan": "acceleration", "mu": mu, "points": { "d": d, "b_3": plan["points"]["b_3"] } });
    let (s, a, o) = files("good", &good);
    let (code, out, err) = run(&["check", &s, &a, "--svg", &o]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("2 of 2 right"));
    assert!(std::path::Path::new(&o).exists());
    let overlay = std::fs::read_to_string(&o).unwrap();
    assert!(overlay.contains("student-d") && overlay.contains("#c00000"));
    let mut bad = good.clone();
    bad["points"]["d"] = serde_json::json!([d[0].as_f64().unwrap() + 15.0, d[1]]);
    let (s, a, o) = files("wrong", &bad);
    let (code, out, _) = run(&["check", &s, &a, "--svg", &o, "--format", "json"]);
    assert_eq!(code, 1);
    let rep: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(rep["wrong"], 1);
    let (s, a, o) = files(
        "bad",
        &serde_json::json!({ "plan": "acceleration", "points": { "d": [1, 2] } }),
    );
    let (code, _, err) = run(&["check", &s, &a, "--svg", &o]);
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
    let (code, out, _) = run(&["solve", &scene, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["acceleration"];
    let answer = serde_json::json!({
        "plan": "acceleration", "mu": plan["mu"], "points": { "d": plan["points"]["d"] }
    });
    let a = dir.join("answer.json");
    std::fs::write(&a, answer.to_string()).unwrap();
    let (code, out, err) = run(&["check", &scene, a.to_str().unwrap()]);
    assert_eq!(code, 4, "{out}{err}");
    assert!(
        out.contains("CANNOT BE JUDGED") && out.contains("exceeds a fifth of the plan"),
        "{out}"
    );
    let (code, out, _) = run(&["check", &scene, a.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 4);
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["status"], 4);
    assert_eq!(r["items"][0]["judgement"], "cannot be judged");
    let _ = std::fs::remove_dir_all(&dir);
}
