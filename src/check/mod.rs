//! Checking hand-drawn plans: the student's answer item by item against
//! the construction at the student's own scale, with a tolerance from the
//! drafting-error model (pencil precision δ propagated through the
//! construction, so it widens where lines meet at small angles), and a
//! diagnosis: the plan is rebuilt with each typical mistake, and the one
//! that explains the answer is named with the step where it happens.

pub mod answer;
pub mod svg;

use crate::analytic::Drive;
use crate::construction::text::{Lang, sentence};
use crate::construction::{Drafting, Mistake, Plan, PlanKind, Setup, Variant, build_plans};
use crate::error::{Error, Issue, Result};
use crate::positions::{Configuration, PositionSolver};
use crate::quantity::format_number;
use crate::solve::{Analysis, Solved};
use answer::{Answer, Given, Quantity};
use kurbo::Vec2;

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
    pub ok: bool,
}

/// A mistake that explains the answer.
#[derive(Clone, Debug)]
pub struct Diagnosis {
    /// One sentence naming the mistake.
    pub mistake: String,
    /// The step of the construction where it happens, and its sentence.
    pub step: Option<(usize, String)>,
    /// How many items the mistaken construction explains.
    pub explained: usize,
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
        self.verdicts.iter().filter(|v| !v.ok).count()
    }
}

/// The best explanation so far: the candidate, (items explained, misfit),
/// and the step where the mistake happens.
type Best = (Candidate, (usize, f64), Option<(usize, String)>);

/// A way the plan may have been built wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Candidate {
    Mistake(Mistake),
    /// The other assembly branch of group g.
    Branch(usize),
    /// Derived values scaled by a factor: μ in mm instead of m (1000 or
    /// 1/1000), or μ inverted (the factor is 1/μ²).
    Scale(f64),
}

const MISTAKES: [Mistake; 9] = [
    Mistake::CoriolisReversed,
    Mistake::CoriolisForgotten,
    Mistake::NormalFromCentre,
    Mistake::MirroredFigure,
    Mistake::WrongPerpendicular,
    Mistake::Epsilon1Forgotten,
    Mistake::Epsilon1Added,
    Mistake::OmegaWrongLink,
    Mistake::OmegaWrongSense,
];

