//! `check` of a hand-drawn force plan (docs/check.md, "Force plans"): an
//! answer read off mechplan's own plan at the student's μ_F is right; one
//! read off the plan drawn with the inertia forces not reversed is wrong
//! and diagnosed; one drawn too small to tell cannot be judged; bad
//! answers are refused naming the field, with the command's statuses.

use mechplan::check::forces::{ForceAnswer, check, from_json};
use mechplan::check::position::StatedPosition;
use mechplan::kinetostatics::force_plan::{self, ForceStep, Which};
use mechplan::kinetostatics::loads::{self, Load, Origin};
use mechplan::scene::Scene;
use mechplan::{Analysis, Solved};
use std::process::Command;

fn scene_path() -> String {
    format!(
        "{}/fixtures/dynamics/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn solved() -> (Analysis, Vec<Solved>) {
    let an =
        Analysis::new(Scene::from_json(&std::fs::read_to_string(scene_path()).unwrap()).unwrap())
            .unwrap();
    let s = an.run().unwrap();
    (an, s)
}

/// The answer a careful student would give for group (4, 5) at position
/// `k` (from 0) at μ_F = `mu`, from the plan built with `loads`: the
/// reactions' segments to 0.1 mm, their directions to 0.5°.
fn answer_from(an: &Analysis, s: &Solved, k: usize, mu: f64, loads: &[Load]) -> ForceAnswer {
    let g = 1; // II(4,5) is the second group attached
    let fp = force_plan::solve_at(an, s, loads, 0.5, Some((Which::Group(g), mu))).unwrap();
    let plan = fp.plans.iter().find(|p| p.group == Some(g)).unwrap();
    let mut segments = Vec::new();
    let mut angles = Vec::new();
    for step in &plan.steps {
        if let ForceStep::Measure(i) = step {
            let v = plan.vectors[*i];
            let name = mechplan::words::forces::force_name(
                &an.mech,
                loads,
                v.force,
                mechplan::words::construction::Lang::En,
            );
            let seg = plan.points[v.to] - plan.points[v.from];
            segments.push((
                format!("/segments/{name}"),
                name.clone(),
                (seg.hypot() * 10.0).round() / 10.0,
            ));
            let deg = seg.y.atan2(seg.x).to_degrees().rem_euclid(360.0);
            angles.push((format!("/angles/{name}"), name, (deg * 2.0).round() / 2.0));
        }
    }
    ForceAnswer {
        position: StatedPosition::new(an.numbering.number(k)),
        links: vec!["4".into(), "5".into()],
        mu,
        delta: 0.5,
        mu_l: Some(0.002),
        segments,
        angles,
        values: Vec::new(),
    }
}

fn reversed_inertia(loads: &[Load]) -> Vec<Load> {
    loads
        .iter()
        .map(|l| match *l {
            Load::Force {
                f,
                origin: Origin::Inertia,
                link,
                point,
                at,
            } => Load::Force {
                f: -f,
                origin: Origin::Inertia,
                link,
                point,
                at,
            },
            Load::Couple {
                m,
                origin: Origin::Inertia,
                link,
            } => Load::Couple {
                m: -m,
                origin: Origin::Inertia,
                link,
            },
            other => other,
        })
        .collect()
}

#[test]
fn a_plan_read_off_the_construction_is_right() {
    let (an, solved) = solved();
    let mut right = 0;
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let ans = answer_from(&an, s, k, 2.0, &loads);
        let r = check(&an, &solved, &ans).unwrap();
        assert_eq!(
            r.wrong(),
            0,
            "position {}: {}",
            k + 1,
            mechplan::presentation::verdict::force_to_text(&r)
        );
        right += usize::from(r.status() == 0);
    }
    assert!(
        right * 2 >= solved.len(),
        "most positions judged right: {right}"
    );
}

#[test]
fn inertia_forces_not_reversed_are_wrong_and_diagnosed() {
    let (an, solved) = solved();
    let mut diagnosed = 0;
    for (k, s) in solved.iter().enumerate() {
        let loads = reversed_inertia(&loads::loads(&an, s, k));
        let ans = answer_from(&an, s, k, 2.0, &loads);
        let r = check(&an, &solved, &ans).unwrap();
        // Where the inertia forces matter more than the drafting error.
        if r.wrong() > 0 {
            let d = r.diagnosis.clone().unwrap_or_default();
            assert!(d.contains("inertia"), "position {}: {d}", k + 1);
            diagnosed += 1;
        } else {
            assert_ne!(
                r.status(),
                0,
                "position {}: a mistaken plan accepted as right",
                k + 1
            );
        }
    }
    assert!(diagnosed >= 3, "{diagnosed} positions diagnosed");
}

