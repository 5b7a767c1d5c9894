//! Checking hand-drawn plans: the student's answer item by item against
//! the construction at the student's own scale, with a tolerance from the
//! drafting-error model of the best-conditioned construction (pencil
//! precision δ propagated through it), a verdict that is never "right"
//! where the tolerance cannot tell the right answer from a typical mistake,
//! and a diagnosis by model selection: the plan rebuilt with each typical
//! mistake, made at one element or everywhere, and the one whose
//! construction explains the answer within its own tolerance, clearly
//! better than any other, named with the step where it enters.

pub mod answer;
pub mod svg;

use crate::error::{Error, Issue, Result};
use crate::kinematics::analytic::{Drive, Order};
use crate::kinematics::construction::text::{Lang, num, sentence};
use crate::kinematics::construction::{
    Drafting, Mistake, Plan, PlanKind, Setup, Variant, build_acceleration, build_plans,
};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::structure::{AssurGroup, DyadKind};
use answer::{Answer, Given, Quantity};
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
pub const MAX_TOLERANCE_OF_PLAN: f64 = 0.2;

/// A way the plan may have been built wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Candidate {
    /// A mistake at one decision (`Some(n)`) or every one, on the checked
    /// plan or on both plans.
    Mistake {
        m: Mistake,
        at: Option<usize>,
        both: bool,
    },
    /// One vector laid off with a wrong length: the n-th, times `factor`.
    Slip { at: usize, factor: f64 },
    /// Two mistakes together, each everywhere on the checked plan.
    Pair(Mistake, Mistake),
    /// The other assembly branch of group g.
    Branch(usize),
    /// Derived values scaled by a factor: μ in mm instead of m (1000 or
    /// 1/1000), or μ inverted (the factor is 1/μ²).
    Scale(f64),
}

/// The discrete mistakes tried, one element at a time and everywhere.
const MISTAKES: [Mistake; 13] = [
    Mistake::CoriolisReversed,
    Mistake::CoriolisForgotten,
    Mistake::CoriolisFactorOne,
    Mistake::NormalFromCentre,
    Mistake::NormalForgotten,
    Mistake::MirroredFigure,
    Mistake::WrongPerpendicular,
    Mistake::TangentialParallel,
    Mistake::WrongLink,
    Mistake::Epsilon1Forgotten,
    Mistake::Epsilon1Added,
    Mistake::OmegaWrongLink,
    Mistake::OmegaWrongSense,
];

fn mistake_sentence(c: Candidate, mu: f64, what: &str) -> String {
    let one = |at: Option<usize>, every: &str, single: &str| -> String {
        if at.is_some() {
            single.to_string()
        } else {
            every.to_string()
        }
    };
    match c {
        Candidate::Mistake { m, at, .. } => match m {
            Mistake::CoriolisReversed => one(at, "The Coriolis acceleration is turned the wrong way: turn the relative velocity by 90° in the sense of ω of the guide.", "One Coriolis acceleration is turned the wrong way: turn the relative velocity by 90° in the sense of ω of the guide."),
            Mistake::CoriolisForgotten => "The Coriolis acceleration is forgotten: a point sliding on a rotating guide has a^k = 2·ω·v_rel.".into(),
            Mistake::CoriolisFactorOne => "The Coriolis acceleration is taken as ω·v_rel: it is 2·ω·v_rel.".into(),
            Mistake::NormalFromCentre => one(at, "Normal components are laid off from the centre instead of toward it: a^n points from the point to the centre of its rotation.", "One normal component is laid off from the centre instead of toward it: a^n points from the point to the centre of its rotation."),
            Mistake::NormalForgotten => one(at, "The normal components ω²·l are forgotten.", "A normal component ω²·l is forgotten."),
            Mistake::MirroredFigure => one(at, "The similar figures are mirrored: their letters must run around them in the same order as around the link.", "A similar figure is mirrored: its letters must run around it in the same order as around the link."),
            Mistake::WrongPerpendicular => "A perpendicular is drawn to the wrong link: v_CB is ⊥ BC, v_CD is ⊥ CD.".into(),
            Mistake::TangentialParallel => one(at, "The relative (tangential) components are drawn parallel to the links instead of perpendicular to them.", "A relative (tangential) component is drawn parallel to its link instead of perpendicular to it."),
            Mistake::WrongLink => "A point is taken on the wrong link: the guide's point (b₃) is not the slider's point (b₂); they differ by the relative sliding.".into(),
            Mistake::Epsilon1Forgotten => "The crank's tangential acceleration ε1·l is forgotten (ε1 ≠ 0).".into(),
            Mistake::Epsilon1Added => "A tangential acceleration of the crank is added although ε1 = 0.".into(),
            Mistake::OmegaWrongLink => one(at, "The normal components ω²·l use ω of the crank instead of each link's own ω.", "A normal component ω²·l uses ω of the crank instead of the link's own ω."),
            Mistake::OmegaWrongSense => "The crank's velocity is laid off against the sense of ω1.".into(),
            Mistake::Slip => "A vector is laid off with a wrong length.".into(),
        },
        Candidate::Slip { factor, .. } => format!(
            "A slip in one length: {what} is laid off {} times its right length (an arithmetic or measuring slip).",
            num(factor)
        ),
        Candidate::Pair(x, y) => {
            let one = |m| {
                mistake_sentence(
                    Candidate::Mistake { m, at: None, both: false },
                    mu,
                    what,
                )
            };
            format!("Two mistakes together: {} {}", one(x), one(y))
        }
        Candidate::Branch(_) => "The mechanism is assembled on the other branch (a group drawn mirrored on the plan of the mechanism).".into(),
        Candidate::Scale(f) if (f - 1000.0).abs() < 1e-9 || (f - 1e-3).abs() < 1e-12 => {
            "The scale μ is applied in the wrong units (mm instead of m, or the reverse): the derived values are off by 1000.".into()
        }
        Candidate::Scale(_) => format!("The scale μ is inverted: values are segment/μ instead of segment·μ (μ = {}).", num(mu)),
    }
}

