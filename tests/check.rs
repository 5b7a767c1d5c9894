//! Checking hand-drawn plans. The catalogue of answers that give segments
//! and values only (judged against the true plan; answers that draw points
//! are judged step by step, tests/check_catalogue.rs): honest answers (the
//! plan drawn with the pencil off by up to δ at every step, and measured
//! with up to δ more, at several standard scales, near-collinear points,
//! extensions, class III) are never rejected; answers with each typical
//! mistake — made at one element or everywhere, an arithmetic slip in one
//! length, the other branch, μ applied wrongly — are never accepted (wrong,
//! or "cannot be judged" where the tolerance cannot tell), and the mistake
//! is named for at least 85 % of them. A mistake drawn exactly within every
//! item's tolerance whose own construction places none of the points it
//! moves (its lines meeting at a glancing angle) is left out: no check can
//! see it. Each case draws its noise from a seed of its own. Plus the
//! answer file's rules and an Inkscape-style SVG.

mod common;
use common::*;
use mechplan::check::answer::{Answer, Given, Item};
use mechplan::check::{Judgement, check, resolve};
use mechplan::construction::{
    Drafting, Mistake, Plan, PlanKind, Setup, Variant, build_acceleration, build_plans,
};
use mechplan::{Analysis, Solved};
use rand::{Rng, SeedableRng};
use serde_json::{Value, json};

/// A fixture solved at a few positions of its sweep (a sixth, a half and
/// five sixths of it).
fn positions(name: &str, v: &Value) -> (Analysis, Vec<Solved>) {
    let sw = sweep(name, v);
    let (key, list) = sw.as_object().unwrap().iter().next().unwrap();
    let list = list.as_array().unwrap();
    let n = list.len();
    let picks: Vec<Value> = [n / 6, n / 2, 5 * n / 6]
        .iter()
        .map(|&k| list[k].clone())
        .collect();
    solve(scene_with(v.clone(), json!({ key.as_str(): picks })))
}

/// The plan a student draws: at their μ (and μ_v for an acceleration
/// plan), with the pencil's `jitter`, or a mistake.
fn drawn(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    mu: f64,
    mu_v: f64,
    variant: Variant,
) -> Option<Plan> {
    let setup = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let drive = mechplan::analytic::Drive {
        q: s.q,
        rate: s.rate,
        rate2: s.rate2,
    };
    let d = Drafting {
        mu_v: Some(if kind == PlanKind::Velocity { mu } else { mu_v }),
        mu_a: Some(mu),
        delta: 0.5,
        variant,
        ..Drafting::default()
    };
    let vel = build_plans(
        &setup,
        &s.config,
        drive,
        mechplan::analytic::Order::Velocity,
        d,
    )
    .ok()?
    .velocity;
    if kind == PlanKind::Velocity {
        return Some(vel);
    }
    build_acceleration(&setup, &s.config, drive, &vel, d).ok()
}

