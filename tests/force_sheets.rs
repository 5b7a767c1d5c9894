//! The force sheets (`forces_<k>`), read back from their SVG: every
//! position of every dynamics fixture has one; the drawing stays inside
//! the page and spans at least 60 % of its field one way; every label lies
//! inside the frame and on no other label; and the drawn polygon is the
//! plan: every vector's ends (the reactions read off among them) lie at
//! `ForcePlan::points` placed as the sheet places them (its start point's
//! dot, μ_F as the caption prints it) to 0.01 mm.

mod common;

use common::sheets;
use mechplan::drawing::{DrawOptions, Sheet, sheet, tree};
use mechplan::kinetostatics::force_plan::{Force, ForceStep};
use mechplan::words::construction::Lang;
use mechplan::words::forces::force_name;
use std::collections::HashMap;

const DYNAMICS: &[&str] = &[
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "arm_two_cylinders",
    "worked_slider_crank",
    "class3_004",
];

fn solve(name: &str, lang: Lang) -> (mechplan::Analysis, Vec<mechplan::Solved>, Vec<Sheet>) {
    let path = format!(
        "{}/fixtures/dynamics/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let scene = mechplan::Scene::from_json(&v.to_string()).unwrap();
    let an = mechplan::Analysis::new(scene).unwrap();
    let s = an.run().unwrap();
    let opt = DrawOptions {
        lang,
        ..DrawOptions::default()
    };
    let sh = sheets(&an, &s, &opt);
    (an, s, sh)
}

fn attr(line: &str, name: &str) -> Option<f64> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()?.parse().ok()
}

fn attr_str<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()
}

/// Every text with an id, by id, with its box (mm) as the renderer lays
/// it out.
fn label_boxes(svg: &str) -> Vec<(String, kurbo::Rect)> {
    let t = tree(svg).unwrap();
    let k = 25.4 / 96.0;
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
    walk(t.root(), k, &mut out);
    out
}

/// The share of `field` (page mm) the rendered drawing inside it spans,
/// across and down (1 px = 0.85 mm).
fn span(svg: &str, field: kurbo::Rect) -> (f64, f64) {
    const DPI: f32 = 30.0;
    let t = tree(svg).unwrap();
    let k = DPI / 25.4;
    let (w, h) = (
        t.size().width() * 25.4 / 96.0,
        t.size().height() * 25.4 / 96.0,
    );
    let (pw, ph) = ((w * k).ceil() as u32, (h * k).ceil() as u32);
    let mut pix = tiny_skia::Pixmap::new(pw, ph).unwrap();
    let s = DPI / 96.0;
    resvg::render(
        &t,
        tiny_skia::Transform::from_scale(s, s),
        &mut pix.as_mut(),
    );
    let k = k as f64;
    let (x0, x1) = ((field.x0 * k).ceil() as u32, (field.x1 * k).floor() as u32);
    let (y0, y1) = ((field.y0 * k).ceil() as u32, (field.y1 * k).floor() as u32);
    let (mut lo, mut hi) = ((u32::MAX, u32::MAX), (0u32, 0u32));
    for y in y0..y1.min(ph) {
        for x in x0..x1.min(pw) {
            let p = pix.pixel(x, y).unwrap();
            if p.red() < 200 || p.green() < 200 || p.blue() < 200 {
                lo = (lo.0.min(x), lo.1.min(y));
                hi = (hi.0.max(x), hi.1.max(y));
            }
        }
    }
    if hi.0 < lo.0 {
        return (0.0, 0.0);
    }
    (
        (hi.0 - lo.0 + 1) as f64 / (x1 - x0) as f64,
        (hi.1 - lo.1 + 1) as f64 / (y1 - y0) as f64,
    )
}