/// Resolve a name of the answer to a plan point: the pole's names, named
/// points (their lower-case names), construction points (n2, k3, b3 or
/// their keys n_2, k_3, b_3).
pub fn resolve(plan: &Plan, name: &str) -> Option<usize> {
    let n = name.trim().to_lowercase();
    if ["p", "pv", "p_v", "pa", "p_a", "π"].contains(&n.as_str()) {
        return Some(0);
    }
    let named = |p: &crate::kinematics::construction::PlanPoint| p.key.to_lowercase() == n;
    if let Some(i) = plan.points.iter().position(named) {
        return Some(i);
    }
    plan.points
        .iter()
        .position(|p| p.name().to_lowercase() == n || p.key.replace('_', "").to_lowercase() == n)
}

/// One item on one plan: what it is, its expected value and tolerance,
/// the given value (compared modulo a turn for directions), the unit, how
/// small a difference the pencil can show in that unit, the item in mm on
/// the plan, and the plan point whose step draws it.
struct Expected {
    what: String,
    expected: f64,
    given: f64,
    tol: f64,
    unit: &'static str,
    /// The pencil precision δ in the item's unit: a mistake that moves the
    /// item by less cannot be seen on paper.
    visible: f64,
    /// (expected, given) in mm on the plan.
    on_plan: Option<(f64, f64)>,
    point: Option<usize>,
    /// For a point: where this plan has it (mm from the pole).
    place: Option<Vec2>,
}

impl Expected {
    /// How far another construction's expectation of this item is from
    /// this one's.
    fn moved(&self, other: &Expected) -> f64 {
        match (self.place, other.place) {
            (Some(a), Some(b)) => (a - b).hypot(),
            _ => (self.expected - other.expected).abs(),
        }
    }
}