/// What a student hands in from their plan `p`: every named point, every
/// segment the construction measures (between named or construction
/// points), and the values of the named points and the links' rates,
/// each measured with up to δ of noise.
fn items_of(
    p: &Plan,
    reference: &Plan,
    an: &Analysis,
    noise: &mut impl FnMut() -> f64,
) -> Vec<Item> {
    let mut out = Vec::new();
    for &pt in &an.points {
        let Some(i) = reference.of_point[pt] else {
            continue;
        };
        if i == 0 {
            continue;
        }
        let key = reference.points[i].key.clone();
        let Some(j) = resolve(p, &key) else { continue };
        // (No points: an answer of segments and values is judged against
        // the true plan; one that draws points, step by step, in
        // tests/check_catalogue.rs.)
        let value = (p.points[j].at.hypot() + noise()).max(0.0) * p.mu;
        let sym = if p.kind == PlanKind::Velocity {
            "v"
        } else {
            "a"
        };
        let name = an.mech.point_name(pt);
        out.push(Item {
            pointer: format!("/values/{sym}_{name}"),
            key: format!("{sym}_{name}"),
            given: Given::Value {
                quantity: mechplan::check::answer::Quantity::Point(name.to_string()),
                value,
            },
            rounding: 0.0,
        });
    }
    for q in &reference.measured {
        let (a, b) = (&reference.points[q.from], &reference.points[q.to]);
        let (Some(ia), Some(ib)) = (resolve(p, &a.key), resolve(p, &b.key)) else {
            continue;
        };
        let mm = ((p.points[ib].at - p.points[ia].at).hypot() + noise()).max(0.0);
        let key = format!("{} {}", a.key, b.key);
        // A segment measured for two rates is given once: an answer gives
        // each thing once (a second is refused as given twice). The noise
        // is drawn all the same, so the catalogue's draws stay as they were.
        if out.iter().any(|it| it.key == key) {
            continue;
        }
        out.push(Item {
            pointer: format!("/segments/{key}"),
            key: key.clone(),
            given: Given::Segment {
                from: key,
                to: String::new(),
                mm,
            },
            rounding: 0.0,
        });
    }
    for (l, r) in p.rates.iter().enumerate() {
        let (Some((w, _)), Some(_)) = (r, reference.rates[l]) else {
            continue;
        };
        if reference.rate_len[l] == 0.0 {
            continue;
        }
        // The rate from the relative segment measured with noise.
        let w = w * (1.0 + noise() / (w.abs() * reference.rate_len[l] / p.mu).max(1.0));
        let id = an.mech.link_id(l);
        let sym = if p.kind == PlanKind::Velocity {
            "omega"
        } else {
            "eps"
        };
        out.push(Item {
            pointer: format!("/values/{sym}{id}"),
            key: format!("{sym}{id}"),
            given: Given::Value {
                quantity: mechplan::check::answer::Quantity::Rate(id.to_string()),
                value: w,
            },
            rounding: 0.0,
        });
    }
    out
}

/// The scenes of the catalogue: every fixture, and the six-link with its
/// centre of mass S2 drawn 0.01 mm off the rod AB (a near-collinear point
/// whose similar triangle is a needle).
fn catalogue_scenes() -> Vec<(String, Value)> {
    let mut out: Vec<(String, Value)> = FIXTURES
        .iter()
        .map(|n| (n.to_string(), fixture(n)))
        .collect();
    let mut v = fixture("six_link_fig2_10");
    let a = v["points"]["A"].clone();
    let b = v["points"]["B"].clone();
    let (ax, ay, bx, by) = (
        a[0].as_f64().unwrap(),
        a[1].as_f64().unwrap(),
        b[0].as_f64().unwrap(),
        b[1].as_f64().unwrap(),
    );
    let l = ((bx - ax).powi(2) + (by - ay).powi(2)).sqrt();
    let (nx, ny) = (-(by - ay) / l, (bx - ax) / l);
    // S2 at the middle of AB as drawn, 1e-5 m to its side, and its lengths
    // from that drawing.
    let (sx, sy) = (0.5 * (ax + bx) + 1e-5 * nx, 0.5 * (ay + by) + 1e-5 * ny);
    v["points"]["S2"] = json!([sx, sy]);
    let lengths = v["lengths"].as_object_mut().unwrap();
    let ab = lengths["A-B"].as_f64().unwrap();
    let off = 1e-5 * ab / l;
    let as2 = ((0.5 * ab).powi(2) + off * off).sqrt();
    lengths.insert("A-S2".into(), json!(as2));
    lengths.insert("B-S2".into(), json!(as2));
    out.push(("six_link_S2_off_the_rod".into(), v));
    out
}

/// The mistake kinds of the catalogue.
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

