//! Shared helpers for the integration tests: fixtures and scene edits.
#![allow(dead_code)]

use mechplan::{Analysis, Scene, Solved};
use serde_json::{Value, json};

pub const FIXTURES: &[&str] = &[
    "four_bar",
    "offset_slider_crank",
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "rrp_rotating_guide_002",
    "class3_004",
    "prp_tangent_drive",
    "slider_driven_rocker",
];

pub fn fixture(name: &str) -> Value {
    let path = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

/// Input values (scene units) that sweep a fixture at 1° (or 1/360 of the
/// slider's range) over the range where it assembles.
pub fn sweep(name: &str, v: &Value) -> Value {
    match name {
        // The slot is parallel to the fixed guide at 0° and 180°.
        "prp_tangent_drive" => {
            json!({ "angles": (0..=140).map(|k| 20.0 + k as f64).collect::<Vec<_>>() })
        }
        // The group locks (a dead point of the three-leash group) near
        // φ = 34.6° and −92°: the crank of `004` rocks, it cannot turn fully.
        "class3_004" => {
            json!({ "angles": (0..=124).map(|k| -90.0 + k as f64).collect::<Vec<_>>() })
        }
        "slider_driven_rocker" => {
            json!({ "s": (0..=360).map(|k| -0.06 + 0.36 * k as f64 / 360.0).collect::<Vec<_>>() })
        }
        _ => {
            let a0 = v["input"]["angle"].as_f64().unwrap();
            json!({ "angles": (0..360).map(|k| a0 + k as f64).collect::<Vec<_>>() })
        }
    }
}

pub fn scene_with(mut v: Value, positions: Value) -> Scene {
    v["positions"] = positions;
    Scene::from_json(&v.to_string()).unwrap()
}

pub fn solve(scene: Scene) -> (Analysis, Vec<Solved>) {
    let an = Analysis::new(scene).unwrap();
    let s = an.run().unwrap();
    (an, s)
}

/// `python3` able to import ezdxf (PyPI), for the DXF tests: the system's
/// where it has ezdxf, else ezdxf installed once by pip into
/// `target/pydeps` (so that `cargo test --release` alone passes on a fresh
/// machine with python3 and pip) and put on `PYTHONPATH`. Panics, naming
/// the cause, where neither works: the DXF tests never pass unchecked.
pub fn python_with_ezdxf() -> std::process::Command {
    use std::process::Command;
    use std::sync::OnceLock;
    static PATH: OnceLock<Option<std::path::PathBuf>> = OnceLock::new();
    let extra = PATH.get_or_init(|| {
        let has = |path: Option<&std::path::Path>| {
            let mut c = Command::new("python3");
            c.args(["-c", "import ezdxf"]);
            if let Some(p) = path {
                c.env("PYTHONPATH", p);
            }
            c.output().map(|o| o.status.success()).unwrap_or(false)
        };
        if has(None) {
            return None;
        }
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/pydeps");
        if !has(Some(&dir)) {
            let out = Command::new("python3")
                .args(["-m", "pip", "install", "--quiet", "--target"])
                .arg(&dir)
                .arg("ezdxf")
                .output()
                .expect("python3 runs (the DXF tests read and write DXF with ezdxf)");
            assert!(
                out.status.success() && has(Some(&dir)),
                "ezdxf cannot be imported nor installed by pip into {}: {}",
                dir.display(),
                String::from_utf8_lossy(&out.stderr)
            );
        }
        Some(dir)
    });
    let mut c = Command::new("python3");
    if let Some(p) = extra {
        c.env("PYTHONPATH", p);
    }
    c
}

/// The first ```dxf block of the project's document `doc` (docs/…), the
/// example a test holds to what the program reads or writes.
#[allow(dead_code)]
pub fn dxf_block(doc: &str) -> String {
    let text = std::fs::read_to_string(format!("{}/{doc}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let start = text.find("```dxf\n").expect("a dxf block in the document") + 7;
    text[start..start + text[start..].find("```").unwrap()].to_string()
}

/// A worked example of docs/check.md, as the page prints it: the first
/// ```json block after the line `heading` is the answer, checked by the
/// command on `fixtures/{fixture}.json`; the command exits with status 1
/// (an answer with a mistake) and prints every line of the first ```text
/// block after the heading, in that order (a line "…" stands for lines
/// the page leaves out).
pub fn check_docs_example(heading: &str, fixture: &str) {
    let root = env!("CARGO_MANIFEST_DIR");
    let page = std::fs::read_to_string(format!("{root}/docs/check.md")).unwrap();
    let at = page
        .find(&format!("\n{heading}\n"))
        .unwrap_or_else(|| panic!("docs/check.md has no heading {heading:?}"));
    let example = &page[at..];
    let block = |fence: &str| {
        let start = example.find(fence).unwrap() + fence.len();
        let end = start + example[start..].find("```").unwrap();
        example[start..end].to_string()
    };
    let (answer, printed) = (block("```json\n"), block("```text\n"));
    let tag: String = heading
        .chars()
        .filter(char::is_ascii_alphanumeric)
        .collect();
    let dir = std::env::temp_dir().join(format!("mechplan-docs-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("answer.json");
    std::fs::write(&file, answer).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &format!("{root}/fixtures/{fixture}.json")])
        .arg(&file)
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{heading}: {text}");
    let mut lines = text.lines();
    for want in printed.lines().filter(|l| *l != "…") {
        assert!(
            lines.any(|l| l == want),
            "{heading}: the page prints a line the command does not, in this order:\n{want}\n---\n{text}"
        );
    }
}

/// The sheets `opt` draws of `solved` (`drawing::sheets`), what they draw
/// beyond the positions (trajectories, extreme positions, chosen
/// positions, diagrams) solved first, as `Study::draw` does: presentation
/// never solves. None where that fails (a diagrams sheet that cannot be
/// built).
pub fn sheets(
    an: &Analysis,
    solved: &[Solved],
    opt: &mechplan::drawing::DrawOptions,
) -> Vec<mechplan::drawing::Sheet> {
    let needs = mechplan::drawing::sheet_needs(an, solved, opt, true);
    match mechplan::studies::sheet_data::SheetData::solve(an, solved, needs) {
        Ok(data) => mechplan::drawing::sheets(an, solved, &data, opt),
        Err(_) => Vec::new(),
    }
}

/// The `mechplan` binary on `args`: its exit status, standard output and
/// standard error.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// A fresh, empty folder for one test of `suite`:
/// `mechplan-SUITE-TAG-PID` in the temporary folder.
pub fn fresh(suite: &str, tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("mechplan-{suite}-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
