//! The start of `positions.count` (the extreme position that begins the
//! working stroke) in scenes the stress catalogue does not hold: an
//! output that turns fully (the steps start at the input's angle as
//! written, which carries its rounding), and a scene that reports fewer
//! points than the output needs (its start still checked).

mod common;
use common::*;
use serde_json::{Value, json};
use std::process::Command;

fn solve(scene: &Value) -> Value {
    let path = std::env::temp_dir().join(format!(
        "mechplan-count-start-{}-{}.json",
        std::process::id(),
        scene["title"].as_str().unwrap_or("").len()
    ));
    std::fs::write(&path, scene.to_string()).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&path)
        .args(["--format", "json"])
        .output()
        .unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The rotating guide of fixture `rrp_rotating_guide_002` turns fully: its
/// count starts at the crank's angle as written. Written in radians a
/// million turns out (6283186.307179587 rad), that angle is known only to
/// its rounding (about 5e-10 rad); the printed bound of the crank's angle
/// must cover its distance from the exact value, 6283186.307179587 mod 2π
/// = 1.000000000523074713… rad (50 digits, mpmath).
#[test]
fn a_fully_turning_output_starts_at_the_written_angle_with_its_rounding() {
    let mut v = fixture("rrp_rotating_guide_002");
    v["units"] = json!({ "length": v["units"]["length"].clone(), "angle": "rad" });
    v["input"]["angle"] = json!(6283186.307179587_f64);
    v["positions"] = json!({ "count": 12, "output": "3" });
    let doc = solve(&v);
    let p = &doc["positions"][0];
    let exact = 1.000_000_000_523_074_7_f64;
    let got = p["input"]["angle"].as_f64().unwrap().to_radians();
    let bound = p["crosscheck"]["bound"]["angle"].as_f64().unwrap();
    assert!(
        (got - exact).abs() <= bound,
        "start {got:.17} rad, exact {exact:.17}, off {:.3e} > bound {bound:.3e}",
        (got - exact).abs()
    );
}

/// A scene that reports only the crank's end still counts from the
/// output's extreme (the shaper's rocker, found by its transfer function's
/// root and checked there with every point it needs).
#[test]
fn a_count_reporting_fewer_points_than_the_output_needs() {
    let mut v = fixture("shaper_fig2_11");
    v["want"] = json!({ "points": ["A"] });
    let doc = solve(&v);
    assert_eq!(doc["positions"].as_array().unwrap().len(), 12);
    let whole = solve(&fixture("shaper_fig2_11"));
    assert_eq!(
        doc["positions"][0]["input"]["angle"],
        whole["positions"][0]["input"]["angle"]
    );
}
