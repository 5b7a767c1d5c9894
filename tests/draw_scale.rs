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
