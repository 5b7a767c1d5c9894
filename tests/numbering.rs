//! One numbering of positions (issue 37): the number a sheet shows is the
//! number every file name, `--position`, result file, answer `position`,
//! check report, gradebook and handout uses — a `count` sweep from 0 (the
//! lecture's: position 0 the extreme position that starts the working
//! stroke), given input values from 1. Older answers and command lines
//! (a `count` sweep counted from 1) are read as before with
//! `"positions_from": 1` or `--positions-from 1`. An answer whose points
//! fit another position than it states, or its own with the crank turned
//! the other way, is graded at the position it states (wrong), the report
//! naming where they fit — never refused.

use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

/// The command's exit status, standard output and standard error.
fn run(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(EXE).args(args).output().unwrap();
    (
        o.status.code().unwrap(),
        String::from_utf8_lossy(&o.stdout).into(),
        String::from_utf8_lossy(&o.stderr).into(),
    )
}

/// A fresh folder of this test run.
fn fresh(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-numbering-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The heading of a drawn sheet, its tags dropped: "Plan of velocities,
/// position 3, φ1 = 145.8°".
fn heading(svg: &str) -> String {
    let start = svg.find("class=\"heading\"").expect("a heading");
    let end = start + svg[start..].find("</text>").unwrap();
    let mut out = String::new();
    let mut tag = false;
    for c in svg[start..end].chars().skip_while(|&c| c != '>').skip(1) {
        match c {
            '<' => tag = true,
            '>' => tag = false,
            c if !tag => out.push(c),
            _ => {}
        }
    }
    out
}

/// The position number and the crank's angle (degrees) a velocity sheet's
/// heading prints: "…, position N, φ1 = X°".
fn printed(svg: &str) -> (usize, f64) {
    let h = heading(svg);
    let rest = &h[h.find("position ").expect("a position in the heading") + 9..];
    let (n, rest) = rest.split_once(", φ1 = ").unwrap();
    (
        n.parse().unwrap(),
        rest.trim_end_matches('°').parse().unwrap(),
    )
}

/// The position of a solve JSON result whose `position` is `n`.
fn numbered(doc: &Value, n: usize) -> &Value {
    doc["positions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["position"] == n)
        .unwrap_or_else(|| panic!("no position {n} in the result file"))
}

/// The answer a careful student reads off the velocity plan of result
/// position `p` (every point of the plan, at its μ).
fn answer_of(p: &Value) -> Value {
    let plan = &p["plans"]["velocity"];
    json!({ "plan": "velocity", "mu": plan["mu"], "points": plan["points"] })
}

/// The velocity sheets a `draw` wrote into `dir`, each as the number its
/// file's name, its heading and the manifest give it (all three the same)
/// with the angle its heading prints.
fn sheets_drawn(dir: &Path) -> Vec<(usize, f64)> {
    let manifest: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sheets.json")).unwrap()).unwrap();
    let mut out = Vec::new();
    for sheet in manifest["sheets"].as_array().unwrap() {
        let file = sheet["file"].as_str().unwrap();
        let Some(n) = file.strip_prefix("velocity_") else {
            continue;
        };
        let n: usize = n.trim_end_matches(".svg").parse().unwrap();
        let (shown, phi) = printed(&std::fs::read_to_string(dir.join(file)).unwrap());
        assert_eq!(shown, n, "{file}: its heading");
        assert_eq!(sheet["position"], n, "{file}: the manifest");
        out.push((n, phi));
    }
    out.sort_by_key(|x| x.0);
    out
}

/// The number printed on the first and the last velocity sheet of a
/// `count` sweep of 12 (0 and 11) and of seven given angles (1 and 7),
/// typed back: the same position in `solve` (its table, JSON and CSV, by
/// the angle the sheet prints), `draw --position` (the same sheet), `check`
/// (an answer read off that position's plan, stating the number or given
/// `--position`: right, its report naming it), the gradebook, the handout
/// and `centres`.
#[test]
fn the_number_on_a_sheet_reaches_the_same_position_everywhere() {
    for (name, all) in [
        ("six_link_fig2_10", (0..12).collect::<Vec<usize>>()),
        ("prp_tangent_drive", (1..=7).collect()),
    ] {
        let dir = fresh(name);
        let sheets = dir.join("sheets");
        let (code, _, err) = run(&["draw", &scene(name), "-o", s(&sheets)]);
        assert_eq!(code, 0, "{err}");
        let drawn = sheets_drawn(&sheets);
        assert_eq!(drawn.iter().map(|x| x.0).collect::<Vec<_>>(), all, "{name}");
        let (_, json, _) = run(&["solve", &scene(name), "--format", "json"]);
        let doc: Value = serde_json::from_str(&json).unwrap();
        let (_, table, _) = run(&["solve", &scene(name)]);
        let (_, csv, _) = run(&["solve", &scene(name), "--format", "csv"]);
        let (_, html_out, _) = run(&["draw", &scene(name), "--html", "-o", s(&dir.join("html"))]);
        assert!(html_out.contains("handout.html"));
        let handout = std::fs::read_to_string(dir.join("html/handout.html")).unwrap();
        for &(n, phi) in [drawn[0], drawn[drawn.len() - 1]].iter() {
            let at = format!("{name} position {n}");
            // solve: the JSON, the table and the CSV at the sheet's angle.
            let p = numbered(&doc, n);
            let angle = p["input"]["angle"].as_f64().unwrap();
            assert!(
                (angle - phi).abs() < 0.05,
                "{at}: {angle} vs {phi} on the sheet"
            );
            let line = table
                .lines()
                .find(|l| l.starts_with(&format!("position {n}: φ1 = ")))
                .unwrap_or_else(|| panic!("{at}: no table heading"));
            assert!(line.contains(&format!("{angle:.3}°")), "{at}: {line}");
            let row = csv
                .lines()
                .find(|l| l.starts_with(&format!("{n},")))
                .unwrap_or_else(|| panic!("{at}: no CSV row"));
            let csv_angle: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
            assert_eq!(csv_angle, angle, "{at}");
            // draw --position: that sheet, byte for byte.
            let one = dir.join(format!("one-{n}"));
            let (code, _, err) = run(&[
                "draw",
                &scene(name),
                "-o",
                s(&one),
                "--position",
                &n.to_string(),
            ]);
            assert_eq!(code, 0, "{at}: {err}");
            let file = format!("velocity_{n}.svg");
            assert_eq!(
                std::fs::read(one.join(&file)).unwrap(),
                std::fs::read(sheets.join(&file)).unwrap(),
                "{at}"
            );
            // check: the answer states the number, or the command line does.
            let mut answer = answer_of(p);
            let bare = dir.join(format!("bare-{n}.json"));
            std::fs::write(&bare, answer.to_string()).unwrap();
            answer["position"] = json!(n);
            let group = dir.join(format!("group-{n}"));
            std::fs::create_dir_all(&group).unwrap();
            let stated = group.join("stated.json");
            std::fs::write(&stated, answer.to_string()).unwrap();
            for args in [
                vec!["check", &scene(name), s(&stated)],
                vec![
                    "check",
                    &scene(name),
                    s(&bare),
                    "--position",
                    &n.to_string(),
                ],
            ] {
                let (code, out, err) = run(&args);
                assert_eq!(code, 0, "{at}: {out}{err}");
                assert!(
                    out.starts_with(&format!("Check of the velocity plan, position {n}, ")),
                    "{at}: {out}"
                );
            }
            let (code, json_report, _) =
                run(&["check", &scene(name), s(&stated), "--format", "json"]);
            assert_eq!(code, 0);
            let report: Value = serde_json::from_str(&json_report).unwrap();
            assert_eq!(report["position"], n, "{at}");
            assert_eq!(report["elsewhere"], Value::Null, "{at}");
            // The gradebook.
            let out = dir.join(format!("graded-{n}"));
            let (code, _, err) = run(&["check", &scene(name), s(&group), "-o", s(&out)]);
            assert_eq!(code, 0, "{at}: {err}");
            let book = std::fs::read_to_string(out.join("gradebook.csv")).unwrap();
            let row = book.lines().nth(1).unwrap();
            assert!(
                row.starts_with(&format!("stated.json,velocity,{n},right,")),
                "{at}: {row}"
            );
            // The handout: the tab, the section and its heading.
            assert!(
                handout.contains(&format!("data-pos=\"{n}\">{n} ·")),
                "{at}: tab"
            );
            let section = &handout[handout
                .find(&format!(
                    "<section class=\"position\" id=\"pos-{n}\" data-pos=\"{n}\">"
                ))
                .unwrap()..];
            assert!(
                section.contains(&format!("<h2>Position {n}: ")),
                "{at}: heading"
            );
            assert!(
                section.contains(&format!(", position {n}\"")),
                "{at}: the board's title"
            );
            // centres.
            let (code, c, err) = run(&[
                "centres",
                &scene(name),
                "--position",
                &n.to_string(),
                "--format",
                "json",
            ]);
            assert_eq!(code, 0, "{at}: {err}");
            let c: Value = serde_json::from_str(&c).unwrap();
            assert_eq!(c["positions"][0]["position"], n, "{at}");
            assert!(
                (c["positions"][0]["q"]
                    .as_f64()
                    .unwrap()
                    .to_degrees()
                    .rem_euclid(360.0)
                    - angle.rem_euclid(360.0))
                .abs()
                    < 1e-6,
                "{at}"
            );
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// Older files and command lines, written when mechplan counted a `count`
/// sweep from 1: an answer saying `"positions_from": 1`, and `check`,
/// `solve` and `draw` given `--positions-from 1`, read them as before (the
/// K-th position is position K); what they write then counts from 1 too.
#[test]
fn older_answers_and_command_lines_are_read_with_positions_from_1() {
    let dir = fresh("older");
    let six = scene("six_link_fig2_10");
    let (_, json, _) = run(&["solve", &six, "--format", "json"]);
    let doc: Value = serde_json::from_str(&json).unwrap();
    // The last of the twelve: position 11, the older position 12.
    let mut answer = answer_of(numbered(&doc, 11));
    let bare = dir.join("bare.json");
    std::fs::write(&bare, answer.to_string()).unwrap();
    answer["position"] = json!(12);
    answer["positions_from"] = json!(1);
    let older = dir.join("older.json");
    std::fs::write(&older, answer.to_string()).unwrap();
    // The answer's own numbering; the report in the scene's.
    let (code, out, err) = run(&["check", &six, s(&older)]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("Check of the velocity plan, position 11, "),
        "{out}"
    );
    // The command line's: --position and the report.
    let (code, out, err) = run(&[
        "check",
        &six,
        s(&bare),
        "--positions-from",
        "1",
        "--position",
        "12",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("Check of the velocity plan, position 12, "),
        "{out}"
    );
    // Without it, position 12 is none of the scene's.
    let (code, _, err) = run(&["check", &six, s(&bare), "--position", "12"]);
    assert_eq!(code, 2);
    assert!(err.contains("--position: position 12 is not one of the scene's positions: they are numbered from 0 to 11"), "{err}");
    // solve: the result files count from 1.
    let (_, json, _) = run(&["solve", &six, "--format", "json", "--positions-from", "1"]);
    let from_1: Value = serde_json::from_str(&json).unwrap();
    for (k, p) in from_1["positions"].as_array().unwrap().iter().enumerate() {
        assert_eq!(p["position"], k + 1);
        assert_eq!(p["input"], doc["positions"][k]["input"]);
    }
    let (_, csv, _) = run(&["solve", &six, "--format", "csv", "--positions-from", "1"]);
    assert!(csv.lines().nth(1).unwrap().starts_with("1,"), "{csv}");
    let (_, table, _) = run(&["solve", &six, "--positions-from", "1"]);
    assert!(table.contains("\nposition 1: φ1 = 235.771°"), "{table}");
    let (code, _, err) = run(&["solve", &six, "--positions-from", "2"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--positions-from") && err.contains("from 0 or from 1"),
        "{err}"
    );
    // draw: --position 12 is the last sheet, named and headed 12.
    let (code, _, err) = run(&[
        "draw",
        &six,
        "-o",
        s(&dir.join("d")),
        "--positions-from",
        "1",
        "--position",
        "12",
    ]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("d/velocity_12.svg")).unwrap();
    assert_eq!(printed(&svg).0, 12);
    let _ = std::fs::remove_dir_all(&dir);
}

/// An answer drawn at position 4 but stating position 1 is graded at
/// position 1: wrong (exit 1), its report (text in each language, and
/// JSON) naming position 4 — not refused.
#[test]
fn an_answer_drawn_at_another_position_is_graded_at_its_own_and_names_it() {
    let dir = fresh("elsewhere");
    let six = scene("six_link_fig2_10");
    let (_, json, _) = run(&["solve", &six, "--format", "json"]);
    let doc: Value = serde_json::from_str(&json).unwrap();
    let mut answer = answer_of(numbered(&doc, 4));
    answer["position"] = json!(1);
    let file = dir.join("four-as-one.json");
    std::fs::write(&file, answer.to_string()).unwrap();
    for (lang, note) in [
        (
            "en",
            "Note: your points fit position 4, not position 1 that the answer states; it is graded at position 1.",
        ),
        (
            "uk",
            "Примітка: ваші точки відповідають положенню 4, а не положенню 1, зазначеному у відповіді; оцінено в положенні 1.",
        ),
        (
            "ru",
            "Примечание: ваши точки соответствуют положению 4, а не положению 1, указанному в ответе; оценено в положении 1.",
        ),
    ] {
        let (code, out, err) = run(&["check", &six, s(&file), "--lang", lang]);
        assert_eq!(code, 1, "{lang}: {out}{err}");
        assert_eq!(out.lines().nth(2), Some(note), "{lang}: {out}");
    }
    let (code, out, _) = run(&["check", &six, s(&file), "--format", "json"]);
    assert_eq!(code, 1);
    let r: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["position"], 1);
    assert_eq!(r["status"], 1);
    assert!(r["wrong"].as_u64().unwrap() > 0);
    assert_eq!(r["elsewhere"]["position"], 4);
    assert_eq!(r["elsewhere"]["reversed"], false);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A Scotch yoke: a plan drawn with the crank turned the other way is the
/// plan of the position half a turn away (its velocities all reversed).
/// Such an answer was refused (exit 2, "fits position …"); it is graded at
/// the position it states (the crank's velocity against ω1, exit 1), the
/// report naming the reversed crank and the position it fits as well.
#[test]
fn a_reversed_crank_is_graded_and_named() {
    let dir = fresh("reversed");
    let yoke = json!({
        "mechplan": 1,
        "title": "Scotch yoke",
        "points": { "O": [0, 0], "A": [0.0866025403784439, 0.05], "D": [0.0866025403784439, -0.2] },
        "links": {
            "0": { "points": ["O"] },
            "1": { "points": ["O", "A"] },
            "2": { "points": ["A"] },
            "3": { "points": ["D"] }
        },
        "sliders": [
            { "slider": "2", "guide": "3", "point": "A", "line": { "through": "D", "angle": 90 } },
            { "slider": "3", "guide": "0", "point": "D", "line": { "through": [0, -0.2], "angle": 0 } }
        ],
        "lengths": { "O-A": 0.1 },
        "input": { "link": "1", "pivot": "O", "angle": 30, "omega": 5 },
        "positions": { "count": 12 }
    });
    let scene = dir.join("yoke.json");
    std::fs::write(&scene, yoke.to_string()).unwrap();
    let (_, json, _) = run(&["solve", s(&scene), "--format", "json"]);
    let doc: Value = serde_json::from_str(&json).unwrap();
    // Position 1's plan turned through the pole, at μ_v = 0.004 (m/s)/mm:
    // position 7's, half a turn on.
    let plan = &numbered(&doc, 1)["plans"]["velocity"];
    let mu = 0.004;
    let turned: serde_json::Map<String, Value> = ["a", "d"]
        .iter()
        .map(|k| {
            let p = &plan["points"][*k];
            let f = plan["mu"].as_f64().unwrap() / mu;
            (
                k.to_string(),
                json!([-p[0].as_f64().unwrap() * f, -p[1].as_f64().unwrap() * f]),
            )
        })
        .collect();
    let answer = json!({ "plan": "velocity", "position": 1, "mu": mu, "points": turned });
    let file = dir.join("reversed.json");
    std::fs::write(&file, answer.to_string()).unwrap();
    let (code, out, err) = run(&["check", s(&scene), s(&file)]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.contains("The crank's velocity is laid off against the sense of ω1."),
        "{out}"
    );
    assert_eq!(
        out.lines().nth(2),
        Some(
            "Note: your points fit position 1 with the crank turned the other way (ω1 reversed), and position 7 as well; it is graded at position 1 with ω1 as the scene gives it."
        ),
        "{out}"
    );
    let (_, out, _) = run(&["check", s(&scene), s(&file), "--format", "json"]);
    let r: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        (r["position"].clone(), r["status"].clone()),
        (json!(1), json!(1))
    );
    assert_eq!(r["elsewhere"]["reversed"], true);
    assert_eq!(r["elsewhere"]["position"], 7);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A scene's `want.plans_at` names positions by their numbers too (a
/// `count` sweep from 0), or from 1 where it says `"positions_from": 1`;
/// a number the scene has not is refused with the range.
#[test]
fn plans_at_names_positions_by_their_numbers() {
    let chosen = |plans_at: Value| {
        let mut v: Value =
            serde_json::from_str(&std::fs::read_to_string(scene("six_link_fig2_10")).unwrap())
                .unwrap();
        v["want"]["plans_at"] = plans_at;
        let study = mechplan::Study::from_json(&v.to_string())?;
        let solution = study.solve()?;
        // The k-th positions (from 1) the course sheet shows.
        let c = mechplan::studies::chosen::Chosen::of(study.analysis(), solution.solved().len());
        Ok::<_, mechplan::Error>((c.velocity, c.acceleration))
    };
    let (_, acc) = chosen(json!([0, 11])).unwrap();
    assert_eq!(acc, [1, 12]);
    let (vel, acc) =
        chosen(json!({ "velocity": [2, 3], "acceleration": [1, 12], "positions_from": 1 }))
            .unwrap();
    assert_eq!((vel, acc), (vec![2, 3], vec![1, 12]));
    let e = chosen(json!([12])).unwrap_err().to_string();
    assert!(
        e.contains("/want/plans_at/0: expected a position number from 0 to 11"),
        "{e}"
    );
    let e = chosen(json!({ "acceleration": [0], "positions_from": 1 }))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("/want/plans_at/acceleration/0: expected a position number from 1 to 12"),
        "{e}"
    );
    let e = chosen(json!({ "acceleration": [1], "positions_from": 3 }))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("/want/plans_at/positions_from: expected 0 or 1"),
        "{e}"
    );
}