/// The expected value and tolerance of an item on `plan`; `Err` names an
/// unknown letter or link.
fn expect(
    an: &Analysis,
    plan: &Plan,
    it: &answer::Item,
    delta: f64,
) -> std::result::Result<Expected, Issue> {
    let unknown = |n: &str| Issue {
        pointer: it.pointer.clone(),
        message: format!(
            "unknown plan point \"{n}\" (this plan has: {})",
            names(plan)
        ),
    };
    let mu = plan.mu;
    let seg = |key: &str| -> std::result::Result<(usize, usize), Issue> {
        let known = |s: &str| resolve(plan, s).is_some();
        let (a, b) = answer::split_segment(key, &known).ok_or_else(|| Issue {
            pointer: it.pointer.clone(),
            message: format!("cannot read \"{key}\" as two plan points; write them with a space, e.g. \"p_v b\" ({})", names(plan)),
        })?;
        Ok((
            resolve(plan, &a).ok_or_else(|| unknown(&a))?,
            resolve(plan, &b).ok_or_else(|| unknown(&b))?,
        ))
    };
    let p = &plan.points;
    Ok(match &it.given {
        Given::Segment { from, mm, .. } => {
            let (a, b) = seg(from)?;
            let len = (p[b].at - p[a].at).hypot();
            Expected {
                what: format!("segment {}{}", p[a].name(), p[b].name()),
                expected: len,
                given: *mm,
                tol: p[a].err + p[b].err + delta,
                unit: "mm",
                visible: delta,
                on_plan: Some((len, *mm)),
                point: Some(a.max(b)),
                place: None,
            }
        }
        Given::Angle { from, deg, .. } => {
            let (a, b) = seg(from)?;
            let d = p[b].at - p[a].at;
            let len = d.hypot();
            let deg_of = |mm: f64| {
                if len > 0.0 {
                    (mm / len).min(std::f64::consts::PI).to_degrees()
                } else {
                    180.0
                }
            };
            let exp = d.atan2().to_degrees();
            // Compare directions modulo a turn.
            let given = exp + crate::geom::wrap_pi((deg - exp).to_radians()).to_degrees();
            Expected {
                what: format!("direction of {}{}", p[a].name(), p[b].name()),
                expected: exp,
                given,
                tol: deg_of(p[a].err + p[b].err + delta),
                unit: "°",
                visible: deg_of(delta),
                on_plan: None,
                point: Some(a.max(b)),
                place: None,
            }
        }
        Given::Point { name, at } => {
            let i = resolve(plan, name).ok_or_else(|| unknown(name))?;
            // Distance from the expected place is the difference; "expected" 0.
            let d = (Vec2::new(at[0], at[1]) - p[i].at).hypot();
            Expected {
                what: format!("point {} (off its place)", p[i].name()),
                expected: 0.0,
                given: d,
                tol: p[i].err + delta,
                unit: "mm",
                visible: delta,
                on_plan: Some((0.0, d)),
                point: Some(i),
                place: Some(p[i].at),
            }
        }
        Given::Value {
            quantity: Quantity::Point(name),
            value,
        } => {
            let m = &an.mech;
            let pi = m.scene.point_index(name).ok_or_else(|| Issue {
                pointer: it.pointer.clone(),
                message: format!("unknown point \"{name}\""),
            })?;
            let i = plan.of_point[pi].ok_or_else(|| Issue {
                pointer: it.pointer.clone(),
                message: format!("point \"{name}\" is not on this plan"),
            })?;
            let (sym, unit) = if plan.kind == PlanKind::Velocity {
                ("v", "m/s")
            } else {
                ("a", "m/s²")
            };
            let len = p[i].at.hypot();
            Expected {
                what: format!("{sym}_{name}"),
                expected: len * mu,
                given: *value,
                tol: (p[i].err + delta) * mu,
                unit,
                visible: delta * mu,
                on_plan: Some((len, value / mu)),
                point: Some(i),
                place: None,
            }
        }
        Given::Value {
            quantity: Quantity::Rate(id),
            value,
        } => {
            let m = &an.mech;
            let l = m.scene.link_index(id).ok_or_else(|| Issue {
                pointer: it.pointer.clone(),
                message: format!("unknown link \"{id}\""),
            })?;
            let (r, bound) = plan.rates[l].ok_or_else(|| Issue {
                pointer: it.pointer.clone(),
                message: format!("link {id} is not constructed on this plan"),
            })?;
            let (sym, unit) = if plan.kind == PlanKind::Velocity {
                ("ω", "rad/s")
            } else {
                ("ε", "rad/s²")
            };
            let len = plan.rate_len[l];
            let measured = plan
                .measured
                .iter()
                .find(|q| q.quantity == format!("{sym}{id}"));
            // A sense that cannot be read off this plan: magnitudes only.
            let (r, given) = if plan.rate_sense[l] {
                (r, *value)
            } else {
                (r.abs(), value.abs())
            };
            Expected {
                what: format!("{sym}{id}"),
                expected: r,
                given,
                tol: bound,
                unit,
                visible: if len > 0.0 { delta * mu / len } else { bound },
                on_plan: (len > 0.0).then(|| (r.abs() * len / mu, value.abs() * len / mu)),
                point: measured.map(|q| q.to),
                place: None,
            }
        }
    })
}

fn names(plan: &Plan) -> String {
    let mut v: Vec<String> = plan.points.iter().map(|p| p.name()).collect();
    v.dedup();
    v.join(", ")
}

/// What the plans of one answer are built from.
struct Builds<'a> {
    an: &'a Analysis,
    s: &'a Solved,
    ans: &'a Answer,
}

impl Builds<'_> {
    fn setup(&self) -> Setup<'_> {
        Setup {
            m: &self.an.mech,
            s: &self.an.structure,
            need: &self.an.need,
            points: &self.an.points,
            include: &self.an.include,
        }
    }

    fn drive(&self) -> Drive {
        Drive {
            q: self.s.q,
            rate: self.s.rate,
            rate2: self.s.rate2,
        }
    }

    /// The answer's plan built on configuration `c` with `variant`: a
    /// velocity plan at the student's μ; an acceleration plan at the
    /// student's μ on their velocity plan (its μ_v, their measured ω).
    fn plan(&self, c: &Configuration, variant: Variant) -> Result<Plan> {
        let (ans, st) = (self.ans, self.setup());
        let d = Drafting {
            mu_v: Some(ans.mu),
            mu_a: None,
            delta: ans.delta,
            variant,
        };
        if ans.plan == PlanKind::Velocity {
            return Ok(build_plans(&st, c, self.drive(), Order::Velocity, d)?.velocity);
        }
        let dv = Drafting {
            mu_v: ans.mu_v,
            ..d
        };
        let mut vel = build_plans(&st, c, self.drive(), Order::Velocity, dv)?.velocity;
        for (id, w) in &ans.omegas {
            if let Some(l) = self.an.mech.scene.link_index(id)
                && let Some(r) = vel.rates[l].as_mut()
            {
                r.0 = *w;
            }
        }
        let da = Drafting {
            mu_v: ans.mu_v,
            mu_a: Some(ans.mu),
            ..d
        };
        build_acceleration(&st, c, self.drive(), &vel, da)
    }
}

