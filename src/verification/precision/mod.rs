//! The work-precision report (`mechplan precision`): for every way of
//! finding the velocities and accelerations, its error against the
//! extended-precision reference ([`crate::verification::reference`]) and its run time per
//! position.
//!
//! Methods:
//! - the construction kernel (plan values = segment × μ; the drafting error
//!   is not counted: this is the kernel's floating-point error);
//! - route (a), the group-wise closed vector contours;
//! - route (b), the constraint solver, at Newton tolerances 1e-4 … 1e-14;
//! - kinematic diagrams: numerical differentiation of the position
//!   function with N positions per revolution, as the lecture draws them
//!   (chords, whose slopes are carried to the interval midpoints, then
//!   chords of that diagram back at the nodes) and by central differences
//!   at the nodes; each evaluation position is taken as a midpoint (chord
//!   velocities) or a node (the rest) of its diagram;
//! - hand drafting emulated: the kernel with pencil noise of δ (every laid
//!   off point, line and constructed point moved by at most δ mm on the
//!   scene's scales), Monte Carlo over seeds.
//!
//! Errors per position are relative as in the cross-check: places to the
//! sketch size; v and ω·size to the largest of them at that position; a and
//! ε·size likewise. Each row gives the maximum and the median over the
//! positions (and seeds) and the items.
//!
//! The measurement gives rows of numbers (`measure`); the report's table
//! and plot are presentation's (`crate::presentation::precision`).


mod measure;
#[cfg(feature = "internals")]
pub use measure::run;
pub use measure::run_watched;
mod report;
pub use report::*;