/// Words of the diagnosis that name each mistake.
fn named(m: Mistake, d: &str) -> bool {
    let words: &[&str] = match m {
        Mistake::CoriolisReversed => &["Coriolis acceleration is turned the wrong way"],
        Mistake::CoriolisForgotten => &["Coriolis acceleration is forgotten"],
        Mistake::CoriolisFactorOne => &["taken as ω·v_rel"],
        Mistake::NormalFromCentre => &["from the centre"],
        Mistake::NormalForgotten => &["ω²·l are forgotten", "ω²·l is forgotten"],
        Mistake::MirroredFigure => &["mirrored"],
        Mistake::WrongPerpendicular => &["perpendicular is drawn to the wrong link"],
        Mistake::TangentialParallel => &["parallel to"],
        Mistake::WrongLink => &["wrong link"],
        Mistake::Epsilon1Forgotten => &["ε1·l is forgotten"],
        Mistake::Epsilon1Added => &["added although ε1 = 0"],
        Mistake::OmegaWrongLink => &["ω of the crank"],
        Mistake::OmegaWrongSense => &["against the sense of ω1"],
        Mistake::Slip => &["slip in one length"],
        Mistake::NeighbourLink => &["neighbouring link"],
        Mistake::SlideAcross => &["along the wrong line"],
        Mistake::PointAtNeighbour => &["at a neighbouring point"],
    };
    words.iter().any(|w| d.contains(w))
}

