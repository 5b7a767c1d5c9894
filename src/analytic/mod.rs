//! The two independent analytic routes. Both give, for every solved link,
//! its pose and its velocity and acceleration state; [`Motion`] turns that
//! into the velocity and acceleration of any point of the link.
//!
//! - [`contour`]: group by group, the closed vector contour of each Assur
//!   group written in its pair coordinates (route (a)).
//! - [`constraint`]: all links at once as poses (x, y, θ) with a constraint
//!   Jacobian, Newton for positions, linear solves for rates (route (b)).

pub mod constraint;
pub mod contour;

use crate::geom::{Pose, perp};
use kurbo::{Point, Vec2};

/// The motion of one link at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    pub pose: Pose,
    /// Angular velocity, positive counter-clockwise.
    pub omega: f64,
    /// Angular acceleration.
    pub epsilon: f64,
    /// Velocity of the link's material point at the world origin.
    pub v0: Vec2,
    /// Acceleration of that material point.
    pub a0: Vec2,
}

impl Motion {
    /// Velocity of the link's material point now at `p`.
    pub fn velocity(&self, p: Point) -> Vec2 {
        self.v0 + perp(p.to_vec2()) * self.omega
    }
    /// Acceleration of the link's material point now at `p`:
    /// a_P = a_O + ε×OP − ω²·OP.
    pub fn acceleration(&self, p: Point) -> Vec2 {
        let r = p.to_vec2();
        self.a0 + perp(r) * self.epsilon - r * (self.omega * self.omega)
    }
    /// Rigid motion from the state of one material point `p`.
    pub fn from_point(pose: Pose, p: Point, v: Vec2, a: Vec2, omega: f64, epsilon: f64) -> Motion {
        let r = p.to_vec2();
        Motion {
            pose,
            omega,
            epsilon,
            v0: v - perp(r) * omega,
            a0: a - perp(r) * epsilon + r * (omega * omega),
        }
    }
}

/// The input's coordinate and rates at one instant: (φ, ω1, ε1) of a crank
/// or (s, v, a) of a driving slider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drive {
    pub q: f64,
    pub rate: f64,
    pub rate2: f64,
}

/// What the caller wants computed: velocities only, or accelerations too.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    Velocity,
    Acceleration,
}
