//! The docs' examples are scenes mechplan accepts: every fenced block
//! tagged ` ```json scene ` in docs/scene-format.md and in README.md (its
//! first scene) is loaded with `Study::from_json` and solved. The other
//! ` ```json ` blocks of the reference that are whole objects (a result,
//! the manifest, a prismatic pair) must at least be valid JSON.

use mechplan::Study;
use std::path::Path;

/// How many complete scenes docs/scene-format.md shows at least: the first
/// scene and the examples (a coupler point, a slider-crank in mm, a
/// rocking guide, a driving slider, a cylinder, two cranks, two
/// cylinders, a sweep, masses, a force table, a course sheet).
const REFERENCE_SCENES: usize = 12;

/// A fenced code block of a Markdown text: its info string (what follows
/// the opening fence), the line of the fence (from 1) and its text.
struct Block {
    info: String,
    line: usize,
    text: String,
}

/// Every fenced block (``` fences) of `markdown`, in order.
fn blocks(markdown: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<Block> = None;
    for (n, line) in markdown.lines().enumerate() {
        let fence = line.trim_start().strip_prefix("```");
        match (&mut open, fence) {
            (None, Some(info)) => {
                open = Some(Block {
                    info: info.trim().to_owned(),
                    line: n + 1,
                    text: String::new(),
                })
            }
            (Some(_), Some(_)) => out.push(open.take().expect("an open block")),
            (Some(b), None) => {
                b.text.push_str(line);
                b.text.push('\n');
            }
            (None, None) => {}
        }
    }
    assert!(
        open.is_none(),
        "a fenced block is never closed (line {})",
        open.map_or(0, |b| b.line)
    );
    out
}

fn read(rel: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The blocks tagged `json scene`.
fn scenes(rel: &str) -> Vec<Block> {
    blocks(&read(rel))
        .into_iter()
        .filter(|b| b.info.split_whitespace().eq(["json", "scene"]))
        .collect()
}

/// Load and solve each scene; the failures, each naming its file and line.
fn failures(rel: &str, scenes: &[Block]) -> Vec<String> {
    let mut out = Vec::new();
    for b in scenes {
        let result = Study::from_json(&b.text).and_then(|study| study.solve().map(|_| ()));
        if let Err(e) = result {
            out.push(format!("{rel}, the scene at line {}: {e}", b.line));
        }
    }
    out
}

#[test]
fn every_scene_of_the_scene_format_reference_is_accepted_and_solved() {
    let rel = "docs/scene-format.md";
    let found = scenes(rel);
    assert!(
        found.len() >= REFERENCE_SCENES,
        "{rel} shows {} scenes marked `json scene`, expected at least {REFERENCE_SCENES}",
        found.len()
    );
    let bad = failures(rel, &found);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_readme_first_scene_is_accepted_and_solved() {
    let rel = "README.md";
    let found = scenes(rel);
    assert!(
        !found.is_empty(),
        "{rel} has no block marked `json scene` (its first scene)"
    );
    let bad = failures(rel, &found);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The reference's other JSON examples that are whole objects (a result,
/// `sheets.json`, a prismatic pair) parse; fragments such as
/// `"dynamics": { … }` are left alone.
#[test]
fn the_reference_json_objects_are_valid_json() {
    let rel = "docs/scene-format.md";
    let mut bad = Vec::new();
    for b in blocks(&read(rel)) {
        if b.info == "json"
            && b.text.trim_start().starts_with('{')
            && let Err(e) = serde_json::from_str::<serde_json::Value>(&b.text)
        {
            bad.push(format!("{rel}, the block at line {}: {e}", b.line));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The block finder itself: tags, fences inside other blocks' text, and
/// the lines it reports.
#[test]
fn blocks_are_found_by_their_tag() {
    let md = "text\n```json scene\n{ \"a\": 1 }\n```\n\n```json\n{}\n```\n```sh\nls\n```\n";
    let all = blocks(md);
    assert_eq!(all.len(), 3);
    assert_eq!(all[0].info, "json scene");
    assert_eq!(all[0].line, 2);
    assert_eq!(all[0].text, "{ \"a\": 1 }\n");
    assert_eq!(all[1].info, "json");
    assert_eq!(all[2].info, "sh");
}