/// The layout checks on one sheet: inside the page, filling its field,
/// labels inside the frame and apart.
fn layout(where_: &str, s: &Sheet) {
    let t = tree(&s.svg).unwrap();
    let size = t.size();
    let bb = t.root().abs_stroke_bounding_box();
    assert!(
        bb.left() >= 0.0
            && bb.top() >= 0.0
            && bb.right() <= size.width() + 1e-3
            && bb.bottom() <= size.height() + 1e-3,
        "{where_}: drawing leaves the page: {bb:?} in {size:?}"
    );
    let field = sheet::field(s.size, false, 0.0);
    let (sx, sy) = span(&s.svg, field);
    assert!(
        sx.max(sy) >= 0.6,
        "{where_}: the drawing spans {:.0} % × {:.0} % of its field",
        100.0 * sx,
        100.0 * sy
    );
    let frame = sheet::frame(s.size);
    let labels = label_boxes(&s.svg);
    assert!(labels.len() > 10, "{where_}: {} labels", labels.len());
    for (id, r) in &labels {
        assert!(
            r.x0 >= frame.x0 && r.x1 <= frame.x1 && r.y0 >= frame.y0 && r.y1 <= frame.y1,
            "{where_}: label {id} {r:?} outside the frame {frame:?}"
        );
    }
    for i in 0..labels.len() {
        for j in i + 1..labels.len() {
            let (a, b) = (&labels[i], &labels[j]);
            assert!(
                a.1.intersect(b.1).area() <= 0.05,
                "{where_}: labels {} {:?} and {} {:?} overlap",
                a.0,
                a.1,
                b.0,
                b.1
            );
        }
    }
}

/// Every force sheet of every dynamics fixture, every position.
#[test]
fn force_sheets_pass_the_layout_checks() {
    for name in DYNAMICS {
        let (_, solved, sh) = solve(name, Lang::En);
        let forces: Vec<&Sheet> = sh
            .iter()
            .filter(|s| s.name.starts_with("forces_"))
            .collect();
        assert_eq!(
            forces.len(),
            solved.len(),
            "{name}: one force sheet a position"
        );
        for s in forces {
            layout(&format!("{name} {}", s.name), s);
        }
    }
}

