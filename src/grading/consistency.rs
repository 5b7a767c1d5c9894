//! Is the answer one answer, of the plan it states, and are its points
//! of the position it states? Refused before anything is judged (bad
//! input, each problem at its field): a name of the other plan (`k3`, a
//! Coriolis point, or the pole `p_a` in a velocity answer; `p_v` in an
//! acceleration answer), a name no plan has, a thing given twice under
//! two spellings (`n2` and `n_2`). Points that do not fit the position the
//! answer states but fit another position of the scene well, or fit it
//! with the crank turned the other way, are never refused: the answer is
//! graded at the position it states, with a note saying where they fit
//! ([`Elsewhere`]).
//!
//! Cost: one plan build at the stated position (the check builds it again;
//! a plan build is a small part of a check, whose diagnosis builds dozens),
//! and only when the answer gives at least two points that do not all fit
//! there, one more plan build at each other position of the scene and one
//! with ω1 reversed at the stated one (docs/check.md measures it).

use super::answer::{Answer, Given, Item};
use super::candidates::Builds;
use super::items::{expect, given_twice, names, pole_of, resolve};
use super::verdict::Elsewhere;
use crate::error::{Error, Issue, Result};
use crate::kinematics::construction::{Mistake, Plan, PlanKind, PointId, Variant};
use crate::kinematics::solve::Analysis;
use crate::lang::Lang;
use crate::pipeline::Solved;
use kurbo::Vec2;

/// How much better another position (or the stated one with ω1
/// reversed) must fit the answer's points than the stated one (Σ
/// distance/tolerance) for the report to say the points fit there.
pub(super) const BETTER_FIT: f64 = 10.0;

/// Refuse an answer whose names are of the other plan or of no plan, or
/// that gives a thing twice; else where its points fit if not at the
/// position it states (`at`, the index of the stated position): the note
/// of its report, never a refusal. A plan the scene cannot build is left
/// to [`super::check`] to refuse.
pub(super) fn refuse_inconsistent(
    an: &Analysis,
    solved: &[Solved],
    (at, ans): (usize, &Answer),
    lang: Lang,
) -> Result<Option<Elsewhere>> {
    let s = &solved[at];
    let Ok(plan) = Builds::new(an, s, ans, lang).plan(&s.config, Variant::default()) else {
        return Ok(None);
    };
    let other = s.plans.as_ref().and_then(|p| match ans.plan {
        PlanKind::Velocity => p.acceleration.as_ref(),
        PlanKind::Acceleration => Some(&p.velocity),
    });
    let mut issues = Vec::new();
    for it in &ans.items {
        if let Some(i) = of_the_other_plan(&plan, other, it) {
            issues.push(i);
        } else if let Err(i) = expect(an, &plan, it, ans.delta, lang) {
            issues.push(i);
        }
    }
    issues.extend(given_twice(an, &plan, &ans.items));
    if issues.is_empty() {
        Ok(elsewhere(an, solved, (at, ans), &plan, lang))
    } else {
        Err(Error::fields(issues))
    }
}

/// The plan points item `it` names (a segment's two ends, split where
/// each half is a point of `plan` or of `other`).
fn names_of(plan: &Plan, other: Option<&Plan>, it: &Item) -> Vec<String> {
    let known = |s: &str| {
        resolve(plan, s).is_some()
            || pole_of(s).is_some()
            || other.is_some_and(|o| resolve(o, s).is_some())
    };
    match &it.given {
        Given::Point { name, .. } => vec![name.clone()],
        Given::Segment { from, .. } | Given::Angle { from, .. } => {
            super::answer::split_segment(from, &known)
                .map(|(a, b)| vec![a, b])
                .unwrap_or_default()
        }
        Given::Value { .. } => Vec::new(),
    }
}

