//! Sheet 1 states what a course sheet states beside its drawings: the
//! structure (Chebyshev's W, the structure formula), the given data, the
//! output's stroke H, the crank angles of the working and idle strokes
//! and K, and the plans' values at the analysed position against the
//! analytic solution. Judged against numbers worked out here from the
//! scene's data alone: the six-link of Fig. 2.10 by its own geometry
//! (circle intersections, finite differences), the compressor by the law
//! of a centric slider-crank (H = 2r, K = 1).

mod common;
use common::*;
use serde_json::Value;

/// The texts of the figure `id` of a sheet, tags stripped, in order.
fn figure_texts(svg: &str, id: &str) -> Vec<String> {
    let start = svg
        .find(&format!("id=\"fig-{id}\""))
        .unwrap_or_else(|| panic!("no figure {id} on the sheet"));
    let rest = &svg[start..];
    let end = rest[1..]
        .find("<g class=\"figure\"")
        .map_or(rest.len(), |e| e + 1);
    rest[..end]
        .lines()
        .filter(|l| l.starts_with("<text"))
        .map(|l| {
            let mut t = String::new();
            let mut inside = false;
            for ch in l.chars() {
                match ch {
                    '<' => inside = true,
                    '>' => inside = false,
                    c if !inside => t.push(c),
                    _ => {}
                }
            }
            t
        })
        .collect()
}

/// The course sheet of fixture `name` in `lang`, and the folder it is in.
fn course_svg(name: &str, lang: &str) -> (String, std::path::PathBuf) {
    let dir = fresh(
        "course_sheet_data",
        &format!("{}_{lang}", name.replace('/', "_")),
    );
    let scene = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let out = dir.to_str().unwrap();
    let (code, _, err) = run(&["draw", &scene, "--course", "--lang", lang, "-o", out]);
    assert_eq!(code, 0, "{err}");
    (
        std::fs::read_to_string(dir.join("course.svg")).unwrap(),
        dir,
    )
}

/// The number after `key` in `line` (a decimal point or comma).
fn number_after(line: &str, key: &str) -> f64 {
    let at = line
        .find(key)
        .unwrap_or_else(|| panic!("no {key} in {line}"))
        + key.len();
    let t: String = line[at..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == ',' || *c == '−' || *c == '-')
        .collect();
    t.replace(',', ".").replace('−', "-").parse().unwrap()
}

/// n and p₅ counted from the scene file: every point shared by k links is
/// k − 1 revolute pairs, every slider one prismatic pair.
fn chebyshev(v: &Value) -> (usize, usize) {
    let links = v["links"].as_object().unwrap();
    let mut shared = std::collections::HashMap::<String, usize>::new();
    for l in links.values() {
        for p in l["points"].as_array().unwrap() {
            *shared.entry(p.as_str().unwrap().to_string()).or_default() += 1;
        }
    }
    let p5 = shared.values().map(|k| k - 1).sum::<usize>() + v["sliders"].as_array().unwrap().len();
    (links.len() - 1, p5)
}

type P = (f64, f64);

fn circles(c0: P, r0: f64, c1: P, r1: f64, upper: bool) -> P {
    let (dx, dy) = (c1.0 - c0.0, c1.1 - c0.1);
    let d = dx.hypot(dy);
    let a = (r0 * r0 - r1 * r1 + d * d) / (2.0 * d);
    let h = (r0 * r0 - a * a).sqrt();
    let m = (c0.0 + a * dx / d, c0.1 + a * dy / d);
    let s = if upper { 1.0 } else { -1.0 };
    (m.0 - s * h * dy / d, m.1 + s * h * dx / d)
}

/// The six-link of Fig. 2.10 worked out from its file alone.
struct SixLink {
    r: f64,
    ab: f64,
    o2: P,
    o2b: f64,
    b0: P,
    c0: P,
    cd: f64,
    guide_y: f64,
}

impl SixLink {
    fn new(v: &Value) -> SixLink {
        let p = |n: &str| {
            (
                v["points"][n][0].as_f64().unwrap(),
                v["points"][n][1].as_f64().unwrap(),
            )
        };
        let l = |k: &str| v["lengths"][k].as_f64().unwrap();
        SixLink {
            r: l("O1-A"),
            ab: l("A-B"),
            o2: p("O2"),
            o2b: l("O2-B"),
            b0: p("B"),
            c0: p("C"),
            cd: l("C-D"),
            guide_y: v["sliders"][0]["line"]["through"][1].as_f64().unwrap(),
        }
    }
    /// B (the assembly of the sketch: B above the line O2-A's side it is
    /// drawn on), the rocker's turn from the sketch, C and D at crank φ.
    fn at(&self, phi: f64) -> (P, f64, P, P) {
        let a = (self.r * phi.cos(), self.r * phi.sin());
        // The sketch's B is on the left of A→O2.
        let b = circles(a, self.ab, self.o2, self.o2b, true);
        let ang = |q: P| (q.1 - self.o2.1).atan2(q.0 - self.o2.0);
        let th = ang(b) - ang(self.b0);
        let (cx, cy) = (self.c0.0 - self.o2.0, self.c0.1 - self.o2.1);
        let c = (
            self.o2.0 + cx * th.cos() - cy * th.sin(),
            self.o2.1 + cx * th.sin() + cy * th.cos(),
        );
        let dy = self.guide_y - c.1;
        let d = (c.0 + (self.cd * self.cd - dy * dy).sqrt(), self.guide_y);
        (b, th, c, d)
    }
    /// The crank angles where crank and coupler lie in line, stretched
    /// (O1B = AB + r) and folded (O1B = AB − r).
    fn extremes(&self) -> (f64, f64) {
        let b_s = circles((0.0, 0.0), self.ab + self.r, self.o2, self.o2b, true);
        let b_f = circles((0.0, 0.0), self.ab - self.r, self.o2, self.o2b, true);
        (b_s.1.atan2(b_s.0), (-b_f.1).atan2(-b_f.0))
    }
}

