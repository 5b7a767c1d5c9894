//! Route (b)'s equations written once, generic over the number type: every
//! moving link a pose (x, y, θ); a revolute pair's point coincides on both
//! links (2 rows), a prismatic pair lets no relative rotation and keeps the
//! slider's point on the guide line (2 rows), each driver fixes its input
//! (1 row; the drivers last, in the scene's order of inputs). The residual Φ(q, x), the Jacobian Φ_q and γ of the
//! acceleration equations Φ_q·q̈ = γ are evaluated in `f64` by route (b)
//! ([`super::constraint`]) and in extended precision by the reference
//! ([`crate::verification::reference`]), whose independence is its own
//! positions and its precision, not a copy of the formulas.

use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use smallvec::SmallVec;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// One number a row (a residual, γ): on the stack up to nine rows, the
/// common mechanisms' (the check evaluates them at every position).
pub type Rows<T> = SmallVec<[T; 9]>;

/// Every link's pose: on the stack up to eight links.
pub type Poses<T> = SmallVec<[Pose<T>; 8]>;

/// What the equations need of a number: a field with square root,
/// trigonometry and the exact image of every `f64`.
pub trait Number:
    Clone
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The number equal to `x` (every finite f64 is a dyadic rational).
    fn from_f64(x: f64) -> Self;
    fn zero() -> Self {
        Self::from_f64(0.0)
    }
    fn one() -> Self {
        Self::from_f64(1.0)
    }
    fn sqrt(&self) -> Self;
    fn sin_cos(&self) -> (Self, Self);
    /// atan2(self, x).
    fn atan2(&self, x: &Self) -> Self;
    /// The angle reduced to (−π, π].
    fn wrap_angle(&self) -> Self;
}

impl Number for f64 {
    #[inline]
    fn from_f64(x: f64) -> f64 {
        x
    }
    #[inline]
    fn sqrt(&self) -> f64 {
        f64::sqrt(*self)
    }
    #[inline]
    fn sin_cos(&self) -> (f64, f64) {
        f64::sin_cos(*self)
    }
    #[inline]
    fn atan2(&self, x: &f64) -> f64 {
        f64::atan2(*self, *x)
    }
    #[inline]
    fn wrap_angle(&self) -> f64 {
        crate::geom::wrap_pi(*self)
    }
}

/// A planar vector (a place, a displacement, a rate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector<T> {
    pub x: T,
    pub y: T,
}

impl<T: Number> Vector<T> {
    #[inline]
    pub fn new(x: T, y: T) -> Self {
        Vector { x, y }
    }
    pub fn zero() -> Self {
        Vector::new(T::zero(), T::zero())
    }
    #[inline]
    pub fn add(&self, o: &Self) -> Self {
        Vector::new(self.x.clone() + o.x.clone(), self.y.clone() + o.y.clone())
    }
    #[inline]
    pub fn sub(&self, o: &Self) -> Self {
        Vector::new(self.x.clone() - o.x.clone(), self.y.clone() - o.y.clone())
    }
    #[inline]
    pub fn scale(&self, k: &T) -> Self {
        Vector::new(self.x.clone() * k.clone(), self.y.clone() * k.clone())
    }
    #[inline]
    pub fn neg(&self) -> Self {
        Vector::new(-self.x.clone(), -self.y.clone())
    }
    #[inline]
    pub fn dot(&self, o: &Self) -> T {
        self.x.clone() * o.x.clone() + self.y.clone() * o.y.clone()
    }
    #[inline]
    pub fn cross(&self, o: &Self) -> T {
        self.x.clone() * o.y.clone() - self.y.clone() * o.x.clone()
    }
    /// k × v: turned by +90°.
    #[inline]
    pub fn perp(&self) -> Self {
        Vector::new(-self.y.clone(), self.x.clone())
    }
    pub fn norm(&self) -> T {
        self.dot(self).sqrt()
    }
    pub fn atan2(&self) -> T {
        self.y.atan2(&self.x)
    }
    /// Rotated by the angle whose (sin, cos) are given.
    #[inline]
    pub fn rotate(&self, s: &T, c: &T) -> Self {
        Vector::new(
            c.clone() * self.x.clone() - s.clone() * self.y.clone(),
            s.clone() * self.x.clone() + c.clone() * self.y.clone(),
        )
    }
}

