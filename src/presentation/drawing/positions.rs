//! The positions sheet (lecture Fig. 2.1): the mechanism in every solved
//! position, numbered as the sheets number them (a `count` sweep from 0,
//! given values from 1), the analysed one in main lines, every rigid link a
//! closed figure in each, the output's extreme positions the others leave
//! out in dash-dot-dot lines, with the trajectories of the coupler points
//! drawn through many more positions. The trajectories and the extreme
//! positions are data of the solution ([`crate::studies::trajectories`],
//! computed by the study layer when a sheet that draws them is asked
//! for): this module only draws them.

use super::canvas::{Canvas, Label, Line, SMALL};
use super::mechanism::body_points;
use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::studies::sheet_data::SheetData;
use crate::studies::trajectories::{Trajectories, crank_tip};
use kurbo::Point;

/// The positions sheet's drawing at `mu_l` of the positions whose
/// configurations are `solved`, the one drawn bold (`d.bold`) given
/// whole, with their trajectories `d.t`
/// ([`crate::studies::trajectories::trajectories`]).
pub fn draw(an: &Analysis, (bold_at, solved): (&Solved, &[&Configuration]), d: Drawn, c: &mut Canvas, mu_l: f64) {
    let (t, bold) = (d.t, d.bold);
    let m = &an.mech;
    if solved.is_empty() {
        return;
    }
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    super::mechanism::draw_over(an, bold_at, solved, c, mu_l, true);
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
    // Every position in thin lines, position 0 (the start of the working
    // stroke, A₀) included, but the bold one: drawn once, in main lines.
    // Of a long sweep only the numbered ones (some 24 round the crank):
    // thousands of outlines over each other are a smear, not a drawing,
    // and the sheet's size stays that of 24.
    for (k, s) in solved.iter().enumerate() {
        if k != bold && k % every == 0 {
            bodies(c, s, Line::Thin);
        }
        // Number the positions as the sheet does (the lecture's 0 … 11 for
        // a `count` sweep), at the input's moving point.
        if let Some(p) = tip
            && k % every == 0
        {
            let at = to(s.point(m, input, p));
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
                w[0].point(m, pr.slider, pr.point),
                w[1].point(m, pr.slider, pr.point),
            );
            (b - a).hypot() / mu_l > 0.5
        });
        for (k, s) in solved.iter().enumerate() {
            let at = to(s.point(m, pr.slider, pr.point));
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

/// What a drawing of the positions reads beyond the positions: their
/// trajectories and the position drawn bold.
#[derive(Clone, Copy)]
pub struct Drawn<'a> {
    pub t: &'a Trajectories,
    /// The position the course analyses (from 0): the middle of the working
    /// stroke by default, not the first, an extreme position where a
    /// slider-crank's links lie on one line.
    pub bold: usize,
}

/// The data a drawing of the `n` positions reads: an internal error where
/// the caller did not solve the trajectories (presentation never solves).
pub fn given(data: &SheetData, n: usize) -> crate::error::Result<Drawn<'_>> {
    let t = data.trajectories.as_ref().ok_or_else(|| {
        crate::error::Error::Internal(
            "the drawing of the positions needs their trajectories (studies::sheet_data), not given"
                .into(),
        )
    })?;
    Ok(Drawn {
        t,
        bold: data.chosen.analysed(n),
    })
}

/// Which positions get their number: every one up to 36 positions (the
/// course's 12 or 24 are all numbered), else every k-th so that some 24
/// numbers stand around the crank's circle, readable.
fn numbering_step(n: usize) -> usize {
    if n <= 36 { 1 } else { n.div_ceil(24) }
}
