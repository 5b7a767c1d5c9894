//! Checking a hand-drawn force plan (docs/check.md, "Force plans"): the
//! student's segments, directions and values of one group's (or the input
//! link's) plan against the plan mechplan draws **at the student's μ_F**,
//! with the drafting-error model's tolerance (δ per vector laid off,
//! 1/sin θ where the closing lines meet), and a verdict that is never
//! "right" where the tolerance cannot tell the right answer from a typical
//! mistake: the plans rebuilt with the inertia forces not reversed (the
//! force m·a instead of −m·a) and without the weights are tried, and an
//! item that one of them also explains (when it differs from the right
//! one) cannot be judged; a wrong answer that one explains is diagnosed.

mod answer;
mod mistakes;
mod place;

pub use answer::{ForceAnswer, from_json, from_svg, is_force_answer, is_force_svg};
pub use mistakes::ForceMistake;

use super::{Judgement, Verdict};
use crate::error::{Error, Result};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep, Which};
use crate::kinetostatics::loads::Load;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::forces::force_name;
use crate::words::notation::Label;
use crate::words::{check, numbers};
use answer::issue;
use place::{which, which_of};

/// The check of a force plan.
#[derive(Clone, Debug)]
pub struct ForceReport {
    /// The position checked, by its number in the study's numbering.
    pub position: usize,
    /// The links whose force plan was checked.
    pub links: Vec<String>,
    /// The plan's scale, N per mm.
    pub mu: f64,
    /// The pencil precision δ the tolerances rest on, mm.
    pub delta: f64,
    /// The verdicts, item by item.
    pub verdicts: Vec<Verdict>,
    /// The items too small to judge at the student's μ_F (indices into
    /// `verdicts`): reported, and the rest graded without them.
    pub small: Vec<usize>,
    /// The typical mistake the whole answer fits, and no other.
    pub mistake: Option<ForceMistake>,
    /// That mistake in words, with the item it shows first in.
    pub diagnosis: Option<String>,
    /// The language of its words.
    pub lang: Lang,
    /// The right plan at the student's μ_F, as the answer was judged
    /// against it (what the overlay draws: presentation never solves).
    pub(crate) plan: ForcePlan,
    /// Its vectors' names, one per vector, in `lang`'s notation.
    pub(crate) names: Vec<Label>,
}

impl ForceReport {
    /// How many items are wrong.
    pub fn wrong(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| v.judgement == Judgement::Wrong)
            .count()
    }
    /// 0 right, 1 wrong, 4 none wrong but some cannot be judged (an item
    /// too small to judge does not withhold the grade of the rest, unless
    /// nothing else was judged).
    pub fn status(&self) -> u8 {
        let judged = (0..self.verdicts.len()).filter(|i| !self.small.contains(i));
        if self.wrong() > 0 {
            1
        } else if judged.clone().any(|i| !self.verdicts[i].ok()) || judged.count() == 0 {
            4
        } else {
            0
        }
    }

    /// The vector of the right plan an item's force name (`R_43`,
    /// `R^τ_12`, `R43`) names, as the items were judged (the last of that
    /// name: a reaction laid off and read off again is its read-off one).
    pub(crate) fn vector_of(&self, name: &str) -> Option<usize> {
        let k = key(name);
        self.names
            .iter()
            .rposition(|l| key(&crate::words::forces::plain(l)) == k)
    }
}

/// The plan whose vectors carry every one of `names` (an SVG answer's
/// labels), as [`which`] finds it by its links.
fn which_by_names(
    an: &Analysis,
    loads: &[Load],
    plans: &[ForcePlan],
    names: &[String],
) -> Option<(Which, usize)> {
    plans.iter().enumerate().find_map(|(k, p)| {
        let has: Vec<String> = p
            .vectors
            .iter()
            .map(|v| key(&force_name(&an.mech, loads, v.force, Lang::En)))
            .collect();
        names
            .iter()
            .all(|n| has.contains(&key(n)))
            .then(|| (which_of(p), k))
    })
}

