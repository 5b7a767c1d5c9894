//! What the check says: each item's judgement and verdict, the diagnosis
//! of a wrong answer, and the report of one answer.

use crate::kinematics::construction::{Mistake, Plan, PlanKind};

/// What the check says of one item.
#[derive(Clone, Debug, PartialEq)]
pub enum Judgement {
    /// Within the tolerance, and no typical mistake could have put it there.
    Right,
    /// Outside the tolerance: the construction cannot give it.
    Wrong,
    /// Within the tolerance, but the tolerance cannot tell the right answer
    /// from a mistaken one at this position (the reason says why).
    CannotJudge(String),
}

/// The verdict on one item.
#[derive(Clone, Debug)]
pub struct Verdict {
    pub pointer: String,
    pub key: String,
    /// What was checked, in words ("segment p_v b", "ω2").
    pub what: String,
    pub expected: f64,
    pub given: f64,
    /// |given − expected| (for points: the distance between them).
    pub difference: f64,
    pub tolerance: f64,
    pub unit: &'static str,
    /// The same item on the plan, in mm (values: their segment), where it
    /// has one: (expected, given).
    pub on_plan: Option<(f64, f64)>,
    /// The step of the construction that draws the item's point (1-based)
    /// and its sentence.
    pub step: Option<(usize, String)>,
    pub judgement: Judgement,
}

impl Verdict {
    pub fn ok(&self) -> bool {
        self.judgement == Judgement::Right
    }
}

/// What explains a wrong answer.
#[derive(Clone, Debug)]
pub struct Diagnosis {
    /// One sentence naming the mistake; `None`: not recognised.
    pub mistake: Option<String>,
    /// The mistake, typed; `None`: not recognised.
    pub explanation: Option<Candidate>,
    /// The step of the construction where it enters, and its sentence.
    pub step: Option<(usize, String)>,
    /// How many items the mistaken construction explains.
    pub explained: usize,
    /// Other explanations as good, when the answer cannot tell them apart.
    pub alternatives: Vec<String>,
}

#[derive(Clone, Debug)]
pub struct Report {
    pub plan: PlanKind,
    pub position: usize,
    pub mu: f64,
    pub delta: f64,
    pub verdicts: Vec<Verdict>,
    /// Worst intersection angle of the construction (degrees).
    pub worst_angle: f64,
    pub diagnosis: Option<Diagnosis>,
    /// The correct plan at the student's scale (for the overlay).
    pub plan_built: Plan,
}

impl Report {
    pub fn wrong(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| v.judgement == Judgement::Wrong)
            .count()
    }
    pub fn unjudged(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| matches!(v.judgement, Judgement::CannotJudge(_)))
            .count()
    }
    pub fn right(&self) -> usize {
        self.verdicts.iter().filter(|v| v.ok()).count()
    }
    /// The exit status of `mechplan check`: 0 every item right, 1 any
    /// wrong, 4 none wrong but some that cannot be judged here.
    pub fn status(&self) -> u8 {
        if self.wrong() > 0 {
            1
        } else if self.unjudged() > 0 {
            4
        } else {
            0
        }
    }
}

/// The fraction of the plan's size beyond which a tolerance judges
/// nothing: an item whose tolerance exceeds a fifth of the plan cannot be
/// told from a point elsewhere on it.
pub const MAX_TOLERANCE_OF_PLAN: f64 = crate::accuracy::ACCURACY.max_tolerance_of_plan;

/// A way the plan may have been built wrong: what a diagnosis names
/// (typed; its sentence is [`Diagnosis::mistake`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Candidate {
    /// A mistake at one decision (`at: Some(n)`, counted in the order of
    /// the construction) or every one, on the checked plan or on both.
    Mistake {
        /// The mistake.
        m: Mistake,
        /// Which of its decisions; `None`: every one.
        at: Option<usize>,
        /// Made on the velocity plan too (an acceleration answer).
        both: bool,
    },
    /// One vector laid off with a wrong length: the n-th, times `factor`.
    Slip {
        /// Which laid-off vector, in the order of the construction.
        at: usize,
        /// Its length over the right one.
        factor: f64,
    },
    /// Two mistakes together, each everywhere on the checked plan.
    Pair(Mistake, Mistake),
    /// The other assembly branch of group g.
    Branch(usize),
    /// Derived values scaled by a factor: μ in mm instead of m (1000 or
    /// 1/1000), or μ inverted (the factor is 1/μ²).
    Scale(f64),
}
