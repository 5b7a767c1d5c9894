//! `draw`'s memory against the number of positions (issue 41): the peak
//! resident set size of the command, read with `getrusage(RUSAGE_CHILDREN)`
//! (the largest of the children waited for; this file runs one test, so
//! no other test's child counts).
//!
//! The positions are held lean (`Solved::lean`: each plan reduced to its
//! rates, some 3 kB a position where a whole one is 20 to 35 kB, made so
//! as each is finished) and each position's own sheets build its plans
//! again; the manifest is printed sheet by sheet; the positions sheet of
//! a long sweep draws the numbered positions only (some 24). What still
//! grows with the count: the lean positions themselves (the mechanism's
//! scale and box read every position before the first sheet is drawn)
//! and the writer's list of the sheets for the manifest. So 2 000
//! positions take about 1.9× the peak of 200 on the four-bar (21 MB
//! against 11 MB; 5.6× before), not yet the 1.5× issue 41 asks for
//! (docs/performance.md, "draw at any count").

#![cfg(target_os = "linux")]

use std::path::PathBuf;
use std::process::Command;

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

/// `struct rusage` of Linux on a 64-bit machine: two `timeval`s, then
/// fourteen `long`s, the first the peak resident set size in KiB.
#[repr(C)]
struct Usage {
    user: [i64; 2],
    system: [i64; 2],
    max_rss_kib: i64,
    rest: [i64; 13],
}

unsafe extern "C" {
    fn getrusage(who: i32, usage: *mut Usage) -> i32;
}

/// `RUSAGE_CHILDREN`.
const CHILDREN: i32 = -1;

/// The largest peak resident set size (KiB) of the children waited for.
fn children_peak_kib() -> i64 {
    let mut u = Usage {
        user: [0; 2],
        system: [0; 2],
        max_rss_kib: 0,
        rest: [0; 13],
    };
    // SAFETY: `u` is a writable `struct rusage` of this platform's layout.
    let status = unsafe { getrusage(CHILDREN, &mut u) };
    assert_eq!(status, 0, "getrusage");
    u.max_rss_kib
}

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-draw-memory-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The peak (KiB) after drawing `count` positions of the four-bar fixture
/// with its own drawings (the positions sheet and each position's
/// mechanism, velocity and acceleration sheets).
fn draw_four_bar(count: usize) -> i64 {
    let path = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["positions"] = serde_json::json!({ "count": count });
    let d = dir(&count.to_string());
    let scene = d.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = d.join("sheets");
    let o = Command::new(EXE)
        .args(["draw", scene.to_str().unwrap(), "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sheets = std::fs::read_dir(&out).unwrap().count();
    // The manifest, the positions sheet and three sheets a position.
    assert_eq!(sheets, 2 + 3 * count);
    std::fs::remove_dir_all(&d).unwrap();
    children_peak_kib()
}

#[test]
fn two_thousand_positions_draw_within_twice_the_memory_of_two_hundred() {
    let short = draw_four_bar(200);
    // The peak of both runs: at least the long one's.
    let long = draw_four_bar(2000);
    println!("draw peak RSS: 200 positions {short} KiB, 2000 positions {long} KiB");
    assert!(
        long as f64 <= 2.0 * short as f64,
        "2000 positions took {long} KiB, 200 took {short} KiB"
    );
}
