//! The catalogue of hand-drawn answers, judged step by step from the
//! student's own points (docs/check.md, "The catalogue").
//!
//! Every fixture (class III, near-collinear points, extensions, cylinders,
//! several inputs) and the six-link with S2 0.01 mm off its rod, at three
//! positions, both plans:
//! - honest answers: the plan drawn with the pencil off by up to δ at
//!   every operation and every point read with up to δ more, with only the
//!   named points or with the construction points too: none rejected, at
//!   most 3 % with an item that cannot be judged (at the standard scale);
//! - wrong answers: every typical mistake at each decision where it can be
//!   made and everywhere, and a slip in each laid-off length, drawn with
//!   the same noise: none accepted, and the mistake named at the step
//!   where it enters for at least 95 % of the rejected ones. A mistake
//!   is in the catalogue where it is certainly seen: drawn exactly, some
//!   point of it lies more than 2δ from, and beyond twice its step's
//!   tolerance of, where the right construction puts it from the
//!   mistaken drawing's own points (within the tolerance it draws what
//!   an honest hand may draw; between once and twice it, the pencil may
//!   carry it back: those are counted apart).
//!
//! Which step a mistake enters at is found here from the two exact
//! drawings (the first step where the mistaken one draws something else);
//! whether a mistake can be seen at all, from the right construction
//! replayed on the exact mistaken drawing (how far each drawn point lies
//! from where its step puts it).

mod common;
use common::*;
use mechplan::check::answer::{Answer, Given, Item, Quantity, Stated, StatedQuantity};
use mechplan::check::{Judgement, check};
use mechplan::construction::{
    Drafting, Drawing, Mistake, Op, Plan, PlanKind, PointId, Setup, Variant, build_acceleration,
    build_plans, replay,
};
use mechplan::{Analysis, Solved};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use serde_json::{Value, json};
use std::collections::BTreeMap;

