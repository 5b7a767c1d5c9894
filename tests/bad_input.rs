//! The bad-input catalogue: every scene here is wrong in one way. Each runs
//! through the `mechplan` binary and must exit with status 2, print a
//! message on stderr that names the offending field (its JSON pointer, the
//! `lengths` key, or the Assur group), never panic, and write nothing to
//! the `-o` file.

use serde_json::{Value, json};
use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// An offset slider-crank in m and degrees: O the crank pivot (the only
/// frame point), crank O-A, connecting rod A-B-S2, slider 3 at B on the
/// horizontal guide y = -0.03.
fn slider_crank() -> Value {
    json!({
        "mechplan": 1,
        "title": "Offset slider-crank",
        "points": {
            "O": [0.0, 0.0],
            "A": [0.069282032302755, 0.04],
            "B": [0.361001075219052, -0.03],
            "S2": [0.171383697323459, 0.0155]
        },
        "links": {
            "0": { "points": ["O"] },
            "1": { "points": ["O", "A"] },
            "2": { "points": ["A", "B", "S2"] },
            "3": { "points": ["B"] }
        },
        "sliders": [
            { "slider": "3", "guide": "0", "point": "B",
              "line": { "through": [0.0, -0.03], "angle": 0 } }
        ],
        "lengths": { "O-A": 0.08, "A-B": 0.3, "A-S2": 0.105, "B-S2": 0.195 },
        "input": { "link": "1", "pivot": "O", "angle": 30, "omega": 10 }
    })
}

/// A Grashof crank-rocker four-bar with a coupler point M.
fn four_bar() -> Value {
    json!({
        "mechplan": 1,
        "title": "Four-bar crank-rocker",
        "points": {
            "O1": [0.0, 0.0],
            "A": [0.070710678118655, 0.070710678118655],
            "B": [0.340242120247775, 0.2939880878667],
            "M": [0.091431148379841, 0.269634437665259],
            "O3": [0.4, 0.0]
        },
        "links": {
            "0": { "points": ["O1", "O3"] },
            "1": { "points": ["O1", "A"] },
            "2": { "points": ["A", "B", "M"] },
            "3": { "points": ["O3", "B"] }
        },
        "lengths": { "O1-A": 0.1, "A-B": 0.35, "O3-B": 0.3, "A-M": 0.2, "B-M": 0.25 },
        "input": { "link": "1", "pivot": "O1", "angle": 45, "omega": 10 }
    })
}

/// A non-Grashof four-bar (0.15 + 0.4 > 0.2 + 0.3): the crank O1-A rocks
/// and cannot reach φ = 180° (A is then 0.6 from O3, the dyad reaches 0.45).
fn rocking_four_bar() -> Value {
    json!({
        "mechplan": 1,
        "points": {
            "O1": [0.0, 0.0],
            "A": [0.1, 0.173205080756888],
            "B": [0.399100984928775, 0.149997305882145],
            "O3": [0.4, 0.0]
        },
        "links": {
            "0": { "points": ["O1", "O3"] },
            "1": { "points": ["O1", "A"] },
            "2": { "points": ["A", "B"] },
            "3": { "points": ["O3", "B"] }
        },
        "lengths": { "O1-A": 0.2, "A-B": 0.3, "O3-B": 0.15 },
        "input": { "link": "1", "pivot": "O1", "angle": 60, "omega": 10 }
    })
}

/// A fresh path under the temp dir, unique per process and call.
fn temp_path(case: &str, ext: &str) -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let n = N.fetch_add(1, Ordering::Relaxed);
    std::env::temp_dir().join(format!(
        "mechplan-bad-input-{case}-{}-{n}.{ext}",
        std::process::id()
    ))
}

struct Run {
    status: Option<i32>,
    stderr: String,
    /// Whether `-o` left the output file (or its temporary sibling) behind.
    wrote: bool,
    out: PathBuf,
}

/// Run `mechplan solve SCENE --format json -o OUT` on scene text.
fn run(case: &str, text: &str) -> Run {
    let scene = temp_path(case, "json");
    let out = temp_path(&format!("{case}-out"), "json");
    std::fs::write(&scene, text).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&scene)
        .args(["--format", "json", "-o"])
        .arg(&out)
        .output()
        .expect("the mechplan binary runs");
    let _ = std::fs::remove_file(&scene);
    let tmp_prefix = format!(".{}.tmp", out.file_name().unwrap().to_string_lossy());
    let tmp_left = std::fs::read_dir(std::env::temp_dir())
        .unwrap()
        .filter_map(|e| e.ok())
        .any(|e| e.file_name().to_string_lossy().starts_with(&tmp_prefix));
    Run {
        status: o.status.code(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
        wrote: out.exists() || tmp_left,
        out,
    }
}

