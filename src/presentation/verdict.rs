//! A check's verdict (`crate::grading`'s report, data) as text for the
//! terminal, as JSON, and as an SVG overlay of the student's points on the
//! correct plan.

use crate::grading::answer::{Answer, Given};
use crate::grading::forces::ForceReport;
use crate::grading::{Judgement, Report};
use crate::kinematics::construction::PlanKind;
use crate::kinematics::solve::Analysis;
use kurbo::Vec2;

/// The report as text for the terminal.
pub fn to_text(r: &Report) -> String {
    use std::fmt::Write as _;
    let fmt = crate::format::format_number;
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
        fmt(r.mu),
        crate::format::format_quantity(r.delta, "mm")
    );
    if r.worst_angle < 5.0 {
        let _ = writeln!(
            t,
            "note: lines of this construction meet at {}°; tolerances are wide here (near a dead centre)",
            fmt(r.worst_angle)
        );
    }
    let _ = writeln!(
        t,
        "  {:<24} {:>12} {:>12} {:>12} {:>12}  verdict",
        "item", "expected", "given", "difference", "tolerance"
    );
    for v in &r.verdicts {
        let verdict = match &v.judgement {
            Judgement::Right => "RIGHT",
            Judgement::Wrong => "WRONG",
            Judgement::CannotJudge(_) => "CANNOT BE JUDGED",
        };
        let _ = writeln!(
            t,
            "  {:<24} {:>12} {:>12} {:>12} {:>12}  {} {}",
            v.what,
            fmt(v.expected),
            fmt(v.given),
            fmt(v.difference),
            fmt(v.tolerance),
            v.unit,
            verdict
        );
        if !v.ok() {
            if let Some((e, g)) = v.on_plan
                && v.unit != "mm"
            {
                let _ = writeln!(
                    t,
                    "      on the plan: {} mm expected, {} mm given",
                    fmt(e),
                    fmt(g)
                );
            }
            if let Some((k, s)) = &v.step {
                let _ = writeln!(t, "      drawn at step {k}: {s}");
            }
            if let Judgement::CannotJudge(why) = &v.judgement {
                let _ = writeln!(t, "      cannot be judged at this position: {why}");
            }
        }
    }
    let _ = writeln!(
        t,
        "total: {} of {} right, {} wrong, {} cannot be judged",
        r.right(),
        r.verdicts.len(),
        r.wrong(),
        r.unjudged()
    );
    if let Some(d) = &r.diagnosis {
        match &d.mistake {
            Some(m) => {
                let _ = writeln!(t, "likely mistake: {m}");
                if let Some((k, s)) = &d.step {
                    let _ = writeln!(t, "  it enters at step {k}: {s}");
                }
            }
            None if !d.alternatives.is_empty() => {
                let _ = writeln!(
                    t,
                    "mistake not recognised: these explain the answer equally well:"
                );
                for a in &d.alternatives {
                    let _ = writeln!(t, "  - {a}");
                }
            }
            None => {
                let _ = writeln!(
                    t,
                    "mistake not recognised: no typical mistake explains these answers"
                );
            }
        }
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
            "difference": v.difference, "tolerance": v.tolerance, "unit": v.unit, "ok": v.ok(),
            "judgement": match &v.judgement {
                Judgement::Right => "right",
                Judgement::Wrong => "wrong",
                Judgement::CannotJudge(_) => "cannot be judged",
            },
            "reason": match &v.judgement { Judgement::CannotJudge(w) => Some(w.clone()), _ => None },
            "on_plan_mm": v.on_plan.map(|(e, g)| serde_json::json!({ "expected": e, "given": g })),
            "step": v.step.as_ref().map(|s| s.0),
            "step_text": v.step.as_ref().map(|s| s.1.clone()),
        })).collect::<Vec<_>>(),
        "right": r.right(),
        "wrong": r.wrong(),
        "cannot_be_judged": r.unjudged(),
        "status": r.status(),
        "diagnosis": r.diagnosis.as_ref().map(|d| serde_json::json!({
            "mistake": d.mistake, "recognised": d.mistake.is_some(),
            "explanation": d.explanation.map(explanation_json),
            "alternatives": d.alternatives,
            "step": d.step.as_ref().map(|s| s.0), "step_text": d.step.as_ref().map(|s| s.1.clone()), "explained": d.explained,
        })),
    })
}