/// A seed of its own for every case (scene, position, plan, scale, the
/// answer drawn), so that a case drawn alone (`CHECK_ONLY`, `CHECK_WHAT`)
/// is the same answer, and a change of tolerances that makes another
/// case visible or not changes no other case's noise (`CHECK_SALT`
/// draws another set).
fn rng_for(case: &str) -> rand::rngs::StdRng {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let salt = std::env::var("CHECK_SALT").unwrap_or_default();
    for b in case.bytes().chain(salt.bytes()) {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    rand::rngs::StdRng::seed_from_u64(h)
}

/// An answer to a check: the items of plan `p` (noise from `rng`), at
/// position `position` (its number: the scenes of [`positions`] list their
/// input values, numbered from 1).
fn answer(kind: PlanKind, mu: f64, mu_v: f64, position: usize, items: Vec<Item>) -> Answer {
    Answer {
        plan: kind,
        position: mechplan::check::position::StatedPosition::new(position),
        mu,
        delta: 0.5,
        items,
        mu_v: (kind == PlanKind::Acceleration).then_some(mu_v),
        stated: Vec::new(),
    }
}

/// The catalogue (see the module's comment). Prints the counts and the
/// misses; docs/check.md records them.
#[test]
fn catalogue_of_honest_and_mistaken_answers() {
    let (mut honest, mut honest_rejected, mut honest_unjudged) = (0, 0, 0);
    let (mut wrong, mut accepted, mut unjudged_only, mut recognised) = (0, 0, 0, 0);
    let mut borderline = 0;
    let mut failures = Vec::new();
    let mut misses: std::collections::BTreeMap<String, usize> = Default::default();
    let only = std::env::var("CHECK_ONLY").ok();
    let only_what = std::env::var("CHECK_WHAT").ok();
    for (name, v) in catalogue_scenes() {
        if only.as_ref().is_some_and(|o| *o != name) {
            continue;
        }
        let (an, solved) = positions(&name, &v);
        for (k, s) in solved.iter().enumerate() {
            let plans = s.plans.as_ref().unwrap();
            for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
                let standard = if kind == PlanKind::Velocity {
                    plans.velocity.mu
                } else {
                    plans.acceleration.as_ref().unwrap().mu
                };
                // The standard scale, and one twice as coarse (a smaller
                // plan, wider tolerances); an acceleration plan drawn on a
                // velocity plan at a coarser scale too.
                for (mu, mu_v) in [
                    (standard, plans.velocity.mu),
                    (2.0 * standard, 2.0 * plans.velocity.mu),
                ] {
                    let Some(reference) = drawn(&an, s, kind, mu, mu_v, Variant::default()) else {
                        continue;
                    };
                    // Honest answers.
                    for seed in 0..4u64 {
                        let mut rng = rng_for(&format!("{name} {k} {kind:?} {mu} honest {seed}"));
                        let Some(p) = drawn(
                            &an,
                            s,
                            kind,
                            mu,
                            mu_v,
                            Variant {
                                jitter: Some(rng.random()),
                                ..Variant::default()
                            },
                        ) else {
                            continue;
                        };
                        let mut noise = || rng.random_range(-0.5..=0.5);
                        let items = items_of(&p, &reference, &an, &mut noise);
                        let r = check(&an, &solved, &answer(kind, mu, mu_v, k + 1, items)).unwrap();
                        honest += 1;
                        if r.wrong() > 0 {
                            honest_rejected += 1;
                            let w = r
                                .verdicts
                                .iter()
                                .find(|v| v.judgement == Judgement::Wrong)
                                .unwrap();
                            failures.push(format!(
                                "{name} position {} {kind:?} μ = {mu} seed {seed}: honest answer rejected: {} given {} expected {} tolerance {}",
                                k + 1, w.what, w.given, w.expected, w.tolerance
                            ));
                        } else if r.unjudged() > 0 {
                            honest_unjudged += 1;
                            if std::env::var_os("CHECK_DEBUG").is_some() {
                                for v in &r.verdicts {
                                    if let Judgement::CannotJudge(w) = &v.judgement {
                                        eprintln!("UNJUDGED {name} {k} {kind:?} {}: {w}", v.what);
                                    }
                                }
                            }
                        }
                    }
                    // Mistaken answers: each kind at each of its elements
                    // and everywhere, and slips.
                    let mut variants: Vec<(String, Option<Mistake>, Variant)> = Vec::new();
                    for m in MISTAKES {
                        let count = drawn(
                            &an,
                            s,
                            kind,
                            mu,
                            mu_v,
                            Variant {
                                mistake: Some(m),
                                at: Some(usize::MAX),
                                on: Some(kind),
                                ..Variant::default()
                            },
                        );
                        let n = count.map_or(0, |p| p.decisions);
                        let mut ats: Vec<Option<usize>> = if n > 0 { vec![None] } else { vec![] };
                        if n > 1 {
                            ats.extend((0..n).map(Some));
                        }
                        for at in ats {
                            variants.push((
                                format!("{m:?} at {at:?}"),
                                Some(m),
                                Variant {
                                    mistake: Some(m),
                                    at,
                                    on: Some(kind),
                                    ..Variant::default()
                                },
                            ));
                        }
                    }
                    let slips = drawn(
                        &an,
                        s,
                        kind,
                        mu,
                        mu_v,
                        Variant {
                            mistake: Some(Mistake::Slip),
                            at: Some(usize::MAX),
                            on: Some(kind),
                            ..Variant::default()
                        },
                    )
                    .map_or(0, |p| p.decisions);
                    for at in 0..slips {
                        let factor = [1.3, 0.6, 10.0][at % 3];
                        variants.push((
                            format!("Slip ×{factor} at {at}"),
                            Some(Mistake::Slip),
                            Variant {
                                mistake: Some(Mistake::Slip),
                                at: Some(at),
                                on: Some(kind),
                                factor,
                                ..Variant::default()
                            },
                        ));
                    }
                    for (what, m, variant) in variants {
                        if only_what.as_ref().is_some_and(|o| *o != what) {
                            continue;
                        }
                        let mut rng = rng_for(&format!("{name} {k} {kind:?} {mu} {what}"));
                        let Some(bad) = drawn(&an, s, kind, mu, mu_v, variant) else {
                            continue;
                        };
                        if bad.mistake_step.is_none() {
                            continue;
                        }
                        let Some(p) = drawn(
                            &an,
                            s,
                            kind,
                            mu,
                            mu_v,
                            Variant {
                                jitter: Some(rng.random()),
                                ..variant
                            },
                        ) else {
                            continue;
                        };
                        let mut none = || 0.0;
                        let exact = items_of(&bad, &reference, &an, &mut none);
                        // Whether the mistake can be seen at all, in the
                        // judge's own measure: the exact mistaken table
                        // (no pencil noise) judged by its own steps. Some
                        // item beyond twice its tolerance: certainly seen
                        // (the pencil's noise, within the tolerance,
                        // cannot carry it back); all within it: the table
                        // draws what an honest hand may draw; between:
                        // borderline, counted apart.
                        let r_exact =
                            check(&an, &solved, &answer(kind, mu, mu_v, k + 1, exact.clone()))
                                .unwrap();
                        let over = r_exact
                            .verdicts
                            .iter()
                            .map(|v| v.difference / v.tolerance.max(1e-300))
                            .fold(0.0, f64::max);
                        if over <= 1.0 {
                            continue;
                        }
                        if over <= 2.0 {
                            borderline += 1;
                            continue;
                        }
                        if std::env::var_os("CHECK_DEBUG").is_some() {
                            for v in &r_exact.verdicts {
                                if v.difference > 2.0 * v.tolerance {
                                    eprintln!(
                                        "VISIBLE {name} {k} {kind:?} {what}: {} {} vs {} (tolerance {})",
                                        v.what, v.given, v.expected, v.tolerance
                                    );
                                }
                            }
                        }
                        let mut noise = || rng.random_range(-0.5..=0.5);
                        let items = items_of(&p, &reference, &an, &mut noise);
                        let r = check(&an, &solved, &answer(kind, mu, mu_v, k + 1, items)).unwrap();
                        wrong += 1;
                        if r.status() == 0 {
                            if std::env::var_os("CHECK_DEBUG").is_some() {
                                eprintln!("ACCEPTED {name} {k} {kind:?} {what}");
                                for v in &r.verdicts {
                                    eprintln!(
                                        "   {} {:?} given {} exp {} tol {}",
                                        v.what, v.judgement, v.given, v.expected, v.tolerance
                                    );
                                }
                                eprintln!("   second: {:?}", r.second_opinion);
                                if let Some(st) = &r.steps {
                                    for s in &st.steps {
                                        eprintln!(
                                            "   step {:?} {} off {} tol {} {:?} pred {:?} given {:?}",
                                            s.step.0,
                                            s.point,
                                            s.off,
                                            s.tolerance,
                                            s.judgement,
                                            s.predicted,
                                            s.given
                                        );
                                    }
                                }
                            }
                            accepted += 1;
                            failures.push(format!(
                                "{name} position {} {kind:?} μ = {mu}: a wrong answer ({what}) accepted",
                                k + 1
                            ));
                            continue;
                        }
                        if r.wrong() == 0 {
                            unjudged_only += 1;
                            continue;
                        }
                        let d = r
                            .diagnosis
                            .as_ref()
                            .and_then(|d| d.mistake.clone())
                            .unwrap_or_default();
                        // A slip in the first vector laid off, the rest
                        // consistent with it, is the plan drawn at another
                        // scale.
                        let rescaled = m == Some(Mistake::Slip)
                            && what.ends_with(" at 0")
                            && d.starts_with("The plan is drawn at μ");
                        if m.is_some_and(|m| named(m, &d)) || rescaled {
                            recognised += 1;
                        } else {
                            let kind_name = what.split(' ').next().unwrap().to_string();
                            if std::env::var_os("CHECK_DEBUG").is_some() {
                                eprintln!(
                                    "MISS {name} {k} {kind:?} {what}: {d} / {:?}",
                                    r.diagnosis.as_ref().map(|d| d.alternatives.clone())
                                );
                            }
                            *misses.entry(format!("{kind_name} ({kind:?})")).or_default() += 1;
                        }
                    }
                }
            }
        }
    }
    let diagnosed = wrong - accepted - unjudged_only;
    eprintln!(
        "honest answers: {honest}, rejected {honest_rejected}, with items that cannot be judged {honest_unjudged}"
    );
    eprintln!(
        "wrong answers: {wrong}, accepted {accepted}, only \"cannot be judged\" {unjudged_only}, rejected {diagnosed}, the mistake named {recognised} ({:.1} %)",
        100.0 * recognised as f64 / diagnosed.max(1) as f64
    );
    eprintln!("misses by mistake: {misses:?}");
    eprintln!("mistakes between once and twice their tolerance (not counted): {borderline}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        honest >= 400 && wrong >= 800,
        "a catalogue too small: {honest}, {wrong}"
    );
    assert!(
        recognised * 100 >= 85 * diagnosed,
        "the mistake named for only {recognised} of {diagnosed} rejected answers"
    );
}

