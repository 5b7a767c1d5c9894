//! Long sweeps: `solve` writes each position as soon as it is solved and
//! drops it (`Analysis::run_each`, the result text a position at a time),
//! so memory does not grow with the number of positions; the text is byte
//! for byte the document's; a refusal at a late position writes nothing.

mod common;
use common::*;
use mechplan::report::{self, Style};
use std::path::PathBuf;
use std::process::{Command, Output};

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-sweeps-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A position's JSON without its wall times (which differ run to run).
fn without_times(mut v: serde_json::Value) -> serde_json::Value {
    if let Some(c) = v.get_mut("crosscheck").and_then(|c| c.as_object_mut()) {
        c.remove("time_s");
    }
    v
}

#[test]
fn streamed_text_is_the_document_byte_for_byte() {
    for name in FIXTURES {
        let v = fixture(name);
        for positions in [sweep(name, &v), v["positions"].clone()] {
            if positions.is_null() {
                continue;
            }
            let (an, solved) = solve(scene_with(v.clone(), positions));
            let whole =
                serde_json::to_string_pretty(&report::to_json(&an, &solved)).unwrap() + "\n";
            assert_eq!(report::to_text(&an, &solved, Style::Json), whole, "{name}");
            assert_eq!(
                report::to_text(&an, &solved, Style::Table(mechplan::Lang::En)),
                report::to_table(&an, &solved, mechplan::Lang::En),
                "{name}"
            );
        }
    }
    // Several chunks of positions; and no positions at all.
    let v = fixture("six_link_fig2_10");
    let (an, solved) = solve(scene_with(v, serde_json::json!({ "count": 1100 })));
    assert!(solved.len() > 2 * mechplan::pipeline::RUN_CHUNK);
    let whole = serde_json::to_string_pretty(&report::to_json(&an, &solved)).unwrap() + "\n";
    assert_eq!(report::to_text(&an, &solved, Style::Json), whole);
    let none = serde_json::to_string_pretty(&report::to_json(&an, &[])).unwrap() + "\n";
    assert_eq!(report::to_text(&an, &[], Style::Json), none);
    // run_each hands over what run returns, in order.
    let mut each = Vec::new();
    an.run_each(|s| {
        each.push(without_times(report::position_json(&an, each.len(), &s)));
        Ok(())
    })
    .unwrap();
    let all: Vec<_> = solved
        .iter()
        .enumerate()
        .map(|(k, s)| without_times(report::position_json(&an, k, s)))
        .collect();
    assert_eq!(each, all);
}

/// 20 000 positions of the six-link mechanism used to take 1.9 GB (every
/// position kept with its plans, a route (b) solver per position, then the
/// whole JSON tree); now they run with the process's data limited to
/// 512 MiB (about 25 MB are used), to a file and to standard output.
#[cfg(target_os = "linux")]
#[test]
fn a_long_sweep_runs_in_bounded_memory() {
    let dir = temp_dir("memory");
    let mut v = fixture("six_link_fig2_10");
    v["positions"] = serde_json::json!({ "count": 20000 });
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = dir.join("result.json");
    let limited = |args: &str| {
        Command::new("bash")
            .arg("-c")
            .arg(format!("ulimit -d 524288; exec '{EXE}' {args}"))
            .output()
            .unwrap()
    };
    let o = limited(&format!(
        "solve '{}' --format json -o '{}'",
        scene.display(),
        out.display()
    ));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("{\n  \"mechplan\": 1,") && text.ends_with("\n  ]\n}\n"));
    assert_eq!(text.matches("\n      \"input\": {").count(), 20000);
    std::fs::remove_file(&out).unwrap();
    drop(text);
    // Standard output: held back, in a temporary file beyond 64 MiB.
    let o = limited(&format!("solve '{}' --format json", scene.display()));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.len() > mechplan::study::files::Spool::MEMORY);
    assert_eq!(text.matches("\n      \"input\": {").count(), 20000);
    assert!(text.ends_with("\n  ]\n}\n"));
}

