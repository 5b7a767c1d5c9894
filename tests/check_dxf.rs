//! DXF answers (docs/check.md, "DXF answers"): plans drawn as a CAD saves
//! them — R12, R2000, R2018; LINE, LWPOLYLINE, POLYLINE; TEXT, MTEXT;
//! inside a block; far from the origin; an R12 file in code page 1251 with
//! a Cyrillic scale — made with ezdxf (tests/dxf_answer.py) from a
//! fixture's plan as `mechplan solve` gives it, are read and graded
//! exactly as their JSON twins, a right one and a wrong one; bad DXF files
//! are refused (status 2) with what and where named.

mod common;

use serde_json::{Value, json};
use std::path::Path;
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
/// answer's /points/b, a drawing's "dxf: label b"), their keys' spelling
/// (n_2, n2), a drawing's notes, and numbers within
/// 1e-6 (a CAD's coordinates are rounded in the file's text); a
/// tolerance of the JSON twin `a` may be wider than the drawing's by the
/// rounding of its typed coordinates (to 0.1 mm: by up to 0.071 mm),
/// which a drawing has not.
fn alike(a: &Value, b: &Value, at: &str) {
    // A point's key is its name as the student spells it: a drawing's
    // label s_2, "s 2", s₂ is read as s2, the plan's n_2 as n2.
    if at.ends_with("/key")
        && let (Some(p), Some(q)) = (a.as_str(), b.as_str())
    {
        assert_eq!(p.replace('_', ""), q.replace('_', ""), "at {at}");
        return;
    }
    if at.ends_with("/tolerance")
        && let (Some(p), Some(q)) = (a.as_f64(), b.as_f64())
    {
        assert!(p >= q - 1e-9 && p - q <= 0.0708, "at {at}: {p} vs {q}");
        return;
    }
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            // A drawing's notes on what its reading left out are the
            // drawing's own; the grading is compared.
            let keys = |m: &serde_json::Map<String, Value>| {
                m.keys()
                    .filter(|k| *k != "pointer" && *k != "notes")
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
    let dir = common::fresh("dxf", fixture);
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

/// The plan `kind` ("velocity", "acceleration") of `fixture` at
/// `position` as `solve` gives it: its points and μ.
fn plan_of(fixture: &str, position: usize, kind: &str) -> (serde_json::Map<String, Value>, f64) {
    let (code, out, err) = run(&["solve", &scene(fixture), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let at = v["positions"].as_array().unwrap().iter();
    let p = &at.clone().find(|p| p["position"] == position).unwrap()["plans"][kind];
    (
        p["points"].as_object().unwrap().clone(),
        p["mu"].as_f64().unwrap(),
    )
}

/// Each habit (`specs`: a name and what tests/dxf_answer.py draws) of a
/// right plan and of a wrong one (point `wrong` reflected through the
/// pole) of `kind` is graded exactly as its JSON twin; the reports of
/// the wrong ones are returned (with their habit's name) for what they
/// note.
fn habits(
    fixture: &str,
    position: usize,
    kind: &str,
    wrong: &str,
    specs: Vec<(String, Value)>,
) -> Vec<(String, Value)> {
    let dir = common::fresh("dxf", &format!("{fixture}-{kind}-habits"));
    let (points, mu) = plan_of(fixture, position, kind);
    let mut bad = points.clone();
    let p = bad[wrong].as_array().unwrap().clone();
    bad[wrong] = json!([-p[0].as_f64().unwrap(), -p[1].as_f64().unwrap()]);
    let mut reports = Vec::new();
    for (tag, pts, status) in [("right", &points, 0), ("wrong", &bad, 1)] {
        let answer = json!({"plan": kind, "position": position, "mu": mu, "points": pts});
        let twin = dir.join(format!("{tag}.json"));
        std::fs::write(&twin, answer.to_string()).unwrap();
        let (code, expected) = report(fixture, &twin, position);
        assert_eq!(code, status, "{tag} JSON twin: {expected}");
        for (name, spec) in &specs {
            let mut spec = spec.clone();
            spec["points"] = json!(pts);
            let path = dir.join(format!("{tag}-{name}.dxf"));
            ezdxf(&path, spec);
            let (code, got) = report(fixture, &path, position);
            assert_eq!(code, status, "{tag} {name}: {got}");
            alike(&expected, &got, &format!("{tag} {name}"));
            if tag == "wrong" {
                reports.push((name.clone(), got));
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    reports
}

/// A spec of tests/dxf_answer.py: `base` with `extra`'s keys over it.
fn with(base: &Value, extra: Value) -> Value {
    let mut v = base.clone();
    for (k, x) in extra.as_object().unwrap() {
        v[k] = x.clone();
    }
    v
}

/// Habit 1: the pole as books and students letter it — P, p, p_v, pv,
/// "p v", pᵥ, p\S^v; (stacked), р typed in the Cyrillic layout, π (its
/// scale naming the velocity plan), π in an MTEXT with its font's codes — each read as the velocity
/// plan's pole; π alone (the scale names no plan), π_a, p_a, pa, "p a",
/// pₐ, π in an MTEXT with font codes as the acceleration plan's; each
/// graded as its JSON twin.
#[test]
fn the_pole_lettered_as_books_and_students_do_reads_as_the_json_twin() {
    let (_, mu_v) = plan_of("four_bar", 1, "velocity");
    let text = |pole: &str, scale: String| json!({"version": "R2018", "lines": "line", "texts": "text", "scale": scale, "origin": [150, 150], "pole": pole});
    let mtext = |pole: &str, scale: String| json!({"version": "R2018", "lines": "lwpolyline", "texts": "mtext", "scale": scale, "origin": [150, 150], "pole": pole, "font": "\\fArial|b0|i1|c0|p34;"});
    let sv = || format!("μv = {mu_v} (m/s)/mm");
    let velocity: Vec<(String, Value)> = vec![
        ("P".into(), text("P", sv())),
        ("p".into(), text("p", sv())),
        ("p_v".into(), text("p_v", sv())),
        ("pv".into(), text("pv", sv())),
        ("p_space_v".into(), text("p v", sv())),
        ("p_unicode_v".into(), text("pᵥ", sv())),
        ("p_stacked_v".into(), mtext("p\\S^v;", sv())),
        (
            "pi_r12".into(),
            with(&text("π", sv()), json!({"version": "R12"})),
        ),
        ("pi_mtext_font".into(), mtext("π", sv())),
        // Typed in the Cyrillic layout.
        ("p_cyrillic".into(), text("р", sv())),
    ];
    let n = velocity.len();
    habits("four_bar", 1, "velocity", "b", velocity);
    // An acceleration plan whose points stand apart by more than a
    // label's reach (15.6 mm at the least).
    let (_, mu_a) = plan_of("slider_driven_rocker", 2, "acceleration");
    let sa = || format!("μ = {mu_a} (m/s²)/mm");
    let acceleration: Vec<(String, Value)> = vec![
        ("pi".into(), text("π", sa())),
        ("pi_a".into(), text("π_a", sa())),
        ("p_a".into(), text("p_a", sa())),
        ("pa".into(), text("pa", sa())),
        ("p_space_a".into(), text("p a", sa())),
        ("p_unicode_a".into(), text("pₐ", sa())),
        ("pi_mtext_font".into(), mtext("π", sa())),
    ];
    let m = acceleration.len();
    habits("slider_driven_rocker", 2, "acceleration", "b", acceleration);
    eprintln!("habit 1 (the pole): {} of {} files read", n + m, n + m);
}

/// Habit 2: a point's index in every form — "s 2", s_2, s_{2}, s₂, MTEXT
/// stacked either way (s\S^2;, s\S2^;) — read as s2, graded as the JSON
/// twin (the six-link's s2, s4 and d_0).
#[test]
fn labels_with_an_index_in_every_form_read_as_the_json_twin() {
    let (_, mu) = plan_of("six_link_fig2_10", 6, "velocity");
    let base = json!({"version": "R2018", "lines": "line", "texts": "text", "scale": format!("μv = {mu} (m/s)/mm"), "origin": [150, 150], "pole": "p_v"});
    let mut specs: Vec<(String, Value)> = Vec::new();
    for index in ["space", "underscore", "braces", "unicode"] {
        for texts in ["text", "mtext"] {
            specs.push((
                format!("{index}_{texts}"),
                with(&base, json!({"index": index, "texts": texts})),
            ));
        }
    }
    specs.push((
        "stacked_mtext".into(),
        with(&base, json!({"index": "stacked", "texts": "mtext"})),
    ));
    let n = specs.len();
    habits("six_link_fig2_10", 6, "velocity", "c", specs);
    eprintln!("habit 2 (indices): {n} of {n} files read");
}

/// Habits 3 and 4: a plan on a sheet — the sheet's border and frame
/// (A4 … A0), a title block of lines touching the frame filled with its
/// texts (a group, "Лист 3", the format "A3" beside the frame's corner,
/// the litera "У"), captions beside the plan (one within a label's reach
/// of a point, the scale written in words), hatching, a dimension of a
/// vector, construction arcs and circles and a polyline's bulge whose end
/// stands at a label — is graded as its JSON twin; what was left out is
/// noted in the report (JSON "notes", and the text's "note:" lines),
/// never refused.
#[test]
fn a_plan_on_a_sheet_with_its_frame_title_block_and_construction_reads_as_the_json_twin() {
    let (points, mu) = plan_of("four_bar", 1, "velocity");
    let b = points["b"].as_array().unwrap();
    let (bx, by) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    let captions = json!([
        ["Velocity plan, position 1", 10, -60],
        ["Scale of velocities: 0.005 (m/s) in 1 mm", 10, -70],
        // Beside the point b, nearer to its end than b's own label.
        ["(fig. 3)", bx + 1.0, by - 3.0],
    ]);
    // The scale in a sentence of a Cyrillic title, in code page 1251.
    let mut in_words = captions.clone();
    in_words
        .as_array_mut()
        .unwrap()
        .push(json!(["Масштаб μv = 0,005 (м/с)/мм", 10, -80]));
    let base = json!({"version": "R2018", "lines": "line", "texts": "text", "scale": format!("μv = {mu} (m/s)/mm"), "origin": [300, 400], "pole": "p_v", "captions": captions});
    let mut specs: Vec<(String, Value)> = Vec::new();
    for sheet in ["A4", "A3", "A2", "A1", "A0"] {
        specs.push((
            format!("sheet_{sheet}"),
            with(&base, json!({"sheet": sheet})),
        ));
    }
    specs.push((
        "sheet_mtext_lwpolyline_pi".into(),
        with(
            &base,
            json!({"sheet": "A3", "texts": "mtext", "lines": "lwpolyline", "pole": "π"}),
        ),
    ));
    specs.push((
        "r12_cp1251_sheet_block".into(),
        with(&base, json!({"version": "R12", "sheet": "A3", "block": true, "codepage": "ANSI_1251", "encoding": "cp1251", "scale": null, "captions": in_words})),
    ));
    specs.push((
        "hatch_dimension_arcs".into(),
        with(
            &base,
            json!({"hatch": true, "dimension": true, "arcs": true}),
        ),
    ));
    specs.push((
        "everything_at_once".into(),
        with(&base, json!({"sheet": "A2", "hatch": true, "dimension": true, "arcs": true, "texts": "mtext"})),
    ));
    let n = specs.len();
    let reports = habits("four_bar", 1, "velocity", "b", specs);
    for (name, r) in &reports {
        let notes: Vec<&str> = r["notes"]
            .as_array()
            .unwrap_or_else(|| panic!("{name}: no notes in {r}"))
            .iter()
            .map(|n| n.as_str().unwrap())
            .collect();
        let notes = notes.join("\n");
        if name.contains("sheet") || name.contains("everything") {
            for left_out in ["Machine Design, gr. 41", "Лист 3", "У", "(fig. 3)"] {
                assert!(notes.contains(left_out), "{name}: {notes}");
            }
            assert!(notes.contains("\"A3\""), "{name}: {notes}");
        } else {
            assert!(notes.contains("(fig. 3)"), "{name}: {notes}");
        }
    }
    eprintln!("habits 3 and 4 (a sheet): {n} of {n} files read");
}

/// Both plans of a position on one sheet, the velocity plan's pole p_v
/// and the acceleration plan's π: each read when asked (`--plan`), the
/// other plan's pole and letters left out and noted — graded as the JSON
/// twin of the plan asked.
#[test]
fn two_plans_on_one_sheet_each_read_when_asked() {
    let (v, mu_v) = plan_of("slider_driven_rocker", 2, "velocity");
    let (a, mu_a) = plan_of("slider_driven_rocker", 2, "acceleration");
    let dir = common::fresh("dxf", "two_plans");
    let path = dir.join("both.dxf");
    ezdxf(
        &path,
        json!({"version": "R2018", "lines": "line", "texts": "text", "scale": format!("μv = {mu_v} (m/s)/mm"), "origin": [200, 200], "pole": "p_v", "points": v,
               "second": {"pole": "π", "points": a, "offset": [300, 0]}, "captions": [[format!("μa = {mu_a} (m/s²)/mm"), 300, -60]]}),
    );
    for (kind, points, mu) in [("velocity", &v, mu_v), ("acceleration", &a, mu_a)] {
        let twin = dir.join(format!("{kind}.json"));
        std::fs::write(
            &twin,
            json!({"plan": kind, "position": 2, "mu": mu, "points": points}).to_string(),
        )
        .unwrap();
        let (code, expected) = report("slider_driven_rocker", &twin, 2);
        // μ is given: the sheet states two.
        let (got_code, out, err) = run(&[
            "check",
            &scene("slider_driven_rocker"),
            path.to_str().unwrap(),
            "--position",
            "2",
            "--plan",
            kind,
            "--mu",
            &mu.to_string(),
            "--format",
            "json",
        ]);
        assert_eq!(got_code, code, "{kind}: {out}{err}");
        let got: Value = serde_json::from_str(&out).unwrap();
        alike(&expected, &got, kind);
        let notes = got["notes"].to_string();
        let other_pole = if kind == "velocity" { "π" } else { "p_v" };
        assert!(notes.contains(other_pole), "{kind}: {notes}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The report in words tells what was left out.
#[test]
fn the_text_report_notes_what_was_left_out() {
    let dir = common::fresh("dxf", "notes");
    let (points, mu) = plan_of("four_bar", 1, "velocity");
    let path = dir.join("sheet.dxf");
    ezdxf(
        &path,
        json!({"version": "R2018", "lines": "line", "texts": "text", "scale": format!("μv = {mu} (m/s)/mm"), "origin": [300, 400], "pole": "π", "sheet": "A3", "points": points}),
    );
    let (code, out, err) = run(&[
        "check",
        &scene("four_bar"),
        path.to_str().unwrap(),
        "--position",
        "1",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("note: texts read as no plan letter, left out:") && out.contains("\"Лист 3\""),
        "{out}"
    );
    assert!(
        out.contains("note: letters next to no end of the plan's lines"),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Refused only where the plan cannot be found, saying what to change:
/// a sheet whose texts hold no pole (the texts it read named), a pole's
/// letter beside no line's end, a pole with no letter beside its plan's
/// ends (only a frame's corner near one).
#[test]
fn a_drawing_without_its_plan_is_refused_saying_what_to_change() {
    let dir = common::fresh("dxf", "no_plan");
    let f = dir.join("answer.dxf");
    let text =
        |s: &str, x: f64, y: f64| format!("0\nTEXT\n8\n0\n10\n{x}\n20\n{y}\n40\n3.5\n1\n{s}\n");
    let line = |x0: f64, y0: f64, x1: f64, y1: f64| {
        format!("0\nLINE\n8\n0\n10\n{x0}\n20\n{y0}\n11\n{x1}\n21\n{y1}\n")
    };
    let frame = [
        line(0.0, 0.0, 420.0, 0.0),
        line(420.0, 0.0, 420.0, 297.0),
        line(420.0, 297.0, 0.0, 297.0),
        line(0.0, 297.0, 0.0, 0.0),
    ]
    .concat();
    // No pole: the texts read are named.
    let body = format!(
        "0\nSECTION\n2\nENTITIES\n{frame}{}{}{}0\nENDSEC\n",
        line(100.0, 100.0, 150.0, 130.0),
        text("Лист 3", 300.0, 10.0),
        text("mu = 0.005", 300.0, 30.0)
    );
    let err = refused(&f, hand(&body).as_bytes(), &["--position", "1"]);
    assert!(
        err.contains("no pole")
            && err.contains("π")
            && err.contains("\"Лист 3\"")
            && err.contains("label the pole"),
        "{err}"
    );
    // The pole's letter beside no line's end.
    let body = format!(
        "0\nSECTION\n2\nENTITIES\n{frame}{}{}{}0\nENDSEC\n",
        line(100.0, 100.0, 150.0, 130.0),
        text("p_v", 200.0, 200.0),
        text("mu = 0.005", 300.0, 30.0)
    );
    let err = refused(&f, hand(&body).as_bytes(), &["--position", "1"]);
    assert!(
        err.contains("\"p_v\" is not next to any line's end") && err.contains("within 8 mm"),
        "{err}"
    );
    // The pole and a vector, its letter beside the frame's corner only.
    let body = format!(
        "0\nSECTION\n2\nENTITIES\n{frame}{}{}{}{}0\nENDSEC\n",
        line(100.0, 100.0, 150.0, 130.0),
        text("p_v", 101.5, 101.5),
        text("b", 415.0, 290.0),
        text("mu = 0.005", 300.0, 30.0)
    );
    let err = refused(&f, hand(&body).as_bytes(), &["--position", "1"]);
    assert!(
        err.contains("no point of the plan is labelled") && err.contains("\"b\""),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
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
    let dir = common::fresh("dxf", "bad");
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
    let dir = common::fresh("dxf", "doc");
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
    let dir = common::fresh("dxf", "overlay");
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
    let dir = common::fresh("dxf", "doc_marked");
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
