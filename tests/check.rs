//! Checking hand-drawn plans: tolerances that hold for pencil noise inside
//! the model and catch three times as much, every typical mistake flagged
//! and diagnosed, an Inkscape-style SVG read like the JSON, bad answers.

mod common;
use common::*;
use mechplan::check::answer::{Answer, Given, Item};
use mechplan::check::{check, resolve};
use mechplan::construction::{Drafting, Mistake, Plan, PlanKind, Setup, Variant, build_plans};
use rand::{Rng, SeedableRng};
use serde_json::json;

fn first_position(name: &str) -> (mechplan::Analysis, Vec<mechplan::Solved>) {
    let v = fixture(name);
    let s = scene_with(v.clone(), input_first(name, &v));
    solve(s)
}

fn input_first(name: &str, v: &serde_json::Value) -> serde_json::Value {
    let sw = sweep(name, v);
    let (key, list) = sw.as_object().unwrap().iter().next().unwrap();
    json!({ key.as_str(): [list[list.as_array().unwrap().len() / 3].clone()] })
}

fn variant_plan(
    an: &mechplan::Analysis,
    s: &mechplan::Solved,
    kind: PlanKind,
    mu: f64,
    variant: Variant,
) -> Option<Plan> {
    let setup = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let d = Drafting {
        mu_v: Some(if kind == PlanKind::Velocity {
            mu
        } else {
            s.plans.as_ref().unwrap().velocity.mu
        }),
        mu_a: Some(mu),
        delta: 0.5,
        variant,
    };
    let order = mechplan::analytic::Order::Acceleration;
    let p = build_plans(
        &setup,
        &s.config,
        mechplan::analytic::Drive {
            q: s.q,
            rate: s.rate,
            rate2: s.rate2,
        },
        order,
        d,
    )
    .ok()?;
    Some(if kind == PlanKind::Velocity {
        p.velocity
    } else {
        p.acceleration.unwrap()
    })
}

/// Segments a student measures: every absolute vector and every relative
/// segment the plan measures, named by their plan points.
fn segment_items(plan: &Plan, reference: &Plan, noise: &mut impl FnMut() -> f64) -> Vec<Item> {
    reference
        .measured
        .iter()
        .map(|q| {
            let (a, b) = (&reference.points[q.from], &reference.points[q.to]);
            let (ia, ib) = (
                resolve(plan, &a.key).unwrap(),
                resolve(plan, &b.key).unwrap(),
            );
            let mm = (plan.points[ib].at - plan.points[ia].at).hypot() + noise();
            let key = format!("{} {}", a.key, b.key);
            Item {
                pointer: format!("/segments/{key}"),
                key: key.clone(),
                given: Given::Segment {
                    from: key,
                    to: String::new(),
                    mm: mm.max(0.0),
                },
            }
        })
        .collect()
}

/// Answers made from the correct plan with pencil noise inside the model
/// (every drafting operation off by at most δ = 0.5 mm, every measurement
/// off by at most δ) pass at least 99 % of the time over 1000 trials; the
/// same items off by three times their tolerance fail.
#[test]
fn pencil_noise_passes_and_three_tolerances_fail() {
    for name in FIXTURES {
        let (an, solved) = first_position(name);
        let s = &solved[0];
        for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
            let plans = s.plans.as_ref().unwrap();
            let reference = if kind == PlanKind::Velocity {
                &plans.velocity
            } else {
                plans.acceleration.as_ref().unwrap()
            };
            let mu = reference.mu;
            let mut rng = rand::rngs::StdRng::seed_from_u64(7);
            let mut passed = 0;
            let trials = 1000;
            for t in 0..trials {
                let drawn = variant_plan(
                    &an,
                    s,
                    kind,
                    mu,
                    Variant {
                        mistake: None,
                        jitter: Some(t as u64 + 1),
                    },
                )
                .unwrap();
                let mut noise = || rng.random_range(-0.5..=0.5);
                let items = segment_items(&drawn, reference, &mut noise);
                let ans = Answer {
                    plan: kind,
                    position: 1,
                    mu,
                    delta: 0.5,
                    items,
                };
                let r = check(&an, &solved, &ans).unwrap();
                if r.wrong() == 0 {
                    passed += 1;
                }
            }
            assert!(
                passed * 100 >= trials * 99,
                "{name} {kind:?}: only {passed} of {trials} noisy answers passed"
            );
            // Three tolerances off: every item wrong.
            let mut none = || 0.0;
            let exact = segment_items(reference, reference, &mut none);
            let ans = Answer {
                plan: kind,
                position: 1,
                mu,
                delta: 0.5,
                items: exact,
            };
            let r = check(&an, &solved, &ans).unwrap();
            assert_eq!(r.wrong(), 0, "{name}: the exact answer passes");
            let mut items = ans.items.clone();
            for (it, v) in items.iter_mut().zip(&r.verdicts) {
                if let Given::Segment { mm, .. } = &mut it.given {
                    *mm = v.expected + 3.0 * v.tolerance;
                }
            }
            let r = check(&an, &solved, &Answer { items, ..ans }).unwrap();
            assert_eq!(
                r.wrong(),
                r.verdicts.len(),
                "{name}: three tolerances off must fail every item"
            );
            eprintln!("{name} {kind:?}: {passed}/{trials} noisy answers passed");
        }
    }
}

