//! `draw` streams (docs/performance.md, "draw at scale"): each sheet is
//! written to its temporary as soon as it is drawn and dropped, so memory
//! stays flat in the number of positions; the sheets' numbers in their
//! title blocks still run 1…n with n counted before the first is drawn.

use std::path::PathBuf;
use std::process::Command;

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-stream-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene_with_count(tag: &str, count: usize) -> PathBuf {
    let path = format!(
        "{}/fixtures/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["positions"] = serde_json::json!({ "count": count });
    let p = dir(tag).join("scene.json");
    std::fs::write(&p, v.to_string()).unwrap();
    p
}

/// The number after `label` in a sheet's title block ("Sheet 9").
fn numbered(svg: &str, label: &str) -> Option<usize> {
    let at = svg.find(&format!(">{label} "))? + label.len() + 2;
    svg[at..].split('<').next()?.parse().ok()
}

#[test]
fn title_blocks_number_the_streamed_sheets_one_to_n() {
    let scene = scene_with_count("numbers", 12);
    let out = dir("numbers-out");
    let o = Command::new(EXE)
        .args(["draw", scene.to_str().unwrap(), "--title-block", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut numbers = Vec::new();
    let mut totals = Vec::new();
    for e in std::fs::read_dir(&out).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "svg") {
            let svg = std::fs::read_to_string(&p).unwrap();
            numbers.push(numbered(&svg, "Sheet").expect("a sheet number"));
            totals.push(numbered(&svg, "Sheets").expect("a sheet count"));
        }
    }
    numbers.sort();
    // The positions sheet, and the mechanism, velocity and acceleration
    // sheets of 12 positions.
    assert_eq!(numbers, (1..=37).collect::<Vec<_>>());
    assert!(totals.iter().all(|&n| n == 37), "{totals:?}");
}

/// Show 3 of issue 26: 2 000 positions of the six-link mechanism drawn
/// (6 001 sheets) with the process's data segment limited to 150 MB (it
/// took 378 MB when every sheet was held until the end).
#[cfg(target_os = "linux")]
#[test]
fn two_thousand_positions_are_drawn_in_bounded_memory() {
    let scene = scene_with_count("long", 2000);
    let out = dir("long-out");
    let o = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "ulimit -d 150000; exec '{EXE}' draw '{}' -o '{}'",
            scene.display(),
            out.display()
        ))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sheets.json")).unwrap()).unwrap();
    let sheets = manifest["sheets"].as_array().unwrap();
    assert_eq!(sheets.len(), 6001);
    for s in sheets {
        let file = s["file"].as_str().unwrap();
        assert!(out.join(file).is_file(), "{file}");
    }
    // No temporary is left behind.
    let left = std::fs::read_dir(&out)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .starts_with('.')
        })
        .count();
    assert_eq!(left, 0);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn one_positions_sheets_are_those_of_the_whole_set() {
    let scene = scene_with_count("one", 12);
    let full = dir("one-full");
    let draw = |out: &std::path::Path, extra: &[&str]| {
        Command::new(EXE)
            .args(["draw", scene.to_str().unwrap(), "--title-block", "-o"])
            .arg(out)
            .args(extra)
            .output()
            .unwrap()
    };
    let o = draw(&full, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Positions 4 and 9 alone (the numbers the sheets show: a count sweep
    // from 0): the same sheets byte for byte (the scales of the whole set,
    // the numbers in it), nothing else.
    let some = dir("one-some");
    let o = draw(&some, &["--position", "4,9"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut names: Vec<String> = std::fs::read_dir(&some)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "acceleration_4.svg",
            "acceleration_9.svg",
            "mechanism_4.svg",
            "mechanism_9.svg",
            "sheets.json",
            "velocity_4.svg",
            "velocity_9.svg"
        ]
    );
    for n in names.iter().filter(|n| n.ends_with(".svg")) {
        assert_eq!(
            std::fs::read(some.join(n)).unwrap(),
            std::fs::read(full.join(n)).unwrap(),
            "{n}"
        );
    }
    // Drawn again into the full set's folder: the others stay, and the
    // manifest still lists all 37.
    let o = draw(&full, &["--position", "4"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(full.join("sheets.json")).unwrap()).unwrap();
    assert_eq!(manifest["sheets"].as_array().unwrap().len(), 37);
    assert_eq!(std::fs::read_dir(&full).unwrap().count(), 38);
    // Each sheet of one position names it as its file does: in its
    // heading, and in the manifest.
    for n in names.iter().filter(|n| n.ends_with(".svg")) {
        let k = &n[n.find('_').unwrap() + 1..n.len() - 4];
        let svg = std::fs::read_to_string(some.join(n)).unwrap();
        assert!(svg.contains(&format!("position {k},")), "{n}");
    }
    let listed: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(some.join("sheets.json")).unwrap()).unwrap();
    for s in listed["sheets"].as_array().unwrap() {
        let file = s["file"].as_str().unwrap();
        let k: u64 = file[file.find('_').unwrap() + 1..file.len() - 4]
            .parse()
            .unwrap();
        assert_eq!(s["position"], k, "{file}");
    }
    // In the older numbering, the same sheets are the 5th and the 10th,
    // named and headed so.
    let older = dir("one-older");
    let o = draw(&older, &["--position", "5,10", "--positions-from", "1"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(older.join("velocity_5.svg")).unwrap();
    assert!(svg.contains("position 5,"), "velocity_5.svg");
    assert_eq!(
        svg.replace("position 5,", "position 4,"),
        std::fs::read_to_string(some.join("velocity_4.svg")).unwrap()
    );
    // A position the scene has not: refused, naming the range.
    for (p, from, range) in [("12", "0", "from 0 to 11"), ("0", "1", "from 1 to 12")] {
        let o = draw(
            &dir("one-bad"),
            &["--position", p, "--positions-from", from],
        );
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(&format!(
                "--position: position {p} is not one of the scene's positions: they are numbered {range}"
            )),
            "{err}"
        );
    }
}

#[test]
fn a_refused_draw_creates_nothing_and_an_interrupted_one_is_cleared() {
    // Refused before the first sheet: the output folder is not made.
    let out = std::env::temp_dir().join(format!(
        "mechplan-stream-refused-out-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&out);
    let scene = scene_with_count("refused", 12);
    let o = Command::new(EXE)
        .args(["draw", scene.to_str().unwrap(), "--position", "13", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists(), "a refused draw made {}", out.display());
    // A run killed mid-way leaves its staging folder (its sheets, not in
    // place); the next run into the folder removes it and says so.
    let out = dir("interrupted");
    let dead = out.join(".mechplan-staging-4000000000");
    std::fs::create_dir_all(&dead).unwrap();
    std::fs::write(dead.join("velocity_1.svg"), "<svg/>").unwrap();
    std::fs::write(dead.join("velocity_2.svg"), "<svg/>").unwrap();
    let o = Command::new(EXE)
        .args(["draw", scene.to_str().unwrap(), "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("removed 2 unfinished file(s) of 1 interrupted run(s)"),
        "{err}"
    );
    let hidden = std::fs::read_dir(&out)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .starts_with('.')
        })
        .count();
    assert_eq!(hidden, 0);
}
