//! An extended-precision reference for measuring errors (never used to
//! answer a scene): positions, velocities and accelerations of every solved
//! link to about 50 significant digits.
//!
//! The equations are route (b)'s, the very code
//! ([`crate::kinematics::analytic::equations`], generic over the number
//! type): every moving link a pose (x, y, θ), two equations per revolute
//! pair, two per prismatic pair, one for the input; but every number is a
//! binary float of [`BITS`] bits (`dashu-float`, correctly rounded `sqrt`,
//! `sin`, `cos`, `atan2`, π). The reference's independence is its own
//! positions and its precision: the links' rigid shapes are rebuilt in that
//! precision from the scene's numbers, which are taken as the exact binary
//! values they are (a value the file gave in degrees or millimetres is
//! recovered as the shortest decimal that the scene's conversion maps onto
//! the stored value, and converted with an extended π or an exact 10⁻³).
//! Positions by Newton's method started from the f64 closed-form solution
//! (so on the same branch) down to a correction of 1e-50 of the sketch
//! size, then the velocity and acceleration systems Φ_q·q̇ = −Φ_t,
//! Φ_q·q̈ = γ by Gaussian elimination with partial pivoting.

use crate::error::{Error, Result};
use crate::kinematics::analytic::Coords;
use crate::kinematics::analytic::equations::{Constraint, Equations, Number, Pose, Prism, Vector};
use crate::kinematics::positions::{Configuration, PositionSolver, describe_input};
use crate::kinematics::solve::Analysis;
use crate::model::scene::{Direction, InputSpec, Through};
use crate::model::shape::Placement;
use dashu_float::FBig;
use dashu_float::round::mode::HalfEven;
use kurbo::{Point, Vec2};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Working precision, bits (≈ 57 decimal digits).
pub const BITS: usize = 192;

/// A real number of [`BITS`] bits.
#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub struct Real(FBig<HalfEven, 2>);

impl Real {
    /// The exact value of an f64 (every finite f64 is a dyadic rational).
    pub fn from_f64(x: f64) -> Real {
        let v = FBig::<HalfEven, 2>::try_from(x).expect("a finite number");
        Real(v.with_precision(BITS).value())
    }
    pub fn zero() -> Real {
        Real::from_f64(0.0)
    }
    pub fn one() -> Real {
        Real::from_f64(1.0)
    }
    /// π to [`BITS`] bits.
    pub fn pi() -> Real {
        static PI: std::sync::OnceLock<Real> = std::sync::OnceLock::new();
        PI.get_or_init(|| Real(FBig::<HalfEven, 2>::pi(BITS)))
            .clone()
    }
    /// Degrees to radians with the extended π.
    pub fn from_degrees(deg: &Real) -> Real {
        deg * &Real::pi() / Real::from_f64(180.0)
    }
    /// A decimal numeral ("-12.5", "3.25e-3") to [`BITS`] bits.
    pub fn from_decimal(s: &str) -> Option<Real> {
        let s = s.trim();
        let (mant, exp) = match s.find(['e', 'E']) {
            Some(i) => (&s[..i], s[i + 1..].parse::<i32>().ok()?),
            None => (s, 0),
        };
        let (neg, mant) = match mant.strip_prefix('-') {
            Some(r) => (true, r),
            None => (false, mant.strip_prefix('+').unwrap_or(mant)),
        };
        let mut v = Real::zero();
        let mut frac = 0i32;
        let mut seen_dot = false;
        let ten = Real::from_f64(10.0);
        let mut any = false;
        for c in mant.chars() {
            match c {
                '.' if !seen_dot => seen_dot = true,
                '0'..='9' => {
                    any = true;
                    v = v * &ten + Real::from_f64(f64::from(c as u8 - b'0'));
                    if seen_dot {
                        frac += 1;
                    }
                }
                _ => return None,
            }
        }
        if !any {
            return None;
        }
        let k = exp - frac;
        let mut p = Real::one();
        for _ in 0..k.unsigned_abs() {
            p = p * &ten;
        }
        let v = if k >= 0 { v * p } else { v / p };
        Some(if neg { -v } else { v })
    }
    /// The nearest f64.
    pub fn to_f64(&self) -> f64 {
        self.0.to_f64().value()
    }
    pub fn sqrt(&self) -> Real {
        Real(self.0.sqrt())
    }
    pub fn sin_cos(&self) -> (Real, Real) {
        let (s, c) = self.0.sin_cos();
        (Real(s), Real(c))
    }
    /// atan2(self, x).
    pub fn atan2(&self, x: &Real) -> Real {
        Real(self.0.atan2(&x.0))
    }
    pub fn abs(&self) -> Real {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }
    pub fn is_negative(&self) -> bool {
        self.0 < FBig::<HalfEven, 2>::ZERO
    }
    pub fn max(self, o: Real) -> Real {
        if o > self { o } else { self }
    }
    pub fn square(&self) -> Real {
        self * self
    }
    /// The angle reduced to (−π, π] (approximately at the ends).
    fn wrap(&self) -> Real {
        let tau = Real::pi() * Real::from_f64(2.0);
        let k = (self / &tau).0.round();
        self - &(Real(k) * tau)
    }
}

