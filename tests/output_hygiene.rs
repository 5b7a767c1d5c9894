//! What the terminal prints reads as a person writes it: no "-0.000000",
//! no direction for a vector at rest, no angle to the last bit of a double
//! (59.99999999999999°), and a reader that closes the pipe early
//! (`solve | head`) ends the run quietly.

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_mechplan"))
}

fn fixture(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> String {
    let out = bin().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The longest run of digits after a decimal point in `text`.
fn most_decimals(text: &str) -> usize {
    let c: Vec<char> = text.chars().collect();
    let mut best = 0;
    for i in 1..c.len() {
        if (c[i - 1] == '.' || c[i - 1] == ',') && i >= 2 && c[i - 2].is_ascii_digit() {
            let n = c[i..].iter().take_while(|x| x.is_ascii_digit()).count();
            best = best.max(n);
        }
    }
    best
}

#[test]
fn a_point_at_rest_has_no_direction_and_no_number_is_minus_zero() {
    // The offset slider-crank's first position: O at rest, and the slider B
    // at a dead centre (|v| a rounding away from 0).
    let out = run(&["solve", &fixture("offset_slider_crank")]);
    for w in out.split([' ', ',', ';', '\n']) {
        let zero = w
            .trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.');
        assert!(
            !(w.starts_with('-') && zero && w.len() > 1),
            "{w:?} in\n{out}"
        );
    }
    let row = |p: &str| {
        out.lines()
            .find(|l| l.trim_start().starts_with(&format!("{p} ")))
            .unwrap_or_else(|| panic!("no row {p} in\n{out}"))
            .split_whitespace()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    // point, x, y, |v|, ∠v, |a|, ∠a
    let o = row("O");
    assert_eq!((o[3].as_str(), o[4].as_str()), ("0.000000", "—"), "{o:?}");
    let b = row("B");
    assert_eq!((b[3].as_str(), b[4].as_str()), ("0.000000", "—"), "{b:?}");
    assert_ne!(b[6], "—", "B accelerates: {b:?}");
    // A moving point keeps its direction.
    assert!(row("A")[4].parse::<f64>().is_ok());
}

#[test]
fn the_centres_state_their_position_to_the_tables_digits() {
    let out = run(&["centres", &fixture("four_bar")]);
    let head = out.lines().next().unwrap();
    assert!(most_decimals(head) <= 3, "{head}");
    assert!(head.contains("°"), "{head}");
}

#[test]
fn a_closed_pipe_ends_the_run_quietly() {
    // A long sweep's table, its reader gone after one line.
    let dir = std::env::temp_dir().join(format!("mechplan-pipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("long.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fixture("four_bar")).unwrap()).unwrap();
    v["positions"] = serde_json::json!({ "count": 20000 });
    std::fs::write(&scene, v.to_string()).unwrap();
    let mut child = bin()
        .args(["solve", scene.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(!first.is_empty());
    // The reader closes its end here (dropped above).
    let out = child.wait_with_output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "status {:?}: {err}", out.status);
    assert!(!err.contains("Broken pipe"), "{err}");
}
