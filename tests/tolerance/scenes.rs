//! The constructions the student draws, scene by scene, as the lecture
//! draws them: the crank's point from ω1 (and ε1), each group's point
//! where its two lines meet, the other points of a link by the similar
//! figure (two arcs, or a division of a segment for a point on the line
//! of two others) or by the relative vector of the link's rates from one
//! known point, the points of the frame at the pole and of a translating
//! link at one plan point. The places of the mechanism's points and the
//! guides' directions are the solved position's (`student::rigid`); every
//! value laid off is the data's or one the student read off their own
//! velocity plan.

use super::hand::{Kind, Line, Sheet, perp};
use crate::student::rigid::{Input, Model};
use kurbo::{Point, Vec2};
use mechplan::Analysis;
use mechplan::construction::PointId;

/// How the student places a point of a link with two known points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum How {
    /// The similar figure: two arcs, or a division for a point on the
    /// line of the two.
    Figure,
    /// The relative vector of the link's rates from the first known point.
    Relation,
}

/// A scene at one position: the model of the method, the names' indices.
pub struct Ctx<'a> {
    pub an: &'a Analysis,
    pub m: Model,
}

/// What a student's velocity plan gives the acceleration plan: the ω of
/// each link read off it, the relative sliding velocities.
#[derive(Clone, Debug, Default)]
pub struct Read {
    pub omega: Vec<(usize, f64)>,
    pub slide: Vec<(&'static str, f64)>,
}

/// The values an acceleration plan is drawn with: the ω the student
/// computes with, the ω the judge takes (as stated, or its own velocity
/// plan's), the sliding velocities read.
pub struct Values {
    pub student: Vec<(usize, f64)>,
    pub judge: Vec<(usize, f64)>,
    pub slide: Vec<(&'static str, f64)>,
}

impl Values {
    pub fn w(&self, link: usize) -> f64 {
        self.student
            .iter()
            .find(|x| x.0 == link)
            .map_or(0.0, |x| x.1)
    }
    pub fn judge_w(&self, link: usize) -> f64 {
        self.judge.iter().find(|x| x.0 == link).map_or(0.0, |x| x.1)
    }
    pub fn slide(&self, name: &str) -> f64 {
        self.slide.iter().find(|x| x.0 == name).map_or(0.0, |x| x.1)
    }
}

impl Ctx<'_> {
    pub fn p(&self, name: &str) -> Point {
        self.m.at[self
            .m
            .names
            .iter()
            .position(|n| n == name)
            .expect("a point")]
    }
    pub fn link(&self, id: &str) -> usize {
        self.an.mech.scene.link_index(id).expect("a link")
    }
    pub fn named(&self, name: &str) -> PointId {
        PointId::Named(self.an.mech.scene.point_index(name).expect("a point"))
    }
    pub fn on(&self, name: &str, link: &str) -> PointId {
        PointId::Coincident {
            point: self.an.mech.scene.point_index(name).expect("a point"),
            link: self.link(link),
        }
    }
    pub fn normal(&self, link: &str) -> PointId {
        PointId::Normal {
            link: self.link(link),
        }
    }
    pub fn coriolis(&self, link: &str) -> PointId {
        PointId::Coriolis {
            link: self.link(link),
        }
    }
    /// The crank's ω1 and ε1.
    pub fn crank(&self) -> (f64, f64) {
        self.m
            .inputs
            .iter()
            .find_map(|i| match i {
                Input::Crank { omega, epsilon, .. } => Some((*omega, *epsilon)),
                Input::Slide { .. } => None,
            })
            .expect("a crank")
    }
    /// The guide's direction of the pair at `point`.
    pub fn guide(&self, point: &str) -> Vec2 {
        let p = self
            .m
            .names
            .iter()
            .position(|n| n == point)
            .expect("a point");
        self.m
            .pairs
            .iter()
            .find(|q| q.point == p)
            .expect("a pair")
            .u
    }
    /// The guide's direction of the pair of `slider` on `guide`.
    pub fn guide_of(&self, slider: &str, guide: &str) -> Vec2 {
        let (s, g) = (self.link(slider), self.link(guide));
        self.m
            .pairs
            .iter()
            .find(|q| q.slider == s && q.guide == g)
            .expect("a pair")
            .u
    }

