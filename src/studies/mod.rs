//! Studies of a solved mechanism, numbers only: instant centres
//! ([`centres`]), motion-law invariants ([`invariants`]), kinematic
//! diagrams by the chord method ([`diagrams`]), link positions in the
//! Frenet trihedron ([`frenet`]).

pub mod centres;
pub mod diagrams;
pub mod frenet;
pub mod invariants;