/// Run a bad scene and check the common promises; `names` must all appear
/// in stderr (the field's pointer, the length key, the group …).
fn reject(case: &str, text: &str, names: &[&str]) -> String {
    let r = run(case, text);
    let _ = std::fs::remove_file(&r.out);
    assert!(
        !r.stderr.contains("panicked"),
        "{case}: the binary panicked:\n{}",
        r.stderr
    );
    assert_eq!(
        r.status,
        Some(2),
        "{case}: exit status {:?}, stderr:\n{}",
        r.status,
        r.stderr
    );
    assert!(
        r.stderr
            .lines()
            .next()
            .is_some_and(|l| l.starts_with("mechplan: ")),
        "{case}: stderr does not start with \"mechplan: \":\n{}",
        r.stderr
    );
    for n in names {
        assert!(
            r.stderr.contains(n),
            "{case}: stderr does not name {n:?}:\n{}",
            r.stderr
        );
    }
    assert!(!r.wrote, "{case}: -o wrote {} anyway", r.out.display());
    r.stderr
}

/// `reject` for a scene built as a JSON value.
fn reject_value(case: &str, v: &Value, names: &[&str]) -> String {
    reject(case, &serde_json::to_string_pretty(v).unwrap(), names)
}

// ---- the positive control -------------------------------------------------

#[test]
fn valid_base_scenes_solve_and_write_json() {
    for (case, v) in [
        ("valid_slider_crank", slider_crank()),
        ("valid_four_bar", four_bar()),
        ("valid_rocking_four_bar", rocking_four_bar()),
    ] {
        let r = run(case, &v.to_string());
        assert_eq!(r.status, Some(0), "{case}: stderr:\n{}", r.stderr);
        let text = std::fs::read_to_string(&r.out).expect("-o wrote the result");
        let _ = std::fs::remove_file(&r.out);
        let out: Value = serde_json::from_str(&text).expect("the result is JSON");
        assert!(
            out["positions"].as_array().is_some_and(|p| !p.is_empty()),
            "{case}: no positions in {text}"
        );
    }
}

// ---- malformed JSON -----------------------------------------------------

#[test]
fn malformed_json_truncated() {
    let text = slider_crank().to_string();
    let cut = &text[..text.len() / 2];
    let e = reject("malformed_json_truncated", cut, &["line 1 column"]);
    assert!(e.contains("JSON"), "{e}");
}

#[test]
fn malformed_json_trailing_comma() {
    let text = serde_json::to_string_pretty(&slider_crank())
        .unwrap()
        .replace("\"omega\": 10", "\"omega\": 10,");
    let e = reject("malformed_json_trailing_comma", &text, &["line ", "column"]);
    assert!(e.contains("trailing comma"), "{e}");
}

// ---- names ----------------------------------------------------------------

#[test]
fn unknown_point_in_link() {
    let mut v = four_bar();
    v["links"]["2"]["points"][1] = json!("X");
    reject_value(
        "unknown_point_in_link",
        &v,
        &["/links/2/points/1", "unknown point \"X\""],
    );
}

#[test]
fn unknown_link_in_sliders() {
    let mut v = slider_crank();
    v["sliders"][0]["slider"] = json!("7");
    reject_value(
        "unknown_link_in_sliders",
        &v,
        &["/sliders/0/slider", "unknown link \"7\""],
    );
}

#[test]
fn unknown_guide_in_sliders() {
    let mut v = slider_crank();
    v["sliders"][0]["guide"] = json!("9");
    reject_value(
        "unknown_guide_in_sliders",
        &v,
        &["/sliders/0/guide", "unknown link \"9\""],
    );
}

#[test]
fn unknown_link_in_input() {
    let mut v = four_bar();
    v["input"]["link"] = json!("5");
    reject_value(
        "unknown_link_in_input",
        &v,
        &["/input/link", "unknown link \"5\""],
    );
}

#[test]
fn repeated_point_name() {
    let text = serde_json::to_string_pretty(&four_bar()).unwrap().replace(
        "\"O3\": [\n      0.4,",
        "\"A\": [0.5, 0.5],\n    \"O3\": [\n      0.4,",
    );
    assert!(text.matches("\"A\": [").count() == 2, "{text}");
    reject("repeated_point_name", &text, &["/points/A", "repeated"]);
}

