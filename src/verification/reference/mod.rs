//! An extended-precision reference for measuring errors (never used to
//! answer a scene): positions, velocities and accelerations of every solved
//! link to about 50 significant digits.
//!
//! The equations are route (b)'s, the very code
//! ([`crate::kinematics::analytic::equations`], generic over the number
//! type): every moving link a pose (x, y, θ), two equations per revolute
//! pair, two per prismatic pair, one for the input; but every number is a
//! binary float of [`BITS`] bits (`dashu-float`, correctly rounded `sqrt`,
//! `sin`, `cos`, `atan2`, π). The reference's independence is its own
//! positions and its precision: the links' rigid shapes are rebuilt in that
//! precision from the scene's numbers, which are taken as the exact binary
//! values they are (a value the file gave in degrees or millimetres is
//! recovered as the shortest decimal that the scene's conversion maps onto
//! the stored value, and converted with an extended π or an exact 10⁻³).
//! Positions by Newton's method started from the f64 closed-form solution
//! (so on the same branch) down to a correction of 1e-50 of the sketch
//! size, then the velocity and acceleration systems Φ_q·q̇ = −Φ_t,
//! Φ_q·q̈ = γ by Gaussian elimination with partial pivoting.


mod model;
#[cfg(feature = "internals")]
pub use model::Exact;
mod real;
#[cfg(feature = "internals")]
pub use real::Real;
#[cfg(not(feature = "internals"))]
pub(crate) use real::Real;
mod solution;
pub use solution::*;