/// A link's pose with the sine and cosine of its angle (computed once):
/// `world(p) = origin + R(angle)·p`.
#[derive(Clone, Debug)]
pub struct Pose<T> {
    pub origin: Vector<T>,
    pub angle: T,
    pub sin: T,
    pub cos: T,
}

impl<T: Number> Pose<T> {
    pub fn new(origin: Vector<T>, angle: T) -> Self {
        let (sin, cos) = angle.sin_cos();
        Pose {
            origin,
            angle,
            sin,
            cos,
        }
    }
    pub fn identity() -> Self {
        Pose {
            origin: Vector::zero(),
            angle: T::zero(),
            sin: T::zero(),
            cos: T::one(),
        }
    }
    /// World direction of a local direction.
    #[inline]
    pub fn dir(&self, local: &Vector<T>) -> Vector<T> {
        local.rotate(&self.sin, &self.cos)
    }
    /// World place of a local point.
    #[inline]
    pub fn apply(&self, local: &Vector<T>) -> Vector<T> {
        self.origin.add(&self.dir(local))
    }
}

/// A slide at the poses of its slider and its guide: the guide's
/// direction `u`, the arms of the slider's point on the slider (`rs`) and
/// of the guide line's point on the guide (`rg`), and `d` = Q − P from the
/// line's point to the slider's.
struct SlideAt<T> {
    u: Vector<T>,
    rs: Vector<T>,
    rg: Vector<T>,
    d: Vector<T>,
}

impl<T: Number> SlideAt<T> {
    /// ḋ, the rate of `d`, from the links' velocities `lin_s`, `lin_g` (of
    /// their frames' origins) and their angular rates `ws`, `wg`.
    fn rate(&self, lin_s: &Vector<T>, lin_g: &Vector<T>, ws: &T, wg: &T) -> Vector<T> {
        lin_s
            .add(&self.rs.perp().scale(ws))
            .sub(&lin_g.add(&self.rg.perp().scale(wg)))
    }
}

/// A prismatic pair in the frames of its links.
#[derive(Clone, Debug)]
pub struct Prism<T> {
    pub slider: usize,
    pub guide: usize,
    /// The slider's point in the slider's frame.
    pub slider_local: Vector<T>,
    /// A point of the guide line and its unit direction, in the guide's frame.
    pub line_point: Vector<T>,
    pub line_dir: Vector<T>,
    /// θ_slider − θ_guide.
    pub delta: T,
}

impl<T: Number> Prism<T> {
    /// At the poses `p`: the guide's direction u and d = Q − P from the
    /// guide line's point to the slider's.
    fn offset(&self, p: &[Pose<T>]) -> (Vector<T>, Vector<T>) {
        let (ps, pg) = (&p[self.slider], &p[self.guide]);
        let u = pg.dir(&self.line_dir);
        let d = ps
            .apply(&self.slider_local)
            .sub(&pg.apply(&self.line_point));
        (u, d)
    }

    /// The slide at the poses `p`.
    fn at(&self, p: &[Pose<T>]) -> SlideAt<T> {
        let (ps, pg) = (&p[self.slider], &p[self.guide]);
        let u = pg.dir(&self.line_dir);
        let rs = ps.dir(&self.slider_local);
        let rg = pg.dir(&self.line_point);
        let d = ps
            .apply(&self.slider_local)
            .sub(&pg.apply(&self.line_point));
        SlideAt { u, rs, rg, d }
    }
}

/// One pair's equations.
#[derive(Clone, Debug)]
pub enum Constraint<T> {
    /// The point at `on_a` on link a and at `on_b` on link b coincide (2 rows).
    Revolute {
        a: usize,
        b: usize,
        on_a: Vector<T>,
        on_b: Vector<T>,
    },
    /// A prismatic pair (2 rows).
    Prismatic(Prism<T>),
    /// Input i's coordinate (1 row).
    Driver(usize),
}

/// The input coordinate as a function of the poses.
#[derive(Clone, Debug)]
pub enum Driver<T> {
    /// A crank: its link's angle plus `offset`, the angle of the crank's
    /// line in its own frame.
    Crank { link: usize, offset: T },
    /// A driving slider: its point `at` (slider's frame) along the guide's
    /// direction `dir` from `foot`, both in the world (the guide is the
    /// frame).
    Slider {
        link: usize,
        at: Vector<T>,
        foot: Vector<T>,
        dir: Vector<T>,
    },
    /// A driving slider on a moving guide (a hydraulic cylinder): the
    /// slider's point along the guide line of its pair `pair` less
    /// `zero`, where the sketch has it: the slide relative to the guide.
    Slide { pair: Prism<T>, zero: T },
}

