//! Kinematic diagrams (lecture 000): the chord construction against the
//! analytic transfer functions, and the order of every numerical method.

mod common;
use common::*;
use mechplan::diagrams::Diagrams;
use mechplan::invariants::{Output, default_output};

/// Reads one curve's error off the errors.
type Pick = fn(&mechplan::diagrams::Errors) -> f64;

/// Fixtures whose crank turns fully (the diagrams cover a revolution).
const FULL_TURN: &[&str] = &[
    "four_bar",
    "offset_slider_crank",
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "dwell_six_link_003",
];

fn analysis(name: &str) -> mechplan::Analysis {
    let v = fixture(name);
    mechplan::Analysis::new(mechplan::Scene::from_json(&v.to_string()).unwrap()).unwrap()
}

/// The chord's ray cuts the ordinate axis at y′ with y′·μ_s′ equal to the
/// mean velocity analogue over the interval (the mean value theorem the
/// lecture cites), the mean found independently by Gauss–Legendre
/// quadrature of route (a)'s transfer function: an independent check of
/// the scale μ_s′ = μ_s/(H1·μ_φ).
#[test]
fn chord_ordinates_times_the_scale_are_the_mean_velocities() {
    for name in FULL_TURN {
        let an = analysis(name);
        let out_link = default_output(&an);
        let d = Diagrams::build(&an, out_link, 12, 180.0).unwrap();
        let mut out = Output::new(&an, out_link).unwrap();
        let scale = d.ds_mid.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        for (k, v) in d.chord_velocity().iter().enumerate() {
            let mean = d.mean_velocity(&mut out, k).unwrap();
            assert!(
                (v - mean).abs() <= 1e-12 * scale,
                "{name}, interval {k}: {v} vs {mean}"
            );
        }
    }
}

/// Errors against N = 12, 24 … 384: every method is of the second order,
/// the error falling at least 4× per halving of the step (less 15 %, once
/// the step is fine enough for the asymptotic rate: from N = 48), except
/// the second derivative by the lecture's end formulas applied twice,
/// which is of the first order at the ends (2× per halving; more where
/// the leading term vanishes, as at the compressor's symmetric start).
#[test]
fn numerical_curves_converge_with_the_second_order() {
    for name in FULL_TURN {
        let an = analysis(name);
        let out = default_output(&an);
        let ns = [12, 24, 48, 96, 192, 384];
        let errs: Vec<_> = ns
            .iter()
            .map(|&n| Diagrams::build(&an, out, n, 180.0).unwrap().errors())
            .collect();
        // (what, error, order): the repeated one-sided end formulas give
        // the second derivative at the ends with the first order only.
        let pick: [(&str, Pick, f64); 7] = [
            ("chords v", |e| e.chord_v.0, 2.0),
            ("chords a", |e| e.chord_a.0, 2.0),
            ("central v", |e| e.central_v.0, 2.0),
            ("central a", |e| e.central_a.0, 2.0),
            ("central a at the ends", |e| e.central_a_ends.0, 1.0),
            ("integration by chords", |e| e.chord_s.0, 2.0),
            ("trapezoids", |e| e.trapezoid_s.0, 2.0),
        ];
        for (what, f, order) in pick {
            let e: Vec<f64> = errs.iter().map(f).collect();
            eprintln!(
                "{name} {what}: {:?}",
                e.iter().map(|x| format!("{x:.2e}")).collect::<Vec<_>>()
            );
            for k in 2..ns.len() - 1 {
                let ratio = e[k] / e[k + 1];
                let want = 2f64.powf(order);
                assert!(
                    ratio >= 0.85 * want,
                    "{name} {what}: error {:.3e} at N = {} and {:.3e} at N = {}: ratio {ratio:.2}",
                    e[k],
                    ns[k],
                    e[k + 1],
                    ns[k + 1]
                );
            }
            assert!(e[0] < 0.5, "{name} {what}: {:e} at N = 12", e[0]);
        }
    }
}

