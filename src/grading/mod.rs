//! Checking hand-drawn plans: the student's answer item by item against
//! the construction at the student's own scale, with a tolerance from the
//! drafting-error model of the best-conditioned construction (pencil
//! precision δ propagated through it), a verdict that is never "right"
//! where the tolerance cannot tell the right answer from a typical mistake,
//! and a diagnosis by model selection: the plan rebuilt with each typical
//! mistake, made at one element or everywhere, and the one whose
//! construction explains the answer within its own tolerance, clearly
//! better than any other, named with the step where it enters.
//!
//! By part: the verdicts and the report ([`Judgement`], [`Verdict`],
//! [`Report`]), the items as a construction expects them (`items`), the
//! mistaken constructions tried and what cannot be judged
//! (`candidates`), the diagnosis (`diagnosis`), an answer refused before
//! it is judged: a name of the other plan, a thing given twice
//! (`consistency`, which also finds where points drawn at another
//! position fit: a note of the report, never a refusal), the position an
//! answer states (`position`). The verdict is data: its
//! text, JSON and overlay sheet are presentation's
//! (`crate::presentation::verdict`), reading the answer's file the front
//! door's (`crate::study`).

pub mod answer;
mod arrows;
mod candidates;
mod consistency;
mod diagnosis;
pub mod forces;
mod items;
mod numbers;
mod homography;
pub mod photo;
pub mod position;
pub mod read;
mod relative;
mod scale;
#[cfg(feature = "photo")]
mod snap;
mod stated;
mod steps;
mod table;
pub mod svg;
pub mod dxf;
mod dxf_text;
mod letters;
mod touching;
pub(crate) mod drawing;
mod verdict;

pub use verdict::Candidate as Explanation;
pub use items::resolve;
pub use verdict::{
    Candidate, Diagnosis, Elsewhere, Found, Grade, Judgement, Report, SecondOpinion, StepReport,
    StepVerdict, Verdict,
};

use crate::error::{Error, Result};
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::{PlanKind, Variant};
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::lang::Lang;
use crate::words::check::step as quoted_step;
use answer::Answer;
use candidates::{Builds, candidates, cannot_judge};
use diagnosis::diagnose;
use items::expect;

/// The position `stated` of `solved`: its index and the position; one the
/// scene does not have is refused, naming the range in the numbering in
/// force (the answer's own, else the study's, `an.numbering`).
fn position_of<'s>(
    an: &Analysis,
    solved: &'s [Solved],
    stated: position::StatedPosition,
) -> Result<(usize, &'s Solved)> {
    let k = stated
        .index(an.numbering, solved.len())
        .map_err(|m| Error::scene("/position", m))?;
    Ok((k, &solved[k]))
}

/// Check `answer` against the scene's analysis: an answer that draws
/// points step by step from the student's own points (the steps'
/// verdicts decide; the comparison with the true plan is the second
/// opinion), one that gives only segments and values against the true
/// plan.
#[cfg(feature = "internals")]
pub fn check(an: &Analysis, solved: &[Solved], ans: &Answer) -> Result<Report> {
    check_in(an, solved, ans, Lang::En)
}

/// [`check`] in `lang`: every sentence of the report (the grade, the
/// mistakes, the reasons, the items' names, the steps quoted) in that
/// language, its numbers with the language's decimal mark.
pub fn check_in(an: &Analysis, solved: &[Solved], ans: &Answer, lang: Lang) -> Result<Report> {
    let (_, s) = position_of(an, solved, ans.position)?;
    let b = Builds::new(an, s, ans, lang);
    let stated = stated::judge(&b, lang)?;
    let (mut report, _) = against_true_plan(an, solved, ans, lang, &stated)?;
    pole_at_the_origin(ans, &report.plan_built)?;
    let Some(mut steps) = steps::judge(&b, &report.plan_built, lang)? else {
        return Ok(report);
    };
    // A stated value written wrong that the drawing did not use: the
    // steps replayed with the true value for it fit better.
    let wrong: Vec<usize> = (0..stated.len())
        .filter(|&k| stated[k].found.is_some())
        .collect();
    let mut unused = false;
    if !wrong.is_empty() {
        let b = Builds {
            unused: wrong,
            ..Builds::new(an, s, ans, lang)
        };
        if let Some(other) = steps::judge(&b, &report.plan_built, lang)?
            && other.wrong_steps() < steps.wrong_steps()
        {
            steps = other;
            unused = true;
        }
    }
    // A plan drawn at another scale than stated: one mistake, the steps
    // judged at the drawn scale.
    let drawn = scale::drawn_at_another(&b, &report.plan_built, &steps, lang)?;
    let w = crate::words::check::phrases(lang);
    if let Some((other, _)) = &drawn {
        steps = other.clone();
    }
    steps.put_first(
        stated
            .iter()
            .filter_map(|j| j.found.clone())
            .map(|mut f| {
                // The drawing is built with the right value: only the
                // number written is wrong.
                if unused && let Some(m) = &mut f.mistake {
                    m.push(' ');
                    m.push_str(&w.stated_unused);
                }
                f
            })
            .collect(),
    );
    if let Some((_, found)) = drawn {
        report.verdicts.push(scale_verdict(ans, &found, lang));
        steps.put_first(vec![found]);
    }
    let global = report.clone();
    report.verdicts = relative::verdicts(&b, &report, &steps);
    table_with_true_plan(&b, &mut report, &global, &mut steps);
    let second = SecondOpinion::of(&global, (&steps, report.grade()), lang);
    // The mistake of the first wrong step; where it is not recognised,
    // or every step is right but items read off them are wrong (a
    // table's rates, values), the one the true plan's comparison names
    // from all the items together, if any.
    let global_named = global.diagnosis.clone().filter(|d| d.mistake.is_some());
    report.diagnosis = steps
        .mistakes
        .first()
        .filter(|f| f.mistake.is_some() || global_named.is_none())
        .map(|f| Diagnosis {
            mistake: f.mistake.clone(),
            explanation: f.explanation,
            step: Some(f.step.clone()),
            explained: f.points.len(),
            alternatives: f.alternatives.clone(),
        })
        .or_else(|| global_named.filter(|_| report.wrong() > 0));
    report.second_opinion = Some(second);
    report.steps = Some(steps);
    Ok(report)
}