/// The μ of a student's velocity plan counts for the normal points of the
/// acceleration plan: an acceleration plan drawn on a velocity plan twice
/// as coarse passes when the answer says so; the ω the student states
/// count with their own rounding instead, whatever the velocity plan's μ.
#[test]
fn the_velocity_plans_scale_widens_the_normal_points() {
    let v = fixture("six_link_fig2_10");
    let (an, solved) = positions("six_link_fig2_10", &v);
    let s = &solved[1];
    let plans = s.plans.as_ref().unwrap();
    let (mu, mu_v) = (
        plans.acceleration.as_ref().unwrap().mu,
        4.0 * plans.velocity.mu,
    );
    let reference = drawn(&an, s, PlanKind::Acceleration, mu, mu_v, Variant::default()).unwrap();
    let standard = drawn(
        &an,
        s,
        PlanKind::Acceleration,
        mu,
        plans.velocity.mu,
        Variant::default(),
    )
    .unwrap();
    let n2 = resolve(&reference, "n_2").unwrap();
    assert!(
        reference.points[n2].err > standard.points[n2].err,
        "n2: {} at μ_v = {mu_v}, {} at {}",
        reference.points[n2].err,
        standard.points[n2].err,
        plans.velocity.mu
    );
    let omega2 = plans.velocity.rates[an.mech.scene.link_index("2").unwrap()]
        .unwrap()
        .0;
    let at = [reference.points[n2].at.x, reference.points[n2].at.y];
    let tolerance = |velocity: serde_json::Value| {
        let text = json!({
            "plan": "acceleration", "position": 2, "mu": mu,
            "velocity": velocity,
            "points": { "n2": at }
        });
        let ans = mechplan::check::answer::from_json(&text.to_string()).unwrap();
        let r = check(&an, &solved, &ans).unwrap();
        assert_eq!(
            r.wrong(),
            0,
            "{}",
            mechplan::presentation::verdict::to_text(&r)
        );
        r.verdicts[0].tolerance
    };
    // Judged from the pole (the crank's point a not drawn): the step's
    // tolerance carries the velocity plan's error in ω2.
    let coarse = tolerance(json!({ "mu": mu_v }));
    let fine = tolerance(json!({ "mu": plans.velocity.mu }));
    assert!(
        coarse > fine,
        "{coarse} at μ_v = {mu_v}, {fine} at the standard"
    );
    // ω2 stated: its rounding, not the velocity plan's scale.
    let stated = tolerance(json!({ "mu": mu_v, "values": { "omega2": omega2 } }));
    let stated_fine = tolerance(json!({ "mu": plans.velocity.mu, "values": { "omega2": omega2 } }));
    assert!(
        stated < coarse && (stated - stated_fine).abs() < 1e-12,
        "{stated} {stated_fine} {coarse}"
    );
}

