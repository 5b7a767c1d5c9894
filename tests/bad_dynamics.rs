//! The `dynamics` object's bad input: every scene here is wrong in one
//! way. Each runs through the `mechplan` binary and must exit with status
//! 2, name the field by its JSON pointer with its own message, never
//! panic, and write nothing to the `-o` file. And the good ones: a scene
//! with `dynamics` gets accelerations and every pair whatever `want` asks.

use serde_json::{Value, json};
use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The worked example (docs/kinetostatics.md) at three crank angles.
fn scene() -> Value {
    let mut v: Value = serde_json::from_str(include_str!(
        "../fixtures/dynamics/worked_slider_crank.json"
    ))
    .unwrap();
    v["positions"] = json!({ "angles": [90, 120, 150] });
    v
}

fn temp_path(case: &str) -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let n = N.fetch_add(1, Ordering::Relaxed);
    std::env::temp_dir().join(format!(
        "mechplan-bad-dynamics-{case}-{}-{n}.json",
        std::process::id()
    ))
}

/// Run `mechplan solve SCENE --format json -o OUT`: (status, stderr, the
/// output if written).
fn run(case: &str, v: &Value) -> (Option<i32>, String, Option<String>) {
    let scene = temp_path(case);
    let out = temp_path(&format!("{case}-out"));
    std::fs::write(&scene, serde_json::to_string_pretty(v).unwrap()).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&scene)
        .args(["--format", "json", "-o"])
        .arg(&out)
        .output()
        .expect("the mechplan binary runs");
    let _ = std::fs::remove_file(&scene);
    let written = std::fs::read_to_string(&out).ok();
    let _ = std::fs::remove_file(&out);
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        written,
    )
}

/// A scene changed by `edit` is refused with `message` at `pointer`, on
/// one line of stderr.
fn reject(case: &str, edit: impl FnOnce(&mut Value), pointer: &str, message: &str) {
    let mut v = scene();
    edit(&mut v);
    let (status, stderr, written) = run(case, &v);
    assert!(!stderr.contains("panicked"), "{case}: panicked:\n{stderr}");
    assert_eq!(status, Some(2), "{case}: stderr:\n{stderr}");
    assert!(
        stderr
            .lines()
            .any(|l| l.contains(&format!("{pointer}: ")) && l.contains(message)),
        "{case}: no line names {pointer} with {message:?}:\n{stderr}"
    );
    assert!(written.is_none(), "{case}: -o wrote a result anyway");
}

#[test]
fn unknown_link() {
    reject(
        "unknown_link",
        |v| v["dynamics"]["links"]["9"] = json!({ "m": 1, "J": 0, "centre": "A" }),
        "/dynamics/links/9",
        "unknown link \"9\"",
    );
}

#[test]
fn frame_refused() {
    reject(
        "frame_mass",
        |v| v["dynamics"]["links"]["0"] = json!({ "m": 1, "J": 0, "centre": "O" }),
        "/dynamics/links/0",
        "the frame, link \"0\", does not move",
    );
    reject(
        "frame_force",
        |v| v["dynamics"]["forces"][0]["link"] = json!(0),
        "/dynamics/forces/0/link",
        "the frame, link \"0\", does not move",
    );
}

#[test]
fn centre_not_on_link() {
    reject(
        "centre_off_link",
        |v| v["dynamics"]["links"]["2"]["centre"] = json!("O"),
        "/dynamics/links/2/centre",
        "point \"O\" is not a point of link \"2\"",
    );
}

#[test]
fn centre_missing() {
    reject(
        "centre_missing",
        |v| {
            v["dynamics"]["links"]["2"]
                .as_object_mut()
                .unwrap()
                .remove("centre");
        },
        "/dynamics/links/2/centre",
        "missing",
    );
}

#[test]
fn negative_mass_and_inertia() {
    reject(
        "negative_mass",
        |v| v["dynamics"]["links"]["2"]["m"] = json!(-2),
        "/dynamics/links/2/m",
        "a mass (kg) must not be negative, found -2",
    );
    reject(
        "negative_j",
        |v| v["dynamics"]["links"]["2"]["J"] = json!(-0.5),
        "/dynamics/links/2/J",
        "a moment of inertia (kg·m²) must not be negative, found -0.5",
    );
}

#[test]
fn non_finite_mass() {
    // JSON has no NaN: the text is written by hand, and the reader finds
    // the field the parser stopped at.
    let text =
        serde_json::to_string_pretty(&scene())
            .unwrap()
            .replacen("\"m\": 2", "\"m\": NaN", 1);
    assert!(text.contains("NaN"));
    let scene = temp_path("nan_mass");
    std::fs::write(&scene, text).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&scene)
        .output()
        .unwrap();
    let _ = std::fs::remove_file(&scene);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("/dynamics/links/2/m: non-finite number NaN"),
        "{stderr}"
    );
}