macro_rules! binop {
    ($tr:ident, $f:ident) => {
        impl $tr<&Real> for &Real {
            type Output = Real;
            fn $f(self, o: &Real) -> Real {
                Real((&self.0).$f(&o.0))
            }
        }
        impl $tr<Real> for Real {
            type Output = Real;
            fn $f(self, o: Real) -> Real {
                Real(self.0.$f(o.0))
            }
        }
        impl $tr<&Real> for Real {
            type Output = Real;
            fn $f(self, o: &Real) -> Real {
                Real(self.0.$f(&o.0))
            }
        }
        impl $tr<Real> for &Real {
            type Output = Real;
            fn $f(self, o: Real) -> Real {
                Real((&self.0).$f(o.0))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real(-self.0)
    }
}
impl Neg for &Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real(-self.0.clone())
    }
}

impl Number for Real {
    fn from_f64(x: f64) -> Real {
        Real::from_f64(x)
    }
    fn sqrt(&self) -> Real {
        Real::sqrt(self)
    }
    fn sin_cos(&self) -> (Real, Real) {
        Real::sin_cos(self)
    }
    fn atan2(&self, x: &Real) -> Real {
        Real::atan2(self, x)
    }
    fn wrap_angle(&self) -> Real {
        self.wrap()
    }
}

/// A planar vector of [`Real`]s.
pub type V2 = Vector<Real>;

impl Vector<Real> {
    pub fn from_point(p: Point) -> V2 {
        V2::new(Real::from_f64(p.x), Real::from_f64(p.y))
    }
    pub fn to_vec2(&self) -> Vec2 {
        Vec2::new(self.x.to_f64(), self.y.to_f64())
    }
    pub fn to_point(&self) -> Point {
        Point::new(self.x.to_f64(), self.y.to_f64())
    }
    /// |a − b| as an f64, for an f64 `b`.
    pub fn dist_f64(&self, b: Vec2) -> f64 {
        self.sub(&V2::new(Real::from_f64(b.x), Real::from_f64(b.y)))
            .norm()
            .to_f64()
    }
}

/// The exact values of some of the scene's numbers, by point name and
/// length key ("A-B"), where the file can only hold their f64 roundings
/// (√3 and the like): the reference is then that of the exact mechanism.
#[derive(Clone, Debug, Default)]
pub struct Exact {
    pub points: Vec<(String, Real, Real)>,
    pub lengths: Vec<(String, Real)>,
}

/// The motion of one link: its pose, and the velocity and acceleration of
/// the material point at its frame's origin.
#[derive(Clone, Debug)]
pub struct RefMotion {
    pub origin: V2,
    pub angle: Real,
    pub omega: Real,
    pub epsilon: Real,
    pub v_origin: V2,
    pub a_origin: V2,
}

/// A point's place, velocity and acceleration.
#[derive(Clone, Debug)]
pub struct RefPoint {
    pub at: V2,
    pub v: V2,
    pub a: V2,
}

impl RefPoint {
    /// Rounded to f64: (place, velocity, acceleration).
    pub fn to_f64(&self) -> (Point, Vec2, Vec2) {
        (self.at.to_point(), self.v.to_vec2(), self.a.to_vec2())
    }
}

