//! What the check says: each item's judgement and verdict, the diagnosis
//! of a wrong answer, and the report of one answer.

use crate::kinematics::construction::{Mistake, Plan, PlanKind};
use kurbo::Vec2;

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
    /// Where the item is in the answer (a JSON pointer).
    pub pointer: String,
    /// The item's key in the answer (`p_v b`, `ω2`).
    pub key: String,
    /// What was checked, in words ("segment p_v b", "ω2").
    pub what: String,
    /// The true value, in `unit` (a point: 0, its given value being its
    /// distance from the true place).
    pub expected: f64,
    /// The student's value, in `unit`.
    pub given: f64,
    /// |given − expected| (for points: the distance between them).
    pub difference: f64,
    /// How far the given value may be from the true one and still be right.
    pub tolerance: f64,
    /// The unit of the values.
    pub unit: &'static str,
    /// The same item on the plan, in mm (values: their segment), where it
    /// has one: (expected, given).
    pub on_plan: Option<(f64, f64)>,
    /// The step of the construction that draws the item's point (1-based)
    /// and its sentence.
    pub step: Option<(usize, String)>,
    /// Right, wrong, or cannot be judged (and why).
    pub judgement: Judgement,
}

impl Verdict {
    /// Whether the item is right.
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

/// Where an answer's points fit when they do not fit the position it
/// states (the answer is graded at the stated position all the same, and
/// its report says this): the stated position with the crank turned the
/// other way (ω1 reversed), another position, or both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Elsewhere {
    /// They fit the stated position with ω1 reversed.
    pub reversed: bool,
    /// They fit this position (its number, in the study's numbering).
    pub position: Option<usize>,
}

///The check of a plan of velocities or accelerations: the verdicts item
/// by item, the diagnosis, and the right plan at the student's scale.
#[derive(Clone, Debug)]
pub struct Report {
    /// Velocities or accelerations.
    pub plan: PlanKind,
    /// The position checked: the one the answer states, by its number in
    /// the study's numbering (a `count` sweep from 0, given values from 1).
    pub position: usize,
    /// Where the answer's points fit if not at the stated position.
    pub elsewhere: Option<Elsewhere>,
    /// The plan's scale (real value per mm).
    pub mu: f64,
    /// The pencil precision δ the tolerances rest on, mm.
    pub delta: f64,
    /// The verdicts, item by item.
    pub verdicts: Vec<Verdict>,
    /// Worst intersection angle of the construction (degrees).
    pub worst_angle: f64,
    /// The typical mistake that explains the wrong items, if one does.
    pub diagnosis: Option<Diagnosis>,
    /// The correct plan at the student's scale (for the overlay).
    pub plan_built: Plan,
    /// Step by step from the student's own points (an answer that draws
    /// points): the verdict that decides.
    pub steps: Option<StepReport>,
    /// Beside the steps' verdict, the comparison with the true plan.
    pub second_opinion: Option<SecondOpinion>,
    /// The language of its sentences.
    pub lang: crate::lang::Lang,
}

/// The comparison of the answer with the true plan (tolerances
/// accumulated along the whole construction), beside the steps' verdict:
/// its counts, and where the two disagree, why.
#[derive(Clone, Debug)]
pub struct SecondOpinion {
    /// Items right by the comparison.
    pub right: usize,
    /// Items wrong by the comparison.
    pub wrong: usize,
    /// Items it cannot judge.
    pub unjudged: usize,
    /// What it names, if anything.
    pub mistake: Option<String>,
    /// Why it disagrees with the steps' verdict; `None`: it agrees.
    pub disagreement: Option<String>,
}

impl SecondOpinion {
    /// The true plan's verdict `global` beside the steps' `steps` and the
    /// grade they give (`grade`, every item counted).
    pub fn of(
        global: &Report,
        (steps, grade): (&StepReport, Grade),
        lang: crate::lang::Lang,
    ) -> SecondOpinion {
        let w = crate::words::check::phrases(lang);
        let fill = crate::words::check::fill;
        let wrong = global.wrong();
        let disagreement = match grade {
            Grade::Wrong if wrong == 0 => {
                let k = steps
                    .steps
                    .iter()
                    .find(|s| s.judgement == Judgement::Wrong)
                    .map_or(0, |s| s.step.0);
                Some(fill(&w.disagreement_steps_wrong, &[("step", &k.to_string())]))
            }
            Grade::Right | Grade::CannotJudge if wrong > 0 => {
                let what = global
                    .verdicts
                    .iter()
                    .find(|v| v.judgement == Judgement::Wrong)
                    .map_or(String::new(), |v| v.what.clone());
                Some(fill(&w.disagreement_steps_right, &[("what", &what)]))
            }
            _ => None,
        };
        SecondOpinion {
            right: global.right(),
            wrong,
            unjudged: global.unjudged(),
            mistake: global.diagnosis.as_ref().and_then(|d| d.mistake.clone()),
            disagreement,
        }
    }
}

