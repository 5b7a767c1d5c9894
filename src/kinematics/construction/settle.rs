//! Whether a plan drawn at a trial scale is the plan its field picks that
//! scale for: the sweep's shortcut that skips the construction at unit
//! scale ([`Plan::settles_in`]).

use super::plan::Plan;
use super::scale::Field;
use kurbo::Vec2;

impl Plan {
    /// Whether this plan, drawn at its scale μ (a standard value whose
    /// `scale::band` is `band`), is the plan `field`'s [`Field::scale`] picks μ for from a
    /// construction at unit scale. The two constructions differ by their
    /// rounding only, a few ulps amplified as the drafting error is (by
    /// 1/sin θ at every intersection: the plan's error radii over δ); so μ
    /// is settled when every extent within a billionth times that
    /// amplification of the plan's own lies in μ's band.
    pub fn settles_in(&self, field: &Field, band: (f64, f64)) -> bool {
        let plan = self;
        // One pass in millimetres: the longest vector (squared), the box,
        // the largest error radius.
        let (mut long2, mut lo, mut hi, mut err) =
            (0.0f64, Vec2::splat(f64::MAX), Vec2::splat(f64::MIN), 0.0f64);
        // (Plain comparisons: a NaN point leaves the extent as it is, and
        // the ratio's own test below refuses a plan that is all NaN.)
        for p in &plan.points {
            let (a, h) = (p.at, p.at.hypot2());
            if h > long2 {
                long2 = h;
            }
            if a.x < lo.x {
                lo.x = a.x;
            }
            if a.y < lo.y {
                lo.y = a.y;
            }
            if a.x > hi.x {
                hi.x = a.x;
            }
            if a.y > hi.y {
                hi.y = a.y;
            }
            if p.err > err {
                err = p.err;
            }
        }
        let mu = plan.mu;
        let ratio = (long2.sqrt() / field.longest)
            .max((hi.x - lo.x) / field.width)
            .max((hi.y - lo.y) / field.height)
            * mu;
        if !(ratio > 0.0 && ratio.is_finite()) {
            // Nothing to fit (all at the pole): the scale is 1.
            return mu == 1.0 && ratio == 0.0;
        }
        let spread = if plan.delta > 0.0 {
            err / plan.delta
        } else {
            0.0
        };
        let slack = 1e-9 * spread.max(1.0 / plan.worst_sin).max(1.0);
        band.0 <= ratio * (1.0 - slack) && ratio * (1.0 + slack) <= band.1
    }
}
