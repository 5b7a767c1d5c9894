//! A check's verdict (`crate::grading`'s report, data) as text for the
//! terminal, as JSON, and as an SVG overlay of the student's points on the
//! correct plan (drawn by [`super::overlay`]).

pub use super::force_overlay::force_overlay;
pub use super::overlay::{overlay, overlay_dxf};
use crate::grading::forces::ForceReport;
use crate::words::numbers;
use crate::grading::{Grade, Judgement, Report, StepReport};
use crate::words::catalogue::CheckPhrases;
use crate::lang::Lang;
use crate::words::check::{self, fill};
use crate::words::numbers::{decimals, quantity, unit};
use crate::kinematics::construction::PlanKind;

/// The report as text for the terminal, in the report's language: the
/// grade, the steps judged from the student's own points and the
/// mistakes found at them (an answer that draws points), the items, and
/// beside them the comparison with the true plan. Its numbers are
/// written with the language's decimal mark, its units in its letters.
pub fn to_text(r: &Report) -> String {
    use std::fmt::Write as _;
    let w = check::phrases(r.lang);
    let fmt = |x: f64| number(x, r.lang);
    let mut t = String::new();
    let kind = &w.plan[usize::from(r.plan == PlanKind::Acceleration)];
    let _ = writeln!(
        t,
        "{}",
        fill(
            &w.title,
            &[
                ("plan", kind),
                ("position", &r.position.to_string()),
                ("mu", &fmt(r.mu)),
                ("delta", &quantity(r.delta, "mm", r.lang)),
            ],
        )
    );
    if r.worst_angle < 5.0 {
        let _ = writeln!(t, "{}", fill(&w.dead_centre, &[("angle", &fmt(r.worst_angle))]));
    }
    // The note of points that fit elsewhere: under the grade.
    let note = r.elsewhere_note().map(|n| n + "\n").unwrap_or_default();
    match &r.steps {
        Some(steps) => {
            let mut s = String::new();
            steps_text(&mut s, w, (steps, r.grade(), r.wrong()), r.lang);
            let cut = s.find('\n').map_or(s.len(), |i| i + 1);
            t.push_str(&s[..cut]);
            t.push_str(&note);
            t.push_str(&s[cut..]);
        }
        None => t.push_str(&note),
    }
    let _ = writeln!(t, "{}", w.items_heading);
    let c = &w.items_columns;
    let _ = writeln!(
        t,
        "  {:<32} {:>12} {:>12} {:>12} {:>12}  {}",
        c[0], c[1], c[2], c[3], c[4], c[5]
    );
    for v in &r.verdicts {
        let _ = writeln!(
            t,
            "  {:<32} {:>12} {:>12} {:>12} {:>12}  {} {}",
            v.what,
            fmt(v.expected),
            fmt(v.given),
            fmt(v.difference),
            fmt(v.tolerance),
            unit(v.unit, r.lang),
            verdict_word(w, &v.judgement)
        );
        if v.ok() {
            continue;
        }
        if let Some((e, g)) = v.on_plan
            && v.unit != "mm"
        {
            let (e, g) = (fmt(e), fmt(g));
            let _ = writeln!(t, "      {}", fill(&w.on_plan, &[("expected", &e), ("given", &g)]));
        }
        match &v.step {
            // A value read off the velocity plan, before the plan is drawn.
            Some((0, s)) => {
                let _ = writeln!(t, "      {}", fill(&w.mistake_step, &[("sentence", s)]));
            }
            Some((k, s)) => {
                let k = k.to_string();
                let _ = writeln!(t, "      {}", fill(&w.drawn_at, &[("step", &k), ("sentence", s)]));
            }
            None => {}
        }
        if let Judgement::CannotJudge(why) = &v.judgement {
            let _ = writeln!(t, "      {}", fill(&w.cannot_judge_why, &[("why", why)]));
        }
    }
    let _ = writeln!(
        t,
        "{}",
        fill(
            &w.total,
            &[
                ("right", &r.right().to_string()),
                ("count", &r.verdicts.len().to_string()),
                ("wrong", &r.wrong().to_string()),
                ("unjudged", &r.unjudged().to_string()),
            ],
        )
    );
    match &r.second_opinion {
        Some(o) => {
            let counts = [
                ("right", o.right.to_string()),
                ("wrong", o.wrong.to_string()),
                ("unjudged", o.unjudged.to_string()),
            ];
            let counts: Vec<(&str, &str)> = counts.iter().map(|(k, v)| (*k, v.as_str())).collect();
            let verdict = match &o.disagreement {
                None => w.second_agrees.clone(),
                Some(why) => fill(&w.second_disagrees, &[("why", why)]),
            };
            let _ = writeln!(t, "{} {verdict}", fill(&w.second_opinion, &counts));
        }
        None => diagnosis_text(&mut t, w, r),
    }
    t
}

