//! A plan drawn at another scale than the one it states: every point the
//! student drew is the right plan's times one factor (μ_stated/μ_drawn:
//! twice, half, μ inverted, μ in mm instead of m …), so the first vector
//! laid off is off by it and, judged at the stated μ, every later step
//! that lays off a length too. Named as one mistake — "drawn at μ = X,
//! stated μ = Y" — made before the plan is drawn; the steps are then
//! replayed at the drawn μ, so that a further mistake is still found at
//! its own step, and the values are read with the μ the student states
//! (their consistent readings are not blamed again).

use super::candidates::Builds;
use super::steps;
use super::verdict::{Candidate, Found, StepReport};
use crate::error::Result;
use crate::format::format_number;
use crate::kinematics::construction::{Plan, PlanKind};
use crate::lang::Lang;
use crate::words::check;
use crate::words::numbers::{decimals, unit};

/// The smallest plan, in pencil widths δ, whose scale is read off it: a
/// plan a few δ across is a dot that fits any scale.
const MIN_PLAN_DELTAS: f64 = 10.0;

/// The student's points' factors against the right plan at the stated
/// scale `standard`: the earliest point's, and the median of all (each a
/// point's projection on the right one, over its length; points drawn
/// within 2δ of the pole tell nothing).
fn factors(b: &Builds, standard: &Plan, steps: &StepReport) -> Vec<f64> {
    let delta = b.ans.delta;
    let mut each: Vec<f64> = steps
        .replay
        .judged
        .iter()
        .filter_map(|j| {
            let right = standard.points.get(j.point)?.at;
            (right.hypot() > 0.0 && j.given.hypot() > 2.0 * delta)
                .then(|| j.given.dot(right) / right.hypot2())
        })
        .filter(|f| f.is_finite() && *f > 0.0)
        .collect();
    let first = each.first().copied();
    each.sort_by(f64::total_cmp);
    let median = each.get(each.len() / 2).copied();
    let mut out: Vec<f64> = first.into_iter().chain(median).collect();
    out.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-3);
    out
}

/// How far the drawn points are from their steps in all, each over its
/// tolerance (a wrong one counted as 10 at most).
fn misfit(steps: &StepReport) -> f64 {
    steps
        .steps
        .iter()
        .map(|s| (s.off / s.tolerance.max(1e-300)).min(10.0))
        .sum()
}

