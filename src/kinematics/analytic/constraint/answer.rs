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
        conditioning: bool,
    ) -> std::result::Result<Corrected, String> {
        let singular = || "the constraint Jacobian is singular".to_string();
        let j = self.jacobian(&u.q);
        let conditioning = if conditioning {
            self.scaled_conditioning(&j)
        } else {
            f64::NAN
        };
        let lu = j.clone().lu();
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
        })
    }
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
}