/// A candidate's plan and how it fits the answer.
struct Fit {
    c: Candidate,
    plan: Plan,
    /// Per item, as this plan expects it (values scaled by a Scale
    /// candidate's factor).
    items: Vec<Expected>,
}

impl Fit {
    /// The items within this construction's own tolerance, and the misfit
    /// Σ (difference / tolerance)².
    fn score(&self) -> (usize, f64) {
        let mut ok = 0;
        let mut misfit = 0.0;
        for e in &self.items {
            let d = (e.given - e.expected).abs() / e.tol.max(1e-300);
            if d <= 1.0 {
                ok += 1;
            }
            misfit += d.min(1e3).powi(2);
        }
        (ok, misfit)
    }
}

/// The answer's items as plan `p` expects them, values scaled by `factor`.
fn expectations(b: &Builds, p: &Plan, factor: f64) -> Option<Vec<Expected>> {
    b.ans
        .items
        .iter()
        .map(|it| {
            let mut e = expect(b.an, p, it, b.ans.delta).ok()?;
            if matches!(it.given, Given::Value { .. }) {
                e.expected *= factor;
                e.tol *= factor.abs();
                e.visible *= factor.abs();
            }
            Some(e)
        })
        .collect()
}

/// Check `answer` against the scene's analysis.
pub fn check(an: &Analysis, solved: &[Solved], ans: &Answer) -> Result<Report> {
    let Some(s) = ans.position.checked_sub(1).and_then(|k| solved.get(k)) else {
        return Err(Error::scene(
            "/position",
            format!(
                "position {} is not one of the scene's positions: they are numbered from 1 to {}",
                ans.position,
                solved.len()
            ),
        ));
    };
    if an.order.is_none()
        || (ans.plan == PlanKind::Acceleration && an.order != Some(Order::Acceleration))
    {
        return Err(Error::scene(
            "/plan",
            "the scene's want.plans does not include this plan",
        ));
    }
    for (id, _) in &ans.omegas {
        if an.mech.scene.link_index(id).is_none() {
            return Err(Error::scene(
                format!("/velocity/values/omega{id}"),
                format!("unknown link \"{id}\""),
            ));
        }
    }
    let b = Builds { an, s, ans };
    let plan = b.plan(&s.config, Variant::default())?;
    let mut exp = Vec::new();
    let mut issues = Vec::new();
    for it in &ans.items {
        match expect(an, &plan, it, ans.delta) {
            Ok(e) => exp.push(e),
            Err(i) => issues.push(i),
        }
    }
    if !issues.is_empty() {
        return Err(Error::Scene(issues));
    }
    let candidates = candidates(&b, &plan, &exp);
    // The plan's size: the farthest of its points from the pole.
    let size = plan.points.iter().map(|p| p.at.hypot()).fold(0.0, f64::max);
    let mut verdicts = Vec::new();
    for (k, (it, e)) in ans.items.iter().zip(&exp).enumerate() {
        let difference = (e.given - e.expected).abs();
        let judgement = if difference > e.tol {
            Judgement::Wrong
        } else {
            cannot_judge(k, e, size, plan.mu, &candidates, ans.mu)
                .map(Judgement::CannotJudge)
                .unwrap_or(Judgement::Right)
        };
        verdicts.push(Verdict {
            pointer: it.pointer.clone(),
            key: it.key.clone(),
            what: e.what.clone(),
            expected: e.expected,
            given: e.given,
            difference,
            tolerance: e.tol,
            unit: e.unit,
            on_plan: e.on_plan,
            step: e
                .point
                .and_then(|i| plan.step_of(i))
                .map(|k| (k + 1, sentence(&plan, k, Lang::En))),
            judgement,
        });
    }
    let mut report = Report {
        plan: ans.plan,
        position: ans.position,
        mu: ans.mu,
        delta: ans.delta,
        worst_angle: plan.worst_angle_deg(),
        diagnosis: None,
        verdicts,
        plan_built: plan,
    };
    if report.wrong() > 0 {
        report.diagnosis = Some(diagnose(&b, &report, &exp, &candidates));
    }
    Ok(report)
}

