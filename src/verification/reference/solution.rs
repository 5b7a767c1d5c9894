//! The extended-precision solution of a scene: route (b)'s equations solved at about 57 digits, position by position.

use crate::error::{Error, Result};
use crate::kinematics::analytic::equations::{Constraint, Equations, Pose};
use crate::kinematics::positions::{Configuration, PositionSolver, describe_input};
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use super::real::{Real, V2};
use super::model::{Exact, Numbers, local_of, prisms, shapes};

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
    #[cfg(feature = "internals")]
    pub fn to_f64(&self) -> (kurbo::Point, kurbo::Vec2, kurbo::Vec2) {
        (self.at.to_point(), self.v.to_vec2(), self.a.to_vec2())
    }
}

/// One solved position.
#[derive(Clone, Debug)]
pub struct RefState {
    /// Per link (scene order); `None` for links not solved.
    pub links: Vec<Option<RefMotion>>,
    /// Local coordinates of the links' points (parallel to the mechanism's).
    pub(super) local: Vec<Vec<V2>>,
    pub(super) points_of: Vec<Vec<usize>>,
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
    pub(super) an: &'a Analysis,
    /// Local coordinates of the links' points (parallel to the mechanism's).
    pub(super) local: Vec<Vec<V2>>,
    /// Route (b)'s equations in extended precision.
    pub(super) eq: Equations<Real>,
    /// Each input's (rate, rate of rate), in the scene's order.
    pub(super) rates: Vec<(Real, Real)>,
    pub(super) size: Real,
    pub(super) ps: PositionSolver<'a>,
}

impl<'a> Reference<'a> {
    pub fn new(an: &'a Analysis) -> Result<Reference<'a>> {
        Reference::with_exact(an, &Exact::default())
    }

    /// The model with some of the scene's numbers replaced by exact values.
    pub fn with_exact(an: &'a Analysis, exact: &Exact) -> Result<Reference<'a>> {
        let m = &an.mech;
        let sc = &m.scene;
        let nums = Numbers::new(sc, exact);
        // Rigid shapes by the contract's rule (as mechanism.rs builds them).
        let (local, sketch_angle) = shapes(m, &nums);
        let prism = prisms(m, &nums, &local, &sketch_angle);
        // Unknowns and equations as route (b) has them.
        let sketch = &nums.sketch;
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
            |l, p| local_of(m, &local, l, p),
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
                InputSpec::Slider { v, a, .. } => (nums.length(v), nums.length(a)),
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

    /// Solve at the input coordinate `q` (rad or m), an exact binary value.
#[cfg(feature = "internals")]
    pub fn solve_f64(&mut self, q: f64) -> Result<RefState> {
        self.solve(&Real::from_f64(q))
    }

    /// Solve at the input coordinate `q` given in extended precision.
#[cfg(feature = "internals")]
    pub fn solve(&mut self, q: &Real) -> Result<RefState> {
        self.solve_coords(std::slice::from_ref(q))
    }

    /// Solve at the input coordinates `q` (one per input) given in
    /// extended precision.
#[cfg(feature = "internals")]
    pub fn solve_coords(&mut self, q: &[Real]) -> Result<RefState> {
        let qf: Vec<f64> = q.iter().map(|x| x.to_f64()).collect();
        let c = self.ps.solve_coords(crate::kinematics::analytic::Coords::new(&qf))?;
        self.refine_coords(q, &c)
    }

    /// The start of the reference at each of `qs`, in order: the double
    /// precision positions, continued from one to the next on the branch
    /// the sketch shows. Each then refines on its own ([`Reference::refine`]).
    pub fn starts(&mut self, qs: &[f64]) -> Result<Vec<Configuration>> {
        qs.iter().map(|&q| self.ps.solve(q)).collect()
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
        let fail = |why: String| {
            Error::assembly(
                "the mechanism (extended-precision reference)",
                describe_input(m, &qf),
                why,
            )
        };
        let x = self.newton(q, c).map_err(fail)?;
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
        let g = self.eq.gamma(&poses, &xd, &acc).into_vec();
        let xdd = gauss(j, g).ok_or_else(|| fail("singular Jacobian".into()))?;
        Ok(RefState {
            links: self.motions(&x, &xd, &xdd),
            local: self.local.clone(),
            points_of: m.links.iter().map(|l| l.points.clone()).collect(),
        })
    }

    /// Newton's method in extended precision at `q` from the double
    /// precision position `c`, down to a correction of 1e-50 of the
    /// sketch's size: the unknowns.
    pub(super) fn newton(&self, q: &[Real], c: &Configuration) -> std::result::Result<Vec<Real>, String> {
        let mut x: Vec<Real> = Vec::with_capacity(3 * self.eq.links.len());
        for &l in &self.eq.links {
            let p = c.pose(l);
            x.push(Real::from_f64(p.origin.x));
            x.push(Real::from_f64(p.origin.y));
            x.push(Real::from_f64(p.angle));
        }
        let stop = &self.size * &Real::from_f64(1e-50);
        for _ in 0..40 {
            let poses = self.eq.poses(&x);
            let r = self.eq.residual(&poses, q).into_vec();
            let j = self.jacobian(&poses);
            let dx = gauss(j, r).ok_or("the constraint Jacobian is singular")?;
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
                return Err("Newton's method diverged".into());
            }
            if big <= stop {
                return Ok(x);
            }
        }
        Err("Newton's method did not converge to 1e-50".into())
    }

    /// Every link's motion from the unknowns `x`, their rates `xd` and
    /// `xdd` (the frame at rest; `None` for links not solved).
    pub(super) fn motions(&self, x: &[Real], xd: &[Real], xdd: &[Real]) -> Vec<Option<RefMotion>> {
        let m = &self.an.mech;
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
        links
    }

    /// The Jacobian Φ_q at the poses.
    pub(super) fn jacobian(&self, p: &[Pose<Real>]) -> Vec<Vec<Real>> {
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
#[cfg(feature = "internals")]
pub fn solve(an: &Analysis, q: f64) -> Result<RefState> {
    Reference::new(an)?.solve_f64(q)
}