/// A number of the text report: [`crate::format::format_number`]'s
/// digits with the language's decimal mark.
fn number(x: f64, lang: Lang) -> String {
    decimals(&crate::format::format_number(x), lang)
}

/// The word of a judgement.
fn verdict_word<'a>(w: &'a CheckPhrases, j: &Judgement) -> &'a str {
    match j {
        Judgement::Right => &w.verdicts[0],
        Judgement::Wrong => &w.verdicts[1],
        Judgement::CannotJudge(_) => &w.verdicts[2],
    }
}

/// The grade, the steps judged from the student's own points, and the
/// mistakes found at them.
fn steps_text(
    t: &mut String,
    w: &CheckPhrases,
    (steps, grade, wrong): (&StepReport, Grade, usize),
    lang: Lang,
) {
    use std::fmt::Write as _;
    let fmt = |x: f64| number(x, lang);
    let grade = match grade {
        Grade::Right => w.grade_right.clone(),
        Grade::CannotJudge => w.grade_cannot_judge.clone(),
        Grade::Wrong if steps.mistakes.len() == 1 => {
            let f = &steps.mistakes[0];
            let mistake = f.mistake.clone().unwrap_or_else(|| w.not_recognised.clone());
            if f.step.0 == 0 {
                fill(&w.grade_wrong_before, &[("mistake", &mistake)])
            } else {
                fill(
                    &w.grade_wrong_one,
                    &[("step", &f.step.0.to_string()), ("mistake", &mistake)],
                )
            }
        }
        Grade::Wrong if steps.mistakes.is_empty() => {
            fill(&w.grade_wrong_items, &[("count", &wrong.to_string())])
        }
        Grade::Wrong => fill(
            &w.grade_wrong_many,
            &[("count", &steps.mistakes.len().to_string())],
        ),
    };
    let _ = writeln!(t, "{grade}");
    let _ = writeln!(t, "{}", w.steps_heading);
    let c = &w.steps_columns;
    let _ = writeln!(t, "  {:>5}  {:<8} {:>10} {:>14}  {}", c[0], c[1], c[2], c[3], c[4]);
    for s in &steps.steps {
        let mut verdict = verdict_word(w, &s.judgement).to_string();
        if let Some(n) = s.mistake {
            let n = (n + 1).to_string();
            verdict = format!("{verdict} ({})", fill(&w.mistake_of_step, &[("n", &n)]));
        }
        let _ = writeln!(
            t,
            "  {:>5}  {:<8} {:>10} {:>14}  {verdict}",
            s.step.0,
            s.point,
            fmt(s.off),
            fmt(s.tolerance)
        );
        if let Judgement::CannotJudge(why) = &s.judgement {
            let _ = writeln!(t, "         {}", fill(&w.cannot_judge_why, &[("why", why)]));
        }
    }
    if steps.mistakes.is_empty() {
        return;
    }
    let _ = writeln!(t, "{}", w.mistakes_heading);
    for (n, f) in steps.mistakes.iter().enumerate() {
        let mistake = f.mistake.clone().unwrap_or_else(|| w.not_recognised.clone());
        let line = if f.step.0 == 0 {
            fill(
                &w.mistake_line_before,
                &[("n", &(n + 1).to_string()), ("mistake", &mistake)],
            )
        } else {
            fill(
                &w.mistake_line,
                &[
                    ("n", &(n + 1).to_string()),
                    ("step", &f.step.0.to_string()),
                    ("mistake", &mistake),
                ],
            )
        };
        let _ = writeln!(t, "  {line}");
        let _ = writeln!(t, "     {}", fill(&w.mistake_step, &[("sentence", &f.step.1)]));
        if !f.points.is_empty() {
            let points = f.points.join(", ");
            let _ = writeln!(t, "     {}", fill(&w.mistake_points, &[("points", &points)]));
        }
        if f.mistake.is_none() && !f.alternatives.is_empty() {
            let _ = writeln!(t, "     {}", w.alternatives);
            for a in &f.alternatives {
                let _ = writeln!(t, "       - {a}");
            }
        }
    }
}

/// The diagnosis of an answer judged against the true plan only.
fn diagnosis_text(t: &mut String, w: &CheckPhrases, r: &Report) {
    use std::fmt::Write as _;
    let Some(d) = &r.diagnosis else { return };
    match &d.mistake {
        Some(m) => {
            let _ = writeln!(t, "{}", fill(&w.likely_mistake, &[("mistake", m)]));
            if let Some((k, s)) = &d.step {
                let k = k.to_string();
                let _ = writeln!(t, "  {}", fill(&w.enters_at, &[("step", &k), ("sentence", s)]));
            }
        }
        None if !d.alternatives.is_empty() => {
            let _ = writeln!(t, "{}", w.alternatives_items);
            for a in &d.alternatives {
                let _ = writeln!(t, "  - {a}");
            }
        }
        None => {
            let _ = writeln!(t, "{}", w.not_recognised_items);
        }
    }
}

