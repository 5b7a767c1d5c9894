#![warn(missing_docs)]
//! mechplan: graphoanalytic kinematic analysis of planar linkages.
//!
//! The modules follow the data flow of the method of a TMM course
//! (docs/architecture.md): [`model`] (the scene file, rigid links, Assur
//! groups) → [`kinematics`] (positions, two analytic routes, the plans as
//! constructions, the analysis of a scene's positions) → [`kinetostatics`]
//! (the force analysis, with the scene's `dynamics`) → [`studies`]
//! (centres, invariants, diagrams) and [`verification`] (checking
//! hand-drawn plans, the extended-precision reference) → [`presentation`]
//! (result files, tables, sheets).

// The library's internals, by the data flow (docs/architecture.md):
// public for the tests, benches and fuzz targets, hidden from the API.
#[doc(hidden)]
pub mod grading;
#[doc(hidden)]
pub mod kinematics;
#[doc(hidden)]
pub mod kinetostatics;
#[doc(hidden)]
pub mod model;
#[doc(hidden)]
pub mod pipeline;
#[doc(hidden)]
pub mod presentation;
#[doc(hidden)]
pub mod studies;
#[doc(hidden)]
pub mod verification;

#[doc(hidden)]
pub mod format;
#[doc(hidden)]
pub mod geom;
#[doc(hidden)]
pub mod json;
pub mod lang;
#[doc(hidden)]
pub mod progress;
#[doc(hidden)]
pub mod words;

pub mod accuracy;
pub mod error;
pub mod study;

// The paths of the first, flat layout, kept: tests, benches and fuzz
// targets reach the internals by them.
#[doc(hidden)]
pub use grading as check;
#[doc(hidden)]
pub use kinematics::{analytic, compiled, construction, positions, solve};
#[doc(hidden)]
pub use model::{mechanism, scene, shape, structure};
#[doc(hidden)]
pub use presentation::{drawing, report};
#[doc(hidden)]
pub use studies::{centres, diagrams, frenet, invariants};
pub use verification::{precision, reference};

pub use error::{Error, Issue, Result};
pub use pipeline::Solved;
pub use scene::Scene;
pub use solve::Analysis;
pub use study::{DrawRequest, Results, Solution, Study};

/// The embedded default scene: the lecture's six-link mechanism (Fig. 2.10).
pub const DEFAULT_SCENE: &str = include_str!("../fixtures/six_link_fig2_10.json");

pub use study::files::write_atomically;