/// The unknowns and equations of the links solved.
#[derive(Clone, Debug)]
pub struct Equations<T> {
    /// Moving links solved, in order; their unknowns are 3·i .. 3·i+3.
    pub links: Vec<usize>,
    /// Each link's place in `links` (the frame and links not solved: none).
    pub slot: Vec<Option<usize>>,
    pub cons: Vec<Constraint<T>>,
    /// Each input's driver, in the scene's order (None: an input whose
    /// link is not solved).
    pub drivers: Vec<Option<Driver<T>>>,
    rows: usize,
}

impl<T: Number> Equations<T> {
    /// The equations of the links `include` marks (the frame is always
    /// fixed): a revolute pair per further link at a point, every prismatic
    /// pair between links inside, the drivers last. `local(l, p)`: point p
    /// in link l's frame; `prism(k)`: prismatic pair k; `sketch(p)`: point
    /// p in the sketch; `sketch_pose(l)`: link l's pose in the sketch; all
    /// in `T`.
    pub fn new(
        m: &Mechanism,
        include: &[bool],
        local: impl Fn(usize, usize) -> Vector<T>,
        prism: impl Fn(usize) -> Prism<T>,
        sketch: impl Fn(usize) -> Vector<T>,
        sketch_pose: impl Fn(usize) -> Pose<T>,
    ) -> Self {
        let frame = m.frame();
        let links: Vec<usize> = (0..m.links.len())
            .filter(|&l| l != frame && include[l])
            .collect();
        let mut slot = vec![None; m.links.len()];
        for (i, &l) in links.iter().enumerate() {
            slot[l] = Some(i);
        }
        let inside = |l: usize| l == frame || include[l];
        let mut cons = Vec::new();
        for p in 0..m.scene.points.len() {
            let ls: Vec<usize> = m
                .links_of_point(p)
                .into_iter()
                .filter(|&l| inside(l))
                .collect();
            for &b in ls.iter().skip(1) {
                cons.push(Constraint::Revolute {
                    a: ls[0],
                    b,
                    on_a: local(ls[0], p),
                    on_b: local(b, p),
                });
            }
        }
        for (k, pr) in m.prismatics.iter().enumerate() {
            if inside(pr.slider) && inside(pr.guide) {
                cons.push(Constraint::Prismatic(prism(k)));
            }
        }
        let pairs = cons.len();
        let mut drivers = Vec::new();
        for (i, spec) in m.scene.inputs().enumerate() {
            if !inside(spec.link()) {
                drivers.push(None);
                continue;
            }
            cons.push(Constraint::Driver(i));
            drivers.push(Some(match *spec {
                InputSpec::Crank { link, pivot, .. } => {
                    let pts = &m.links[link].points;
                    let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                    let offset = local(link, other).sub(&local(link, pivot)).atan2();
                    Driver::Crank { link, offset }
                }
                InputSpec::Slider { link, pair, .. } if m.prismatics[pair].guide == frame => {
                    // The sketch's point projected on the guide (the frame).
                    let pr = prism(pair);
                    let frame = Pose::identity();
                    let (o, dir) = (frame.apply(&pr.line_point), frame.dir(&pr.line_dir));
                    let along = sketch(m.prismatics[pair].point).sub(&o).dot(&dir);
                    Driver::Slider {
                        link,
                        at: pr.slider_local,
                        foot: o.add(&dir.scale(&along)),
                        dir,
                    }
                }
                InputSpec::Slider { pair, .. } => {
                    // The sketch's point along the guide line, in the
                    // guide's frame at its sketch pose.
                    let pr = prism(pair);
                    let gs = sketch_pose(pr.guide);
                    let p = sketch(m.prismatics[pair].point).sub(&gs.origin);
                    let local = p.rotate(&-gs.sin.clone(), &gs.cos);
                    let zero = local.sub(&pr.line_point).dot(&pr.line_dir);
                    Driver::Slide { pair: pr, zero }
                }
            }));
        }
        let rows = 2 * pairs + drivers.iter().flatten().count();
        Equations {
            links,
            slot,
            cons,
            drivers,
            rows,
        }
    }

