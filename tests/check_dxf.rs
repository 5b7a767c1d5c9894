//! DXF answers (docs/check.md, "DXF answers"): plans drawn as a CAD saves
//! them — R12, R2000, R2018; LINE, LWPOLYLINE, POLYLINE; TEXT, MTEXT;
//! inside a block; far from the origin; an R12 file in code page 1251 with
//! a Cyrillic scale — made with ezdxf (tests/dxf_answer.py) from a
//! fixture's plan as `mechplan solve` gives it, are read and graded
//! exactly as their JSON twins, a right one and a wrong one; bad DXF files
//! are refused (status 2) with what and where named.

mod common;

use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// A fresh folder for one test.
fn fresh(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mechplan-dxf-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn scene(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

/// The velocity plan of `fixture` at `position` (its number, as the result
/// file and the sheets give it: these count sweeps from 0) as `solve`
/// gives it: its points (mm from the pole, y up) and μ.
fn plan(fixture: &str, position: usize) -> (serde_json::Map<String, Value>, f64) {
    let (code, out, err) = run(&["solve", &scene(fixture), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let at = v["positions"].as_array().unwrap().iter();
    let p = &at.clone().find(|p| p["position"] == position).unwrap()["plans"]["velocity"];
    (
        p["points"].as_object().unwrap().clone(),
        p["mu"].as_f64().unwrap(),
    )
}

/// A DXF written by tests/dxf_answer.py from `spec` (its "path" set).
fn ezdxf(path: &Path, mut spec: Value) {
    spec["path"] = json!(path.to_str().unwrap());
    python("dxf_answer.py", &spec);
}

/// What the test script `tests/{script}` (python3 with ezdxf) prints,
/// given `spec` on its standard input; a panic with its errors when it
/// fails.
fn python(script: &str, spec: &Value) -> Vec<u8> {
    let mut child = common::python_with_ezdxf()
        .arg(format!("{}/tests/{script}", env!("CARGO_MANIFEST_DIR")))
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("python3 (with ezdxf: the system's, or pip's into target/pydeps)");
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(spec.to_string().as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "tests/{script} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// `check`'s JSON report of an answer at `position`, and its status.
fn report(fixture: &str, answer: &Path, position: usize) -> (i32, Value) {
    let (code, out, err) = run(&[
        "check",
        &scene(fixture),
        answer.to_str().unwrap(),
        "--position",
        &position.to_string(),
        "--format",
        "json",
    ]);
    assert!(code == 0 || code == 1, "status {code}: {err}");
    (code, serde_json::from_str(&out).unwrap())
}

/// The same report: every value alike but the items' pointers (a JSON
/// answer's /points/b, a drawing's "dxf: label b") and numbers within
/// 1e-6 (a CAD's coordinates are rounded in the file's text); a
/// tolerance of the JSON twin `a` may be wider than the drawing's by the
/// rounding of its typed coordinates (to 0.1 mm: by up to 0.071 mm),
/// which a drawing has not.
fn alike(a: &Value, b: &Value, at: &str) {
    if at.ends_with("/tolerance")
        && let (Some(p), Some(q)) = (a.as_f64(), b.as_f64())
    {
        assert!(p >= q - 1e-9 && p - q <= 0.0708, "at {at}: {p} vs {q}");
        return;
    }
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            let keys = |m: &serde_json::Map<String, Value>| {
                m.keys()
                    .filter(|k| *k != "pointer")
                    .cloned()
                    .collect::<Vec<_>>()
            };
            assert_eq!(keys(x), keys(y), "at {at}");
            for k in keys(x) {
                alike(&x[&k], &y[&k], &format!("{at}/{k}"));
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "at {at}");
            for (k, (p, q)) in x.iter().zip(y).enumerate() {
                alike(p, q, &format!("{at}/{k}"));
            }
        }
        (Value::Number(p), Value::Number(q)) => {
            let (p, q) = (p.as_f64().unwrap(), q.as_f64().unwrap());
            assert!(
                (p - q).abs() <= 1e-6 * (1.0 + p.abs()),
                "at {at}: {p} vs {q}"
            );
        }
        _ => assert_eq!(a, b, "at {at}"),
    }
}

/// The ways a CAD saves a plan, each read as its JSON twin.
fn variants(mu: f64) -> Vec<(&'static str, Value)> {
    let scale = format!("μv = {mu} (m/s)/mm");
    let comma = format!("μv = {} (м/с)/мм", mu.to_string().replace('.', ","));
    vec![
        (
            "r12_line_text",
            json!({"version": "R12", "lines": "line", "texts": "text", "scale": scale, "origin": [150, 150]}),
        ),
        (
            "r2000_lwpolyline_mtext_frame",
            json!({"version": "R2000", "lines": "lwpolyline", "texts": "mtext", "scale": scale, "origin": [210, 150], "frame": true}),
        ),
        (
            "r2018_polyline_text",
            json!({"version": "R2018", "lines": "polyline", "texts": "text", "scale": scale, "origin": [150, 150]}),
        ),
        (
            "r2018_block_far_from_the_origin",
            json!({"version": "R2018", "lines": "line", "texts": "mtext", "scale": scale, "origin": [1.0e6, -2.5e6], "block": true}),
        ),
        (
            "r2000_pole_p_the_scale_names_the_plan",
            json!({"version": "R2000", "lines": "line", "texts": "text", "scale": scale, "origin": [150, 150], "pole": "p"}),
        ),
        (
            "r12_cp1251_block",
            json!({"version": "R12", "lines": "polyline", "texts": "text", "scale": comma, "origin": [150, 150], "block": true, "codepage": "ANSI_1251", "encoding": "cp1251"}),
        ),
    ]
}

/// Each variant of a right plan and of a wrong one (point `wrong`
/// reflected through the pole, a vector drawn the wrong way) is graded
/// exactly as its JSON twin.
fn twins(fixture: &str, position: usize, wrong: &str) {
    let dir = fresh(fixture);
    let (points, mu) = plan(fixture, position);
    let mut bad = points.clone();
    let p = bad[wrong].as_array().unwrap().clone();
    bad[wrong] = json!([-p[0].as_f64().unwrap(), -p[1].as_f64().unwrap()]);
    for (tag, pts, status) in [("right", &points, 0), ("wrong", &bad, 1)] {
        let answer = json!({"plan": "velocity", "position": position, "mu": mu, "points": pts});
        let twin = dir.join(format!("{tag}.json"));
        std::fs::write(&twin, answer.to_string()).unwrap();
        let (code, expected) = report(fixture, &twin, position);
        assert_eq!(code, status, "{tag} JSON twin");
        for (name, mut spec) in variants(mu) {
            spec["points"] = json!(pts);
            if spec.get("pole").is_none() {
                spec["pole"] = json!("p_v");
            }
            let path = dir.join(format!("{tag}-{name}.dxf"));
            ezdxf(&path, spec);
            let (code, got) = report(fixture, &path, position);
            assert_eq!(code, status, "{tag} {name}");
            alike(&expected, &got, &format!("{tag} {name}"));
        }
    }
    // A group of the JSON and DXF answers: each graded as alone.
    let out = dir.join("out");
    let (code, _, err) = run(&[
        "check",
        &scene(fixture),
        dir.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--position",
        &position.to_string(),
    ]);
    assert_eq!(code, 1, "{err}");
    let book = std::fs::read_to_string(out.join("gradebook.csv"))
        .or_else(|_| {
            std::fs::read_dir(&out)
                .unwrap()
                .map(|e| e.unwrap().path())
                .find(|p| p.extension().is_some_and(|x| x == "csv"))
                .map(std::fs::read_to_string)
                .unwrap()
        })
        .unwrap();
    assert_eq!(
        book.lines().filter(|l| l.contains(".dxf")).count(),
        2 * variants(mu).len(),
        "{book}"
    );
    // Each DXF answer's marked copy beside its overlay.
    let copies = std::fs::read_dir(out.join("overlays"))
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "dxf")
        })
        .count();
    assert_eq!(copies, 2 * variants(mu).len());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn dxf_answers_of_the_four_bar_read_as_their_json_twins() {
    twins("four_bar", 1, "b");
}

/// Labels with subscripts (s2, s4: `s\S^2;` in MTEXT) and more points (a
/// position where no two are closer than a label's snapping distance).
#[test]
fn dxf_answers_of_the_six_link_read_as_their_json_twins() {
    twins("six_link_fig2_10", 6, "c");
}

/// A DXF written by hand: its groups, one per line pair.
fn hand(sections: &str) -> String {
    format!("0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n0\nENDSEC\n{sections}0\nEOF\n")
}

fn refused(file: &Path, bytes: &[u8], extra: &[&str]) -> String {
    std::fs::write(file, bytes).unwrap();
    let mut args = vec!["check", "fixtures/four_bar.json", file.to_str().unwrap()];
    args.extend_from_slice(extra);
    let (code, out, err) = run(&args);
    assert_eq!(code, 2, "{out}{err}");
    err
}

#[test]
fn bad_dxf_answers_are_refused_naming_what_and_where() {
    let dir = fresh("bad");
    let f = dir.join("answer.dxf");
    // Binary DXF.
    let err = refused(&f, b"AutoCAD Binary DXF\r\n\x1a\x00\x00\x00SECTION", &[]);
    assert!(
        err.contains("binary DXF") && err.contains("answer.dxf"),
        "{err}"
    );
    // Binary, named otherwise: found by its content.
    let err = refused(
        &dir.join("answer.bin"),
        b"AutoCAD Binary DXF\r\n\x1a\x00",
        &[],
    );
    assert!(err.contains("binary DXF"), "{err}");
    // Empty.
    let err = refused(&f, b"", &[]);
    assert!(
        err.contains("not an ASCII DXF") && err.contains("empty"),
        "{err}"
    );
    // No texts: lines only.
    let lines =
        hand("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n5\n0\nENDSEC\n");
    let err = refused(&f, lines.as_bytes(), &["--mu", "0.005"]);
    assert!(err.contains("no texts"), "{err}");
    // Nothing at all drawn.
    let err = refused(&f, hand("").as_bytes(), &[]);
    assert!(err.contains("no lines and no texts"), "{err}");
    // Letters that are not the scene's.
    let mut body = String::from("0\nSECTION\n2\nENTITIES\n");
    for (name, x, y) in [("p_v", 0.0, 0.0), ("q", 30.0, 10.0), ("z", -20.0, 25.0)] {
        if name != "p_v" {
            body.push_str(&format!("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n{x}\n21\n{y}\n"));
        }
        body.push_str(&format!(
            "0\nTEXT\n8\n0\n10\n{}\n20\n{}\n40\n3.5\n1\n{name}\n",
            x + 1.5,
            y + 1.5
        ));
    }
    body.push_str("0\nTEXT\n8\n0\n10\n0\n20\n-40\n40\n3.5\n1\nmu = 0.005\n0\nENDSEC\n");
    let err = refused(&f, hand(&body).as_bytes(), &["--position", "2"]);
    assert!(
        err.contains("dxf: label q") || err.contains("dxf: label z"),
        "{err}"
    );
    // An entity that cannot be read: where it is, by line and handle.
    let bad = hand(
        "0\nSECTION\n2\nENTITIES\n0\nLINE\n5\n2F\n8\n0\n10\nabc\n20\n0\n11\n1\n21\n1\n0\nENDSEC\n",
    );
    let err = refused(&f, bad.as_bytes(), &[]);
    assert!(
        err.contains("LINE at line") && err.contains("handle 2F") && err.contains("\"abc\""),
        "{err}"
    );
    // Not a group code where one should be.
    let err = refused(&f, b"0\nSECTION\n2\nENTITIES\nLINE\n", &[]);
    assert!(
        err.contains("line 5") && err.contains("group code"),
        "{err}"
    );
    // Blocks nested too deep: B0 inserts B1 … B29 holds a line.
    let mut blocks = String::from("0\nSECTION\n2\nBLOCKS\n");
    for k in 0..30 {
        blocks.push_str(&format!("0\nBLOCK\n8\n0\n2\nB{k}\n70\n0\n10\n0\n20\n0\n"));
        if k < 29 {
            blocks.push_str(&format!("0\nINSERT\n8\n0\n2\nB{}\n10\n0\n20\n0\n", k + 1));
        } else {
            blocks.push_str("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n1\n");
        }
        blocks.push_str("0\nENDBLK\n8\n0\n");
    }
    blocks.push_str(
        "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nINSERT\n8\n0\n2\nB0\n10\n0\n20\n0\n0\nENDSEC\n",
    );
    let err = refused(&f, hand(&blocks).as_bytes(), &[]);
    assert!(err.contains("nested") || err.contains("deep"), "{err}");
    assert!(
        err.contains("INSERT at line") && err.contains("B16"),
        "{err}"
    );
    // Blocks that expand to millions of entities: 8 levels of 10 inserts.
    let mut bomb = String::from("0\nSECTION\n2\nBLOCKS\n");
    for k in 0..8 {
        bomb.push_str(&format!("0\nBLOCK\n2\nB{k}\n10\n0\n20\n0\n"));
        for j in 0..10 {
            if k < 7 {
                bomb.push_str(&format!("0\nINSERT\n2\nB{}\n10\n{j}\n20\n0\n", k + 1));
            }
        }
        if k == 7 {
            bomb.push_str("0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n");
        }
        bomb.push_str("0\nENDBLK\n");
    }
    bomb.push_str(
        "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nB0\n10\n0\n20\n0\n0\nENDSEC\n",
    );
    let err = refused(&f, hand(&bomb).as_bytes(), &[]);
    assert!(err.contains("more than 1000000 entities"), "{err}");
    // A block that inserts itself.
    let cycle = hand(
        "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nA\n10\n0\n20\n0\n0\nINSERT\n2\nA\n10\n1\n20\n0\n0\nENDBLK\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nINSERT\n2\nA\n10\n0\n20\n0\n0\nENDSEC\n",
    );
    let err = refused(&f, cycle.as_bytes(), &[]);
    assert!(err.contains("deep"), "{err}");
    // A block the file does not define.
    let missing =
        hand("0\nSECTION\n2\nENTITIES\n0\nINSERT\n5\nA1\n2\nNOPE\n10\n0\n20\n0\n0\nENDSEC\n");
    let err = refused(&f, missing.as_bytes(), &[]);
    assert!(
        err.contains("\"NOPE\"") && err.contains("handle A1"),
        "{err}"
    );
    // Inches are converted, other units refused.
    let units = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n3\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nTEXT\n10\n0\n20\n0\n1\np_v\n0\nENDSEC\n0\nEOF\n";
    let err = refused(&f, units.as_bytes(), &[]);
    assert!(err.contains("$INSUNITS = 3"), "{err}");
    // Larger than an answer may be.
    let huge = hand(&"999\ncomment\n".repeat(1 << 20));
    let err = refused(&f, huge.as_bytes(), &[]);
    assert!(err.contains("at most"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The example of docs/check.md ("A DXF drawn in a CAD") is graded right,
/// its title left alone; with CRLF line ends too.
#[test]
fn the_documented_dxf_answer_is_right() {
    let text = common::dxf_block("docs/check.md");
    let dir = fresh("doc");
    for (name, text) in [
        ("lf.dxf", text.to_string()),
        ("crlf.dxf", text.replace('\n', "\r\n")),
    ] {
        let f = dir.join(name);
        std::fs::write(&f, text).unwrap();
        let (code, out, err) = run(&[
            "check",
            "fixtures/four_bar.json",
            f.to_str().unwrap(),
            "--position",
            "1",
        ]);
        assert_eq!(code, 0, "{name}: {out}{err}");
        assert!(out.contains("3 of 3 right"), "{out}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check --dxf`: the overlay written into a copy of the student's own
/// file, read back with ezdxf (tests/dxf_overlay.py) — R12, R2000 in code
/// page 1251 with CRLF line ends, R2018 inside a block far from the
/// origin: no audit error; the student's entities all there; a layer of
/// its own holding the right plan, each of its points at the place the
/// plan puts it from the student's pole (0.01 mm); the copy read again as
/// an answer graded as the original (the overlay's layer skipped); the
/// copy's line ends the original's. A JSON answer is refused.
#[test]
fn the_overlay_is_written_into_a_copy_of_the_students_dxf() {
    let dir = fresh("overlay");
    let (points, mu) = plan("six_link_fig2_10", 2);
    let mut wrong = points.clone();
    let c = wrong["c"].as_array().unwrap().clone();
    wrong["c"] = json!([c[0].as_f64().unwrap() + 8.0, c[1]]);
    let scale = format!("μv = {mu} (m/s)/mm");
    let comma = format!("μv = {} (м/с)/мм", mu.to_string().replace('.', ","));
    let cases = [
        (
            "r12",
            json!({"version": "R12", "lines": "line", "texts": "text", "scale": scale, "origin": [150, 150]}),
            false,
        ),
        (
            "r2000_cp1251",
            json!({"version": "R2000", "lines": "lwpolyline", "texts": "mtext", "scale": comma, "origin": [210, 150], "frame": true, "codepage": "ANSI_1251", "encoding": "cp1251"}),
            true,
        ),
        (
            "r2018_block_far",
            json!({"version": "R2018", "lines": "line", "texts": "mtext", "scale": scale, "origin": [1.0e6, -2.5e6], "block": true}),
            false,
        ),
    ];
    for (name, mut spec, crlf) in cases {
        spec["points"] = json!(wrong);
        spec["pole"] = json!("p_v");
        let answer = dir.join(format!("{name}.dxf"));
        ezdxf(&answer, spec.clone());
        if crlf {
            // The cp1251 bytes kept, each LF made CRLF.
            let bytes: Vec<u8> = std::fs::read(&answer)
                .unwrap()
                .iter()
                .flat_map(|&b| {
                    if b == b'\n' {
                        vec![b'\r', b'\n']
                    } else {
                        vec![b]
                    }
                })
                .collect();
            std::fs::write(&answer, bytes).unwrap();
        }
        let copy = dir.join(format!("{name}.marked.dxf"));
        let (code, _, err) = run(&[
            "check",
            &scene("six_link_fig2_10"),
            answer.to_str().unwrap(),
            "--position",
            "2",
            "--dxf",
            copy.to_str().unwrap(),
        ]);
        assert_eq!(code, 1, "{name}: {err}");
        // Where the right plan's points are in the file: the pole's place
        // plus the plan's millimetres (the files are in mm or unitless).
        let o = spec["origin"].as_array().unwrap();
        let (ox, oy) = (o[0].as_f64().unwrap(), o[1].as_f64().unwrap());
        let places: serde_json::Map<String, Value> = points
            .iter()
            .map(|(k, p)| {
                let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
                (k.clone(), json!([ox + x, oy + y]))
            })
            .collect();
        let read = overlay_read(&answer, &copy, &places);
        assert_eq!(read["audit_errors"], json!([]), "{name}: {read}");
        assert_eq!(read["original"], read["copy"], "{name}: {read}");
        assert_eq!(read["missing"], json!([]), "{name}: {read}");
        assert_eq!(read["layer_color"], json!(5), "{name}: {read}");
        let overlay = read["overlay"].as_object().unwrap();
        assert!(
            overlay.get("LINE").is_some() && overlay.get("TEXT").is_some(),
            "{name}: {read}"
        );
        if name == "r12" {
            assert!(!overlay.contains_key("LWPOLYLINE") && !overlay.contains_key("MTEXT"));
        }
        let bytes = std::fs::read(&copy).unwrap();
        let bare_lf = bytes
            .windows(2)
            .filter(|w| w[1] == b'\n' && w[0] != b'\r')
            .count();
        assert_eq!(bare_lf == 0, crlf, "{name}: line ends");
        // The marked copy read again is the student's drawing alone.
        let (c1, first) = report("six_link_fig2_10", &answer, 3);
        let (c2, again) = report("six_link_fig2_10", &copy, 3);
        assert_eq!(c1, c2);
        alike(&first, &again, name);
    }
    // A JSON answer has no file of the student's to copy.
    let json_answer = dir.join("a.json");
    std::fs::write(
        &json_answer,
        json!({"plan": "velocity", "mu": mu, "points": points}).to_string(),
    )
    .unwrap();
    let (code, _, err) = run(&[
        "check",
        &scene("six_link_fig2_10"),
        json_answer.to_str().unwrap(),
        "--dxf",
        dir.join("x.dxf").to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("dxf") && err.contains("--svg"), "{err}");
    assert!(!dir.join("x.dxf").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The marked copy of docs/check.md's example (R2000 with no TABLES and
/// no handles; its scale as a TEXT, which ezdxf reads without subclass
/// markers): the overlay's handles took the numbers ezdxf gives the
/// student's entities, whose audit dropped the student's lines. Marked
/// again, the copy holds one overlay, not two.
#[test]
fn the_documented_answer_is_marked_without_handles() {
    let text = common::dxf_block("docs/check.md");
    let mtext = "MTEXT\n100\nAcDbEntity\n8\nLETTERS\n100\nAcDbMText\n10\n150\n20\n100\n40\n3.5\n71\n1\n1\n{\\fArial|b0|i0;\\U+03BC\\S^v; = 0,005 (m/s)/mm}\n";
    assert!(text.contains(mtext));
    let text = text.replace(
        mtext,
        "TEXT\n8\nLETTERS\n10\n150\n20\n100\n40\n3.5\n1\n\\U+03BCv = 0,005 (m/s)/mm\n",
    );
    let dir = fresh("doc_marked");
    let answer = dir.join("answer.dxf");
    std::fs::write(&answer, &text).unwrap();
    let (points, _) = plan("four_bar", 1);
    let places: serde_json::Map<String, Value> = points
        .iter()
        .map(|(k, p)| {
            let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            (k.clone(), json!([200.0 + x, 150.0 + y]))
        })
        .collect();
    let mark = |from: &Path, to: &Path| {
        let (code, _, err) = run(&[
            "check",
            "fixtures/four_bar.json",
            from.to_str().unwrap(),
            "--position",
            "1",
            "--dxf",
            to.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
    };
    let (once, twice) = (dir.join("once.dxf"), dir.join("twice.dxf"));
    mark(&answer, &once);
    mark(&once, &twice);
    let read = overlay_read(&answer, &once, &places);
    assert_eq!(read["audit_errors"], json!([]), "{read}");
    assert_eq!(read["original"], read["copy"], "{read}");
    assert_eq!(read["missing"], json!([]), "{read}");
    let again = overlay_read(&answer, &twice, &places);
    assert_eq!(again["copy"], read["copy"], "{again}");
    assert_eq!(again["overlay"], read["overlay"], "{again}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// tests/dxf_overlay.py's report on a marked copy.
fn overlay_read(original: &Path, copy: &Path, points: &serde_json::Map<String, Value>) -> Value {
    let spec = json!({"original": original, "copy": copy, "points": points});
    serde_json::from_slice(&python("dxf_overlay.py", &spec)).unwrap()
}
