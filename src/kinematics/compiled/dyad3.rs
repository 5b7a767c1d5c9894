//! A dyad's velocity contour in scalars, for the walk every dyad of the
//! structure takes when no cylinder drives it: the 3×3 matrix, its
//! inverse and the walk written out, with the arithmetic of the general
//! compiled contour ([`super::rates`]) and of nalgebra's 3×3 determinant,
//! inverse and product operation for operation, so the rates are the same
//! to the bit and a plain dyad's rates skip the general loop.

use super::twists::{Contour, PairTwist, Src, Walk};
use crate::accuracy::ACCURACY;
use crate::kinematics::analytic::contour::{self, Twist, bracket};
use crate::kinematics::analytic::{Motion, Order};
use crate::kinematics::positions::Configuration;
use kurbo::Vec2;

/// A dyad's contour in scalars: no driven pair, and the walk every
/// dyad of the structure takes (K1 → L1 → L2, K2 known), so the matrix,
/// its inverse and the walk are written out. The arithmetic is that of
/// [`Contour::run`] (and of nalgebra's 3×3 determinant, inverse and
/// product that it calls), operation for operation.
#[derive(Clone, Debug)]
pub(super) struct Dyad3 {
    pub(super) group: usize,
    pub(super) links: [usize; 2],
    pub(super) ends: [usize; 2],
    pub(super) pairs: [PairTwist; 3],
}

impl Dyad3 {
    /// The scalar form of `g`, when its walk is the plain one.
    pub(super) fn of(g: &Contour<3>) -> Option<Dyad3> {
        let plain = g.driven.is_none()
            && g.n_walk == 2
            && matches!(
                g.walk[0],
                Walk {
                    base: Src::Known(_),
                    j: 0,
                    forward: true
                }
            )
            && matches!(
                g.walk[1],
                Walk {
                    base: Src::Found(0),
                    j: 1,
                    forward: true
                }
            )
            && g.drift_from[0] == g.walk[0].base
            && g.drift_from[1] == Src::Found(0)
            && g.drift_from[2] == Src::Found(1)
            && g.ends[0].0 == g.walk[0].base
            && g.n_links == 2;
        let (Src::Known(k1), Src::Known(k2)) = g.ends[0] else {
            return None;
        };
        let link = |s: Src| g.links[..2].iter().find(|e| e.1 == s).map(|e| e.0);
        let (Some(l1), Some(l2)) = (link(Src::Found(0)), link(Src::Found(1))) else {
            return None;
        };
        (plain && l1 == g.o_link).then(|| Dyad3 {
            group: g.group,
            links: [l1, l2],
            ends: [g.known[k1], g.known[k2]],
            pairs: g.pairs,
        })
    }

    /// The group's rates, written to `out`; `None` when its velocity
    /// contour is singular.
    #[inline]
    pub(super) fn run(
        &self,
        c: &Configuration,
        out: &mut [Option<Motion>],
        order: Order,
    ) -> Option<()> {
        let [l1, l2] = self.links;
        let o = c.pose(l1).origin;
        let [p0, p1, p2] = &self.pairs;
        let (x0, x1, x2) = (p0.twist(c, o), p1.twist(c, o), p2.twist(c, o));
        // The longest arm: the square root is monotone and correctly
        // rounded, so the root of the largest square is the largest root
        // (`Vec2::hypot` is `hypot2().sqrt()`), with one root taken.
        let arm2 = |t: Twist| if t.w != 0.0 { t.v.hypot2() } else { 0.0 };
        let reach = f64::max(f64::max(f64::max(0.0, arm2(x0)), arm2(x1)), arm2(x2)).sqrt();
        let pl = if reach > 0.0 { 1.0 / reach } else { 1.0 };
        // The contour's columns in the group's units, made dimensionless.
        let col = |t: Twist| {
            let a = [t.w, t.v.x * pl, t.v.y * pl];
            let s = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
                .sqrt()
                .max(f64::MIN_POSITIVE);
            let k = 1.0 / s;
            ([a[0] * k, a[1] * k, a[2] * k], s)
        };
        let ([m11, m21, m31], s0) = col(x0);
        let ([m12, m22, m32], s1) = col(x1);
        let ([m13, m23, m33], s2) = col(x2);
        let minor_m12_m23 = m22 * m33 - m32 * m23;
        let minor_m11_m23 = m21 * m33 - m31 * m23;
        let minor_m11_m22 = m21 * m32 - m31 * m22;
        let det = m11 * minor_m12_m23 - m12 * minor_m11_m23 + m13 * minor_m11_m22;
        if det.abs() < ACCURACY.min_contour_determinant || det == 0.0 {
            return None;
        }
        let inv = [
            [
                minor_m12_m23 / det,
                (m13 * m32 - m33 * m12) / det,
                (m12 * m23 - m22 * m13) / det,
            ],
            [
                -minor_m11_m23 / det,
                (m11 * m33 - m31 * m13) / det,
                (m13 * m21 - m23 * m11) / det,
            ],
            [
                minor_m11_m22 / det,
                (m12 * m31 - m32 * m11) / det,
                (m11 * m22 - m21 * m12) / det,
            ],
        ];
        let solve = |t: Twist| {
            let b = [t.w, t.v.x * pl, t.v.y * pl];
            let y = |r: usize| inv[r][0] * b[0] + inv[r][1] * b[1] + inv[r][2] * b[2];
            [y(0) / s0, y(1) / s1, y(2) / s2]
        };
        let [k1, k2] = self.ends;
        let st = |l: usize| contour::state(&out[l].expect("attachment solved first"), o);
        let ((v1, a1), (v2, a2)) = (st(k1), st(k2));
        let qd = solve(v2 - v1);
        let vl1 = v1 + x0 * qd[0];
        let vl2 = vl1 + x1 * qd[1];
        let (al1, al2) = if order == Order::Acceleration {
            let d0 = bracket(v1, x0) * qd[0];
            let d1 = bracket(vl1, x1) * qd[1];
            let d2 = bracket(vl2, x2) * qd[2];
            let r = a2 - a1;
            let r = Twist {
                w: r.w - d0.w - d1.w - d2.w,
                v: Vec2::new(
                    r.v.x - d0.v.x - d1.v.x - d2.v.x,
                    r.v.y - d0.v.y - d1.v.y - d2.v.y,
                ),
            };
            let qdd = solve(r);
            let al1 = a1 + (x0 * qdd[0] + d0);
            (al1, al1 + (x1 * qdd[1] + d1))
        } else {
            (Twist::default(), Twist::default())
        };
        for (l, v, a) in [(l1, vl1, al1), (l2, vl2, al2)] {
            out[l] = Some(contour::twist_motion(c.pose(l), o, v, a));
        }
        Some(())
    }
}