#[test]
fn a_plan_drawn_too_small_cannot_be_judged() {
    let (an, solved) = solved();
    let loads = loads::loads(&an, &solved[0], 0);
    // At 200 N/mm the whole plan is a millimetre or two.
    let ans = answer_from(&an, &solved[0], 0, 200.0, &loads);
    let r = check(&an, &solved, &ans).unwrap();
    assert_eq!(r.wrong(), 0);
    assert_eq!(
        r.status(),
        4,
        "{}",
        mechplan::presentation::verdict::force_to_text(&r)
    );
}

#[test]
fn bad_force_answers_are_refused_naming_the_field() {
    let (an, solved) = solved();
    let cases = [
        (
            r#"{"plan":"force","links":["4","5"],"segments":{"R_34":50}}"#,
            "/mu",
        ),
        (
            r#"{"plan":"force","links":["4","5"],"mu":2,"segments":{"R_34":"x"}}"#,
            "/segments/R_34",
        ),
        (
            r#"{"plan":"force","links":["4","5"],"mu":-2,"segments":{"R_34":5}}"#,
            "/mu",
        ),
        (r#"{"plan":"force","mu":2,"segments":{"R_34":5}}"#, "/links"),
        (
            r#"{"plan":"force","links":["4","5"],"mu":2}"#,
            "nothing to check",
        ),
        (
            r#"{"plan":"force","links":["4","5"],"mu":2,"colour":1,"segments":{"R_34":5}}"#,
            "/colour",
        ),
    ];
    for (text, field) in cases {
        let e = from_json(text).unwrap_err().to_string();
        assert!(e.contains(field), "{text}: {e}");
    }
    let read = |t: &str| {
        check(&an, &solved, &from_json(t).unwrap())
            .unwrap_err()
            .to_string()
    };
    let e = read(r#"{"plan":"force","links":["2","5"],"mu":2,"segments":{"R_34":5}}"#);
    assert!(e.contains("/links") && e.contains("[4, 5]"), "{e}");
    let e = read(r#"{"plan":"force","links":["4","5"],"mu":2,"segments":{"R_99":5}}"#);
    assert!(e.contains("/segments/R_99") && e.contains("R_34"), "{e}");
    let e = read(r#"{"plan":"force","links":["1"],"mu":2,"values":{"M_b":1}}"#);
    assert!(e.contains("/values/M_b") && e.contains("mu_l"), "{e}");
    let e = read(r#"{"plan":"force","position":99,"links":["1"],"mu":2,"values":{"R_01":1}}"#);
    assert!(e.contains("/position"), "{e}");
}

#[test]
fn the_command_answers_with_its_statuses() {
    let dir = std::env::temp_dir().join(format!("mechplan_check_forces_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (an, solved) = solved();
    let loads = loads::loads(&an, &solved[0], 0);
    let right = answer_from(&an, &solved[0], 0, 2.0, &loads);
    let to_json = |a: &ForceAnswer| {
        let seg: serde_json::Map<String, serde_json::Value> = a
            .segments
            .iter()
            .map(|(_, k, v)| (k.clone(), (*v).into()))
            .collect();
        serde_json::json!({ "plan": "force", "position": a.position.number, "links": a.links, "mu": a.mu, "segments": seg })
            .to_string()
    };
    let run = |text: String, extra: &[&str]| {
        let p = dir.join("answer.json");
        std::fs::write(&p, text).unwrap();
        Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &scene_path(), p.to_str().unwrap()])
            .args(extra)
            .output()
            .unwrap()
    };
    let out = run(to_json(&right), &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let mut wrong = right.clone();
    wrong.segments[0].2 *= 1.5;
    let out = run(to_json(&wrong), &["--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["wrong"], 1);
    let out = run(r#"{"plan":"force","links":["4","5"],"mu":2}"#.into(), &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nothing to check"));
    std::fs::remove_dir_all(&dir).ok();
}

/// The review of 2026-11-24: a scale no drawing has is refused, never
/// judged (it was "right" with a NaN); the weights-left-out plan names its
/// forces by the same loads (it was diagnosed from an external force); a
/// driving slider's F_b takes the polygon's tolerance in N at the
/// student's μ_F, without μ_l; `--mu` applies and `--plan` is refused.
#[test]
fn review_findings_stay_fixed() {
    let (an, solved) = solved();
    for mu in ["1e-310", "1e300", "0"] {
        let text =
            format!(r#"{{"plan":"force","links":["4","5"],"mu":{mu},"segments":{{"R_34":5}}}}"#);
        let e = from_json(&text).unwrap_err().to_string();
        assert!(e.contains("/mu"), "{mu}: {e}");
    }
    // Link 1 without mass: G_2 = 2000 N is not what leaving the weights
    // out gives (F_3 = 2000 N is).
    let path = format!(
        "{}/fixtures/dynamics/worked_slider_crank.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["dynamics"]["links"].as_object_mut().unwrap().remove("1");
    let w = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let ws = w.run().unwrap();
    let ans = from_json(
        r#"{"plan":"force","position":1,"links":["2","3"],"mu":20,"values":{"G_2":2000}}"#,
    )
    .unwrap();
    let r = check(&w, &ws, &ans).unwrap();
    assert_eq!(r.wrong(), 1);
    assert!(
        r.diagnosis
            .as_deref()
            .is_none_or(|d| !d.contains("weights")),
        "{:?}",
        r.diagnosis
    );
    // A driving slider: F_b's tolerance grows with μ_F and needs no μ_l.
    let path = format!(
        "{}/fixtures/slider_driven_rocker.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["dynamics"] = serde_json::json!({
        "g": [0, -9.81],
        "links": { "1": { "m": 2, "J": 0, "centre": "A" }, "2": { "m": 1, "J": 0.01, "centre": "A" }, "3": { "m": 1, "J": 0.01, "centre": "B" } },
        "moments": [ { "link": "3", "M": 5 } ]
    });
    let sa = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let ss = sa.run().unwrap();
    let fb = ss[0].dynamics.as_ref().unwrap().balancing[0].value();
    let tol = |mu: f64| {
        let text = format!(r#"{{"plan":"force","links":["1"],"mu":{mu},"values":{{"F_b":{fb}}}}}"#);
        let r = check(&sa, &ss, &from_json(&text).unwrap()).unwrap();
        assert_eq!(r.wrong(), 0);
        r.verdicts[0].tolerance
    };
    let (fine, coarse) = (tol(0.1), tol(10.0));
    assert!(coarse > 50.0 * fine, "{fine} {coarse}");
    let _ = an;
    let _ = solved;
}

#[test]
fn command_line_mu_applies_and_plan_is_refused() {
    let dir =
        std::env::temp_dir().join(format!("mechplan_check_forces_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("a.json");
    std::fs::write(
        &p,
        r#"{"plan":"force","position":1,"links":["4","5"],"mu":20,"segments":{"R_34":5}}"#,
    )
    .unwrap();
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &scene_path(), p.to_str().unwrap()])
            .args(extra)
            .output()
            .unwrap()
    };
    let out = run(&["--mu", "5"]);
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("μ_F = 5 N/mm"),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let out = run(&["--plan", "acceleration"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--plan"));
    std::fs::remove_dir_all(&dir).ok();
}

/// A force plan drawn in a vector editor: the vectors of group (4, 5) as
/// lines (in a layer with a transform, y down as SVG draws), each
/// labelled with its force's name beside its middle, "μ_F = 2 N/mm"
/// written on it; read back and judged right; one vector drawn 1.5 times
/// too long is wrong; a drawing of a kinematic plan (no μ_F) is left to
/// the kinematic reader.
#[test]
fn a_force_plan_drawn_in_an_editor_is_read_and_judged() {
    let (an, solved) = solved();
    let s = &solved[0];
    let loads = loads::loads(&an, s, 0);
    let fp = force_plan::solve_at(&an, s, &loads, 0.5, Some((Which::Group(1), 2.0))).unwrap();
    let plan = fp.plans.iter().find(|p| p.group == Some(1)).unwrap();
    let svg = |stretch: Option<&str>| {
        let mut body = String::new();
        for v in &plan.vectors {
            let name = mechplan::words::forces::force_name(
                &an.mech,
                &loads,
                v.force,
                mechplan::words::construction::Lang::En,
            );
            let (a, mut b) = (plan.points[v.from], plan.points[v.to]);
            if stretch == Some(name.as_str()) {
                b = a + (b - a) * 1.5;
            }
            // y down on paper; 100 mm from the corner.
            let p = |q: kurbo::Vec2| (100.0 + q.x, 100.0 - q.y);
            let (pa, pb) = (p(a), p(b));
            let m = ((pa.0 + pb.0) / 2.0, (pa.1 + pb.1) / 2.0);
            let n = kurbo::Vec2::new(pb.1 - pa.1, -(pb.0 - pa.0)).normalize() * 2.0;
            body += &format!(
                "<path d=\"M {} {} L {} {}\" stroke=\"black\"/>\n<text x=\"{}\" y=\"{}\" font-size=\"3\">{name}</text>\n",
                pa.0,
                pa.1,
                pb.0,
                pb.1,
                m.0 + n.x - 0.9,
                m.1 + n.y + 1.0
            );
        }
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"297mm\" height=\"210mm\" viewBox=\"0 0 297 210\">\n<g transform=\"translate(5 3)\">\n{body}<text x=\"10\" y=\"200\">μ_F = 2 N/mm</text>\n</g></svg>\n"
        )
    };
    // Drawn at the first position: an answer that states none is of it.
    let first = StatedPosition::default();
    let ans = mechplan::check::forces::from_svg(&svg(None), None, 0.5, first).unwrap();
    assert!(ans.segments.len() >= 5, "{:?}", ans.segments);
    let r = check(&an, &solved, &ans).unwrap();
    assert_eq!(
        r.wrong(),
        0,
        "{}",
        mechplan::presentation::verdict::force_to_text(&r)
    );
    let ans = mechplan::check::forces::from_svg(&svg(Some("R_05")), None, 0.5, first).unwrap();
    let r = check(&an, &solved, &ans).unwrap();
    assert!(
        r.wrong() >= 1,
        "{}",
        mechplan::presentation::verdict::force_to_text(&r)
    );
    assert!(mechplan::check::forces::is_force_svg(&svg(None)));
    assert!(!mechplan::check::forces::is_force_svg(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><text x=\"1\" y=\"1\">μ_v = 0.01</text></svg>"
    ));
    // Through the command: status 0, and 1 for the stretched vector.
    let dir =
        std::env::temp_dir().join(format!("mechplan_check_forces_svg_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (stretch, status) in [(None, 0), (Some("R_05"), 1)] {
        let p = dir.join("plan.svg");
        std::fs::write(&p, svg(stretch)).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &scene_path(), p.to_str().unwrap()])
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(status),
            "{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
    // The same plan drawn in a CAD and saved as DXF (y up, LINE and
    // TEXT, "μ_F = 2 N/mm" as \U+03BC): read and judged as the SVG.
    let dxf = |stretch: Option<&str>| {
        let mut body = String::new();
        for v in &plan.vectors {
            let name = mechplan::words::forces::force_name(
                &an.mech,
                &loads,
                v.force,
                mechplan::words::construction::Lang::En,
            );
            let (a, mut b) = (plan.points[v.from], plan.points[v.to]);
            if stretch == Some(name.as_str()) {
                b = a + (b - a) * 1.5;
            }
            let (pa, pb) = ((100.0 + a.x, 100.0 + a.y), (100.0 + b.x, 100.0 + b.y));
            let m = ((pa.0 + pb.0) / 2.0, (pa.1 + pb.1) / 2.0);
            let n = kurbo::Vec2::new(pb.1 - pa.1, -(pb.0 - pa.0)).normalize() * -2.0;
            body += &format!(
                "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n0\nTEXT\n8\n0\n10\n{}\n20\n{}\n40\n3\n1\n{name}\n",
                pa.0,
                pa.1,
                pb.0,
                pb.1,
                m.0 + n.x - 0.9,
                m.1 + n.y - 1.05
            );
        }
        format!(
            "0\nSECTION\n2\nENTITIES\n{body}0\nTEXT\n8\n0\n10\n10\n20\n5\n40\n3\n1\n\\U+03BC_F = 2 N/mm\n0\nENDSEC\n0\nEOF\n"
        )
    };
    for (stretch, status) in [(None, 0), (Some("R_05"), 1)] {
        let p = dir.join("plan.dxf");
        std::fs::write(&p, dxf(stretch)).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &scene_path(), p.to_str().unwrap()])
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(status),
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// docs/check.md's worked example of a force verdict (τ with the wrong
/// sign, from the independent catalogue): the command prints the page's
/// lines in order and exits with status 1.
#[test]
fn the_worked_example_in_the_docs() {
    let root = env!("CARGO_MANIFEST_DIR");
    let page = std::fs::read_to_string(format!("{root}/docs/check.md")).unwrap();
    let at = page
        .find("\n### A worked example: τ with the wrong sign\n")
        .expect("the heading");
    let example = &page[at..];
    let block = |fence: &str| {
        let start = example.find(fence).unwrap() + fence.len();
        let end = start + example[start..].find("```").unwrap();
        example[start..end].to_string()
    };
    let (answer, printed) = (block("```json\n"), block("```text\n"));
    // The page's answer is the catalogue's file, item for item.
    let file =
        format!("{root}/tests/forces_catalogue/six_link_fig2_10/0_23_tau_wrong_sign_vectors.json");
    let page_answer: serde_json::Value = serde_json::from_str(&answer).unwrap();
    let stored: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(page_answer, stored, "the page's answer is the catalogue's");
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &scene_path(), &file])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(1), "{text}");
    let mut lines = text.lines();
    for want in printed.lines().filter(|l| *l != "…") {
        assert!(
            lines.any(|l| l == want),
            "the page prints a line the command does not, in this order:\n{want}\n---\n{text}"
        );
    }
}

/// Group (4, 5)'s plan at the first position drawn at μ_F = 2 N/mm: each
/// vector's force name and its ends (mm, y up).
fn drawn_vectors(an: &Analysis, s: &Solved) -> Vec<(String, kurbo::Vec2, kurbo::Vec2)> {
    let loads = loads::loads(an, s, 0);
    let fp = force_plan::solve_at(an, s, &loads, 0.5, Some((Which::Group(1), 2.0))).unwrap();
    let plan = fp.plans.iter().find(|p| p.group == Some(1)).unwrap();
    plan.vectors
        .iter()
        .map(|v| {
            let name = mechplan::words::forces::force_name(
                &an.mech,
                &loads,
                v.force,
                mechplan::words::construction::Lang::En,
            );
            (name, plan.points[v.from], plan.points[v.to])
        })
        .collect()
}

/// An arrowhead's triangle (y as drawn): its tip at `tip`, 3 mm long
/// and 2 mm wide, pointing from `back`'s side.
fn arrow_triangle(tip: (f64, f64), back: (f64, f64)) -> [(f64, f64); 3] {
    let u = kurbo::Vec2::new(tip.0 - back.0, tip.1 - back.1).normalize();
    let b = (tip.0 - 3.0 * u.x, tip.1 - 3.0 * u.y);
    [tip, (b.0 - u.y, b.1 + u.x), (b.0 + u.y, b.1 - u.x)]
}

/// The plan drawn in SVG (y down, 100 mm from the corner) in a layer
/// `translate(5 3) scale(k)`, each vector's arrowhead a `marker-end` or a
/// filled triangle (`marker`), the `reversed` one's at its tail instead
/// (a `marker-start`, a triangle pointing out of the tail).
fn arrow_svg(
    vs: &[(String, kurbo::Vec2, kurbo::Vec2)],
    k: f64,
    marker: bool,
    reversed: &str,
) -> String {
    let mut body = String::new();
    for (name, a, b) in vs {
        // In the layer's units.
        let p = |q: kurbo::Vec2| ((100.0 + q.x) / k, (100.0 - q.y) / k);
        let (pa, pb) = (p(*a), p(*b));
        let m = ((pa.0 + pb.0) / 2.0, (pa.1 + pb.1) / 2.0);
        let n = kurbo::Vec2::new(pb.1 - pa.1, -(pb.0 - pa.0)).normalize() * 2.0 / k;
        let (head, back) = if name == reversed { (pa, pb) } else { (pb, pa) };
        let mark = match (marker, name == reversed) {
            (true, false) => " marker-end=\"url(#arrow)\"",
            (true, true) => " style=\"marker-start:url(#arrow)\"",
            (false, _) => "",
        };
        body += &format!(
            "<path d=\"M {} {} L {} {}\" stroke=\"black\" fill=\"none\"{mark}/>\n<text x=\"{}\" y=\"{}\" font-size=\"{}\">{name}</text>\n",
            pa.0,
            pa.1,
            pb.0,
            pb.1,
            m.0 + n.x - 0.9 / k,
            m.1 + n.y + 1.0 / k,
            3.0 / k
        );
        if !marker {
            let t = arrow_triangle((head.0 * k, head.1 * k), (back.0 * k, back.1 * k));
            body += &format!(
                "<path d=\"M {} {} L {} {} L {} {} Z\" style=\"fill:#000000;stroke:none\"/>\n",
                t[0].0 / k,
                t[0].1 / k,
                t[1].0 / k,
                t[1].1 / k,
                t[2].0 / k,
                t[2].1 / k
            );
        }
    }
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"297mm\" height=\"210mm\" viewBox=\"0 0 297 210\">\n<defs><marker id=\"arrow\" orient=\"auto\" markerWidth=\"6\" markerHeight=\"4\" refX=\"6\" refY=\"2\"><path d=\"M 0 0 L 6 2 L 0 4 Z\"/></marker></defs>\n<g transform=\"translate(5 3) scale({k})\">\n{body}<text x=\"{}\" y=\"{}\" font-size=\"{}\">μ_F = 2 N/mm</text>\n</g></svg>\n",
        10.0 / k,
        200.0 / k,
        3.0 / k
    )
}

/// The plan drawn in a CAD (DXF, y up): LINEs, each with a SOLID
/// triangle at its head (the `reversed` one's at its tail), one of them
/// (the first) inserted as a block, the third an LWPOLYLINE whose width
/// tapers to 0 (its SOLID left out).
fn arrow_dxf(vs: &[(String, kurbo::Vec2, kurbo::Vec2)], reversed: &str) -> String {
    let mut body = String::new();
    let mut blocks = String::new();
    for (i, (name, a, b)) in vs.iter().enumerate() {
        let (pa, pb) = ((100.0 + a.x, 100.0 + a.y), (100.0 + b.x, 100.0 + b.y));
        let m = ((pa.0 + pb.0) / 2.0, (pa.1 + pb.1) / 2.0);
        let n = kurbo::Vec2::new(pb.1 - pa.1, -(pb.0 - pa.0)).normalize() * -2.0;
        let (head, back) = if name == reversed { (pa, pb) } else { (pb, pa) };
        let t = arrow_triangle(head, back);
        body += &format!(
            "0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n0\nTEXT\n8\n0\n10\n{}\n20\n{}\n40\n3\n1\n{name}\n",
            pa.0,
            pa.1,
            pb.0,
            pb.1,
            m.0 + n.x - 0.9,
            m.1 + n.y - 1.05
        );
        let solid = |o: (f64, f64)| {
            format!(
                "0\nSOLID\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n12\n{}\n22\n{}\n13\n{}\n23\n{}\n",
                t[0].0 - o.0,
                t[0].1 - o.1,
                t[1].0 - o.0,
                t[1].1 - o.1,
                t[2].0 - o.0,
                t[2].1 - o.1,
                t[2].0 - o.0,
                t[2].1 - o.1
            )
        };
        if i == 2 && name != reversed {
            // An LWPOLYLINE arrow: the shaft, then the head tapering
            // from 2 mm wide to 0 over its last 3 mm.
            let u = kurbo::Vec2::new(pb.0 - pa.0, pb.1 - pa.1).normalize();
            let base = (pb.0 - 3.0 * u.x, pb.1 - 3.0 * u.y);
            body = body.replacen(
                &format!("0\nLINE\n8\n0\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n", pa.0, pa.1, pb.0, pb.1),
                &format!(
                    "0\nLWPOLYLINE\n8\n0\n90\n3\n70\n0\n10\n{}\n20\n{}\n10\n{}\n20\n{}\n40\n2\n41\n0\n10\n{}\n20\n{}\n",
                    pa.0, pa.1, base.0, base.1, pb.0, pb.1
                ),
                1,
            );
        } else if i == 0 {
            // A block of the arrow drawn at its tip, inserted there.
            blocks += &format!(
                "0\nBLOCK\n8\n0\n2\nARROW\n70\n0\n10\n0\n20\n0\n{}0\nENDBLK\n",
                solid(head)
            );
            body += &format!(
                "0\nINSERT\n8\n0\n2\nARROW\n10\n{}\n20\n{}\n",
                head.0, head.1
            );
        } else {
            body += &solid((0.0, 0.0));
        }
    }
    format!(
        "0\nSECTION\n2\nBLOCKS\n{blocks}0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{body}0\nTEXT\n8\n0\n10\n10\n20\n5\n40\n3\n1\n\\U+03BC_F = 2 N/mm\n0\nENDSEC\n0\nEOF\n"
    )
}

/// `check` of a drawn plan's file: its status and what it printed.
fn check_file(file: &str, text: &str) -> (i32, String) {
    let dir = std::env::temp_dir().join(format!("mechplan_check_arrows_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(file);
    std::fs::write(&p, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &scene_path(), p.to_str().unwrap()])
        .output()
        .unwrap();
    std::fs::remove_file(&p).ok();
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.code().unwrap_or(-1), said)
}

/// The arrowheads of a drawn force plan give its vectors' directions:
/// with `marker-end` arrows every direction is read and judged right; one
/// vector's arrow at its tail (`marker-start`) turns its direction
/// round, judged wrong (status 1); filled triangles in a scaled layer
/// read the same; a DXF with SOLID arrowheads (one inserted as a block)
/// too, and one SOLID at a tail judged wrong.
#[test]
fn a_drawn_force_plans_arrowheads_give_its_directions() {
    let (an, solved) = solved();
    let vs = drawn_vectors(&an, &solved[0]);
    let first = StatedPosition::default();
    let read = |svg: &str| mechplan::check::forces::from_svg(svg, None, 0.5, first).unwrap();
    let directions = |r: &mechplan::check::forces::ForceReport| {
        r.verdicts
            .iter()
            .filter(|v| v.unit == "°")
            .map(|v| (v.key.clone(), format!("{:?}", v.judgement)))
            .collect::<Vec<_>>()
    };
    // G_5's: a vector whose tail is no joint where the plan turns back
    // over itself (there two arrowheads would stand one on the other).
    let reversed = "G_5".to_string();
    assert!(vs.iter().any(|v| v.0 == reversed));
    for (k, marker) in [(1.0, true), (0.5, false), (2.0, false)] {
        let ans = read(&arrow_svg(&vs, k, marker, ""));
        assert_eq!(
            ans.angles.len(),
            ans.segments.len(),
            "{:?} {:?}",
            ans.angles,
            ans.segments
        );
        for (_, name, deg) in &ans.angles {
            let (_, a, b) = vs.iter().find(|v| &v.0 == name).unwrap();
            let want = (b.y - a.y).atan2(b.x - a.x).to_degrees().rem_euclid(360.0);
            let off = (deg - want).rem_euclid(360.0);
            assert!(off.min(360.0 - off) < 0.01, "{name}: {deg} vs {want}");
        }
        let r = check(&an, &solved, &ans).unwrap();
        let text = mechplan::presentation::verdict::force_to_text(&r);
        assert!(!directions(&r).is_empty(), "{text}");
        assert_eq!(r.status(), 0, "{text}");
        // The reversed vector's direction is judged wrong.
        let ans = read(&arrow_svg(&vs, k, marker, &reversed));
        let r = check(&an, &solved, &ans).unwrap();
        let text = mechplan::presentation::verdict::force_to_text(&r);
        assert_eq!(r.status(), 1, "{text}");
        assert!(
            directions(&r)
                .iter()
                .any(|(key, j)| key.contains(&reversed) && j == "Wrong"),
            "{reversed}: {text}"
        );
    }
    let (status, said) = check_file("plan.svg", &arrow_svg(&vs, 1.0, true, ""));
    assert_eq!(status, 0, "{said}");
    let (status, said) = check_file("plan.svg", &arrow_svg(&vs, 1.0, true, &reversed));
    assert_eq!(status, 1, "{said}");
    // DXF: SOLID arrowheads.
    let ans = read(&arrow_dxf(&vs, ""));
    assert_eq!(
        ans.angles.len(),
        ans.segments.len(),
        "{:?} {:?}",
        ans.angles,
        ans.segments
    );
    let (status, said) = check_file("plan.dxf", &arrow_dxf(&vs, ""));
    assert_eq!(status, 0, "{said}");
    let (status, said) = check_file("plan.dxf", &arrow_dxf(&vs, &reversed));
    assert_eq!(status, 1, "{said}");
    // No arrowheads: lengths only, as before.
    let plain = arrow_svg(&vs, 1.0, true, "").replace(" marker-end=\"url(#arrow)\"", "");
    assert!(read(&plain).angles.is_empty());
}

/// The catalogue's answer `name` of the six-link (tests/forces_catalogue).
fn catalogued(name: &str) -> String {
    format!(
        "{}/tests/forces_catalogue/six_link_fig2_10/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// A fresh folder for one test's output.
fn fresh(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!(
        "mechplan-force-overlay-{tag}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The element of `svg` with the id `id` (its start tag).
fn element<'a>(svg: &'a str, id: &str) -> Option<&'a str> {
    let at = svg.find(&format!("id=\"{id}\""))?;
    let start = svg[..at].rfind('<')?;
    Some(&svg[start..at + svg[at..].find('>')?])
}

/// `check … --svg` of a force answer writes its overlay (atomically: no
/// temporary left beside it), valid SVG: the right polygon, each vector
/// the answer gives drawn in its judgement's style (τ's sign reversed: the
/// wrong R^τ_12 red with its tolerance circle; a right answer's green),
/// the diagnosis under it, a legend; in Ukrainian with a decimal comma.
#[test]
fn a_force_answer_has_its_overlay() {
    let dir = fresh("svg");
    let overlay = |answer: &str, lang: &str| {
        let out = dir.join(format!("{answer}-{lang}.svg"));
        let st = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &scene_path(), &catalogued(answer), "--svg"])
            .arg(&out)
            .args(["--lang", lang])
            .output()
            .unwrap();
        let svg = std::fs::read_to_string(&out).unwrap();
        mechplan::drawing::tree(&svg).expect("valid SVG");
        roxmltree::Document::parse(&svg).expect("well-formed XML");
        (st.status.code().unwrap(), svg)
    };
    let (code, svg) = overlay("0_23_tau_wrong_sign_vectors", "en");
    assert_eq!(code, 1);
    assert!(svg.contains("right-vec-"), "the right polygon is drawn");
    // R^τ_12 is plan vector k: drawn red (its group wrong-item), its
    // tolerance circle about the right end.
    let wrong = svg.find("class=\"wrong-item\"").expect("a wrong item");
    let vec_at = svg[wrong..].find("id=\"student-vec-").unwrap() + wrong;
    let id: String = svg[vec_at + 4..]
        .chars()
        .take_while(|c| *c != '"')
        .collect();
    let k = id.trim_start_matches("student-vec-");
    let line = element(&svg, &id).unwrap();
    assert!(line.contains("#c00000"), "{line}");
    assert!(element(&svg, &format!("tolerance-{k}")).is_some());
    assert!(
        svg.contains("R<tspan") || svg.contains("R</"),
        "vectors named"
    );
    assert!(svg.contains("the tangential components R"), "the diagnosis");
    assert!(svg.contains("id=\"diagnosis-0\""));
    assert!(svg.contains("id=\"legend-0\""));
    assert!(
        svg.contains("class=\"right-item\""),
        "the right vectors green"
    );
    let (code, svg) = overlay("0_1_honest_vectors", "en");
    assert_eq!(code, 0);
    assert!(svg.contains("class=\"right-item\"") && !svg.contains("class=\"wrong-item\""));
    assert!(!svg.contains("diagnosis-0"));
    let (_, svg) = overlay("0_1_honest_vectors", "uk");
    assert!(svg.contains("2,5 Н/мм"), "μ_F with a decimal comma");
    let left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".svg"))
        .collect();
    assert!(left.is_empty(), "temporaries left: {left:?}");
}

/// A group with a right and a wrong force answer: the gradebook lists
/// both with their grade, the wrong one's mistake named, and each its
/// overlay.
#[test]
fn a_group_grades_force_answers_with_the_mistake_named() {
    let dir = fresh("group");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    for a in ["0_1_honest_vectors", "0_23_tau_wrong_sign_vectors"] {
        std::fs::copy(catalogued(a), answers.join(format!("{a}.json"))).unwrap();
    }
    let out = dir.join("graded");
    let st = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &scene_path()])
        .arg(&answers)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(
        st.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    let csv = std::fs::read_to_string(out.join("gradebook.csv")).unwrap();
    let row = |stem: &str| {
        csv.lines()
            .find(|l| l.starts_with(stem))
            .unwrap()
            .to_string()
    };
    let right = row("0_1_honest_vectors");
    assert!(right.contains(",force,0,right,"), "{right}");
    let wrong = row("0_23_tau_wrong_sign_vectors");
    assert!(wrong.contains(",force,0,wrong,"), "{wrong}");
    assert!(
        wrong.contains("tangential components R^τ with the wrong sign"),
        "{wrong}"
    );
    for a in ["0_1_honest_vectors", "0_23_tau_wrong_sign_vectors"] {
        assert!(
            out.join("overlays").join(format!("{a}.svg")).is_file(),
            "{a}"
        );
    }
}

/// Review findings of the force check (issue 42): a μ_l that draws the
/// mechanism a few millimetres across is refused (a wrong M_b passed as
/// too small to judge); a cylinder's balancing force is judged as F_b
/// and M_b is refused for it; a drawing piling thousands of arrowheads
/// on thousands of lines is read (or refused) at once, not ground through.
#[test]
fn force_review_findings_stay_fixed() {
    let root = env!("CARGO_MANIFEST_DIR");
    let dir = std::env::temp_dir().join(format!("mechplan-force-review-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let run = |scene: &str, name: &str, text: &str| {
        let f = dir.join(name);
        std::fs::write(&f, text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["check", &format!("{root}/fixtures/dynamics/{scene}.json")])
            .arg(&f)
            .output()
            .unwrap();
        let said = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        (out.status.code(), said)
    };
    // M_b 200 where it is 96.7: wrong at μ_l = 0.002, refused at 0.2.
    let mb = |mu_l: f64| {
        format!(
            "{{\"plan\":\"force\",\"position\":1,\"links\":[\"1\"],\"mu\":20,\"mu_l\":{mu_l},\"values\":{{\"R_21\":1054,\"R_01\":1048,\"M_b\":200}}}}"
        )
    };
    let (st, said) = run("worked_slider_crank", "mb.json", &mb(0.002));
    assert_eq!(st, Some(1), "{said}");
    let (st, said) = run("worked_slider_crank", "mb.json", &mb(0.2));
    assert_eq!(st, Some(2), "{said}");
    assert!(said.contains("/mu_l"), "{said}");
    // The arm's cylinder 1-2-3 at position 2: F_b 17 914 N.
    let fb = |key: &str, v: f64| {
        format!(
            "{{\"plan\":\"force\",\"position\":2,\"links\":[\"1\",\"2\",\"3\"],\"mu\":200,\"values\":{{\"{key}\":{v}}}}}"
        )
    };
    assert_eq!(
        run("arm_two_cylinders", "fb.json", &fb("F_b", 17914.0)).0,
        Some(0)
    );
    assert_eq!(
        run("arm_two_cylinders", "fb.json", &fb("F_b", -17914.0)).0,
        Some(1)
    );
    let (st, said) = run("arm_two_cylinders", "fb.json", &fb("M_b", 17914.0));
    assert_eq!(st, Some(2), "{said}");
    assert!(
        said.contains("/values/M_b") && said.contains("F_b"),
        "{said}"
    );
    // 2 000 lines and 2 000 triangles piled on one spot, and 12 000
    // marked lines: an answer at once (read or refused), never minutes.
    let mut pile = String::from(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 300 300\"><text x=\"10\" y=\"290\">μ_F = 2 N/mm</text>\n",
    );
    for _ in 0..2000 {
        pile += "<path d=\"M 10 50 L 110 50\" stroke=\"black\"/><polygon points=\"110,50 106,48 106,52\"/>\n";
    }
    let mut marked = pile.clone();
    pile += "<text x=\"60\" y=\"48\">R_34</text></svg>\n";
    marked += "<g marker-end=\"url(#a)\">";
    for k in 0..12_000 {
        marked += &format!(
            "<path d=\"M 10 {} L 20 {}\" stroke=\"black\"/>",
            k % 200,
            k % 200
        );
    }
    marked += "</g><text x=\"60\" y=\"48\">R_34</text></svg>\n";
    for (name, text) in [("pile.svg", &pile), ("marked.svg", &marked)] {
        let t = std::time::Instant::now();
        let (st, said) = run("six_link_fig2_10", name, text);
        assert!(
            t.elapsed().as_secs_f64() < 5.0,
            "{name} {:?}: {said}",
            t.elapsed()
        );
        assert!(matches!(st, Some(0 | 1 | 2 | 4)), "{name}: {said}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