fn mistake_sentence(c: Candidate, mu: f64) -> String {
    match c {
        Candidate::Mistake(m) => match m {
            Mistake::CoriolisReversed => "The Coriolis acceleration is turned the wrong way: turn the relative velocity by 90° in the sense of ω of the guide.".into(),
            Mistake::CoriolisForgotten => "The Coriolis acceleration is forgotten: a point sliding on a rotating guide has a^k = 2·ω·v_rel.".into(),
            Mistake::NormalFromCentre => "A normal component is laid off from the centre instead of toward it: a^n points from the point to the centre of its rotation.".into(),
            Mistake::MirroredFigure => "A similar figure is mirrored: its letters must run around it in the same order as around the link.".into(),
            Mistake::WrongPerpendicular => "A perpendicular is drawn to the wrong link: v_CB is ⊥ BC, v_CD is ⊥ CD.".into(),
            Mistake::Epsilon1Forgotten => "The crank's tangential acceleration ε1·l is forgotten (ε1 ≠ 0).".into(),
            Mistake::Epsilon1Added => "A tangential acceleration of the crank is added although ε1 = 0.".into(),
            Mistake::OmegaWrongLink => "A normal component ω²·l uses ω of the crank instead of the link's own ω.".into(),
            Mistake::OmegaWrongSense => "The crank's velocity is laid off against the sense of ω1.".into(),
        },
        Candidate::Branch(_) => "The mechanism is assembled on the other branch (a group drawn mirrored on the plan of the mechanism).".into(),
        Candidate::Scale(f) if (f - 1000.0).abs() < 1e-9 || (f - 1e-3).abs() < 1e-12 => {
            "The scale μ is applied in the wrong units (mm instead of m, or the reverse): the derived values are off by 1000.".into()
        }
        Candidate::Scale(_) => format!("The scale μ is inverted: values are segment/μ instead of segment·μ (μ = {}).", format_number(mu)),
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
    let named = |p: &crate::construction::PlanPoint| p.key.to_lowercase() == n;
    if let Some(i) = plan.points.iter().position(named) {
        return Some(i);
    }
    plan.points
        .iter()
        .position(|p| p.name().to_lowercase() == n || p.key.replace('_', "").to_lowercase() == n)
}

/// The expected value and tolerance of an item on `plan`; `Err` names an
/// unknown letter or link.
fn expect(
    an: &Analysis,
    plan: &Plan,
    it: &answer::Item,
    delta: f64,
) -> std::result::Result<(String, f64, f64, f64, &'static str), Issue> {
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
            (
                format!("segment {}{}", p[a].name(), p[b].name()),
                len,
                *mm,
                p[a].err + p[b].err + delta,
                "mm",
            )
        }
        Given::Angle { from, deg, .. } => {
            let (a, b) = seg(from)?;
            let d = p[b].at - p[a].at;
            let tol = if d.hypot() > 0.0 {
                ((p[a].err + p[b].err + delta) / d.hypot())
                    .min(std::f64::consts::PI)
                    .to_degrees()
            } else {
                180.0
            };
            let exp = d.atan2().to_degrees();
            // Compare directions modulo a turn.
            let given = exp + crate::geom::wrap_pi((deg - exp).to_radians()).to_degrees();
            (
                format!("direction of {}{}", p[a].name(), p[b].name()),
                exp,
                given,
                tol,
                "°",
            )
        }
        Given::Point { name, at } => {
            let i = resolve(plan, name).ok_or_else(|| unknown(name))?;
            // Distance from the expected place is the difference; "expected" 0.
            let d = (Vec2::new(at[0], at[1]) - p[i].at).hypot();
            (
                format!("point {} (off its place)", p[i].name()),
                0.0,
                d,
                p[i].err + delta,
                "mm",
            )
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
            (
                format!("{sym}_{name}"),
                p[i].at.hypot() * mu,
                *value,
                (p[i].err + delta) * mu,
                unit,
            )
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
            (format!("{sym}{id}"), r, *value, bound, unit)
        }
    })
}

fn names(plan: &Plan) -> String {
    let mut v: Vec<String> = plan.points.iter().map(|p| p.name()).collect();
    v.dedup();
    v.join(", ")
}

/// The plan of `kind` built on configuration `c` at scale `mu`.
fn plan_on(
    an: &Analysis,
    s: &Solved,
    c: &Configuration,
    kind: PlanKind,
    mu: f64,
    delta: f64,
    variant: Variant,
) -> Result<Plan> {
    let setup = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let d = Drafting {
        mu_v: if kind == PlanKind::Velocity {
            Some(mu)
        } else {
            None
        },
        mu_a: if kind == PlanKind::Acceleration {
            Some(mu)
        } else {
            None
        },
        delta,
        variant,
    };
    let order = if kind == PlanKind::Velocity {
        crate::analytic::Order::Velocity
    } else {
        crate::analytic::Order::Acceleration
    };
    let plans = build_plans(
        &setup,
        c,
        Drive {
            q: s.q,
            rate: s.rate,
            rate2: s.rate2,
        },
        order,
        d,
    )?;
    Ok(match kind {
        PlanKind::Velocity => plans.velocity,
        PlanKind::Acceleration => plans.acceleration.expect("asked for"),
    })
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
        || (ans.plan == PlanKind::Acceleration
            && an.order != Some(crate::analytic::Order::Acceleration))
    {
        return Err(Error::scene(
            "/plan",
            "the scene's want.plans does not include this plan",
        ));
    }
    let plan = plan_on(
        an,
        s,
        &s.config,
        ans.plan,
        ans.mu,
        ans.delta,
        Variant::default(),
    )?;
    let mut verdicts = Vec::new();
    let mut issues = Vec::new();
    for it in &ans.items {
        match expect(an, &plan, it, ans.delta) {
            Ok((what, expected, given, tol, unit)) => {
                let difference = (given - expected).abs();
                verdicts.push(Verdict {
                    pointer: it.pointer.clone(),
                    key: it.key.clone(),
                    what,
                    expected,
                    given,
                    difference,
                    tolerance: tol,
                    unit,
                    ok: difference <= tol,
                });
            }
            Err(i) => issues.push(i),
        }
    }
    if !issues.is_empty() {
        return Err(Error::Scene(issues));
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
        report.diagnosis = diagnose(an, s, ans, &report);
    }
    Ok(report)
}