    /// The crank's point O A: v_A = ω1 × OA from the pole; a_A = −ω1²·OA
    /// (and + ε1 × OA from the normal's end n1).
    pub fn crank_point(&self, sh: &mut Sheet, (o, a): (&str, &str), link: &str, vel: bool) -> Vec2 {
        let (w1, e1) = self.crank();
        let r = self.p(a) - self.p(o);
        if vel {
            let at = sh.lay(Vec2::ZERO, perp(r) * w1);
            sh.hand_in(self.named(a), at, Kind::Crank, false);
            return at;
        }
        let n = sh.lay(Vec2::ZERO, -r * (w1 * w1));
        if e1 == 0.0 {
            sh.hand_in(self.named(a), n, Kind::Crank, false);
            return n;
        }
        sh.hand_in(self.normal(link), n, Kind::Crank, true);
        let at = sh.lay(n, perp(r) * e1);
        sh.hand_in(self.named(a), at, Kind::Crank, false);
        at
    }

    /// The line of X from J of a rigid link: ⊥ JX through j; on an
    /// acceleration plan through the end of the normal ω²·JX laid off from
    /// j toward J (handed in as the link's n). Returns the line and where
    /// it starts (j, or n).
    pub fn rigid(
        &self,
        sh: &mut Sheet,
        (j, jn): (Vec2, &str),
        xn: &str,
        rate: Option<(f64, &str)>,
    ) -> (Line, Vec2) {
        let r = self.p(xn) - self.p(jn);
        let from = match rate {
            Some((w, link)) if w != 0.0 => {
                let n = sh.lay(j, -r * (w * w));
                sh.hand_in(self.normal(link), n, Kind::Normal, true);
                n
            }
            _ => j,
        };
        (sh.line(from, perp(r)), from)
    }

    /// A point X of a link with known points `a` (of A) and `b` (of B),
    /// drawn as `how` says: the figure (two arcs, or a division where X
    /// is on the line AB), or the relative vector of the link's rates
    /// from a: ω×AX (velocities: `rates` = (ω, 0), `omega` None), or
    /// −ω²·AX + ε×AX (accelerations: `omega` the ω computed with). The
    /// point, and the kind of its step.
    pub fn point_of(
        &self,
        sh: &mut Sheet,
        how: How,
        (a, an): (Vec2, &str),
        (b, bn): (Vec2, &str),
        xn: &str,
        (rate, omega): (f64, Option<f64>),
    ) -> (Vec2, Kind) {
        let (la, lb, lx) = (self.p(an), self.p(bn), self.p(xn));
        let r = lx - la;
        if how == How::Relation {
            let from = match omega {
                Some(w) => sh.lay(a, -r * (w * w)),
                None => a,
            };
            return (sh.lay(from, perp(r) * rate), Kind::Relation);
        }
        let ab = lb - la;
        let t = r.dot(ab) / ab.hypot2();
        if (r.cross(ab) / ab.hypot2()).abs() < 1e-9 {
            return (sh.divide(a, b, t), Kind::Division);
        }
        // The arcs meet at 180° less the triangle's angle at X.
        let (xa, xb) = (la - lx, lb - lx);
        let at_x = xa.cross(xb).abs().atan2(xa.dot(xb)).to_degrees();
        let kind = if 180.0 - at_x < 30.0 {
            Kind::ArcsGlancing
        } else {
            Kind::Arcs
        };
        (sh.arcs((a, la), (b, lb), lx), kind)
    }

    /// Where the relative vector from `a` (typed) puts X with the rates
    /// as read off the typed points: ω×AX, or −ω²·AX + ε×AX — the place
    /// of the step the judge should take this point by.
    pub fn relation_place(
        &self,
        sh: &Sheet,
        (a, an): (Vec2, &str),
        xn: &str,
        (rate, omega): (f64, Option<f64>),
    ) -> Vec2 {
        let r = self.p(xn) - self.p(an);
        let n = omega.map_or(Vec2::ZERO, |w| -r * (w * w));
        a + (n + perp(r) * rate) / sh.mu
    }

    /// The rate read off the typed points `from` → `to` of J → X (no
    /// measuring error: the judge's reading).
    pub fn typed_rate(&self, sh: &Sheet, (from, to): (Vec2, Vec2), (jn, xn): (&str, &str)) -> f64 {
        let (r, rel) = (self.p(xn) - self.p(jn), to - from);
        r.cross(rel).signum() * rel.hypot() * sh.mu / r.hypot()
    }
}
