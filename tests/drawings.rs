//! Drawings: golden SVG files (style) and numeric plan snapshots (answers)
//! kept apart, and rendered checks of every sheet through usvg: inside the
//! page, labels clear of each other and of vectors, arrowheads at vector
//! ends, plan points where the construction put them.
//! Regenerate the golden files with UPDATE_GOLDEN=1.

mod common;
use common::sheets;
use common::*;
use mechplan::drawing::{DrawOptions, Sheet};
use serde_json::{Value, json};

fn fixture_sheets(name: &str) -> (mechplan::Analysis, Vec<mechplan::Solved>, Vec<Sheet>) {
    let v = fixture(name);
    let scene = mechplan::Scene::from_json(&v.to_string()).unwrap();
    let (an, s) = solve(scene);
    let sh = sheets(&an, &s, &DrawOptions::default());
    (an, s, sh)
}

fn golden(path: &str, got: &str) {
    let path = format!("{}/tests/golden/{path}", env!("CARGO_MANIFEST_DIR"));
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::create_dir_all(std::path::Path::new(&path).parent().unwrap()).unwrap();
        std::fs::write(&path, got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path)
        .unwrap_or_else(|_| panic!("{path} missing: run with UPDATE_GOLDEN=1"));
    if want != got {
        let diff: Vec<String> = want
            .lines()
            .zip(got.lines())
            .enumerate()
            .filter(|(_, (a, b))| a != b)
            .take(6)
            .map(|(i, (a, b))| format!("line {}:\n- {a}\n+ {b}", i + 1))
            .collect();
        panic!(
            "{path} differs (UPDATE_GOLDEN=1 regenerates):\n{}",
            diff.join("\n")
        );
    }
}

/// Golden SVG of the first position's sheets (and the positions sheet) of
/// every fixture: a change of drawing style shows here.
#[test]
fn golden_svg_sheets() {
    for name in FIXTURES {
        let (an, _, sh) = fixture_sheets(name);
        // The first position's, by its number (a count sweep's position 0).
        let first = an.numbering.number(0);
        for s in sh
            .iter()
            .filter(|s| s.position == Some(first) || s.name == "positions")
        {
            if s.name != "positions" {
                assert!(s.name.ends_with(&format!("_{first}")), "{}", s.name);
            }
            golden(&format!("svg/{name}/{}.svg", s.name), &s.svg);
        }
    }
}

/// Numeric snapshot of the first position's plans: a change of answer
/// shows here, apart from a change of style. Compared to 1e-9 mm.
#[test]
fn plan_snapshots() {
    for name in FIXTURES {
        let (_, s, _) = fixture_sheets(name);
        let plans = s[0].plans.as_ref().unwrap();
        let mut doc = serde_json::Map::new();
        for (k, plan) in [
            ("velocity", Some(&plans.velocity)),
            ("acceleration", plans.acceleration.as_ref()),
        ] {
            let Some(plan) = plan else { continue };
            let pts: serde_json::Map<String, Value> = plan
                .points
                .iter()
                .map(|p| (p.key.clone(), json!([p.at.x, p.at.y])))
                .collect();
            doc.insert(k.into(), json!({ "mu": plan.mu, "points": pts }));
        }
        let got = serde_json::to_string_pretty(&Value::Object(doc)).unwrap() + "\n";
        let path = format!(
            "{}/tests/golden/plans/{name}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        if std::env::var_os("UPDATE_GOLDEN").is_some() {
            std::fs::create_dir_all(std::path::Path::new(&path).parent().unwrap()).unwrap();
            std::fs::write(&path, &got).unwrap();
            continue;
        }
        let want: Value = serde_json::from_str(
            &std::fs::read_to_string(&path)
                .unwrap_or_else(|_| panic!("{path} missing: UPDATE_GOLDEN=1")),
        )
        .unwrap();
        let got: Value = serde_json::from_str(&got).unwrap();
        for k in ["velocity", "acceleration"] {
            assert_eq!(want[k]["mu"], got[k]["mu"], "{name} {k} μ");
            let (w, g) = (
                want[k]["points"].as_object().unwrap(),
                got[k]["points"].as_object().unwrap(),
            );
            assert_eq!(
                w.keys().collect::<Vec<_>>(),
                g.keys().collect::<Vec<_>>(),
                "{name} {k}: plan points"
            );
            for (key, wp) in w {
                for i in 0..2 {
                    let (a, b) = (wp[i].as_f64().unwrap(), g[key][i].as_f64().unwrap());
                    assert!((a - b).abs() <= 1e-9, "{name} {k} {key}: {a} vs {b}");
                }
            }
        }
    }
}

