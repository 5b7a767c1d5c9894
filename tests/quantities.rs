//! Small quantities in messages keep their significant digits: a point
//! 3e-12 mm off its place is reported as such, not as "0" (or "0.000000").

use std::process::Command;

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

#[test]
fn a_tiny_difference_is_printed_with_significant_digits() {
    let dir = std::env::temp_dir().join(format!("mechplan-quantities-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut scene: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(format!(
            "{}/fixtures/six_link_fig2_10.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    scene["positions"] = serde_json::json!({ "angles": [60] });
    let s = dir.join("scene.json");
    std::fs::write(&s, scene.to_string()).unwrap();
    let s = s.display().to_string();
    let out = Command::new(EXE)
        .args(["solve", &s, "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let plan = &doc["positions"][0]["plans"]["velocity"];
    let b = &plan["points"]["b"];
    let (x, y) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    let answer = serde_json::json!({
        "plan": "velocity",
        "mu": plan["mu"],
        "points": { "b": [x + 3e-12, y] }
    });
    let a = dir.join("answer.json");
    std::fs::write(&a, answer.to_string()).unwrap();
    let out = Command::new(EXE)
        .args(["check", &s, &a.display().to_string()])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    let row = text
        .lines()
        .find(|l| l.contains("point b"))
        .unwrap_or_else(|| panic!("{text}"));
    let tiny: Vec<f64> = row
        .split_whitespace()
        .filter(|t| t.contains("e-1"))
        .map(|t| t.parse().unwrap())
        .collect();
    assert!(
        tiny.iter().any(|d| (1e-12..5e-12).contains(d)),
        "the difference of 3e-12 mm is lost: {row}"
    );
}
