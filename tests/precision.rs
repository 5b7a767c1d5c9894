//! The work-precision report on the four-bar with small settings: every
//! method is there, and the errors are ordered as they must be.

use mechplan::precision::{self, Row, Settings};
use mechplan::{Analysis, Scene};

fn four_bar() -> Analysis {
    let text = std::fs::read_to_string(format!(
        "{}/fixtures/four_bar.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    Analysis::new(Scene::from_json(&text).unwrap()).unwrap()
}

fn row<'a>(rows: &'a [Row], method: &str, setting: &str) -> &'a Row {
    rows.iter()
        .find(|r| r.method == method && r.setting == setting)
        .unwrap_or_else(|| panic!("no row {method} {setting}"))
}

#[test]
fn report_on_the_four_bar_has_its_shape() {
    let an = four_bar();
    let set = Settings {
        newton_tols: vec![1e-4, 1e-14],
        diagram_ns: vec![36, 360, 3600],
        seeds: 4,
        delta: 0.5,
        positions: Some(8),
        min_time: 0.003,
    };
    let r = precision::run(&an, &set).unwrap();
    assert_eq!(r.positions, 8);
    for m in ["kernel", "contour", "newton", "chords", "central", "hand"] {
        assert!(r.rows.iter().any(|x| x.method == m), "method {m} missing");
    }
    for x in &r.rows {
        assert!(
            x.time > 0.0 && x.time < 0.1,
            "{} {}: {} s",
            x.method,
            x.setting,
            x.time
        );
        assert!(x.compared > 0);
    }
    // The exact routes are at the level of f64.
    for m in ["kernel", "contour"] {
        let w = row(&r.rows, m, "").worst();
        assert!(w < 1e-14, "{m}: {w:.2e}");
    }
    let loose = row(&r.rows, "newton", "tol 1e-4").worst();
    let tight = row(&r.rows, "newton", "tol 1e-14").worst();
    assert!(
        tight < loose,
        "Newton 1e-14 {tight:.2e} not below 1e-4 {loose:.2e}"
    );
    assert!(tight < 1e-14, "{tight:.2e}");
    // Central differences are of the second order: ×10 positions, ÷100 error.
    let (c360, c3600) = (
        row(&r.rows, "central", "N = 360"),
        row(&r.rows, "central", "N = 3600"),
    );
    for k in 1..5 {
        let (a, b) = (c360.err[k].unwrap().max, c3600.err[k].unwrap().max);
        let ratio = a / b;
        assert!(
            (60.0..160.0).contains(&ratio),
            "{}: N = 360 {a:.2e}, N = 3600 {b:.2e}, ratio {ratio:.1}",
            precision::KINDS[k]
        );
    }
    // Hand drafting at δ = 0.5 mm is far coarser than any computation,
    // and the chords carried to the midpoints beat central differences for v.
    let hand = row(&r.rows, "hand", "δ = 0.5 mm, 4 seeds");
    assert!(hand.worst_rates() > 1e-5 && hand.worst_rates() < 0.2);
    assert!(hand.err[0].is_none());
    let ch = row(&r.rows, "chords", "N = 360");
    assert!(ch.err[1].unwrap().max < c360.err[1].unwrap().max);
    // The table and the plot.
    let md = mechplan::presentation::precision::to_markdown(&r);
    assert_eq!(md.lines().count(), 2 + r.rows.len());
    let svg = mechplan::presentation::precision::to_svg(&r, "four_bar");
    mechplan::drawing::tree(&svg).unwrap();
    assert!(svg.contains("run time per position"));
}
