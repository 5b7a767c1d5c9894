//! An answer found otherwise (route (a)'s, a student's) put to route
//! (b)'s equations: its unknowns, and the answer corrected by them.

use super::ConstraintSolver;
use super::dense::{self, Lu, Square};
use crate::geom::Pose;
use crate::kinematics::analytic::equations::{Pose as PoseOf, Poses};
use crate::kinematics::analytic::{InputRates, MAX_INPUTS, Motion, Order};
use nalgebra::{DMatrix, DVectorView, DVectorViewMut};
use smallvec::{SmallVec, smallvec};
use std::borrow::Cow;

pub use super::dense::Col;

/// Right-hand sides solved together ([`Factors::solve_many`]).
type Sides = SmallVec<[Col; 4]>;

/// An answer's run: its unknowns, with its inputs' (rate, rate of rate).
type Run<'a> = (&'a Unknowns, &'a [(f64, f64)]);

/// One number an input (their accelerations).
type Inputs = SmallVec<[f64; MAX_INPUTS]>;

/// x − d, entry by entry (nalgebra's `x - d`).
fn minus(x: &[f64], d: &[f64]) -> Col {
    if x.len() > dense::MAX {
        return x.iter().zip(d).map(|(x, d)| x - d).collect();
    }
    let mut out = [0.0; dense::MAX];
    for ((o, x), d) in out.iter_mut().zip(x).zip(d) {
        *o = x - d;
    }
    Col::from_buf_and_len(out, x.len())
}

/// The inputs' accelerations of `rates` (each input's rate, rate of rate).
fn accelerations(rates: &[(f64, f64)]) -> Inputs {
    rates.iter().map(|r| r.1).collect()
}