#[test]
fn six_link_structure_stroke_and_given_data() {
    let v = fixture("dynamics/six_link_fig2_10");
    let (svg, dir) = course_svg("dynamics/six_link_fig2_10", "en");
    let t = figure_texts(&svg, "given");
    let (n, p5) = chebyshev(&v);
    let w = 3 * n as i64 - 2 * p5 as i64;
    assert!(
        t.iter()
            .any(|l| l.ends_with(&format!("= 3·{n} − 2·{p5} − 0 = {w}"))),
        "Chebyshev's count 3·{n} − 2·{p5} = {w} on the sheet: {t:?}"
    );
    assert!(
        t.iter().any(|l| l.contains("I(0,1) → II(2,3) → II(4,5)")),
        "{t:?}"
    );
    assert!(
        t.iter()
            .any(|l| l.contains("Group (2, 3), class II, kind 1 (RRR)")),
        "{t:?}"
    );
    assert!(
        t.iter()
            .any(|l| l.contains("Group (4, 5), class II, kind 2 (RRP)")),
        "{t:?}"
    );

    let m = SixLink::new(&v);
    // Sanity of the geometry worked out here: at the sketch's crank angle
    // it gives the sketch's D.
    let phi_sketch = v["input"]["angle"].as_f64().unwrap().to_radians();
    let d_sketch = v["points"]["D"][0].as_f64().unwrap();
    assert!((m.at(phi_sketch).3.0 - d_sketch).abs() < 1e-9);
    let (s, f) = m.extremes();
    let h = (m.at(s).3.0 - m.at(f).3.0).abs();
    // The crank turns clockwise: the larger angle between the extremes is
    // the working stroke.
    let cw = |from: f64, to: f64| (from - to).rem_euclid(std::f64::consts::TAU);
    let (w1, w2) = (cw(s, f), cw(f, s));
    let (working, start) = if w1 > w2 { (w1, s) } else { (w2, f) };
    let idle = std::f64::consts::TAU - working;
    let line = |key: &str| {
        t.iter()
            .find(|l| l.contains(key))
            .unwrap_or_else(|| panic!("{key}: {t:?}"))
    };
    let h_sheet = number_after(line("H ="), "H =");
    assert!((h_sheet - h).abs() <= 0.005 * h, "H {h_sheet} against {h}");
    let wl = line("working stroke");
    assert!(
        (number_after(wl, "φw =") - working.to_degrees()).abs() <= 0.051,
        "{wl} against {}",
        working.to_degrees()
    );
    assert!(
        (number_after(wl, "φi =") - idle.to_degrees()).abs() <= 0.051,
        "{wl}"
    );
    assert!((number_after(line("K ="), "φw/φi =") - working / idle).abs() <= 0.0005 + 1e-12);

    // The given data: every length of the scene, ω₁ and the masses.
    for (k, l) in v["lengths"].as_object().unwrap() {
        let key = format!("l{}, m", k.replace('-', ""));
        let at = t
            .iter()
            .position(|c| *c == key)
            .unwrap_or_else(|| panic!("{key}: {t:?}"));
        let x: f64 = t[at + 1].parse().unwrap();
        assert!((x - l.as_f64().unwrap()).abs() < 1e-9, "{key}");
    }
    assert!(t.iter().any(|c| c == "ω1, rad/s"));
    for (link, lm) in v["dynamics"]["links"].as_object().unwrap() {
        let key = format!("m{link}, kg");
        let at = t
            .iter()
            .position(|c| *c == key)
            .unwrap_or_else(|| panic!("{key}: {t:?}"));
        assert_eq!(t[at + 1].parse::<f64>().unwrap(), lm["m"].as_f64().unwrap());
    }

    // The comparison at the analysed position.
    let c = figure_texts(&svg, "compare");
    let k: usize = c[0].rsplit(' ').next().unwrap().parse().unwrap();
    let phi = start - std::f64::consts::TAU * k as f64 / 12.0;
    let omega = v["input"]["omega"].as_f64().unwrap().abs();
    let hd = 1e-4;
    let d1 = |f: &dyn Fn(f64) -> f64| (f(phi + hd) - f(phi - hd)) / (2.0 * hd);
    let d2 = |f: &dyn Fn(f64) -> f64| (f(phi + hd) - 2.0 * f(phi) + f(phi - hd)) / (hd * hd);
    let bx = |p: f64| m.at(p).0.0;
    let by = |p: f64| m.at(p).0.1;
    let cx = |p: f64| m.at(p).2.0;
    let cy = |p: f64| m.at(p).2.1;
    let dx = |p: f64| m.at(p).3.0;
    let th = |p: f64| m.at(p).1;
    let expected = [
        ("vB, m/s", omega * d1(&bx).hypot(d1(&by))),
        ("vC, m/s", omega * d1(&cx).hypot(d1(&cy))),
        ("vD, m/s", omega * d1(&dx).abs()),
        ("ω3, rad/s", omega * d1(&th).abs()),
        ("aB, m/s²", omega * omega * d2(&bx).hypot(d2(&by))),
        ("aC, m/s²", omega * omega * d2(&cx).hypot(d2(&cy))),
        ("aD, m/s²", omega * omega * d2(&dx).abs()),
        ("ε3, rad/s²", omega * omega * d2(&th).abs()),
    ];
    let scales: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sheets.json")).unwrap()).unwrap();
    let course = scales["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["file"] == "course.svg")
        .unwrap()["scales"]
        .clone();
    let mu_v = course["mu_v"].as_f64().unwrap();
    for (key, exact) in expected {
        let at = c
            .iter()
            .position(|x| x == key)
            .unwrap_or_else(|| panic!("{key}: {c:?}"));
        let cell = |j: usize| c[at + j].parse::<f64>().unwrap();
        let (segment, plan, analytic) = (cell(1), cell(2), cell(3));
        assert!(
            (analytic - exact).abs() <= 0.005 * exact,
            "{key}: analytic {analytic} against {exact} worked out here"
        );
        // The segment read to 0.5 mm: the plan's value within half a
        // reading of the exact one (and its rounding to three digits).
        let per_mm = plan / segment;
        assert!(
            (plan - exact).abs() <= 0.25 * per_mm * 1.01 + 0.005 * exact,
            "{key}: plan {plan} ({segment} mm) against {exact}"
        );
        assert_eq!(
            (segment * 2.0).fract(),
            0.0,
            "{key}: {segment} mm read to 0.5 mm"
        );
        if key.starts_with('v') {
            assert!(
                (per_mm - mu_v).abs() <= 0.005 * mu_v,
                "{key}: read at μ_v = {mu_v}"
            );
        }
    }
}

#[test]
fn compressor_stroke_is_twice_the_crank_and_k_is_one() {
    let v = fixture("dynamics/compressor_fig2_12");
    let r = v["lengths"]["O-A"].as_f64().unwrap();
    for lang in ["en", "uk"] {
        let (svg, _) = course_svg("dynamics/compressor_fig2_12", lang);
        let t = figure_texts(&svg, "given");
        let line = |key: &str| {
            t.iter()
                .find(|l| l.contains(key))
                .unwrap_or_else(|| panic!("{key}: {t:?}"))
        };
        let h = number_after(line("H ="), "H =");
        assert!(
            (h - 2.0 * r).abs() < 1e-9,
            "{lang}: H {h} against 2r = {}",
            2.0 * r
        );
        let k = line("K =");
        assert!(
            k.ends_with("= 1"),
            "{lang}: K of a centric slider-crank: {k}"
        );
        if lang == "uk" {
            assert!(
                t.iter().any(|l| l.starts_with("ступінь вільності")),
                "{t:?}"
            );
            assert!(t.iter().any(|l| l.contains("хід повзуна 5")), "{t:?}");
        }
    }
}

/// On A1 every course sheet holds the structure and given data and the
/// comparison; on A2, where they cannot all pack, the comparison goes
/// first and the structure and given data stay.
#[test]
fn every_a1_course_sheet_holds_sheet_one_data() {
    for name in [
        "dynamics/six_link_fig2_10",
        "dynamics/shaper_fig2_11",
        "dynamics/compressor_fig2_12",
        "four_bar",
        "boom_cylinder",
    ] {
        for size in ["A1", "A2"] {
            let dir = fresh(
                "course_sheet_data_all",
                &format!("{}_{size}", name.replace('/', "_")),
            );
            let scene = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
            let (code, _, err) = run(&[
                "draw",
                &scene,
                "--course",
                "--sheet",
                size,
                "-o",
                dir.to_str().unwrap(),
            ]);
            assert_eq!(code, 0, "{err}");
            let svg = std::fs::read_to_string(dir.join("course.svg")).unwrap();
            assert!(
                svg.contains("id=\"fig-given\""),
                "{name} {size}: the structure and given data"
            );
            if size == "A1" {
                assert!(svg.contains("id=\"fig-compare\""), "{name}: the comparison");
            }
        }
    }
}