/// The plan drawn at another scale than stated: where replaying the
/// steps at a scale the student's points suggest leaves fewer steps wrong
/// than at the stated one (and the first point right), the steps so
/// replayed, their values read with the stated μ, and the scale's
/// mistake.
pub(super) fn drawn_at_another(
    b: &Builds,
    standard: &Plan,
    steps: &StepReport,
    lang: Lang,
) -> Result<Option<(StepReport, Found)>> {
    let wrong = steps.wrong_steps();
    // Another scale shows at every vector laid off to length: at two
    // steps at least, where the plan lays off more than one (one wrong
    // length among others is a slip); where it lays off one (a velocity
    // plan of one crank, every later point found by directions), that one
    // vector off and every later step consistent with it is the plan
    // drawn at another scale.
    let lengths = standard
        .steps
        .iter()
        .filter(|s| matches!(s.op, crate::kinematics::construction::Op::LayOff { .. }))
        .count();
    // (One point tells a wrong length from another scale no more than a
    // slip: a scale is read off two points at least.)
    if wrong == 0 || steps.steps.len() < 2 {
        return Ok(None);
    }
    // One step wrong among several lengths: another scale only where the
    // later lengths, drawn at it, fit at least as well as at the stated
    // one (they may be too short to tell; then the scale explains as
    // well as a slip does, and is the simpler account of a plan whose
    // first vector alone is off).
    let alone = wrong < 2 && lengths > 1;
    let mu = b.ans.mu;
    let points_drawn = b
        .ans
        .items
        .iter()
        .any(|it| matches!(it.given, super::answer::Given::Point { .. }));
    let mut best: Option<(StepReport, f64)> = None;
    for f in factors(b, standard, steps) {
        // A factor the pencil could draw is no other scale.
        if (f - 1.0).abs() < 0.02 {
            continue;
        }
        let drawn = mu / f;
        let at = Builds {
            drawn_mu: Some(drawn),
            unused: b.unused.clone(),
            ..Builds::new(b.an, b.s, b.ans, b.lang)
        };
        let mut scaled = standard.clone();
        for p in &mut scaled.points {
            p.at *= f;
            p.err *= f;
        }
        scaled.mu = drawn;
        // A plan drawn so small that every point is within a few pencil
        // widths of the pole fits any scale: no scale is read off it.
        let size = scaled.points.iter().map(|p| p.at.hypot()).fold(0.0, f64::max);
        if size < MIN_PLAN_DELTAS * b.ans.delta {
            continue;
        }
        let Ok(Some(other)) = steps::judge(&at, &scaled, lang) else {
            continue;
        };
        let first_right = other
            .steps
            .first()
            .is_some_and(|s| s.judgement != super::Judgement::Wrong);
        let n = other.wrong_steps();
        // A table's numbers are readings each on its own: another scale
        // is what they show only where it explains every one.
        let fits = (!alone || misfit(&other) <= misfit(steps)) && (points_drawn || n == 0);
        if fits && first_right && n < wrong && best.as_ref().is_none_or(|x| n < x.0.wrong_steps()) {
            best = Some((other, drawn));
        }
    }
    let Some((mut other, drawn)) = best else {
        return Ok(None);
    };
    // The values are read with the μ the student states.
    other.replay.mu = mu;
    Ok(Some((other, scale_mistake(b, drawn, lang))))
}

/// The mistake of a plan drawn at `drawn` instead of the stated scale:
/// made before the plan, named with both scales (and as μ inverted or in
/// the wrong units where it is; for an answer of values alone, as μ
/// applied so), the scale's step quoted with the student's beside it.
fn scale_mistake(b: &Builds, drawn: f64, lang: Lang) -> Found {
    let mu = b.ans.mu;
    let w = check::phrases(lang);
    let fmt = |x: f64| decimals(&format_number(x), lang);
    let u = unit(
        if b.ans.plan == PlanKind::Velocity {
            "(m/s)/mm"
        } else {
            "(m/s²)/mm"
        },
        lang,
    );
    let c = Candidate::DrawnScale { drawn, stated: mu };
    let mut mistake = super::candidates::mistake_sentence(c, mu, "", lang);
    let ratio = mu / drawn;
    let inverted = (mu * drawn - 1.0).abs() < 0.02;
    let units = [1000.0, 1e-3].iter().any(|k| (ratio / k - 1.0).abs() < 0.02);
    // An answer of values alone draws nothing: its values are off by the
    // factor, μ applied wrongly.
    let values_only = b
        .ans
        .items
        .iter()
        .all(|it| matches!(it.given, super::answer::Given::Value { .. }));
    if values_only && units {
        mistake = w.scale_units.clone();
    } else if values_only && inverted {
        mistake = check::fill(&w.scale_inverted, &[("mu", &fmt(mu))]);
    } else if inverted {
        mistake.push(' ');
        mistake.push_str(&w.scale_drawn_inverted);
    } else if units {
        mistake.push(' ');
        mistake.push_str(&w.scale_drawn_units);
    }
    let step = check::fill(&w.scale_step, &[("mu", &fmt(mu)), ("unit", &u)]);
    let yours = check::fill(&w.yours, &[("value", &format!("μ = {} {u}", fmt(drawn)))]);
    Found {
        explanation: Some(c),
        mistake: Some(mistake),
        step: (0, format!("{step} ({yours})")),
        points: Vec::new(),
        alternatives: Vec::new(),
    }
}
