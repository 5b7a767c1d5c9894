//! The positions sheet (lecture Fig. 2.1): the mechanism in every solved
//! position, numbered as the sheets number them (a `count` sweep from 0,
//! given values from 1), the analysed one in main lines, every rigid link a
//! closed figure in each, the output's extreme positions the others leave
//! out in dash-dot-dot lines, with the trajectories of the coupler points
//! drawn through many more positions.

use super::canvas::{Canvas, Label, Line, SMALL};
use super::mechanism::body_points;
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::Analysis;
use crate::model::mechanism::Mechanism;
use crate::model::scene::{InputSpec, PositionsSpec};
use crate::pipeline::Solved;
use kurbo::Point;

/// The trajectories of the coupler points (m), computed once for every
/// scale the sheet is tried at, and the crank's circle.
pub struct Trajectories {
    paths: Vec<Vec<Point>>,
    /// The crank's pivot and radius, m, when it turns fully.
    circle: Option<(Point, f64)>,
    /// The output's extreme positions not among the positions drawn (the
    /// end of the working stroke, and its start where the positions do
    /// not begin there), each with its sign: 0 for the start, 1 the end.
    extremes: Vec<(Configuration, usize)>,
}

/// The input link's point off the frame (a crank's end), if it has one.
fn crank_tip(m: &Mechanism) -> Option<usize> {
    m.links[m.scene.input.link()]
        .points
        .iter()
        .copied()
        .find(|&p| !m.links_of_point(p).contains(&m.frame()))
}

/// The positions sheet's drawing of `solved` at `mu_l`, with the
/// trajectories `t` ([`trajectories`]).
pub fn draw(an: &Analysis, solved: &[Solved], t: &Trajectories, c: &mut Canvas, mu_l: f64) {
    let m = &an.mech;
    if solved.is_empty() {
        return;
    }
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    // The bold position: the one the course analyses (the middle of the
    // working stroke by default), not the first, an extreme position where
    // a slider-crank's links lie on one line.
    let bold = super::chosen::position(an, solved);
    super::mechanism::draw_over(an, &solved[bold], solved, c, mu_l, true);
    let input = m.scene.input.link();
    let tip = crank_tip(m);
    let every = numbering_step(solved.len());
    // Each link in one path through its body's corners, closed where it
    // has three or more (a rigid link is a closed figure in every
    // position, as in the main one); centres of mass left out. A
    // position is a handful of elements: the sheet grows linearly.
    let bodies = |c: &mut Canvas, config: &Configuration, line: Line| {
        for l in (0..m.links.len()).filter(|&l| l != m.frame() && an.link(l)) {
            let mut xy: Vec<Point> = body_points(m, l)
                .into_iter()
                .map(|p| to(config.point(m, l, p)))
                .collect();
            if xy.len() >= 3 {
                xy.push(xy[0]);
            }
            c.path(xy, line);
        }
    };
    // The output's extreme positions the positions leave out (the end of
    // the working stroke, A′₀ of the lecture) in dash-dot-dot lines
    // (ГОСТ 2.303's line for extreme positions), the crank's end named.
    for (config, which) in &t.extremes {
        bodies(c, config, Line::DashDotDot);
        if let Some(p) = tip {
            let at = to(config.point(m, input, p));
            let prime = if *which == 1 { "′" } else { "" };
            c.circle(at, 0.4, "black", 0.0);
            c.label_later(
                at,
                Label::new(format!("{}{prime}", m.point_name(p)), "0"),
                SMALL,
                Some(format!("extreme-{which}")),
            );
        }
    }
    for (k, s) in solved.iter().enumerate() {
        if k > 0 {
            bodies(c, &s.config, Line::Thin);
        }
        // Number the positions as the sheet does (the lecture's 0 … 11 for
        // a `count` sweep), at the input's moving point.
        if let Some(p) = tip
            && k % every == 0
        {
            let at = to(s.config.point(m, input, p));
            c.circle(at, 0.4, "black", 0.0);
            c.label_later(
                at,
                Label::new(crate::presentation::position_number(an, k).to_string(), ""),
                SMALL,
                Some(format!("pos-{}", crate::presentation::position_number(an, k))),
            );
        }
    }
    // The sliders' places on their fixed guides (the walls reach them
    // all), numbered as the crank's (lecture Fig. 2.1: B₀ … B₁₁ along the
    // guide), where the slider moves between positions.
    for (j, pr) in m.prismatics.iter().enumerate() {
        if pr.guide != m.frame() || !an.link(pr.slider) {
            continue;
        }
        let moves = solved.windows(2).any(|w| {
            let (a, b) = (
                w[0].config.point(m, pr.slider, pr.point),
                w[1].config.point(m, pr.slider, pr.point),
            );
            (b - a).hypot() / mu_l > 0.5
        });
        for (k, s) in solved.iter().enumerate() {
            let at = to(s.config.point(m, pr.slider, pr.point));
            c.circle(at, 0.5, "black", 0.0);
            if moves && k % every == 0 {
                c.label_later(
                    at,
                    Label::new(crate::presentation::position_number(an, k).to_string(), ""),
                    SMALL,
                    Some(format!(
                        "slider-{j}-pos-{}",
                        crate::presentation::position_number(an, k)
                    )),
                );
            }
        }
    }
    for path in &t.paths {
        c.path(path.iter().map(|&p| to(p)).collect(), Line::DashDot);
    }
    // The crank's circle, on which the positions are marked.
    if let Some((o, r)) = t.circle {
        let circle = (0..=96)
            .map(|k| to(o + kurbo::Vec2::from_angle(std::f64::consts::TAU * k as f64 / 96.0) * r))
            .collect();
        c.path(circle, Line::DashDot);
    }
    c.place_pending();
}

