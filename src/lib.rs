//! mechplan: graphoanalytic kinematic analysis of planar linkages.
//!
//! The modules follow the data flow of the method of a TMM course
//! (docs/architecture.md): [`model`] (the scene file, rigid links, Assur
//! groups) → [`kinematics`] (positions, two analytic routes, the plans as
//! constructions, the analysis of a scene's positions) → [`studies`]
//! (centres, invariants, diagrams) and [`verification`] (checking
//! hand-drawn plans, the extended-precision reference) → [`presentation`]
//! (result files, tables, sheets).

pub mod kinematics;
pub mod model;
pub mod presentation;
pub mod studies;
pub mod verification;

pub mod accuracy;
pub mod error;
pub mod geom;
pub mod json;
pub mod output;
pub mod progress;

// The paths of the first, flat layout, kept: tests, benches and fuzz
// targets reach the internals by them.
#[doc(hidden)]
pub use kinematics::{analytic, construction, positions, solve};
#[doc(hidden)]
pub use model::{mechanism, scene, shape, structure};
#[doc(hidden)]
pub use presentation::{drawing, quantity, report};
#[doc(hidden)]
pub use studies::{centres, diagrams, frenet, invariants};
#[doc(hidden)]
pub use verification::{check, precision, reference};

pub use error::{Error, Issue, Result};
pub use scene::Scene;
pub use solve::{Analysis, Solved};

/// The embedded default scene: the lecture's six-link mechanism (Fig. 2.10).
pub const DEFAULT_SCENE: &str = include_str!("../fixtures/six_link_fig2_10.json");

pub use output::write_atomically;
