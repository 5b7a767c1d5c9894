//! The mistaken constructions tried (each typical mistake at one decision
//! or everywhere, the other branch of a group, the scale applied wrongly),
//! how each fits the answer, and the items that cannot be judged because
//! a mistaken construction fits the answer as well.

use super::verdict::{Candidate, MAX_TOLERANCE_OF_PLAN};
use super::answer::{Answer, Given, StatedQuantity};
use super::items::{Expected, expect};
use crate::error::Result;
use crate::format::num;
use crate::lang::Lang;
use crate::words::check;
use crate::words::numbers::{decimals, quantity};
use crate::kinematics::analytic::{Drives, Order};
use crate::kinematics::construction::{
    self, Drafting, Drawing, Mistake, Plan, PlanKind, Variant, build_acceleration, build_plans,
};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::Analysis;
use crate::model::structure::{AssurGroup, DyadKind};
use crate::pipeline::Solved;

/// The discrete mistakes tried, one element at a time and everywhere.
pub(super) const MISTAKES: [Mistake; 16] = [
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
    Mistake::NeighbourLink,
    Mistake::SlideAcross,
    Mistake::PointAtNeighbour,
];

/// The mistake of candidate `c` in one sentence in `lang` (`what`: the
/// vector a slip lays off; `mu`: the student's scale).
pub(super) fn mistake_sentence(c: Candidate, mu: f64, what: &str, lang: Lang) -> String {
    mistake_sentence_at(c, mu, what, None, lang)
}

/// [`mistake_sentence`], in the scene's own letters where the mistake is
/// made at one decision and `at` gives the right construction's step
/// where it enters (the plan and the step's index).
pub(super) fn mistake_sentence_at(
    c: Candidate,
    mu: f64,
    what: &str,
    at: Option<(&Plan, usize)>,
    lang: Lang,
) -> String {
    let w = check::phrases(lang);
    if let (Candidate::Mistake { m, at: Some(_), .. }, Some((plan, k))) = (c, at)
        && let Some(s) = check::mistake_here(lang, m, plan, k)
    {
        return s;
    }
    match c {
        Candidate::Mistake { m, at, .. } => check::mistake(lang, m, at.is_some()).to_string(),
        Candidate::Slip { factor, .. } => check::fill(
            &w.slip_of,
            &[("what", what), ("factor", &decimals(&num(factor), lang))],
        ),
        Candidate::Pair(x, y) => check::fill(
            &w.pair,
            &[
                ("first", check::mistake(lang, x, false)),
                ("second", check::mistake(lang, y, false)),
            ],
        ),
        Candidate::Branch(_) => w.branch.clone(),
        Candidate::Stated { .. } => check::fill(&w.stated_plain, &[("name", what)]),
        Candidate::DrawnScale { drawn, stated } => check::fill(
            &w.scale_drawn,
            &[
                ("drawn", &decimals(&num(drawn), lang)),
                ("stated", &decimals(&num(stated), lang)),
                ("factor", &decimals(&num(stated / drawn), lang)),
            ],
        ),
        Candidate::Scale(f) if (f - 1000.0).abs() < 1e-9 || (f - 1e-3).abs() < 1e-12 => {
            w.scale_units.clone()
        }
        Candidate::Scale(_) => check::fill(&w.scale_inverted, &[("mu", &decimals(&num(mu), lang))]),
    }
}

/// What the plans of one answer are built from.
pub(super) struct Builds<'a> {
    pub(super) an: &'a Analysis,
    pub(super) s: &'a Solved,
    pub(super) ans: &'a Answer,
    /// The language of the report's sentences.
    pub(super) lang: Lang,
    /// The scale the student drew at, where it is not the one stated (a
    /// plan drawn at another μ): the replays are made at it.
    pub(super) drawn_mu: Option<f64>,
    /// Stated values (indices into `ans.stated`) a replay takes as true:
    /// a value written wrong that the student's drawing did not use.
    pub(super) unused: Vec<usize>,
}

impl<'a> Builds<'a> {
    pub(super) fn new(an: &'a Analysis, s: &'a Solved, ans: &'a Answer, lang: Lang) -> Self {
        Builds {
            an,
            s,
            ans,
            lang,
            drawn_mu: None,
            unused: Vec::new(),
        }
    }

    fn drive(&self) -> Drives {
        self.s.drives
    }