/// A force's key as students write it: without `_` and `^`, so that
/// "R_34", "R34" and "R^τ_34" → "Rτ34" all read.
fn key(s: &str) -> String {
    s.chars().filter(|c| *c != '_' && *c != '^').collect()
}

/// What a plan says of one item: (expected, tolerance, on the plan in mm:
/// a segment's or a value's length, a direction's vector's).
type Expect = (f64, f64, Option<f64>);

/// The balancing value and the forces on the input link of `plan`.
fn balancing(plan: &ForcePlan) -> Option<(f64, f64)> {
    let b = plan.steps.iter().find_map(|s| match s {
        ForceStep::Balancing { value, .. } => Some(*value),
        _ => None,
    })?;
    // The forces with arms about the pivot: those laid off (the pivot's
    // own reaction, read off last, has none).
    let forces: f64 = plan
        .steps
        .iter()
        .filter_map(|s| match s {
            ForceStep::LayOff(i) => Some(plan.vectors[*i].value.hypot()),
            _ => None,
        })
        .sum();
    Some((b, forces))
}

/// An item of `plan`, by kind: "segment", "angle" or "value".
fn expect(
    an: &Analysis,
    loads: &[Load],
    plan: &ForcePlan,
    kind: &str,
    name: &str,
    ans: &ForceAnswer,
) -> std::result::Result<Expect, String> {
    let k = key(name);
    if crate::words::forces::is_balancing(&k, "F") {
        let (b, _) =
            balancing(plan).ok_or("this plan has no balancing force: it is the input link's")?;
        if balances_a_crank(an, plan) {
            return Err("this input is a crank: its balancing value is the moment M_b".into());
        }
        let drive = plan.vectors.iter().position(|v| matches!(v.force, Force::Drive { .. }));
        let Some(i) = drive else {
            // A cylinder's drive acts inside its group, off the polygon:
            // from its body's equilibrium, with the reactions read off the
            // plan (the worst of their ends' errors, and δ twice).
            if kind != "value" {
                return Err("a cylinder's balancing force acts inside its group, not on the polygon: give it as a value".into());
            }
            let worst = plan.err.iter().copied().fold(0.0, f64::max);
            return Ok((b, (worst + 2.0 * ans.delta) * plan.mu, None));
        };
        // A driving slider's is laid off on the polygon: a vector of it.
        let v = &plan.vectors[i];
        let seg = plan.points[v.to] - plan.points[v.from];
        if kind == "value" {
            let tol = vector_tolerance(plan, i, ans.delta) * plan.mu;
            return Ok((b, tol, Some(seg.hypot())));
        }
        return Ok(vector_item(plan, i, kind, ans.delta));
    }
    if crate::words::forces::is_balancing(&k, "M") && !balances_a_crank(an, plan) {
        return Err("this input is a driving slider: its balancing value is the force F_b".into());
    }
    if crate::words::forces::is_balancing(&k, "M") {
        if kind != "value" {
            return Err("the balancing moment (force) is a value, not a segment".into());
        }
        let (b, forces) = balancing(plan)
            .ok_or("this plan has no balancing moment (force): it is the input link's")?;
        let Some(mu_l) = ans.mu_l else {
            return Err(
                "give mu_l, the scale of your drawing of the mechanism (m/mm): the arms of the balancing moment are measured on it"
                    .into(),
            );
        };
        return Ok((b, balancing_tolerance(plan, ans, mu_l, forces), None));
    }
    let found = plan
        .vectors
        .iter()
        .rposition(|v| key(&force_name(&an.mech, loads, v.force, Lang::En)) == k)
        .ok_or_else(|| {
            let names: Vec<String> = plan
                .vectors
                .iter()
                .map(|v| force_name(&an.mech, loads, v.force, Lang::En))
                .collect();
            format!(
                "no force \"{name}\" on this plan (its forces: {})",
                names.join(", ")
            )
        })?;
    Ok(vector_item(plan, found, kind, ans.delta))
}

