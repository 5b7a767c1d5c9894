//! The diagnosis of a wrong answer by model selection: the mistaken
//! construction that explains every item, clearly better than any other of
//! another kind; two mistakes together; a slip in one laid-off length.

use super::candidates::{Builds, Fit, expectations, mistake_sentence, mistake_sentence_at};
use super::verdict::Candidate;
use super::items::Expected;
use super::{Diagnosis, Report};
use crate::accuracy::ACCURACY;
use crate::kinematics::construction::{Mistake, Plan, Variant};
use crate::lang::Lang;
use crate::words::check;

/// Name the mistake that explains the answer: the candidates whose
/// construction puts every item within its own tolerance; of those the
/// one with the least misfit, if no other explanation of a different kind
/// comes close (within a factor 2 of its misfit); otherwise "not
/// recognised". When no discrete mistake explains the answer, a slip in
/// one laid-off length is tried (its factor fitted).
pub(super) fn diagnose(b: &Builds, r: &Report, exp: &[Expected], cands: &[Fit]) -> Diagnosis {
    let n = exp.len();
    one_mistake(b, r, cands, n)
        .or_else(|| two_mistakes(b, r, cands, n))
        .or_else(|| slip(b, r, exp))
        .unwrap_or(Diagnosis {
            mistake: None,
            explanation: None,
            step: None,
            explained: 0,
            alternatives: Vec::new(),
        })
}

/// The step where a candidate's mistake enters (the first where its
/// construction draws something else than the right one, `right`), with
/// the right construction's sentence for it: the step drawn wrong or left
/// out (for a step the mistake adds, the added step's own).
fn step_of(f: &Fit, right: &Plan, lang: Lang) -> Option<(usize, String)> {
    let k = right.first_difference(&f.plan).or(f.plan.mistake_step)?;
    let adds = matches!(
        f.c,
        Candidate::Mistake {
            m: Mistake::Epsilon1Added,
            ..
        }
    );
    let plan = if adds || k >= right.steps.len() {
        &f.plan
    } else {
        right
    };
    let k = k.min(plan.steps.len().saturating_sub(1));
    Some((k + 1, check::step(plan, k, lang)))
}

/// What a candidate's mistaken step lays off ("a vector" in `lang` if it
/// says not).
fn what_of(f: &Fit, lang: Lang) -> String {
    let a_vector = || check::phrases(lang).a_vector.clone();
    f.plan
        .mistake_step
        .and_then(|k| f.plan.steps.get(k))
        .map(|st| match &st.op {
            crate::kinematics::construction::Op::LayOff { what, .. } => what.clone(),
            _ => a_vector(),
        })
        .unwrap_or_else(a_vector)
}

/// The candidate that explains all `n` items, named unless another of a
/// different kind fits about as well (then all of them, "not recognised").
fn one_mistake(b: &Builds, r: &Report, cands: &[Fit], n: usize) -> Option<Diagnosis> {
    let mut explaining: Vec<(&Fit, f64)> = cands
        .iter()
        .filter_map(|f| {
            let (ok, misfit) = f.score();
            (ok == n).then_some((f, misfit))
        })
        .collect();
    explaining.sort_by(|a, b| a.1.total_cmp(&b.1));
    let &(best, misfit) = explaining.first()?;
    let sentence_of = |f: &Fit| {
        let at = r.plan_built.first_difference(&f.plan).map(|k| (&r.plan_built, k));
        mistake_sentence_at(f.c, r.mu, &what_of(f, b.lang), at, b.lang)
    };
    let name = sentence_of(best);
    // Explanations of another kind that fit about as well.
    let mut alternatives: Vec<String> = explaining[1..]
        .iter()
        .filter(|(f, m)| {
            *m <= ACCURACY.distinct_misfit * misfit.max(1e-12) && !same_kind(f.c, best.c)
        })
        .map(|(f, _)| sentence_of(f))
        .collect();
    alternatives.dedup();
    let mistake = alternatives.is_empty().then_some(name.clone());
    if mistake.is_none() {
        alternatives.insert(0, name);
    }
    Some(Diagnosis {
        explanation: mistake.is_some().then_some(best.c),
        mistake,
        step: step_of(best, &r.plan_built, b.lang),
        explained: n,
        alternatives,
    })
}

/// Two mistakes combined, each everywhere: the pairs of the kinds this
/// plan can make (the candidates'), the one that explains all `n` items
/// named unless others fit about as well.
fn two_mistakes(b: &Builds, r: &Report, cands: &[Fit], n: usize) -> Option<Diagnosis> {
    let mut kinds: Vec<Mistake> = Vec::new();
    for f in cands {
        if let Candidate::Mistake { m, both: false, .. } = f.c
            && !kinds.contains(&m)
        {
            kinds.push(m);
        }
    }
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
    let (best, misfit) = pairs.first()?;
    let others = pairs[1..]
        .iter()
        .filter(|p| p.1 <= ACCURACY.distinct_misfit * misfit.max(1e-12))
        .count();
    let name = mistake_sentence(best.c, r.mu, &what_of(best, b.lang), b.lang);
    Some(Diagnosis {
        explanation: (others == 0).then_some(best.c),
        mistake: (others == 0).then(|| name.clone()),
        step: step_of(best, &r.plan_built, b.lang),
        explained: n,
        alternatives: if others == 0 {
            Vec::new()
        } else {
            pairs
                .iter()
                .take(others + 1)
                .map(|p| mistake_sentence(p.0.c, r.mu, &what_of(&p.0, b.lang), b.lang))
                .collect()
        },
    })
}

/// A slip in one length: each laid-off vector in turn, its factor fitted;
/// the one that explains every item best.
fn slip(b: &Builds, r: &Report, exp: &[Expected]) -> Option<Diagnosis> {
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
    let (f, _) = best?;
    Some(Diagnosis {
        explanation: Some(f.c),
        mistake: Some(mistake_sentence(f.c, r.mu, &what_of(&f, b.lang), b.lang)),
        step: step_of(&f, &r.plan_built, b.lang),
        explained: exp.len(),
        alternatives: Vec::new(),
    })
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
