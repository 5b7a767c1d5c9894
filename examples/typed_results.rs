//! The library's results as typed data: a plan's points and scale, and a
//! checked answer's steps and mistakes, read as fields (no JSON values).
//!
//! `cargo run --release --example typed_results`

use mechplan::study::plan::Plan;
use mechplan::study::verdict::{Grade, Judgement, Report};
use mechplan::{Checked, PlanKind, Study};

fn main() -> Result<(), mechplan::Error> {
    let study = Study::from_json(mechplan::DEFAULT_SCENE)?;
    let solution = study.solve()?;
    let position = solution.position(3)?;

    // The velocity plan as the construction drew it.
    let plan: &Plan = position
        .plan(PlanKind::Velocity)
        .expect("the default scene asks for velocities");
    println!("velocity plan at position 3, μ_v = {} (m/s)/mm", plan.mu);
    for p in &plan.points {
        println!(
            "  {:>4} at ({:8.3}, {:8.3}) mm from the pole, ± {:.3} mm",
            p.key, p.at.x, p.at.y, p.err
        );
    }

    // A student's answer: the same plan with its last point drawn 6 mm
    // off, as a JSON answer file says it.
    let last = plan.points.len() - 1;
    let points: Vec<String> = plan
        .points
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.key.is_empty())
        .map(|(i, p)| {
            let dy = if i == last { 6.0 } else { 0.0 };
            format!("\"{}\": [{:.2}, {:.2}]", p.key, p.at.x, p.at.y + dy)
        })
        .collect();
    let answer = format!(
        r#"{{"plan": "velocity", "position": 3, "mu": {}, "points": {{{}}}}}"#,
        plan.mu,
        points.join(", ")
    );
    let checked = study.check_answer(&answer, "answer.json", false)?;
    let Checked::Kinematic(k) = checked else {
        unreachable!("a velocity plan is a kinematic answer")
    };
    let report: &Report = &k.report;
    let steps = report.steps.as_ref().expect("the answer draws points");
    println!("graded {:?}", steps.grade());
    for s in &steps.steps {
        let said = match &s.judgement {
            Judgement::Right => "right".to_string(),
            Judgement::Wrong => "WRONG".to_string(),
            Judgement::CannotJudge(why) => format!("cannot be judged: {why}"),
        };
        println!(
            "  step {:>2} {:>4}: {:.2} mm off, tolerance {:.2} mm: {said}",
            s.step.0, s.point, s.off, s.tolerance
        );
    }
    for m in &steps.mistakes {
        println!(
            "  mistake at step {}: {} (points {:?})",
            m.step.0,
            m.mistake.as_deref().unwrap_or("not recognised"),
            m.points
        );
    }
    assert_eq!(steps.grade(), Grade::Wrong);
    Ok(())
}
