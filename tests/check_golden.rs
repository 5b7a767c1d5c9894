//! The fast path's check (no plans: `solve --format csv` and `table`)
//! made cheaper must decide as before, to the bit (issue 41): for every
//! fixture as it is and over a fine sweep, and every scene of the stress
//! catalogue as it is, the CSV rows, every position's check figures (its kind, the
//! residual, the data sensitivity, the conditioning, the orientation and,
//! where printed, the bounds) and the refusal's message, hashed (SHA-256)
//! per scene and compared with `tests/golden/fast_check.sha256`, which was
//! made before the check was changed. Both with the check printed (the
//! JSON result: the SVD's conditioning, the bounds) and not (table, CSV:
//! the conditioning only decided).
//!
//! `MECHPLAN_BLESS=1 cargo test --release --test check_golden` writes the
//! file anew (only for a change meant to move the check's figures).

use mechplan::scene::PositionsSpec;
use mechplan::{Analysis, Scene};
use sha2::{Digest, Sha256};
use std::fmt::Write as _;
use std::path::Path;

const GOLDEN: &str = "tests/golden/fast_check.sha256";

/// Positions of each fixture's sweep (a full turn of its input).
const SWEEP: usize = 1500;

/// Every fixture as it is and at `SWEEP` positions (where a crank turns
/// fully), every stress scene as it is.
fn scenes() -> Vec<(String, Scene)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut v = Vec::new();
    for (dir, sweep) in [("fixtures", true), ("fixtures/stress", false)] {
        let mut paths: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        paths.sort();
        for p in paths {
            let text = std::fs::read_to_string(&p).unwrap();
            let Ok(mut scene) = Scene::from_json(&text) else {
                continue;
            };
            scene.want.plans = false;
            let name = p.strip_prefix(root).unwrap().display().to_string();
            if sweep {
                let mut fine = scene.clone();
                fine.positions = PositionsSpec::Count {
                    count: SWEEP,
                    output: None,
                };
                v.push((format!("{name} (sweep)"), fine));
            }
            v.push((name, scene));
        }
    }
    v
}

/// The text of one scene's fast path, the check printed or not: a line
/// per position (CSV row, check figures), then the error if any.
fn outcome(scene: &Scene, printed: bool) -> String {
    let mut out = String::new();
    let an = match Analysis::new(scene.clone()) {
        Ok(mut an) => {
            an.printed_check = printed;
            an
        }
        Err(e) => return format!("refused: {e}\n"),
    };
    let mut k = 0;
    let done = an.run_each(|s| {
        out.push_str(&mechplan::report::csv_row(&an, k, &s));
        if let Some(c) = &s.check {
            writeln!(
                out,
                "{:?} {:e} {} {:?} {:e} {:?} {:?}",
                c.method,
                c.max_rel_diff,
                c.worst,
                c.data_sensitivity,
                c.conditioning,
                c.orientation,
                c.bound
            )
            .unwrap();
        }
        k += 1;
        Ok(())
    });
    if let Err(e) = done {
        writeln!(out, "error: {e}").unwrap();
    }
    out
}

fn hashes() -> Vec<String> {
    let mut lines = Vec::new();
    for (name, scene) in scenes() {
        for printed in [false, true] {
            let text = outcome(&scene, printed);
            let refused = text.contains("error: ") || text.starts_with("refused: ");
            let rows = text.lines().count();
            let hash: String = Sha256::digest(text.as_bytes())
                .iter()
                .map(|b| format!("{b:02x}"))
                .collect();
            let kind = if printed { "printed" } else { "decided" };
            lines.push(format!(
                "{name} {kind} {hash} lines={rows} refused={refused}"
            ));
        }
    }
    lines
}

#[test]
fn fast_check_decides_as_before() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let got = hashes();
    if std::env::var_os("MECHPLAN_BLESS").is_some() {
        std::fs::write(root.join(GOLDEN), got.join("\n") + "\n").unwrap();
        return;
    }
    let want = std::fs::read_to_string(root.join(GOLDEN)).unwrap();
    let want: Vec<&str> = want.lines().collect();
    // The catalogue covers refusals as well as answers.
    let refused = want.iter().filter(|l| l.ends_with("refused=true")).count();
    assert!(
        want.len() > 100 && refused > 10,
        "{} scenes, {refused} refused",
        want.len()
    );
    let differ: Vec<String> = want
        .iter()
        .zip(&got)
        .filter(|(w, g)| **w != g.as_str())
        .map(|(w, g)| format!("was {w}\nnow {g}"))
        .collect();
    assert_eq!(
        want.len(),
        got.len(),
        "scenes: {} then, {} now",
        want.len(),
        got.len()
    );
    assert!(differ.is_empty(), "{}", differ.join("\n"));
}