/// A table (no point drawn) judged by its steps, and beside them by the
/// true plan: its numbers are readings a student may have made each on
/// its own, not a drawing each step of which stands on the last. So a
/// point it gives that fits the true plan is right even where it does not
/// follow from the table's earlier points (the step's mistake is then no
/// mistake), and where its steps find nothing wrong, an item the true
/// plan finds wrong — beyond the tolerance accumulated along the whole
/// construction, which no honest table exceeds — is wrong (the
/// direction a table of lengths leaves open can hide a mistake from its
/// steps, not from its rates and values).
fn table_with_true_plan(b: &Builds, report: &mut Report, global: &Report, steps: &mut StepReport) {
    let drawn = b
        .ans
        .items
        .iter()
        .any(|it| matches!(it.given, answer::Given::Point { .. }));
    if drawn {
        return;
    }
    let n = b.ans.items.len();
    let gives = table::gives(b, &global.plan_built);
    let mut cleared: Vec<String> = Vec::new();
    for ((v, g), gives) in report.verdicts.iter_mut().zip(&global.verdicts).zip(&gives) {
        if let Some((i, _)) = gives
            && v.judgement == Judgement::Wrong
            && g.judgement == Judgement::Right
        {
            *v = g.clone();
            cleared.push(global.plan_built.points[*i].name());
        }
    }
    if !cleared.is_empty() {
        let true_plan = &global.plan_built;
        for (st, j) in steps.steps.iter_mut().zip(&steps.replay.judged) {
            if st.judgement == Judgement::Wrong && cleared.contains(&st.point) {
                // Judged against the true plan: its place there, how far
                // the student's length (or point) is from it, and its
                // accumulated tolerance.
                let right = &true_plan.points[j.point.min(true_plan.points.len() - 1)];
                st.predicted = right.at;
                st.off = if j.on_circle {
                    (st.given.hypot() - right.at.hypot()).abs()
                } else {
                    (st.given - right.at).hypot()
                };
                st.tolerance = right.err + b.ans.delta;
                st.judgement = Judgement::Right;
                st.mistake = None;
            }
        }
        for f in &mut steps.mistakes {
            f.points.retain(|p| !cleared.contains(p));
        }
        // Mistakes left without a point they put off their place (made
        // before the plan, with no points, stay).
        let keep: Vec<bool> = steps
            .mistakes
            .iter()
            .map(|f| f.step.0 == 0 || !f.points.is_empty())
            .collect();
        let mut index = Vec::new();
        let mut m = 0;
        for &k in &keep {
            index.push(m);
            m += usize::from(k);
        }
        for st in &mut steps.steps {
            st.mistake = st.mistake.filter(|&i| keep[i]).map(|i| index[i]);
        }
        let mut i = 0;
        steps.mistakes.retain(|_| {
            i += 1;
            keep[i - 1]
        });
    }
    if steps.wrong_steps() == 0 {
        for k in 0..n {
            if global.verdicts[k].judgement == Judgement::Wrong
                && report.verdicts[k].judgement != Judgement::Wrong
            {
                report.verdicts[k] = global.verdicts[k].clone();
            }
        }
    }
}

