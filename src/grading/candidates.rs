//! The mistaken constructions tried (each typical mistake at one decision
//! or everywhere, the other branch of a group, the scale applied wrongly),
//! how each fits the answer, and the items that cannot be judged because
//! a mistaken construction fits the answer as well.

use super::verdict::{Candidate, MAX_TOLERANCE_OF_PLAN};
use super::answer::{Answer, Given};
use super::items::{Expected, expect};
use crate::error::Result;
use crate::format::num;
use crate::kinematics::analytic::{Drives, Order};
use crate::kinematics::construction::{
    Drafting, Mistake, Plan, PlanKind, Variant, build_acceleration, build_plans,
};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::Analysis;
use crate::model::structure::{AssurGroup, DyadKind};
use crate::pipeline::Solved;

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

pub(super) fn mistake_sentence(c: Candidate, mu: f64, what: &str) -> String {
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

/// What the plans of one answer are built from.
pub(super) struct Builds<'a> {
    pub(super) an: &'a Analysis,
    pub(super) s: &'a Solved,
    pub(super) ans: &'a Answer,
}

impl Builds<'_> {
    fn drive(&self) -> Drives {
        self.s.drives
    }

    /// The answer's plan built on configuration `c` with `variant`: a
    /// velocity plan at the student's μ; an acceleration plan at the
    /// student's μ on their velocity plan (its μ_v, their measured ω).
    pub(super) fn plan(&self, c: &Configuration, variant: Variant) -> Result<Plan> {
        let (ans, st) = (self.ans, self.an.setup());
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
pub(super) struct Fit {
    pub(super) c: Candidate,
    pub(super) plan: Plan,
    /// Per item, as this plan expects it (values scaled by a Scale
    /// candidate's factor).
    pub(super) items: Vec<Expected>,
}

impl Fit {
    /// The items within this construction's own tolerance, and the misfit
    /// Σ (difference / tolerance)².
    pub(super) fn score(&self) -> (usize, f64) {
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
pub(super) fn expectations(b: &Builds, p: &Plan, factor: f64) -> Option<Vec<Expected>> {
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

/// Is item `k` (within its tolerance) one this answer cannot be judged
/// on? Either its tolerance exceeds [`MAX_TOLERANCE_OF_PLAN`] of the plan,
/// or the whole answer fits some typical mistake's construction within its
/// tolerances as well, and that construction moves this item visibly (by
/// more than the pencil's δ): the answer could be that mistake drawn
/// carefully, so "right" would accept it.
pub(super) fn cannot_judge(
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
            crate::format::format_quantity(tol_mm, "mm"),
            crate::format::format_quantity(size, "mm")
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
                crate::format::format_quantity(e.tol, e.unit),
                crate::format::format_quantity(moved, e.unit),
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
pub(super) fn candidates(b: &Builds, plan: &Plan, exp: &[Expected]) -> Vec<Fit> {
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
        if !an.group(g) || !has_branch {
            continue;
        }
        let Ok(mut ps) = PositionSolver::new(&an.mech, &an.structure, an.need.clone()) else {
            continue;
        };
        if ps.branches.sign[g] == 0.0 {
            continue;
        }
        ps.branches.sign[g] = -ps.branches.sign[g];
        let Ok(c) = ps.solve_at_coords(s.drives.coords()) else {
            continue;
        };
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
