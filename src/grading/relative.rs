//! The answer's items judged relative to the student's own drawing: a
//! drawn point by the step that draws it ([`super::steps`]), a segment, a
//! direction or a value on the replayed plan (the student's points where
//! they drew them, the others predicted from those), so a value read off
//! a point drawn wrong is judged as a reading, not as the mistake again.

use super::candidates::Builds;
use super::items::expect;
use super::verdict::{Judgement, MAX_TOLERANCE_OF_PLAN, Report, StepReport, Verdict};
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
                    Some(s) => Verdict {
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
