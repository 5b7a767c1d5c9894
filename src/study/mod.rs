//! The library's front door: a [`Study`] is a scene read and made ready;
//! it solves, reports, draws and checks. Everything the `mechplan` command
//! does is one call here, so another program does it the same way. This
//! is the only module that reads or writes files; the library never
//! prints (the command does, `src/terminal.rs`).
//!
//! ```
//! use mechplan::Study;
//!
//! // The lecture's six-link mechanism, embedded in the crate.
//! let study = Study::from_json(mechplan::DEFAULT_SCENE)?;
//! let solution = study.solve()?;
//! // The slider D's velocity at the first position (position 0: the
//! // scene's twelve positions are numbered from 0, as its sheets are),
//! // by route (a) …
//! let d = solution.position(0)?.point("D")?;
//! let v = d.velocity().expect("the scene asks for velocities");
//! // … and as measured on the velocity plan: the same, within its bound.
//! let measured = d.measured_velocity().expect("the scene asks for plans");
//! assert!((v - measured).hypot() < 1e-9);
//! // The result file, as `mechplan solve --format json` writes it.
//! let json = solution.to_json();
//! assert_eq!(json["mechplan"], 1);
//! # Ok::<(), mechplan::Error>(())
//! ```
//!
//! Parameters that the command line shows as options are named here by
//! their bare names (`output`, `position`, `sheet` …) in [`crate::Issue`]s.

mod again;
mod check_file;
pub mod files;
mod group;
mod prepared;
mod reads;
mod sheets;
mod solution;
mod studies;

/// The verdicts of a checked answer, by name: what a [`Checked`] holds
/// ([`KinematicCheck::report`], [`Checked::Force`], a photographed
/// plan's [`KinematicCheck::photo`]).
pub mod verdict {
    pub use crate::grading::forces::{ForceMistake, ForceReport};
    pub use crate::grading::photo::{PhotoReading, Snapped};
    pub use crate::grading::{
        Candidate, Diagnosis, Elsewhere, Found, Grade, Judgement, Report, SecondOpinion,
        StepReport, StepVerdict, Verdict,
    };
}

/// A plan of velocities or accelerations as built, by name: the plans a
/// verdict compares with ([`verdict::Report`]), their points, lines and
/// steps, and the typical mistakes a wrong plan is explained by.
pub mod plan {
    pub use crate::kinematics::construction::plan::{Known, Quantity, Step};
    pub use crate::kinematics::construction::{
        Dir, Field, Judged, Measured, Mistake, Op, Plan, PlanLine, PlanPoint, PointId, Why,
    };
}

/// The studies' results as typed records, by name: what [`Centres`] and
/// [`Invariants`] give besides their table and JSON (the same numbers, in
/// the units the files use).
pub mod records {
    pub use crate::presentation::studies::{
        CentresAt, InstantCentre, PeakConstants, PhaseRecord, UndeterminedCentre,
    };
}

pub use check_file::check_file;
pub use group::{GRADEBOOK, Graded, OVERLAYS, SUMMARY, check_group, is_group};
pub use prepared::{DEFAULT_SCENE, DrawRequest, Results, Study, read};
pub use sheets::{SheetWriter, Written, write_sheets};
pub use solution::{LinkResult, PointResult, PositionResult, Positions, Solution};
pub use studies::{
    Centres, CheckRequest, Checked, Diagram, Invariants, KinematicCheck, PrecisionReport,
};

pub use crate::error::in_file;
pub use crate::presentation::gradebook::{Counts, Grade, GradeRow, Totals};

use crate::error::{Error, Result};
use crate::presentation::drawing::{self, DrawOptions};
use std::path::Path;

/// positions at `count` segments per revolution, written into `dir`.
pub fn frenet(dir: &Path, format: drawing::Format, count: usize) -> Result<Written> {
    if !(2..=10_000).contains(&count) {
        return Err(Error::scene("count", "must be from 2 to 10000 segments"));
    }
    let sheets = drawing::frenet::sheets(count, &DrawOptions::default());
    write_sheets(&sheets, dir, format, 150.0)
}