    /// The answer's plan built on configuration `c` with `variant`: a
    /// velocity plan at the student's μ; an acceleration plan at the
    /// student's μ on the true velocity plan at their μ_v (its ω and
    /// relative velocities as measured there, not as the student states
    /// them: the comparison with the true plan).
    pub(super) fn plan(&self, c: &Configuration, variant: Variant) -> Result<Plan> {
        self.build(c, variant, None)
    }

    /// [`Builds::plan`] replayed with the student's points `given` in
    /// place of the constructed ones ([`construction::replay`]), at the
    /// scale they drew at, every step with the values they state (their
    /// ω, their relative sliding velocities), as their drawing was built.
    pub(super) fn replay(
        &self,
        c: &Configuration,
        variant: Variant,
        given: &Drawing,
    ) -> Result<Plan> {
        self.build(c, variant, Some(given))
    }

    /// The velocity plan an acceleration answer stands on: at the
    /// student's μ_v (default the standard one), drawn right.
    pub(super) fn velocity_plan(&self, c: &Configuration) -> Result<Plan> {
        let d = Drafting {
            mu_v: self.ans.mu_v,
            mu_a: None,
            delta: self.ans.delta,
            ..self.an.drafting
        };
        let st = self.an.setup();
        Ok(build_plans(&st, c, self.drive(), Order::Velocity, d)?.velocity)
    }

    fn build(
        &self,
        c: &Configuration,
        variant: Variant,
        given: Option<&Drawing>,
    ) -> Result<Plan> {
        let (ans, st) = (self.ans, self.an.setup());
        let mu = match given {
            Some(_) => self.drawn_mu.unwrap_or(ans.mu),
            None => ans.mu,
        };
        let d = Drafting {
            mu_v: Some(mu),
            mu_a: None,
            delta: ans.delta,
            variant,
            ..self.an.drafting
        };
        if ans.plan == PlanKind::Velocity {
            if let Some(given) = given {
                let kind = (PlanKind::Velocity, None);
                return construction::replay(&st, c, self.drive(), kind, d, given.clone());
            }
            return Ok(build_plans(&st, c, self.drive(), Order::Velocity, d)?.velocity);
        }
        let dv = Drafting {
            mu_v: ans.mu_v,
            ..d
        };
        let mut vel = build_plans(&st, c, self.drive(), Order::Velocity, dv)?.velocity;
        if given.is_some() {
            self.take_stated(c, &mut vel);
        }
        let da = Drafting {
            mu_v: ans.mu_v,
            mu_a: Some(mu),
            ..d
        };
        match given {
            Some(given) => {
                let kind = (PlanKind::Acceleration, Some(&vel));
                construction::replay(&st, c, self.drive(), kind, da, given.clone())
            }
            None => build_acceleration(&st, c, self.drive(), &vel, da),
        }
    }

    /// Put the values the student states into the velocity plan `vel`
    /// their acceleration plan stands on: each stated ω is the ω of its
    /// link and of the links that turn with it (a slider and its guide:
    /// the Coriolis acceleration of a rocking guide takes the ω the
    /// student states for the guide), its error the rounding of the digits
    /// written; a stated relative sliding velocity is the length of the
    /// relative segment its Coriolis acceleration is built from.
    fn take_stated(&self, c: &Configuration, vel: &mut Plan) {
        let m = &self.an.mech;
        let stated_links: Vec<usize> = self
            .ans
            .stated
            .iter()
            .filter_map(|s| match &s.quantity {
                StatedQuantity::Omega(id) => m.scene.link_index(id),
                StatedQuantity::Slide(_) => None,
            })
            .collect();
        for (k, s) in self.ans.stated.iter().enumerate() {
            if self.unused.contains(&k) {
                continue;
            }
            match &s.quantity {
                StatedQuantity::Omega(id) => {
                    let Some(l) = m.scene.link_index(id) else { continue };
                    for t in turning_with(m, l) {
                        if (t == l || !stated_links.contains(&t)) && vel.rates[t].is_some() {
                            vel.rates[t] = Some((s.value, s.rounding));
                            vel.rate_sense[t] = true;
                        }
                    }
                }
                StatedQuantity::Slide(raw) => {
                    let Some((p, l1, l2)) = super::items::slide_of(m, raw) else { continue };
                    let Some(at) = world_of(m, c, p) else { continue };
                    let find = |v: &Plan, l: usize| {
                        let local = c.pose(l).local(at);
                        let tol = 1e-9 * m.link_scale(l).max(1e-300);
                        v.known_at(l, local, tol)
                    };
                    let (Some(i1), Some(i2)) = (find(vel, l1), find(vel, l2)) else { continue };
                    let rel = vel.points[i1].at - vel.points[i2].at;
                    if rel.hypot() == 0.0 {
                        continue;
                    }
                    let length = s.value / vel.mu;
                    let (moved, other) = if i1 != 0 { (i1, i2) } else { (i2, i1) };
                    let sign = if moved == i1 { 1.0 } else { -1.0 };
                    vel.points[moved].at = vel.points[other].at + rel * (sign * length / rel.hypot());
                    vel.points[moved].err = s.rounding / vel.mu;
                    vel.points[other].err = 0.0;
                }
            }
        }
    }
}