impl ConstraintSolver<'_> {
    /// An answer found otherwise (route (a)'s) in this route's unknowns:
    /// each solved link's pose (x, y, θ) from `pose`, and from `motion`
    /// (with `order`) the velocity of its frame's origin and ω, its
    /// acceleration and ε.
    pub fn unknowns(
        &self,
        pose: impl Fn(usize) -> Pose,
        motion: &[Option<Motion>],
        order: Option<Order>,
    ) -> Unknowns {
        let n = 3 * self.eq.links.len();
        let mut q: Col = smallvec![0.0; n];
        let (mut qd, mut qdd): (Col, Col) = (smallvec![0.0; n], smallvec![0.0; n]);
        for (i, &l) in self.eq.links.iter().enumerate() {
            let p = pose(l);
            (q[3 * i], q[3 * i + 1], q[3 * i + 2]) = (p.origin.x, p.origin.y, p.angle);
            if let Some(mo) = motion[l] {
                let (v, a) = (mo.velocity(p.origin), mo.acceleration(p.origin));
                (qd[3 * i], qd[3 * i + 1], qd[3 * i + 2]) = (v.x, v.y, mo.omega);
                (qdd[3 * i], qdd[3 * i + 1], qdd[3 * i + 2]) = (a.x, a.y, mo.epsilon);
            }
        }
        Unknowns {
            q,
            qd: order.map(|_| qd),
            qdd: (order == Some(Order::Acceleration)).then_some(qdd),
        }
    }

    /// This route's equations at an answer `u` found otherwise, at the
    /// input coordinates `x` with each input's (rate, rate of rate): the
    /// residuals of the closure equations Φ(q), of their first time
    /// derivative Φ_q·q̇ − (the drivers' rates) and of their second
    /// Φ_q·q̈ − γ(q, q̇), each turned into the change of the answer that
    /// cancels it, Φ_q⁻¹·residual (for the positions one Newton step, for
    /// the rates the linear solves of [`Self::solve_rates_of`]), and the
    /// answer so corrected. The rates' residuals are taken at the answer's
    /// own positions and velocities, so that each quantity is checked on
    /// its own. With `conditioning`, the scaled conditioning of Φ_q at the
    /// answer's positions.
    pub fn corrected(
        &self,
        u: &Unknowns,
        x: &[f64],
        rates: &[(f64, f64)],
        conditioning: Conditioning,
    ) -> std::result::Result<Corrected, String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        // The links' poses (their sines and cosines) once for the three
        // evaluations at the answer.
        let at = self.eq.poses(&u.q);
        let j = self.jacobian_at(&at, u.q.len());
        let lu = j.lu();
        let conditioning = match conditioning {
            Conditioning::Exact => self.scaled_conditioning(&j.dmatrix()),
            Conditioning::Decided(threshold) => self
                .conditioning_at_least(&j, &lu)
                .filter(|&c| c >= threshold)
                .unwrap_or_else(|| self.scaled_conditioning(&j.dmatrix())),
        };
        let orientation = lu.determinant().signum();
        // The three residuals, each at the answer itself, solved together
        // (the same bits as one by one, `Factors::solve_many`).
        let b = self.driver_rates(rates);
        let mut rhs: Sides = smallvec![self.eq.residual(&at, x)];
        if let Some(qd) = &u.qd {
            rhs.push(j.mul_sub(qd, &b));
            if let Some(qdd) = &u.qdd {
                let g = self.eq.gamma(&at, qd, &accelerations(rates));
                rhs.push(j.mul_sub(qdd, &g));
            }
        }
        if !lu.solve_many(&mut rhs) {
            return Err(singular());
        }
        let mut dx = rhs.into_iter();
        let mut next = |x: &Col| minus(x, &dx.next().expect("a residual each"));
        let q = next(&u.q);
        let qd = u.qd.as_ref().map(&mut next);
        let qdd = qd.as_ref().and(u.qdd.as_ref()).map(&mut next);
        Ok(Corrected {
            motion: self.motions(&q, qd.as_deref(), qdd.as_deref()),
            conditioning,
            orientation,
            factors: lu,
            poses: at,
        })
    }

    /// The answer `u` corrected by the equations of nearby mechanisms
    /// (the scene with its data changed by a few roundings, each at its
    /// own input coordinates; `scenes`), whose corrected answers are their
    /// own to first order: the positions by one Newton step, the rates at
    /// the corrected positions and velocities; the linear solves by the LU
    /// factors `near` of this mechanism's Jacobian instead of each one's
    /// own. The residuals are each mechanism's, and the change of the
    /// inverse (a few roundings of the data, times κ) enters only the
    /// correction of a residual itself of that size — second order, far
    /// below what the data check compares. `runs`: more rates of the same
    /// answer (the transfer functions' unit runs, each with its inputs'
    /// rates), corrected at the same positions. `near`: this mechanism's
    /// answer `u` corrected ([`Self::corrected`]), its factors and its
    /// links' poses at `u`. Each scene's motions and
    /// its runs', in order; the scenes' independent solves made together
    /// (`Factors::solve_many`: the same bits as one by one). Its vectors
    /// on the stack ([`Col`]): it runs at every position of a sweep.
    pub fn corrected_together(
        &self,
        scenes: &[(&Self, &[f64])],
        u: &Unknowns,
        rates: &[(f64, f64)],
        runs: &[(Unknowns, InputRates)],
        near: &Corrected,
    ) -> std::result::Result<Vec<(Motions, Vec<Motions>)>, String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        let solve = |mut rhs: Sides| match near.factors.solve_many(&mut rhs) {
            true => Ok(rhs),
            false => Err(singular()),
        };
        // Every run of the answer: the real rates first; each run's input
        // accelerations once for every scene.
        let all: SmallVec<[Run; 4]> = std::iter::once((u, rates))
            .chain(runs.iter().map(|(u, r)| (u, r.as_slice())))
            .collect();
        let accs: SmallVec<[Inputs; 2]> = all.iter().map(|(_, rates)| accelerations(rates)).collect();
        // The poses at `u` depend on the data only through the links'
        // slots, the same in every scene of one mechanism.
        let residual = |cs: &Self, x: &[f64]| match cs.eq.slot == self.eq.slot {
            true => cs.eq.residual(&near.poses, x),
            false => cs.eq.residual(&cs.eq.poses(&u.q), x),
        };
        let dq = solve(scenes.iter().map(|(cs, x)| residual(cs, x)).collect())?;
        let qs: SmallVec<[Col; 2]> = dq.iter().map(|d| minus(&u.q, d)).collect();
        // Each scene's poses at its corrected positions, once for its
        // Jacobian and every run's γ.
        let ats: SmallVec<[Poses<f64>; 2]> = scenes.iter().zip(&qs).map(|((cs, _), q)| cs.eq.poses(q)).collect();
        let js: SmallVec<[Jacobian; 2]> = scenes.iter().zip(&ats).map(|((cs, _), at)| cs.jacobian_at(at, u.q.len())).collect();
        // The velocities of every run of every scene.
        let mut rhs = Sides::new();
        for ((cs, _), j) in scenes.iter().zip(&js) {
            for (u, rates) in &all {
                if let Some(qd) = &u.qd {
                    rhs.push(j.mul_sub(qd, &cs.driver_rates(rates)));
                }
            }
        }
        let mut dqd = solve(rhs)?.into_iter();
        let mut qds: SmallVec<[SmallVec<[Option<Col>; 2]>; 2]> = SmallVec::new();
        for _ in scenes {
            qds.push(all.iter().map(|(u, _)| u.qd.as_ref().map(|qd| minus(qd, &dqd.next().expect("one a run")))).collect());
        }
        // … and their accelerations, at those velocities.
        let mut rhs = Sides::new();
        for ((((cs, _), j), at), qd) in scenes.iter().zip(&js).zip(&ats).zip(&qds) {
            for (((u, _), acc), qd_new) in all.iter().zip(&accs).zip(qd) {
                if let (Some(qdd), Some(qd_new)) = (&u.qdd, qd_new) {
                    let g = cs.eq.gamma(at, qd_new, acc);
                    rhs.push(j.mul_sub(qdd, &g));
                }
            }
        }
        let mut dqdd = solve(rhs)?.into_iter();
        let mut out = Vec::with_capacity(scenes.len());
        for (((cs, _), at), qd) in scenes.iter().zip(&ats).zip(&qds) {
            let mut motions = all.iter().zip(qd).map(|((u, _), qd)| {
                let qdd = match (&u.qdd, qd) {
                    (Some(qdd), Some(_)) => Some(minus(qdd, &dqdd.next().expect("one a run"))),
                    _ => None,
                };
                cs.motions_at(at, qd.as_deref(), qdd.as_deref())
            });
            let first = motions.next().expect("the real rates");
            out.push((first, motions.collect()));
        }
        Ok(out)
    }

    /// The drivers' rates as the right-hand side of Φ_q·q̇ = b.
    fn driver_rates(&self, rates: &[(f64, f64)]) -> Col {
        let mut b: Col = smallvec![0.0; self.rows()];
        for &(i, row) in &self.driver_rows {
            b[row] = rates[i].0;
        }
        b
    }

    /// A lower bound on [`ConstraintSolver::scaled_conditioning`] from the
    /// LU factors of the (unscaled) Jacobian `j`, without an SVD:
    /// 1/(‖J_s‖_F·‖J_s⁻¹‖_F), the scaled Jacobian J_s = R·J·G (rows R,
    /// columns G as there) and its inverse G⁻¹·J⁻¹·R⁻¹. Since ‖A‖₂ ≤
    /// ‖A‖_F ≤ √n·‖A‖₂ it lies between σ_min/σ_max over n and σ_min/σ_max
    /// (shrunk by 1e-8 of itself for the inverse's own rounding, far
    /// below where it is used). `None` where a column vanishes or the
    /// inverse does not exist.
    fn conditioning_at_least(&self, j: &Jacobian, lu: &Factors) -> Option<f64> {
        let rows = self.row_scales();
        let n = j.ncols();
        let mut g: Col = smallvec![1.0; n];
        for i in 0..self.eq.links.len() {
            g[3 * i + 2] = 1.0 / self.scale[i];
        }
        for (c, gc) in g.iter_mut().enumerate() {
            let norm = j
                .column(c)
                .iter()
                .zip(&rows)
                .map(|(x, r)| (x * r * *gc).powi(2))
                .sum::<f64>()
                .sqrt();
            if norm == 0.0 || !norm.is_finite() {
                return None;
            }
            *gc /= norm;
        }
        let mut f2 = 0.0;
        let inverse = lu.inverse_columns(|c, col| {
            if let Some(rc) = rows.get(c) {
                for (x, gr) in col.iter().zip(&g) {
                    f2 += (x / (gr * rc)).powi(2);
                }
            }
        });
        if !inverse {
            return None;
        }
        let bound = 1.0 / ((n as f64).sqrt() * f2.sqrt()) * (1.0 - 1e-8);
        bound.is_finite().then_some(bound)
    }

    /// The Jacobian ∂Φ/∂q at the links' poses `at` (`n` unknowns), on
    /// the stack where it is square and small ([`dense`]).
    fn jacobian_at(&self, at: &[PoseOf<f64>], n: usize) -> Jacobian {
        let mut j = match Square::zeros(n).filter(|_| self.rows() == n) {
            Some(j) => Stored::Stack(j),
            None => Stored::Heap(DMatrix::zeros(self.rows(), n)),
        };
        match &mut j {
            Stored::Stack(j) => self.eq.jacobian(at, |r, c, v| j.add(r, c, v)),
            Stored::Heap(j) => self.eq.jacobian(at, |r, c, v| j[(r, c)] += v),
        }
        Jacobian(j)
    }
}

