//! What the force analysis finds in the pairs and at the inputs: the
//! reactions of revolute and prismatic pairs, and the balancing moment
//! (force) of an input.

use kurbo::{Point, Vec2};

/// The reaction in a revolute pair: the force `r` (N) of link `first` on
/// link `second` at the pair's point; `second` feels `r`, `first` −`r`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RevoluteReaction {
    /// Index into `Mechanism::revolutes`.
    pub pair: usize,
    pub point: usize,
    pub first: usize,
    pub second: usize,
    pub at: Point,
    pub r: Vec2,
}

/// The reaction in a prismatic pair: the guide's force `n` (N) on the
/// slider, perpendicular to the guide, and its couple `m` (N·m) about the
/// pair's point `q`; together one force `n` through `at` = q + (m/|n|)·u
/// along the guide, when `n` is not zero (else `at` is `None`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GuideReaction {
    /// Index into `Mechanism::prismatics`.
    pub pair: usize,
    pub slider: usize,
    pub guide: usize,
    pub point: usize,
    /// The pair's point (the slider's point on the guide line).
    pub q: Point,
    /// The guide's direction.
    pub u: Vec2,
    pub n: Vec2,
    pub m: f64,
    pub at: Option<Point>,
}

/// What the drive applies to an input link to keep the motion given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Balancing {
    /// On a crank, N·m, counter-clockwise positive.
    Moment(f64),
    /// Along a driving slider's guide direction, N (a cylinder: on the
    /// rod, and its opposite on the barrel).
    Force(f64),
}

impl Balancing {
    pub fn value(&self) -> f64 {
        match *self {
            Balancing::Moment(x) | Balancing::Force(x) => x,
        }
    }
}
