//! Regression tests from fuzzing (`fuzz/`, target `scene`; see
//! `docs/fuzzing.md`) and the reader's size limits. Every crashing input
//! the fuzzer finds becomes a named test here, inline, asserting a clean
//! error or success; the limits each get a test with its message.

use mechplan::drawing::{DrawOptions, sheet_needs, sheets};
use mechplan::scene::{
    MAX_COUNT, MAX_FILE_BYTES, MAX_LINKS, MAX_MAGNITUDE, MAX_POINTS, MAX_POSITIONS,
};
use mechplan::studies::sheet_data::SheetData;
use mechplan::{Analysis, Error, Scene};
use std::fmt::Write as _;

/// What the fuzz target does: read, analyse, solve, draw; `Err` is fine,
/// a panic is not.
fn pipeline(text: &str) -> Result<usize, Error> {
    let scene = Scene::from_json(text)?;
    let an = Analysis::new(scene)?;
    let solved = an.run()?;
    let opt = DrawOptions::default();
    let data = SheetData::solve(&an, &solved, sheet_needs(&an, &solved, &opt, true))?;
    Ok(sheets(&an, &solved, &data, &opt).len())
}

/// The error message of a scene the reader must reject.
fn rejected(text: &str) -> String {
    match Scene::from_json(text) {
        Ok(_) => panic!("accepted a scene beyond a limit"),
        Err(e) => e.to_string(),
    }
}

/// A valid four-bar whose `points`, `links`, `positions` can be grown.
fn four_bar(extra_points: &str, extra_links: &str, positions: &str) -> String {
    format!(
        r#"{{"mechplan": 1,
  "points": {{"O1": [0, 0], "A": [0.070710678118655, 0.070710678118655],
             "B": [0.340242120247775, 0.2939880878667], "O3": [0.4, 0]{extra_points}}},
  "links": {{"0": {{"points": ["O1", "O3"]}}, "1": {{"points": ["O1", "A"]}},
            "2": {{"points": ["A", "B"]}}, "3": {{"points": ["O3", "B"]}}{extra_links}}},
  "lengths": {{"O1-A": 0.1, "A-B": 0.35, "O3-B": 0.3}},
  "input": {{"link": "1", "pivot": "O1", "angle": 45, "omega": 10}}{positions}}}"#
    )
}

#[test]
fn the_base_scene_solves() {
    assert_eq!(pipeline(&four_bar("", "", "")).unwrap(), 3);
}

#[test]
fn fixtures_and_stress_catalogue_never_panic() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures");
    for dir in [root.clone(), root.join("stress")] {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "json") && !p.ends_with("004_table1.json") {
                let text = std::fs::read_to_string(&p).unwrap();
                // Either outcome is fine; reaching here without a panic is the test.
                let _ = pipeline(&text);
            }
        }
    }
}

#[test]
fn limit_file_length() {
    let mut text = four_bar("", "", "");
    text.push_str(&" ".repeat(MAX_FILE_BYTES + 1 - text.len()));
    assert_eq!(text.len(), MAX_FILE_BYTES + 1);
    let e = rejected(&text);
    assert!(
        e.contains(&format!("the file has {} bytes", MAX_FILE_BYTES + 1))
            && e.contains(&format!("at most {MAX_FILE_BYTES}")),
        "{e}"
    );
    // Exactly at the limit the file is read.
    text.pop();
    assert!(Scene::from_json(&text).is_ok());
}