/// A constraint Jacobian: on the stack ([`dense::Square`]) where it is
/// square and has at most [`dense::MAX`] unknowns, else nalgebra's; the
/// same numbers either way.
struct Jacobian(Stored<Square, DMatrix<f64>>);

/// One of two stores of the same numbers.
#[derive(Clone)]
enum Stored<S, H> {
    Stack(S),
    Heap(H),
}

impl Jacobian {
    /// Its LU factors (nalgebra's `LU::new`, to the bit).
    fn lu(&self) -> Factors {
        Factors(match &self.0 {
            Stored::Stack(j) => Stored::Stack(j.lu()),
            Stored::Heap(j) => Stored::Heap(j.clone().lu()),
        })
    }

    /// As nalgebra's matrix.
    fn dmatrix(&self) -> Cow<'_, DMatrix<f64>> {
        match &self.0 {
            Stored::Stack(j) => Cow::Owned(j.to_dmatrix()),
            Stored::Heap(j) => Cow::Borrowed(j),
        }
    }

    /// The number of unknowns.
    fn ncols(&self) -> usize {
        match &self.0 {
            Stored::Stack(j) => j.n(),
            Stored::Heap(j) => j.ncols(),
        }
    }

    /// Column `c`.
    fn column(&self, c: usize) -> &[f64] {
        match &self.0 {
            Stored::Stack(j) => j.column(c),
            Stored::Heap(j) => {
                let n = j.nrows();
                &j.as_slice()[c * n..(c + 1) * n]
            }
        }
    }

    /// J·x − b (nalgebra's `&j * x - b`, to the bit).
    fn mul_sub(&self, x: &[f64], b: &[f64]) -> Col {
        match &self.0 {
            Stored::Stack(j) => j.mul_sub(x, b),
            Stored::Heap(j) => {
                let (x, b) = (DVectorView::from_slice(x, x.len()), DVectorView::from_slice(b, b.len()));
                (j * x - b).iter().copied().collect()
            }
        }
    }
}