/// Which positions get their number: every one up to 36 positions (the
/// course's 12 or 24 are all numbered), else every k-th so that some 24
/// numbers stand around the crank's circle, readable.
fn numbering_step(n: usize) -> usize {
    if n <= 36 { 1 } else { n.div_ceil(24) }
}

/// The trajectories of the points that are neither on the frame, nor on
/// a link turning about a fixed pivot, nor on a slider of a frame guide:
/// through 72 positions per revolution of a crank turning fully, else
/// through the solved ones.
pub fn trajectories(an: &Analysis, solved: &[Solved]) -> Trajectories {
    let m = &an.mech;
    if solved.is_empty() {
        return Trajectories {
            paths: Vec::new(),
            circle: None,
            extremes: Vec::new(),
        };
    }
    let full_turn = matches!(m.scene.input, InputSpec::Crank { .. })
        && !m.scene.several_inputs()
        && solved.len() >= 12;
    let mut paths: Vec<Vec<Point>> = Vec::new();
    let tracked: Vec<(usize, usize)> = (0..m.scene.points.len())
        .filter_map(|p| {
            let ls = m.links_of_point(p);
            let l = *ls.iter().find(|&&l| an.link(l))?;
            let pivoted = |l: usize| {
                l == m.frame()
                    || m.links[l]
                        .points
                        .iter()
                        .any(|&q| m.links_of_point(q).contains(&m.frame()))
            };
            let slides_on_frame = m
                .prismatics
                .iter()
                .any(|pr| pr.slider == l && pr.guide == m.frame());
            (!ls.iter().all(|&l| pivoted(l)) && !slides_on_frame).then_some((p, l))
        })
        .collect();
    if full_turn && let Ok(mut ps) = PositionSolver::new(m, &an.structure, an.need.clone()) {
        {
            let q0 = solved[0].q;
            let dir = m.scene.input.sense();
            let mut ok = true;
            let mut samples: Vec<Vec<Point>> = vec![Vec::new(); tracked.len()];
            for k in 0..=72 {
                match ps.solve(q0 + dir * std::f64::consts::TAU * k as f64 / 72.0) {
                    Ok(cfg) => {
                        for (i, &(p, l)) in tracked.iter().enumerate() {
                            samples[i].push(cfg.point(m, l, p));
                        }
                    }
                    Err(_) => {
                        ok = false;
                        break;
                    }
                }
            }
            if ok {
                paths = samples;
            }
        }
    }
    if paths.is_empty() {
        paths = tracked
            .iter()
            .map(|&(p, l)| solved.iter().map(|s| s.config.point(m, l, p)).collect())
            .collect();
    }
    let input = m.scene.input.link();
    let tip = crank_tip(m);
    let circle = match (&m.scene.input, tip) {
        (InputSpec::Crank { pivot, .. }, Some(p)) if full_turn => {
            let o = solved[0].config.point(m, m.frame(), *pivot);
            Some((o, (solved[0].config.point(m, input, p) - o).hypot()))
        }
        _ => None,
    };
    let extremes = if full_turn {
        extremes(an, solved)
    } else {
        Vec::new()
    };
    Trajectories {
        paths,
        circle,
        extremes,
    }
}

/// The output's two extreme positions (the start and the end of its
/// working stroke) that are not among the `solved` ones, followed from
/// the first solved position on its branch; none where the output turns
/// fully or a position cannot be reached.
fn extremes(an: &Analysis, solved: &[Solved]) -> Vec<(Configuration, usize)> {
    let m = &an.mech;
    let out = match m.scene.positions {
        PositionsSpec::Count {
            output: Some(out), ..
        } => out,
        _ => an.default_output(),
    };
    let Ok((start, stroke)) = an.working_stroke(out) else {
        return Vec::new();
    };
    if stroke >= std::f64::consts::TAU {
        return Vec::new();
    }
    let Ok(mut ps) = PositionSolver::new(m, &an.structure, an.need.clone()) else {
        return Vec::new();
    };
    let dir = m.scene.input.sense();
    let q0 = solved[0].q;
    // The start, unwound to within a turn after the first position.
    let start = q0 + dir * (dir * (start - q0)).rem_euclid(std::f64::consts::TAU);
    let drawn = |q: f64| {
        solved.iter().any(|s| {
            let d = (s.q - q).rem_euclid(std::f64::consts::TAU);
            d.min(std::f64::consts::TAU - d) < 1e-9
        })
    };
    let mut out = Vec::new();
    if ps.solve(q0).is_err() {
        return out;
    }
    for (which, q) in [(0, start), (1, start + dir * stroke)] {
        match ps.solve(q) {
            Ok(config) if !drawn(q) => out.push((config, which)),
            Ok(_) => {}
            Err(_) => return Vec::new(),
        }
    }
    out
}
