//! Failed writes: every command checks every write to standard output and
//! to files, exits with status 3 and a message naming the path (or
//! "standard output"), and leaves no temporary file behind. The failures
//! are real: /dev/full (no space left), a file-size limit (`ulimit -f`,
//! with SIGXFSZ ignored as Python's subprocess leaves it, so the write
//! fails with EFBIG), a read-only folder, a path under a regular file.
#![cfg(target_os = "linux")]

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn fixture(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-out-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Every entry of `dir` (none may be a leftover temporary).
fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Run `mechplan ARGS` with standard output going to /dev/full.
fn to_dev_full(args: &[&str]) -> Output {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    Command::new(EXE)
        .args(args)
        .stdout(Stdio::from(full))
        .output()
        .unwrap()
}

/// Run `mechplan ARGS` under a file-size limit of `blocks` × 1024 bytes,
/// SIGXFSZ ignored, standard output to `stdout`.
fn limited(blocks: u32, args: &[&str], stdout: &Path) -> Output {
    let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
    Command::new("bash")
        .arg("-c")
        .arg(format!(
            "trap '' XFSZ; ulimit -f {blocks}; exec '{EXE}' {} > '{}'",
            quoted.join(" "),
            stdout.display()
        ))
        .output()
        .unwrap()
}

#[test]
fn every_command_fails_on_a_full_standard_output() {
    let six = fixture("six_link_fig2_10");
    let four = fixture("four_bar");
    let dir = temp_dir("full-stdout");
    let answer = dir.join("answer.json");
    std::fs::write(
        &answer,
        r#"{ "plan": "velocity", "mu": 0.01, "points": { "b": [1, 2] } }"#,
    )
    .unwrap();
    let (draw_dir, frenet_dir, diagram_dir) = (
        dir.join("draw").display().to_string(),
        dir.join("frenet").display().to_string(),
        dir.join("diagram").display().to_string(),
    );
    let answer = answer.display().to_string();
    let cases: Vec<Vec<&str>> = vec![
        vec!["solve", &six],
        vec!["solve", &six, "--format", "json"],
        vec!["solve", &six, "--steps"],
        vec!["check", &six, &answer],
        vec!["draw", &six, "-o", &draw_dir],
        vec!["draw", &six, "-o", &draw_dir, "--html"],
        vec!["diagram", &six],
        vec!["diagram", &six, "-o", &diagram_dir],
        vec!["centres", &four],
        vec!["centres", &four, "--format", "json"],
        vec!["invariants", &six],
        vec![
            "precision",
            &four,
            "--seeds",
            "2",
            "--positions",
            "4",
            "--min-time",
            "0.001",
        ],
        vec!["frenet", "-o", &frenet_dir],
    ];
    for args in cases {
        let o = to_dev_full(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(3), "{args:?}: {err}");
        assert!(
            err.contains("cannot write standard output") && err.contains("No space left"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn a_file_size_limit_fails_solve_and_leaves_no_temporary() {
    let six = fixture("six_link_fig2_10");
    let dir = temp_dir("ulimit-solve");
    // Standard output cut by the limit.
    let out = dir.join("stdout.json");
    let o = limited(1, &["solve", &six, "--format", "json"], &out);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("cannot write standard output"));
    // A file given by -o: nothing at all, and no temporary.
    let target = dir.join("result.json");
    let t = target.display().to_string();
    for format in ["json", "table"] {
        let o = limited(
            1,
            &["solve", &six, "--format", format, "-o", &t],
            &dir.join("log"),
        );
        assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("cannot write {t}")),
            "{}",
            stderr(&o)
        );
        assert_eq!(entries(&dir), vec!["log", "stdout.json"]);
    }
}

#[test]
fn a_file_size_limit_fails_draw_and_leaves_none_of_its_temporaries() {
    // Two sheets: velocity_1 (about 4.4 kB) fits under the limit and is
    // written to its temporary first; acceleration_1 (about 6 kB) does not.
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fixture("six_link_fig2_10")).unwrap())
            .unwrap();
    v["want"]["drawings"] = serde_json::json!(["velocity", "acceleration"]);
    v["positions"] = serde_json::json!({ "angles": [60] });
    let dir = temp_dir("ulimit-draw");
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let sheets = dir.join("sheets");
    let (s, d) = (scene.display().to_string(), sheets.display().to_string());
    let o = Command::new(EXE)
        .args(["draw", &s, "-o", &d])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let small = std::fs::metadata(sheets.join("velocity_1.svg"))
        .unwrap()
        .len();
    let large = std::fs::metadata(sheets.join("acceleration_1.svg"))
        .unwrap()
        .len();
    let blocks = (small / 1024 + 1) as u32;
    assert!(large > 1024 * blocks as u64, "{small} {large}");
    std::fs::remove_dir_all(&sheets).unwrap();
    let o = limited(blocks, &["draw", &s, "-o", &d], &dir.join("log"));
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("acceleration_1.svg") && stderr(&o).contains("cannot write"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        entries(&sheets),
        Vec::<String>::new(),
        "nothing left in {d}"
    );
    // The handout: one file, no temporary either.
    let o = limited(blocks, &["draw", &s, "-o", &d, "--html"], &dir.join("log"));
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("handout.html"), "{}", stderr(&o));
    assert_eq!(entries(&sheets), Vec::<String>::new());
}