#[test]
fn limit_points() {
    let mut extra = String::new();
    for k in 0..=MAX_POINTS - 4 {
        write!(extra, r#", "P{k}": [{k}, 1]"#).unwrap();
    }
    let e = rejected(&four_bar(&extra, "", ""));
    assert!(
        e.contains(&format!(
            "/points: {} points; at most {MAX_POINTS}",
            MAX_POINTS + 1
        )),
        "{e}"
    );
}

#[test]
fn limit_links() {
    let mut extra = String::new();
    for k in 4..=MAX_LINKS {
        write!(extra, r#", "{k}": {{"points": ["A", "B"]}}"#).unwrap();
    }
    let e = rejected(&four_bar("", &extra, ""));
    assert!(
        e.contains(&format!(
            "/links: {} links; at most {MAX_LINKS}",
            MAX_LINKS + 1
        )),
        "{e}"
    );
}

#[test]
fn limit_positions_list() {
    let list = vec!["45"; MAX_POSITIONS + 1].join(",");
    let e = rejected(&four_bar(
        "",
        "",
        &format!(r#", "positions": {{"angles": [{list}]}}"#),
    ));
    assert!(
        e.contains(&format!(
            "/positions/angles: {} positions; at most {MAX_POSITIONS}",
            MAX_POSITIONS + 1
        )),
        "{e}"
    );
}

/// A count is made step by step as the sweep goes (no list is read), so
/// it may pass the lists' limit; beyond `MAX_COUNT` it is refused.
#[test]
fn limit_positions_count() {
    let scene = four_bar(
        "",
        "",
        &format!(r#", "positions": {{"count": {}}}"#, MAX_POSITIONS + 1),
    );
    assert!(Scene::from_json(&scene).is_ok());
    let e = rejected(&four_bar(
        "",
        "",
        &format!(r#", "positions": {{"count": {}}}"#, MAX_COUNT + 1),
    ));
    assert!(
        e.contains(&format!(
            "/positions/count: expected a whole number from 1 to {MAX_COUNT}"
        )),
        "{e}"
    );
}

#[test]
fn limit_magnitude() {
    let text = four_bar("", "", "").replace(r#""omega": 10"#, r#""omega": 1e101"#);
    let e = rejected(&text);
    assert!(
        e.contains("/input/omega") && e.contains(&format!("{MAX_MAGNITUDE:e}")),
        "{e}"
    );
}

/// Found by the `shape` fuzz target: a point whose two reference points
/// coincide (C drawn at A, D placed by its lengths to A and C) was placed
/// at NaN; it is a clear error naming the point.
#[test]
fn coincident_references_are_an_error_not_nan() {
    let text = r#"{"mechplan": 1,
      "points": {"O": [0, 0], "A": [0.1, 0], "B": [0.5, 0], "C": [0.1, 0], "D": [0.3, 0.2], "Q": [0.6, 0]},
      "links": {"0": {"points": ["O", "Q"]}, "1": {"points": ["O", "A"]},
                "2": {"points": ["A", "B", "C", "D"]}, "3": {"points": ["Q", "B"]}},
      "lengths": {"A-D": 0.28, "C-D": 0.28},
      "input": {"link": "1", "pivot": "O", "angle": 0, "omega": 1}}"#;
    let e = pipeline(text).unwrap_err().to_string();
    assert!(
        e.contains("/links/2/points/3")
            && e.contains("\"D\" cannot be placed")
            && e.contains("coincide"),
        "{e}"
    );
}

/// The DXF answer reader (fuzz target `dxf_answer`, CI 2026-11-29): a
/// file ending in a SECTION with neither a name nor a body sliced past
/// its end; now an answer refused with a message.
#[test]
fn dxf_answer_ending_in_a_bare_section_is_refused() {
    let study = mechplan::Study::from_json(mechplan::DEFAULT_SCENE).unwrap();
    let solution = study.solve().unwrap();
    for text in ["   0\nSECTION\n  ", "0\nSECTION", "0\nSECTION\n2\nENTITIES"] {
        let req = mechplan::CheckRequest::default();
        let e = solution
            .check_answer(text, "answer.dxf", true, &req)
            .err()
            .unwrap_or_else(|| panic!("{text:?} read as an answer"));
        assert!(e.to_string().contains("answer.dxf"), "{e}");
    }
}