/// An SVG sheet with the correct plan (black) and the student's points
/// (red crosses, labelled), for `check --svg`.
pub fn overlay(an: &Analysis, ans: &Answer, r: &Report) -> String {
    use crate::presentation::drawing::canvas::{Canvas, Class, Label, SMALL};
    let plan = &r.plan_built;
    let mut c = Canvas::default();
    crate::presentation::drawing::plan::draw(plan, &mut c, &an.points);
    // The student's points: given directly, or the far end of a segment
    // from the pole.
    for it in &ans.items {
        let at = match &it.given {
            Given::Point { at, .. } => Some(kurbo::Point::new(at[0], at[1])),
            _ => None,
        };
        if let Some(p) = at {
            let d = 1.2;
            c.prims
                .push(crate::presentation::drawing::canvas::Prim::Seg {
                    a: p + Vec2::new(-d, -d),
                    b: p + Vec2::new(d, d),
                    class: Class::Thin,
                    id: Some(format!("student-{}", it.key)),
                });
            c.prims
                .push(crate::presentation::drawing::canvas::Prim::Seg {
                    a: p + Vec2::new(-d, d),
                    b: p + Vec2::new(d, -d),
                    class: Class::Thin,
                    id: None,
                });
            c.label(p, Label::new(format!("{}*", it.key), ""), SMALL, None);
            if let Some(crate::presentation::drawing::canvas::Prim::Text { class, .. }) =
                c.prims.last_mut()
            {
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
        r.right(),
        r.verdicts.len(),
        r.diagnosis
            .as_ref()
            .and_then(|d| d.mistake.as_ref())
            .map(|m| format!(" — {m}"))
            .unwrap_or_default()
    );
    crate::presentation::drawing::page_svg(
        "check".into(),
        title,
        &c,
        None,
        &crate::presentation::drawing::DrawOptions::default(),
    )
    .svg
}

/// A typed explanation as JSON: its kind, and which element or factor.
fn explanation_json(e: crate::grading::Explanation) -> serde_json::Value {
    use crate::grading::Explanation as E;
    match e {
        E::Mistake { m, at, both } => {
            serde_json::json!({ "kind": format!("{m:?}"), "at": at, "both_plans": both })
        }
        E::Slip { at, factor } => serde_json::json!({ "kind": "Slip", "at": at, "factor": factor }),
        E::Pair(a, b) => {
            serde_json::json!({ "kind": "Pair", "mistakes": [format!("{a:?}"), format!("{b:?}")] })
        }
        E::Branch(g) => serde_json::json!({ "kind": "Branch", "group": g + 1 }),
        E::Scale(f) => serde_json::json!({ "kind": "Scale", "factor": f }),
    }
}

/// A force plan's report in words.
pub fn force_to_text(r: &ForceReport) -> String {
    use std::fmt::Write as _;
    let mut t = format!(
        "Force plan of links {}, position {}, μ_F = {} N/mm, δ = {} mm\n",
        r.links.join(", "),
        r.position,
        r.mu,
        r.delta
    );
    for v in &r.verdicts {
        let verdict = match &v.judgement {
            Judgement::Right => "right".to_string(),
            Judgement::Wrong => "WRONG".to_string(),
            Judgement::CannotJudge(why) => format!("cannot be judged: {why}"),
        };
        let _ = writeln!(
            t,
            "  {}: given {:.4} {u}, expected {:.4} ± {:.4} {u}: {verdict}",
            v.what,
            v.given,
            v.expected,
            v.tolerance,
            u = v.unit
        );
    }
    match &r.diagnosis {
        Some(d) => {
            let _ = writeln!(t, "  Diagnosis: the plan was drawn with {d}.");
        }
        None if r.wrong() > 0 => {
            let _ = writeln!(
                t,
                "  Diagnosis: no typical mistake explains the wrong items."
            );
        }
        None => {}
    }
    t
}

/// A force plan's report as JSON.
pub fn force_to_json(r: &ForceReport) -> serde_json::Value {
    let items: Vec<serde_json::Value> = r
        .verdicts
        .iter()
        .map(|v| {
            let (verdict, why) = match &v.judgement {
                Judgement::Right => ("right", None),
                Judgement::Wrong => ("wrong", None),
                Judgement::CannotJudge(w) => ("cannot_judge", Some(w.clone())),
            };
            serde_json::json!({
                "pointer": v.pointer, "key": v.key, "what": v.what,
                "given": v.given, "expected": v.expected, "difference": v.difference,
                "tolerance": v.tolerance, "unit": v.unit, "verdict": verdict, "why": why,
            })
        })
        .collect();
    serde_json::json!({
        "plan": "force",
        "position": r.position,
        "links": r.links,
        "mu": r.mu,
        "delta": r.delta,
        "items": items,
        "wrong": r.wrong(),
        "diagnosis": r.diagnosis,
        "status": r.status(),
    })
}