/// A scene asking for "diagrams" gets the diagrams sheet from `draw`; the
/// command prints the table or writes the sheet; a slider input is refused
/// (a diagram over a revolution needs a crank).
#[test]
fn diagrams_are_drawn_when_asked_and_printed_by_the_command() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let dir = std::env::temp_dir().join(format!("mechplan-diagrams-{}", std::process::id()));
    let mut v = fixture("offset_slider_crank");
    v["want"] = serde_json::json!({ "drawings": ["mechanism", "diagrams"] });
    let scene = dir.join("scene.json");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = std::process::Command::new(exe)
        .args(["draw", scene.to_str().unwrap(), "-o", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("diagrams.svg")).unwrap();
    for id in ["P1", "P2", "s0", "v0", "a0"] {
        assert!(svg.contains(&format!("id=\"{id}\"")), "{id}");
    }
    let table = std::process::Command::new(exe)
        .args(["diagram", scene.to_str().unwrap(), "-n", "24"])
        .output()
        .unwrap();
    assert!(table.status.success());
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(
        text.contains("N = 24") && text.contains("trapezoids"),
        "{text}"
    );
    let slider = format!(
        "{}/fixtures/slider_driven_rocker.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let bad = std::process::Command::new(exe)
        .args(["diagram", &slider])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("crank"));
    // A point at rest has no diagram.
    let rest = std::process::Command::new(exe)
        .args(["diagram", scene.to_str().unwrap(), "--point", "O"])
        .output()
        .unwrap();
    assert_eq!(rest.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&rest.stderr).contains("does not move"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A point along its path (the four-bar's coupler point M): the arc
/// length over the revolution equals the length of its path measured
/// independently (a polyline through 20 000 of its positions, corrected
/// for the chords' O(h²) shortfall by Richardson's rule); the chord
/// ordinates are the mean speed analogues.
#[test]
fn a_point_along_its_path() {
    let an = analysis("four_bar");
    let m = &an.mech;
    let p = m.scene.point_index("M").unwrap();
    let d = Diagrams::build_point(&an, p, 12, 180.0).unwrap();
    let total = d.s[d.n];
    let mut ps =
        mechplan::positions::PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
    let l = an.carrier(p);
    let polyline = |ps: &mut mechplan::positions::PositionSolver, k: usize| -> f64 {
        let at = |ps: &mut mechplan::positions::PositionSolver, j: usize| {
            let phi = d.phi0 + d.dir * std::f64::consts::TAU * j as f64 / k as f64;
            ps.solve(phi).unwrap().point(m, l, p)
        };
        let mut last = at(ps, 0);
        let mut sum = 0.0;
        for j in 1..=k {
            let q = at(ps, j);
            sum += (q - last).hypot();
            last = q;
        }
        sum
    };
    let (l1, l2) = (polyline(&mut ps, 10_000), polyline(&mut ps, 20_000));
    let length = l2 + (l2 - l1) / 3.0;
    assert!(
        (total - length).abs() <= 1e-9 * length,
        "{total} vs {length}"
    );
    let mut out = Output::point(&an, p).unwrap();
    let scale = d.ds_mid.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    for (k, v) in d.chord_velocity().iter().enumerate() {
        let mean = d.mean_velocity(&mut out, k).unwrap();
        assert!(
            (v - mean).abs() <= 1e-12 * scale,
            "interval {k}: {v} vs {mean}"
        );
    }
}

/// The displacement runs from the extreme position in the sense of the
/// working stroke: never below the axis (the shaper's ram goes toward −x,
/// its slide along the guide is negative; the diagram's s is not).
#[test]
fn the_displacement_is_positive_along_the_working_stroke() {
    for name in FULL_TURN {
        let an = analysis(name);
        let d = Diagrams::build(&an, default_output(&an), 12, 180.0).unwrap();
        let top = d.s.iter().fold(0.0f64, |a, &x| a.max(x));
        assert!(top > 0.0, "{name}: {:?}", d.s);
        for (k, x) in d.s.iter().enumerate() {
            assert!(*x >= -1e-12 * top, "{name}: s at node {k} is {x}");
        }
        // Its analogue is the derivative of that s: rising at the start.
        assert!(d.ds_mid[0] > 0.0, "{name}: {:?}", d.ds_mid);
    }
}

/// The numbers of a text in order, each as written (its decimal mark
/// kept): digits, one mark ('.' or ','), digits. A mark not between
/// digits ("12, from") ends the number.
fn numbers_written(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if !c[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let start = i;
        while i < c.len() && c[i].is_ascii_digit() {
            i += 1;
        }
        if i + 1 < c.len() && (c[i] == '.' || c[i] == ',') && c[i + 1].is_ascii_digit() {
            i += 1;
            while i < c.len() && c[i].is_ascii_digit() {
                i += 1;
            }
        }
        out.push(c[start..i].iter().collect());
    }
    out
}

/// `mechplan diagram` of a Ukrainian scene (`want.lang`: "uk") prints its
/// table in Ukrainian, with the decimal comma, and writes its sheet so;
/// `--lang en` gives English with decimal points, `--lang ru` Russian:
/// the same numbers, only their mark and the words changed.
#[test]
fn the_diagram_command_speaks_the_scenes_language_or_lang() {
    let dir = fresh("diagrams", "lang");
    let mut v = fixture("six_link_fig2_10");
    v["want"] = serde_json::json!({ "lang": "uk" });
    let scene = dir.join("scene.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let scene = scene.to_str().unwrap();
    let table = |extra: &[&str]| {
        let mut args = vec!["diagram", scene];
        args.extend_from_slice(extra);
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{extra:?}: {err}");
        out
    };
    let has_mark = |t: &str, mark: char| {
        numbers_written(t)
            .iter()
            .filter(|n| n.contains(mark))
            .count()
    };
    let uk = table(&[]);
    for word in [
        "кінематичні діаграми",
        "масштаби",
        "вузол",
        "точно",
        "інтервал",
        "хорди",
    ] {
        assert!(
            uk.contains(word),
            "the Ukrainian table has no {word:?}:\n{uk}"
        );
    }
    for word in ["kinematic", "scales", "node", "exact", "interval", "chords"] {
        assert!(
            !uk.contains(word),
            "an English {word:?} in the Ukrainian table:\n{uk}"
        );
    }
    assert_eq!(
        has_mark(&uk, '.'),
        0,
        "a decimal point in the Ukrainian table:\n{uk}"
    );
    assert!(
        has_mark(&uk, ',') > 50,
        "the Ukrainian table's decimal commas:\n{uk}"
    );
    assert_eq!(table(&["--lang", "uk"]), uk, "--lang uk is the scene's own");

    let en = table(&["--lang", "en"]);
    for word in [
        "kinematic diagrams",
        "scales",
        "node",
        "exact",
        "interval",
        "chords",
    ] {
        assert!(
            en.contains(word),
            "the English table has no {word:?}:\n{en}"
        );
    }
    assert!(!en.contains("вузол") && !en.contains("масштаби"), "{en}");
    assert_eq!(
        has_mark(&en, ','),
        0,
        "a decimal comma in the English table:\n{en}"
    );
    assert!(has_mark(&en, '.') > 50, "{en}");
    // The same numbers in both: only the mark differs.
    let points = |t: &str| -> Vec<String> {
        numbers_written(t)
            .into_iter()
            .map(|n| n.replace(',', "."))
            .collect()
    };
    assert_eq!(points(&uk), points(&en), "the numbers of the two tables");

    let ru = table(&["--lang", "ru"]);
    assert!(ru.contains("узел") && ru.contains("масштабы"), "{ru}");
    assert_eq!(has_mark(&ru, '.'), 0, "{ru}");

    // The sheet too: in the scene's language, or --lang's.
    for (lang, title, mark, other) in [
        (None, "Кінематичні діаграми", ',', '.'),
        (Some("en"), "Kinematic diagrams", '.', ','),
    ] {
        let out = dir.join(format!("sheet-{}", lang.unwrap_or("scene")));
        let mut args = vec!["diagram", scene, "-o", out.to_str().unwrap()];
        if let Some(l) = lang {
            args.extend(["--lang", l]);
        }
        let (code, _, err) = run(&args);
        assert_eq!(code, 0, "{lang:?}: {err}");
        let svg = std::fs::read_to_string(out.join("diagrams.svg")).unwrap();
        assert!(svg.contains(title), "{lang:?}: the sheet's title");
        // The sheet's words: the text of its <tspan>s.
        let text: String = svg
            .split("<tspan")
            .skip(1)
            .filter_map(|t| Some(&t[t.find('>')? + 1..t.find("</tspan>")?]))
            .collect::<Vec<_>>()
            .join(" ");
        assert!(has_mark(&text, mark) > 0, "{lang:?}: {text}");
        assert_eq!(has_mark(&text, other), 0, "{lang:?}: {text}");
    }
    // An unknown language is refused, as the other commands refuse it.
    let (code, _, err) = run(&["diagram", scene, "--lang", "xx"]);
    assert_eq!(code, 2, "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
