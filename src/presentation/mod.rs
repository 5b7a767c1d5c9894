//! Presentation: reads a finished solution and writes it for people,
//! never solving again. What a sheet draws beyond the solved positions
//! comes solved: the positions' trajectories, the output's extreme
//! positions, the positions a course singles out (from the working
//! stroke) and the kinematic diagrams are data of the solution
//! ([`crate::studies::sheet_data::SheetData`]), solved by the study layer
//! for the sheets a request draws ([`drawing::sheet_needs`]) and only
//! drawn here (`tests/architecture.rs` checks that no file here names the
//! position solver, its solving items or a solving call). The result file and the terminal's table
//! ([`report`]), the tables of results as data, for the terminal and the
//! handout alike ([`tables`]), the sheets and the handout ([`drawing`]),
//! the force analysis in the result ([`dynamics`]) and in steps
//! ([`force_steps`]), a check's verdict as text and JSON ([`verdict`])
//! and its overlay drawing ([`overlay`]), a group of answers' gradebook and summary page
//! ([`gradebook`]), the work-precision report's table and plot
//! ([`precision`]), the studies' tables ([`studies`]).

pub mod drawing;
pub mod dynamics;
pub mod force_steps;
pub mod gradebook;
pub mod force_overlay;
pub mod overlay;
pub mod photo_overlay;
pub mod precision;
pub mod report;
mod steps;
pub mod studies;
pub mod tables;
mod text_table;
pub mod verdict;

/// The number of the sweep's position `k` (counted from 0), as every
/// output writes it and every input reads it: in the study's numbering
/// ([`crate::kinematics::solve::Analysis::numbering`]), by default the
/// scene's — a `count` sweep from 0 (the lecture's: position 0 is the start
/// of the working stroke, as the diagrams' axis 0 … n on the same sheet
/// counts), the input values given (`angles`, `s`, `values`) from 1.
pub(crate) fn position_number(an: &crate::kinematics::solve::Analysis, k: usize) -> usize {
    an.numbering.number(k)
}
