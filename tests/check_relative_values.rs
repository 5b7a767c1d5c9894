//! A prismatic pair's relative values as items of an answer (issue 37:
//! every number on an answer judged): the sliding velocity v_B3B2 on a
//! velocity plan; the whole relative acceleration a_B3B2, the sliding
//! acceleration a^r_B3B2 and the Coriolis acceleration a^k_B3B2 on an
//! acceleration plan. The right values come from tests/student's
//! rigid-body solver (the method's own equations, never mechplan's
//! construction): v_rel and a_rel of each pair, a^k = 2·|ω_guide|·|v_rel|.
//! Written to three significant digits they are never wrong, on an answer
//! of values alone and on one with the plan's points drawn exactly
//! (undecided where a mistake's value lies within the tolerance too: at
//! most 3 % with the points, at most a third written alone); each
//! taken 1.5 times, where that moves it more than 2δ on the plan and twice
//! the honest item's tolerance, it is wrong.

mod student;

use mechplan::PlanKind;
use mechplan::check::answer::from_json;
use mechplan::check::{Judgement, Report, check};
use student::drawing::{
    AnswerFile, Drawing, acceleration_plan, significant, standard_mu, velocity_plan,
};
use student::rigid::{Model, Options, perp};
use student::scenes;

fn grade(case: &scenes::Case, a: &AnswerFile) -> Report {
    let text = a.to_json();
    let ans = from_json(&text).unwrap_or_else(|e| panic!("{e} in {text}"));
    check(&case.an, &case.solved, &ans).unwrap_or_else(|e| panic!("{e} in {text}"))
}

/// The verdict of the item written under `key`.
fn verdict<'a>(r: &'a Report, key: &str) -> &'a Judgement {
    &r.verdicts
        .iter()
        .find(|v| v.key == key)
        .unwrap_or_else(|| panic!("no verdict for {key}"))
        .judgement
}