/// Rebuild the plan with each candidate mistake; name the one that
/// explains the answer (all items within tolerance, or far more of them
/// than the correct plan with a much smaller misfit).
fn diagnose(an: &Analysis, s: &Solved, ans: &Answer, report: &Report) -> Option<Diagnosis> {
    let score = |plan: &Plan, factor: f64| -> Option<(usize, f64)> {
        let mut ok = 0;
        let mut misfit = 0.0;
        for it in &ans.items {
            let (_, mut expected, given, tol, _) = expect(an, plan, it, ans.delta).ok()?;
            if matches!(it.given, Given::Value { .. }) {
                expected *= factor;
            }
            let d = (given - expected).abs() / tol.max(1e-300);
            if d <= 1.0 {
                ok += 1;
            }
            misfit += d.min(30.0).powi(2);
        }
        Some((ok, misfit))
    };
    let base = score(&report.plan_built, 1.0)?;
    let mut best: Option<Best> = None;
    let consider = |c: Candidate, plan: &Plan, factor: f64, best: &mut Option<Best>| {
        let Some(sc) = score(plan, factor) else {
            return;
        };
        if best
            .as_ref()
            .is_none_or(|b| sc.0 > b.1.0 || (sc.0 == b.1.0 && sc.1 < b.1.1))
        {
            let step = plan
                .mistake_step
                .map(|k| (k + 1, sentence(plan, k.min(plan.steps.len() - 1), Lang::En)));
            *best = Some((c, sc, step));
        }
    };
    let same = |a: &Plan, b: &Plan| {
        a.points.len() == b.points.len()
            && a.points
                .iter()
                .zip(&b.points)
                .all(|(x, y)| (x.at - y.at).hypot() < 1e-9)
    };
    for m in MISTAKES {
        let Ok(plan) = plan_on(
            an,
            s,
            &s.config,
            ans.plan,
            ans.mu,
            ans.delta,
            Variant {
                mistake: Some(m),
                jitter: None,
            },
        ) else {
            continue;
        };
        if plan.mistake_step.is_none() || same(&plan, &report.plan_built) {
            continue;
        }
        consider(Candidate::Mistake(m), &plan, 1.0, &mut best);
    }
    // The other assembly branch of each group with one.
    for g in 0..an.structure.groups.len() {
        let Ok(mut ps) = PositionSolver::new(&an.mech, &an.structure, an.need.clone()) else {
            continue;
        };
        if !an.need[g]
            || ps.branches.sign[g] == 0.0
            || matches!(
                an.structure.groups[g],
                crate::structure::AssurGroup::Triad(_)
            )
        {
            continue;
        }
        let kind_has_branch = match &an.structure.groups[g] {
            crate::structure::AssurGroup::Dyad(d) => !matches!(
                d.kind,
                crate::structure::DyadKind::Prp | crate::structure::DyadKind::Rpp
            ),
            _ => false,
        };
        if !kind_has_branch {
            continue;
        }
        ps.branches.sign[g] = -ps.branches.sign[g];
        let Ok(c) = ps.solve_at(s.q) else { continue };
        let Ok(plan) = plan_on(an, s, &c, ans.plan, ans.mu, ans.delta, Variant::default()) else {
            continue;
        };
        consider(Candidate::Branch(g), &plan, 1.0, &mut best);
    }
    if ans
        .items
        .iter()
        .any(|i| matches!(i.given, Given::Value { .. }))
    {
        for f in [1000.0, 1e-3, 1.0 / (ans.mu * ans.mu)] {
            consider(Candidate::Scale(f), &report.plan_built, f, &mut best);
        }
    }
    let (c, sc, step) = best?;
    let n = ans.items.len();
    let explains = sc.0 == n || (sc.0 > base.0 && sc.1 < base.1 / 4.0);
    explains.then(|| Diagnosis {
        mistake: mistake_sentence(c, ans.mu),
        step,
        explained: sc.0,
    })
}