/// The LU factors of a constraint Jacobian: on the stack where it is
/// (`dense::Lu`), else nalgebra's; the same bits either way.
#[derive(Clone)]
pub struct Factors(Stored<Lu, nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>>);

impl std::fmt::Debug for Factors {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.0 {
            Stored::Stack(lu) => write!(f, "Factors(on the stack, {} unknowns)", lu.n()),
            Stored::Heap(lu) => write!(f, "Factors({lu:?})"),
        }
    }
}

impl Factors {
    /// Solves J·x = b for each b of `bs` in place: on the stack eight at a
    /// time ([`Lu::solve_rows`]: each column by the operations of a solve
    /// of its own, in the same order, so the same bits; their chains of
    /// dependent divisions overlap). False where J is singular.
    fn solve_many(&self, bs: &mut [Col]) -> bool {
        const AT_ONCE: usize = 8;
        match &self.0 {
            Stored::Stack(lu) => {
                let n = lu.n();
                let mut rows = [0.0; dense::MAX * AT_ONCE];
                for group in bs.chunks_mut(AT_ONCE) {
                    let k = group.len();
                    for (c, b) in group.iter().enumerate() {
                        for (r, x) in b.iter().enumerate() {
                            rows[r * k + c] = *x;
                        }
                    }
                    if !lu.solve_rows(&mut rows, k) {
                        return false;
                    }
                    for (c, b) in group.iter_mut().enumerate() {
                        for (r, x) in b.iter_mut().enumerate().take(n) {
                            *x = rows[r * k + c];
                        }
                    }
                }
                true
            }
            Stored::Heap(lu) => bs.iter_mut().all(|b| {
                let n = b.len();
                lu.solve_mut(&mut DVectorViewMut::from_slice(b, n))
            }),
        }
    }

