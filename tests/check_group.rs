//! `check SCENE DIR` (docs/check.md, "A group at once"): a folder of 30
//! answers of the six-link with loads — plans of velocities and
//! accelerations read off the construction with a little noise (one drawn
//! as an SVG), points moved, the crank's velocity reversed, force plans
//! right, wrong and drawn too small, a broken JSON and an unknown letter —
//! graded in one run. The gradebook is read back with a CSV parser that
//! is not mechplan's, every file's grade is the one it was built with,
//! the overlays and the summary page's links are there, and the exit
//! status is the group's (2 with an unreadable answer, 1 with a wrong one,
//! 4 with one that cannot be judged, 0). Plus what a group refuses, the
//! default output folder and an output that cannot be written.

use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/fixtures/dynamics/six_link_fig2_10.json"
);

/// The gradebook's header, in order.
const COLUMNS: [&str; 9] = [
    "file",
    "plan",
    "position",
    "grade",
    "mistakes",
    "right",
    "wrong",
    "undecided",
    "message",
];

/// The binary on `args`, in `cwd`: its exit status, standard output and
/// standard error.
fn run_in(cwd: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .current_dir(cwd)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

fn run(args: &[&str]) -> (i32, String, String) {
    run_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

/// A fresh folder for one test.
fn fresh(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mechplan-group-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The scene's result file (`solve --format json`): the plans' points and
/// the reactions the answers are read off.
fn solved() -> Value {
    let (code, out, err) = run(&["solve", SCENE, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// A pencil's noise, the same every run: uniform in ±0.1 mm.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.2
    }
}

/// What an answer was built to be.
#[derive(Clone, Debug)]
struct Built {
    grade: &'static str,
    /// `velocity`, `acceleration`, `force`; empty when unreadable.
    plan: &'static str,
    position: usize,
    /// A piece of the mistakes' column ("" for none expected).
    mistake: &'static str,
    /// A piece of the message (unreadable answers; the note of one whose
    /// points fit elsewhere).
    message: String,
}

impl Built {
    fn new(grade: &'static str, plan: &'static str, position: usize) -> Built {
        Built {
            grade,
            plan,
            position,
            mistake: "",
            message: String::new(),
        }
    }
    fn kinematic(&self) -> bool {
        matches!(self.plan, "velocity" | "acceleration")
    }
}

/// A plan's points `names` at position `k` (its number: the scene counts
/// its 12 positions from 0, as its sheets do), as a student reads them
/// off: each coordinate within 0.1 mm.
fn points(doc: &Value, kind: &str, k: usize, names: &[&str], noise: &mut Noise) -> Value {
    let plan = &doc["positions"][k]["plans"][kind];
    assert_eq!(
        doc["positions"][k]["position"], k,
        "the result file's number"
    );
    let mut pts = serde_json::Map::new();
    for n in names {
        let p = &plan["points"][*n];
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        pts.insert(n.to_string(), json!([x + noise.next(), y + noise.next()]));
    }
    json!({ "plan": kind, "position": k, "mu": plan["mu"], "points": pts })
}

/// The reactions of group (4, 5) at position `k` (its number, from 0):
/// R_34 at C, R_54 at D, the guide's R_05 on the slider, in N.
fn reactions(doc: &Value, k: usize) -> BTreeMap<&'static str, f64> {
    let mut out = BTreeMap::new();
    let norm = |v: &Value| v[0].as_f64().unwrap().hypot(v[1].as_f64().unwrap());
    for pair in doc["positions"][k]["dynamics"]["pairs"].as_array().unwrap() {
        if pair["slider"] == "5" {
            out.insert("R_05", norm(&pair["N"]));
        } else if pair["point"] == "C" {
            out.insert("R_34", norm(&pair["R"]));
        } else if pair["point"] == "D" {
            out.insert("R_54", norm(&pair["R"]));
        }
    }
    assert_eq!(out.len(), 3);
    out
}

/// A force plan's answer of group (4, 5) at μ_F = `mu`, R_34 times
/// `factor`.
fn force(doc: &Value, k: usize, mu: f64, factor: f64) -> Value {
    let mut values = serde_json::Map::new();
    for (name, v) in reactions(doc, k) {
        let f = if name == "R_34" { factor } else { 1.0 };
        values.insert(name.into(), json!(v * f));
    }
    json!({ "plan": "force", "position": k, "links": ["4", "5"], "mu": mu, "values": values })
}

/// The velocity plan at position 0 drawn in a vector editor: the pole and
/// the ends of p_v a and p_v s2, labelled, with μ written on the sheet.
fn drawn_svg(doc: &Value) -> String {
    let plan = &doc["positions"][0]["plans"]["velocity"];
    let pole = (60.0, 120.0);
    let mut body = String::new();
    for k in ["p_v", "a", "s2"] {
        let (x, y) = if k == "p_v" {
            (0.0, 0.0)
        } else {
            let p = &plan["points"][k];
            (p[0].as_f64().unwrap() + 0.05, p[1].as_f64().unwrap() - 0.05)
        };
        let (gx, gy) = (pole.0 + x, pole.1 - y);
        if k != "p_v" {
            body.push_str(&format!(
                r#"<path d="M {} {} L {gx} {gy}" stroke="black" fill="none"/>"#,
                pole.0, pole.1
            ));
        }
        body.push_str(&format!(
            r#"<text x="{}" y="{}" font-size="4">{k}</text>"#,
            gx + 2.0,
            gy - 2.0
        ));
    }
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">{body}<text x="20" y="20" font-size="5">μ = {}</text></svg>"#,
        plan["mu"]
    )
}

/// The file name with `&`, quotes and angle brackets that the summary
/// must escape.
const ODD: &str = "right-v03 \"smith\" & <jones>.json";

/// Write the 30 answers into `dir` (and two files the group must not
/// take); what each was built to be, by file name.
fn build_group(dir: &Path) -> BTreeMap<String, Built> {
    let doc = solved();
    let mut noise = Noise(2024);
    let mut built = BTreeMap::new();
    let mut put = |name: &str, text: String, b: Built| {
        std::fs::write(dir.join(name), text).unwrap();
        built.insert(name.to_string(), b);
    };
    let all = ["a", "b", "c", "d", "s2", "s3", "s4"];
    let abcd = ["a", "b", "c", "d"];
    // Right: velocity plans where the construction judges every point,
    // the acceleration plan at position 2, each with all its points and
    // with a, b, c, d only; and the SVG drawing (of position 0, the first:
    // it states none).
    for k in [0, 3, 4, 6, 7, 9] {
        for (tag, names) in [("all", &all[..]), ("abcd", &abcd[..])] {
            let name = if k == 3 && tag == "abcd" {
                ODD.to_string()
            } else {
                format!("right-v{k:02}-{tag}.json")
            };
            let a = points(&doc, "velocity", k, names, &mut noise);
            put(&name, a.to_string(), Built::new("right", "velocity", k));
        }
    }
    for (tag, names) in [("all", &all[..]), ("abcd", &abcd[..])] {
        let mut a = points(&doc, "acceleration", 2, names, &mut noise);
        a["velocity"] = json!({ "mu": doc["positions"][2]["plans"]["velocity"]["mu"] });
        put(
            &format!("right-a02-{tag}.json"),
            a.to_string(),
            Built::new("right", "acceleration", 2),
        );
    }
    put(
        "right-drawn.svg",
        drawn_svg(&doc),
        Built::new("right", "velocity", 0),
    );
    // Wrong: the slider's point d moved 15 mm along the guide …
    for k in [1, 4, 7, 10] {
        let mut a = points(&doc, "velocity", k, &abcd, &mut noise);
        let x = a["points"]["d"][0].as_f64().unwrap();
        a["points"]["d"][0] = json!(x + 15.0);
        put(
            &format!("wrong-moved-v{k:02}.json"),
            a.to_string(),
            Built::new("wrong", "velocity", k),
        );
    }
    // … and the whole plan turned through the pole: the crank's velocity
    // laid off against ω1, a mistake the diagnosis names with its step.
    for k in [3, 8] {
        let mut a = points(&doc, "velocity", k, &abcd, &mut noise);
        for n in abcd {
            let p = a["points"][n].clone();
            a["points"][n] = json!([-p[0].as_f64().unwrap(), -p[1].as_f64().unwrap()]);
        }
        let mut b = Built::new("wrong", "velocity", k);
        b.mistake = "against the sense of ω1";
        b.message = format!("fit position {k} with the crank turned the other way (ω1 reversed)");
        put(&format!("wrong-reversed-v{k:02}.json"), a.to_string(), b);
    }
    // Force plans: right at 2 N/mm, R_34 half as long again (wrong), and
    // drawn at 200 N/mm, too small to tell (cannot be judged).
    for k in [1, 5] {
        put(
            &format!("force-right-{k:02}.json"),
            force(&doc, k, 2.0, 1.0).to_string(),
            Built::new("right", "force", k),
        );
    }
    put(
        "force-wrong-03.json",
        force(&doc, 3, 2.0, 1.5).to_string(),
        Built::new("wrong", "force", 3),
    );
    for k in [5, 8] {
        // Each item too small is reported in the message.
        let mut b = Built::new("cannot be judged", "force", k);
        b.message = "within the pencil's error".into();
        put(
            &format!("force-small-{k:02}.json"),
            force(&doc, k, 200.0, 1.0).to_string(),
            b,
        );
    }
    // Acceleration plans where the true plan alone cannot tell the right
    // points from a mistake's; the steps judged from the student's own
    // points can: at position 4 a tangential component drawn ∥ would put
    // b within its tolerance too, but b sits on the right construction,
    // where the mistaken one would put it far less likely.
    for (k, names, grade) in [(4, &all[..], "right"), (10, &abcd[..], "right")] {
        put(
            &format!("undecided-a{k:02}.json"),
            points(&doc, "acceleration", k, names, &mut noise).to_string(),
            Built::new(grade, "acceleration", k),
        );
    }
    // Unreadable: broken JSON, and a letter the plan has not.
    let mut b = Built::new("unreadable", "", 0);
    b.message = "malformed JSON".into();
    put(
        "unreadable-broken.json",
        r#"{"plan": "velocity", "mu": 0.01, "points": {"#.into(),
        b,
    );
    let mut b = Built::new("unreadable", "", 0);
    b.message = "/points/q: unknown plan point \"q\"".into();
    put(
        "unreadable-letter.json",
        json!({ "plan": "velocity", "position": 3, "mu": 0.01, "points": { "q": [1, 2] } })
            .to_string(),
        b,
    );
    // Not answers of the group: another kind of file, and a folder
    // (not searched).
    std::fs::write(dir.join("notes.txt"), "not an answer").unwrap();
    std::fs::create_dir_all(dir.join("older")).unwrap();
    std::fs::write(dir.join("older/old.json"), "{}").unwrap();
    assert_eq!(built.len(), 30);
    built
}

/// The gradebook read back by the csv crate: its header and its records.
fn gradebook(path: &Path) -> Vec<BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header, COLUMNS);
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            header
                .iter()
                .cloned()
                .zip(rec.iter().map(String::from))
                .collect()
        })
        .collect()
}