/// The mistakes of the catalogue.
const MISTAKES: [Mistake; 16] = [
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

/// Words of a diagnosis that name each mistake.
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

/// A seed of its own for every case, so that a case can be run alone
/// (`CATALOGUE_ONLY=scene`, `CATALOGUE_WHAT=…`) and give the same answer.
fn rng_for(case: &str) -> StdRng {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let salt = std::env::var("CATALOGUE_SALT").unwrap_or_default();
    for b in case.bytes().chain(salt.bytes()) {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    StdRng::seed_from_u64(h)
}

/// Every fixture and the six-link with S2 a hair off its rod, each with
/// three positions (a sixth, a half and five sixths of its sweep or of its
/// own positions).
fn scenes() -> Vec<(String, Analysis, Vec<Solved>)> {
    let mut names: Vec<String> =
        std::fs::read_dir(format!("{}/fixtures", env!("CARGO_MANIFEST_DIR")))
            .unwrap()
            .filter_map(|e| {
                let p = e.unwrap().path();
                (p.extension().is_some_and(|x| x == "json"))
                    .then(|| p.file_stem().unwrap().to_string_lossy().into_owned())
            })
            .collect();
    names.sort();
    let mut out = Vec::new();
    let mut add = |name: String, v: Value| {
        let (an, solved) = if FIXTURES.contains(&name.as_str()) {
            let sw = sweep(&name, &v);
            let (key, list) = sw.as_object().unwrap().iter().next().unwrap();
            let list = list.as_array().unwrap();
            let n = list.len();
            let picks: Vec<Value> = [n / 6, n / 2, 5 * n / 6]
                .iter()
                .map(|&k| list[k].clone())
                .collect();
            solve(scene_with(v.clone(), json!({ key.as_str(): picks })))
        } else {
            let (an, solved) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
            let n = solved.len();
            let picks = if n >= 3 {
                [n / 6, n / 2, 5 * n / 6]
                    .iter()
                    .map(|&k| solved[k].clone())
                    .collect()
            } else {
                solved
            };
            (an, picks)
        };
        out.push((name, an, solved));
    };
    for name in names {
        let v = fixture(&name);
        add(name, v);
    }
    let mut v = fixture("six_link_fig2_10");
    let p = |k: &str| {
        let a = &v["points"][k];
        (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
    };
    let ((ax, ay), (bx, by)) = (p("A"), p("B"));
    let l = ((bx - ax).powi(2) + (by - ay).powi(2)).sqrt();
    let (nx, ny) = (-(by - ay) / l, (bx - ax) / l);
    let (sx, sy) = (0.5 * (ax + bx) + 1e-5 * nx, 0.5 * (ay + by) + 1e-5 * ny);
    v["points"]["S2"] = json!([sx, sy]);
    let lengths = v["lengths"].as_object_mut().unwrap();
    let ab = lengths["A-B"].as_f64().unwrap();
    let off = 1e-5 * ab / l;
    let as2 = ((0.5 * ab).powi(2) + off * off).sqrt();
    lengths.insert("A-S2".into(), json!(as2));
    lengths.insert("B-S2".into(), json!(as2));
    add("six_link_S2_off_the_rod".into(), v);
    out
}

fn setup(an: &Analysis) -> Setup<'_> {
    Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    }
}

/// The plan a student draws at their μ (and μ_v for an acceleration
/// plan), with `variant` (a mistake, the pencil's noise).
fn drawn(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    mus: (f64, f64),
    variant: Variant,
) -> Option<Plan> {
    drawn_with_velocity(an, s, kind, mus, variant).map(|x| x.0)
}

/// [`drawn`], and the ω the student measured on their velocity plan
/// (written with three significant digits, as a student writes them).
fn drawn_with_velocity(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    (mu, mu_v): (f64, f64),
    variant: Variant,
) -> Option<(Plan, Vec<(String, f64)>)> {
    let st = setup(an);
    let d = Drafting {
        mu_v: Some(if kind == PlanKind::Velocity { mu } else { mu_v }),
        mu_a: Some(mu),
        delta: 0.5,
        variant,
        ..Drafting::default()
    };
    let order = mechplan::analytic::Order::Velocity;
    let vel = build_plans(&st, &s.config, s.drives, order, d)
        .ok()?
        .velocity;
    let omegas = vel
        .rates
        .iter()
        .enumerate()
        .filter(|(l, _)| vel.rate_len[*l] > 0.0)
        .filter_map(|(l, r)| {
            let w = (*r)?.0;
            if w == 0.0 {
                return Some((an.mech.link_id(l).to_string(), 0.0));
            }
            let digits = 10f64.powi(2 - w.abs().log10().floor() as i32);
            Some((
                an.mech.link_id(l).to_string(),
                (w * digits).round() / digits,
            ))
        })
        .collect();
    if kind == PlanKind::Velocity {
        return Some((vel, omegas));
    }
    let acc = build_acceleration(&st, &s.config, s.drives, &vel, d).ok()?;
    Some((acc, omegas))
}

/// The points a student hands in from plan `p` (named as the right plan
/// `reference` names them): the named points, and with `construction` the
/// construction points too (n, k, σ …), each read with up to δ of noise.
fn points_of(
    p: &Plan,
    reference: &Plan,
    construction: bool,
    mut rng: Option<&mut StdRng>,
) -> Vec<(String, [f64; 2])> {
    let mut out = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for (i, q) in reference.points.iter().enumerate() {
        if i == 0 || q.key.is_empty() || !seen.insert(q.key.clone()) {
            continue;
        }
        let is_named = matches!(q.id, PointId::Named(_));
        if !is_named && !construction {
            continue;
        }
        // The same point of the student's plan (the same id, the same
        // occurrence).
        let nth = reference.points[..i]
            .iter()
            .filter(|x| x.id == q.id)
            .count();
        let Some(at) = p
            .points
            .iter()
            .filter(|x| x.id == q.id)
            .nth(nth)
            .map(|x| x.at)
        else {
            continue;
        };
        let (dx, dy) = match rng.as_mut() {
            Some(rng) => loop {
                let (x, y): (f64, f64) =
                    (rng.random_range(-0.5..=0.5), rng.random_range(-0.5..=0.5));
                if x * x + y * y <= 0.25 {
                    break (x, y);
                }
            },
            None => (0.0, 0.0),
        };
        out.push((q.key.clone(), [at.x + dx, at.y + dy]));
    }
    out
}

/// An answer: the points, and each point's value read off them (|p x|·μ).
fn answer(
    kind: PlanKind,
    (mu, mu_v): (f64, f64),
    position: usize,
    points: &[(String, [f64; 2])],
    an: &Analysis,
    reference: &Plan,
    omegas: Vec<(String, f64)>,
) -> Answer {
    let mut items = Vec::new();
    for (key, at) in points {
        items.push(Item {
            pointer: format!("/points/{key}"),
            key: key.clone(),
            given: Given::Point {
                name: key.clone(),
                at: *at,
            },
            rounding: 0.0,
        });
        let Some(i) = reference.points.iter().position(|q| &q.key == key) else {
            continue;
        };
        if let PointId::Named(pt) = reference.points[i].id {
            let sym = if kind == PlanKind::Velocity { "v" } else { "a" };
            let name = an.mech.point_name(pt).to_string();
            items.push(Item {
                pointer: format!("/values/{sym}_{name}"),
                key: format!("{sym}_{name}"),
                given: Given::Value {
                    quantity: Quantity::Point(name),
                    value: at[0].hypot(at[1]) * mu,
                },
                rounding: 0.0,
            });
        }
    }
    Answer {
        plan: kind,
        // The `position`-th of the positions solved (some are a few picked
        // out of a `count` sweep): counted from 1 whatever the scene's
        // numbering, as `"positions_from": 1` reads it.
        position: mechplan::check::position::StatedPosition::numbered(
            position,
            mechplan::scene::Numbering::FROM_1,
        ),
        mu,
        delta: 0.5,
        items,
        mu_v: (kind == PlanKind::Acceleration).then_some(mu_v),
        stated: if kind == PlanKind::Acceleration {
            omegas
                .into_iter()
                .map(|(id, w)| Stated {
                    pointer: format!("/velocity/values/omega{id}"),
                    key: format!("omega{id}"),
                    quantity: StatedQuantity::Omega(id),
                    value: w,
                    // Three significant digits, as written.
                    rounding: if w == 0.0 {
                        5e-4
                    } else {
                        0.5 * 10f64.powi(w.abs().log10().floor() as i32 - 2)
                    },
                })
                .collect()
        } else {
            Vec::new()
        },
    }
}

/// A tenth of the pencil's δ: a mistake that moves a point by less is not
/// where it shows.
const VISIBLE: f64 = 0.05;

/// The first step where plan `b` draws something else than plan `a`
/// (another operation, or a point elsewhere by a tenth of δ).
fn first_difference(a: &Plan, b: &Plan) -> Option<usize> {
    let out = |op: &Op| match op {
        Op::LayOff { to, .. } => Some(*to),
        Op::Intersect { out, .. }
        | Op::Similar { out, .. }
        | Op::Divide { out, .. }
        | Op::Coincide { out, .. } => Some(*out),
        _ => None,
    };
    for (k, (x, y)) in a.steps.iter().zip(&b.steps).enumerate() {
        if std::mem::discriminant(&x.op) != std::mem::discriminant(&y.op) {
            return Some(k);
        }
        if let (Some(i), Some(j)) = (out(&x.op), out(&y.op))
            && (a.points[i].at - b.points[j].at).hypot() > VISIBLE
        {
            return Some(k);
        }
    }
    (a.steps.len() != b.steps.len()).then_some(a.steps.len().min(b.steps.len()))
}

/// How far the exact mistaken drawing's points lie from where the right
/// construction, replayed on its own points, puts them: the largest, and
/// the largest over its step's tolerance.
fn seen(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    (mu, mu_v): (f64, f64),
    points: &[(String, [f64; 2])],
    reference: &Plan,
) -> Option<(f64, f64)> {
    let st = setup(an);
    let mut drawing = Drawing {
        points: Vec::new(),
        triads: reference.triads.clone(),
        circles: Vec::new(),
    };
    for (key, at) in points {
        let i = reference.points.iter().position(|q| &q.key == key)?;
        let id = reference.points[i].id;
        let nth = reference.points[..i].iter().filter(|q| q.id == id).count();
        drawing
            .points
            .push((id, nth, kurbo::Vec2::new(at[0], at[1]), 0.0));
    }
    let d = Drafting {
        mu_v: Some(if kind == PlanKind::Velocity { mu } else { mu_v }),
        mu_a: Some(mu),
        delta: 0.5,
        variant: Variant::default(),
        ..Drafting::default()
    };
    let order = mechplan::analytic::Order::Velocity;
    let plan = if kind == PlanKind::Velocity {
        replay(&st, &s.config, s.drives, (kind, None), d, drawing).ok()?
    } else {
        let vel = build_plans(&st, &s.config, s.drives, order, d)
            .ok()?
            .velocity;
        replay(&st, &s.config, s.drives, (kind, Some(&vel)), d, drawing).ok()?
    };
    // (In the judge's own measure: a point where two lines meet by its
    // distance from each, a point of a link from the right construction
    // that fits it best.)
    Some(plan.judged.iter().fold((0.0, 0.0), |(m, r), j| {
        let (off, tol) = j.apart(j.given);
        (f64::max(m, off), f64::max(r, off / tol))
    }))
}

/// The most honest answers at the standard scale with an item that
/// cannot be judged, and the fewest rejected answers whose mistake is
/// named at its step, in per cent.
const UNDECIDED_PERCENT: usize = 3;
const NAMED_PERCENT: usize = 95;

#[derive(Default)]
struct Counts {
    honest: usize,
    honest_standard: usize,
    rejected: usize,
    unjudged: usize,
    unjudged_standard: usize,
    wrong: usize,
    invisible: usize,
    /// Mistakes seen beyond their step's tolerance but within twice it:
    /// accepted, only "cannot be judged", rejected.
    borderline: [usize; 3],
    accepted: usize,
    unjudged_only: usize,
    named_at_step: usize,
    failures: Vec<String>,
    undecided: BTreeMap<String, usize>,
    misses: BTreeMap<String, usize>,
}

#[test]
fn catalogue_of_honest_and_mistaken_answers_step_by_step() {
    let only = std::env::var("CATALOGUE_ONLY").ok();
    let only_what = std::env::var("CATALOGUE_WHAT").ok();
    let debug = std::env::var_os("CATALOGUE_DEBUG").is_some();
    let mut c = Counts::default();
    for (name, an, solved) in scenes() {
        if only.as_ref().is_some_and(|o| *o != name) {
            continue;
        }
        let all: Vec<Solved> = solved.clone();
        for (k, s) in solved.iter().enumerate() {
            let plans = s.plans.as_ref().unwrap();
            for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
                let standard = match kind {
                    PlanKind::Velocity => plans.velocity.mu,
                    PlanKind::Acceleration => match &plans.acceleration {
                        Some(a) => a.mu,
                        None => continue,
                    },
                };
                for (scale, mus) in [
                    ("standard", (standard, plans.velocity.mu)),
                    ("coarse", (2.0 * standard, 2.0 * plans.velocity.mu)),
                ] {
                    let Some(reference) = drawn(&an, s, kind, mus, Variant::default()) else {
                        continue;
                    };
                    let case = format!("{name} position {} {kind:?} {scale}", k + 1);
                    honest_answers(
                        &mut c,
                        &case,
                        (&an, &all, k, s),
                        kind,
                        mus,
                        &reference,
                        scale,
                        debug,
                    );
                    mistaken_answers(
                        &mut c,
                        &case,
                        (&an, &all, k, s),
                        kind,
                        mus,
                        &reference,
                        only_what.as_deref(),
                        debug,
                    );
                }
            }
        }
    }
    report(&c);
}

