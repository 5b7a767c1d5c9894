//! What acts on the links while their force plans are drawn: a force
//! known on a link, the forces and moment of a set of links, a reaction
//! recorded in the mechanism's conventions, the scale a plan is drawn at.

use super::plan::{Force, ForcePlans};
use crate::kinetostatics::newton_euler::guide_frame;
use crate::kinematics::solve::{Analysis, Position};
use crate::model::structure::Joint;
use kurbo::{Point, Vec2};

/// A force known on a link: a load, or a reaction found (of a later group
/// on this link).
#[derive(Clone, Copy, Debug)]
pub(super) struct Applied {
    pub link: usize,
    pub at: Point,
    pub f: Vec2,
    pub couple: f64,
    pub force: Force,
}

impl Applied {
    pub(super) fn moment_about(&self, p: Point) -> f64 {
        (self.at - p).cross(self.f) + self.couple
    }
}

/// What acts on a set of links: its forces (the polygon's vectors, in
/// order) and its moment about any point.
pub(super) struct Side<'a> {
    pub links: Vec<usize>,
    pub known: &'a [Applied],
}

impl Side<'_> {
    pub(super) fn has(&self, l: usize) -> bool {
        self.links.contains(&l)
    }
    pub(super) fn forces(&self) -> impl Iterator<Item = &Applied> {
        self.known.iter().filter(|a| self.has(a.link))
    }
    pub(super) fn sum(&self) -> Vec2 {
        self.forces().fold(Vec2::ZERO, |s, a| s + a.f)
    }
    pub(super) fn moment_about(&self, p: Point) -> f64 {
        self.forces().map(|a| a.moment_about(p)).sum()
    }
}

/// The scale a plan is drawn at, from its points at unit scale.
pub(super) type ScaleOf<'a> = &'a dyn Fn(&[Vec2]) -> f64;

/// Record the reaction `r` (with couple `c`) of link `from` on link `to`
/// in pair `joint` in the mechanism's conventions.
#[allow(clippy::too_many_arguments)]
pub(super) fn record(
    (an, s): (&Analysis, &Position),
    out: &mut ForcePlans,
    joint: Joint,
    from: usize,
    to: usize,
    r: Vec2,
    c: f64,
) {
    let m = &an.mech;
    match joint {
        Joint::R(p) => {
            if let Some(k) = m
                .revolutes
                .iter()
                .position(|rv| rv.point == p && (rv.a, rv.b) == (from, to))
            {
                out.revolute[k] = Some(r);
            } else if let Some(k) = m
                .revolutes
                .iter()
                .position(|rv| rv.point == p && (rv.a, rv.b) == (to, from))
            {
                out.revolute[k] = Some(-r);
            }
        }
        Joint::P(k) => {
            // The guide's force on the slider, along the guide's left normal.
            let (_, _, n) = guide_frame(an, s, k);
            let (r, c) = if m.prismatics[k].slider == to {
                (r, c)
            } else {
                (-r, -c)
            };
            out.prismatic[k] = Some((r.dot(n), c));
        }
    }
}
