//! mechplan: graphoanalytic kinematic analysis of planar linkages.
//!
//! The data flow follows the method of a TMM course: [`scene`] (the file) →
//! [`mechanism`] (rigid links, pairs) → [`structure`] (mobility, Assur
//! groups) → [`positions`] → [`analytic`] (two independent routes) →
//! [`solve`] (sequences of positions, the cross-check) → [`report`].

pub mod analytic;
pub mod centres;
pub mod check;
pub mod construction;
pub mod diagrams;
pub mod drawing;
pub mod error;
pub mod frenet;
pub mod geom;
pub mod invariants;
pub mod json;
pub mod mechanism;
pub mod output;
pub mod positions;
pub mod precision;
pub mod progress;
pub mod quantity;
pub mod reference;
pub mod report;
pub mod scene;
pub mod shape;
pub mod solve;
pub mod structure;

pub use error::{Error, Issue, Result};
pub use scene::Scene;
pub use solve::{Analysis, Solved};

/// The embedded default scene: the lecture's six-link mechanism (Fig. 2.10).
pub const DEFAULT_SCENE: &str = include_str!("../fixtures/six_link_fig2_10.json");

pub use output::write_atomically;
