//! The data check to first order (the fast path's), and the data check of
//! the transfer functions (φ', φ'', v_q, a_q): how far
//! the scene's data changed by a few units of rounding (the input moved by
//! as many units of its own rounding) move them, measured on the transfer
//! functions themselves.
//!
//! The real rates do not stand in for them: ε_n = ω1²·φ''_n + ε1·φ'_n, and
//! where ε1 outweighs ω1² (a slow crank, a start) or the two terms of a
//! change cancel, the relative change of the real accelerations can be
//! many times smaller than that of φ''. A `count` start near a toggle is
//! such a place: its own error moves φ'' by φ'''·δq, and φ''' is large
//! there (issue 41: the rod's φ'' printed 2.6× and 10.4× beyond its bound
//! at starts 1e-9 and 1e-10 of the rod from a slider-crank's toggle).

use super::compare::Mine;
use super::crosscheck::{ChangedData, DATA_PERTURBATION, Residuals};
use crate::kinematics::analytic::constraint::{ConstraintSolver, Corrected, Unknowns};
use crate::kinematics::analytic::{Coords, Drives, InputRates, Motion, Order, contour};
use smallvec::SmallVec;
use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::{Analysis, Position};

/// A unit run: inputs i (and j) at unit rate, with its motions.
type Run<'a> = ((usize, Option<usize>), &'a [Option<Motion>]);

/// The unit drives of the transfer functions a position keeps, in the
/// order of [`Position::analogue`], [`Position::more_analogues`] and
/// [`Position::mixed`]: input i at unit rate (and input j with it), the
/// others standing; with each run's motions.
fn transfer_runs(s: &Position) -> SmallVec<[Run<'_>; 4]> {
    let w = s.drives.len();
    let mut out = SmallVec::new();
    if s.analogue.iter().all(Option::is_none) {
        return out;
    }
    out.push(((0, None), &s.analogue));
    for (i, mo) in s.more_analogues.iter().enumerate() {
        out.push(((i + 1, None), mo));
    }
    let pairs = (0..w).flat_map(|i| (i + 1..w).map(move |j| (i, Some(j))));
    for (ij, mo) in pairs.zip(&s.mixed) {
        out.push((ij, mo));
    }
    out
}

/// The input rates of a unit run: (1, 0) for inputs i and j, (0, 0) for
/// the others.
fn unit_rates(n: usize, (i, j): (usize, Option<usize>)) -> InputRates {
    (0..n)
        .map(|k| (if k == i || Some(k) == j { 1.0 } else { 0.0 }, 0.0))
        .collect()
}

impl Analysis {
    /// The data sensitivity to first order: route (b)'s equations of each
    /// changed scene (the input moved too, as [`Analysis::data_sensitivity`]
    /// moves it) at route (a)'s answer `u`, corrected by one step, and
    /// compared with the answer (`mine`: its real rates made ready for
    /// comparisons) as the data check compares; the solves by the scene's
    /// own factors `near`; the transfer functions' runs at the same
    /// corrected positions (`ConstraintSolver::corrected_together`, both
    /// scenes at once). `None` where a changed scene is refused or its
    /// Jacobian singular (the solve again decides).
    pub(super) fn linear_sensitivity(
        &self,
        mine: &Mine,
        u: &Unknowns,
        eqs: &Residuals,
        near: &Corrected,
        q_rounding: Coords,
        changed: &ChangedData,
    ) -> Option<(f64, f64)> {
        let s = mine.position();
        let units = DATA_PERTURBATION / f64::EPSILON;
        let rates = self.input_rates();
        // The transfer functions' runs in route (b)'s unknowns, corrected
        // at the same positions as the real rates (on the stack the one run
        // of a mechanism with one input: a few hundred bytes each).
        let transfer_runs = transfer_runs(s);
        let runs: SmallVec<[(Unknowns, InputRates); 1]> = transfer_runs
            .iter()
            .map(|&(ij, mine)| {
                let u = eqs.base.unknowns(|l| s.config.pose(l), mine, self.order);
                (u, unit_rates(s.drives.len(), ij))
            })
            .collect();
        let mut scenes: SmallVec<[_; 2]> = SmallVec::new();
        for ((cs, an), sign) in eqs.changed.iter().zip(changed).zip([1.0, -1.0]) {
            let (Some(cs), Ok(an)) = (cs, an) else {
                return None;
            };
            let mut x = s.drives.coords();
            for (x, r) in x.iter_mut().zip(q_rounding.iter()) {
                *x += sign * units * r;
            }
            scenes.push((cs, an, x));
        }
        let with_x: SmallVec<[(&ConstraintSolver, &[f64]); 2]> =
            scenes.iter().map(|(cs, _, x)| (*cs, &x[..])).collect();
        let moved = eqs.base.corrected_together(&with_x, u, &rates, &runs, near).ok()?;
        let (mut worst, mut transfer) = (0.0f64, 0.0f64);
        let mine_runs: SmallVec<[Mine; 1]> = transfer_runs
            .iter()
            .map(|&(_, run)| self.mine(s, run))
            .collect();
        for ((_, an, _), (motion, moved)) in scenes.iter().zip(&moved) {
            // A NaN is no sensitivity (f64::max would drop it): refused,
            // so that the position falls back to the full solve.
            let (d, _) = self.compare_most(mine, motion, &an.mech);
            if d.is_nan() {
                return None;
            }
            worst = worst.max(d);
            for (mine, other) in mine_runs.iter().zip(moved) {
                let t = self.compare_most(mine, other, &an.mech).0;
                if t.is_nan() {
                    return None;
                }
                transfer = transfer.max(t);
            }
        }
        Some((worst, transfer))
    }

    /// The largest relative change of the transfer functions of `s` on
    /// the changed scene `an` placed at `c` (route (a) solved again with
    /// unit drives), each run against its own scale as the cross-check
    /// compares the real rates.
    pub(super) fn transfer_moved(
        &self,
        s: &Position,
        an: &Analysis,
        c: &Configuration,
        drives: Drives,
        order: Order,
    ) -> std::result::Result<f64, String> {
        let mut worst = 0.0f64;
        for ((i, j), mine) in transfer_runs(s) {
            let other = contour::solve(&an.mech, &an.structure, &an.need, c, drives.unit(i, j), order)
                .map_err(|e| e.to_string())?;
            let (d, _) = self.compare_with(s, mine, &other, &an.mech);
            if d > worst || d.is_nan() {
                worst = d;
            }
        }
        Ok(worst)
    }

}