/// One solved position.
#[derive(Clone, Debug)]
pub struct RefState {
    pub q: Real,
    /// Per link (scene order); `None` for links not solved.
    pub links: Vec<Option<RefMotion>>,
    /// Local coordinates of the links' points (parallel to the mechanism's).
    local: Vec<Vec<V2>>,
    points_of: Vec<Vec<usize>>,
}

impl RefState {
    /// Point `p` as carried by solved link `l`.
    pub fn point_on(&self, l: usize, p: usize) -> RefPoint {
        let mo = self.links[l].as_ref().expect("link solved");
        let i = self.points_of[l]
            .iter()
            .position(|&x| x == p)
            .expect("point on link");
        let (s, c) = mo.angle.sin_cos();
        let r = self.local[l][i].rotate(&s, &c);
        let w2 = mo.omega.square();
        RefPoint {
            at: mo.origin.add(&r),
            v: mo.v_origin.add(&r.perp().scale(&mo.omega)),
            a: mo
                .a_origin
                .add(&r.perp().scale(&mo.epsilon))
                .sub(&r.scale(&w2)),
        }
    }
    /// Point `p` on the link that reports it.
    pub fn point(&self, an: &Analysis, p: usize) -> RefPoint {
        self.point_on(an.carrier(p), p)
    }
}

/// The extended-precision model of a scene, ready to solve positions.
pub struct Reference<'a> {
    an: &'a Analysis,
    /// Local coordinates of the links' points (parallel to the mechanism's).
    local: Vec<Vec<V2>>,
    /// Route (b)'s equations in extended precision.
    eq: Equations<Real>,
    /// Each input's (rate, rate of rate), in the scene's order.
    rates: Vec<(Real, Real)>,
    size: Real,
    ps: PositionSolver<'a>,
}

/// The shortest decimal that the scene's conversion (× `unit`) maps onto
/// `x`, in extended precision times the exact unit; `x` itself when the
/// unit is 1.
fn recover(x: f64, unit: f64, exact_unit: impl Fn() -> Real) -> Real {
    if unit == 1.0 || x == 0.0 {
        return Real::from_f64(x);
    }
    let d = x / unit;
    for digits in 1..=17 {
        let s = format!("{:.*e}", digits - 1, d);
        if s.parse::<f64>().map(|v| v * unit) == Ok(x)
            && let Some(r) = Real::from_decimal(&s)
        {
            return r * exact_unit();
        }
    }
    Real::from_f64(x)
}