/// Vector `i` of `plan` as an item of kind `kind`: its segment, its
/// value or its direction, with the tolerance of the step that draws it.
fn vector_item(plan: &ForcePlan, i: usize, kind: &str, delta: f64) -> Expect {
    let v = &plan.vectors[i];
    let seg = plan.points[v.to] - plan.points[v.from];
    let tol_mm = vector_tolerance(plan, i, delta);
    match kind {
        "segment" => (seg.hypot(), tol_mm, Some(seg.hypot())),
        "value" => (v.value.hypot(), tol_mm * plan.mu, Some(seg.hypot())),
        _ => {
            let deg = seg.y.atan2(seg.x).to_degrees().rem_euclid(360.0);
            // A vector no longer than its own tolerance may point anywhere.
            let tol = if seg.hypot() <= tol_mm {
                180.0
            } else {
                (tol_mm / seg.hypot()).asin().to_degrees()
            };
            // (its vector's length on the plan, to say how small it is)
            (deg, tol, Some(seg.hypot()))
        }
    }
}

/// Whether `plan`'s balancing value is a crank's moment (else a driving
/// slider's or a cylinder's force).
fn balances_a_crank(an: &Analysis, plan: &ForcePlan) -> bool {
    plan.steps.iter().any(|s| match s {
        ForceStep::Balancing { input, .. } => matches!(
            an.mech.scene.input_at(*input),
            crate::model::scene::InputSpec::Crank { .. }
        ),
        _ => false,
    })
}

/// A vector's tolerance on the plan, mm, judged as its step draws it: a
/// load laid off from the student's own previous point, 2δ (drawn and
/// read), wherever it stands in the polygon; a reaction carried over from
/// another plan or a moment equation and laid off, 4δ (its value read
/// there as well); a reaction read off the closed polygon, the drafting
/// error of its two ends (amplified where the closing lines meet) and δ.
fn vector_tolerance(plan: &ForcePlan, k: usize, delta: f64) -> f64 {
    let v = &plan.vectors[k];
    let laid_off = plan.steps.contains(&ForceStep::LayOff(k));
    match (laid_off, v.force) {
        (true, Force::Load(_)) => 2.0 * delta,
        (true, _) => 4.0 * delta,
        (false, _) => plan.err[v.from] + plan.err[v.to] + delta,
    }
}

/// The balancing moment's tolerance, N·m: each arm measured to δ on the
/// drawing at μ_l (δ·μ_l·|F|), each force read to δ (a load) or 2δ (a
/// reaction read off its plan) at μ_F times its arm. `forces`: the sum of
/// the forces, for a plan without arms (δ·μ_l·Σ|F|).
fn balancing_tolerance(plan: &ForcePlan, ans: &ForceAnswer, mu_l: f64, forces: f64) -> f64 {
    if plan.arms.is_empty() {
        return ans.delta * mu_l * forces;
    }
    plan.arms
        .iter()
        .map(|&(k, arm)| {
            let v = &plan.vectors[k];
            let read = match v.force {
                Force::Load(_) => ans.delta,
                _ => 2.0 * ans.delta,
            };
            ans.delta * mu_l * v.value.hypot() + arm * read * plan.mu
        })
        .sum()
}

/// The difference of two readings of kind `kind` (angles modulo 360°).
fn difference(kind: &str, a: f64, b: f64) -> f64 {
    if kind == "angle" {
        let d = (a - b).rem_euclid(360.0);
        d.min(360.0 - d)
    } else {
        (a - b).abs()
    }
}

/// Check a force-plan answer against the analysis (the report in English).
#[cfg(feature = "internals")]
pub fn check(an: &Analysis, solved: &[Solved], ans: &ForceAnswer) -> Result<ForceReport> {
    check_in(an, solved, ans, Lang::En)
}