/// The verdict on the scale a plan states where it is drawn at another:
/// wrong, the drawn scale expected.
fn scale_verdict(ans: &Answer, found: &verdict::Found, lang: Lang) -> Verdict {
    let drawn = match found.explanation {
        Some(verdict::Candidate::DrawnScale { drawn, .. }) => drawn,
        _ => ans.mu,
    };
    Verdict {
        pointer: "/mu".into(),
        key: "mu".into(),
        what: crate::words::check::phrases(lang).scale_item.clone(),
        expected: drawn,
        given: ans.mu,
        difference: (ans.mu - drawn).abs(),
        tolerance: 0.0,
        unit: if ans.plan == PlanKind::Velocity {
            "(m/s)/mm"
        } else {
            "(m/s²)/mm"
        },
        on_plan: None,
        step: Some(found.step.clone()),
        judgement: Judgement::Wrong,
    }
}

/// An answer's points are millimetres from the pole: a pole given
/// elsewhere than [0, 0] contradicts them (never read as a shift). The
/// pole is what the right plan `plan` resolves the name to (a scene point
/// named P is that point).
fn pole_at_the_origin(ans: &Answer, plan: &crate::kinematics::construction::Plan) -> Result<()> {
    for it in &ans.items {
        if let answer::Given::Point { name, at } = &it.given
            && resolve(plan, name) == Some(0)
            && (at[0] != 0.0 || at[1] != 0.0)
        {
            return Err(Error::fields(vec![crate::error::Issue {
                pointer: it.pointer.clone(),
                message: format!(
                    "the pole is the origin of the answer's coordinates: give it as [0, 0] or leave it out (given [{}, {}])",
                    at[0], at[1]
                ),
            }]));
        }
    }
    Ok(())
}

/// Every item of `answer` against the true plan at the student's scale,
/// with the tolerance accumulated along the whole construction; and which
/// items cannot be judged because a typical mistake explains the whole
/// answer as well.
fn against_true_plan(
    an: &Analysis,
    solved: &[Solved],
    ans: &Answer,
    lang: Lang,
    stated: &[stated::StatedJudged],
) -> Result<(Report, Vec<bool>)> {
    let (at, s) = position_of(an, solved, ans.position)?;
    if !an.plans
        || an.order.is_none()
        || (ans.plan == PlanKind::Acceleration && an.order != Some(Order::Acceleration))
    {
        return Err(Error::scene(
            "/plan",
            "the scene's want.plans does not include this plan",
        ));
    }
    let elsewhere = consistency::refuse_inconsistent(an, solved, (at, ans), lang)?;
    let b = Builds::new(an, s, ans, lang);
    let plan = b.plan(&s.config, Variant::default())?;
    let mut exp = Vec::new();
    let mut issues = Vec::new();
    for it in &ans.items {
        match expect(an, &plan, it, ans.delta, lang) {
            Ok(e) => exp.push(e),
            Err(i) => issues.push(i),
        }
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    let candidates = candidates(&b, &plan, &exp);
    // The plan's size: the farthest of its points from the pole.
    let size = plan.points.iter().map(|p| p.at.hypot()).fold(0.0, f64::max);
    let mut verdicts = Vec::new();
    let mut ambiguous = vec![false; ans.items.len()];
    for (k, (it, e)) in ans.items.iter().zip(&exp).enumerate() {
        let difference = (e.given - e.expected).abs();
        let judgement = if difference > e.tol {
            Judgement::Wrong
        } else {
            match cannot_judge(k, e, (size, plan.mu), &candidates, ans.mu, lang) {
                Some((why, by_mistake)) => {
                    ambiguous[k] = by_mistake;
                    Judgement::CannotJudge(why)
                }
                None => Judgement::Right,
            }
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
                .map(|k| (k + 1, quoted_step(&plan, k, lang))),
            judgement,
        });
    }
    verdicts.extend(stated.iter().map(|j| j.verdict.clone()));
    let mut report = Report {
        plan: ans.plan,
        position: an.numbering.number(at),
        elsewhere,
        mu: ans.mu,
        delta: ans.delta,
        worst_angle: plan.worst_angle_deg(),
        diagnosis: None,
        verdicts,
        plan_built: plan,
        steps: None,
        second_opinion: None,
        lang,
    };
    if report.wrong() > 0 {
        // A value stated wrong is the mistake the plan is built on.
        report.diagnosis = Some(match stated.iter().find_map(|j| j.found.as_ref()) {
            Some(f) => Diagnosis {
                mistake: f.mistake.clone(),
                explanation: f.explanation,
                step: Some(f.step.clone()),
                explained: 1,
                alternatives: Vec::new(),
            },
            None => diagnose(&b, &report, &exp, &candidates),
        });
    }
    Ok((report, ambiguous))
}
