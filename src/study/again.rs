//! A sweep drawn without holding its positions ([`Again`]): the sheets
//! that share scales (the mechanism's μ_l and the box every position's
//! drawing is centred on, the positions sheet) read every position before
//! the first is drawn, so the positions are solved again each time the
//! sheets read them all, each dropped as soon as it is read. What is kept
//! between the runs is a few numbers a position: its input and its
//! configuration (the extent, the positions sheet, the trajectories), and
//! whole only the first position and the one drawn bold. Each run holds
//! a chunk of positions in flight, lean ([`Solved::lean`]): a position's
//! own sheets get its plans built again when its turn comes
//! ([`Analysis::plans_again`]: the same plans to the bit).

use super::files;
use super::solution::{Solution, finish, staged_sheets};
use super::{DrawRequest, Study, Written};
use crate::error::{Error, Result};
use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::presentation::drawing::Sweep;
use crate::studies::chosen::Chosen;
use crate::studies::sheet_data::SheetData;
use crate::studies::trajectories::Sketch;

impl Study {
    /// Draw the sheets (or the handout) into `req.dir`: the files written
    /// and the notes for the user.
    pub fn draw(&self, req: &DrawRequest) -> Result<Written> {
        req.validate()?;
        // A folder that cannot be written fails now, not after the sweep.
        files::check_writable(&req.dir, &req.dir)?;
        // The pipeline run once, the positions held, where a sheet reads
        // them all at once (the course sheet's scales chosen from it);
        // else run again for each reading of the sweep, none held.
        let (study, solved) = self.solved_for_sheets(req)?;
        match solved {
            Some(solved) => Solution::new(&study, solved).draw_dropped(req),
            None => draw(&study, req),
        }
    }
}

/// The positions of a study, solved again each time they are read
/// ([`Sweep::each`]), with what a first run kept of them.
pub(super) struct Again<'a> {
    study: &'a Study,
    /// The study's analysis making its positions lean as it finishes them.
    lean: Analysis,
    /// Each position's input and configuration.
    sketches: Vec<Sketch>,
    /// The first position (which drawings a scene asks for by default)
    /// and the one the positions sheet draws bold, with its index; held
    /// lean ([`Solved::lean`]).
    first: Solved,
    bold: (usize, Solved),
}

impl<'a> Again<'a> {
    /// A first run over the positions of `study`, each dropped as soon as
    /// what the sweep keeps of it is taken.
    pub(super) fn of(study: &'a Study) -> Result<Again<'a>> {
        study.held()?;
        let mut an = (*study.analysis).clone();
        an.lean = true;
        let n = an.mech.scene.positions.count();
        let bold_at = Chosen::of(&an, n).analysed(n);
        let mut sketches = Vec::with_capacity(n);
        let (mut first, mut bold) = (None, None);
        study.each_of(&an, |s| {
            let k = sketches.len();
            sketches.push(Sketch {
                q: s.q,
                config: s.config.clone(),
            });
            if k == 0 {
                first = Some(s.clone());
            }
            if k == bold_at {
                bold = Some(s);
            }
            Ok(())
        })?;
        match (first, bold) {
            (Some(first), Some(bold)) if sketches.len() == n => Ok(Again {
                study,
                lean: an,
                sketches,
                first,
                bold: (bold_at, bold),
            }),
            _ => Err(Error::Internal(format!(
                "the sweep of {n} positions gave {}",
                sketches.len()
            ))),
        }
    }
}

impl Sweep for Again<'_> {
    fn len(&self) -> usize {
        self.sketches.len()
    }
    fn get(&self, k: usize) -> Option<&Solved> {
        match k {
            0 => Some(&self.first),
            k if k == self.bold.0 => Some(&self.bold.1),
            _ => None,
        }
    }
    fn configs(&self) -> Vec<&Configuration> {
        self.sketches.iter().map(|s| &s.config).collect()
    }
    fn each(
        &self,
        want: &dyn Fn(usize) -> bool,
        f: &mut dyn FnMut(usize, &Solved) -> Result<()>,
    ) -> Result<()> {
        let an = &*self.study.analysis;
        self.each_lean(&mut |k, held| {
            if !want(k) {
                return Ok(());
            }
            let mut s = held.clone();
            s.position.plans = an.plans_again(k, held)?.map(Box::new);
            f(k, &s)
        })
    }
    fn each_lean(&self, f: &mut dyn FnMut(usize, &Solved) -> Result<()>) -> Result<()> {
        let mut k = 0;
        self.study.each_of(&self.lean, |s| {
            f(k, &s)?;
            k += 1;
            Ok(())
        })
    }
    fn held(&self) -> Option<&[Solved]> {
        None
    }
}

/// The sheets `req` asks for of `study` drawn into `req.dir`, no position
/// held ([`Again`]).
fn draw(study: &Study, req: &DrawRequest) -> Result<Written> {
    let sweep = Again::of(study)?;
    let an = &*study.analysis;
    let data = |needs| SheetData::solve(an, &sweep.sketches, needs);
    let (writer, notes) = staged_sheets(study, &sweep, &data, req)?;
    drop(sweep);
    finish(writer, notes)
}