/// The issue of item `it` if it names a point that `plan` does not have
/// but the other plan of the position (`other`) does: the pole of the
/// other plan, or an acceleration plan's construction point (`n2`, `k3`)
/// in a velocity answer. The message names where the answer says its
/// plan: `/plan`, or a drawing's pole label and `--plan`.
fn of_the_other_plan(plan: &Plan, other: Option<&Plan>, it: &Item) -> Option<Issue> {
    let (this, that) = match plan.kind {
        PlanKind::Velocity => ("velocity", "acceleration"),
        PlanKind::Acceleration => ("acceleration", "velocity"),
    };
    let name = names_of(plan, other, it)
        .into_iter()
        .find(|n| resolve(plan, n).is_none() && other_has(plan, other, n))?;
    let what = match other.and_then(|o| resolve(o, &name).map(|i| o.points[i].id)) {
        Some(PointId::Coriolis { .. }) => " (a Coriolis point)",
        Some(PointId::Normal { .. }) => " (the end of a normal component)",
        _ if pole_of(&name).is_some() => " (its pole)",
        _ => "",
    };
    let said = if it.pointer.starts_with("svg") {
        format!("this drawing is a {this} plan (by --plan or its pole's label)")
    } else {
        format!("/plan says \"{this}\"")
    };
    Some(Issue {
        pointer: it.pointer.clone(),
        message: format!(
            "\"{name}\" belongs to the {that} plan{what}, but {said}: if the answer is the {that} plan, say so; else name the {this} plan's points ({})",
            names(plan)
        ),
    })
}

/// Is `name` a point of the other plan than `plan`: its pole, or a point
/// of `other`?
fn other_has(plan: &Plan, other: Option<&Plan>, name: &str) -> bool {
    pole_of(name).is_some_and(|k| k != plan.kind) || other.is_some_and(|o| resolve(o, name).is_some())
}

/// How the answer's points fit `plan`: Σ distance/tolerance over them, and
/// whether each is within its tolerance; `None` if a name does not
/// resolve there.
fn fit(plan: &Plan, points: &[(&str, [f64; 2])], delta: f64) -> Option<(f64, bool)> {
    let (mut misfit, mut within) = (0.0, true);
    for (name, at) in points {
        let p = &plan.points[resolve(plan, name)?];
        let d = (Vec2::new(at[0], at[1]) - p.at).hypot() / (p.err + delta);
        misfit += d;
        within &= d <= 1.0;
    }
    Some((misfit, within))
}

/// Where the answer's points (two or more) fit when they do not fit the
/// stated position's `plan` (the position at index `at`): the stated
/// position with ω1 reversed, and the other position that fits best, each
/// when it fits every point within its tolerance and [`BETTER_FIT`] times
/// better than the stated one (both, where a symmetric mechanism's
/// reversed plan equals another position's). The other plans are built
/// (at the student's μ) only when the stated one does not fit.
fn elsewhere(
    an: &Analysis,
    solved: &[Solved],
    (at, ans): (usize, &Answer),
    plan: &Plan,
    lang: Lang,
) -> Option<Elsewhere> {
    let points: Vec<(&str, [f64; 2])> = ans
        .items
        .iter()
        .filter_map(|it| match &it.given {
            Given::Point { name, at } => Some((name.as_str(), *at)),
            _ => None,
        })
        .collect();
    if points.len() < 2 {
        return None;
    }
    let (stated, within) = fit(plan, &points, ans.delta)?;
    if within {
        return None;
    }
    let fits = |s: &Solved, variant: Variant| {
        let p = Builds::new(an, s, ans, lang).plan(&s.config, variant).ok()?;
        match fit(&p, &points, ans.delta) {
            Some((m, true)) if stated > BETTER_FIT * m => Some(m),
            _ => None,
        }
    };
    let reversed = fits(&solved[at], Variant::everywhere(Mistake::OmegaWrongSense));
    let mut best: Option<(usize, f64)> = None;
    for (k, s) in solved.iter().enumerate() {
        if k == at {
            continue;
        }
        if let Some(m) = fits(s, Variant::default())
            && best.is_none_or(|(_, b)| m < b)
        {
            best = Some((k, m));
        }
    }
    let position = best.map(|(k, _)| an.numbering.number(k));
    (reversed.is_some() || position.is_some()).then_some(Elsewhere {
        reversed: reversed.is_some(),
        position,
    })
}
