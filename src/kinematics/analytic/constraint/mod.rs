//! Route (b): a general constraint solver, independent of the group
//! decomposition's formulas. Each moving link is a pose (x, y, θ); each
//! revolute pair gives two equations (its point coincides on both links),
//! each prismatic pair two (no relative rotation; the slider's point on the
//! guide line), the input one. Positions by Newton's method from the
//! previous solution, velocities and accelerations by linear solves with
//! the constraint Jacobian, whose conditioning is checked by SVD. The
//! equations themselves (Φ, Φ_q, γ) are [`super::equations`], written once
//! for f64 and for the extended-precision reference.


mod answer;
mod dense;
mod path;
pub use answer::{Conditioning, Corrected, Unknowns};
// Named by the fields of those (the library's `internals`).
#[cfg(feature = "internals")]
pub use answer::{Col, Factors};
mod solver;
pub use solver::*;