impl Report {
    /// The report's note on an answer whose points fit elsewhere than the
    /// position it states ([`Elsewhere`]): another position, the stated
    /// one with ω1 reversed, or both, in the report's language; `None`
    /// when they fit there (or fit nowhere).
    pub fn elsewhere_note(&self) -> Option<String> {
        let e = self.elsewhere?;
        let w = crate::words::check::phrases(self.lang);
        let fill = crate::words::check::fill;
        let stated = self.position.to_string();
        Some(match (e.reversed, e.position) {
            (true, Some(k)) => fill(
                &w.elsewhere_both,
                &[("stated", &stated), ("position", &k.to_string())],
            ),
            (true, None) => fill(&w.elsewhere_reversed, &[("stated", &stated)]),
            (false, Some(k)) => fill(
                &w.elsewhere_position,
                &[("stated", &stated), ("position", &k.to_string())],
            ),
            (false, None) => return None,
        })
    }
    /// How many items are wrong.
    pub fn wrong(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| v.judgement == Judgement::Wrong)
            .count()
    }
    /// The grade as a teacher gives it, from every item's verdict (a drawn
    /// point's is its step's).
    pub fn grade(&self) -> Grade {
        if self.wrong() > 0 {
            Grade::Wrong
        } else if self.unjudged() > 0 {
            Grade::CannotJudge
        } else {
            Grade::Right
        }
    }
    /// How many items cannot be judged.
    pub fn unjudged(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| matches!(v.judgement, Judgement::CannotJudge(_)))
            .count()
    }
    /// How many items are right.
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
    /// A value stated as read off the velocity plan (`velocity.values`,
    /// its index there) is wrong.
    Stated {
        /// Which stated value, in the answer's order.
        index: usize,
    },
    /// The plan is drawn at another scale than the one stated.
    DrawnScale {
        /// The scale the points are drawn at.
        drawn: f64,
        /// The scale the answer states.
        stated: f64,
    },
}

/// The verdict on one point the student drew, at the step that draws it.
#[derive(Clone, Debug)]
pub struct StepVerdict {
    /// The step (1-based) and its sentence.
    pub step: (usize, String),
    /// The point's name ("b", "n2").
    pub point: String,
    /// Where the step puts it from the student's own earlier points, mm
    /// from the pole (of the right constructions, the nearest).
    pub predicted: Vec2,
    /// Where the student drew it.
    pub given: Vec2,
    /// |given − predicted|, mm.
    pub off: f64,
    /// The step's own tolerance, mm.
    pub tolerance: f64,
    /// Right, wrong, or cannot be judged (and why).
    pub judgement: Judgement,
    /// The mistake that explains it (an index into
    /// [`StepReport::mistakes`]), when it is wrong.
    pub mistake: Option<usize>,
}

/// A mistake found at a step, with the drawn points it puts off their
/// place (each step after it judged from the student's own points).
#[derive(Clone, Debug)]
pub struct Found {
    /// The mistake, typed; `None`: the step is wrong but no typical
    /// mistake explains it.
    pub explanation: Option<Candidate>,
    /// The mistake in one sentence; `None`: not recognised.
    pub mistake: Option<String>,
    /// The step where it enters (1-based) and that step's sentence as the
    /// right construction says it.
    pub step: (usize, String),
    /// The drawn points it puts off their place.
    pub points: Vec<String>,
    /// Other explanations as good, when the drawing cannot tell them apart.
    pub alternatives: Vec<String>,
}

/// The grade of an answer as a teacher gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Grade {
    /// Every step right.
    Right,
    /// Wrong at one or more steps (each mistake counted once).
    Wrong,
    /// No step wrong, but some cannot be told from a mistake at this
    /// position and scale.
    CannotJudge,
}

/// The step-by-step verdict of one answer.
#[derive(Clone, Debug)]
pub struct StepReport {
    /// One verdict per point the student drew, in the order of the
    /// construction.
    pub steps: Vec<StepVerdict>,
    /// The mistakes found, in the order of their steps.
    pub mistakes: Vec<Found>,
    /// The replayed plan: the student's points where they drew them, the
    /// others predicted from them (the answer's other items are judged on
    /// it).
    pub replay: Plan,
}

impl StepReport {
    /// How many drawn points are wrong at their steps.
    pub fn wrong_steps(&self) -> usize {
        self.steps
            .iter()
            .filter(|s| s.judgement == Judgement::Wrong)
            .count()
    }
    /// Put `found` (mistakes made before the plan is drawn: values read
    /// off the velocity plan, the scale) first among the mistakes.
    pub fn put_first(&mut self, found: Vec<Found>) {
        let n = found.len();
        if n == 0 {
            return;
        }
        for s in &mut self.steps {
            s.mistake = s.mistake.map(|k| k + n);
        }
        let rest = std::mem::take(&mut self.mistakes);
        self.mistakes = found;
        self.mistakes.extend(rest);
    }
    /// The grade of the steps: wrong if a step is, else cannot judge if one cannot be judged, else right.
    pub fn grade(&self) -> Grade {
        if self.steps.iter().any(|s| s.judgement == Judgement::Wrong) {
            Grade::Wrong
        } else if self
            .steps
            .iter()
            .any(|s| matches!(s.judgement, Judgement::CannotJudge(_)))
        {
            Grade::CannotJudge
        } else {
            Grade::Right
        }
    }
}

