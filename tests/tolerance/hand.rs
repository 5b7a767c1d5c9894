//! The student's hand on paper: every operation of the method as a
//! draftsman makes it, with the errors of a pencil of precision δ — a
//! vector laid off ends within δ of where it should, a line is drawn
//! shifted by up to δ, a compass is set within δ of the radius it should
//! have, a segment is measured within δ, a point is read off the sheet
//! within δ and its coordinates typed rounded to their digits. Written
//! from the method alone (lecture 000, "Метод планів швидкостей та
//! прискорень"); nothing here calls mechplan's construction kernel.

use super::DELTA;
use kurbo::{Point, Vec2};
use mechplan::construction::PointId;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// `k × v`: `v` turned by +90°.
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// Which kind of step drew a point (the rows of the table the test prints).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// The crank's point laid off from the pole (or from its normal's end).
    Crank,
    /// A normal component ω²·l laid off with the ω the student read and
    /// stated (the judge takes the digits written).
    Normal,
    /// The same, ω not stated (the judge takes its own velocity plan's).
    NormalFromPlan,
    /// A Coriolis acceleration 2·ω·v_rel laid off, ω stated.
    Coriolis,
    /// The same, ω not stated.
    CoriolisFromPlan,
    /// A point where two lines meet.
    Lines,
    /// A similar figure by two arcs meeting at 30° or more.
    Arcs,
    /// A similar figure by two arcs meeting at a glancing angle (under
    /// 30°: a triangle with more than 150° at the new point).
    ArcsGlancing,
    /// A proportional division of a segment.
    Division,
    /// The relative vector of a link's rates from one known point.
    Relation,
    /// A point coinciding with another (the frame's, a translating link's).
    Coincide,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Crank => "lay off: the crank's v_A, a_A",
            Kind::Normal => "lay off: a normal ω²·l, ω stated",
            Kind::NormalFromPlan => "lay off: a normal ω²·l, ω off the plan",
            Kind::Coriolis => "lay off: Coriolis 2·ω·v_rel, ω stated",
            Kind::CoriolisFromPlan => "lay off: Coriolis 2·ω·v_rel, ω off plan",
            Kind::Lines => "two lines meeting",
            Kind::Arcs => "a similar figure, arcs at ≥ 30°",
            Kind::ArcsGlancing => "a similar figure, arcs at 10–20°",
            Kind::Division => "a proportional division",
            Kind::Relation => "relative vector ω×AX, −ω²·AX+ε×AX",
            Kind::Coincide => "coinciding (frame, translating link)",
        }
    }
}

/// The errors of one draw: uniform in a disc of radius δ (a point) or in
/// [−δ, δ] (a line's shift, a radius, a measured length); or, in a draw
/// at the corners, each at its extreme: every point's error δ along one
/// direction of the draw, either way, every scalar ±δ — the draws where
/// the errors add up to the worst case.
pub struct Hand {
    rng: StdRng,
    pub corner: bool,
    dir: Vec2,
}

impl Hand {
    pub fn new(seed: u64) -> Hand {
        Hand {
            rng: StdRng::seed_from_u64(seed),
            corner: false,
            dir: Vec2::new(1.0, 0.0),
        }
    }
    /// A new draw, at the corners or not.
    pub fn start(&mut self, corner: bool) {
        self.corner = corner;
        let a: f64 = self.rng.random_range(0.0..std::f64::consts::TAU);
        self.dir = Vec2::new(a.cos(), a.sin());
    }
    /// A number in [−1, 1] (±1 at the corners: a hair inside, so that
    /// the sum of errors at the worst case is not beyond it by the
    /// rounding of floating point).
    pub fn unit(&mut self) -> f64 {
        if self.corner {
            let one = 1.0 - 1e-9;
            if self.rng.random_bool(0.5) { one } else { -one }
        } else {
            self.rng.random_range(-1.0..=1.0)
        }
    }
    /// A displacement within δ.
    pub fn point(&mut self) -> Vec2 {
        if self.corner {
            return self.dir * (self.unit() * DELTA);
        }
        loop {
            let v = Vec2::new(
                self.rng.random_range(-1.0..=1.0),
                self.rng.random_range(-1.0..=1.0),
            );
            if v.hypot2() <= 1.0 {
                return v * DELTA;
            }
        }
    }
    /// A scalar within δ.
    pub fn scalar(&mut self) -> f64 {
        self.unit() * DELTA
    }
    pub fn chance(&mut self, p: f64) -> bool {
        self.rng.random_bool(p)
    }
}

/// A point handed in.
#[derive(Clone, Copy, Debug)]
pub struct Handed {
    pub id: PointId,
    pub typed: Vec2,
    pub kind: Kind,
    pub route: Option<Route>,
}

/// The construction a point of a link was drawn by, as the judge should
/// find it among its routes.
#[derive(Clone, Copy, Debug)]
pub enum Route {
    /// The figure on the plan points `a`, `b` (`None`: the pole), the
    /// point at a + ρ·(b − a), ρ complex: where the judge has them (the
    /// typed points, or its own prediction of those not handed in).
    Figure(Option<PointId>, Option<PointId>, Vec2),
    /// The relative vector from a typed point, with the rates the judge
    /// reads off the typed points: its place; and its place without the
    /// rate (where the plan does not show the rate's sense).
    Relation(Vec2, Vec2),
}