/// The report as text for the terminal.
pub fn to_text(r: &Report) -> String {
    use std::fmt::Write as _;
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
        format_number(r.mu),
        crate::quantity::format_quantity(r.delta, "mm")
    );
    if r.worst_angle < 5.0 {
        let _ = writeln!(
            t,
            "note: lines of this construction meet at {}°; tolerances are wide here (near a dead centre)",
            format_number(r.worst_angle)
        );
    }
    let _ = writeln!(
        t,
        "  {:<24} {:>12} {:>12} {:>12} {:>12}  verdict",
        "item", "expected", "given", "difference", "tolerance"
    );
    for v in &r.verdicts {
        let _ = writeln!(
            t,
            "  {:<24} {:>12} {:>12} {:>12} {:>12}  {} {}",
            v.what,
            format_number(v.expected),
            format_number(v.given),
            format_number(v.difference),
            format_number(v.tolerance),
            v.unit,
            if v.ok { "OK" } else { "WRONG" }
        );
    }
    let _ = writeln!(
        t,
        "total: {} of {} right",
        r.verdicts.len() - r.wrong(),
        r.verdicts.len()
    );
    if let Some(d) = &r.diagnosis {
        let _ = writeln!(t, "likely mistake: {}", d.mistake);
        if let Some((k, s)) = &d.step {
            let _ = writeln!(t, "  at step {k}: {s}");
        }
    } else if r.wrong() > 0 {
        let _ = writeln!(t, "no single typical mistake explains these answers");
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
            "difference": v.difference, "tolerance": v.tolerance, "unit": v.unit, "ok": v.ok,
        })).collect::<Vec<_>>(),
        "right": r.verdicts.len() - r.wrong(),
        "wrong": r.wrong(),
        "diagnosis": r.diagnosis.as_ref().map(|d| serde_json::json!({
            "mistake": d.mistake, "step": d.step.as_ref().map(|s| s.0), "step_text": d.step.as_ref().map(|s| s.1.clone()), "explained": d.explained,
        })),
    })
}

/// An SVG sheet with the correct plan (black) and the student's points
/// (red crosses, labelled), for `check --svg`.
pub fn overlay(an: &Analysis, ans: &Answer, r: &Report) -> String {
    use crate::drawing::canvas::{Canvas, Class, Label, SMALL};
    let plan = &r.plan_built;
    let mut c = Canvas::default();
    crate::drawing::plan::draw(plan, &mut c, &an.points);
    // The student's points: given directly, or the far end of a segment
    // from the pole.
    for it in &ans.items {
        let at = match &it.given {
            Given::Point { at, .. } => Some(kurbo::Point::new(at[0], at[1])),
            _ => None,
        };
        if let Some(p) = at {
            let d = 1.2;
            c.prims.push(crate::drawing::canvas::Prim::Seg {
                a: p + Vec2::new(-d, -d),
                b: p + Vec2::new(d, d),
                class: Class::Thin,
                id: Some(format!("student-{}", it.key)),
            });
            c.prims.push(crate::drawing::canvas::Prim::Seg {
                a: p + Vec2::new(-d, d),
                b: p + Vec2::new(d, -d),
                class: Class::Thin,
                id: None,
            });
            c.label(p, Label::new(format!("{}*", it.key), ""), SMALL, None);
            if let Some(crate::drawing::canvas::Prim::Text { class, .. }) = c.prims.last_mut() {
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
        r.verdicts.len() - r.wrong(),
        r.verdicts.len(),
        r.diagnosis
            .as_ref()
            .map(|d| format!(" — {}", d.mistake))
            .unwrap_or_default()
    );
    crate::drawing::page_svg(
        "check".into(),
        title,
        &c,
        None,
        &crate::drawing::DrawOptions::default(),
    )
    .svg
}