/// Is item `k` (within its tolerance) one this answer cannot be judged
/// on? Either its tolerance exceeds [`MAX_TOLERANCE_OF_PLAN`] of the plan,
/// or the whole answer fits some typical mistake's construction within its
/// tolerances as well, and that construction moves this item visibly (by
/// more than the pencil's δ): the answer could be that mistake drawn
/// carefully, so "right" would accept it.
fn cannot_judge(
    k: usize,
    e: &Expected,
    size: f64,
    mu: f64,
    candidates: &[Fit],
    student_mu: f64,
) -> Option<String> {
    let tol_mm = match e.unit {
        "mm" => e.tol,
        "°" => None?,
        _ => e
            .on_plan
            .map(|(x, _)| {
                if e.expected != 0.0 {
                    e.tol * x / e.expected.abs()
                } else {
                    e.tol / mu
                }
            })
            .unwrap_or(e.tol / mu),
    };
    if e.unit != "°" && size > 0.0 && tol_mm > MAX_TOLERANCE_OF_PLAN * size {
        return Some(format!(
            "its tolerance ({}) exceeds a fifth of the plan ({} across): near a dead point the construction cannot place it",
            crate::presentation::quantity::format_quantity(tol_mm, "mm"),
            crate::presentation::quantity::format_quantity(size, "mm")
        ));
    }
    for f in candidates {
        let other = &f.items[k];
        let moved = e.moved(other);
        // The whole answer fits a mistaken construction within its own
        // tolerances, and that construction moves this item visibly: the
        // answer cannot tell which was drawn. (An answer that contradicts
        // the mistake anywhere rules it out.)
        let fits = f.score().0 == f.items.len();
        if moved > e.visible && fits {
            return Some(format!(
                "within its tolerance ({}) of the right construction and of a mistaken one that moves it by only {}: {}",
                crate::presentation::quantity::format_quantity(e.tol, e.unit),
                crate::presentation::quantity::format_quantity(moved, e.unit),
                mistake_sentence(f.c, student_mu, &e.what)
            ));
        }
    }
    None
}

/// Every discrete candidate's plan (the typical mistakes at each of their
/// decisions and everywhere, the other branch of each group, the scale
/// applied wrongly), with its expected values on the answer's items;
/// candidates that change no item are left out.
fn candidates(b: &Builds, plan: &Plan, exp: &[Expected]) -> Vec<Fit> {
    let (an, s, ans) = (b.an, b.s, b.ans);
    let fit = |c: Candidate, p: Plan, factor: f64| -> Option<Fit> {
        let items = expectations(b, &p, factor)?;
        // The same answer as the right construction: no candidate.
        let differs = items
            .iter()
            .zip(exp)
            .any(|(x, e)| e.moved(x) > 1e-9 * (1.0 + e.expected.abs() + e.tol));
        differs.then_some(Fit { c, plan: p, items })
    };
    let mut out = Vec::new();
    let variant = |m: Mistake, at: Option<usize>, both: bool| Variant {
        mistake: Some(m),
        at,
        on: (!both).then_some(ans.plan),
        ..Variant::default()
    };
    for m in MISTAKES {
        // How many decisions of this kind the checked plan takes.
        let Ok(count) = b.plan(&s.config, variant(m, Some(usize::MAX), false)) else {
            continue;
        };
        let n = count.decisions;
        let mut tries: Vec<(Option<usize>, bool)> = Vec::new();
        if n > 0 {
            tries.push((None, false));
        }
        if n > 1 {
            tries.extend((0..n).map(|i| (Some(i), false)));
        }
        if ans.plan == PlanKind::Acceleration {
            // A mistake made on the velocity plan too (the student's ω).
            tries.push((None, true));
        }
        for (at, both) in tries {
            if let Ok(p) = b.plan(&s.config, variant(m, at, both))
                && p.mistake_step.is_some()
                && let Some(f) = fit(Candidate::Mistake { m, at, both }, p, 1.0)
            {
                out.push(f);
            }
        }
    }
    // The other assembly branch of each group with one.
    for g in 0..an.structure.groups.len() {
        let has_branch = match &an.structure.groups[g] {
            AssurGroup::Dyad(d) => !matches!(d.kind, DyadKind::Prp | DyadKind::Rpp),
            AssurGroup::Triad(_) => false,
        };
        if !an.need[g] || !has_branch {
            continue;
        }
        let Ok(mut ps) = PositionSolver::new(&an.mech, &an.structure, an.need.clone()) else {
            continue;
        };
        if ps.branches.sign[g] == 0.0 {
            continue;
        }
        ps.branches.sign[g] = -ps.branches.sign[g];
        let Ok(c) = ps.solve_at(s.q) else { continue };
        if let Ok(p) = b.plan(&c, Variant::default())
            && let Some(f) = fit(Candidate::Branch(g), p, 1.0)
        {
            out.push(f);
        }
    }
    if ans
        .items
        .iter()
        .any(|i| matches!(i.given, Given::Value { .. }))
    {
        for f in [1000.0, 1e-3, 1.0 / (ans.mu * ans.mu)] {
            if let Some(x) = fit(Candidate::Scale(f), plan.clone(), f) {
                out.push(x);
            }
        }
    }
    out
}