/// The polygon drawn is the plan: each plan's vectors end where its points
/// are, placed by the start point's dot and the printed μ_F.
#[test]
fn drawn_polygons_are_the_force_plans() {
    for name in DYNAMICS {
        let (an, solved, sh) = solve(name, Lang::En);
        for (k, s) in solved.iter().enumerate() {
            // Its number as the sheet and its file name it.
            let number = an.numbering.number(k);
            let where_ = format!("{name} position {number}");
            let plans = &s
                .dynamics
                .as_ref()
                .unwrap()
                .force_plans
                .as_ref()
                .unwrap()
                .plans;
            let svg = &sh
                .iter()
                .find(|x| x.name == format!("forces_{number}"))
                .unwrap()
                .svg;
            let lines: Vec<&str> = svg.lines().collect();
            let by_id: HashMap<&str, &str> = lines
                .iter()
                .filter_map(|l| Some((attr_str(l, "id")?, *l)))
                .collect();
            for (i, plan) in plans.iter().enumerate() {
                let tag = format!("f{}", i + 1);
                let dot = by_id[format!("{tag}-pt-0").as_str()];
                let o = kurbo::Point::new(attr(dot, "cx").unwrap(), attr(dot, "cy").unwrap());
                // "μ<tspan …>F</tspan><tspan> = 25 N/mm</tspan>"
                let cap = by_id[format!("{tag}-mu").as_str()];
                let mu: f64 = cap
                    .split(" = ")
                    .nth(1)
                    .and_then(|t| t.split(' ').next())
                    .and_then(|x| x.parse().ok())
                    .unwrap_or_else(|| panic!("{where_}: no μ_F in {cap}"));
                let kx = plan.mu / mu;
                let place = |j: usize| {
                    let p = plan.points[j] - plan.points[0];
                    kurbo::Point::new(o.x + p.x * kx, o.y - p.y * kx)
                };
                let mut reactions = 0;
                for (vi, v) in plan.vectors.iter().enumerate() {
                    let id = format!("{tag}-vec-{}-{}", v.from, v.to);
                    let Some(line) = by_id.get(id.as_str()) else {
                        // A vector under a micrometre is not drawn.
                        assert!(
                            (plan.points[v.to] - plan.points[v.from]).hypot() * kx < 1e-6,
                            "{where_}: vector {id} missing"
                        );
                        continue;
                    };
                    let a = kurbo::Point::new(attr(line, "x1").unwrap(), attr(line, "y1").unwrap());
                    let b = kurbo::Point::new(attr(line, "x2").unwrap(), attr(line, "y2").unwrap());
                    // Each coordinate: the page is written to 0.01 mm, the
                    // dot and the line each rounded by at most half that.
                    for (got, want) in [(a, place(v.from)), (b, place(v.to))] {
                        assert!(
                            (got.x - want.x).abs().max((got.y - want.y).abs()) <= 0.01 + 1e-9,
                            "{where_}: {id} ends at {got:?}, the plan's point at {want:?}"
                        );
                    }
                    if plan.steps.contains(&ForceStep::Measure(vi)) {
                        assert!(
                            line.contains(r#"class="bold""#),
                            "{where_}: reaction {id} not bold"
                        );
                        reactions += 1;
                    }
                }
                assert!(reactions >= 1, "{where_}: plan {tag} reads off no reaction");
            }
        }
    }
}

/// The course's names per language, and kinematic scenes without a force
/// sheet (their sheets are the golden files' of tests/drawings.rs).
#[test]
fn names_and_only_with_dynamics() {
    let (_, _, sh) = solve("six_link_fig2_10", Lang::Uk);
    let s = sh.iter().find(|s| s.name == "forces_0").unwrap();
    assert!(s.title.starts_with("Силовий розрахунок"), "{}", s.title);
    for want in [
        ">M<tspan",
        ">зр</tspan>",
        ">Φ<tspan",
        ">R<tspan",
        ">τ</tspan>",
        "Н/мм",
    ] {
        assert!(s.svg.contains(want), "uk force sheet lacks {want}");
    }
    let (_, _, sh) = solve("worked_slider_crank", Lang::Ru);
    let s = sh.iter().find(|s| s.name == "forces_1").unwrap();
    assert!(s.svg.contains(">ур</tspan>"), "ru: M_ур missing");
    let path = format!("{}/fixtures/four_bar.json", env!("CARGO_MANIFEST_DIR"));
    let scene = mechplan::Scene::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    let an = mechplan::Analysis::new(scene).unwrap();
    let solved = an.run().unwrap();
    let sh = sheets(&an, &solved, &DrawOptions::default());
    assert!(!sh.is_empty() && sh.iter().all(|s| !s.name.starts_with("forces")));
}

/// Panel `tag`'s free body as drawn: the box of its points' circles
/// (`{tag}-joint-…`), mm.
fn body_box(svg: &str, tag: &str) -> Option<kurbo::Rect> {
    let prefix = format!("{tag}-joint-");
    svg.split('<')
        .filter(|l| attr_str(l, "id").is_some_and(|id| id.starts_with(&prefix)))
        .filter_map(|l| Some(kurbo::Point::new(attr(l, "cx")?, attr(l, "cy")?)))
        .map(|p| kurbo::Rect::from_points(p, p))
        .reduce(|a, b| a.union(b))
}

/// Every free body of every force panel, on the force sheets of every
/// position and on the course's force sheet, is drawn at least 40 mm
/// across or down: each at its own μ_l (one μ_l for all shrank the input
/// link to 10–15 mm beside a large group), its letters at their size.
#[test]
fn every_free_body_is_at_least_40_mm() {
    for name in DYNAMICS {
        let (an, solved, mut sh) = solve(name, Lang::En);
        let opt = DrawOptions {
            course: true,
            ..DrawOptions::default()
        };
        sh.extend(
            sheets(&an, &solved, &opt)
                .into_iter()
                .filter(|s| s.name == "course_forces"),
        );
        let mut smallest = f64::INFINITY;
        for s in sh
            .iter()
            .filter(|s| s.name.starts_with("forces_") || s.name == "course_forces")
        {
            for i in 1.. {
                let Some(b) = body_box(&s.svg, &format!("f{i}")) else {
                    break;
                };
                let size = b.width().max(b.height());
                smallest = smallest.min(size);
                assert!(
                    size >= 40.0,
                    "{name} {}: free body f{i} is {size:.1} mm",
                    s.name
                );
            }
        }
        assert!(smallest.is_finite(), "{name}: no free body found");
        eprintln!("{name}: smallest free body {smallest:.1} mm");
    }
}

/// All the sheets with force panels of fixture `name` in `lang`: every
/// position's force sheet and the course's force sheet.
fn panel_sheets(name: &str, lang: Lang) -> (mechplan::Analysis, Vec<mechplan::Solved>, Vec<Sheet>) {
    let (an, solved, mut sh) = solve(name, lang);
    let opt = DrawOptions {
        course: true,
        lang,
        ..DrawOptions::default()
    };
    sh.extend(
        sheets(&an, &solved, &opt)
            .into_iter()
            .filter(|s| s.name == "course_forces"),
    );
    sh.retain(|s| s.name.starts_with("forces_") || s.name == "course_forces");
    (an, solved, sh)
}

/// The position a sheet of [`panel_sheets`] draws (its index, from 0):
/// the number the sheet states (its `position`, the number in its file's
/// name), read in the scene's numbering.
fn position_of(an: &mechplan::Analysis, solved: &[mechplan::Solved], s: &Sheet) -> usize {
    let number = s.position.expect("a sheet of one position");
    let k = an.numbering.index(number, solved.len()).unwrap();
    match s.name.strip_prefix("forces_") {
        Some(n) => assert_eq!(n.parse::<usize>().unwrap(), number, "{}", s.name),
        None => assert_eq!(
            k,
            mechplan::studies::chosen::Chosen::of(an, solved.len()).analysed(solved.len()),
            "{}",
            s.name
        ),
    }
    k
}

/// The two ends of a `<line>` (page mm).
fn line_ends(l: &str) -> (kurbo::Point, kurbo::Point) {
    (
        kurbo::Point::new(attr(l, "x1").unwrap(), attr(l, "y1").unwrap()),
        kurbo::Point::new(attr(l, "x2").unwrap(), attr(l, "y2").unwrap()),
    )
}

/// The box of a `<polygon>`'s points (page mm).
fn polygon_box(l: &str) -> kurbo::Rect {
    let v: Vec<f64> = attr_str(l, "points")
        .unwrap()
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    v.chunks(2)
        .map(|p| kurbo::Rect::from_points((p[0], p[1]), (p[0], p[1])))
        .reduce(|a, b| a.union(b))
        .unwrap()
}

/// Every element with an id, by id (the sheets write one a line).
fn by_id(svg: &str) -> HashMap<String, String> {
    svg.lines()
        .filter_map(|l| Some((attr_str(l, "id")?.to_string(), l.to_string())))
        .collect()
}

/// The μ_l of panel `i` (1-based) of a sheet.
fn mu_l(s: &Sheet, i: usize) -> f64 {
    s.scales
        .iter()
        .filter(|(k, _)| *k == "mu_l")
        .nth(i - 1)
        .unwrap()
        .1
}

/// A prismatic pair's reaction is drawn on its slider (R₀₅ stood 220 mm
/// off the shaper's slider at its line of action, linked to nothing):
/// every such arrow ends within 3 mm of its slider's block where the
/// block is on the panel, and its line of action's offset from the
/// slider's centre is a dimension line as long as the offset at the
/// panel's μ_l (to 0.5 mm; one longer than 25 mm drawn 25 mm long).
#[test]
fn guide_reactions_are_drawn_on_their_sliders() {
    let mut arrows = 0;
    let mut offsets = 0;
    for name in DYNAMICS {
        let (an, solved, sh) = panel_sheets(name, Lang::En);
        for s in &sh {
            let k = position_of(&an, &solved, s);
            let d = solved[k].dynamics.as_ref().unwrap();
            let ids = by_id(&s.svg);
            for (id, l) in &ids {
                // "f1-force-8-p2": panel f1, pair 2.
                let Some((tag, rest)) = id.split_once("-force-") else {
                    continue;
                };
                let Some((_, pair)) = rest.split_once("-p") else {
                    continue;
                };
                let Some(block) = ids.get(&format!("{tag}-slider-{pair}")) else {
                    continue;
                };
                let b = polygon_box(block).inflate(3.0, 3.0);
                let (p, q) = line_ends(l);
                assert!(
                    b.contains(p) || b.contains(q),
                    "{name} {}: {id} from {p:?} to {q:?}, its slider at {b:?}",
                    s.name
                );
                arrows += 1;
            }
            for (id, l) in &ids {
                let Some((tag, pair)) = id.split_once("-offset-") else {
                    continue;
                };
                let Ok(pair) = pair.parse::<usize>() else {
                    continue;
                };
                let panel: usize = tag[1..].parse().unwrap();
                let g = &d.prismatics[pair];
                let x = (g.at.unwrap() - g.q).dot(g.u).abs() / mu_l(s, panel);
                let (p, q) = line_ends(l);
                let drawn = (q - p).hypot();
                assert!(
                    (drawn - x.min(25.0)).abs() <= 0.5,
                    "{name} {}: {id} is {drawn:.2} mm, the offset {x:.2} mm at μ_l",
                    s.name
                );
                assert!(ids.contains_key(&format!("{id}-label")), "{id} unlabelled");
                offsets += 1;
            }
        }
    }
    assert!(
        arrows > 0 && offsets > 0,
        "{arrows} arrows, {offsets} offsets"
    );
}

/// A text element's words, its tags and spaces dropped.
fn words_of(l: &str) -> String {
    let body = l.split_once('>').map_or("", |x| x.1);
    let mut out = String::new();
    let mut tag = false;
    for ch in body.chars() {
        match ch {
            '<' => tag = true,
            '>' => tag = false,
            c if !tag && !c.is_whitespace() => out.push(c),
            _ => {}
        }
    }
    out
}

/// The forces of a plan's polygon in the order they are laid off round
/// it from its start: the vectors laid off, then the component of the
/// line through the last end and that of the line through the start
/// (or the reaction read off from the end back to the start).
fn laid_off(plan: &mechplan::kinetostatics::force_plan::ForcePlan) -> Vec<Force> {
    let mut out = Vec::new();
    let mut end = 0;
    for st in &plan.steps {
        if let ForceStep::LayOff(vi) = st {
            out.push(plan.vectors[*vi].force);
            end = plan.vectors[*vi].to;
        }
    }
    let mut closed = false;
    for st in &plan.steps {
        if let ForceStep::Intersect {
            lines, out: meet, ..
        } = st
        {
            assert_eq!(plan.lines[lines[1]].through, end);
            assert_eq!(plan.lines[lines[0]].through, 0);
            let _ = meet;
            out.push(plan.lines[lines[1]].force);
            out.push(plan.lines[lines[0]].force);
            closed = true;
        }
    }
    if !closed {
        let v = plan
            .vectors
            .iter()
            .find(|v| v.from == end && v.to == 0)
            .expect("a reaction closing the polygon");
        out.push(v.force);
    }
    out
}

/// Beside every polygon its vector equation, as the course writes it:
/// exactly the polygon's vectors, in the order laid off, "= 0".
#[test]
fn every_polygon_has_its_vector_equation() {
    let mut count = 0;
    for name in DYNAMICS {
        for lang in [Lang::En, Lang::Uk] {
            let (an, solved, sh) = panel_sheets(name, lang);
            for s in &sh {
                let k = position_of(&an, &solved, s);
                let d = solved[k].dynamics.as_ref().unwrap();
                let ids = by_id(&s.svg);
                for (i, plan) in d.force_plans.as_ref().unwrap().plans.iter().enumerate() {
                    let tag = format!("f{}", i + 1);
                    let mut text = String::new();
                    for j in 0.. {
                        let Some(l) = ids.get(&format!("{tag}-equation-{j}")) else {
                            break;
                        };
                        text += &words_of(l);
                    }
                    let want: Vec<String> = laid_off(plan)
                        .into_iter()
                        .map(|f| force_name(&an.mech, &d.loads, f, lang).replace(['^', '_'], ""))
                        .collect();
                    let want = want.join("+") + "=0";
                    assert_eq!(text, want, "{name} {} {tag}", s.name);
                    count += 1;
                }
            }
        }
    }
    assert!(count > 0);
}

/// The point (m) each moment equation of a plan is taken about, by step,
/// with its links: ΣM about a point for a component, the input link's
/// about its pivot for the balancing moment.
fn moment_points(
    an: &mechplan::Analysis,
    s: &mechplan::Solved,
    plan: &mechplan::kinetostatics::force_plan::ForcePlan,
) -> Vec<(usize, kurbo::Point, Vec<usize>)> {
    let m = &an.mech;
    let mut out = Vec::new();
    for (i, st) in plan.steps.iter().enumerate() {
        match st {
            ForceStep::Moment { links, about, .. } => out.push((i, *about, links.clone())),
            ForceStep::Balancing { input, .. } => {
                if let Some(&mechplan::model::scene::InputSpec::Crank { link, pivot, .. }) =
                    m.scene.inputs().nth(*input)
                {
                    out.push((i, s.config.point(m, link, pivot), vec![link]));
                }
            }
            _ => {}
        }
    }
    out
}

/// The line of action of a plan's vector (a point, a direction; m) and
/// the link it acts on: a load's, a pin's reaction, a guide's reaction at
/// its line; `None` for the others.
fn line_of(
    an: &mechplan::Analysis,
    s: &mechplan::Solved,
    v: &mechplan::kinetostatics::force_plan::Drawn,
) -> Option<(kurbo::Point, kurbo::Vec2, usize)> {
    use mechplan::kinetostatics::Load;
    use mechplan::kinetostatics::force_plan::Part;
    use mechplan::model::structure::Joint;
    let d = s.dynamics.as_ref().unwrap();
    match v.force {
        Force::Load(i) => match d.loads[i] {
            Load::Force { link, at, f, .. } => Some((at, f, link)),
            _ => None,
        },
        Force::Reaction {
            to,
            joint,
            part: Part::Whole,
            ..
        } => match joint {
            Joint::R(p) => Some((s.config.point(&an.mech, to, p), v.value, to)),
            Joint::P(k) => {
                let g = &d.prismatics[k];
                Some((g.at.unwrap_or(g.q), v.value, to))
            }
        },
        _ => None,
    }
}

/// On each free body the arms h of the forces in the moment equations
/// the method writes, as the course draws them: every known force
/// (a load, a reaction of a group solved before) on an equation's links
/// whose arm is 2 mm or more at the panel's μ_l has its arm, a thin line
/// from the moment point as long as the point's distance from the
/// force's line of action at μ_l (to 0.5 mm), labelled.
#[test]
fn free_bodies_show_the_arms_of_their_moment_equations() {
    let mut arms = 0;
    for name in DYNAMICS {
        let (an, solved, sh) = panel_sheets(name, Lang::En);
        for s in &sh {
            let k = position_of(&an, &solved, s);
            let sol = &solved[k];
            let d = sol.dynamics.as_ref().unwrap();
            let ids = by_id(&s.svg);
            for (i, plan) in d.force_plans.as_ref().unwrap().plans.iter().enumerate() {
                let tag = format!("f{}", i + 1);
                let mu = mu_l(s, i + 1);
                for (step, about, links) in moment_points(&an, sol, plan) {
                    for (vi, v) in plan.vectors.iter().enumerate() {
                        // A reaction read off this plan is no known force.
                        if plan.steps.contains(&ForceStep::Measure(vi)) || v.value.hypot() == 0.0 {
                            continue;
                        }
                        let Some((at, f, link)) = line_of(&an, sol, v) else {
                            continue;
                        };
                        if !links.contains(&link) {
                            continue;
                        }
                        // A reaction from inside the group is no outer force.
                        if let Force::Reaction { from, .. } = v.force
                            && plan.links.contains(&from)
                        {
                            continue;
                        }
                        let h = (about - at).cross(f).abs() / f.hypot() / mu;
                        let id = format!("{tag}-arm-s{step}-v{vi}");
                        let Some(l) = ids.get(&id) else {
                            assert!(h < 2.0, "{name} {} {tag}: no arm {id} ({h:.1} mm)", s.name);
                            continue;
                        };
                        let (p, q) = line_ends(l);
                        let drawn = (q - p).hypot();
                        assert!(
                            (drawn - h).abs() <= 0.5,
                            "{name} {} {id}: arm {drawn:.2} mm, the distance {h:.2} mm at μ_l",
                            s.name
                        );
                        assert!(ids.contains_key(&format!("{id}-label")), "{id} unlabelled");
                        arms += 1;
                    }
                }
            }
        }
    }
    assert!(arms > 20, "{arms} arms");
    eprintln!("{arms} arms checked");
}

/// Every force sheet (and the course's) says, in its language, that the
/// arrows on the free bodies are not to scale, only the polygons are.
#[test]
fn force_sheets_say_their_arrows_are_not_to_scale() {
    for lang in [Lang::En, Lang::Uk, Lang::Ru] {
        let want: String = mechplan::words::catalogue(lang)
            .sheets
            .not_to_scale
            .chars()
            .filter(|c| !c.is_whitespace() && *c != '_')
            .collect();
        for name in ["shaper_fig2_11", "compressor_fig2_12"] {
            let (_, _, sh) = panel_sheets(name, lang);
            assert!(sh.iter().any(|s| s.name == "course_forces"));
            for s in &sh {
                let ids = by_id(&s.svg);
                let mut got = String::new();
                for j in 0.. {
                    let Some(l) = ids.get(&format!("forces-note-{j}")) else {
                        break;
                    };
                    got += &words_of(l);
                }
                assert_eq!(got, want, "{name} {} ({lang:?})", s.name);
            }
        }
    }
}

/// Vectors of a polygon too short to carry their names (under 5 mm, over
/// 0.2 mm) stand again in a local enlargement beside it (ГОСТ 2.305's
/// detail "I (5:1)"): the same vector, the same direction, a standard
/// enlargement (ГОСТ 2.302) times as long and at least 4 mm, named there;
/// the polygon marks the place with a ring.
#[test]
fn short_polygon_vectors_are_enlarged_beside_it() {
    let mut enlarged = 0;
    for name in DYNAMICS {
        let (_, _, sh) = solve(name, Lang::En);
        for s in sh.iter().filter(|s| s.name.starts_with("forces_")) {
            let lines: Vec<&str> = s.svg.lines().collect();
            let by_id: HashMap<&str, &str> = lines
                .iter()
                .filter_map(|l| Some((attr_str(l, "id")?, *l)))
                .collect();
            let seg = |l: &str| {
                let a = kurbo::Point::new(attr(l, "x1").unwrap(), attr(l, "y1").unwrap());
                let b = kurbo::Point::new(attr(l, "x2").unwrap(), attr(l, "y2").unwrap());
                b - a
            };
            for (id, l) in &by_id {
                // "f2-vec-3-4": a polygon's own vector.
                let Some((tag, rest)) = id.split_once("-vec-") else {
                    continue;
                };
                if tag.contains("-d") || !l.starts_with("<line") {
                    continue;
                }
                let v = seg(l);
                if !(0.2..5.0).contains(&v.hypot()) {
                    continue;
                }
                let twin = (1..=4).find_map(|n| {
                    by_id
                        .get(format!("{tag}-d{n}-vec-{rest}").as_str())
                        .map(|t| (n, *t))
                });
                let (n, t) = twin.unwrap_or_else(|| {
                    panic!("{}: {id} ({:.2} mm) has no enlargement", s.name, v.hypot())
                });
                assert!(
                    by_id.contains_key(format!("{tag}-d{n}").as_str()),
                    "{}: no ring {tag}-d{n}",
                    s.name
                );
                let w = seg(t);
                let m = w.hypot() / v.hypot();
                assert!(
                    [2.0, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0]
                        .iter()
                        .any(|&k: &f64| (m - k).abs() <= k * (0.01 + 0.03 / v.hypot())),
                    "{}: {id} enlarged {m:.3} times",
                    s.name
                );
                assert!(
                    v.cross(w).abs() <= 0.02 * v.hypot() * w.hypot() + 0.05,
                    "{}: {id} turned",
                    s.name
                );
                assert!(v.dot(w) > 0.0, "{}: {id} reversed", s.name);
                assert!(
                    w.hypot() >= 4.0,
                    "{}: {id} still {:.2} mm enlarged",
                    s.name,
                    w.hypot()
                );
                enlarged += 1;
            }
        }
    }
    assert!(enlarged >= 10, "only {enlarged} short vectors seen");
}
