//! What a force plan is: its vectors and lines, the steps that drew it,
//! and every pair's reaction as the plans find it.

use crate::model::structure::Joint;
use kurbo::{Point, Vec2};

/// Which force a vector of a plan is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Force {
    /// A known load (index into the position's loads).
    Load(usize),
    /// The reaction of link `from` on link `to` in the pair `joint`, or its
    /// component.
    Reaction {
        from: usize,
        to: usize,
        joint: Joint,
        part: Part,
    },
    /// The drive force of input `input` (a driving slider) on link `on`.
    Drive { input: usize, on: usize },
}

/// A reaction whole, or its component found first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    Whole,
    /// Perpendicular to the link's line (from a moment equation).
    Tangential,
    /// Along the link's line (closing the polygon).
    Normal,
    /// Along the guide of the middle prismatic pair (from a projection).
    AlongGuide,
    /// Perpendicular to that guide (closing the polygon).
    AcrossGuide,
}

/// A vector of the plan: from plan point `from` to `to`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drawn {
    pub from: usize,
    pub to: usize,
    pub force: Force,
    /// The real force, N (measured off the plan for the unknowns).
    pub value: Vec2,
}

/// A line drawn to close the polygon: through plan point `through`, in
/// direction `dir`, the line of `force`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnLine {
    pub through: usize,
    pub dir: Vec2,
    pub force: Force,
}

/// One step of a force plan, for the steps in words.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceStep {
    /// ΣM about point `about` of `links` = 0 gives `force` (a scalar along
    /// its known direction), N; or a couple (`force` a prismatic pair's).
    /// `about_name`: the point's id; `None` for a class III group's Assur
    /// point (where the axes of two leashes meet).
    Moment {
        links: Vec<usize>,
        about: Point,
        about_name: Option<usize>,
        force: Force,
        value: f64,
    },
    /// The projection of `links`' equilibrium on a guide gives `force`.
    Projection {
        links: Vec<usize>,
        force: Force,
        value: f64,
    },
    /// Vector `Drawn` number `.0` laid off.
    LayOff(usize),
    /// Line number `.0` drawn.
    Line(usize),
    /// Lines `a`, `b` meet at plan point `out`, at sine `sin`.
    Intersect {
        lines: [usize; 2],
        out: usize,
        sin: f64,
    },
    /// The closing vector: the reaction read off the polygon.
    Measure(usize),
    /// The couple of a prismatic pair (the place of its normal force) from
    /// the moments of `links`: `value`, N·m; the force acts at `at`.
    Couple {
        links: Vec<usize>,
        force: Force,
        value: f64,
        at: Option<Point>,
    },
    /// The balancing moment (force) of input `input` from the input link's
    /// equilibrium.
    Balancing { input: usize, value: f64 },
}

/// The force plan of one Assur group (or of an input link).
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePlan {
    /// The group (index into `Structure::groups`); `None`: an input link.
    pub group: Option<usize>,
    /// The input (scene order) when `group` is `None`.
    pub input: Option<usize>,
    /// The links cut out.
    pub links: Vec<usize>,
    /// Scale, N per mm.
    pub mu: f64,
    /// Pencil precision δ, mm.
    pub delta: f64,
    /// Plan points, mm from the first (the start of the polygon).
    pub points: Vec<Vec2>,
    /// Their drafting error radii, mm.
    pub err: Vec<f64>,
    pub vectors: Vec<Drawn>,
    pub lines: Vec<DrawnLine>,
    pub steps: Vec<ForceStep>,
    /// The smallest sine of the lines' meeting (1: none).
    pub worst_sin: f64,
    /// The input link's plan: each force whose moment gives the balancing
    /// moment, by its vector, with its arm about the pivot, m (what a
    /// student measures on the drawing of the mechanism).
    pub arms: Vec<(usize, f64)>,
}

/// A slip in drawing one plan, as a student makes it (the mistakes
/// `check` names; [`super::solve_slipped`]): the plan is drawn as the
/// course draws it but for this one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slip {
    /// The tangential components R^τ with the sign of their moment
    /// equation reversed: the first side's, the second's, or both.
    TangentialSign { first: bool, second: bool },
    /// The tangential components laid along the link (their value right).
    TangentialAlong,
    /// The reactions of the groups solved before taken with the wrong
    /// sign (R_ij on this group's link where R_ji acts).
    NeighbourSign,
    /// The balancing moment from the moments about the crank's other
    /// joint instead of its pivot.
    BalancingAbout,
}

/// Every pair's reaction as the force plans find it (the conventions of
/// [`super::newton_euler::Unknowns`]), and the plans.
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePlans {
    pub plans: Vec<ForcePlan>,
    /// Per revolute pair: the force of its first link on its second, N.
    pub revolute: Vec<Option<Vec2>>,
    /// Per prismatic pair: the guide's normal force on the slider along
    /// the guide's left normal, N, and its couple about the pair's point.
    pub prismatic: Vec<Option<(f64, f64)>>,
    /// Per input: the balancing moment (force).
    pub drives: Vec<Option<f64>>,
}
