//! The symbol of a hydraulic (pneumatic) cylinder on the plan of the
//! mechanism (ГОСТ 2.770-68, "цилиндр с поршнем"): the barrel a narrow
//! rectangle along the cylinder's axis, closed at both ends (its pivot's
//! end and the end cap the rod passes through); the piston a stroke
//! across the barrel; the rod a line from the piston out through the end
//! cap to its pin. Each cylinder is a group `cylinder-K` (K: the pair's
//! number from 1), so that a reader finds its parts. Drawn for the
//! driving pair of a driving slider on a moving guide (the cylinder is the
//! guide, the rod the slider), over the two links' own lines.

use super::canvas::{Canvas, Class, MAIN};
use crate::geom::perp;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use kurbo::Point;

/// Half the barrel's width, mm.
const HALF_WIDTH: f64 = 2.2;
/// The barrel's length (mm) when the cylinder link has no point along its
/// axis but its pivot.
const DEFAULT_BARREL: f64 = 16.0;

/// The prismatic pairs drawn as cylinders: those of the driving sliders
/// whose guide is a moving link.
pub fn pairs(an: &Analysis) -> Vec<usize> {
    let m = &an.mech;
    m.scene
        .inputs()
        .filter_map(|i| match *i {
            InputSpec::Slider { pair, .. } if m.prismatics[pair].guide != m.frame() => Some(pair),
            _ => None,
        })
        .filter(|&k| an.link(m.prismatics[k].guide) && an.link(m.prismatics[k].slider))
        .collect()
}

/// Draw every cylinder of position `s` at scale `mu_l` (m/mm).
pub fn draw(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64) {
    for k in pairs(an) {
        one(an, s, c, mu_l, k);
    }
}

pub(crate) fn one(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64, k: usize) {
    c.group_id("cylinder", format!("cylinder-{}", k + 1), |c| {
        barrel(an, s, c, mu_l, k)
    });
}

/// The barrel, the piston and the rod of pair `k`.
fn barrel(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64, k: usize) {
    let m = &an.mech;
    let pr = &m.prismatics[k];
    let to = |p: Point| Point::new(p.x / mu_l, p.y / mu_l);
    let u = s.config.pose(pr.guide).dir(pr.line_dir);
    let n = perp(u);
    let origin = to(s.config.pose(pr.guide).apply(pr.line_point));
    let along = |p: Point| (p - origin).dot(u);
    let on_axis = |t: f64| origin + u * t;
    let pin = to(s.config.point(m, pr.slider, pr.point));
    let t_pin = along(pin);
    // The barrel: the cylinder link's points along the axis, its bottom
    // the end away from the rod's pin, its cap the end toward it.
    let ts: Vec<f64> = m.links[pr.guide]
        .points
        .iter()
        .map(|&p| along(to(s.config.point(m, pr.guide, p))))
        .collect();
    let (lo, hi) = ts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    let toward_pin = if t_pin >= 0.5 * (lo + hi) { 1.0 } else { -1.0 };
    let (bottom, cap) = if hi - lo > 2.0 * HALF_WIDTH {
        if toward_pin > 0.0 { (lo, hi) } else { (hi, lo) }
    } else {
        (lo, lo + toward_pin * DEFAULT_BARREL)
    };
    // The piston: the rod's point deepest in the barrel (the rod's pin
    // alone: a little inside the cap), kept inside the barrel.
    let depth = |t: f64| (t - bottom) * toward_pin;
    let len = depth(cap);
    let deepest = m.links[pr.slider]
        .points
        .iter()
        .map(|&p| along(to(s.config.point(m, pr.slider, p))))
        .fold(t_pin, |a, t| if depth(t) < depth(a) { t } else { a });
    let piston_depth = if deepest == t_pin {
        len - 3.0
    } else {
        depth(deepest)
    }
    .clamp(1.0, (len - 1.0).max(1.0));
    let piston = bottom + toward_pin * piston_depth;
    // The barrel over the links' lines, closed at both ends: the rod
    // passes through the end cap.
    let corners = |t0: f64, t1: f64, h: f64| {
        vec![
            on_axis(t0) - n * h,
            on_axis(t1) - n * h,
            on_axis(t1) + n * h,
            on_axis(t0) + n * h,
        ]
    };
    c.poly(corners(bottom, cap, HALF_WIDTH), "white", 0.0);
    for end in [bottom, cap] {
        c.seg(
            on_axis(end) - n * HALF_WIDTH,
            on_axis(end) + n * HALF_WIDTH,
            Class::Main,
        );
    }
    for side in [-1.0, 1.0] {
        c.seg(
            on_axis(bottom) + n * (side * HALF_WIDTH),
            on_axis(cap) + n * (side * HALF_WIDTH),
            Class::Main,
        );
    }
    // The pivot's side of the barrel: the cylinder link's line up to it.
    // The piston, and the rod from it to the pin.
    c.poly(
        corners(
            piston - toward_pin * 0.4,
            piston + toward_pin * 0.4,
            HALF_WIDTH - 0.3,
        ),
        "black",
        MAIN,
    );
    c.seg(on_axis(piston), pin, Class::Main);
}
