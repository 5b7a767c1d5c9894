#![warn(missing_docs)]
//! mechplan: graphoanalytic kinematic analysis of planar linkages — the
//! plan of a mechanism, its plans of velocities and accelerations as the
//! constructions of a TMM course, cross-checked at every position by two
//! analytic routes, and (with masses and loads) the force analysis.
//!
//! The front door is a [`Study`]: a scene file read and made ready. It
//! solves every position ([`Study::solve`], or one at a time with flat
//! memory: [`Study::positions`]), whose points and links read by name;
//! writes the result files to any `io::Write` ([`Study::write_results`]);
//! draws the lecture's sheets ([`Solution::sheets`] as SVG text,
//! [`Study::draw`] into a folder); and checks a student's hand-drawn plan
//! ([`Study::check_answer`]), or a whole group of them into a gradebook
//! ([`check_group`]). The library never prints; the `mechplan` command
//! does.
//!
//! ```
//! use mechplan::Study;
//!
//! let study = Study::from_json(mechplan::DEFAULT_SCENE)?;
//! let solution = study.solve()?;
//! let b = solution.position(3)?.point("B")?;
//! let v = b.velocity().expect("the scene asks for velocities");
//! println!("v_B = {:.3} m/s at ({:.3}, {:.3})", v.hypot(), b.place().x, b.place().y);
//! # Ok::<(), mechplan::Error>(())
//! ```
//!
//! Features: `render` (PNG and PDF sheets) and `cli` (the command) are on
//! by default; `default-features = false` builds the analysis alone.
//! Inside, the modules follow the method's data flow, one direction only
//! (docs/architecture.md): base → model → kinematics → kinetostatics,
//! studies, verification → pipeline → words → grading → presentation →
//! study (this front door).

/// The data-flow modules: private to the API, public to the project's own
/// tests, benches and fuzz targets with the `internals` feature (no
/// stability promised there).
macro_rules! internal_modules {
    ($($name:ident),* $(,)?) => {$(
        #[cfg(feature = "internals")]
        #[doc(hidden)]
        pub mod $name;
        #[cfg(not(feature = "internals"))]
        mod $name;
    )*};
}

// Base, then the layers from the lowest (docs/architecture.md).
internal_modules!(
    format,
    geom,
    json,
    progress,
    model,
    kinematics,
    kinetostatics,
    studies,
    verification,
    pipeline,
    words,
    grading,
    presentation,
);

pub mod accuracy;
pub mod error;
pub mod lang;
pub mod study;

// The paths of the first, flat layout, kept for the project's tests,
// benches and fuzz targets.
#[cfg(feature = "internals")]
#[doc(hidden)]
pub use scene::Scene;
#[cfg(feature = "internals")]
#[doc(hidden)]
pub use {
    grading as check,
    kinematics::{analytic, compiled, construction, positions, solve},
    model::{mechanism, scene, shape, structure},
    pipeline::Solved,
    presentation::{drawing, report},
    solve::Analysis,
    studies::{centres, diagrams, frenet, invariants},
    verification::{precision, reference},
};

pub use error::{Error, Issue, Result};
pub use kinematics::construction::PlanKind;
pub use kurbo::{Point, Vec2};
pub use lang::Lang;
pub use model::scene::Numbering;
pub use presentation::drawing::{Format, Sheet, SheetKind, SheetSize};
pub use progress::{Progress, Silent};
pub use study::DEFAULT_SCENE;
pub use study::files::{Spool, write_atomically};
pub use study::{
    Centres, CheckRequest, Checked, Diagram, DrawRequest, Grade, GradeRow, Graded, Invariants,
    LinkResult, PointResult, PositionResult, Positions, PrecisionReport, Results, Solution, Study,
    Totals, Written, check_file, check_group, frenet,
};
pub use verification::precision::Settings as PrecisionSettings;

/// The README's Rust examples, run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