/// Name the mistake that explains the answer: the candidates whose
/// construction puts every item within its own tolerance; of those the
/// one with the least misfit, if no other explanation of a different kind
/// comes close (within a factor 2 of its misfit); otherwise "not
/// recognised". When no discrete mistake explains the answer, a slip in
/// one laid-off length is tried (its factor fitted).
fn diagnose(b: &Builds, r: &Report, exp: &[Expected], cands: &[Fit]) -> Diagnosis {
    let n = exp.len();
    let step_of = |f: &Fit| {
        f.plan.mistake_step.map(|k| {
            let k = k.min(f.plan.steps.len().saturating_sub(1));
            (k + 1, sentence(&f.plan, k, Lang::En))
        })
    };
    let what_of = |f: &Fit| -> String {
        f.plan
            .mistake_step
            .and_then(|k| f.plan.steps.get(k))
            .map(|st| match &st.op {
                crate::kinematics::construction::Op::LayOff { what, .. } => what.clone(),
                _ => String::from("a vector"),
            })
            .unwrap_or_else(|| "a vector".into())
    };
    let mut explaining: Vec<(&Fit, f64)> = cands
        .iter()
        .filter_map(|f| {
            let (ok, misfit) = f.score();
            (ok == n).then_some((f, misfit))
        })
        .collect();
    explaining.sort_by(|a, b| a.1.total_cmp(&b.1));
    if let Some(&(best, misfit)) = explaining.first() {
        let sentence_of = |f: &Fit| mistake_sentence(f.c, r.mu, &what_of(f));
        let name = sentence_of(best);
        // Explanations of another kind that fit about as well.
        let mut alternatives: Vec<String> = explaining[1..]
            .iter()
            .filter(|(f, m)| *m <= 2.0 * misfit.max(1e-12) && !same_kind(f.c, best.c))
            .map(|(f, _)| sentence_of(f))
            .collect();
        alternatives.dedup();
        let mistake = alternatives.is_empty().then_some(name.clone());
        if mistake.is_none() {
            alternatives.insert(0, name);
        }
        return Diagnosis {
            mistake,
            step: step_of(best),
            explained: n,
            alternatives,
        };
    }
    // Two mistakes combined, each everywhere: the pairs of the kinds this
    // plan can make.
    let kinds: Vec<Mistake> = {
        let mut k: Vec<Mistake> = Vec::new();
        for f in cands {
            if let Candidate::Mistake { m, both: false, .. } = f.c
                && !k.contains(&m)
            {
                k.push(m);
            }
        }
        k
    };
    let mut pairs: Vec<(Fit, f64)> = Vec::new();
    for (i, &x) in kinds.iter().enumerate() {
        for &y in &kinds[i + 1..] {
            let variant = Variant {
                mistake: Some(x),
                also: Some(y),
                on: Some(b.ans.plan),
                ..Variant::default()
            };
            if let Ok(p) = b.plan(&b.s.config, variant)
                && let Some(items) = expectations(b, &p, 1.0)
            {
                let f = Fit {
                    c: Candidate::Pair(x, y),
                    plan: p,
                    items,
                };
                let (ok, misfit) = f.score();
                if ok == n {
                    pairs.push((f, misfit));
                }
            }
        }
    }
    pairs.sort_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((best, misfit)) = pairs.first() {
        let others = pairs[1..]
            .iter()
            .filter(|p| p.1 <= 2.0 * misfit.max(1e-12))
            .count();
        let name = mistake_sentence(best.c, r.mu, &what_of(best));
        return Diagnosis {
            mistake: (others == 0).then(|| name.clone()),
            step: step_of(best),
            explained: n,
            alternatives: if others == 0 {
                Vec::new()
            } else {
                pairs
                    .iter()
                    .take(others + 1)
                    .map(|p| mistake_sentence(p.0.c, r.mu, &what_of(&p.0)))
                    .collect()
            },
        };
    }
    // A slip in one length: each laid-off vector in turn, its factor fitted.
    let mut best: Option<(Fit, f64)> = None;
    if let Ok(count) = b.plan(
        &b.s.config,
        Variant {
            mistake: Some(Mistake::Slip),
            at: Some(usize::MAX),
            on: Some(b.ans.plan),
            ..Variant::default()
        },
    ) {
        for at in 0..count.decisions {
            if let Some((f, misfit)) = fit_slip(b, at, exp)
                && best.as_ref().is_none_or(|x| misfit < x.1)
            {
                best = Some((f, misfit));
            }
        }
    }
    if let Some((f, _)) = best {
        return Diagnosis {
            mistake: Some(mistake_sentence(f.c, r.mu, &what_of(&f))),
            step: step_of(&f),
            explained: n,
            alternatives: Vec::new(),
        };
    }
    Diagnosis {
        mistake: None,
        step: None,
        explained: 0,
        alternatives: Vec::new(),
    }
}

