//! The input side of issue 41, through the `mechplan` binary: every file
//! read with a bound (a device, an endless pipe refused at once under a
//! memory limit), the file named in every JSON error, input values in
//! messages without float noise, and the note when lengths look like
//! millimetres read as metres.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_mechplan");

/// A fresh folder of this suite's.
fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "mechplan-input-faults-{}-{tag}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn fixture(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures")
        .join(name)
        .display()
        .to_string()
}

/// `mechplan ARGS` under a 500 MB address-space limit, and how long it
/// took.
fn limited(args: &[&str]) -> (Output, Duration) {
    let t = Instant::now();
    let o = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 500000; exec \"$0\" \"$@\"")
        .arg(BIN)
        .args(args)
        .output()
        .unwrap();
    (o, t.elapsed())
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_device_as_scene_is_refused_at_once_under_a_memory_limit() {
    let (o, t) = limited(&["solve", "/dev/zero"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("/dev/zero") && e.contains("at most 4194304 bytes (4 MiB)"),
        "{e}"
    );
    assert!(t < Duration::from_secs(1), "{t:?}");
    // An answer read from a device: the answers' own limit.
    let (o, t) = limited(&["check", &fixture("four_bar.json"), "/dev/zero"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("/dev/zero") && e.contains("at most 8388608 bytes (8 MiB)"),
        "{e}"
    );
    assert!(t < Duration::from_secs(1), "{t:?}");
}

#[test]
fn a_pipe_fed_without_end_as_scene_is_refused_at_once() {
    let d = dir("fifo");
    let fifo = d.join("scene.json");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    // `yes` writes into the pipe until the reader closes it.
    let mut feeder = Command::new("sh")
        .arg("-c")
        .arg("exec yes '{\"mechplan\": 1,' > \"$0\"")
        .arg(&fifo)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let (o, t) = limited(&["solve", fifo.to_str().unwrap()]);
    let _ = feeder.kill();
    let _ = feeder.wait();
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains(fifo.to_str().unwrap()) && e.contains("at most 4194304 bytes"),
        "{e}"
    );
    assert!(t < Duration::from_secs(1), "{t:?}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_large_regular_file_is_refused_by_its_size_naming_it() {
    let d = dir("large");
    let p = d.join("big.json");
    std::fs::write(&p, " ".repeat((4 << 20) + 1)).unwrap();
    let o = run(&["solve", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains(p.to_str().unwrap()) && e.contains("the file has 4194305 bytes"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn json_syntax_errors_name_the_file_and_the_place() {
    let d = dir("syntax");
    let scene = d.join("broken scene.json");
    std::fs::write(&scene, "{\"mechplan\": 1,\n  \"points\": {,}\n}\n").unwrap();
    let o = run(&["solve", scene.to_str().unwrap()]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("line 2 column") && e.contains(scene.to_str().unwrap()),
        "{e}"
    );
    // A repeated name is the JSON's too.
    std::fs::write(&scene, "{\"mechplan\": 1, \"mechplan\": 1}").unwrap();
    let e = stderr(&run(&["solve", scene.to_str().unwrap()]));
    assert!(
        e.contains("repeated") && e.contains(scene.to_str().unwrap()),
        "{e}"
    );
    // An answer, and a marks file, checked against a good scene.
    for (name, text) in [
        (
            "answer.json",
            "{\"plan\": \"velocity\",\n \"points\": [1, 2,]\n}",
        ),
        ("marks.json", "{\"photo\": {\"file\": \"p.jpg\",}\n}"),
    ] {
        let a = d.join(name);
        std::fs::write(&a, text).unwrap();
        let o = run(&["check", &fixture("four_bar.json"), a.to_str().unwrap()]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{e}");
        assert!(
            e.contains("line ") && e.contains("column") && e.contains(a.to_str().unwrap()),
            "{e}"
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// A four-bar whose coupler and rocker reach O3 only while the crank is
/// below 53.6°: assembled at 30°, not at 60°.
const SHORT_FOUR_BAR: &str = r#"{
  "mechplan": 1,
  "points": {
    "O1": [0, 0], "A": [0.0866, 0.05], "B": [0.3353, 0.0764], "O3": [0.4, 0]
  },
  "links": {
    "0": { "points": ["O1", "O3"] },
    "1": { "points": ["O1", "A"] },
    "2": { "points": ["A", "B"] },
    "3": { "points": ["O3", "B"] }
  },
  "lengths": { "O1-A": 0.1, "A-B": 0.25, "O3-B": 0.1 },
  "input": { "link": "1", "pivot": "O1", "angle": 30, "omega": 10 },
  "positions": { "angles": [30, 60] }
}"#;

#[test]
fn input_values_in_refusals_read_as_written() {
    let d = dir("noise");
    let p = d.join("short.json");
    std::fs::write(&p, SHORT_FOUR_BAR).unwrap();
    let o = run(&["solve", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    // It read "φ = 59.99999999999999°": 60° come back through radians.
    assert!(e.contains("cannot be assembled at φ = 60°:"), "{e}");
    assert!(!e.contains("59.99"), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

/// The scene-format doc's first four-bar with its lengths multiplied by
/// `k` and `units` as given.
fn first_four_bar(k: f64, units: &str) -> String {
    let p = |x: f64| x * k;
    format!(
        r#"{{
  "mechplan": 1,{units}
  "points": {{ "O1": [0, 0], "A": [{}, {}], "B": [{}, {}], "O3": [{}, 0] }},
  "links": {{
    "0": {{ "points": ["O1", "O3"] }}, "1": {{ "points": ["O1", "A"] }},
    "2": {{ "points": ["A", "B"] }}, "3": {{ "points": ["O3", "B"] }}
  }},
  "lengths": {{ "O1-A": {}, "A-B": {}, "O3-B": {} }},
  "input": {{ "link": "1", "pivot": "O1", "angle": 60, "omega": 10 }}
}}"#,
        p(0.05),
        p(0.0866),
        p(0.3),
        p(0.25),
        p(0.4),
        p(0.1),
        p(0.3),
        p(0.27)
    )
}

#[test]
fn lengths_like_millimetres_without_units_draw_a_note() {
    let d = dir("units");
    let p = d.join("scene.json");
    let note = "add \"units\": {\"length\": \"mm\"}";
    // In millimetres without `units`: a 500 m mechanism, solved, noted.
    std::fs::write(&p, first_four_bar(1000.0, "")).unwrap();
    let o = run(&["solve", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{e}");
    assert!(
        e.contains("mechplan: note:") && e.contains("read as metres") && e.contains(note),
        "{e}"
    );
    // The same with its units stated, and the metre scene: no note.
    for text in [
        first_four_bar(1000.0, r#" "units": { "length": "mm" },"#),
        first_four_bar(1.0, ""),
        first_four_bar(1.0, r#" "units": { "angle": "deg" },"#),
    ] {
        std::fs::write(&p, text).unwrap();
        let o = run(&["solve", p.to_str().unwrap()]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(0), "{e}");
        assert!(!e.contains("note"), "{e}");
    }
    let _ = std::fs::remove_dir_all(&d);
}
