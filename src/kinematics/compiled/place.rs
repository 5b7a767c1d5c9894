//! The position steps of a compiled [`Program`]: a point of a link and a
//! link's posing segment with their constants worked out at load, the
//! closed form of each kind of dyad (RRR, RRP, RPR) with its lengths and
//! angles, the [`Place`] step list, and [`Program`]'s running of it. What
//! a plain closed form cannot place (a tangency, PRP and RPP, a cylinder's
//! dyad) goes to the interpreted solver, so the numbers and the errors are
//! those of [`crate::kinematics::positions`].

use crate::accuracy::ACCURACY;
use crate::geom::{Line, Pose, circle_circle, circle_line};
use crate::kinematics::positions::{self, Configuration, pair_of, point_of};
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Chained, DyadKind};
use kurbo::{Point, Vec2};

/// The angle and the length of a constant local segment (the one a link
/// is posed by): `atan2` and `hypot` done once.
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment {
    pub(super) v: Vec2,
    pub(super) angle: f64,
    pub(super) len: f64,
}

impl Segment {
    pub(super) fn new(v: Vec2) -> Segment {
        Segment {
            v,
            angle: v.atan2(),
            len: v.hypot(),
        }
    }
    /// The pose that puts local point `lp` at `at_p` and turns this
    /// segment (from `lp`) onto `at_q − at_p`: the interpreted
    /// `set_by_two_local` with its constant half done.
    #[inline(always)]
    pub(super) fn pose(&self, lp: Vec2, at_p: Point, at_q: Point) -> Pose {
        let (w, l) = (at_q - at_p, self.v);
        let angle = w.atan2() - self.angle;
        let norm = w.hypot() * self.len;
        let turn = (l.dot(w) / norm, l.cross(w) / norm);
        Pose::through_turned(at_p, lp, angle, turn)
    }
}

/// A point of a link: the link and the point's local coordinates on it.
#[derive(Clone, Copy, Debug)]
pub(super) struct On {
    pub(super) link: usize,
    pub(super) local: Vec2,
}

impl On {
    pub(super) fn new(m: &Mechanism, link: usize, p: usize) -> On {
        On {
            link,
            local: m.local(link, p),
        }
    }
    #[inline(always)]
    pub(super) fn world(&self, c: &Configuration) -> Point {
        c.pose(self.link).apply(self.local)
    }
}

/// A class II group RRR: the circles about B (on K1) and D (on K2) meet
/// at C.
#[derive(Clone, Debug)]
pub(super) struct Rrr {
    pub(super) group: usize,
    pub(super) sign: f64,
    pub(super) links: [usize; 2],
    pub(super) b: On,
    pub(super) d: On,
    /// B and C on link 1, D and C on link 2.
    pub(super) b1: Vec2,
    pub(super) d2: Vec2,
    pub(super) seg1: Segment,
    pub(super) seg2: Segment,
}

/// A class II group RRP: the circle about B meets the guide line.
#[derive(Clone, Debug)]
pub(super) struct Rrp {
    pub(super) group: usize,
    pub(super) sign: f64,
    pub(super) links: [usize; 2],
    pub(super) b: On,
    pub(super) b1: Vec2,
    pub(super) seg1: Segment,
    pub(super) r1: f64,
    /// The known link K2 of the guide pair, and whether it is the guide.
    pub(super) k2: usize,
    pub(super) k2_guide: bool,
    pub(super) delta: f64,
    /// The point of K2 the line is drawn from (the line's point on the
    /// guide, the slider's point on the slider) and the offset of C from
    /// the other's in link 2 (turned by link 2's angle).
    pub(super) anchor: Vec2,
    pub(super) offset: Vec2,
    pub(super) line_dir: Vec2,
    /// C on link 2.
    pub(super) c2: Vec2,
}

/// A class II group RPR: the rocking guide's angle in closed form.
#[derive(Clone, Debug)]
pub(super) struct Rpr {
    pub(super) group: usize,
    pub(super) sign: f64,
    pub(super) guide: usize,
    pub(super) slider: usize,
    /// The guide's and the slider's pins on their known links, and on
    /// the guide and the slider.
    pub(super) jg: On,
    pub(super) js: On,
    pub(super) jg_local: Vec2,
    pub(super) js_local: Vec2,
    pub(super) h: f64,
    pub(super) alpha: f64,
    pub(super) delta: f64,
}

impl Rrr {
    /// Place the group by its plain closed form; `false` where it cannot
    /// (the interpreted form decides).
    #[inline(always)]
    pub(super) fn place(&self, c: &mut Configuration) -> bool {
        let (b, dd) = (self.b.world(c), self.d.world(c));
        match circle_circle(b, self.seg1.len, dd, self.seg2.len, self.sign, -1.0) {
            Some(x) => {
                c.poses[self.links[0]] = Some(self.seg1.pose(self.b1, b, x));
                c.poses[self.links[1]] = Some(self.seg2.pose(self.d2, dd, x));
                true
            }
            None => false,
        }
    }
}

impl Rrp {
    /// Place the group by its plain closed form; `false` where it cannot.
    #[inline(always)]
    pub(super) fn place(&self, c: &mut Configuration) -> bool {
        let b = self.b.world(c);
        let kp = c.pose(self.k2);
        let th2 = if self.k2_guide {
            kp.angle + self.delta
        } else {
            kp.angle - self.delta
        };
        let (sin, cos) = th2.sin_cos();
        let rot = |v: Vec2| Vec2::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y);
        let line = if self.k2_guide {
            Line {
                point: kp.apply(self.anchor) + rot(self.offset),
                dir: kp.dir(self.line_dir),
            }
        } else {
            Line {
                point: kp.apply(self.anchor) + rot(self.offset),
                dir: rot(self.line_dir),
            }
        };
        match circle_line(b, self.r1, &line, self.sign, -1.0) {
            Some(x) => {
                c.poses[self.links[0]] = Some(self.seg1.pose(self.b1, b, x));
                c.poses[self.links[1]] = Some(Pose::through_turned(x, self.c2, th2, (cos, sin)));
                true
            }
            None => false,
        }
    }
}

