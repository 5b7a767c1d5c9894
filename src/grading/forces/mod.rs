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

pub use answer::{ForceAnswer, from_json, from_svg, is_force_answer, is_force_svg};

use super::{Judgement, Verdict};
use crate::error::{Error, Result};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{self, ForcePlan, ForceStep, Which};
use crate::kinetostatics::loads::{Load, Origin};
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::forces::force_name;
use crate::words::{check, numbers};
use answer::issue;

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
    /// The typical mistake that explains every wrong item, if one does.
    pub diagnosis: Option<String>,
    /// The language of its words.
    pub lang: Lang,
}

impl ForceReport {
    /// How many items are wrong.
    pub fn wrong(&self) -> usize {
        self.verdicts
            .iter()
            .filter(|v| v.judgement == Judgement::Wrong)
            .count()
    }
    /// 0 right, 1 wrong, 4 none wrong but some cannot be judged.
    pub fn status(&self) -> u8 {
        if self.wrong() > 0 {
            1
        } else if self.verdicts.iter().any(|v| !v.ok()) {
            4
        } else {
            0
        }
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

/// A plan's place: its group's, or its input link's.
fn which_of(p: &ForcePlan) -> Which {
    match (p.group, p.input) {
        (Some(g), _) => Which::Group(g),
        (None, Some(i)) => Which::Input(i),
        (None, None) => unreachable!("a plan is a group's or an input's"),
    }
}

/// Which plan the answer's links name.
fn which(an: &Analysis, plans: &[ForcePlan], links: &[String]) -> Option<(Which, usize)> {
    let m = &an.mech;
    let mut want: Vec<&str> = links.iter().map(String::as_str).collect();
    want.sort_unstable();
    plans.iter().enumerate().find_map(|(k, p)| {
        let mut ids: Vec<&str> = p.links.iter().map(|&l| m.link_id(l)).collect();
        ids.sort_unstable();
        (ids == want).then(|| (which_of(p), k))
    })
}

/// What a plan says of one item: (expected, tolerance, on the plan in mm).
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
        // A driving slider's balancing force is laid off on the polygon:
        // its drafting tolerance, in N.
        if kind != "value" {
            return Err("the balancing force is a value, not a segment".into());
        }
        let (b, _) =
            balancing(plan).ok_or("this plan has no balancing force: it is the input link's")?;
        let v = plan
            .vectors
            .iter()
            .find(|v| {
                matches!(
                    v.force,
                    crate::kinetostatics::force_plan::Force::Drive { .. }
                )
            })
            .ok_or("this input is a crank: its balancing value is the moment M_b")?;
        let seg = plan.points[v.to] - plan.points[v.from];
        let tol = (plan.err[v.from] + plan.err[v.to] + ans.delta) * plan.mu;
        return Ok((b, tol, Some(seg.hypot())));
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
        // Each arm read to δ on the drawing at μ_l, each force to its own.
        return Ok((b, ans.delta * mu_l * forces, None));
    }
    let v = plan
        .vectors
        .iter()
        .rev()
        .find(|v| key(&force_name(&an.mech, loads, v.force, Lang::En)) == k)
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
    let seg = plan.points[v.to] - plan.points[v.from];
    let tol_mm = plan.err[v.from] + plan.err[v.to] + ans.delta;
    Ok(match kind {
        "segment" => (seg.hypot(), tol_mm, Some(seg.hypot())),
        "value" => (v.value.hypot(), tol_mm * plan.mu, Some(seg.hypot())),
        _ => {
            let deg = seg.y.atan2(seg.x).to_degrees().rem_euclid(360.0);
            let tol = (tol_mm / seg.hypot().max(1e-300)).atan().to_degrees();
            (deg, tol.min(180.0), None)
        }
    })
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
    let delta = ans.delta;
    let at_scale = |loads: &[Load]| -> Result<ForcePlan> {
        let fp = force_plan::solve_at(an, s, loads, delta, Some((w, ans.mu)))?;
        let (_, i) = which(an, &fp.plans, &ans.links).expect("the same structure");
        Ok(fp.plans[i].clone())
    };
    let plan = at_scale(right_loads)?;
    // The typical mistakes, as whole plans at the student's scale.
    let mistaken: Vec<(&str, ForcePlan)> = mistakes(right_loads, lang)
        .into_iter()
        .filter_map(|(what, loads)| at_scale(&loads).ok().map(|p| (what, p)))
        .collect();
    let judge = Judge {
        an,
        loads: right_loads,
        plan: &plan,
        ans,
        mistaken: &mistaken,
        lang,
    };
    let mut verdicts = Vec::new();
    let mut issues = Vec::new();
    let mut explained: Vec<usize> = vec![0; mistaken.len()];
    let items = [
        ("segment", &ans.segments, "mm"),
        ("angle", &ans.angles, "°"),
        ("value", &ans.values, ""),
    ];
    for (kind, list, unit) in items {
        for (pointer, name, given) in list.iter() {
            match judge.verdict((kind, unit), pointer, name, *given, &mut explained) {
                Ok(v) => verdicts.push(v),
                Err(i) => issues.push(i),
            }
        }
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    let wrong = verdicts
        .iter()
        .filter(|v| v.judgement == Judgement::Wrong)
        .count();
    let diagnosis = (wrong > 0)
        .then(|| {
            mistaken
                .iter()
                .zip(&explained)
                .filter(|(_, n)| **n >= wrong)
                .max_by_key(|(_, n)| **n)
                .map(|((what, _), _)| what.to_string())
        })
        .flatten();
    Ok(ForceReport {
        position: an.numbering.number(at),
        links: ans.links.clone(),
        mu: ans.mu,
        delta,
        verdicts,
        diagnosis,
        lang,
    })
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

/// The typical mistakes, each with the loads it draws the plans with:
/// the inertia forces and couples not reversed, the weights left out.
fn mistakes(right_loads: &[Load], lang: Lang) -> Vec<(&'static str, Vec<Load>)> {
    let w = check::phrases(lang);
    vec![
        (
            w.force_not_reversed.as_str(),
            right_loads
                .iter()
                .map(|l| match *l {
                    Load::Force {
                        f,
                        origin: Origin::Inertia,
                        link,
                        point,
                        at,
                    } => Load::Force {
                        f: -f,
                        origin: Origin::Inertia,
                        link,
                        point,
                        at,
                    },
                    Load::Couple {
                        m,
                        origin: Origin::Inertia,
                        link,
                    } => Load::Couple {
                        m: -m,
                        origin: Origin::Inertia,
                        link,
                    },
                    other => other,
                })
                .collect(),
        ),
        (
            w.force_weights_left_out.as_str(),
            // Zeroed in place (a zero force is not drawn), so that every
            // other load keeps its index and its name.
            right_loads
                .iter()
                .map(|l| match *l {
                    Load::Force {
                        origin: Origin::Gravity,
                        link,
                        point,
                        at,
                        ..
                    } => Load::Force {
                        f: kurbo::Vec2::ZERO,
                        origin: Origin::Gravity,
                        link,
                        point,
                        at,
                    },
                    other => other,
                })
                .collect(),
        ),
    ]
}

/// What the items are judged against: the plan at the student's scale
/// with the right loads, and the plans of the typical mistakes.
struct Judge<'a> {
    an: &'a Analysis,
    loads: &'a [Load],
    plan: &'a ForcePlan,
    ans: &'a ForceAnswer,
    mistaken: &'a [(&'a str, ForcePlan)],
    /// The language of the report's words.
    lang: Lang,
}