#[test]
fn relative_values_of_prismatic_pairs_are_judged() {
    let (mut right, mut wrong) = (0, 0);
    // Undecided honest values: [values alone, with the points].
    let mut undecided = [0usize; 2];
    let mut judged = [0usize; 2];
    for case in scenes::fixtures() {
        for (k, s) in case.solved.iter().enumerate() {
            let m = Model::new(&case.json, &case.an, s);
            let Some(vel) = m.velocities(&Options::default()) else {
                continue;
            };
            let Some(acc) = m.accelerations(&vel, &vel.omega, &Options::default()) else {
                continue;
            };
            let mu_v = standard_mu(velocity_plan(&m, &vel).largest());
            let mu_a = standard_mu(acceleration_plan(&m, &acc).largest());
            // (plan, key, the right value, μ)
            let mut values: Vec<(PlanKind, String, f64, f64)> = Vec::new();
            for (q, pair) in m.pairs.iter().enumerate() {
                let p = &m.names[pair.point];
                let rel = format!(
                    "{p}{}{p}{}",
                    m.links[pair.guide].id, m.links[pair.slider].id
                );
                let w_g = if m.moving(pair.guide) {
                    vel.omega[pair.guide]
                } else {
                    0.0
                };
                let u = vel.line[q];
                let coriolis = perp(u * vel.v_rel[q]) * (2.0 * w_g);
                let sliding = acc.line[q] * acc.a_rel[q];
                values.push((
                    PlanKind::Velocity,
                    format!("v_{rel}"),
                    vel.v_rel[q].abs(),
                    mu_v,
                ));
                values.push((
                    PlanKind::Acceleration,
                    format!("a^r_{rel}"),
                    acc.a_rel[q].abs(),
                    mu_a,
                ));
                values.push((
                    PlanKind::Acceleration,
                    format!("a^k_{rel}"),
                    coriolis.hypot(),
                    mu_a,
                ));
                values.push((
                    PlanKind::Acceleration,
                    format!("a_{rel}"),
                    (coriolis + sliding).hypot(),
                    mu_a,
                ));
            }
            for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
                let mine: Vec<&(PlanKind, String, f64, f64)> =
                    values.iter().filter(|v| v.0 == kind).collect();
                if mine.is_empty() {
                    continue;
                }
                let mu = mine[0].3;
                let drawing: Drawing = match kind {
                    PlanKind::Velocity => velocity_plan(&m, &vel).at_scale(mu),
                    PlanKind::Acceleration => acceleration_plan(&m, &acc).at_scale(mu),
                };
                let answer = |points: bool, factor: f64| AnswerFile {
                    plan: kind,
                    position: k + 1,
                    mu,
                    title: format!("{} position {} relative values", case.name, k + 1),
                    points: if points {
                        drawing.0.iter().map(|(n, _, v)| (n.clone(), *v)).collect()
                    } else {
                        Vec::new()
                    },
                    segments: Vec::new(),
                    angles: Vec::new(),
                    values: mine
                        .iter()
                        .map(|(_, key, x, _)| (key.clone(), significant(x * factor, 3)))
                        .collect(),
                    velocity: (kind == PlanKind::Acceleration).then(|| (mu_v, Vec::new())),
                };
                for points in [false, true] {
                    let r = grade(&case, &answer(points, 1.0));
                    for (_, key, x, _) in &mine {
                        let j = verdict(&r, key);
                        // Never wrong; undecided only where a mistake's
                        // value lies within its tolerance too (counted).
                        assert!(
                            *j != Judgement::Wrong,
                            "{} position {} {key} = {x:.4} (points: {points}): {j:?}\n{}",
                            case.name,
                            k + 1,
                            mechplan::presentation::verdict::to_text(&r)
                        );
                        right += 1;
                        judged[usize::from(points)] += 1;
                        if *j != Judgement::Right {
                            undecided[usize::from(points)] += 1;
                            eprintln!(
                                "undecided: {} position {} {key} points {points}: {j:?}",
                                case.name,
                                k + 1
                            );
                        }
                    }
                    let tolerance = |key: &str| {
                        r.verdicts
                            .iter()
                            .find(|v| v.key == key)
                            .map_or(f64::INFINITY, |v| v.tolerance)
                    };
                    let tolerances: Vec<f64> = mine.iter().map(|v| tolerance(&v.1)).collect();
                    let r = grade(&case, &answer(points, 1.5));
                    for ((_, key, x, mu), tol) in mine.iter().zip(tolerances) {
                        // Certainly seen: more than 2δ on the plan and
                        // twice the honest item's tolerance.
                        if 0.5 * x / mu <= 1.0 || 0.5 * x <= 2.0 * tol {
                            continue;
                        }
                        let j = verdict(&r, key);
                        assert!(
                            *j == Judgement::Wrong,
                            "{} position {} {key} = {:.4} for {x:.4} (points: {points}): {j:?}",
                            case.name,
                            k + 1,
                            1.5 * x
                        );
                        wrong += 1;
                    }
                }
            }
        }
    }
    eprintln!(
        "relative values: {right} right ones, none wrong; undecided {} of {} with the points drawn, {} of {} written alone; {wrong} wrong ones judged wrong",
        undecided[1], judged[1], undecided[0], judged[0]
    );
    assert!(
        right >= 100 && wrong >= 40,
        "too few: {right} right, {wrong} wrong"
    );
    // With the points drawn each value is read off the student's own
    // points: as decided as any step (≤ 3 %). Written alone, a value deep
    // in the construction (the ram's a_K0K5) carries the tolerance of the
    // whole construction before it, as a table of values does.
    assert!(
        undecided[1] * 100 <= 3 * judged[1],
        "{} of {} right values with points undecided",
        undecided[1],
        judged[1]
    );
    assert!(
        undecided[0] * 3 <= judged[0],
        "{} of {} right values written alone undecided",
        undecided[0],
        judged[0]
    );
}

#[test]
fn a_relative_value_on_the_other_plan_is_refused() {
    let case = scenes::fixtures()
        .into_iter()
        .find(|c| c.name == "shaper_fig2_11")
        .unwrap();
    let text = r#"{"plan":"velocity","position":1,"mu":0.004,"values":{"a^r_B3B2":1.0}}"#;
    let ans = from_json(text);
    let e = match ans {
        Err(e) => e.to_string(),
        Ok(a) => check(&case.an, &case.solved, &a).unwrap_err().to_string(),
    };
    assert!(
        e.contains("a^r_B3B2") && e.contains("acceleration plan"),
        "{e}"
    );
}