impl Rpr {
    /// Place the group by its plain closed form; `false` where it cannot.
    #[inline(always)]
    pub(super) fn place(&self, c: &mut Configuration) -> bool {
        let (jg, js) = (self.jg.world(c), self.js.world(c));
        let w = js - jg;
        let dist = w.hypot();
        let sn = self.h / dist;
        // Above a bound of the tolerance the interpreted form
        // judges by (its rounding of the group's numbers),
        // clear of every failure it tests.
        let bound = 2.0
            * ACCURACY.tangency_roundings
            * f64::EPSILON
            * (self.h.abs() + jg.x.abs() + jg.y.abs() + js.x.abs() + js.y.abs());
        if sn.is_finite() && self.h.abs() - dist <= 0.0 && dist > bound {
            let sn = sn.clamp(-1.0, 1.0);
            let gamma_minus_beta = sn.atan2(self.sign * (1.0 - sn * sn).max(0.0).sqrt());
            let psi = w.atan2() - gamma_minus_beta - self.alpha;
            c.poses[self.guide] = Some(Pose::through(jg, self.jg_local, psi));
            c.poses[self.slider] = Some(Pose::through(js, self.js_local, psi + self.delta));
            true
        } else {
            false
        }
    }
}

/// One step of the positions.
#[derive(Clone, Debug)]
pub(super) enum Place {
    /// A crank about its pivot: its pose through the pivot at `at`
    /// (`local` on the crank), turned by the input angle less `offset`.
    Crank {
        input: usize,
        link: usize,
        at: Point,
        local: Vec2,
        offset: f64,
    },
    /// A slider on a guide of the frame: its point at `q0 + dir·s`, its
    /// angle `delta` (cosine and sine `turn`).
    Slider {
        input: usize,
        link: usize,
        q0: Point,
        dir: Vec2,
        local: Vec2,
        delta: f64,
        turn: (f64, f64),
    },
    /// A driving slider on a moving guide: its pair places its link
    /// from the known one.
    Chained(Chained),
    Rrr(Box<Rrr>),
    Rrp(Box<Rrp>),
    Rpr(Box<Rpr>),
    /// Any other dyad (PRP, RPP, a cylinder's): the interpreted closed form.
    Dyad {
        group: usize,
    },
    /// A class III group: Newton from its tracked pose.
    Triad {
        group: usize,
    },
}

/// The step that places dyad `gi`: its kind's closed form with its
/// constants, or the interpreted one (PRP, RPP, a cylinder's).
pub(super) fn dyad_place(
    m: &Mechanism,
    gi: usize,
    d: &crate::model::structure::Dyad,
    sign: f64,
) -> Place {
    if d.cylinder.is_some() {
        return Place::Dyad { group: gi };
    }
    let [l1, l2] = d.links;
    match d.kind {
        DyadKind::Rrr => {
            let (pb, pc, pd) = positions::rrr_points(d);
            let (b1, c1) = (m.local(l1, pb), m.local(d.mid.from, pc));
            let (d2, c2) = (m.local(l2, pd), m.local(d.mid.to, pc));
            Place::Rrr(Box::new(Rrr {
                group: gi,
                sign,
                links: d.links,
                b: On::new(m, d.ext1.from, pb),
                d: On::new(m, d.ext2.to, pd),
                b1,
                d2,
                seg1: Segment::new(c1 - b1),
                seg2: Segment::new(c2 - d2),
            }))
        }
        DyadKind::Rrp => {
            let (pb, pc) = (point_of(d.ext1.joint), point_of(d.mid.joint));
            let k = pair_of(d.ext2.joint);
            let k2 = d.ext2.to;
            let pr = &m.prismatics[k];
            let x = m.local(l2, pc);
            let k2_guide = pr.guide == k2;
            let (anchor, offset) = if k2_guide {
                (pr.line_point, x - pr.slider_local)
            } else {
                (pr.slider_local, x - pr.line_point)
            };
            let (b1, c1) = (m.local(l1, pb), m.local(d.mid.from, pc));
            Place::Rrp(Box::new(Rrp {
                group: gi,
                sign,
                links: d.links,
                b: On::new(m, d.ext1.from, pb),
                b1,
                seg1: Segment::new(c1 - b1),
                r1: (c1 - b1).hypot(),
                k2,
                k2_guide,
                delta: pr.delta,
                anchor,
                offset,
                line_dir: pr.line_dir,
                c2: x,
            }))
        }
        DyadKind::Rpr => {
            let rg = positions::rocking_guide(m, d);
            let pin = |p: usize| {
                if p == point_of(d.ext1.joint) {
                    On::new(m, d.ext1.from, p)
                } else {
                    On::new(m, d.ext2.to, p)
                }
            };
            Place::Rpr(Box::new(Rpr {
                group: gi,
                sign,
                guide: rg.guide,
                slider: rg.slider,
                jg: pin(rg.pin_guide),
                js: pin(rg.pin_slider),
                jg_local: m.local(rg.guide, rg.pin_guide),
                js_local: m.local(rg.slider, rg.pin_slider),
                h: rg.h,
                alpha: rg.alpha,
                delta: rg.delta,
            }))
        }
        DyadKind::Prp | DyadKind::Rpp => Place::Dyad { group: gi },
    }
}