    /// Number of equations.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Every link's pose (the frame and links not solved: the identity).
    pub fn poses(&self, q: &[T]) -> Poses<T> {
        self.slot
            .iter()
            .map(|s| match *s {
                Some(i) => Pose::new(
                    Vector::new(q[3 * i].clone(), q[3 * i + 1].clone()),
                    q[3 * i + 2].clone(),
                ),
                None => Pose::identity(),
            })
            .collect()
    }

    /// The residual Φ(q, x) at input coordinates `x` (one per input in
    /// the scene's order), from the poses.
    pub fn residual(&self, p: &[Pose<T>], x: &[T]) -> Rows<T> {
        let mut r = Rows::with_capacity(self.rows);
        for c in &self.cons {
            match c {
                Constraint::Revolute { a, b, on_a, on_b } => {
                    let d = p[*a].apply(on_a).sub(&p[*b].apply(on_b));
                    r.extend([d.x, d.y]);
                }
                Constraint::Prismatic(pr) => {
                    let (ps, pg) = (&p[pr.slider], &p[pr.guide]);
                    let turn = ps.angle.clone() - pg.angle.clone() - pr.delta.clone();
                    r.push(turn.wrap_angle());
                    let (u, d) = pr.offset(p);
                    r.push(u.cross(&d));
                }
                Constraint::Driver(i) => {
                    let x = x[*i].clone();
                    r.push(match self.driver(*i) {
                        // A crank angle is defined modulo a turn.
                        Driver::Crank { link, offset } => {
                            (p[*link].angle.clone() + offset.clone() - x).wrap_angle()
                        }
                        Driver::Slider {
                            link,
                            at,
                            foot,
                            dir,
                        } => dir.dot(&p[*link].apply(at).sub(foot)) - x,
                        Driver::Slide { pair, zero } => {
                            let (u, d) = pair.offset(p);
                            u.dot(&d) - zero.clone() - x
                        }
                    })
                }
            }
        }
        r
    }

    /// Row `row` += ± w·∂(world point of link l)/∂(x, y, θ) = [w | w·(k×r)],
    /// r the point's arm R(θ)·local; `add(row, column, value)` accumulates.
    fn put_point(
        &self,
        add: &mut impl FnMut(usize, usize, T),
        row: usize,
        l: usize,
        r: &Vector<T>,
        negative: bool,
        w: &Vector<T>,
    ) {
        if let Some(i) = self.slot[l] {
            let t = [w.x.clone(), w.y.clone(), w.dot(&r.perp())];
            for (k, t) in t.into_iter().enumerate() {
                add(row, 3 * i + k, if negative { -t } else { t });
            }
        }
    }

    /// Row `row` of a slide along `w`, its links `(slider, guide)`: the
    /// slider's point, the guide line's point, then `turn`, the row's
    /// change with the guide's angle through its direction.
    fn put_slide(
        &self,
        add: &mut impl FnMut(usize, usize, T),
        row: usize,
        pair: &Prism<T>,
        sl: &SlideAt<T>,
        w: &Vector<T>,
        turn: T,
    ) {
        self.put_point(add, row, pair.slider, &sl.rs, false, w);
        self.put_point(add, row, pair.guide, &sl.rg, true, w);
        if let Some(i) = self.slot[pair.guide] {
            add(row, 3 * i + 2, turn);
        }
    }

    /// The Jacobian Φ_q at the poses, cell by cell into `add(row, column,
    /// value)` (a cell may receive several values, to be summed in order,
    /// onto a matrix of zeros).
    pub fn jacobian(&self, p: &[Pose<T>], mut add: impl FnMut(usize, usize, T)) {
        let add = &mut add;
        let (ex, ey) = (
            Vector::new(T::one(), T::zero()),
            Vector::new(T::zero(), T::one()),
        );
        let mut row = 0;
        for c in &self.cons {
            match c {
                Constraint::Revolute { a, b, on_a, on_b } => {
                    let ra = p[*a].dir(on_a);
                    let rb = p[*b].dir(on_b);
                    for (k, w) in [(0, &ex), (1, &ey)] {
                        self.put_point(add, row + k, *a, &ra, false, w);
                        self.put_point(add, row + k, *b, &rb, true, w);
                    }
                    row += 2;
                }
                Constraint::Prismatic(pr) => {
                    if let Some(i) = self.slot[pr.slider] {
                        add(row, 3 * i + 2, T::one());
                    }
                    if let Some(i) = self.slot[pr.guide] {
                        add(row, 3 * i + 2, -T::one());
                    }
                    // f = u × (Q − P): u and P turn with the guide;
                    // u × X = (k×u)·X.
                    let sl = pr.at(p);
                    let n = sl.u.perp();
                    let turn = n.cross(&sl.d);
                    self.put_slide(add, row + 1, pr, &sl, &n, turn);
                    row += 2;
                }
                Constraint::Driver(k) => {
                    match self.driver(*k) {
                        Driver::Crank { link, .. } => {
                            let i = self.slot[*link].expect("the input is solved");
                            add(row, 3 * i + 2, T::one());
                        }
                        Driver::Slider { link, at, dir, .. } => {
                            let r = p[*link].dir(at);
                            self.put_point(add, row, *link, &r, false, dir);
                        }
                        Driver::Slide { pair, .. } => {
                            // f = u·(Q − P): u and P turn with the guide.
                            let sl = pair.at(p);
                            let turn = sl.u.perp().dot(&sl.d);
                            self.put_slide(add, row, pair, &sl, &sl.u, turn);
                        }
                    }
                    row += 1;
                }
            }
        }
    }

