//! One μ per plan: the scale a plan is built at is the one its steps
//! (`solve --steps`), the result file (`solve --format json`), its sheet
//! (`draw`, read back from `sheets.json`), the course sheet and the
//! handout (`draw --html`) state, each read from the written output.

use serde_json::Value;
use std::process::Command;

fn mechplan(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A number as a uk/ru or en text writes it.
fn number(t: &str) -> f64 {
    t.trim_end_matches(['.', ','])
        .replace(',', ".")
        .parse()
        .unwrap()
}

/// Every "μ_v = …" / "μ_a = …" of `text` after each mark (a plan's
/// heading, a handout's section), the first of each kind per mark, in
/// order: (kind, μ).
fn stated(text: &str, sym: (&str, &str), marks: &[usize]) -> Vec<(char, f64)> {
    let mut out = Vec::new();
    for (i, &m) in marks.iter().enumerate() {
        let end = marks.get(i + 1).copied().unwrap_or(text.len());
        let part = &text[m..end];
        for (kind, s) in [('v', sym.0), ('a', sym.1)] {
            if let Some(j) = part.find(s) {
                let rest = &part[j + s.len()..];
                let n: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == ',')
                    .collect();
                out.push((kind, number(&n)));
            }
        }
    }
    out
}

fn check(scene: &str, lang: &str, name: &str) {
    let root =
        std::env::temp_dir().join(format!("mechplan-one-scale-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&root).unwrap();
    let dir = Dir(root);
    let path = dir.path().join("scene.json");
    std::fs::write(&path, scene).unwrap();
    let p = path.to_str().unwrap();
    // The result file.
    let json: Value = serde_json::from_str(&mechplan(&["solve", p, "--format", "json"])).unwrap();
    let mut want = Vec::new();
    for pos in json["positions"].as_array().unwrap() {
        want.push(('v', pos["plans"]["velocity"]["mu"].as_f64().unwrap()));
        if let Some(a) = pos["plans"]["acceleration"]["mu"].as_f64() {
            want.push(('a', a));
        }
    }
    // The steps: a plan's heading starts a line at the margin.
    let steps = mechplan(&["solve", p, "--steps", "--lang", lang]);
    let marks: Vec<usize> = steps
        .match_indices('\n')
        .map(|(i, _)| i + 1)
        .filter(|&i| steps[i..].chars().next().is_some_and(|c| c.is_alphabetic()))
        .collect();
    assert_eq!(stated(&steps, ("μ_v = ", "μ_a = "), &marks), want, "steps");
    // The sheets, the course sheet among them when the scene wants it.
    let out = dir.path().join("sheets");
    mechplan(&["draw", p, "-o", out.to_str().unwrap()]);
    let sheets: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sheets.json")).unwrap()).unwrap();
    let scale = |file: String, key: &str| scale_in(&sheets, &file, key);
    // Each position's sheets, named by its number in the result file.
    let drawn_in = |sheets: &Value| -> Vec<(char, f64)> {
        let scale = |file: String, key: &str| scale_in(sheets, &file, key);
        let mut drawn = Vec::new();
        for pos in json["positions"].as_array().unwrap() {
            let k = &pos["position"];
            drawn.push(('v', scale(format!("velocity_{k}.svg"), "mu_v").unwrap()));
            if let Some(a) = scale(format!("acceleration_{k}.svg"), "mu_a") {
                drawn.push(('a', a));
            }
        }
        drawn
    };
    let drawn = drawn_in(&sheets);
    if let Some(mu_v) = scale("course.svg".into(), "mu_v") {
        // The course sheet's one μ_v is every velocity plan's it shows
        // (all of them, up to 24 positions): the result file, the steps
        // and the handout state it.
        assert!(
            want.iter().filter(|w| w.0 == 'v').all(|w| w.1 == mu_v),
            "course μ_v {mu_v}"
        );
        // A position's own sheets are at their own scales: those of the
        // same scene drawn without the course sheet (issue 40: an A1
        // sheet's μ ran A4 plans off their page).
        let mut alone: Value = serde_json::from_str(scene).unwrap();
        alone["want"]["drawings"] = serde_json::json!(["mechanism", "velocity", "acceleration"]);
        let apath = dir.path().join("alone.json");
        std::fs::write(&apath, alone.to_string()).unwrap();
        let aout = dir.path().join("alone");
        mechplan(&[
            "draw",
            apath.to_str().unwrap(),
            "-o",
            aout.to_str().unwrap(),
        ]);
        let asheets: Value =
            serde_json::from_str(&std::fs::read_to_string(aout.join("sheets.json")).unwrap())
                .unwrap();
        assert_eq!(drawn, drawn_in(&asheets), "sheets at their own scales");
    } else {
        assert_eq!(drawn, want, "sheets");
    }
    // The handout: a section per position.
    let html_dir = dir.path().join("html");
    mechplan(&["draw", p, "-o", html_dir.to_str().unwrap(), "--html"]);
    let html = std::fs::read_to_string(html_dir.join("handout.html")).unwrap();
    let marks: Vec<usize> = html
        .match_indices("<section class=\"position\"")
        .map(|(i, _)| i)
        .collect();
    let sym = ("μ<sub>v</sub> = ", "μ<sub>a</sub> = ");
    assert_eq!(stated(&html, sym, &marks), want, "handout");
}

/// The scale `key` a manifest (`sheets.json`) lists for sheet `file`.
fn scale_in(sheets: &Value, file: &str, key: &str) -> Option<f64> {
    sheets["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["file"] == file)
        .and_then(|s| s["scales"][key].as_f64())
}

/// A scratch folder, removed when done.
struct Dir(std::path::PathBuf);

impl Dir {
    fn path(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn fixture(name: &str) -> Value {
    let p = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

#[test]
fn a_plan_has_one_scale_in_every_output() {
    check(&fixture("six_link_fig2_10").to_string(), "en", "six");
}

#[test]
fn in_ukrainian_too() {
    let mut s = fixture("shaper_fig2_11");
    s["want"]["lang"] = "uk".into();
    check(&s.to_string(), "uk", "shaper");
}

#[test]
fn the_course_sheet_gives_its_scales_to_the_plans_it_shows() {
    for (name, lang) in [("six_link_fig2_10", "en"), ("compressor_fig2_12", "ru")] {
        let mut s = fixture(name);
        s["want"]["lang"] = lang.into();
        s["want"]["drawings"] =
            serde_json::json!(["course", "mechanism", "velocity", "acceleration"]);
        check(&s.to_string(), lang, name);
    }
}

/// Every number after `mark` in `text`, in order.
fn all_after(text: &str, mark: &str) -> Vec<f64> {
    text.match_indices(mark)
        .map(|(i, _)| {
            let n: String = text[i + mark.len()..]
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == ',')
                .collect();
            number(&n)
        })
        .collect()
}

/// The parts of `text` from each `start` to the next `end`.
fn parts<'a>(text: &'a str, start: &str, end: &str) -> Vec<&'a str> {
    text.match_indices(start)
        .map(|(i, _)| &text[i..i + text[i..].find(end).unwrap()])
        .collect()
}

/// One μ_F per force plan: the result file's (`force_plans[].mu`), the
/// one `solve --steps` states in the plan's heading and the handout's (in
/// its figure's caption and its heading there); the lever's μ_F as the
/// steps and the handout state it.
fn check_forces(scene: &str, lang: &str, name: &str) {
    let root =
        std::env::temp_dir().join(format!("mechplan-one-mu-f-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&root).unwrap();
    let dir = Dir(root);
    let path = dir.path().join("scene.json");
    std::fs::write(&path, scene).unwrap();
    let p = path.to_str().unwrap();
    let json: Value = serde_json::from_str(&mechplan(&["solve", p, "--format", "json"])).unwrap();
    let mut want = Vec::new();
    for pos in json["positions"].as_array().unwrap() {
        for plan in pos["dynamics"]["force_plans"].as_array().unwrap() {
            want.push(plan["mu"].as_f64().unwrap());
        }
    }
    assert!(!want.is_empty());
    // The steps: a plan's heading states μ_F alone, the lever's with μ_v.
    let steps = mechplan(&["solve", p, "--steps", "--lang", lang]);
    let (levers, plans): (Vec<&str>, Vec<&str>) = steps
        .lines()
        .filter(|l| l.contains("μ_F = "))
        .partition(|l| l.contains("μ_v = "));
    let of = |lines: &[&str]| -> Vec<f64> {
        lines.iter().flat_map(|l| all_after(l, "μ_F = ")).collect()
    };
    assert_eq!(of(&plans), want, "steps");
    let lever_mu = of(&levers);
    // The handout.
    let html_dir = dir.path().join("html");
    mechplan(&["draw", p, "-o", html_dir.to_str().unwrap(), "--html"]);
    let html = std::fs::read_to_string(html_dir.join("handout.html")).unwrap();
    let mark = "μ<sub>F</sub> = ";
    let figures = parts(&html, "<figure class=\"fig force\"", "</figure>");
    let captions: Vec<f64> = figures
        .iter()
        .flat_map(|f| all_after(&f[..f.find("</figcaption>").unwrap()], mark))
        .collect();
    assert_eq!(captions, want, "handout, the figures' captions");
    let heads: Vec<f64> = figures
        .iter()
        .flat_map(|f| all_after(parts(f, "<p class=\"force-head\">", "</p>")[0], mark))
        .collect();
    assert_eq!(heads, want, "handout, the plans' headings");
    let drawn: Vec<f64> = parts(&html, "<figure class=\"fig lever\"", "</figcaption>")
        .iter()
        .flat_map(|f| all_after(f, mark))
        .collect();
    assert_eq!(drawn, lever_mu, "handout, the levers");
}

#[test]
fn a_force_plan_has_one_scale_in_every_output() {
    check_forces(
        &fixture("dynamics/six_link_fig2_10").to_string(),
        "en",
        "six",
    );
    let mut s = fixture("dynamics/shaper_fig2_11");
    s["want"]["lang"] = "uk".into();
    check_forces(&s.to_string(), "uk", "shaper");
}