#[test]
fn a_refusal_at_a_late_position_writes_nothing() {
    // A triple rocker swept over 700 positions within its limits, then one
    // beyond them: refused after two chunks were written.
    let mut v: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(format!(
            "{}/fixtures/stress/non_grashof_beyond.json",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap(),
    )
    .unwrap();
    let mut angles: Vec<f64> = (0..700).map(|k| 0.3 + 1.2 * k as f64 / 700.0).collect();
    angles.push(1.7);
    v["positions"] = serde_json::json!({ "angles": angles });
    let dir = temp_dir("late");
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let (s, out) = (
        scene.display().to_string(),
        dir.join("result.json").display().to_string(),
    );
    for args in [
        vec!["solve", &s, "--format", "json", "-o", &out],
        vec!["solve", &s, "-o", &out],
        vec!["solve", &s, "--format", "json"],
        vec!["solve", &s, "--steps"],
    ] {
        let o = Command::new(EXE).args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("cannot be assembled"), "{}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?}: printed half a result");
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(left, vec!["scene.json"], "{args:?}");
    }
}

/// A million positions of the four-bar to CSV (issue 41): a count passes
/// the lists' 100 000 (`MAX_POSITIONS`; the steps are made as the sweep
/// reaches them, no list is kept) and the rows are written as they are
/// solved, so the run fits the process's data limited to 100 MB. About
/// 30 s in release on the project's 2-core machine (a 577 MB file, removed
/// after); left out of debug builds, where it would take many minutes.
#[cfg(target_os = "linux")]
#[cfg_attr(debug_assertions, ignore = "a million positions: run in release")]
#[test]
fn a_million_positions_stream_to_csv_within_100_mb() {
    use std::io::BufRead;
    let dir = temp_dir("million");
    let mut v = fixture("four_bar");
    v["positions"] = serde_json::json!({ "count": 1_000_000 });
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = dir.join("result.csv");
    let o = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "ulimit -d 102400; exec '{EXE}' solve '{}' --format csv -o '{}'",
            scene.display(),
            out.display()
        ))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let file = std::io::BufReader::new(std::fs::File::open(&out).unwrap());
    let (mut rows, mut last) = (0usize, String::new());
    for line in file.lines() {
        last = line.unwrap();
        rows += 1;
    }
    std::fs::remove_dir_all(&dir).unwrap();
    // The header and a row a position, numbered from 0 (a count sweep).
    assert_eq!(rows, 1_000_001);
    assert!(last.starts_with("999999,"), "{last}");
}

/// What holds every position at once (the sheets, here) takes at most
/// `MAX_POSITIONS` of a longer count, refused at once naming the field;
/// `solve` takes it.
#[test]
fn drawing_refuses_a_count_beyond_what_it_holds() {
    let dir = temp_dir("held");
    let mut v = fixture("four_bar");
    let n = mechplan::scene::MAX_POSITIONS + 1;
    v["positions"] = serde_json::json!({ "count": n });
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let sheets = dir.join("sheets");
    let o = Command::new(EXE)
        .args(["draw", &scene.display().to_string(), "-o"])
        .arg(&sheets)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains(&format!("/positions/count: {n} positions"))
            && e.contains("at most 100000")
            && e.contains("`mechplan solve`"),
        "{e}"
    );
    assert!(!sheets.join("sheets.json").exists());
    // The work-precision report holds them all too (and their references).
    let o = Command::new(EXE)
        .args(["precision", &scene.display().to_string()])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("/positions/count"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The library's `Analysis::run` holds every position: a count beyond
/// what it holds is refused at once, naming the field, where
/// `run_each` streams any count.
#[test]
fn the_library_run_refuses_a_count_it_cannot_hold() {
    let path = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["positions"]["count"] = serde_json::json!(200_000);
    let an = mechplan::Analysis::new(mechplan::scene::Scene::from_json(&v.to_string()).unwrap())
        .unwrap();
    let t = std::time::Instant::now();
    let e = an.run().expect_err("200 000 positions held").to_string();
    assert!(t.elapsed().as_secs_f64() < 1.0, "refused before solving");
    assert!(
        e.contains("/positions/count") && e.contains("run_each"),
        "{e}"
    );
    // The same scene streams.
    let mut n = 0;
    an.run_each(|_| {
        n += 1;
        if n == 50 {
            return Err(mechplan::Error::scene("/stop", "enough"));
        }
        Ok(())
    })
    .expect_err("stopped after 50");
    assert_eq!(n, 50);
}