/// [`check`] with the report's words in `lang`.
pub fn check_in(
    an: &Analysis,
    solved: &[Solved],
    ans: &ForceAnswer,
    lang: Lang,
) -> Result<ForceReport> {
    let (at, s) = super::position_of(an, solved, ans.position)?;
    let Some(fp) = s.dynamics.as_ref().and_then(|d| d.force_plans.as_ref()) else {
        return Err(Error::scene(
            "/plan",
            "the scene has no force plans to check against: it needs a dynamics object",
        ));
    };
    let right_loads = s.dynamics.as_ref().map_or(&[][..], |d| &d.loads[..]);
    let ans = &with_links(an, right_loads, &fp.plans, (an.numbering.number(at), ans))?;
    let Some((w, _)) = which(an, &fp.plans, &ans.links) else {
        let all: Vec<String> = fp
            .plans
            .iter()
            .map(|p| {
                let ids: Vec<&str> = p.links.iter().map(|&l| an.mech.link_id(l)).collect();
                format!("[{}]", ids.join(", "))
            })
            .collect();
        return Err(Error::scene(
            "/links",
            format!(
                "no force plan of these links (the plans: {})",
                all.join(", ")
            ),
        ));
    };
    if let Some(mu_l) = ans.mu_l {
        drawn_large_enough(an, s, mu_l)?;
    }
    let place = mistakes::At {
        an,
        s,
        loads: right_loads,
        delta: ans.delta,
        which: w,
        mu: ans.mu,
        links: &ans.links,
    };
    let plan = place.plan(right_loads, None)?;
    // The typical mistakes, as whole plans at the student's scale.
    let mistaken: Vec<(ForceMistake, ForcePlan)> = ForceMistake::ALL
        .into_iter()
        .flat_map(|m| place.mistaken(m, &plan).into_iter().map(move |p| (m, p)))
        .collect();
    let judge = Judge {
        an,
        loads: right_loads,
        plan: &plan,
        ans,
        mistaken: &mistaken,
        lang,
    };
    let (readings, issues) = judge.read_all();
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    Ok(judge.report(an.numbering.number(at), &readings))
}

/// Refuses a μ_l at which the mechanism is drawn under 10 mm across: the
/// arms of M_b read there would make its tolerance as large as itself,
/// and a wrong M_b would pass as too small to judge.
fn drawn_large_enough(an: &Analysis, s: &Solved, mu_l: f64) -> Result<()> {
    let mut box_ = kurbo::Rect::from_points(s.point(an, 0).at, s.point(an, 0).at);
    for p in 1..an.mech.scene.points.len() {
        box_ = box_.union_pt(s.point(an, p).at);
    }
    let across = box_.width().hypot(box_.height()) / mu_l;
    if across >= 10.0 {
        return Ok(());
    }
    let mm = crate::format::num(across);
    Err(Error::scene(
        "/mu_l",
        format!(
            "μ_l = {mu_l} m/mm draws the mechanism {mm} mm across: a drawing of it at least 10 mm across is needed to read the arms of M_b"
        ),
    ))
}

/// The answer with its plan's links: an SVG answer names its forces, not
/// its links, and the plan holding them all gives them.
fn with_links(
    an: &Analysis,
    loads: &[Load],
    plans: &[ForcePlan],
    (position, ans): (usize, &ForceAnswer),
) -> Result<ForceAnswer> {
    let mut ans = ans.clone();
    if ans.links.is_empty() {
        let names: Vec<String> = ans.segments.iter().map(|x| x.1.clone()).collect();
        if let Some((_, i)) = which_by_names(an, loads, plans, &names) {
            ans.links = plans[i]
                .links
                .iter()
                .map(|&l| an.mech.link_id(l).to_string())
                .collect();
        } else {
            return Err(Error::scene(
                "svg",
                format!(
                    "no force plan of position {position} has all the forces labelled ({})",
                    names.join(", ")
                ),
            ));
        }
    }
    Ok(ans)
}

/// An item's kind as the catalogue orders them: segment, angle, value.
fn kind_index(kind: &str) -> usize {
    match kind {
        "segment" => 0,
        "angle" => 1,
        _ => 2,
    }
}

/// What the items are judged against: the plan at the student's scale
/// with the right loads, and the plans of the typical mistakes.
struct Judge<'a> {
    an: &'a Analysis,
    loads: &'a [Load],
    plan: &'a ForcePlan,
    ans: &'a ForceAnswer,
    mistaken: &'a [(ForceMistake, ForcePlan)],
    /// The language of the report's words.
    lang: Lang,
}