/// A file name as the summary links it: percent-encoded but for the
/// unreserved characters.
fn encoded(name: &str) -> String {
    name.bytes()
        .map(|b| {
            if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
                (b as char).to_string()
            } else {
                format!("%{b:02X}")
            }
        })
        .collect()
}

fn stem(name: &str) -> &str {
    Path::new(name).file_stem().unwrap().to_str().unwrap()
}

#[test]
fn a_folder_of_thirty_answers_is_graded_at_once() {
    let dir = fresh("thirty");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    let built = build_group(&answers);
    let out = dir.join("graded");
    let (code, stdout, stderr) = run(&[
        "check",
        SCENE,
        answers.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "an unreadable answer: status 2\n{stdout}{stderr}");
    let count = |g: &str| built.values().filter(|b| b.grade == g).count();
    assert_eq!((count("right"), count("wrong")), (19, 7));
    assert!(
        stdout.contains(&format!(
            "30 answers: 19 right, 7 wrong, {} cannot be judged, 2 unreadable",
            count("cannot be judged")
        )),
        "{stdout}"
    );
    assert!(stdout.contains(&format!("wrote {}", out.join("gradebook.csv").display())));
    let rows = gradebook(&out.join("gradebook.csv"));
    assert_eq!(rows.len(), 30);
    // In the order of the files' names, each as it was built.
    let names: Vec<&String> = rows.iter().map(|r| &r["file"]).collect();
    let sorted: Vec<&String> = built.keys().collect();
    assert_eq!(names, sorted);
    for r in &rows {
        let b = &built[&r["file"]];
        let f = &r["file"];
        assert_eq!(r["grade"], b.grade, "{f}: {r:?}");
        assert_eq!(r["plan"], b.plan, "{f}");
        if b.grade == "unreadable" {
            assert!(r["message"].contains(&b.message), "{f}: {r:?}");
            for c in ["position", "mistakes", "right", "wrong", "undecided"] {
                assert_eq!(r[c], "", "{f}: {c}");
            }
            continue;
        }
        // A checked answer's message is the report's note, where its
        // points fit elsewhere than stated.
        match b.message.as_str() {
            "" => assert_eq!(r["message"], "", "{f}"),
            m => assert!(r["message"].contains(m), "{f}: {r:?}"),
        }
        assert_eq!(r["position"], b.position.to_string(), "{f}");
        let n = |c: &str| r[c].parse::<usize>().unwrap();
        match b.grade {
            "right" => assert!(n("right") > 0 && n("wrong") + n("undecided") == 0, "{f}"),
            "wrong" => assert!(n("wrong") > 0, "{f}"),
            _ => assert!(n("wrong") == 0 && n("undecided") > 0, "{f}"),
        }
        // A mistake is named only where something is wrong, with its
        // step where the diagnosis has one.
        assert_eq!(r["mistakes"].is_empty(), b.grade != "wrong", "{f}: {r:?}");
        assert!(r["mistakes"].contains(b.mistake), "{f}: {r:?}");
        if !b.mistake.is_empty() {
            assert!(r["mistakes"].starts_with("step "), "{f}: {r:?}");
        }
    }
    // An overlay for every answer checked (a force plan's: the right
    // polygon, its values-only answer's items written wrong under it),
    // none for the unreadable ones.
    let overlays = out.join("overlays");
    let checked: Vec<(&String, &Built)> =
        built.iter().filter(|(_, b)| !b.plan.is_empty()).collect();
    assert_eq!(std::fs::read_dir(&overlays).unwrap().count(), checked.len());
    let page = std::fs::read_to_string(out.join("summary.html")).unwrap();
    for (name, b) in &checked {
        let svg = std::fs::read_to_string(overlays.join(format!("{}.svg", stem(name)))).unwrap();
        let drawn = if b.kinematic() {
            "student-"
        } else {
            "right-vec-"
        };
        assert!(svg.starts_with("<svg") && svg.contains(drawn), "{name}");
        let link = format!("href=\"overlays/{}.svg\"", encoded(stem(name)));
        assert!(page.contains(&link), "{link}");
    }
    assert_eq!(page.matches("href=").count(), checked.len());
    // Every text escaped, the scene named, the totals on top, nothing
    // fetched.
    assert!(page.contains("right-v03 &quot;smith&quot; &amp; &lt;jones&gt;.json"));
    assert!(!page.contains("<jones>"));
    assert!(page.contains("Scene: ") && page.contains("six_link_fig2_10.json"));
    assert!(page.contains("<b>19</b>right") && page.contains("<b>2</b>unreadable"));
    assert!(!page.contains("<script") && !page.contains("http://") && !page.contains("https://"));
    // No temporary left behind.
    for d in [&out, &overlays] {
        for e in std::fs::read_dir(d).unwrap() {
            let n = e.unwrap().file_name();
            assert!(!n.to_string_lossy().contains(".tmp"), "{n:?}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Files given one by one are a group too; its status is its worst
/// answer's; the JSON format is one array of the reports.
#[test]
fn files_given_are_a_group_with_the_worst_status() {
    let dir = fresh("files");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    build_group(&answers);
    let path = |n: &str| answers.join(n).display().to_string();
    let out = dir.join("out").display().to_string();
    let group = |files: &[&str], extra: &[&str]| {
        let paths: Vec<String> = files.iter().map(|f| path(f)).collect();
        let mut args = vec!["check", SCENE];
        args.extend(paths.iter().map(String::as_str));
        args.extend(["-o", out.as_str()]);
        args.extend(extra);
        run(&args)
    };
    let right = "right-v04-all.json";
    let wrong = "wrong-moved-v07.json";
    let undecided = "force-small-08.json";
    let (code, stdout, err) = group(&[right, wrong, undecided], &[]);
    assert_eq!(code, 1, "{stdout}{err}");
    let rows = gradebook(&Path::new(&out).join("gradebook.csv"));
    let files: Vec<&str> = rows.iter().map(|r| r["file"].as_str()).collect();
    assert_eq!(files, [path(right), path(wrong), path(undecided)]);
    assert_eq!(group(&[right, undecided], &[]).0, 4);
    assert_eq!(group(&[right, "right-drawn.svg"], &[]).0, 0);
    // One file with an output folder: a group of one.
    let (code, stdout, _) = group(&[right], &[]);
    assert_eq!(code, 0);
    assert!(stdout.starts_with("1 answer: 1 right,"), "{stdout}");
    // --format json: the reports, one array.
    let (code, stdout, _) = group(&[right, "unreadable-broken.json"], &["--format", "json"]);
    assert_eq!(code, 2);
    let v: Value = serde_json::from_str(&stdout).unwrap();
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 2);
    assert_eq!(a[0]["grade"], "right");
    assert_eq!(a[0]["report"]["status"], 0);
    assert_eq!(a[1]["grade"], "unreadable");
    assert!(a[1]["message"].as_str().unwrap().contains("malformed JSON"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// What a group refuses (exit 2, nothing written): `--svg`, a position
/// the scene has not, a folder without answers, a bad scene; an output
/// that cannot be written is status 3; without `-o` the results go to
/// `mechplan-check` in the working folder.
#[test]
fn refusals_and_the_default_output() {
    let dir = fresh("refusals");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    let a = answers.join("a.json");
    let b = answers.join("b.json");
    let doc = solved();
    let mut noise = Noise(7);
    for p in [&a, &b] {
        let ans = points(&doc, "velocity", 3, &["a", "b", "c", "d"], &mut noise);
        std::fs::write(p, ans.to_string()).unwrap();
    }
    let (a, b, ad) = (
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        answers.to_str().unwrap(),
    );
    let out = dir.join("out");
    let o = out.to_str().unwrap();
    let (code, _, err) = run(&["check", SCENE, a, b, "-o", o, "--svg", "x.svg"]);
    assert_eq!(code, 2);
    assert!(err.contains("--svg"), "{err}");
    let (code, _, err) = run(&["check", SCENE, ad, "-o", o, "--position", "12"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--position") && err.contains("from 0 to 11"),
        "{err}"
    );
    // In the older numbering (the answers state theirs: position 3 of
    // the scene's numbering), position 12 is the last one.
    let (code, out_text, err) = run(&[
        "check",
        SCENE,
        ad,
        "-o",
        o,
        "--position",
        "12",
        "--positions-from",
        "1",
    ]);
    assert_eq!(code, 1, "{out_text}{err}");
    let rows = gradebook(&out.join("gradebook.csv"));
    assert!(rows.iter().all(|r| r["position"] == "12"), "{rows:?}");
    // Drawn at the 4th position, graded at the 12th: each row's note names
    // the 4th in the same numbering.
    assert!(
        rows.iter()
            .all(|r| r["grade"] == "wrong"
                && r["message"].contains("fit position 4, not position 12")),
        "{rows:?}"
    );
    let (code, _, err) = run(&["check", SCENE, ad, "-o", o, "--positions-from", "2"]);
    assert_eq!(code, 2);
    assert!(err.contains("--positions-from"), "{err}");
    std::fs::remove_dir_all(&out).unwrap();
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let (code, _, err) = run(&["check", SCENE, empty.to_str().unwrap(), "-o", o]);
    assert_eq!(code, 2);
    assert!(err.contains("no *.json, *.svg or *.dxf"), "{err}");
    let bad_scene = dir.join("scene.json");
    std::fs::write(&bad_scene, "{").unwrap();
    let (code, _, _) = run(&["check", bad_scene.to_str().unwrap(), ad, "-o", o]);
    assert_eq!(code, 2);
    assert!(!out.exists(), "nothing written on bad input");
    // An output folder under a file cannot be made.
    let (code, _, err) = run(&["check", SCENE, ad, "-o", &format!("{a}/out")]);
    assert_eq!(code, 3, "{err}");
    // The default output folder, in the working folder.
    let (code, stdout, err) = run_in(&dir, &["check", SCENE, ad]);
    assert_eq!(code, 0, "{stdout}{err}");
    assert!(
        stdout.contains("wrote mechplan-check/gradebook.csv"),
        "{stdout}"
    );
    assert_eq!(
        gradebook(&dir.join("mechplan-check/gradebook.csv")).len(),
        2
    );
    assert!(dir.join("mechplan-check/overlays/b.svg").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The number after `prefix` in `text` (a decimal comma read as a point),
/// and whether it is there.
fn number_after(text: &str, prefix: &str) -> Option<f64> {
    let rest = &text[text.find(prefix)? + prefix.len()..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | ',' | '-' | 'e')))
        .unwrap_or(rest.len());
    rest[..end].replace(',', ".").parse().ok()
}

/// A wrong answer's `mistakes` column is never empty: a value (v_B, ε3)
/// or a segment written wrong off points drawn right is named with what
/// was written and what is right, in the report's language; beside a
/// mistake at a step too; and an answer of values only names its wrong
/// value when no typical mistake explains it.
#[test]
fn a_value_written_wrong_is_named_in_the_gradebook() {
    let dir = fresh("values");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    let doc = solved();
    let mut noise = Noise(11);
    let abcd = ["a", "b", "c", "d"];
    let v = |k: usize, p: &str| {
        let v = &doc["positions"][k]["points"][p]["v"];
        v[0].as_f64().unwrap().hypot(v[1].as_f64().unwrap())
    };
    let eps = |k: usize, l: &str| doc["positions"][k]["links"][l]["epsilon"].as_f64().unwrap();
    // (file, answer, what is named (en, uk), written, right).
    let mut cases: Vec<(&str, Value, [&str; 2], f64, f64)> = Vec::new();
    let mut a = points(&doc, "velocity", 3, &abcd, &mut noise);
    a["values"] = json!({ "v_B": 1.3 * v(3, "B") });
    cases.push((
        "value-v03.json",
        a,
        ["v_B", "v_B"],
        1.3 * v(3, "B"),
        v(3, "B"),
    ));
    let mut a = points(&doc, "acceleration", 3, &abcd, &mut noise);
    a["velocity"] = json!({ "mu": doc["positions"][3]["plans"]["velocity"]["mu"] });
    a["values"] = json!({ "eps3": eps(3, "3") + 15.0 });
    cases.push((
        "eps-a03.json",
        a,
        ["ε3", "ε3"],
        eps(3, "3") + 15.0,
        eps(3, "3"),
    ));
    let mut a = points(&doc, "velocity", 7, &abcd, &mut noise);
    let b = &doc["positions"][7]["plans"]["velocity"]["points"]["b"];
    let pb = b[0].as_f64().unwrap().hypot(b[1].as_f64().unwrap());
    a["segments"] = json!({ "p_v b": 1.2 * pb });
    let seg = ["segment p_vb", "відрізок p_vb"];
    cases.push(("segment-v07.json", a, seg, 1.2 * pb, pb));
    let only = json!({ "plan": "velocity", "position": 2, "mu": 0.01, "values": { "v_B": 2.0 * v(2, "B") } });
    cases.push((
        "only-values-v02.json",
        only,
        ["v_B", "v_B"],
        2.0 * v(2, "B"),
        v(2, "B"),
    ));
    for (name, a, ..) in &cases {
        std::fs::write(answers.join(name), a.to_string()).unwrap();
    }
    // A point moved and a value written wrong: both named.
    let mut a = points(&doc, "velocity", 6, &abcd, &mut noise);
    let x = a["points"]["d"][0].as_f64().unwrap();
    a["points"]["d"][0] = json!(x + 15.0);
    a["values"] = json!({ "v_B": 1.5 * v(6, "B") });
    std::fs::write(answers.join("moved-and-value-v06.json"), a.to_string()).unwrap();
    let langs = [
        ("en", "written ", "right "),
        ("uk", "записано ", "правильно "),
    ];
    for (l, (lang, written, right)) in langs.into_iter().enumerate() {
        let out = dir.join(lang);
        let (code, stdout, err) = run(&[
            "check",
            SCENE,
            answers.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--lang",
            lang,
        ]);
        assert_eq!(code, 1, "{stdout}{err}");
        let rows = gradebook(&out.join("gradebook.csv"));
        assert_eq!(rows.len(), 5);
        for r in &rows {
            let f = &r["file"];
            assert_eq!(r["grade"], "wrong", "{f}: {r:?}");
            assert!(
                !r["mistakes"].is_empty(),
                "{f}: a wrong row names its mistake"
            );
        }
        let row = |f: &str| rows.iter().find(|r| r["file"] == f).unwrap();
        for (name, _, what, given, expected) in &cases {
            let m = &row(name)["mistakes"];
            let what = format!("{}: {written}", what[l]);
            assert!(m.contains(&what), "{name}: {m}");
            let item = &m[m.find(&what).unwrap()..];
            let g = number_after(item, &what).unwrap_or_else(|| panic!("{name}: {m}"));
            assert!(
                (g - given).abs() <= 1e-3 * given.abs(),
                "{name}: written {g}, not {given}: {m}"
            );
            let e = number_after(item, right).unwrap_or_else(|| panic!("{name}: {m}"));
            assert!(
                (e - expected).abs() <= 0.05 * expected.abs(),
                "{name}: right {e}, not {expected}: {m}"
            );
        }
        let m = &row("moved-and-value-v06.json")["mistakes"];
        assert!(
            m.starts_with("step ") && m.contains(&format!("v_B: {written}")),
            "{m}"
        );
        assert_eq!(
            m.matches(" | ").count(),
            1,
            "the moved point's step and the value: {m}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