#[allow(clippy::too_many_arguments)]
fn honest_answers(
    c: &mut Counts,
    case: &str,
    (an, all, k, s): (&Analysis, &[Solved], usize, &Solved),
    kind: PlanKind,
    mus: (f64, f64),
    reference: &Plan,
    scale: &str,
    debug: bool,
) {
    for seed in 0..4u64 {
        let mut rng = rng_for(&format!("{case} honest {seed}"));
        let jitter = Variant {
            jitter: Some(rng.random()),
            ..Variant::default()
        };
        let Some((p, omegas)) = drawn_with_velocity(an, s, kind, mus, jitter) else {
            continue;
        };
        let points = points_of(&p, reference, seed >= 2, Some(&mut rng));
        let a = answer(kind, mus, k + 1, &points, an, reference, omegas);
        let r = check(an, all, &a).unwrap();
        c.honest += 1;
        c.honest_standard += usize::from(scale == "standard");
        if r.wrong() > 0 {
            c.rejected += 1;
            let w = r
                .verdicts
                .iter()
                .find(|v| v.judgement == Judgement::Wrong)
                .unwrap();
            c.failures.push(format!(
                "{case} seed {seed}: honest answer rejected: {} given {} expected {} tolerance {}",
                w.what, w.given, w.expected, w.tolerance
            ));
        } else if r.unjudged() > 0 {
            c.unjudged += 1;
            c.unjudged_standard += usize::from(scale == "standard");
            for v in &r.verdicts {
                if let Judgement::CannotJudge(why) = &v.judgement {
                    let why = why
                        .split(": ")
                        .nth(1)
                        .unwrap_or(why)
                        .split(" Drawn")
                        .next()
                        .unwrap()
                        .to_string();
                    if scale == "standard" {
                        *c.undecided.entry(format!("{why} ({kind:?})")).or_default() += 1;
                    }
                    if debug {
                        eprintln!(
                            "UNDECIDED {case} seed {seed} {}: {why} [{}]",
                            v.what,
                            match &v.judgement {
                                Judgement::CannotJudge(w) => w.clone(),
                                _ => String::new(),
                            }
                        );
                    }
                    break;
                }
            }
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn mistaken_answers(
    c: &mut Counts,
    case: &str,
    (an, all, k, s): (&Analysis, &[Solved], usize, &Solved),
    kind: PlanKind,
    mus: (f64, f64),
    reference: &Plan,
    only_what: Option<&str>,
    debug: bool,
) {
    let mut variants: Vec<(String, Mistake, Variant)> = Vec::new();
    let on = |m: Mistake, at: Option<usize>| Variant {
        mistake: Some(m),
        at,
        on: Some(kind),
        ..Variant::default()
    };
    for m in MISTAKES {
        let n = drawn(an, s, kind, mus, on(m, Some(usize::MAX))).map_or(0, |p| p.decisions);
        let mut ats: Vec<Option<usize>> = (0..n).map(Some).collect();
        if n > 1 {
            ats.push(None);
        }
        for at in ats {
            variants.push((format!("{m:?} at {at:?}"), m, on(m, at)));
        }
    }
    let slips =
        drawn(an, s, kind, mus, on(Mistake::Slip, Some(usize::MAX))).map_or(0, |p| p.decisions);
    for at in 0..slips {
        let factor = [1.3, 0.6, 10.0][at % 3];
        let v = Variant {
            factor,
            ..on(Mistake::Slip, Some(at))
        };
        variants.push((format!("Slip ×{factor} at {at}"), Mistake::Slip, v));
    }
    for (what, m, variant) in variants {
        if only_what.is_some_and(|o| o != what) {
            continue;
        }
        let Some(bad) = drawn(an, s, kind, mus, variant) else {
            continue;
        };
        let Some(enters) = first_difference(reference, &bad) else {
            continue;
        };
        let mut rng = rng_for(&format!("{case} {what}"));
        let construction = rng.random::<bool>();
        // Whether the mistake can be seen at all: the exact mistaken
        // drawing's points against the right steps from its own points.
        let exact = points_of(&bad, reference, construction, None);
        let Some((off, over)) = seen(an, s, kind, mus, &exact, reference) else {
            continue;
        };
        // Two places less than 2δ apart are the same drawing (each is
        // drawn to δ); a mistake that, drawn exactly, puts every point
        // within its step's tolerance of the right construction from its
        // own points draws what an honest hand may draw: no judge that
        // passes honest answers can see it. Beyond twice that tolerance
        // the pencil's noise (within the tolerance) cannot carry it back:
        // it is certainly seen. Between the two it may or may not be.
        if off <= 1.0 || over <= 1.0 {
            c.invisible += 1;
            continue;
        }
        let borderline = over <= 2.0;
        let jitter = Variant {
            jitter: Some(rng.random()),
            ..variant
        };
        let Some((p, omegas)) = drawn_with_velocity(an, s, kind, mus, jitter) else {
            continue;
        };
        let points = points_of(&p, reference, construction, Some(&mut rng));
        let a = answer(kind, mus, k + 1, &points, an, reference, omegas);
        let r = check(an, all, &a).unwrap();
        if borderline {
            c.borderline[usize::from(r.status() != 0) + usize::from(r.wrong() > 0)] += 1;
            continue;
        }
        c.wrong += 1;
        if r.status() == 0 {
            if debug {
                for st in r.steps.iter().flat_map(|s| &s.steps) {
                    eprintln!(
                        "ACCEPTED step {} {}: off {:.3} mm, tolerance {:.3} mm",
                        st.step.0, st.point, st.off, st.tolerance
                    );
                }
            }
            c.accepted += 1;
            c.failures.push(format!(
                "{case}: a wrong answer ({what}) accepted (seen {off:.3} mm off)"
            ));
            continue;
        }
        if r.wrong() == 0 {
            c.unjudged_only += 1;
            continue;
        }
        let steps = r
            .steps
            .as_ref()
            .expect("an answer with points is judged step by step");
        let first = steps.mistakes.first();
        let sentence = first.and_then(|f| f.mistake.clone()).unwrap_or_default();
        let step = first.map(|f| f.step.0);
        // A slip in the first vector laid off, every later point found
        // from it by directions or by lengths too short to tell, is the
        // plan drawn at another scale: named so, before the plan.
        let rescaled = m == Mistake::Slip
            && what.ends_with(" at 0")
            && sentence.starts_with("The plan is drawn at μ")
            && step == Some(0);
        if (named(m, &sentence) && step == Some(enters + 1)) || rescaled {
            c.named_at_step += 1;
        } else {
            let kind_name = what.split(' ').next().unwrap().to_string();
            if debug {
                eprintln!(
                    "MISS {case} {what}: step {step:?} (enters at {}) {sentence:?} / {:?}",
                    enters + 1,
                    first.map(|f| f.alternatives.clone())
                );
            }
            *c.misses
                .entry(format!("{kind_name} ({kind:?})"))
                .or_default() += 1;
        }
    }
}

fn report(c: &Counts) {
    let diagnosed = c.wrong - c.accepted - c.unjudged_only;
    eprintln!(
        "honest answers: {}, rejected {}, with an item that cannot be judged {} ({} of {} at the standard scale, {:.1} %)",
        c.honest,
        c.rejected,
        c.unjudged,
        c.unjudged_standard,
        c.honest_standard,
        100.0 * c.unjudged_standard as f64 / c.honest_standard.max(1) as f64
    );
    eprintln!(
        "undecided at the standard scale, by reason: {:#?}",
        c.undecided
    );
    eprintln!(
        "mistakes that draw within their steps' tolerances (left out): {}",
        c.invisible
    );
    eprintln!(
        "mistakes between once and twice their step's tolerance: {} (accepted {}, only \"cannot be judged\" {}, rejected {})",
        c.borderline.iter().sum::<usize>(),
        c.borderline[0],
        c.borderline[1],
        c.borderline[2]
    );
    eprintln!(
        "wrong answers: {}, accepted {}, only \"cannot be judged\" {}, rejected {}, the mistake named at its step {} ({:.1} %)",
        c.wrong,
        c.accepted,
        c.unjudged_only,
        diagnosed,
        c.named_at_step,
        100.0 * c.named_at_step as f64 / diagnosed.max(1) as f64
    );
    eprintln!("misses by mistake: {:?}", c.misses);
    assert!(c.failures.is_empty(), "{}", c.failures.join("\n"));
    assert!(
        c.honest >= 400 && c.wrong >= 800,
        "a catalogue too small: {}, {}",
        c.honest,
        c.wrong
    );
    assert!(
        c.unjudged_standard * 100 <= UNDECIDED_PERCENT * c.honest_standard,
        "{} of {} honest answers at the standard scale cannot be judged",
        c.unjudged_standard,
        c.honest_standard
    );
    assert!(
        c.named_at_step * 100 >= NAMED_PERCENT * diagnosed,
        "the mistake named at its step for only {} of {diagnosed} rejected answers",
        c.named_at_step
    );
}

/// One early mistake, every later step drawn from it as the construction
/// says: wrong at the mistake's step (counted once, named), every later
/// step right from the student's own points — where the comparison with
/// the true plan finds several items wrong.
#[test]
fn one_early_mistake_is_carried_forward() {
    let cases = [
        (
            "six_link_fig2_10",
            PlanKind::Acceleration,
            Mistake::NormalFromCentre,
            1,
        ),
        (
            "six_link_fig2_10",
            PlanKind::Velocity,
            Mistake::OmegaWrongSense,
            0,
        ),
        (
            "shaper_fig2_11",
            PlanKind::Acceleration,
            Mistake::CoriolisReversed,
            0,
        ),
        (
            "four_bar",
            PlanKind::Velocity,
            Mistake::WrongPerpendicular,
            0,
        ),
        (
            "class3_004",
            PlanKind::Acceleration,
            Mistake::NormalForgotten,
            0,
        ),
    ];
    let all = scenes();
    for (name, kind, m, at) in cases {
        let (_, an, solved) = all.iter().find(|s| s.0 == name).unwrap();
        let s = &solved[1];
        let plans = s.plans.as_ref().unwrap();
        let mu = match kind {
            PlanKind::Velocity => plans.velocity.mu,
            PlanKind::Acceleration => plans.acceleration.as_ref().unwrap().mu,
        };
        let mus = (mu, plans.velocity.mu);
        let reference = drawn(an, s, kind, mus, Variant::default()).unwrap();
        let variant = Variant {
            mistake: Some(m),
            at: Some(at),
            on: Some(kind),
            ..Variant::default()
        };
        let bad = drawn(an, s, kind, mus, variant).unwrap();
        let enters = first_difference(&reference, &bad).unwrap();
        let mut rng = rng_for(&format!("carried {name} {kind:?}"));
        let jitter = Variant {
            jitter: Some(rng.random()),
            ..variant
        };
        let (p, omegas) = drawn_with_velocity(an, s, kind, mus, jitter).unwrap();
        let points = points_of(&p, &reference, false, Some(&mut rng));
        let r = check(
            an,
            solved,
            &answer(kind, mus, 2, &points, an, &reference, omegas),
        )
        .unwrap();
        let steps = r.steps.as_ref().unwrap();
        let text = mechplan::presentation::verdict::to_text(&r);
        assert_eq!(steps.mistakes.len(), 1, "{name} {kind:?} {m:?}: {text}");
        let found = &steps.mistakes[0];
        assert_eq!(found.step.0, enters + 1, "{name} {kind:?} {m:?}: {text}");
        assert!(named(m, found.mistake.as_deref().unwrap_or("")), "{text}");
        let wrong: Vec<_> = steps
            .steps
            .iter()
            .filter(|v| v.judgement == Judgement::Wrong)
            .collect();
        assert_eq!(wrong.len(), 1, "{name} {kind:?} {m:?}: {text}");
        // Everything after follows from the student's own points; against
        // the true plan, more than the one point is off.
        let second = r.second_opinion.as_ref().unwrap();
        assert!(second.wrong >= 2, "{name} {kind:?} {m:?}: {text}");
        assert!(text.contains("carried forward"), "{text}");
        if std::env::var_os("SHOW_REPORT").is_some() {
            eprintln!("{text}");
        }
    }
}

/// The worked example of docs/check.md: its answer, read from the page,
/// checked by the command gives the report the page prints (every line of
/// it but the elided items, in order).
#[test]
fn the_worked_example_in_the_docs() {
    check_docs_example("### A worked example", "six_link_fig2_10");
}

/// A forgotten a^n_BA is named at the step that should have laid it off,
/// quoting that step (not the next normal component's).
#[test]
fn a_forgotten_normal_quotes_its_own_step() {
    let all = scenes();
    let (_, an, solved) = all.iter().find(|s| s.0 == "six_link_fig2_10").unwrap();
    let s = &solved[1];
    let plans = s.plans.as_ref().unwrap();
    let kind = PlanKind::Acceleration;
    let mus = (plans.acceleration.as_ref().unwrap().mu, plans.velocity.mu);
    let reference = drawn(an, s, kind, mus, Variant::default()).unwrap();
    // Decision 0 is the crank's normal, 1 the coupler's a^n_BA.
    let variant = Variant {
        mistake: Some(Mistake::NormalForgotten),
        at: Some(1),
        on: Some(kind),
        ..Variant::default()
    };
    let (bad, omegas) = drawn_with_velocity(an, s, kind, mus, variant).unwrap();
    let points = points_of(&bad, &reference, false, None);
    let r = check(
        an,
        solved,
        &answer(kind, mus, 2, &points, an, &reference, omegas),
    )
    .unwrap();
    let found = &r.steps.as_ref().unwrap().mistakes[0];
    let text = mechplan::presentation::verdict::to_text(&r);
    assert!(
        found
            .mistake
            .as_deref()
            .is_some_and(|m| m.contains("forgotten")),
        "{text}"
    );
    assert!(
        found.step.1.contains("a^n_BA") && !found.step.1.contains("a^n_BO2"),
        "{}: {text}",
        found.step.1
    );
    assert_eq!(
        found.step.0,
        first_difference(&reference, &bad).unwrap() + 1
    );
}

/// The grade counts every item: points drawn right with a value read off
/// them wrong is wrong (as the exit status says); a pole drawn away from
/// the origin is refused, not silently moved.
#[test]
fn the_grade_counts_every_item_and_the_pole_is_the_origin() {
    let all = scenes();
    let (_, an, solved) = all.iter().find(|s| s.0 == "six_link_fig2_10").unwrap();
    let s = &solved[1];
    let plans = s.plans.as_ref().unwrap();
    let kind = PlanKind::Velocity;
    let mus = (plans.velocity.mu, plans.velocity.mu);
    let reference = drawn(an, s, kind, mus, Variant::default()).unwrap();
    let points = points_of(&reference, &reference, false, None);
    let mut a = answer(kind, mus, 2, &points, an, &reference, Vec::new());
    let right = check(an, solved, &a).unwrap();
    assert_ne!(right.status(), 1, "the exact answer is not wrong");
    // v_B read 1.5 times too long.
    let vb = a.items.iter_mut().find(|i| i.key == "v_B").unwrap();
    if let Given::Value { value, .. } = &mut vb.given {
        *value *= 1.5;
    }
    let r = check(an, solved, &a).unwrap();
    let text = mechplan::presentation::verdict::to_text(&r);
    assert_eq!(r.status(), 1, "{text}");
    assert!(
        text.contains("Grade: WRONG") && !text.contains("Grade: RIGHT"),
        "{text}"
    );
    let json = mechplan::presentation::verdict::to_json(&r);
    assert_eq!(json["grade"], "wrong");
    // The pole at [5, 5]: refused, naming its field.
    let mut a = answer(kind, mus, 2, &points, an, &reference, Vec::new());
    a.items.push(Item {
        pointer: "/points/p_v".into(),
        key: "p_v".into(),
        given: Given::Point {
            name: "p_v".into(),
            at: [5.0, 5.0],
        },
        rounding: 0.0,
    });
    let err = check(an, solved, &a).unwrap_err().to_string();
    assert!(
        err.contains("/points/p_v") && err.contains("origin"),
        "{err}"
    );
}