/// Two candidates that name the same mistake (one element of a kind and
/// every element of it, on one plan or both).
fn same_kind(a: Candidate, b: Candidate) -> bool {
    match (a, b) {
        (Candidate::Mistake { m: x, .. }, Candidate::Mistake { m: y, .. }) => x == y,
        (Candidate::Branch(_), Candidate::Branch(_)) => true,
        (Candidate::Scale(x), Candidate::Scale(y)) => x == y,
        (Candidate::Pair(a, b), Candidate::Pair(c, d)) => (a, b) == (c, d),
        _ => false,
    }
}

/// The laid-off vector `at` with its length times a factor fitted to the
/// answer (a coarse grid, then golden sections); `Some` when the slip
/// explains every item within its tolerance. Factors that are another
/// named mistake (0: a component forgotten; −1: reversed; ½: a factor 2
/// forgotten) are left to those.
fn fit_slip(b: &Builds, at: usize, exp: &[Expected]) -> Option<(Fit, f64)> {
    let eval = |factor: f64| -> Option<(Fit, f64, usize)> {
        let p = b
            .plan(
                &b.s.config,
                Variant {
                    mistake: Some(Mistake::Slip),
                    at: Some(at),
                    on: Some(b.ans.plan),
                    factor,
                    ..Variant::default()
                },
            )
            .ok()?;
        let items = expectations(b, &p, 1.0)?;
        let f = Fit {
            c: Candidate::Slip { at, factor },
            plan: p,
            items,
        };
        let (ok, misfit) = f.score();
        Some((f, misfit, ok))
    };
    let grid = [
        0.1, 0.25, 0.5, 0.75, 0.9, 1.1, 1.25, 1.5, 2.0, 3.0, 5.0, 10.0,
    ];
    let mut best = (1.0, f64::INFINITY);
    for &g in &grid {
        if let Some((_, m, _)) = eval(g)
            && m < best.1
        {
            best = (g, m);
        }
    }
    // Golden sections on the log of the factor around the best grid point.
    let (mut lo, mut hi) = ((best.0 / 2.0f64).ln(), (best.0 * 2.0f64).ln());
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..40 {
        let (a, c) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
        let ma = eval(a.exp()).map_or(f64::INFINITY, |x| x.1);
        let mc = eval(c.exp()).map_or(f64::INFINITY, |x| x.1);
        if ma < mc {
            hi = c;
        } else {
            lo = a;
        }
    }
    let factor = (0.5 * (lo + hi)).exp();
    let named = [0.0, -1.0, 0.5, 1.0]
        .iter()
        .any(|&x| (factor - x).abs() < 0.02);
    let (f, misfit, ok) = eval(factor)?;
    let moved = f.items.iter().zip(exp).any(|(x, e)| e.moved(x) > e.visible);
    (ok == exp.len() && moved && !named).then_some((f, misfit))
}

/// The report as text for the terminal.
pub fn to_text(r: &Report) -> String {
    use std::fmt::Write as _;
    let fmt = crate::presentation::quantity::format_number;
    let mut t = String::new();
    let kind = if r.plan == PlanKind::Velocity {
        "velocity"
    } else {
        "acceleration"
    };
    let _ = writeln!(
        t,
        "Check of the {kind} plan, position {}, μ = {}, pencil precision δ = {}",
        r.position,
        fmt(r.mu),
        crate::presentation::quantity::format_quantity(r.delta, "mm")
    );
    if r.worst_angle < 5.0 {
        let _ = writeln!(
            t,
            "note: lines of this construction meet at {}°; tolerances are wide here (near a dead centre)",
            fmt(r.worst_angle)
        );
    }
    let _ = writeln!(
        t,
        "  {:<24} {:>12} {:>12} {:>12} {:>12}  verdict",
        "item", "expected", "given", "difference", "tolerance"
    );
    for v in &r.verdicts {
        let verdict = match &v.judgement {
            Judgement::Right => "RIGHT",
            Judgement::Wrong => "WRONG",
            Judgement::CannotJudge(_) => "CANNOT BE JUDGED",
        };
        let _ = writeln!(
            t,
            "  {:<24} {:>12} {:>12} {:>12} {:>12}  {} {}",
            v.what,
            fmt(v.expected),
            fmt(v.given),
            fmt(v.difference),
            fmt(v.tolerance),
            v.unit,
            verdict
        );
        if !v.ok() {
            if let Some((e, g)) = v.on_plan
                && v.unit != "mm"
            {
                let _ = writeln!(
                    t,
                    "      on the plan: {} mm expected, {} mm given",
                    fmt(e),
                    fmt(g)
                );
            }
            if let Some((k, s)) = &v.step {
                let _ = writeln!(t, "      drawn at step {k}: {s}");
            }
            if let Judgement::CannotJudge(why) = &v.judgement {
                let _ = writeln!(t, "      cannot be judged at this position: {why}");
            }
        }
    }
    let _ = writeln!(
        t,
        "total: {} of {} right, {} wrong, {} cannot be judged",
        r.right(),
        r.verdicts.len(),
        r.wrong(),
        r.unjudged()
    );
    if let Some(d) = &r.diagnosis {
        match &d.mistake {
            Some(m) => {
                let _ = writeln!(t, "likely mistake: {m}");
                if let Some((k, s)) = &d.step {
                    let _ = writeln!(t, "  it enters at step {k}: {s}");
                }
            }
            None if !d.alternatives.is_empty() => {
                let _ = writeln!(
                    t,
                    "mistake not recognised: these explain the answer equally well:"
                );
                for a in &d.alternatives {
                    let _ = writeln!(t, "  - {a}");
                }
            }
            None => {
                let _ = writeln!(
                    t,
                    "mistake not recognised: no typical mistake explains these answers"
                );
            }
        }
    }
    t
}

