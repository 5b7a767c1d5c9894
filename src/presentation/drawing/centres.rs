//! Instant centres on the plan of the mechanism (`draw --centres`): a small
//! open circle labelled P₁₃ at each centre near the mechanism; a centre
//! far off the drawing, or at infinity, as an arrow at the drawing's edge
//! pointing to it, labelled with its name (∞ for a centre at infinity), so
//! that none is silently dropped.

use super::canvas::{Canvas, Class, Label, SMALL};
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::studies::centres::{self, Place};
use kurbo::{Point, Rect, Vec2};

/// How far around the mechanism centres are drawn in place: at least this
/// many mm, and at least this part of the mechanism's larger extent.
const MARGIN: f64 = 12.0;
const MARGIN_PART: f64 = 0.3;

/// Mark the instant centres of position `s` on a canvas where the
/// mechanism was drawn at scale `mu_l` (m per mm).
pub fn draw(an: &Analysis, s: &Solved, c: &mut Canvas, mu_l: f64) {
    let m = &an.mech;
    let cs = centres::find(an, &s.config);
    let b = c.bounds();
    let e = MARGIN.max(MARGIN_PART * b.width().max(b.height()));
    let area = Rect::new(b.x0 - e, b.y0 - e, b.x1 + e, b.y1 + e);
    let mid = area.center();
    for ce in &cs.found {
        let (base, sub) = centres::name(m, ce);
        let (toward, infinite) = match ce.place {
            Place::At(p) => {
                let at = Point::new(p.x / mu_l, p.y / mu_l);
                if area.contains(at) {
                    // A pair's centre is its joint, already drawn.
                    if !matches!(ce.how, centres::How::Revolute(_)) {
                        c.circle(at, 1.1, "none", 0.25);
                    }
                    c.label_later(at, Label::new(base, sub), SMALL, None);
                    continue;
                }
                (at - mid, false)
            }
            Place::Infinity(d) => (d, true),
        };
        // An arrow at the edge of the area, toward the centre (for a centre
        // at infinity, toward the half-line on the side of the centre).
        let Some(dir) = unit(toward) else { continue };
        let edge = exit(area, mid, dir);
        let tail = edge - dir * 7.0;
        c.seg(tail, edge, Class::Thin);
        c.arrow(edge, dir);
        let label = Label::new(base, sub);
        let label = if infinite {
            label.with_tail(" ∞")
        } else {
            label
        };
        c.label_later(tail, label, SMALL, None);
    }
}

fn unit(v: Vec2) -> Option<Vec2> {
    let h = v.hypot();
    (h.is_finite() && h > 0.0).then(|| v / h)
}

/// Where the ray from `from` (inside `r`) along `dir` leaves the rectangle.
fn exit(r: Rect, from: Point, dir: Vec2) -> Point {
    let mut t = f64::INFINITY;
    if dir.x > 0.0 {
        t = t.min((r.x1 - from.x) / dir.x);
    } else if dir.x < 0.0 {
        t = t.min((r.x0 - from.x) / dir.x);
    }
    if dir.y > 0.0 {
        t = t.min((r.y1 - from.y) / dir.y);
    } else if dir.y < 0.0 {
        t = t.min((r.y0 - from.y) / dir.y);
    }
    from + dir * t
}
