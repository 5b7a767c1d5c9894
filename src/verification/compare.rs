//! Two answers at one position compared as the cross-check and the data
//! check measure them: places over the sketch's size, angles in radians,
//! velocities and ω·size over the largest of them, accelerations and
//! ε·size likewise; the largest relative difference, and what it belongs
//! to. One side (route (a)'s answer, or one run of its transfer
//! functions) is compared with several others at a position (route (b)'s,
//! each changed scene's): its places, rates and scales are made once
//! ([`Mine`]) and the item that differs most is named only when asked.

use super::worst::{Quantity, Worst};
use crate::geom::wrap_pi;
use crate::kinematics::analytic::{Motion, Order};
use crate::kinematics::solve::{Analysis, Position};
use crate::model::mechanism::Mechanism;
use kurbo::{Point, Vec2};
use smallvec::SmallVec;

/// What a compared number belongs to: a point or a link.
#[derive(Clone, Copy, Debug)]
pub(super) enum Item {
    Point(usize),
    Link(usize),
}

/// The item that differs most, with its kind (`None`: nothing differs).
pub(super) type Most = Option<(Quantity, Item)>;

/// One side of the comparisons at a position: the motions of `s`
/// compared (its real rates, or one run of its transfer functions), each
/// compared point's place and its velocity and acceleration there, and
/// the scales of velocities and accelerations.
pub(super) struct Mine<'a> {
    s: &'a Position,
    motion: &'a [Option<Motion>],
    /// (point, the link carrying it, its place, its velocity and
    /// acceleration), in the analysis's order of points.
    points: SmallVec<[Compared; 8]>,
    sv: f64,
    sa: f64,
}

/// A compared point of one side: (the point, the link carrying it, its
/// place, its velocity and acceleration).
type Compared = (usize, usize, Point, (Vec2, Vec2));

impl<'a> Mine<'a> {
    /// The position compared.
    pub(super) fn position(&self) -> &'a Position {
        self.s
    }
}

/// A point's velocity and acceleration on link `l` of `mo`, at `at`.
fn rates_at(mo: &[Option<Motion>], l: usize, at: Point) -> (Vec2, Vec2) {
    let k = mo[l].expect("a compared link is solved");
    (k.velocity(at), k.acceleration(at))
}

impl Analysis {
    /// The side `motion` of `s` made ready for comparisons ([`Mine`]).
    pub(super) fn mine<'a>(&self, s: &'a Position, motion: &'a [Option<Motion>]) -> Mine<'a> {
        let m = &self.mech;
        let points: SmallVec<[Compared; 8]> = self
            .points
            .iter()
            .map(|&p| {
                let l = self.carrier(p);
                let at = s.config.point(m, l, p);
                let rates = match self.order {
                    Some(_) => rates_at(motion, l, at),
                    None => (Vec2::ZERO, Vec2::ZERO),
                };
                (p, l, at, rates)
            })
            .collect();
        // Velocities and angular velocities share a scale (ω·size), as do
        // accelerations and angular accelerations (ε·size).
        let (mut sv, mut sa) = (f64::MIN_POSITIVE, f64::MIN_POSITIVE);
        if self.order.is_some() {
            for (_, _, _, (va, aa)) in &points {
                sv = sv.max(va.hypot());
                sa = sa.max(aa.hypot());
            }
            for l in (0..m.links.len()).filter(|&l| self.link(l)) {
                let ma = motion[l].expect("a compared link is solved");
                sv = sv.max(ma.omega.abs() * m.size);
                sa = sa.max(ma.epsilon.abs() * m.size);
            }
        }
        Mine {
            s,
            motion,
            points,
            sv,
            sa,
        }
    }

    /// The largest relative difference between `mine` and the motions
    /// `other` of mechanism `om` (the same links and points, its own
    /// shapes: a scene with its data changed), and what it belongs to.
    pub(super) fn compare_most(
        &self,
        mine: &Mine,
        other: &[Option<Motion>],
        om: &Mechanism,
    ) -> (f64, Most) {
        let m = &self.mech;
        let mut worst = (0.0f64, None);
        let mut note = |d: f64, kind: Quantity, what: Item| {
            if d > worst.0 || d.is_nan() {
                worst = (d, Some((kind, what)));
            }
        };
        // The other side's place of every compared point, its velocity and
        // acceleration there (where the analysis has them), once.
        let order = self.order;
        let others: SmallVec<[(Point, Vec2, Vec2); 8]> = mine
            .points
            .iter()
            .map(|&(p, l, _, _)| {
                let at = other[l].unwrap().pose.apply(om.local(l, p));
                let (v, a) = match order {
                    Some(_) => rates_at(other, l, at),
                    None => (Vec2::ZERO, Vec2::ZERO),
                };
                (at, v, a)
            })
            .collect();
        let links = || (0..m.links.len()).filter(|&l| self.link(l));
        for (&(p, _, at, _), &(at_b, _, _)) in mine.points.iter().zip(&others) {
            note((at - at_b).hypot() / m.size, Quantity::Position, Item::Point(p));
        }
        for l in links() {
            let d = wrap_pi(mine.s.config.pose(l).angle - other[l].unwrap().pose.angle).abs();
            note(d, Quantity::Angle, Item::Link(l));
        }
        let Some(order) = order else {
            return worst;
        };
        let acc = order == Order::Acceleration;
        let (sv, sa) = (mine.sv, mine.sa);
        // In the order the names were always reported in (ties keep the
        // first): v, ω, then a, ε.
        for (&(p, _, _, (va, _)), &(_, vb, _)) in mine.points.iter().zip(&others) {
            note((va - vb).hypot() / sv, Quantity::Velocity, Item::Point(p));
        }
        for l in links() {
            let (ma, mb) = (mine.motion[l].unwrap(), other[l].unwrap());
            note((ma.omega - mb.omega).abs() * m.size / sv, Quantity::Omega, Item::Link(l));
        }
        if acc {
            for (&(p, _, _, (_, aa)), &(_, _, ab)) in mine.points.iter().zip(&others) {
                note((aa - ab).hypot() / sa, Quantity::Acceleration, Item::Point(p));
            }
            for l in links() {
                let (ma, mb) = (mine.motion[l].unwrap(), other[l].unwrap());
                let d = (ma.epsilon - mb.epsilon).abs() * m.size / sa;
                note(d, Quantity::Epsilon, Item::Link(l));
            }
        }
        worst
    }

    /// The item `most` by its name.
    pub(super) fn named(&self, most: Most) -> Worst {
        let m = &self.mech;
        match most {
            None => Worst::default(),
            Some((kind, Item::Point(p))) => Worst::of(kind, m.point_name(p)),
            Some((kind, Item::Link(l))) => Worst::of(kind, m.link_id(l)),
        }
    }

    /// [`Analysis::compare_most`] of `mine` of `s` made for this one
    /// comparison, the item named.
    pub(super) fn compare_with(
        &self,
        s: &Position,
        mine: &[Option<Motion>],
        other: &[Option<Motion>],
        om: &Mechanism,
    ) -> (f64, Worst) {
        let (d, most) = self.compare_most(&self.mine(s, mine), other, om);
        (d, self.named(most))
    }
}
