//! The two independent analytic routes. Both give, for every solved link,
//! its pose and its velocity and acceleration state; [`Motion`] turns that
//! into the velocity and acceleration of any point of the link.
//!
//! - [`contour`]: group by group, the closed vector contour of each Assur
//!   group written in its pair coordinates (route (a)).
//! - [`constraint`]: all links at once as poses (x, y, θ) with a constraint
//!   Jacobian, Newton for positions, linear solves for rates (route (b)).
//! - [`equations`]: route (b)'s equations generic over the number type
//!   (f64 here, extended precision in the reference).

pub mod constraint;
pub mod contour;
pub mod equations;

use crate::geom::{Pose, perp};
use kurbo::{Point, Vec2};

/// The motion of one link at one instant.
///
/// The state is kept at a material point `at` of the link (or near it: a
/// joint of its group), not at the world origin: the velocity of the
/// link's point at the origin of a small linkage drawn far from it is the
/// difference of two large numbers (ω×r against v), and would lose the
/// linkage's own digits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    pub pose: Pose,
    /// Angular velocity, positive counter-clockwise.
    pub omega: f64,
    /// Angular acceleration.
    pub epsilon: f64,
    /// Where the state is kept.
    pub at: Point,
    /// Velocity of the link's material point now at `at`.
    pub v_at: Vec2,
    /// Acceleration of that material point.
    pub a_at: Vec2,
}

impl Motion {
    /// Velocity of the link's material point now at `p`.
    pub fn velocity(&self, p: Point) -> Vec2 {
        self.v_at + perp(p - self.at) * self.omega
    }
    /// Acceleration of the link's material point now at `p`:
    /// a_P = a_O + ε×OP − ω²·OP.
    pub fn acceleration(&self, p: Point) -> Vec2 {
        let r = p - self.at;
        self.a_at + perp(r) * self.epsilon - r * (self.omega * self.omega)
    }
    /// Rigid motion from the state of one material point `p`.
    pub fn from_point(pose: Pose, p: Point, v: Vec2, a: Vec2, omega: f64, epsilon: f64) -> Motion {
        Motion {
            pose,
            omega,
            epsilon,
            at: p,
            v_at: v,
            a_at: a,
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

/// What the caller wants computed: velocities only, or accelerations too
/// (and, as [`crate::kinematics::construction::PlanKind`], which plan).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Order {
    Velocity,
    Acceleration,
}