    /// det J.
    fn determinant(&self) -> f64 {
        match &self.0 {
            Stored::Stack(lu) => lu.determinant(),
            Stored::Heap(lu) => lu.determinant(),
        }
    }

    /// `f` of each column of J⁻¹ in order; false (and `f` never called)
    /// where J is singular.
    fn inverse_columns(&self, mut f: impl FnMut(usize, &[f64])) -> bool {
        match &self.0 {
            Stored::Stack(lu) => {
                let n = lu.n();
                let mut inv = [0.0; dense::MAX * dense::MAX];
                if !lu.inverse_rows(&mut inv) {
                    return false;
                }
                let mut col = [0.0; dense::MAX];
                for c in 0..n {
                    for (r, x) in col[..n].iter_mut().enumerate() {
                        *x = inv[r * n + c];
                    }
                    f(c, &col[..n]);
                }
                true
            }
            Stored::Heap(lu) => match lu.try_inverse() {
                Some(inv) => {
                    for c in 0..inv.ncols() {
                        f(c, inv.column(c).as_slice());
                    }
                    true
                }
                None => false,
            },
        }
    }
}

impl ConstraintSolver<'_> {
    /// At the positions of `u`: σ_min/σ_max of the scaled Jacobian by its
    /// SVD, the lower bound [`Conditioning::Decided`] rests on, and the
    /// number of unknowns n (the bound is within a factor n). For tests.
    #[doc(hidden)]
    #[cfg(feature = "internals")]
    pub fn conditioning_both(&self, u: &Unknowns) -> (f64, Option<f64>, usize) {
        let j = self.jacobian_at(&self.eq.poses(&u.q), u.q.len());
        let bound = self.conditioning_at_least(&j, &j.lu());
        (self.scaled_conditioning(&j.dmatrix()), bound, j.ncols())
    }
}

/// Every solved link's motion (`None` for the others).
pub type Motions = Vec<Option<Motion>>;


/// What [`ConstraintSolver::corrected`] finds of the conditioning.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Conditioning {
    /// σ_min/σ_max of the scaled Jacobian, by its SVD.
    Exact,
    /// A lower bound on it where that bound is at least the threshold
    /// given (every comparison with the threshold or below decides as the
    /// exact value would), else the exact value.
    Decided(f64),
}

/// An answer in route (b)'s unknowns ([`ConstraintSolver::unknowns`]):
/// the poses, and the rates where the analysis has them.
#[derive(Clone, Debug)]
pub struct Unknowns {
    pub q: Col,
    pub qd: Option<Col>,
    pub qdd: Option<Col>,
}

/// An answer corrected by route (b)'s equations
/// ([`ConstraintSolver::corrected`]).
#[derive(Clone, Debug)]
pub struct Corrected {
    /// Every solved link's corrected motion (zero rates where the answer
    /// had none).
    pub motion: Vec<Option<Motion>>,
    /// σ_min/σ_max of the scaled Jacobian at the answer's positions (or
    /// the lower bound [`Conditioning::Decided`] allows).
    pub conditioning: f64,
    /// The sign of det Φ_q there: the orientation of the assembly, which
    /// changes only through a singular position.
    pub orientation: f64,
    /// The LU factors of Φ_q at the answer's positions: for
    /// [`ConstraintSolver::corrected_together`].
    pub factors: Factors,
    /// The links' poses at the answer's positions (their sines and
    /// cosines): for [`ConstraintSolver::corrected_together`].
    pub poses: Poses<f64>,
}