/// The report as JSON.
pub fn to_json(r: &Report) -> serde_json::Value {
    serde_json::json!({
        "plan": if r.plan == PlanKind::Velocity { "velocity" } else { "acceleration" },
        "position": r.position,
        "mu": r.mu,
        "delta": r.delta,
        "worst_angle": r.worst_angle,
        "items": r.verdicts.iter().map(|v| serde_json::json!({
            "pointer": v.pointer, "key": v.key, "what": v.what, "expected": v.expected, "given": v.given,
            "difference": v.difference, "tolerance": v.tolerance, "unit": v.unit, "ok": v.ok(),
            "judgement": match &v.judgement {
                Judgement::Right => "right",
                Judgement::Wrong => "wrong",
                Judgement::CannotJudge(_) => "cannot be judged",
            },
            "reason": match &v.judgement { Judgement::CannotJudge(w) => Some(w.clone()), _ => None },
            "on_plan_mm": v.on_plan.map(|(e, g)| serde_json::json!({ "expected": e, "given": g })),
            "step": v.step.as_ref().map(|s| s.0),
            "step_text": v.step.as_ref().map(|s| s.1.clone()),
        })).collect::<Vec<_>>(),
        "right": r.right(),
        "wrong": r.wrong(),
        "cannot_be_judged": r.unjudged(),
        "status": r.status(),
        "diagnosis": r.diagnosis.as_ref().map(|d| serde_json::json!({
            "mistake": d.mistake, "recognised": d.mistake.is_some(),
            "alternatives": d.alternatives,
            "step": d.step.as_ref().map(|s| s.0), "step_text": d.step.as_ref().map(|s| s.1.clone()), "explained": d.explained,
        })),
    })
}

/// An SVG sheet with the correct plan (black) and the student's points
/// (red crosses, labelled), for `check --svg`.
pub fn overlay(an: &Analysis, ans: &Answer, r: &Report) -> String {
    use crate::presentation::drawing::canvas::{Canvas, Class, Label, SMALL};
    let plan = &r.plan_built;
    let mut c = Canvas::default();
    crate::presentation::drawing::plan::draw(plan, &mut c, &an.points);
    // The student's points: given directly, or the far end of a segment
    // from the pole.
    for it in &ans.items {
        let at = match &it.given {
            Given::Point { at, .. } => Some(kurbo::Point::new(at[0], at[1])),
            _ => None,
        };
        if let Some(p) = at {
            let d = 1.2;
            c.prims
                .push(crate::presentation::drawing::canvas::Prim::Seg {
                    a: p + Vec2::new(-d, -d),
                    b: p + Vec2::new(d, d),
                    class: Class::Thin,
                    id: Some(format!("student-{}", it.key)),
                });
            c.prims
                .push(crate::presentation::drawing::canvas::Prim::Seg {
                    a: p + Vec2::new(-d, d),
                    b: p + Vec2::new(d, -d),
                    class: Class::Thin,
                    id: None,
                });
            c.label(p, Label::new(format!("{}*", it.key), ""), SMALL, None);
            if let Some(crate::presentation::drawing::canvas::Prim::Text { class, .. }) =
                c.prims.last_mut()
            {
                *class = "student";
            }
        }
    }
    let title = format!(
        "Check: {} plan, position {} — {} of {} right{}",
        if r.plan == PlanKind::Velocity {
            "velocity"
        } else {
            "acceleration"
        },
        r.position,
        r.right(),
        r.verdicts.len(),
        r.diagnosis
            .as_ref()
            .and_then(|d| d.mistake.as_ref())
            .map(|m| format!(" — {m}"))
            .unwrap_or_default()
    );
    crate::presentation::drawing::page_svg(
        "check".into(),
        title,
        &c,
        None,
        &crate::presentation::drawing::DrawOptions::default(),
    )
    .svg
}