impl<'a> Reference<'a> {
    pub fn new(an: &'a Analysis) -> Result<Reference<'a>> {
        Reference::with_exact(an, &Exact::default())
    }

    /// The model with some of the scene's numbers replaced by exact values.
    pub fn with_exact(an: &'a Analysis, exact: &Exact) -> Result<Reference<'a>> {
        let m = &an.mech;
        let sc = &m.scene;
        let lu = sc.length_unit;
        let au = sc.angle_unit;
        let len_unit = move || {
            if lu == 1e-3 {
                Real::one() / Real::from_f64(1000.0)
            } else {
                Real::from_f64(lu)
            }
        };
        let ang_unit = move || {
            if au == std::f64::consts::PI / 180.0 {
                Real::pi() / Real::from_f64(180.0)
            } else {
                Real::from_f64(au)
            }
        };
        let length = |x: f64| recover(x, lu, len_unit);
        let angle = |x: f64| recover(x, au, ang_unit);
        let sketch: Vec<V2> = sc
            .points
            .iter()
            .map(|p| match exact.points.iter().find(|e| e.0 == p.name) {
                Some((_, x, y)) => V2::new(x.clone(), y.clone()),
                None => V2::new(length(p.sketch.x), length(p.sketch.y)),
            })
            .collect();
        let given = |a: usize, b: usize| -> Option<Real> {
            let l = sc
                .lengths
                .iter()
                .find(|l| (l.a == a && l.b == b) || (l.a == b && l.b == a))?;
            Some(match exact.lengths.iter().find(|e| e.0 == l.key) {
                Some((_, v)) => v.clone(),
                None => length(l.value),
            })
        };
        let dist =
            |a: usize, b: usize| given(a, b).unwrap_or_else(|| sketch[a].sub(&sketch[b]).norm());
        let guide_dir = |k: usize| -> V2 {
            match sc.sliders[k].line.direction {
                Direction::Angle(a) => {
                    let (s, c) = angle(a).sin_cos();
                    V2::new(c, s)
                }
                Direction::Along(q, r) => {
                    let v = sketch[r].sub(&sketch[q]);
                    let n = v.norm();
                    v.scale(&(Real::one() / n))
                }
            }
        };
        // Rigid shapes by the contract's rule (as mechanism.rs builds them).
        let mut local: Vec<Vec<V2>> = Vec::new();
        let mut sketch_angle: Vec<Real> = Vec::new();
        for (l, link) in m.links.iter().enumerate() {
            let pts = &link.points;
            if l == m.frame() {
                local.push(pts.iter().map(|&p| sketch[p].clone()).collect());
                sketch_angle.push(Real::zero());
                continue;
            }
            let mut loc = vec![V2::zero(); pts.len()];
            if pts.len() == 1 {
                let k = sc
                    .sliders
                    .iter()
                    .position(|s| s.slider == l)
                    .expect("a one-point link is a slider (checked)");
                sketch_angle.push(guide_dir(k).atan2());
                local.push(loc);
                continue;
            }
            let axis = sketch[pts[1]].sub(&sketch[pts[0]]);
            sketch_angle.push(axis.atan2());
            loc[1] = V2::new(dist(pts[0], pts[1]), Real::zero());
            let axis_len = axis.norm();
            let (ca, sa) = (axis.x.clone() / &axis_len, axis.y.clone() / &axis_len);
            for k in 2..pts.len() {
                let p = pts[k];
                // The placement mechanism.rs decided (crate::model::shape), in
                // extended precision.
                let (j1, j2, flat, side) = match m.placements[l][k] {
                    Placement::Sketch => {
                        // The sketch position in the link's frame.
                        loc[k] = sketch[p].sub(&sketch[pts[0]]).rotate(&-&sa, &ca);
                        continue;
                    }
                    Placement::OnLine { refs } => (refs.0, refs.1, true, 1.0),
                    Placement::Triangle { refs, side } => (refs.0, refs.1, false, side),
                    Placement::Origin | Placement::Base => unreachable!("first two points"),
                };
                let (r1, r2) = (dist(p, pts[j1]), dist(p, pts[j2]));
                let (a, b) = (loc[j1].clone(), loc[j2].clone());
                let ab = b.sub(&a);
                let d = ab.norm();
                let e = ab.scale(&(Real::one() / &d));
                let x = (d.square() + r1.square() - r2.square()) / (Real::from_f64(2.0) * &d);
                let h2 = r1.square() - x.square();
                let foot = a.add(&e.scale(&x));
                loc[k] = if flat || h2.is_negative() {
                    foot
                } else {
                    let h = h2.sqrt() * Real::from_f64(side);
                    foot.add(&e.perp().scale(&h))
                };
            }
            local.push(loc);
        }
        let local_of = |l: usize, p: usize| -> V2 {
            let i = m.links[l]
                .points
                .iter()
                .position(|&x| x == p)
                .expect("point on link");
            local[l][i].clone()
        };
        let mut prism = Vec::new();
        for (k, s) in sc.sliders.iter().enumerate() {
            let ga = &sketch_angle[s.guide];
            let (gs, gc) = ga.sin_cos();
            let through = match s.line.through {
                Through::Point(p) => local_of(s.guide, p),
                Through::Coords(c) => V2::new(length(c.x), length(c.y)),
            };
            let dir = match s.line.direction {
                Direction::Angle(_) => guide_dir(k).rotate(&-&gs, &gc),
                Direction::Along(q, r) => {
                    let v = local_of(s.guide, r).sub(&local_of(s.guide, q));
                    let n = v.norm();
                    v.scale(&(Real::one() / n))
                }
            };
            let line_point = through.add(&dir.perp().scale(&length(s.line.offset)));
            prism.push(Prism {
                slider: s.slider,
                guide: s.guide,
                slider_local: local_of(s.slider, s.point),
                line_point,
                line_dir: dir,
                delta: &sketch_angle[s.slider] - ga,
            });
        }
        // Unknowns and equations as route (b) has them.
        let sketch_pose = |l: usize| {
            let origin = match m.links[l].points.first() {
                Some(&p) if l != m.frame() => sketch[p].clone(),
                _ => V2::zero(),
            };
            Pose::new(origin, sketch_angle[l].clone())
        };
        let eq = Equations::new(
            m,
            &an.include,
            local_of,
            |k| prism[k].clone(),
            |p| sketch[p].clone(),
            sketch_pose,
        );
        let rates = sc
            .inputs()
            .map(|i| match *i {
                InputSpec::Crank { omega, epsilon, .. } => {
                    (Real::from_f64(omega), Real::from_f64(epsilon))
                }
                InputSpec::Slider { v, a, .. } => (length(v), length(a)),
            })
            .collect();
        let ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
        Ok(Reference {
            an,
            local,
            eq,
            rates,
            size: Real::from_f64(m.size),
            ps,
        })
    }

    /// The (first) input's rates (ω1, ε1) or (v, a) as the reference takes
    /// them.
    pub fn rates(&self) -> (Real, Real) {
        self.rates[0].clone()
    }

    /// Solve at the input coordinate `q` (rad or m), an exact binary value.
    pub fn solve_f64(&mut self, q: f64) -> Result<RefState> {
        self.solve(&Real::from_f64(q))
    }

    /// Solve at the input coordinate `q` given in extended precision.
    pub fn solve(&mut self, q: &Real) -> Result<RefState> {
        self.solve_coords(std::slice::from_ref(q))
    }

    /// Solve at the input coordinates `q` (one per input) given in
    /// extended precision.
    pub fn solve_coords(&mut self, q: &[Real]) -> Result<RefState> {
        let qf: Vec<f64> = q.iter().map(|x| x.to_f64()).collect();
        let c = self.ps.solve_coords(Coords::new(&qf))?;
        self.refine_coords(q, &c)
    }

    /// The start of the reference at each of `qs`, in order: the double
    /// precision positions, continued from one to the next on the branch
    /// the sketch shows. Each then refines on its own ([`Reference::refine`]).
    pub fn starts(&mut self, qs: &[f64]) -> Result<Vec<Configuration>> {
        qs.iter().map(|&q| self.ps.solve(q)).collect()
    }

    /// [`Reference::starts`] of several inputs.
    pub fn starts_coords(&mut self, qs: &[Coords]) -> Result<Vec<Configuration>> {
        qs.iter().map(|&q| self.ps.solve_coords(q)).collect()
    }

    /// Newton's method in extended precision from the double precision
    /// position `c` at `q`, then velocities and accelerations. Independent
    /// of any other position, so positions can be refined in parallel.
    pub fn refine(&self, q: &Real, c: &Configuration) -> Result<RefState> {
        self.refine_coords(std::slice::from_ref(q), c)
    }

    /// [`Reference::refine`] at the input coordinates `q` (one per input).
    pub fn refine_coords(&self, q: &[Real], c: &Configuration) -> Result<RefState> {
        let m = &self.an.mech;
        let qf: Vec<f64> = q.iter().map(|x| x.to_f64()).collect();
        let mut x: Vec<Real> = Vec::with_capacity(3 * self.eq.links.len());
        for &l in &self.eq.links {
            let p = c.pose(l);
            x.push(Real::from_f64(p.origin.x));
            x.push(Real::from_f64(p.origin.y));
            x.push(Real::from_f64(p.angle));
        }
        let fail = |why: String| {
            Error::assembly(
                "the mechanism (extended-precision reference)",
                describe_input(m, &qf),
                why,
            )
        };
        let stop = &self.size * &Real::from_f64(1e-50);
        let mut done = false;
        for _ in 0..40 {
            let poses = self.eq.poses(&x);
            let r = self.eq.residual(&poses, q);
            let j = self.jacobian(&poses);
            let dx =
                gauss(j, r).ok_or_else(|| fail("the constraint Jacobian is singular".into()))?;
            let mut big = Real::zero();
            for (i, d) in dx.iter().enumerate() {
                let d = if i % 3 == 2 {
                    d * &self.size
                } else {
                    d.clone()
                };
                big = big.max(d.abs());
            }
            for (xi, d) in x.iter_mut().zip(&dx) {
                *xi = &*xi - d;
            }
            if !big.to_f64().is_finite() {
                return Err(fail("Newton's method diverged".into()));
            }
            if big <= stop {
                done = true;
                break;
            }
        }
        if !done {
            return Err(fail("Newton's method did not converge to 1e-50".into()));
        }
        let poses = self.eq.poses(&x);
        let j = self.jacobian(&poses);
        let n = j.len();
        let mut b = vec![Real::zero(); n];
        let mut row = 0;
        for c in &self.eq.cons {
            match c {
                Constraint::Driver(i) => {
                    b[row] = self.rates[*i].0.clone();
                    row += 1;
                }
                _ => row += 2,
            }
        }
        let xd = gauss(j.clone(), b).ok_or_else(|| fail("singular Jacobian".into()))?;
        let acc: Vec<Real> = self.rates.iter().map(|r| r.1.clone()).collect();
        let g = self.eq.gamma(&poses, &xd, &acc);
        let xdd = gauss(j, g).ok_or_else(|| fail("singular Jacobian".into()))?;
        let mut links = vec![None; m.links.len()];
        links[m.frame()] = Some(RefMotion {
            origin: V2::zero(),
            angle: Real::zero(),
            omega: Real::zero(),
            epsilon: Real::zero(),
            v_origin: V2::zero(),
            a_origin: V2::zero(),
        });
        for (i, &l) in self.eq.links.iter().enumerate() {
            links[l] = Some(RefMotion {
                origin: V2::new(x[3 * i].clone(), x[3 * i + 1].clone()),
                angle: x[3 * i + 2].clone(),
                omega: xd[3 * i + 2].clone(),
                epsilon: xdd[3 * i + 2].clone(),
                v_origin: V2::new(xd[3 * i].clone(), xd[3 * i + 1].clone()),
                a_origin: V2::new(xdd[3 * i].clone(), xdd[3 * i + 1].clone()),
            });
        }
        Ok(RefState {
            q: q[0].clone(),
            links,
            local: self.local.clone(),
            points_of: m.links.iter().map(|l| l.points.clone()).collect(),
        })
    }

    /// The Jacobian Φ_q at the poses.
    fn jacobian(&self, p: &[Pose<Real>]) -> Vec<Vec<Real>> {
        let mut j = vec![vec![Real::zero(); 3 * self.eq.links.len()]; self.eq.rows()];
        self.eq.jacobian(p, |r, c, v| j[r][c] = &j[r][c] + v);
        j
    }
}

/// Solve A·x = b by Gaussian elimination with partial pivoting.
pub fn gauss(mut a: Vec<Vec<Real>>, mut b: Vec<Real>) -> Option<Vec<Real>> {
    let n = b.len();
    for k in 0..n {
        let piv = (k..n).max_by(|&i, &j| {
            a[i][k]
                .abs()
                .partial_cmp(&a[j][k].abs())
                .unwrap_or(std::cmp::Ordering::Equal)
        })?;
        if a[piv][k] == Real::zero() {
            return None;
        }
        a.swap(k, piv);
        b.swap(k, piv);
        let pivot = a[k][k].clone();
        for i in k + 1..n {
            if a[i][k] == Real::zero() {
                continue;
            }
            let f = &a[i][k] / &pivot;
            #[allow(clippy::needless_range_loop)] // rows i and k of one matrix
            for c in k..n {
                let t = &f * &a[k][c];
                a[i][c] = &a[i][c] - t;
            }
            let t = &f * &b[k];
            b[i] = &b[i] - t;
        }
    }
    let mut x = vec![Real::zero(); n];
    for k in (0..n).rev() {
        let mut s = b[k].clone();
        for c in k + 1..n {
            s = s - &a[k][c] * &x[c];
        }
        x[k] = s / &a[k][k];
    }
    Some(x)
}

/// The reference at one input coordinate (rad or m, an exact binary value).
pub fn solve(an: &Analysis, q: f64) -> Result<RefState> {
    Reference::new(an)?.solve_f64(q)
}