/// An attribute of an SVG element line written by mechplan.
fn attr(line: &str, name: &str) -> Option<f64> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()?.parse().ok()
}

fn attr_str<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()
}

/// Label boxes (mm) as the renderer lays the text out.
fn label_boxes(svg: &str) -> Vec<(String, kurbo::Rect)> {
    let tree = mechplan::drawing::tree(svg).unwrap();
    let k = 25.4 / 96.0; // px → mm
    let mut out = Vec::new();
    fn walk(g: &usvg::Group, k: f64, out: &mut Vec<(String, kurbo::Rect)>) {
        for n in g.children() {
            match n {
                usvg::Node::Group(g) => walk(g, k, out),
                usvg::Node::Text(t) if !t.id().is_empty() => {
                    let b = n.abs_bounding_box();
                    out.push((
                        t.id().to_string(),
                        kurbo::Rect::new(
                            b.left() as f64 * k,
                            b.top() as f64 * k,
                            b.right() as f64 * k,
                            b.bottom() as f64 * k,
                        ),
                    ));
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), k, &mut out);
    out
}

fn seg_hits(a: kurbo::Point, b: kurbo::Point, r: &kurbo::Rect) -> bool {
    // Sample the segment densely: exact enough at 0.05 mm.
    let n = ((b - a).hypot() / 0.05).ceil().max(1.0) as usize;
    (0..=n).any(|i| r.contains(a.lerp(b, i as f64 / n as f64)))
}

/// Every sheet of every fixture, every position: the rendered checks.
#[test]
fn rendered_sheets_pass_the_layout_checks() {
    for name in FIXTURES {
        let (an, solved, sh) = fixture_sheets(name);
        for s in &sh {
            let where_ = format!("{name} {}", s.name);
            let tree = mechplan::drawing::tree(&s.svg).unwrap();
            let size = tree.size();
            let bb = tree.root().abs_stroke_bounding_box();
            assert!(
                bb.left() >= 0.0
                    && bb.top() >= 0.0
                    && bb.right() <= size.width() + 1e-3
                    && bb.bottom() <= size.height() + 1e-3,
                "{where_}: drawing leaves the page: {bb:?} in {size:?}"
            );
            let labels = label_boxes(&s.svg);
            // How far apart two boxes are (0 when they touch or overlap).
            let apart = |a: &kurbo::Rect, b: &kurbo::Rect| {
                let dx = (a.x0 - b.x1).max(b.x0 - a.x1).max(0.0);
                let dy = (a.y0 - b.y1).max(b.y0 - a.y1).max(0.0);
                dx.max(dy)
            };
            for i in 0..labels.len() {
                for j in i + 1..labels.len() {
                    let (a, b) = (&labels[i], &labels[j]);
                    assert!(
                        a.1.intersect(b.1).area() <= 0.05,
                        "{where_}: labels {} and {} overlap",
                        a.0,
                        b.0
                    );
                    // A link's number stands apart: "S₄ 4" is not one label.
                    if a.0.starts_with("link-") || b.0.starts_with("link-") {
                        assert!(
                            apart(&a.1, &b.1) >= 1.0,
                            "{where_}: {} and {} read as one ({:.2} mm apart)",
                            a.0,
                            b.0,
                            apart(&a.1, &b.1)
                        );
                    }
                }
            }
            let lines: Vec<&str> = s.svg.lines().collect();
            let vectors: Vec<(String, kurbo::Point, kurbo::Point)> = lines
                .iter()
                .filter(|l| l.starts_with("<line") && l.contains(r#" id="vec-"#))
                .map(|l| {
                    (
                        attr_str(l, "id").unwrap().to_string(),
                        kurbo::Point::new(attr(l, "x1").unwrap(), attr(l, "y1").unwrap()),
                        kurbo::Point::new(attr(l, "x2").unwrap(), attr(l, "y2").unwrap()),
                    )
                })
                .collect();
            let arrows: Vec<kurbo::Point> = lines
                .iter()
                .filter(|l| l.contains(r#"class="arrow""#))
                .map(|l| {
                    let pts = attr_str(l, "points").unwrap();
                    let v: Vec<f64> = pts
                        .split_whitespace()
                        .take(2)
                        .map(|x| x.parse().unwrap())
                        .collect();
                    kurbo::Point::new(v[0], v[1])
                })
                .collect();
            for (id, a, b) in &vectors {
                // A vector under a millimetre is a line and its end's dot:
                // its head would be a blob (at most 0.4 of it, 0.4 mm).
                assert!(
                    (*b - *a).hypot() < 1.0 || arrows.iter().any(|t| (*t - *b).hypot() <= 0.011),
                    "{where_}: no arrowhead at the end of {id}"
                );
                for (lid, r) in &labels {
                    // The label's own anchor may touch its vector's end: shrink the box a little.
                    let r = r.inset(-0.3);
                    if r.width() > 0.0 && r.height() > 0.0 {
                        assert!(
                            !seg_hits(*a, *b, &r),
                            "{where_}: label {lid} lies on vector {id}"
                        );
                    }
                }
            }
            // Plan points where the construction put them (±0.1 mm).
            if let Some(k) = s
                .name
                .strip_prefix("velocity_")
                .or(s.name.strip_prefix("acceleration_"))
            {
                let number: usize = k.parse().unwrap();
                assert_eq!(s.position, Some(number), "{}", s.name);
                let pos = an.numbering.index(number, solved.len()).unwrap();
                let plans = solved[pos].plans.as_ref().unwrap();
                let plan = if s.name.starts_with("velocity") {
                    &plans.velocity
                } else {
                    plans.acceleration.as_ref().unwrap()
                };
                let find = |key: &str| {
                    lines
                        .iter()
                        .find(|l| l.starts_with(&format!(r#"<circle id="pt-{key}""#)))
                        .map(|l| kurbo::Point::new(attr(l, "cx").unwrap(), attr(l, "cy").unwrap()))
                };
                let pole = find(&plan.points[0].key).expect("the pole is drawn");
                // The sheet's plan is built at its own scale: the solver's
                // plan points scaled by the ratio of the scales.
                let key = if s.name.starts_with("velocity") {
                    "mu_v"
                } else {
                    "mu_a"
                };
                let mu = s.scales.iter().find(|(k, _)| *k == key).unwrap().1;
                let k = plan.mu / mu;
                for &p in &an.points {
                    let i = plan.of_point[p].unwrap();
                    let want = plan.points[i].at * k;
                    // Points sharing a place share one dot: find the dot there.
                    let expected = kurbo::Point::new(pole.x + want.x, pole.y - want.y);
                    let near = lines
                        .iter()
                        .filter(|l| l.starts_with(r#"<circle id="pt-"#))
                        .any(|l| {
                            let c =
                                kurbo::Point::new(attr(l, "cx").unwrap(), attr(l, "cy").unwrap());
                            (c - expected).hypot() <= 0.1
                        });
                    assert!(
                        near,
                        "{where_}: plan point {} not drawn at its place",
                        plan.points[i].key
                    );
                }
            }
        }
        eprintln!("{name}: {} sheets checked", sh.len());
    }
}

/// Leave out what the scene does not need: no acceleration sheet when only
/// velocities are wanted, only the drawings asked for, no ε1 arrow when
/// ε1 = 0, no definitions block at all.
#[test]
fn only_wanted_drawings_and_marks() {
    let mut v = fixture("six_link_fig2_10");
    v["want"] = json!({ "plans": ["velocity"], "drawings": ["velocity"] });
    v["positions"] = json!({ "angles": [60] });
    let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
    let sh = sheets(&an, &s, &DrawOptions::default());
    assert_eq!(
        sh.iter().map(|s| s.name.as_str()).collect::<Vec<_>>(),
        vec!["velocity_1"]
    );
    let (_, _, all) = fixture_sheets("six_link_fig2_10");
    for s in &all {
        assert!(!s.svg.contains("<defs"), "{}: unused defs", s.name);
        assert!(
            !s.svg.contains(r#"id="input-ε""#),
            "{}: ε1 = 0 but an ε1 arrow is drawn",
            s.name
        );
    }
    let (_, _, four) = fixture_sheets("four_bar");
    assert!(
        four.iter().any(|s| s.svg.contains(r#"id="input-ε""#)),
        "four-bar has ε1 ≠ 0: its arrow is drawn"
    );
    assert!(
        all.iter().all(|s| !s.svg.contains("k_")),
        "no Coriolis point without a moving guide"
    );
}

/// Plan labels that cannot be misread: the Coriolis point is always the
/// lecture's k₃, and a scene point whose letter the construction uses for
/// its own points (p, n, k, r) takes a prime (the ram's K is k′, a pin K on
/// link 3 is k′₃ beside k₃); Assur's special point is σ₃, never s₃ (a
/// centre of mass); a repeated point's prime follows its letter (n′₃), not
/// the subscript. The keys do not change.
#[test]
fn plan_point_labels_read_unambiguously() {
    let label = |plans: &mechplan::construction::Plan, key: &str| {
        let p = plans
            .points
            .iter()
            .find(|p| p.key == key)
            .unwrap_or_else(|| panic!("no plan point {key}"));
        (p.label.0.clone(), p.label.1.clone())
    };
    let acc = |v: Value| {
        let (_, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
        s[0].plans.as_ref().unwrap().acceleration.clone().unwrap()
    };
    // The shaper's point K is on the ram, link 5: k′ on the plan, beside
    // the Coriolis point of link 3, the lecture's k₃.
    let shaper = fixture("shaper_fig2_11");
    let plan = acc(shaper.clone());
    assert_eq!(label(&plan, "k_3"), ("k".into(), "3".into()));
    assert_eq!(label(&plan, "k"), ("k′".into(), "".into()));
    assert_eq!(label(&plan, "m"), ("m".into(), "".into()));
    // With the slider's pin on the rocking guide 3 called K, K of link 3
    // is k′₃ on the plan and the Coriolis point stays k₃.
    let renamed = shaper
        .to_string()
        .replace("\"K\"", "\"Q\"")
        .replace("\"K-M\"", "\"Q-M\"")
        .replace("\"B\"", "\"K\"")
        .replace("\"A-B\"", "\"A-K\"");
    let renamed: Value = serde_json::from_str(&renamed).unwrap();
    let plan = acc(renamed);
    assert_eq!(label(&plan, "k_3"), ("k".into(), "3".into()));
    assert_eq!(label(&plan, "k"), ("k′".into(), "".into()));
    // No two plan points of one plan share a label.
    for f in [
        "shaper_fig2_11",
        "boom_cylinder",
        "prp_tangent_drive",
        "rrp_rotating_guide_002",
    ] {
        let (_, s) = solve(mechplan::Scene::from_json(&fixture(f).to_string()).unwrap());
        let plans = s[0].plans.as_ref().unwrap();
        for p in std::iter::once(&plans.velocity).chain(plans.acceleration.as_ref()) {
            let mut seen = std::collections::HashSet::new();
            for q in &p.points {
                assert!(
                    seen.insert(q.label.clone()),
                    "{f}: label {:?} twice",
                    q.label
                );
                assert!(
                    q.key.starts_with("p_") || !(q.label.0 == "p" && q.label.1.is_empty()),
                    "{f}: a scene point written p beside the pole"
                );
            }
        }
    }
    let class3 = acc(fixture("class3_004"));
    assert_eq!(label(&class3, "s_3"), ("σ".into(), "3".into()));
    assert_eq!(label(&class3, "n_3'"), ("n′".into(), "3".into()));
    assert_eq!(label(&class3, "n_3''"), ("n′′".into(), "3".into()));
}