/// One item of the answer read against every plan: what the right plan
/// expects, and whether each mistaken plan gives it (and differs there
/// from the right one).
struct Reading<'a> {
    kind: &'static str,
    unit: &'static str,
    pointer: &'a str,
    name: &'a str,
    given: f64,
    expect: Expect,
    /// Per mistaken plan: (it gives the item within its tolerance, it is
    /// apart from the right plan there).
    mistakes: Vec<(bool, bool)>,
}

impl Judge<'_> {
    /// Every item of the answer read (segments, directions, values); the
    /// items that cannot be read, as issues.
    fn read_all(&self) -> (Vec<Reading<'_>>, Vec<crate::error::Issue>) {
        let ans = self.ans;
        let items = [
            ("segment", &ans.segments, "mm"),
            ("angle", &ans.angles, "°"),
            ("value", &ans.values, ""),
        ];
        let mut readings = Vec::new();
        let mut issues = Vec::new();
        for (kind, list, unit) in items {
            for (pointer, name, given) in list.iter() {
                match self.read((kind, unit), pointer, name, *given) {
                    Ok(r) => readings.push(r),
                    Err(i) => issues.push(i),
                }
            }
        }
        (readings, issues)
    }

    /// The item `name` of kind `kind` that gives `given`, read against the
    /// right plan and every mistaken one. `Err`: it cannot be read.
    fn read<'b>(
        &self,
        (kind, unit): (&'static str, &'static str),
        pointer: &'b str,
        name: &'b str,
        given: f64,
    ) -> std::result::Result<Reading<'b>, crate::error::Issue> {
        let (an, loads, ans) = (self.an, self.loads, self.ans);
        let w = check::phrases(self.lang);
        let (expected, tol, on_plan) =
            expect(an, loads, self.plan, kind, name, ans).map_err(|msg| issue(pointer, msg))?;
        let unit = match (kind, unit) {
            ("value", _) if key(name).starts_with('M') => "N·m",
            ("value", _) => "N",
            (_, u) => u,
        };
        if !(expected.is_finite() && tol.is_finite()) {
            let mu = crate::format::num(ans.mu);
            return Err(issue(pointer, check::fill(&w.force_not_finite, &[("mu", &mu)])));
        }
        let mistakes = self
            .mistaken
            .iter()
            .map(|(_, p)| match expect(an, loads, p, kind, name, ans) {
                Ok((e2, t2, _)) if e2.is_finite() && t2.is_finite() => (
                    difference(kind, given, e2) <= t2,
                    difference(kind, e2, expected) > tol,
                ),
                _ => (false, false),
            })
            .collect();
        Ok(Reading {
            kind,
            unit,
            pointer,
            name,
            given,
            expect: (expected, tol, on_plan),
            mistakes,
        })
    }

    /// The report: each item right, wrong, too small to judge, or not to
    /// be judged because the whole answer fits a mistaken plan as well as
    /// the right one; the mistake named when the whole answer fits it and
    /// no other.
    fn report(&self, position: usize, readings: &[Reading]) -> ForceReport {
        let w = check::phrases(self.lang);
        // The mistaken plans the whole answer fits, that differ somewhere.
        let fits: Vec<usize> = (0..self.mistaken.len())
            .filter(|&j| {
                readings.iter().all(|r| r.mistakes[j].0) && readings.iter().any(|r| r.mistakes[j].1)
            })
            .collect();
        let mut verdicts = Vec::new();
        let mut small = Vec::new();
        for r in readings {
            let (expected, tol, on_plan) = r.expect;
            let diff = difference(r.kind, r.given, expected);
            let also = fits.iter().find(|&&j| r.mistakes[j].1);
            let judgement = if diff > tol {
                Judgement::Wrong
            } else if (r.kind != "angle" && tol >= expected.abs()) || (r.kind == "angle" && tol >= 180.0) {
                small.push(verdicts.len());
                let what = format!("{} {}", w.force_kinds[kind_index(r.kind)], r.name);
                Judgement::CannotJudge(match on_plan {
                    Some(mm) => {
                        let size = crate::format::num(round_to(mm, 0.1));
                        let size = numbers::decimals(&size, self.lang);
                        check::fill(&w.force_small, &[("what", &what), ("size", &size)])
                    }
                    None => {
                        let tol = numbers::quantity(tol, r.unit, self.lang);
                        check::fill(&w.force_small_value, &[("what", &what), ("tol", &tol)])
                    }
                })
            } else if let Some(&j) = also {
                let what = self.mistaken[j].0.words(self.lang);
                Judgement::CannotJudge(check::fill(&w.force_mistake_too, &[("what", &what)]))
            } else {
                Judgement::Right
            };
            verdicts.push(Verdict {
                pointer: r.pointer.to_string(),
                key: r.name.to_string(),
                what: format!("{} {}", w.force_kinds[kind_index(r.kind)], r.name),
                expected,
                given: r.given,
                difference: diff,
                tolerance: tol,
                unit: r.unit,
                on_plan: on_plan.filter(|_| r.kind != "angle").map(|e| {
                    (
                        e,
                        if r.kind == "value" {
                            r.given / self.ans.mu
                        } else {
                            r.given
                        },
                    )
                }),
                step: None,
                judgement,
            });
        }
        let (named, alike) = self.named(readings, &verdicts);
        let mistake = named.map(|j| self.mistaken[j].0);
        let either = (alike.len() > 1).then(|| {
            let all: Vec<String> = alike.iter().map(|m| m.words(self.lang)).collect();
            check::fill(&w.force_either, &[("mistakes", &all.join(&w.force_or))])
        });
        let diagnosis = named.map(|j| {
            let m = self.mistaken[j].0;
            let first = (0..readings.len())
                .find(|&i| verdicts[i].judgement == Judgement::Wrong && readings[i].mistakes[j].0);
            match first {
                Some(i) => check::fill(
                    &w.force_first_at,
                    &[("mistake", &m.words(self.lang)), ("item", &verdicts[i].what)],
                ),
                None => m.words(self.lang),
            }
        });
        let diagnosis = diagnosis.or(either);
        ForceReport {
            position,
            links: self.ans.links.clone(),
            mu: self.ans.mu,
            delta: self.ans.delta,
            verdicts,
            small,
            mistake,
            diagnosis,
            lang: self.lang,
            plan: self.plan.clone(),
            names: self
                .plan
                .vectors
                .iter()
                .map(|v| {
                    crate::words::forces::force(&self.an.mech, self.loads, v.force, self.lang)
                        .unwrap_or_else(|| Label::new("?", ""))
                })
                .collect(),
        }
    }
}

