//! The answer's items judged relative to the student's own drawing: a
//! drawn point by the step that draws it ([`super::steps`]), a segment, a
//! direction or a value on the replayed plan (the student's points where
//! they drew them, the others predicted from those), so a value read off
//! a point drawn wrong is judged as a reading, not as the mistake again.

use super::candidates::Builds;
use super::answer::{Given, Item};
use super::items::expect;
use super::verdict::{Judgement, MAX_TOLERANCE_OF_PLAN, Report, StepReport, StepVerdict, Verdict};
use crate::words::check;
use crate::words::numbers::quantity;

/// The verdicts of the answer's items, in its order: drawn points from
/// their steps, the other items on the replay; an item the replay cannot
/// place keeps the true plan's verdict (`global`).
pub(super) fn verdicts(b: &Builds, global: &Report, steps: &StepReport) -> Vec<Verdict> {
    let (standard, replay) = (&global.plan_built, &steps.replay);
    let w = check::phrases(b.lang);
    // (The plan's size as drawn: a plan drawn at another scale than
    // stated is judged at its own.)
    let size = replay
        .points
        .iter()
        .map(|p| p.at.hypot())
        .fold(0.0, f64::max);
    let n = b.ans.items.len();
    let gives = super::table::gives(b, standard);
    let mut out: Vec<Verdict> = b
        .ans
        .items
        .iter()
        .zip(&global.verdicts)
        .zip(&gives)
        .map(|((it, g), gives)| {
            // A point the item gives (drawn, or a table's measure of it):
            // judged at the step that draws it.
            if let Some((i, _)) = gives {
                let i = *i;
                let id = standard.points[i].id;
                let nth = standard.points[..i].iter().filter(|p| p.id == id).count();
                let step = replay
                    .judged
                    .iter()
                    .position(|j| j.id == id && j.nth == nth)
                    .map(|k| &steps.steps[k]);
                return match step {
                    Some(s) if matches!(it.given, Given::Point { .. }) => Verdict {
                        pointer: it.pointer.clone(),
                        key: it.key.clone(),
                        what: check::fill(&w.point_from_own, &[("name", &s.point)]),
                        expected: 0.0,
                        given: s.off,
                        difference: s.off,
                        tolerance: s.tolerance,
                        unit: "mm",
                        on_plan: Some((0.0, s.off)),
                        step: Some(s.step.clone()),
                        judgement: s.judgement.clone(),
                    },
                    // A table's measure of the point: in its own terms,
                    // against what the step puts there, judged as the step.
                    Some(s) => table_verdict(b, it, g, s),
                    None => g.clone(),
                };
            }
            let Ok(e) = expect(b.an, replay, it, b.ans.delta, b.lang) else {
                return g.clone();
            };
            let difference = (e.given - e.expected).abs();
            let tol_mm = e.tol_mm(replay.mu).unwrap_or(0.0);
            let judgement = if difference > e.tol {
                Judgement::Wrong
            } else if size > 0.0 && tol_mm > MAX_TOLERANCE_OF_PLAN * size {
                let (tol, size) = (quantity(tol_mm, "mm", b.lang), quantity(size, "mm", b.lang));
                Judgement::CannotJudge(check::fill(&w.too_wide, &[("tol", &tol), ("size", &size)]))
            } else {
                Judgement::Right
            };
            Verdict {
                pointer: it.pointer.clone(),
                key: it.key.clone(),
                what: e.what.clone(),
                expected: e.expected,
                given: e.given,
                difference,
                tolerance: e.tol,
                unit: e.unit,
                on_plan: e.on_plan,
                step: g.step.clone(),
                judgement,
            }
        })
        .collect();
    // The values stated as read off the velocity plan: judged against
    // the true ones, as the true plan's report has them.
    out.extend(global.verdicts.iter().skip(n).cloned());
    out
}

/// The verdict of a table's measure `it` of a point (a segment from the
/// pole, its direction, the point's value) judged at that point's step
/// `s`: what the step puts there in the measure's own unit, the student's
/// measure, the step's tolerance in that unit, the step's judgement. (`g`:
/// the true plan's verdict, for its name.)
fn table_verdict(b: &Builds, it: &Item, g: &Verdict, s: &StepVerdict) -> Verdict {
    let (p, mu) = (s.predicted, b.ans.mu);
    let (expected, given, tolerance, unit) = match &it.given {
        Given::Segment { mm, .. } => (p.hypot(), *mm, s.tolerance, "mm"),
        Given::Angle { deg, .. } => {
            let at = p.atan2().to_degrees();
            let given = at + crate::geom::wrap_pi((deg - at).to_radians()).to_degrees();
            let tol = (s.tolerance / p.hypot().max(1e-300))
                .min(std::f64::consts::PI)
                .to_degrees();
            // (Written from the point to the pole: the opposite direction.)
            let reversed = g.expected.is_finite()
                && crate::geom::wrap_pi((g.expected - at).to_radians()).abs() > 1.0;
            let at = if reversed { at + 180.0 } else { at };
            let given = at + crate::geom::wrap_pi((given - at).to_radians()).to_degrees();
            (at, given, tol, "°")
        }
        Given::Value { value, .. } => (p.hypot() * mu, *value, s.tolerance * mu, g.unit),
        Given::Point { .. } => (0.0, s.off, s.tolerance, "mm"),
    };
    Verdict {
        pointer: it.pointer.clone(),
        key: it.key.clone(),
        what: g.what.clone(),
        expected,
        given,
        difference: (given - expected).abs(),
        tolerance,
        unit,
        on_plan: match &it.given {
            Given::Segment { mm, .. } => Some((p.hypot(), *mm)),
            Given::Value { value, .. } => Some((p.hypot(), value / mu)),
            _ => None,
        },
        step: Some(s.step.clone()),
        judgement: s.judgement.clone(),
    }
}