#[test]
fn repeated_link_id() {
    let text = serde_json::to_string_pretty(&four_bar()).unwrap().replace(
        "\"3\": {",
        "\"2\": { \"points\": [\"B\", \"O3\"] },\n    \"3\": {",
    );
    reject("repeated_link_id", &text, &["/links/2", "repeated"]);
}

#[test]
fn point_repeated_in_one_link() {
    let mut v = four_bar();
    v["links"]["2"]["points"] = json!(["A", "B", "M", "B"]);
    let e = reject_value(
        "point_repeated_in_one_link",
        &v,
        &["/links/2/points/3", "listed twice"],
    );
    assert_eq!(e.lines().count(), 1, "{e}");
}

#[test]
fn want_points_unknown_point() {
    let mut v = four_bar();
    v["want"] = json!({ "points": ["M", "Z"] });
    reject_value(
        "want_points_unknown_point",
        &v,
        &["/want/points/1", "unknown point \"Z\""],
    );
}

// ---- links ---------------------------------------------------------------

#[test]
fn link_with_no_points() {
    let mut v = four_bar();
    v["links"]["4"] = json!({ "points": [] });
    reject_value(
        "link_with_no_points",
        &v,
        &["/links/4/points", "at least one point"],
    );
}

#[test]
fn one_point_link_not_a_slider() {
    let mut v = slider_crank();
    v["sliders"] = json!([]);
    reject_value(
        "one_point_link_not_a_slider",
        &v,
        &["/links/3/points", "single point"],
    );
}

#[test]
fn zero_length_link_coincident_points() {
    let mut v = four_bar();
    v["points"]["A"] = json!([0.0, 0.0]);
    v["lengths"].as_object_mut().unwrap().remove("O1-A");
    reject_value(
        "zero_length_link_coincident_points",
        &v,
        &["/links/1/points", "zero-length"],
    );
}

#[test]
fn zero_length_in_lengths() {
    let mut v = four_bar();
    v["lengths"]["O1-A"] = json!(0);
    reject_value("zero_length_in_lengths", &v, &["/lengths/O1-A", "positive"]);
}

#[test]
fn negative_length() {
    let mut v = four_bar();
    v["lengths"]["A-B"] = json!(-0.35);
    reject_value("negative_length", &v, &["/lengths/A-B", "positive"]);
}

#[test]
fn lengths_break_triangle_inequality() {
    let mut v = four_bar();
    v["lengths"]["A-M"] = json!(0.1);
    v["lengths"]["B-M"] = json!(0.1);
    let e = reject_value(
        "lengths_break_triangle_inequality",
        &v,
        &["/links/2/points/2", "triangle inequality"],
    );
    // The broken shape is not checked against `lengths` again.
    assert_eq!(e.lines().count(), 1, "{e}");
}

#[test]
fn frame_length_disagrees_with_coordinates() {
    let mut v = four_bar();
    v["lengths"]["O1-O3"] = json!(0.5);
    reject_value(
        "frame_length_disagrees_with_coordinates",
        &v,
        &["/lengths/O1-O3", "frame points are exact"],
    );
}

#[test]
fn length_between_points_of_no_common_link() {
    let mut v = four_bar();
    v["lengths"]["O1-B"] = json!(0.4);
    reject_value(
        "length_between_points_of_no_common_link",
        &v,
        &["/lengths/O1-B", "share no link"],
    );
}

// ---- sliders -------------------------------------------------------------

#[test]
fn slider_point_off_its_guide_in_sketch() {
    let mut v = slider_crank();
    v["points"]["B"] = json!([0.361, 0.05]);
    let e = reject_value(
        "slider_point_off_its_guide_in_sketch",
        &v,
        &["/sliders/0/point", "off its guide"],
    );
    assert_eq!(e.lines().count(), 1, "{e}");
}

#[test]
fn slider_point_not_on_slider_link() {
    let mut v = slider_crank();
    v["sliders"][0]["point"] = json!("A");
    reject_value(
        "slider_point_not_on_slider_link",
        &v,
        &["/sliders/0/point", "not a point of the slider"],
    );
}

// ---- numbers -------------------------------------------------------------

fn with_number(token: &str) -> String {
    serde_json::to_string_pretty(&slider_crank())
        .unwrap()
        .replace("\"omega\": 10", &format!("\"omega\": {token}"))
}

#[test]
fn nan_number() {
    let e = reject("nan_number", &with_number("NaN"), &["/input/omega"]);
    assert!(e.contains("non-finite"), "{e}");
}

#[test]
fn infinity_number() {
    let e = reject(
        "infinity_number",
        &with_number("Infinity"),
        &["/input/omega"],
    );
    assert!(e.contains("non-finite"), "{e}");
}