#[test]
fn a_full_device_as_target_is_written_to_and_fails() {
    // A device is written to directly (a rename would replace it, and an
    // older mechplan run by root did replace /dev/full with a regular
    // file): the write fails, no temporary appears, the device stays. The
    // device is reached through a link in a temporary folder, so that a
    // regression replaces the link, never the device.
    use std::os::unix::fs::symlink;
    let six = fixture("six_link_fig2_10");
    let dir = temp_dir("device");
    let (full, null) = (dir.join("full"), dir.join("null"));
    symlink("/dev/full", &full).unwrap();
    symlink("/dev/null", &null).unwrap();
    let f = full.display().to_string();
    let o = Command::new(EXE)
        .args(["solve", &six, "--format", "json", "-o", &f])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!("cannot write {f}")),
        "{}",
        stderr(&o)
    );
    assert_eq!(entries(&dir), vec!["full", "null"]);
    assert!(
        std::fs::symlink_metadata(&full)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    let n = null.display().to_string();
    let o = Command::new(EXE)
        .args(["solve", &six, "-o", &n])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(entries(&dir), vec!["full", "null"]);
    assert!(
        std::fs::symlink_metadata(&null)
            .unwrap()
            .file_type()
            .is_symlink()
    );
}

#[test]
fn an_unwritable_target_fails_with_its_path() {
    let six = fixture("six_link_fig2_10");
    let dir = temp_dir("unwritable");
    // A path under a regular file: no folder can be made there.
    let file = dir.join("plain");
    std::fs::write(&file, "x").unwrap();
    let under = file.join("result.json").display().to_string();
    let o = Command::new(EXE)
        .args(["solve", &six, "-o", &under])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains(&under), "{}", stderr(&o));
    let under_dir = file.join("sheets").display().to_string();
    for extra in [&[][..], &["--html"][..]] {
        let mut args = vec!["draw", &six, "-o", &under_dir];
        args.extend_from_slice(extra);
        let o = Command::new(EXE).args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(3), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(&under_dir), "{}", stderr(&o));
    }
    // A read-only folder (not for root, who writes there anyway).
    use std::os::unix::fs::PermissionsExt;
    let ro = dir.join("read-only");
    std::fs::create_dir_all(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    let probe = ro.join("probe");
    if std::fs::write(&probe, "x").is_ok() {
        let _ = std::fs::remove_file(&probe);
        eprintln!("running as root: the read-only folder case is skipped");
    } else {
        let target = ro.join("result.json").display().to_string();
        let o = Command::new(EXE)
            .args(["solve", &six, "-o", &target])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
        assert!(stderr(&o).contains(&target), "{}", stderr(&o));
        assert_eq!(entries(&ro), Vec::<String>::new());
    }
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
}

/// A bad scene is still status 2 (bad input), not 3.
#[test]
fn bad_input_keeps_status_2() {
    let o = Command::new(EXE)
        .args(["solve", "/nonexistent/scene.json"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}