/// Where the mechanism's point `p` is in configuration `c` (on the first
/// posed link that carries it).
pub(super) fn world_of(
    m: &crate::model::mechanism::Mechanism,
    c: &Configuration,
    p: usize,
) -> Option<kurbo::Point> {
    (0..m.links.len())
        .find(|&l| m.links[l].points.contains(&p) && c.poses[l].is_some())
        .map(|l| c.point(m, l, p))
}

/// The links that turn with link `l` (itself too): those joined to it by
/// prismatic pairs, one after another (a slider shares its guide's ω).
pub(super) fn turning_with(m: &crate::model::mechanism::Mechanism, l: usize) -> Vec<usize> {
    let mut out = vec![l];
    let mut k = 0;
    while k < out.len() {
        for pr in &m.prismatics {
            for (a, b) in [(pr.slider, pr.guide), (pr.guide, pr.slider)] {
                if a == out[k] && !out.contains(&b) && b != m.frame() {
                    out.push(b);
                }
            }
        }
        k += 1;
    }
    out
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
            let mut e = expect(b.an, p, it, b.ans.delta, b.lang).ok()?;
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
/// on (why, and whether because a typical mistake explains the whole
/// answer as well)? Either its tolerance exceeds [`MAX_TOLERANCE_OF_PLAN`] of the plan,
/// or the whole answer fits some typical mistake's construction within its
/// tolerances as well, and that construction moves this item visibly (by
/// more than the pencil's δ): the answer could be that mistake drawn
/// carefully, so "right" would accept it.
pub(super) fn cannot_judge(
    k: usize,
    e: &Expected,
    (size, mu): (f64, f64),
    candidates: &[Fit],
    student_mu: f64,
    lang: Lang,
) -> Option<(String, bool)> {
    let w = check::phrases(lang);
    let quantity = |x: f64, unit: &str| quantity(x, unit, lang);
    // An item's tolerance in mm on the plan.
    let mm = |e: &Expected| e.tol_mm(mu);
    let tol_mm = mm(e)?;
    if size > 0.0 && tol_mm > MAX_TOLERANCE_OF_PLAN * size {
        let (tol, size) = (quantity(tol_mm, "mm"), quantity(size, "mm"));
        return Some((check::fill(&w.too_wide, &[("tol", &tol), ("size", &size)]), false));
    }
    for f in candidates {
        let other = &f.items[k];
        let moved = e.moved(other);
        // The whole answer fits a mistaken construction within its own
        // tolerances, and that construction moves this item visibly: the
        // answer cannot tell which was drawn. (An answer that contradicts
        // the mistake anywhere rules it out; a construction whose own
        // tolerance exceeds a fifth of the plan judges nothing and is no
        // candidate.)
        let fits = f.score().0 == f.items.len();
        let judges = mm(other).is_none_or(|t| t <= MAX_TOLERANCE_OF_PLAN * size);
        if moved > e.visible && fits && judges {
            let mistake = mistake_sentence(f.c, student_mu, &e.what, lang);
            return Some((
                check::fill(
                    &w.ambiguous,
                    &[
                        ("tol", &quantity(e.tol, e.unit)),
                        ("moved", &quantity(moved, e.unit)),
                        ("mistake", &mistake),
                    ],
                ),
                true,
            ));
        }
    }
    None
}

/// The position `s` with one group assembled on its other branch: each
/// group that has one, and that configuration.
pub(super) fn other_branches(an: &Analysis, s: &Solved) -> Vec<(usize, Configuration)> {
    let mut out = Vec::new();
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
        if let Ok(c) = ps.solve_at_coords(s.drives.coords()) {
            out.push((g, c));
        }
    }
    out
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
    for (g, c) in other_branches(an, s) {
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