fn mistake_name(m: Mistake) -> &'static str {
    match m {
        Mistake::CoriolisReversed => "Coriolis acceleration is turned the wrong way",
        Mistake::CoriolisForgotten => "Coriolis acceleration is forgotten",
        Mistake::NormalFromCentre => "laid off from the centre",
        Mistake::MirroredFigure => "similar figure is mirrored",
        Mistake::WrongPerpendicular => "perpendicular is drawn to the wrong link",
        Mistake::Epsilon1Forgotten => "tangential acceleration ε1·l is forgotten",
        Mistake::Epsilon1Added => "added although ε1 = 0",
        Mistake::OmegaWrongLink => "uses ω of the crank",
        Mistake::OmegaWrongSense => "against the sense of ω1",
    }
}

/// Each typical mistake, wherever the fixture makes it possible: an answer
/// built with it is flagged wrong and diagnosed as that mistake, with the
/// step where it happens.
#[test]
fn every_typical_mistake_is_flagged_and_diagnosed() {
    let mistakes = [
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
    let mut seen = std::collections::BTreeSet::new();
    for name in FIXTURES {
        let (an, solved) = first_position(name);
        let s = &solved[0];
        for m in mistakes {
            for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
                let plans = s.plans.as_ref().unwrap();
                let reference = if kind == PlanKind::Velocity {
                    &plans.velocity
                } else {
                    plans.acceleration.as_ref().unwrap()
                };
                let Some(wrong) = variant_plan(
                    &an,
                    s,
                    kind,
                    reference.mu,
                    Variant {
                        mistake: Some(m),
                        jitter: None,
                    },
                ) else {
                    continue;
                };
                if wrong.mistake_step.is_none() {
                    continue; // the mistake cannot be made here
                }
                // The student's points: every named point of the mistaken plan.
                let items: Vec<Item> = an
                    .points
                    .iter()
                    .filter_map(|&p| wrong.of_point[p])
                    .filter(|&i| i != 0)
                    .map(|i| Item {
                        pointer: format!("/points/{}", wrong.points[i].key),
                        key: wrong.points[i].key.clone(),
                        given: Given::Point {
                            name: wrong.points[i].key.clone(),
                            at: [wrong.points[i].at.x, wrong.points[i].at.y],
                        },
                    })
                    .collect();
                let differs = items.iter().any(|it| {
                    let Given::Point { name, at } = &it.given else {
                        unreachable!()
                    };
                    let i = resolve(reference, name).unwrap();
                    (reference.points[i].at - kurbo::Vec2::new(at[0], at[1])).hypot() > 3.0
                });
                if !differs {
                    continue; // too small an effect at this position to be seen
                }
                let r = check(
                    &an,
                    &solved,
                    &Answer {
                        plan: kind,
                        position: 1,
                        mu: reference.mu,
                        delta: 0.5,
                        items,
                    },
                )
                .unwrap();
                assert!(r.wrong() > 0, "{name} {kind:?} {m:?}: not flagged");
                let d = r
                    .diagnosis
                    .as_ref()
                    .unwrap_or_else(|| panic!("{name} {kind:?} {m:?}: no diagnosis"));
                assert!(
                    d.mistake.contains(mistake_name(m)),
                    "{name} {kind:?} {m:?}: diagnosed as {}",
                    d.mistake
                );
                assert!(d.step.is_some(), "{name} {m:?}: no step named");
                seen.insert(format!("{m:?}"));
            }
        }
    }
    assert_eq!(
        seen.len(),
        mistakes.len(),
        "every mistake tested somewhere: {seen:?}"
    );
}

/// μ applied in the wrong units: values off by 1000 are diagnosed so.
#[test]
fn scale_in_the_wrong_units_is_diagnosed() {
    let (an, solved) = first_position("six_link_fig2_10");
    let plan = &solved[0].plans.as_ref().unwrap().velocity;
    let m = &an.mech;
    let mut values = serde_json::Map::new();
    for n in ["B", "C", "D"] {
        let v = plan
            .value_of(m.scene.point_index(n).unwrap())
            .unwrap()
            .hypot();
        values.insert(format!("v_{n}"), json!(v * 1000.0));
    }
    let text = json!({ "plan": "velocity", "mu": plan.mu, "values": values }).to_string();
    let ans = mechplan::check::answer::from_json(&text).unwrap();
    let r = check(&an, &solved, &ans).unwrap();
    assert_eq!(r.wrong(), 3);
    assert!(r.diagnosis.unwrap().mistake.contains("wrong units"));
}

