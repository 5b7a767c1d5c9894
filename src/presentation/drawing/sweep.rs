//! The positions the sheets draw ([`Sweep`]): held in memory, or solved
//! again by the study layer each time the sheets read them all (a long
//! sweep: memory flat in the number of positions). Presentation never
//! solves: it only asks the sweep for its positions.

use crate::error::{Error, Result};
use crate::kinematics::positions::Configuration;
use crate::pipeline::Solved;

/// The positions of a study, as the sheets read them.
pub trait Sweep {
    /// How many positions.
    fn len(&self) -> usize;
    /// Whether there are none.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Position `k` (from 0) where it is at hand: every one held, else
    /// the first and the one the positions sheet draws bold.
    fn get(&self, k: usize) -> Option<&Solved>;
    /// Every position's configuration, in order.
    fn configs(&self) -> Vec<&Configuration>;
    /// Every position in order that `want` names (by index, from 0), each
    /// handed to `f` (solved again where they are not held, and dropped
    /// after).
    fn each(
        &self,
        want: &dyn Fn(usize) -> bool,
        f: &mut dyn FnMut(usize, &Solved) -> Result<()>,
    ) -> Result<()>;
    /// [`Sweep::each`], where the positions may come lean
    /// ([`Solved::lean`]: of their plans, the rates only, as the plan of
    /// the mechanism reads them).
    fn each_lean(&self, f: &mut dyn FnMut(usize, &Solved) -> Result<()>) -> Result<()> {
        self.each(&|_| true, f)
    }
    /// Every position at once, where they are held (the sheets that read
    /// all of them together: the course sheet, the plans at scales the
    /// scene fixes).
    fn held(&self) -> Option<&[Solved]>;
}

impl Sweep for &[Solved] {
    fn len(&self) -> usize {
        <[Solved]>::len(self)
    }
    fn get(&self, k: usize) -> Option<&Solved> {
        <[Solved]>::get(self, k)
    }
    fn configs(&self) -> Vec<&Configuration> {
        self.iter().map(|s| &s.config).collect()
    }
    fn each(
        &self,
        want: &dyn Fn(usize) -> bool,
        f: &mut dyn FnMut(usize, &Solved) -> Result<()>,
    ) -> Result<()> {
        let mut wanted = self.iter().enumerate().filter(|(k, _)| want(*k));
        wanted.try_for_each(|(k, s)| f(k, s))
    }
    fn held(&self) -> Option<&[Solved]> {
        Some(self)
    }
}

impl Sweep for Vec<Solved> {
    fn len(&self) -> usize {
        <[Solved]>::len(self)
    }
    fn get(&self, k: usize) -> Option<&Solved> {
        <[Solved]>::get(self, k)
    }
    fn configs(&self) -> Vec<&Configuration> {
        self.iter().map(|s| &s.config).collect()
    }
    fn each(
        &self,
        want: &dyn Fn(usize) -> bool,
        f: &mut dyn FnMut(usize, &Solved) -> Result<()>,
    ) -> Result<()> {
        let mut wanted = self.iter().enumerate().filter(|(k, _)| want(*k));
        wanted.try_for_each(|(k, s)| f(k, s))
    }
    fn held(&self) -> Option<&[Solved]> {
        Some(self)
    }
}

/// Position `k` of `sweep`, which the caller keeps at hand; an internal
/// error if it does not.
pub(super) fn at(sweep: &dyn Sweep, k: usize) -> Result<&Solved> {
    sweep
        .get(k)
        .ok_or_else(|| Error::Internal(format!("position {k} of the sweep is not held")))
}

/// Every position of `sweep` at once; an internal error where the caller
/// did not hold them for a sheet that reads them together.
pub(super) fn held(sweep: &dyn Sweep) -> Result<&[Solved]> {
    sweep.held().ok_or_else(|| {
        Error::Internal("a sheet that reads every position at once needs them held".into())
    })
}