/// Which of the points drawn a student hands in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Handing {
    /// Every point, the construction points (n, k, b₃ …) too.
    All,
    /// The named points (b, s2 …) only.
    Named,
    /// The named points but those where two lines meet: the judge then
    /// places the later points from where those lines meet, with its
    /// error radius.
    NoMeetings,
}

/// A line drawn on the sheet: a point on it and its unit direction.
#[derive(Clone, Copy)]
pub struct Line(pub Vec2, pub Vec2);

/// A student's sheet at scale μ: the operations of the method on the
/// points where they are on paper, the points handed in (read off and
/// typed to `q` mm: 0 exact), with the kind of step that drew each.
pub struct Sheet<'h> {
    pub mu: f64,
    pub q: f64,
    pub hand: &'h mut Hand,
    /// Handed in: the point, where it was typed, the kind of its step,
    /// and the route the judge should take it by.
    pub handed: Vec<Handed>,
    /// Which points are handed in.
    pub handing: Handing,
}

impl Sheet<'_> {
    /// Lay off the real vector `v` from `from`: its end, within δ.
    pub fn lay(&mut self, from: Vec2, v: Vec2) -> Vec2 {
        from + v / self.mu + self.hand.point()
    }
    /// A line through `through` in direction `dir`, drawn shifted by up
    /// to δ.
    pub fn line(&mut self, through: Vec2, dir: Vec2) -> Line {
        let u = dir.normalize();
        Line(through + perp(u) * self.hand.scalar(), u)
    }
    /// Where two lines drawn meet.
    pub fn meet(&self, a: Line, b: Line) -> Vec2 {
        let t = (b.0 - a.0).cross(b.1) / a.1.cross(b.1);
        a.0 + a.1 * t
    }
    /// The figure similar to the link's A B X on the sheet's `a`, `b`
    /// (the same order of letters) by two arcs: about a with the radius
    /// ab·AX/AB, about b with ab·BX/AB, each compass set within δ, the
    /// crossing on X's side of ab. Where the arcs so drawn do not meet,
    /// the student marks the point halfway across the gap between them.
    pub fn arcs(&mut self, (a, la): (Vec2, Point), (b, lb): (Vec2, Point), lx: Point) -> Vec2 {
        let k = (b - a).hypot() / (lb - la).hypot();
        let ra = (lx - la).hypot() * k + self.hand.scalar();
        let rb = (lx - lb).hypot() * k + self.hand.scalar();
        let side = (lb - la).cross(lx - la).signum();
        let d = (b - a).hypot();
        let u = (b - a) / d;
        if ra + rb < d {
            return a + u * (0.5 * (ra + d - rb));
        }
        let x = (d * d + ra * ra - rb * rb) / (2.0 * d);
        let h = (ra * ra - x * x).max(0.0).sqrt();
        a + u * x + perp(u) * (side * h)
    }
    /// The point dividing `a b` at `t` (a + t·(b − a)), marked within δ.
    pub fn divide(&mut self, a: Vec2, b: Vec2, t: f64) -> Vec2 {
        a + (b - a) * t + self.hand.point()
    }
    /// The rate (ω or ε) of a link read off the relative segment `from`
    /// → `to` of its points J → X: the segment measured within δ, over
    /// the link's length, its sense from the side of JX the segment turns.
    pub fn rate(&mut self, from: Vec2, to: Vec2, (j, x): (Point, Point)) -> f64 {
        let (r, rel) = (x - j, to - from);
        r.cross(rel).signum() * (rel.hypot() + self.hand.scalar()) * self.mu / r.hypot()
    }
    /// A length along `u` read off the sheet (`from` → `to`), within δ,
    /// with its sign: a relative sliding velocity.
    pub fn along(&mut self, from: Vec2, to: Vec2, u: Vec2) -> f64 {
        let s = (to - from).dot(u);
        s.signum() * ((to - from).hypot() + self.hand.scalar()) * self.mu
    }
    /// Hand in point `id` drawn at `at`: read off within δ and typed.
    pub fn hand_in(&mut self, id: PointId, at: Vec2, kind: Kind, construction: bool) {
        if (construction && self.handing != Handing::All)
            || (kind == Kind::Lines && self.handing == Handing::NoMeetings)
        {
            return;
        }
        let read = at + self.hand.point();
        let typed = if self.q > 0.0 {
            Vec2::new(
                (read.x / self.q).round() * self.q,
                (read.y / self.q).round() * self.q,
            )
        } else {
            read
        };
        self.handed.push(Handed {
            id,
            typed,
            kind,
            route: None,
        });
    }
    /// How far coordinates typed to `q` may be from what was read.
    pub fn rounding(&self) -> f64 {
        if self.q > 0.0 {
            (0.5 * self.q).hypot(0.5 * self.q)
        } else {
            0.0
        }
    }
    /// Where point `id` was typed, if handed in.
    pub fn typed(&self, id: PointId) -> Option<Vec2> {
        self.handed.iter().find(|h| h.id == id).map(|h| h.typed)
    }
}

/// A value as a student writes it, to three significant digits, and the
/// rounding of what is written (half a unit of its last digit).
pub fn three_digits(w: f64) -> (f64, f64) {
    if w == 0.0 {
        return (0.0, 5e-4);
    }
    let digits = 10f64.powi(2 - w.abs().log10().floor() as i32);
    ((w * digits).round() / digits, 0.5 / digits)
}
