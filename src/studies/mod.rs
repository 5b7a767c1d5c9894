//! Studies of a solved mechanism, numbers only: instant centres
//! ([`centres`]), motion-law invariants ([`invariants`]), kinematic
//! diagrams by the chord method ([`diagrams`]), link positions in the
//! Frenet trihedron ([`frenet`]), the points' trajectories and the
//! output's extreme positions the drawings of the positions show
//! ([`trajectories`]), the positions a course singles out ([`chosen`]),
//! and all a request's sheets draw beyond the solved positions
//! ([`sheet_data`]).

pub mod centres;
pub mod chosen;
pub mod diagrams;
pub mod frenet;
pub mod invariants;
pub mod sheet_data;
pub mod stroke;
pub mod trajectories;