#[test]
fn negative_infinity_in_coordinates() {
    let text = serde_json::to_string_pretty(&four_bar())
        .unwrap()
        .replace("0.340242120247775", "-Infinity");
    let e = reject("negative_infinity_in_coordinates", &text, &["/points/B/0"]);
    assert!(e.contains("non-finite"), "{e}");
}

#[test]
fn huge_number_1e999() {
    let e = reject(
        "huge_number_1e999",
        &with_number("1e999"),
        &["/input/omega"],
    );
    assert!(
        e.contains("out of range") || e.contains("non-finite"),
        "{e}"
    );
}

#[test]
fn wrong_type_string_for_number() {
    let mut v = slider_crank();
    v["input"]["omega"] = json!("10");
    reject_value(
        "wrong_type_string_for_number",
        &v,
        &["/input/omega", "expected a number, found a string"],
    );
}

#[test]
fn wrong_type_number_for_coordinates() {
    let mut v = four_bar();
    v["points"]["B"] = json!(0.34);
    reject_value(
        "wrong_type_number_for_coordinates",
        &v,
        &["/points/B", "expected coordinates"],
    );
}

// ---- structure -----------------------------------------------------------

#[test]
fn mobility_zero_truss() {
    let mut v = four_bar();
    v["links"]["4"] = json!({ "points": ["A", "O3"] });
    let e = reject_value("mobility_zero_truss", &v, &["/links", "mobility W"]);
    assert!(e.contains("= 0"), "{e}");
}

#[test]
fn mobility_two_five_bar() {
    let v = json!({
        "mechplan": 1,
        "points": {
            "O1": [0.0, 0.0], "A": [0.05, 0.0866], "B": [0.2, 0.3],
            "C": [0.45, 0.15], "O2": [0.4, 0.0]
        },
        "links": {
            "0": { "points": ["O1", "O2"] },
            "1": { "points": ["O1", "A"] },
            "2": { "points": ["A", "B"] },
            "3": { "points": ["B", "C"] },
            "4": { "points": ["O2", "C"] }
        },
        "input": { "link": "1", "pivot": "O1", "angle": 60, "omega": 10 }
    });
    let e = reject_value("mobility_two_five_bar", &v, &["/links", "mobility W"]);
    assert!(e.contains("= 2"), "{e}");
}

#[test]
fn non_assemblable_position() {
    let mut v = rocking_four_bar();
    v["positions"] = json!({ "angles": [60, 180] });
    let e = reject_value(
        "non_assemblable_position",
        &v,
        &["cannot be assembled at φ = 180", "II(2,3)"],
    );
    assert!(!e.contains("φ = 60"), "{e}");
}

#[test]
fn positions_count_on_a_crank_that_cannot_turn_fully() {
    let mut v = rocking_four_bar();
    v["positions"] = json!({ "count": 12 });
    reject_value(
        "positions_count_on_a_crank_that_cannot_turn_fully",
        &v,
        &["cannot turn fully", "positions", "count", "II(2,3)"],
    );
}

// ---- top level, input, version ---------------------------------------------

#[test]
fn unknown_top_level_field() {
    let mut v = four_bar();
    v["colour"] = json!("red");
    reject_value(
        "unknown_top_level_field",
        &v,
        &["/colour", "unknown field \"colour\""],
    );
}

#[test]
fn missing_input() {
    let mut v = four_bar();
    v.as_object_mut().unwrap().remove("input");
    reject_value("missing_input", &v, &["/input", "missing"]);
}

#[test]
fn omega_and_rpm_both_given() {
    let mut v = four_bar();
    v["input"]["rpm"] = json!(100);
    reject_value(
        "omega_and_rpm_both_given",
        &v,
        &["/input", "\"omega\" or \"rpm\", not both"],
    );
}

#[test]
fn input_pivot_not_on_frame() {
    let mut v = four_bar();
    v["input"]["pivot"] = json!("A");
    reject_value(
        "input_pivot_not_on_frame",
        &v,
        &["/input/pivot", "not a point of the frame"],
    );
}

#[test]
fn mechplan_version_2() {
    let mut v = four_bar();
    v["mechplan"] = json!(2);
    reject_value(
        "mechplan_version_2",
        &v,
        &["/mechplan", "unsupported format version 2"],
    );
}

#[test]
fn missing_scene_file() {
    let path = temp_path("missing_scene_file", "json");
    let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&path)
        .output()
        .unwrap();
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.starts_with("mechplan: ") && e.contains(&*path.to_string_lossy()),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
}
