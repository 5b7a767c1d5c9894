//! The kinematics: positions group by group ([`positions`]), velocities
//! and accelerations by two independent analytic routes ([`analytic`]; route
//! (a) also compiled per mechanism, [`compiled`]) and
//! as the plans a draftsman draws ([`construction`]), and the analysis of a
//! scene's positions ([`solve`]; its cross-check is
//! [`crate::verification::crosscheck`]).

pub mod analytic;
pub mod compiled;
pub mod construction;
pub mod positions;
pub mod solve;