/// Values: "-3.40 cw" contradicts itself and is refused; "CW", "Ccw" are
/// read in any case; a quantity of the other plan (a_B in a velocity
/// answer, ω in an acceleration answer) is refused, not read as another.
#[test]
fn values_signs_cases_and_plans() {
    let (an, solved) = positions("six_link_fig2_10", &fixture("six_link_fig2_10"));
    let refused = [
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "omega2": "-3.40 cw" } }),
            "both a sign and a sense",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "omega2": "+3.40 ccw" } }),
            "both a sign and a sense",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "a_B": 3.4 } }),
            "belongs to the acceleration plan",
        ),
        (
            json!({ "plan": "acceleration", "mu": 0.1, "values": { "omega2": 3.4 } }),
            "belongs to the velocity plan",
        ),
        (
            json!({ "plan": "acceleration", "mu": 0.1, "values": { "v_B": 3.4 } }),
            "belongs to the velocity plan",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "eps2": 3.4 } }),
            "belongs to the acceleration plan",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "velocity": { "mu": 0.01 }, "values": { "v_B": 3.4 } }),
            "/velocity",
        ),
        (
            json!({ "plan": "velocity", "mu": 0.01, "values": { "omega2": "fast cw" } }),
            "cannot read",
        ),
    ];
    for (text, expect) in refused {
        let e = mechplan::check::answer::from_json(&text.to_string())
            .map(|_| String::new())
            .unwrap_or_else(|e| e.to_string());
        assert!(e.contains(expect), "{text}: {e}");
    }
    let w2 = solved[0].plans.as_ref().unwrap().velocity.rates
        [an.mech.scene.link_index("2").unwrap()]
    .unwrap()
    .0;
    let sense = if w2 < 0.0 { "CW" } else { "Ccw" };
    for written in [format!("{:.6} {sense}", w2.abs()), format!("{w2:.6}")] {
        let text = json!({ "plan": "velocity", "mu": 0.01, "values": { "omega2": written } });
        let ans = mechplan::check::answer::from_json(&text.to_string()).unwrap();
        let Given::Value { value, .. } = ans.items[0].given else {
            unreachable!()
        };
        assert!((value - w2).abs() < 1e-5, "{written}: {value} vs {w2}");
        assert_eq!(check(&an, &solved, &ans).unwrap().wrong(), 0);
    }
    // The opposite sense is wrong, not read as the right one.
    let opposite = if w2 < 0.0 { "ccw" } else { "cw" };
    let text = json!({ "plan": "velocity", "mu": 0.01, "values": { "omega2": format!("{:.6} {opposite}", w2.abs()) } });
    let ans = mechplan::check::answer::from_json(&text.to_string()).unwrap();
    assert_eq!(check(&an, &solved, &ans).unwrap().wrong(), 1);
}