impl Judge<'_> {
    /// The verdict on the item `name` of kind `kind` (its unit `unit`, a
    /// value's by its name) that gives `given`; counts in `explained` the
    /// items each mistaken plan explains (when it differs from the right
    /// one). `Err`: the item cannot be read.
    fn verdict(
        &self,
        (kind, unit): (&str, &'static str),
        pointer: &str,
        name: &str,
        given: f64,
        explained: &mut [usize],
    ) -> std::result::Result<Verdict, crate::error::Issue> {
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
        let diff = difference(kind, given, expected);
        let mut also = None;
        for (j, (what, p)) in self.mistaken.iter().enumerate() {
            let Ok((e2, t2, _)) = expect(an, loads, p, kind, name, ans) else {
                continue;
            };
            let apart = difference(kind, e2, expected) > tol;
            if apart && difference(kind, given, e2) <= t2 {
                explained[j] += 1;
                also.get_or_insert(*what);
            }
        }
        let judgement = if diff > tol {
            Judgement::Wrong
        } else if kind != "angle" && tol >= expected.abs() {
            let tol = numbers::quantity(tol, unit, self.lang);
            Judgement::CannotJudge(check::fill(&w.force_too_small, &[("tol", &tol)]))
        } else if let Some(what) = also {
            Judgement::CannotJudge(check::fill(&w.force_mistake_too, &[("what", what)]))
        } else {
            Judgement::Right
        };
        Ok(Verdict {
            pointer: pointer.to_string(),
            key: name.to_string(),
            what: format!("{} {name}", w.force_kinds[kind_index(kind)]),
            expected,
            given,
            difference: diff,
            tolerance: tol,
            unit,
            on_plan: on_plan.map(|e| {
                (
                    e,
                    if kind == "value" {
                        given / ans.mu
                    } else {
                        given
                    },
                )
            }),
            step: None,
            judgement,
        })
    }
}
