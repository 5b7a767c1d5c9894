//! Motion-law invariants (paper 003): the known laws' peak constants, a
//! sine mechanism whose output is the harmonic law exactly, and the dwell
//! fixture built on a straight-line slider-crank.

use mechplan::invariants::{self, PhaseKind, Settings, peaks};
use mechplan::{Analysis, Scene};
use std::f64::consts::PI;

fn close(what: &str, got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-6 * want.abs().max(1.0),
        "{what}: {got} vs {want}"
    );
}

/// Harmonic (B = π/2, C = π²/2, D = π³/8), cycloidal (B = 2, C = 2π,
/// D = 3√3π/2) and parabolic, constant acceleration (B = 2, C = 4, D = 8)
/// reproduced from the sampled laws, on coarse and fine grids.
#[test]
fn known_laws_give_their_peak_constants() {
    let harmonic = |x: f64| {
        (
            (1.0 - (PI * x).cos()) / 2.0,
            PI / 2.0 * (PI * x).sin(),
            PI * PI / 2.0 * (PI * x).cos(),
        )
    };
    let cycloidal = |x: f64| {
        let t = 2.0 * PI * x;
        (x - t.sin() / (2.0 * PI), 1.0 - t.cos(), 2.0 * PI * t.sin())
    };
    let parabolic = |x: f64| {
        if x < 0.5 {
            (2.0 * x * x, 4.0 * x, 4.0)
        } else {
            (1.0 - 2.0 * (1.0 - x).powi(2), 4.0 * (1.0 - x), -4.0)
        }
    };
    for n in [7, 12, 50, 333] {
        let h = peaks(&harmonic, n);
        close("harmonic B", h.b, PI / 2.0);
        close("harmonic C", h.c, PI * PI / 2.0);
        close("harmonic D", h.d, PI.powi(3) / 8.0);
        let c = peaks(&cycloidal, n);
        close("cycloidal B", c.b, 2.0);
        close("cycloidal C", c.c, 2.0 * PI);
        close("cycloidal D", c.d, 3.0 * 3f64.sqrt() * PI / 2.0);
        let p = peaks(&parabolic, n);
        close("parabolic B", p.b, 2.0);
        close("parabolic C", p.c, 4.0);
        close("parabolic D", p.d, 8.0);
    }
}

/// A sine mechanism (Scotch yoke): the crank's pin slides in a vertical
/// slot of a yoke that slides horizontally, so the yoke follows r·cos φ:
/// the harmonic law exactly, on each half turn.
#[test]
fn a_scotch_yoke_moves_by_the_harmonic_law() {
    let scene = serde_json::json!({
        "mechplan": 1,
        "title": "Scotch yoke",
        "units": { "length": "m", "angle": "deg" },
        "points": { "O": [0, 0], "A": [0.0866025403784439, 0.05], "D": [0.0866025403784439, -0.2] },
        "links": {
            "0": { "points": ["O"] },
            "1": { "points": ["O", "A"] },
            "2": { "points": ["A"] },
            "3": { "points": ["D"] }
        },
        "sliders": [
            { "slider": "2", "guide": "3", "point": "A", "line": { "through": "D", "angle": 90 } },
            { "slider": "3", "guide": "0", "point": "D", "line": { "through": [0, -0.2], "angle": 0 } }
        ],
        "lengths": { "O-A": 0.1 },
        "input": { "link": "1", "pivot": "O", "angle": 30, "omega": 5 }
    });
    let an = Analysis::new(Scene::from_json(&scene.to_string()).unwrap()).unwrap();
    let set = Settings {
        output: invariants::default_output(&an),
        tolerance: 1e-3,
        min_dwell: 10f64.to_radians(),
        n: 720,
    };
    let list = invariants::phases(&an, &set).unwrap();
    assert_eq!(list.len(), 2, "{list:?}");
    for p in &list {
        assert!(p.kind != PhaseKind::Dwell);
        close("phase angle", p.span, PI);
        close("stroke", p.stroke, 0.2);
        let k = p.peaks.unwrap();
        close("B", k.b, PI / 2.0);
        close("C", k.c, PI * PI / 2.0);
        close("D", k.d, PI.powi(3) / 8.0);
    }
}

fn dwell_fixture() -> Analysis {
    let path = format!(
        "{}/fixtures/dwell_six_link_003.json",
        env!("CARGO_MANIFEST_DIR")
    );
    Analysis::new(Scene::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()).unwrap()
}

/// The six-link dwell mechanism: a dwell of about 54° at the lower extreme
/// within 0.1 % of the stroke; with the guide through the crank's centre
/// (e = 0) recess and approach have equal constants, as `003` says; and
/// the constants do not move with the grid.
#[test]
fn the_dwell_fixture_dwells_and_its_constants_are_stable() {
    let an = dwell_fixture();
    let run = |n: usize| {
        invariants::phases(
            &an,
            &Settings {
                output: invariants::default_output(&an),
                tolerance: 1e-3,
                min_dwell: 10f64.to_radians(),
                n,
            },
        )
        .unwrap()
    };
    let coarse = run(720);
    let fine = run(2880);
    let dwell = fine.iter().find(|p| p.kind == PhaseKind::Dwell).unwrap();
    let span = dwell.span.to_degrees();
    assert!((50.0..60.0).contains(&span), "dwell {span}°");
    let find =
        |l: &[invariants::Phase], k: PhaseKind| l.iter().find(|p| p.kind == k).unwrap().clone();
    let (r, a) = (
        find(&fine, PhaseKind::Recess),
        find(&fine, PhaseKind::Approach),
    );
    let (kr, ka) = (r.peaks.unwrap(), a.peaks.unwrap());
    close("B recess = approach", kr.b, ka.b);
    close("C recess = approach", kr.c, ka.c);
    close("D recess = approach", kr.d, ka.d);
    close("φ_p recess = approach", r.span, a.span);
    close(
        "phases fill the turn",
        r.span + a.span + dwell.span,
        2.0 * PI,
    );
    for k in [PhaseKind::Recess, PhaseKind::Approach] {
        let (c, f) = (
            find(&coarse, k).peaks.unwrap(),
            find(&fine, k).peaks.unwrap(),
        );
        close("B stable", c.b, f.b);
        close("C stable", c.c, f.c);
        close("D stable", c.d, f.d);
    }
    // A dwell mechanism's peaks exceed the harmonic law's over the same
    // stroke: it must move in less crank angle.
    assert!(kr.b > PI / 2.0 && kr.c > PI * PI / 2.0);
}

/// The command prints the phases as JSON; a bad option is refused.
#[test]
fn invariants_command_prints_phases_and_refuses_bad_options() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let scene = format!(
        "{}/fixtures/dwell_six_link_003.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = std::process::Command::new(exe)
        .args(["invariants", &scene, "--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let phases = v["phases"].as_array().unwrap();
    assert_eq!(phases.len(), 3);
    assert!(phases.iter().any(|p| p["phase"] == "dwell"));
    for (args, field) in [
        (vec!["--tolerance", "2"], "--tolerance"),
        (vec!["--output", "9"], "--output"),
        (vec!["--output", "0"], "--output"),
    ] {
        let out = std::process::Command::new(exe)
            .args(["invariants", &scene])
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(field),
            "{args:?}"
        );
    }
    // A slider input has no revolution to split into phases.
    let slider = format!(
        "{}/fixtures/slider_driven_rocker.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = std::process::Command::new(exe)
        .args(["invariants", &slider])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("crank"));
}