/// The report as JSON.
pub fn to_json(r: &Report) -> serde_json::Value {
    serde_json::json!({
        "plan": if r.plan == PlanKind::Velocity { "velocity" } else { "acceleration" },
        "position": r.position,
        "elsewhere": r.elsewhere.map(|e| serde_json::json!({
            "reversed": e.reversed, "position": e.position, "note": r.elsewhere_note(),
        })),
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
        "grade": r.steps.as_ref().map(|_| match r.grade() {
            Grade::Right => "right",
            Grade::Wrong => "wrong",
            Grade::CannotJudge => "cannot be judged",
        }),
        "steps": r.steps.as_ref().map(|st| st.steps.iter().map(|s| serde_json::json!({
            "step": s.step.0, "step_text": s.step.1, "point": s.point,
            "given": [s.given.x, s.given.y], "predicted": [s.predicted.x, s.predicted.y],
            "off": s.off, "tolerance": s.tolerance,
            "judgement": judgement_word(&s.judgement),
            "reason": match &s.judgement { Judgement::CannotJudge(w) => Some(w.clone()), _ => None },
            "mistake": s.mistake.map(|n| n + 1),
        })).collect::<Vec<_>>()),
        "mistakes": r.steps.as_ref().map(|st| st.mistakes.iter().map(|f| serde_json::json!({
            "step": f.step.0, "step_text": f.step.1, "mistake": f.mistake,
            "recognised": f.mistake.is_some(),
            "explanation": f.explanation.map(explanation_json),
            "points": f.points, "alternatives": f.alternatives,
        })).collect::<Vec<_>>()),
        "second_opinion": r.second_opinion.as_ref().map(|o| serde_json::json!({
            "right": o.right, "wrong": o.wrong, "cannot_be_judged": o.unjudged,
            "mistake": o.mistake, "agrees": o.disagreement.is_none(), "disagreement": o.disagreement,
        })),
    })
}

/// A judgement in the report's JSON.
fn judgement_word(j: &Judgement) -> &'static str {
    match j {
        Judgement::Right => "right",
        Judgement::Wrong => "wrong",
        Judgement::CannotJudge(_) => "cannot be judged",
    }
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
        E::Stated { index } => serde_json::json!({ "kind": "Stated", "index": index }),
        E::DrawnScale { drawn, stated } => {
            serde_json::json!({ "kind": "DrawnScale", "drawn": drawn, "stated": stated })
        }
    }
}

/// A force plan's report in words.
pub fn force_to_text(r: &ForceReport) -> String {
    use std::fmt::Write as _;
    let w = check::phrases(r.lang);
    let num = |x: f64| numbers::decimals(&crate::format::num(x), r.lang);
    let mut t = fill(
        &w.force_title,
        &[
            ("links", &r.links.join(", ")),
            ("position", &r.position.to_string()),
            ("mu", &num(r.mu)),
            ("delta", &num(r.delta)),
        ],
    );
    t.push('\n');
    for v in &r.verdicts {
        let verdict = match &v.judgement {
            Judgement::Right => w.force_verdicts[0].clone(),
            Judgement::Wrong => w.force_verdicts[1].clone(),
            Judgement::CannotJudge(why) => fill(&w.force_verdicts[2], &[("why", why)]),
        };
        let fixed = |x: f64| numbers::decimals(&format!("{x:.4}"), r.lang);
        let _ = writeln!(
            t,
            "{}",
            fill(
                &w.force_item,
                &[
                    ("what", &v.what),
                    ("given", &fixed(v.given)),
                    ("unit", &force_unit(v.unit, r.lang)),
                    ("expected", &fixed(v.expected)),
                    ("tol", &fixed(v.tolerance)),
                    ("verdict", &verdict),
                ],
            )
        );
    }
    match &r.diagnosis {
        Some(d) => {
            let _ = writeln!(t, "{}", fill(&w.force_diagnosis, &[("mistake", d)]));
        }
        None if r.wrong() > 0 => {
            let _ = writeln!(t, "{}", w.force_not_recognised);
        }
        None => {}
    }
    t
}

/// A force plan item's unit in `lang` (N, N·m, mm as the force plans'
/// sheets write them; others as the language's unit letters).
fn force_unit(u: &str, lang: Lang) -> String {
    let w = &crate::words::catalogue(lang).force_plans;
    match u {
        "N" => w.newton.clone(),
        "N·m" => w.newton_metre.clone(),
        "mm" => w.mm.clone(),
        _ => numbers::unit(u, lang),
    }
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