/// μ applied in the wrong units: values off by 1000 are diagnosed so.
#[test]
fn scale_in_the_wrong_units_is_diagnosed() {
    let (an, solved) = positions("six_link_fig2_10", &fixture("six_link_fig2_10"));
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
    // One mistake, counted once: the values are each other's consistent
    // readings at the scale in the wrong units (the scale is the item
    // judged wrong).
    assert!(
        r.wrong() >= 1,
        "{}",
        mechplan::presentation::verdict::to_text(&r)
    );
    let d = r.diagnosis.unwrap().mistake.unwrap();
    assert!(d.contains("wrong units"), "{d}");
}

/// An Inkscape-style SVG answer (text labels next to points, path
/// segments, group transforms) is read and checked like the JSON.
#[test]
fn inkscape_svg_answer_is_read_and_checked() {
    let (an, solved) = positions("six_link_fig2_10", &fixture("six_link_fig2_10"));
    let plan = &solved[0].plans.as_ref().unwrap().velocity;
    // The student's drawing: pole at (60, 120) mm on an A4 page, drawn
    // inside a translated and scaled group as Inkscape writes layers.
    let mut body = String::new();
    let pole = (30.0, 60.0); // in the group's units (2 units = 1 mm)
    let mut labels = vec![("p_v".to_string(), 0.0, 0.0)];
    for k in ["a", "b", "c", "d", "s2"] {
        let i = resolve(plan, k).unwrap();
        labels.push((k.to_string(), plan.points[i].at.x, plan.points[i].at.y));
    }
    for (k, x, y) in &labels {
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
    assert_eq!(
        r.wrong(),
        0,
        "{}",
        mechplan::presentation::verdict::to_text(&r)
    );
}

/// Bad answers get clear messages naming the field.
#[test]
fn bad_answers_are_refused_with_the_field_named() {
    let (an, solved) = positions("six_link_fig2_10", &fixture("six_link_fig2_10"));
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

/// Two mistakes students combine (the Coriolis acceleration turned the
/// wrong way, or forgotten, and the normal components laid off from the
/// centre) are named together where each moves the answer visibly and no
/// single mistake explains it.
#[test]
fn two_mistakes_together_are_named() {
    let mut tried = 0;
    for name in [
        "shaper_fig2_11",
        "rrp_rotating_guide_002",
        "compressor_fig2_12",
    ] {
        let v = fixture(name);
        let (an, solved) = positions(name, &v);
        for (k, s) in solved.iter().enumerate() {
            let plans = s.plans.as_ref().unwrap();
            let (mu, mu_v) = (plans.acceleration.as_ref().unwrap().mu, plans.velocity.mu);
            let reference =
                drawn(&an, s, PlanKind::Acceleration, mu, mu_v, Variant::default()).unwrap();
            for first in [Mistake::CoriolisReversed, Mistake::CoriolisForgotten] {
                let make = |mistake: Mistake, also: Option<Mistake>| {
                    let p = drawn(
                        &an,
                        s,
                        PlanKind::Acceleration,
                        mu,
                        mu_v,
                        Variant {
                            mistake: Some(mistake),
                            also,
                            on: Some(PlanKind::Acceleration),
                            ..Variant::default()
                        },
                    )?;
                    let mut none = || 0.0;
                    Some(items_of(&p, &reference, &an, &mut none))
                };
                let (Some(pair), Some(one), Some(other)) = (
                    make(first, Some(Mistake::NormalFromCentre)),
                    make(first, None),
                    make(Mistake::NormalFromCentre, None),
                ) else {
                    continue;
                };
                // Each mistake must show beyond the other one's tolerance.
                let r1 = check(
                    &an,
                    &solved,
                    &answer(PlanKind::Acceleration, mu, mu_v, k + 1, one),
                )
                .unwrap();
                let r2 = check(
                    &an,
                    &solved,
                    &answer(PlanKind::Acceleration, mu, mu_v, k + 1, other),
                )
                .unwrap();
                let r = check(
                    &an,
                    &solved,
                    &answer(PlanKind::Acceleration, mu, mu_v, k + 1, pair),
                )
                .unwrap();
                let single = |d: &Option<mechplan::check::Diagnosis>| {
                    d.as_ref()
                        .and_then(|d| d.mistake.clone())
                        .is_some_and(|m| !m.contains("Two mistakes"))
                };
                if r1.wrong() == 0 || r2.wrong() == 0 || r.wrong() == 0 || single(&r.diagnosis) {
                    continue;
                }
                tried += 1;
                let d = r
                    .diagnosis
                    .as_ref()
                    .and_then(|d| d.mistake.clone())
                    .unwrap_or_else(|| mechplan::presentation::verdict::to_text(&r));
                assert!(
                    d.contains("Two mistakes")
                        && d.contains("Coriolis")
                        && d.contains("from the centre"),
                    "{name} position {} {first:?}: {d}",
                    k + 1
                );
            }
        }
    }
    assert!(tried > 0, "no position where both mistakes show");
}
