//! The arcs of angular velocities on the plan of the mechanism (the
//! inputs' ω1, ε1 and every other turning link's ω): drawn in a free
//! direction, clear of the hatching and the slider blocks drawn before.

use super::canvas::{Canvas, Class, FONT, Label, Prim};
use crate::geom::perp;
use kurbo::{Point, Vec2};

/// What a link's ω arc must keep clear of, as drawn so far: each a test
/// of a point (within 1 mm of a hatching stroke, or inside a block).
pub(super) fn obstacles(c: &Canvas) -> Vec<Box<dyn Fn(Point) -> bool>> {
    let mut out: Vec<Box<dyn Fn(Point) -> bool>> = Vec::new();
    for p in &c.prims {
        match p {
            Prim::Seg { a, b, class: Class::Hatch, .. } => {
                let (a, b) = (*a, *b);
                out.push(Box::new(move |x: Point| {
                    let t = ((x - a).dot(b - a) / (b - a).hypot2().max(1e-12)).clamp(0.0, 1.0);
                    (x - (a + (b - a) * t)).hypot() < 1.0
                }));
            }
            Prim::Poly { pts, fill: "white", .. } if pts.len() == 4 => {
                let q = pts.clone();
                out.push(Box::new(move |x: Point| {
                    let side = |i: usize| {
                        let e = q[(i + 1) % 4] - q[i];
                        e.cross(x - q[i]) / e.hypot().max(1e-12)
                    };
                    let s: Vec<f64> = (0..4).map(side).collect();
                    s.iter().all(|v| *v > -1.5) || s.iter().all(|v| *v < 1.5)
                }));
            }
            _ => {}
        }
    }
    out
}

/// An arc of radius `r` about `o` in the free direction `mid` (`room`
/// wide), its arrow in the sense of `val` (counter-clockwise positive),
/// labelled.
pub(super) fn rate_arc(
    c: &mut Canvas,
    (o, r): (Point, f64),
    (mid, room): (f64, f64),
    val: f64,
    label: Label,
    id: String,
) {
    let sweep = room.min(1.6) * val.signum();
    let a0 = mid - sweep / 2.0;
    c.arc(o, r, a0, sweep);
    let end = a0 + sweep;
    c.arrow(o + Vec2::from_angle(end) * r, perp(Vec2::from_angle(end)) * val.signum());
    let at = o + Vec2::from_angle(a0 + sweep / 2.0) * (r + 2.0);
    c.label_later(at, label, FONT, Some(id));
}
