//! A run whose positions' scales are chosen from them all: every position
//! solved once, then the few whose plans a sheet shows at scales found
//! by composing it (the course sheet's) finished again at them.

use super::{Analysis, Solved};
use crate::error::Result;
use crate::kinematics::solve::ScalesAt;
use std::cell::RefCell;
use std::sync::Arc;

impl Analysis {
    /// Every position solved (as [`Analysis::run`], telling `progress`),
    /// then some of them finished again at scales chosen from them all:
    /// `keep`, of the number of positions, names the positions (from 0)
    /// that may be; `scales`, from every position solved, fixes the
    /// scales of single positions ([`Analysis::scales_at`]: the course
    /// sheet's, found by composing it), and the positions it names are
    /// finished again at them — their plans built, checked and measured
    /// there, as a run of the analysis with those scales gives them (the
    /// positions are found once; only a position's finishing depends on
    /// its scales). The positions, and the scales fixed.
    pub fn run_rescaled(
        &self,
        progress: &dyn crate::progress::Progress,
        keep: &dyn Fn(usize) -> Vec<usize>,
        scales: impl FnOnce(&[Solved]) -> Result<ScalesAt>,
    ) -> Result<(Vec<Solved>, Arc<ScalesAt>)> {
        let out = RefCell::new(Vec::new());
        let mut fixed = Arc::default();
        self.run_kept(
            progress,
            keep,
            |s| {
                out.borrow_mut().push(s);
                Ok(())
            },
            |again| {
                let mut out = out.borrow_mut();
                let at = scales(&out)?;
                let mut an = self.clone();
                an.scales_at = Arc::new(at);
                // (A position the scene's `want.plans_at` names beyond
                // the last has no plan to draw, nor to finish again.)
                let n = out.len();
                for &k in an.scales_at.keys().filter(|&&k| k < n) {
                    out[k] = again(&an, k)?;
                }
                fixed = an.scales_at;
                Ok(())
            },
        )?;
        Ok((out.into_inner(), fixed))
    }

}