impl Judge<'_> {
    /// The mistake to name: the one mistaken plan that explains every
    /// wrong item and every other item as well (a reading of the finished
    /// plan, like a reaction read the wrong way round, may touch some
    /// items only: there the others may be right), and no other does.
    /// Beside it, every mistake that explains the answer so (more than one:
    /// the answer cannot tell them apart, and none is named).
    fn named(
        &self,
        readings: &[Reading],
        verdicts: &[Verdict],
    ) -> (Option<usize>, Vec<ForceMistake>) {
        let wrong = |i: usize| verdicts[i].judgement == Judgement::Wrong;
        if !(0..readings.len()).any(wrong) {
            return (None, Vec::new());
        }
        let explains = |j: usize| {
            let partial = self.mistaken[j].0 == ForceMistake::ActionForReaction;
            (0..readings.len()).all(|i| {
                let (fits, _) = readings[i].mistakes[j];
                fits || (partial && !wrong(i))
            })
        };
        // One mistake, though it may be drawn more ways than one (τ's sign).
        let found: Vec<usize> = (0..self.mistaken.len()).filter(|&j| explains(j)).collect();
        let mut alike: Vec<ForceMistake> = Vec::new();
        for &j in &found {
            if !alike.contains(&self.mistaken[j].0) {
                alike.push(self.mistaken[j].0);
            }
        }
        let one = (alike.len() == 1).then(|| found[0]);
        (one, alike)
    }
}

/// `x` to the nearest multiple of `step`.
fn round_to(x: f64, step: f64) -> f64 {
    (x / step).round() * step
}