    /// Driver of input `i`.
    fn driver(&self, i: usize) -> &Driver<T> {
        self.drivers[i]
            .as_ref()
            .expect("a driver of every input solved")
    }

    /// γ of the acceleration equations Φ_q·q̈ = γ (the terms quadratic in
    /// q̇), at the poses, the rates `qd` and the inputs' accelerations (one
    /// per input in the scene's order).
    pub fn gamma(&self, p: &[Pose<T>], qd: &[T], input_acc: &[T]) -> Rows<T> {
        let rate = |l: usize| self.slot[l].map_or(T::zero(), |i| qd[3 * i + 2].clone());
        let lin = |l: usize| {
            self.slot[l].map_or(Vector::zero(), |i| {
                Vector::new(qd[3 * i].clone(), qd[3 * i + 1].clone())
            })
        };
        let square = |w: T| w.clone() * w;
        let mut g = Rows::with_capacity(self.rows);
        for c in &self.cons {
            match c {
                Constraint::Revolute { a, b, on_a, on_b } => {
                    let ra = p[*a].dir(on_a);
                    let rb = p[*b].dir(on_b);
                    let t = ra
                        .scale(&square(rate(*a)))
                        .sub(&rb.scale(&square(rate(*b))));
                    g.extend([t.x, t.y]);
                }
                Constraint::Prismatic(pr) => {
                    let (ws, wg) = (rate(pr.slider), rate(pr.guide));
                    let sl = pr.at(p);
                    let dd = sl.rate(&lin(pr.slider), &lin(pr.guide), &ws, &wg);
                    let SlideAt { u, rs, rg, d } = sl;
                    // f̈ = ü×d + 2u̇×ḋ + u×d̈; the q̈-free part goes to γ.
                    let quad = u.neg().scale(&wg).scale(&wg).cross(&d)
                        + T::from_f64(2.0) * u.perp().scale(&wg).cross(&dd)
                        + u.cross(
                            &rs.neg()
                                .scale(&ws)
                                .scale(&ws)
                                .add(&rg.scale(&wg).scale(&wg)),
                        );
                    g.extend([T::zero(), -quad]);
                }
                Constraint::Driver(i) => {
                    let acc = input_acc[*i].clone();
                    g.push(match self.driver(*i) {
                        Driver::Crank { .. } => acc,
                        Driver::Slider { link, at, dir, .. } => {
                            let r = p[*link].dir(at);
                            acc + square(rate(*link)) * dir.dot(&r)
                        }
                        Driver::Slide { pair, .. } => {
                            // f̈ = ü·d + 2u̇·ḋ + u·d̈; the q̈-free part
                            // leaves γ.
                            let (ws, wg) = (rate(pair.slider), rate(pair.guide));
                            let sl = pair.at(p);
                            let dd = sl.rate(&lin(pair.slider), &lin(pair.guide), &ws, &wg);
                            let SlideAt { u, rs, rg, d } = sl;
                            let quad = -(square(wg.clone()) * u.dot(&d))
                                + T::from_f64(2.0) * wg.clone() * u.perp().dot(&dd)
                                + u.dot(&rs.neg().scale(&square(ws)).add(&rg.scale(&square(wg))));
                            acc - quad
                        }
                    })
                }
            }
        }
        g
    }
}
