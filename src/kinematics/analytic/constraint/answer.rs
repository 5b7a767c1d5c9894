//! An answer found otherwise (route (a)'s, a student's) put to route
//! (b)'s equations: its unknowns, and the answer corrected by them.

use super::ConstraintSolver;
use crate::geom::Pose;
use crate::kinematics::analytic::{Motion, Order};
use nalgebra::DVector;

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
        let mut q = DVector::zeros(n);
        let (mut qd, mut qdd) = (DVector::zeros(n), DVector::zeros(n));
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
    /// its own; with `relinearize` at the corrected ones instead (an
    /// answer of a slightly different mechanism: the scene with its data
    /// changed, whose corrected answer is its own to first order). With
    /// `conditioning`, the scaled conditioning of Φ_q at the answer's
    /// positions (else NaN).
    pub fn corrected(
        &self,
        u: &Unknowns,
        x: &[f64],
        rates: &[(f64, f64)],
        relinearize: bool,
        conditioning: Conditioning,
    ) -> std::result::Result<Corrected, String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        let j = self.jacobian(&u.q);
        let lu = j.clone().lu();
        let conditioning = match conditioning {
            Conditioning::Exact => self.scaled_conditioning(&j),
            Conditioning::Decided(threshold) => self
                .conditioning_at_least(&j, &lu)
                .filter(|&c| c >= threshold)
                .unwrap_or_else(|| self.scaled_conditioning(&j)),
        };
        let orientation = lu.determinant().signum();
        let q = &u.q - lu.solve(&self.residual(&u.q, x)).ok_or_else(singular)?;
        let (j, lu, at) = if relinearize {
            let j = self.jacobian(&q);
            (j.clone(), j.lu(), &q)
        } else {
            (j, lu, &u.q)
        };
        let mut b = DVector::zeros(self.rows());
        for &(i, row) in &self.driver_rows {
            b[row] = rates[i].0;
        }
        let qd = match &u.qd {
            Some(qd) => Some(qd - lu.solve(&(&j * qd - b)).ok_or_else(singular)?),
            None => None,
        };
        let qdd = match (&u.qdd, &u.qd, &qd) {
            (Some(qdd), Some(qd_own), Some(qd_new)) => {
                let acc: Vec<f64> = rates.iter().map(|r| r.1).collect();
                let g = self.gamma(at, if relinearize { qd_new } else { qd_own }, &acc);
                Some(qdd - lu.solve(&(&j * qdd - g)).ok_or_else(singular)?)
            }
            _ => None,
        };
        Ok(Corrected {
            motion: self.motions(&q, qd.as_ref(), qdd.as_ref()),
            conditioning,
            orientation,
            factors: (!relinearize).then_some(lu),
        })
    }

    /// As [`Self::corrected`] with `relinearize`, the linear solves by the
    /// LU factors `near` of a nearby mechanism's Jacobian (the scene before
    /// its data were changed by a few roundings) instead of this one's
    /// own: the residuals are this mechanism's, so the corrected answer is
    /// its own to first order, and the change of the inverse (a few
    /// roundings of the data, times κ) enters only the correction of a
    /// residual itself of that size — second order, far below what the
    /// data check compares.
    pub fn corrected_runs_by(
        &self,
        u: &Unknowns,
        x: &[f64],
        rates: &[(f64, f64)],
        runs: &[(Unknowns, Vec<(f64, f64)>)],
        near: &Factors,
    ) -> std::result::Result<(Corrected, Vec<Motions>), String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        let q = &u.q - near.solve(&self.residual(&u.q, x)).ok_or_else(singular)?;
        let j = self.jacobian(&q);
        let motion = self.rates_by(&q, &j, u, rates, near)?;
        let runs = runs
            .iter()
            .map(|(u, rates)| self.rates_by(&q, &j, u, rates, near))
            .collect::<std::result::Result<Vec<_>, _>>()?;
        let corrected = Corrected {
            motion,
            conditioning: f64::NAN,
            orientation: f64::NAN,
            factors: None,
        };
        Ok((corrected, runs))
    }

    /// The rates of `u` corrected at the positions `q` (Jacobian `j`) by
    /// the factors `near`, with each input's (rate, rate of rate).
    fn rates_by(
        &self,
        q: &DVector<f64>,
        j: &nalgebra::DMatrix<f64>,
        u: &Unknowns,
        rates: &[(f64, f64)],
        near: &Factors,
    ) -> std::result::Result<Vec<Option<Motion>>, String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        let mut b = DVector::zeros(self.rows());
        for &(i, row) in &self.driver_rows {
            b[row] = rates[i].0;
        }
        let qd = match &u.qd {
            Some(qd) => Some(qd - near.solve(&(j * qd - b)).ok_or_else(singular)?),
            None => None,
        };
        let qdd = match (&u.qdd, &qd) {
            (Some(qdd), Some(qd_new)) => {
                let acc: Vec<f64> = rates.iter().map(|r| r.1).collect();
                let g = self.gamma(q, qd_new, &acc);
                Some(qdd - near.solve(&(j * qdd - g)).ok_or_else(singular)?)
            }
            _ => None,
        };
        Ok(self.motions(q, qd.as_ref(), qdd.as_ref()))
    }
}

impl ConstraintSolver<'_> {
    /// At the positions of `u`: σ_min/σ_max of the scaled Jacobian by its
    /// SVD, the lower bound [`Conditioning::Decided`] rests on, and the
    /// number of unknowns n (the bound is within a factor n). For tests.
    #[doc(hidden)]
    #[cfg(feature = "internals")]
    pub fn conditioning_both(&self, u: &Unknowns) -> (f64, Option<f64>, usize) {
        let j = self.jacobian(&u.q);
        let lu = j.clone().lu();
        let bound = self.conditioning_at_least(&j, &lu);
        (self.scaled_conditioning(&j), bound, j.ncols())
    }
}

/// Every solved link's motion (`None` for the others).
pub type Motions = Vec<Option<Motion>>;

/// The LU factors of a constraint Jacobian.
pub type Factors = nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>;

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
    pub q: DVector<f64>,
    pub qd: Option<DVector<f64>>,
    pub qdd: Option<DVector<f64>>,
}

/// An answer corrected by route (b)'s equations
/// ([`ConstraintSolver::corrected`]).
#[derive(Clone, Debug)]
pub struct Corrected {
    /// Every solved link's corrected motion (zero rates where the answer
    /// had none).
    pub motion: Vec<Option<Motion>>,
    /// σ_min/σ_max of the scaled Jacobian at the answer's positions (NaN
    /// when not asked for).
    pub conditioning: f64,
    /// The sign of det Φ_q there: the orientation of the assembly, which
    /// changes only through a singular position.
    pub orientation: f64,
    /// The LU factors of Φ_q at the answer's positions (without
    /// `relinearize`): for [`ConstraintSolver::corrected_runs_by`].
    pub factors: Option<Factors>,
}
