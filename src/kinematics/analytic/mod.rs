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
    #[inline]
    pub fn velocity(&self, p: Point) -> Vec2 {
        self.v_at + perp(p - self.at) * self.omega
    }
    /// Acceleration of the link's material point now at `p`:
    /// a_P = a_O + ε×OP − ω²·OP.
    #[inline]
    pub fn acceleration(&self, p: Point) -> Vec2 {
        let r = p - self.at;
        self.a_at + perp(r) * self.epsilon - r * (self.omega * self.omega)
    }
    /// Rigid motion from the state of one material point `p`.
    #[inline]
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

/// The most inputs a scene may have ([`crate::model::scene::MAX_INPUTS`]).
pub const MAX_INPUTS: usize = crate::model::scene::MAX_INPUTS;

/// Every input's (rate, rate of rate), in the scene's order: on the stack
/// (at most [`MAX_INPUTS`]).
pub type InputRates = smallvec::SmallVec<[(f64, f64); MAX_INPUTS]>;

/// The coordinates of every input at one position, in the scene's order of
/// inputs (rad for a crank, m for a slider): a value, without allocation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coords {
    len: usize,
    x: [f64; MAX_INPUTS],
}

impl Coords {
    /// The coordinate of a single input.
    #[inline]
    pub fn one(q: f64) -> Coords {
        Coords::new(&[q])
    }
    /// The coordinates listed (at most [`MAX_INPUTS`]).
    #[inline]
    pub fn new(q: &[f64]) -> Coords {
        assert!(
            !q.is_empty() && q.len() <= MAX_INPUTS,
            "1 to {MAX_INPUTS} inputs"
        );
        let mut x = [0.0; MAX_INPUTS];
        x[..q.len()].copy_from_slice(q);
        Coords { len: q.len(), x }
    }
    /// The first input's coordinate.
    #[inline]
    pub fn first(&self) -> f64 {
        self.x[0]
    }
}

impl std::ops::Deref for Coords {
    type Target = [f64];
    #[inline]
    fn deref(&self) -> &[f64] {
        &self.x[..self.len]
    }
}

impl std::ops::DerefMut for Coords {
    fn deref_mut(&mut self) -> &mut [f64] {
        &mut self.x[..self.len]
    }
}

/// Every input's coordinate and rates at one instant, in the scene's order
/// of inputs (one [`Drive`] each). A single input's [`Drive`] converts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drives {
    len: usize,
    d: [Drive; MAX_INPUTS],
}

impl Drives {
    /// The drives listed (at most [`MAX_INPUTS`]).
    #[inline]
    pub fn new(d: &[Drive]) -> Drives {
        assert!(
            !d.is_empty() && d.len() <= MAX_INPUTS,
            "1 to {MAX_INPUTS} inputs"
        );
        let zero = Drive {
            q: 0.0,
            rate: 0.0,
            rate2: 0.0,
        };
        let mut all = [zero; MAX_INPUTS];
        all[..d.len()].copy_from_slice(d);
        Drives {
            len: d.len(),
            d: all,
        }
    }
    /// At coordinates `q` with the rates `rates` ((rate, rate of rate) of
    /// each input).
    pub fn at(q: &[f64], rates: &[(f64, f64)]) -> Drives {
        let d: Vec<Drive> = q
            .iter()
            .zip(rates)
            .map(|(&q, &(rate, rate2))| Drive { q, rate, rate2 })
            .collect();
        Drives::new(&d)
    }
    /// The same coordinates with every input standing but input `i`,
    /// moving at unit rate (the transfer functions' run: ∂/∂q_i); with
    /// `j` too, inputs `i` and `j` at unit rate (for the mixed second
    /// derivatives).
    pub fn unit(&self, i: usize, j: Option<usize>) -> Drives {
        let mut out = *self;
        for (k, d) in out.iter_mut().enumerate() {
            let on = k == i || Some(k) == j;
            d.rate = if on { 1.0 } else { 0.0 };
            d.rate2 = 0.0;
        }
        out
    }
    /// The coordinates.
    #[inline]
    pub fn coords(&self) -> Coords {
        let mut x = [0.0; MAX_INPUTS];
        for (x, d) in x.iter_mut().zip(self.iter()) {
            *x = d.q;
        }
        Coords { len: self.len, x }
    }
    /// The first input's drive.
    #[inline]
    pub fn first(&self) -> Drive {
        self.d[0]
    }
}

impl From<Drive> for Drives {
    #[inline]
    fn from(d: Drive) -> Drives {
        Drives::new(&[d])
    }
}

impl std::ops::Deref for Drives {
    type Target = [Drive];
    #[inline]
    fn deref(&self) -> &[Drive] {
        &self.d[..self.len]
    }
}

impl std::ops::DerefMut for Drives {
    fn deref_mut(&mut self) -> &mut [Drive] {
        &mut self.d[..self.len]
    }
}

/// What the caller wants computed: velocities only, or accelerations too
/// (and, as [`crate::kinematics::construction::PlanKind`], which plan).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Order {
    /// Velocities only.
    Velocity,
    /// Velocities and accelerations.
    Acceleration,
}
