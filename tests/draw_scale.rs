//! The scale of the plan of the mechanism, μ_l: a scene that fixes it
//! (`want.scales.mu_l`) is drawn at it, and a drawing that does not fit
//! the sheet asked for is refused with the reason (without `--sheet`, the
//! smallest sheet that holds it is used); a scene that leaves it open is
//! drawn at the scale that fills the sheet, stated on the sheet and in the
//! manifest.

use std::path::PathBuf;
use std::process::{Command, Output};

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn run(args: &[&str]) -> Output {
    Command::new(EXE).args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-scale-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn fixture_path(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

/// `solve`'s μ_l of a scene file.
fn solve_mu_l(scene: &str) -> f64 {
    let o = run(&["solve", scene, "--format", "json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    v["mu_l"].as_f64().unwrap()
}

/// The μ_l written on a mechanism sheet ("μ_l = 0.005 m/mm").
fn drawn_mu_l(svg: &str) -> f64 {
    let end = svg.find(" m/mm").expect("a scale label in m/mm");
    let start = svg[..end].rfind("= ").unwrap() + 2;
    svg[start..end].parse().unwrap()
}

fn scene_with_mu_l(tag: &str, mu_l: f64) -> String {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fixture_path("six_link_fig2_10")).unwrap())
            .unwrap();
    v["want"]["scales"] = serde_json::json!({ "mu_l": mu_l });
    let p = dir(tag).join("scene.json");
    std::fs::write(&p, v.to_string()).unwrap();
    p.display().to_string()
}

/// The scales the manifest gives for a sheet file.
fn manifest_scale(dir: &std::path::Path, file: &str, key: &str) -> f64 {
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sheets.json")).unwrap()).unwrap();
    m["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["file"] == file)
        .and_then(|s| s["scales"][key].as_f64())
        .unwrap_or_else(|| panic!("no {key} for {file} in the manifest"))
}

#[test]
fn an_open_mu_l_fills_the_sheet_and_is_stated() {
    for entry in std::fs::read_dir(format!("{}/fixtures", env!("CARGO_MANIFEST_DIR"))).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let scene = path.display().to_string();
        let out = dir("fixtures").join("sheets");
        let o = run(&["draw", &scene, "-o", out.to_str().unwrap()]);
        assert!(o.status.success(), "{scene}: {}", stderr(&o));
        let svg = std::fs::read_to_string(out.join("mechanism_1.svg")).unwrap();
        assert!(svg.contains(r#"width="297mm""#), "{scene}: drawn on A4");
        assert_eq!(
            drawn_mu_l(&svg),
            manifest_scale(&out, "mechanism_1.svg", "mu_l"),
            "{scene}"
        );
    }
}

#[test]
fn a_mu_l_that_fits_is_drawn_as_given() {
    let scene = scene_with_mu_l("fits", 0.01);
    assert_eq!(solve_mu_l(&scene), 0.01);
    let out = dir("fits-out");
    let o = run(&["draw", &scene, "-o", out.to_str().unwrap(), "--sheet", "A4"]);
    assert!(o.status.success(), "{}", stderr(&o));
    for sheet in ["mechanism_1.svg", "positions.svg"] {
        let svg = std::fs::read_to_string(out.join(sheet)).unwrap();
        assert_eq!(drawn_mu_l(&svg), 0.01, "{sheet}");
    }
}

#[test]
fn a_mu_l_that_does_not_fit_is_refused_with_the_reason() {
    // At 0.001 m/mm the six-link mechanism's positions span about
    // 976 × 407 mm: more than any sheet's field.
    let scene = scene_with_mu_l("too-small", 0.001);
    assert_eq!(solve_mu_l(&scene), 0.001);
    for sheet in [&["--sheet", "A4"][..], &[][..]] {
        let out = dir("too-small-out");
        let mut args = vec!["draw", &scene, "-o", out.to_str().unwrap()];
        args.extend_from_slice(sheet);
        let o = run(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{sheet:?}: {err}");
        for part in [
            "/want/scales/mu_l",
            "at μ_l = 0.001 m/mm",
            " mm × ",
            "larger than the field of",
            "(260.0 mm × 178.0 mm)",
            "the smallest standard μ_l that fits sheet A4 is 0.005 m/mm",
        ] {
            if part.starts_with("(260") && sheet.is_empty() {
                continue;
            }
            assert!(err.contains(part), "{sheet:?}: no \"{part}\" in {err}");
        }
        assert_eq!(
            std::fs::read_dir(&out).unwrap().count(),
            0,
            "nothing is drawn"
        );
    }
    // A fixed μ_l that does not fit A4: refused on A4 (the message offers
    // A3), drawn on A3 with a note when no sheet is asked for.
    let scene = scene_with_mu_l("a3", 0.003);
    let out = dir("a3-out");
    let o = run(&["draw", &scene, "-o", out.to_str().unwrap(), "--sheet", "A4"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--sheet") && err.contains("or draw on --sheet A3"),
        "{err}"
    );
    let o = run(&["draw", &scene, "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("drawn on A3"), "{}", stderr(&o));
    let svg = std::fs::read_to_string(out.join("mechanism_1.svg")).unwrap();
    assert!(svg.contains(r#"width="420mm""#));
    assert_eq!(drawn_mu_l(&svg), 0.003);
}

fn scene_with_scales(tag: &str, scales: serde_json::Value) -> String {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fixture_path("six_link_fig2_10")).unwrap())
            .unwrap();
    v["want"]["scales"] = scales;
    let p = dir(tag).join("scene.json");
    std::fs::write(&p, v.to_string()).unwrap();
    p.display().to_string()
}

/// `draw` under a memory limit (a scale nobody can draw once ran to
/// gigabytes before refusing): its output, and the wall time.
fn draw_limited(scene: &str, out: &std::path::Path) -> (Output, std::time::Duration) {
    let t = std::time::Instant::now();
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 400000; exec '{EXE}' draw '{scene}' -o '{}'",
            out.display()
        ))
        .output()
        .unwrap();
    (o, t.elapsed())
}

#[test]
fn a_scale_no_sheet_can_hold_is_refused_at_once() {
    // The joints alone at μ_l = 1e-9 m/mm span 9.5e8 mm: refused before
    // anything is drawn (it once took 20 s and 690 MB at 1e-6, and ran
    // out of memory at 1e-9), as are plans at μ_v or μ_a = 1e-9.
    for (tag, scales, field, part) in [
        (
            "l",
            serde_json::json!({ "mu_l": 1e-9 }),
            "/want/scales/mu_l",
            "is at least (its joints alone) 9.537e8 mm × 3.997e8 mm",
        ),
        (
            "v",
            serde_json::json!({ "mu_v": 1e-9 }),
            "/want/scales/mu_v",
            "the smallest standard μ_v that fits every position is 0.02 (m/s)/mm",
        ),
        (
            "a",
            serde_json::json!({ "mu_a": 1e-9 }),
            "/want/scales/mu_a",
            "the smallest standard μ_a that fits every position is 0.2 (m/s²)/mm",
        ),
    ] {
        let scene = scene_with_scales(&format!("absurd-{tag}"), scales);
        let out = dir(&format!("absurd-{tag}-out"));
        let (o, took) = draw_limited(&scene, &out);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{tag}: {err}");
        assert!(err.contains(field) && err.contains(part), "{tag}: {err}");
        assert!(took.as_secs_f64() < 1.0, "{tag}: refused after {took:?}");
        assert_eq!(std::fs::read_dir(&out).unwrap().count(), 0, "nothing drawn");
    }
}

#[test]
fn a_plan_scale_that_overflows_one_position_is_refused_naming_it() {
    // At μ_v = 0.01 (m/s)/mm the six-link's velocity plan at position 8
    // (its sheets count from 0) is 184.6 mm tall, more than A4's 178 mm field: once drawn off the
    // sheet without a word, now refused with the scale that fits all
    // twelve positions, at which it is drawn.
    let scene = scene_with_scales("v-over", serde_json::json!({ "mu_v": 0.01 }));
    let out = dir("v-over-out");
    let o = run(&["draw", &scene, "-o", out.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    for part in [
        "/want/scales/mu_v",
        "136.7 mm × 184.6 mm at position 8",
        "(260.0 mm × 178.0 mm)",
        "fits every position is 0.02 (m/s)/mm",
    ] {
        assert!(err.contains(part), "no \"{part}\" in {err}");
    }
    let scene = scene_with_scales("v-fits", serde_json::json!({ "mu_v": 0.02 }));
    let out = dir("v-fits-out");
    let o = run(&["draw", &scene, "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    for k in 0..12 {
        assert_eq!(
            manifest_scale(&out, &format!("velocity_{k}.svg"), "mu_v"),
            0.02
        );
    }
}

/// The four-bar scaled by `k` (every coordinate and length), one position.
fn four_bar_scaled(tag: &str, k: f64) -> String {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(fixture_path("four_bar")).unwrap()).unwrap();
    for (_, p) in v["points"].as_object_mut().unwrap() {
        for c in p.as_array_mut().unwrap() {
            *c = serde_json::json!(c.as_f64().unwrap() * k);
        }
    }
    for (_, l) in v["lengths"].as_object_mut().unwrap() {
        *l = serde_json::json!(l.as_f64().unwrap() * k);
    }
    v["positions"] = serde_json::json!({ "count": 1 });
    let p = dir(tag).join(format!("scene-{k}.json"));
    std::fs::write(&p, v.to_string()).unwrap();
    p.display().to_string()
}

/// The plan of the mechanism's μ_l is one of ГОСТ 2.302's scales of a
/// drawing, as the standard prints them (1:15 and 1:75 among them, no
/// 1:250), from a four-bar of a few millimetres to one of hundreds of
/// metres; each of the standard's scales up to 1:1000 is met on the way.
#[test]
fn the_mechanism_takes_gost_2_302s_scales() {
    let printed = [
        "100:1", "50:1", "40:1", "20:1", "10:1", "5:1", "4:1", "2.5:1", "2:1", "1:1", "1:2",
        "1:2.5", "1:4", "1:5", "1:10", "1:15", "1:20", "1:25", "1:40", "1:50", "1:75", "1:100",
        "1:200", "1:400", "1:500", "1:800", "1:1000", // For large objects.
        "1:2000", "1:5000", "1:10000",
    ];
    let mu_of = |s: &str| {
        let (a, b) = s.split_once(':').unwrap();
        b.parse::<f64>().unwrap() / a.parse::<f64>().unwrap() * 1e-3
    };
    let mut met = std::collections::BTreeSet::new();
    // 1.08 apart: finer than the standard's closest steps (1:75 → 1:100
    // is ×1.33), from ×0.003 to ×3000.
    let mut k = 0.003f64;
    while k < 3000.0 {
        let mu = solve_mu_l(&four_bar_scaled("gost", k));
        let at = printed
            .iter()
            .position(|s| (mu_of(s) - mu).abs() <= 1e-9 * mu);
        let at = at.unwrap_or_else(|| panic!("×{k}: μ_l = {mu} m/mm is no scale of ГОСТ 2.302"));
        met.insert(at);
        k *= 1.08;
    }
    let missed: Vec<&str> = (0..printed.len() - 3)
        .filter(|i| !met.contains(i))
        .map(|i| printed[i])
        .collect();
    assert!(missed.is_empty(), "never chosen: {missed:?}");
}