#[test]
fn mass_not_a_number() {
    reject(
        "mass_string",
        |v| v["dynamics"]["links"]["2"]["m"] = json!("2 kg"),
        "/dynamics/links/2/m",
        "expected a number, found a string",
    );
}

#[test]
fn unknown_field() {
    reject(
        "unknown_field",
        |v| v["dynamics"]["links"]["2"]["mass"] = json!(2),
        "/dynamics/links/2/mass",
        "unknown field \"mass\"",
    );
    reject(
        "unknown_top",
        |v| v["dynamics"]["gravity"] = json!([0, -9.81]),
        "/dynamics/gravity",
        "unknown field \"gravity\"",
    );
}

#[test]
fn gravity_not_a_vector() {
    reject(
        "g_number",
        |v| v["dynamics"]["g"] = json!(-9.81),
        "/dynamics/g",
        "expected a vector [x, y], found a number",
    );
}

#[test]
fn force_unknown_point() {
    reject(
        "force_unknown_point",
        |v| v["dynamics"]["forces"][0]["point"] = json!("Q"),
        "/dynamics/forces/0/point",
        "unknown point \"Q\"",
    );
}

#[test]
fn force_point_not_on_link() {
    reject(
        "force_point_off_link",
        |v| v["dynamics"]["forces"][0]["point"] = json!("A"),
        "/dynamics/forces/0/point",
        "point \"A\" is not a point of link \"3\"",
    );
}

#[test]
fn force_list_of_wrong_length() {
    reject(
        "force_list_length",
        |v| v["dynamics"]["forces"][0]["F"] = json!([[1, 0], [2, 0]]),
        "/dynamics/forces/0/F",
        "a list of 2 values, but the scene has 3 positions",
    );
}

#[test]
fn force_list_item_not_a_vector() {
    reject(
        "force_list_item",
        |v| v["dynamics"]["forces"][0]["F"] = json!([[1, 0], [2, 0], [3]]),
        "/dynamics/forces/0/F/2",
        "expected a vector [x, y]",
    );
}

#[test]
fn moment_list_of_wrong_length() {
    reject(
        "moment_list_length",
        |v| v["dynamics"]["moments"] = json!([{ "link": "2", "M": [1, 2, 3, 4] }]),
        "/dynamics/moments/0/M",
        "a list of 4 values, but the scene has 3 positions",
    );
}

#[test]
fn moment_not_a_number() {
    reject(
        "moment_string",
        |v| v["dynamics"]["moments"] = json!([{ "link": "2", "M": "ten" }]),
        "/dynamics/moments/0/M",
        "expected a number, found a string",
    );
}

#[test]
fn moment_unknown_link() {
    reject(
        "moment_link",
        |v| v["dynamics"]["moments"] = json!([{ "link": "7", "M": 1 }]),
        "/dynamics/moments/0/link",
        "unknown link \"7\"",
    );
}

#[test]
fn forces_not_a_list() {
    reject(
        "forces_object",
        |v| v["dynamics"]["forces"] = json!({ "link": "3" }),
        "/dynamics/forces",
        "expected a list",
    );
}

#[test]
fn too_many_moving_links() {
    reject(
        "too_many_links",
        |v| {
            let links = v["links"].as_object_mut().unwrap();
            for i in 0..200 {
                links.insert(format!("{}", 10 + i), json!({ "points": ["A", "B"] }));
            }
        },
        "/dynamics",
        "the force analysis takes at most 200 moving links (one dense system of 3 equations each); the scene has 203",
    );
}

// ---- the good ones -------------------------------------------------------

/// With `want` asking for velocities and one point only, the accelerations
/// are still computed and every pair of every group is reported.
#[test]
fn dynamics_brings_accelerations_and_every_pair() {
    let mut v = scene();
    v["want"] = json!({ "rates": ["velocity"], "plans": [], "points": ["A"] });
    v["dynamics"]["forces"][0]["F"] = json!([[2000, 0], [1500, 0], [0, 0]]);
    let (status, stderr, written) = run("good_velocity_only", &v);
    assert_eq!(status, Some(0), "{stderr}");
    let out: Value = serde_json::from_str(&written.expect("a result")).unwrap();
    let positions = out["positions"].as_array().unwrap();
    assert_eq!(positions.len(), 3);
    for p in positions {
        assert!(p["points"]["A"]["a"].is_array(), "no acceleration: {p}");
        let pairs = p["dynamics"]["pairs"].as_array().unwrap();
        // O, A, B revolute and the slider's guide: every pair.
        assert_eq!(pairs.len(), 4, "{p}");
        assert!(p["dynamics"]["balancing"]["M"].is_number(), "{p}");
    }
}

/// A scene without `dynamics` has none in its result.
#[test]
fn no_dynamics_no_field() {
    let mut v = scene();
    v.as_object_mut().unwrap().remove("dynamics");
    let (status, stderr, written) = run("good_without", &v);
    assert_eq!(status, Some(0), "{stderr}");
    assert!(!written.unwrap().contains("\"dynamics\""));
}