/// The other assembly branch: a plan built on the mirrored group.
#[test]
fn wrong_branch_is_diagnosed() {
    let (an, solved) = first_position("four_bar");
    let s = &solved[0];
    let mut ps =
        mechplan::positions::PositionSolver::new(&an.mech, &an.structure, an.need.clone()).unwrap();
    ps.branches.sign[0] = -ps.branches.sign[0];
    let c = ps.solve_at(s.q).unwrap();
    let setup = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let mu = s.plans.as_ref().unwrap().velocity.mu;
    let d = Drafting {
        mu_v: Some(mu),
        ..Drafting::default()
    };
    let wrong = build_plans(
        &setup,
        &c,
        mechplan::analytic::Drive {
            q: s.q,
            rate: s.rate,
            rate2: s.rate2,
        },
        mechplan::analytic::Order::Velocity,
        d,
    )
    .unwrap()
    .velocity;
    let items: Vec<Item> = ["b", "m"]
        .iter()
        .map(|k| {
            let i = resolve(&wrong, k).unwrap();
            Item {
                pointer: format!("/points/{k}"),
                key: k.to_string(),
                given: Given::Point {
                    name: k.to_string(),
                    at: [wrong.points[i].at.x, wrong.points[i].at.y],
                },
            }
        })
        .collect();
    let r = check(
        &an,
        &solved,
        &Answer {
            plan: PlanKind::Velocity,
            position: 1,
            mu,
            delta: 0.5,
            items,
        },
    )
    .unwrap();
    assert!(r.wrong() > 0);
    assert!(r.diagnosis.unwrap().mistake.contains("other branch"));
}

/// An Inkscape-style SVG answer (text labels next to points, path
/// segments, group transforms) is read and checked like the JSON.
#[test]
fn inkscape_svg_answer_is_read_and_checked() {
    let (an, solved) = first_position("six_link_fig2_10");
    let plan = &solved[0].plans.as_ref().unwrap().velocity;
    // The student's drawing: pole at (60, 120) mm on an A4 page, drawn
    // inside a translated and scaled group as Inkscape writes layers.
    let mut body = String::new();
    let pole = (30.0, 60.0); // in the group's units (scaled ×2 below)
    let mut labels = vec![("p_v".to_string(), 0.0, 0.0)];
    for k in ["a", "b", "c", "d", "s2"] {
        let i = resolve(plan, k).unwrap();
        labels.push((k.to_string(), plan.points[i].at.x, plan.points[i].at.y));
    }
    for (k, x, y) in &labels {
        // Group units are half a millimetre: scale(2) maps them to mm... no: the group is scale(0.5), so 2 units = 1 mm.
        let (gx, gy) = (pole.0 + x * 2.0, pole.1 - y * 2.0);
        if k != "p_v" {
            body.push_str(&format!(
                r#"<path d="M {} {} L {gx} {gy}" stroke="black" fill="none"/>"#,
                pole.0, pole.1
            ));
        }
        body.push_str(&format!(
            r#"<text x="{}" y="{}" font-size="7">{k}</text>"#,
            gx + 3.0,
            gy - 3.0
        ));
    }
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297"><g transform="translate(45 90) scale(0.5)">{body}<text x="0" y="-20" font-size="8">μ = {}</text></g></svg>"#,
        plan.mu
    );
    let ans = mechplan::check::svg::from_svg(&svg, None, None, 0.5, 1).unwrap();
    assert_eq!(ans.plan, PlanKind::Velocity);
    assert_eq!(ans.mu, plan.mu);
    assert_eq!(ans.items.len(), 5);
    let r = check(&an, &solved, &ans).unwrap();
    assert_eq!(r.wrong(), 0, "{}", mechplan::check::to_text(&r));
}

/// Bad answers get clear messages naming the field.
#[test]
fn bad_answers_are_refused_with_the_field_named() {
    let (an, solved) = first_position("six_link_fig2_10");
    let cases = [
        (
            json!({ "plan": "velocity", "mu": 0.01, "segments": { "p_v q": 10 } }),
            "unknown plan point \"q\"",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "segments": { "p_v b": -3 } }),
            "/segments/p_v b",
        ),
        (
            json!({ "plan": "velocity", "segments": { "p_v b": 3 } }),
            "/mu",
        ),
        (
            json!({ "plan": "speed", "mu": 0.01, "segments": { "p_v b": 3 } }),
            "/plan",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "position": 9, "segments": { "p_v b": 3 } }),
            "/position",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "q_B": 3 } }),
            "unknown quantity",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01 }),
            "nothing to check",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "omega9": 3 } }),
            "unknown link",
        ),
    ];
    for (text, expect) in cases {
        let err = match mechplan::check::answer::from_json(&text.to_string()) {
            Err(e) => e.to_string(),
            Ok(a) => check(&an, &solved, &a)
                .map(|_| String::new())
                .unwrap_or_else(|e| e.to_string()),
        };
        assert!(err.contains(expect), "{text}: {err}");
    }
}
