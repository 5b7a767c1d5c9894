//! Each step's tolerance against the construction a student actually
//! draws (issue 37; docs/check.md, "Each step's tolerance, by Monte
//! Carlo").
//!
//! A student's honest plans are simulated on paper from the method
//! (`tolerance::hand`, `tolerance::mechanisms`; nothing of mechplan's
//! construction kernel draws them): every point laid off ends within δ of
//! its place, every line is drawn shifted by up to δ, every compass set
//! within δ of its radius, every segment measured within δ; each point
//! handed in is read off the sheet within δ and its coordinates typed
//! exactly, to 0.1 mm or to 1 mm (every point, or only the named ones, or
//! those but the points where two lines meet, which the judge then
//! places itself); an acceleration plan is drawn with the ω and sliding
//! velocities the student read off their own velocity plan, the ω stated
//! to three significant digits (the judge takes the digits written) or
//! not stated (the judge takes its own velocity plan's ω and v_rel). Half
//! the draws have every error uniform (in a disc of radius δ, or in
//! [−δ, δ]), half at its extremes (every point's error δ along one
//! direction of the draw, either way; every scalar ±δ): the draws where
//! the errors add up to the worst case. On real positions of the
//! four-bar, the six-link (and the six-link with S2 off its rod, the
//! coupler's triangle with 160°, 165° and 170° at S2: s2 by two arcs
//! meeting at 20°, 15° and 10°, on either side of AB), the crank with a
//! rotating guide and the shaper, at three positions each, at the
//! standard scale and at twice it, each drawing is handed
//! to the kernel's replay (`construction::replay`, as the grader does) and
//! each point judged at its step:
//!
//! - coverage: every honest point within its step's tolerance (misfit
//!   ≤ 1) in every draw — and within the tolerance of the route it was
//!   drawn by (the figure the judge draws, or the relative vector from
//!   the point the student took);
//! - tightness: in each kind of step the largest deviation reaches at
//!   least 70 % of that route's tolerance (the model is not loose).
//!
//! Printed per kind of step and typing: draws (points judged), the worst
//! misfit, the worst deviation over its route's tolerance (`TOLERANCE_DRAWS`
//! sets the draws per scene, position, scale and typing: 1500).

mod student;
mod tolerance;

use kurbo::Vec2;
use mechplan::analytic::Order;
use mechplan::construction::{
    Drafting, Drawing, Judged, Plan, PlanKind, PointId, build_plans, replay,
};
use mechplan::{Analysis, Solved};
use std::collections::BTreeMap;
use student::rigid::Model;
use student::scenes::{Case, six_link_s2_off_the_rod, three_positions};
use tolerance::DELTA;
use tolerance::hand::{Hand, Handed, Handing, Kind, Route, Sheet, three_digits};
use tolerance::mechanisms as mech;
use tolerance::scenes::{Ctx, How, Read, Values};

/// The typings of coordinates: exact, to 0.1 mm, to 1 mm.
const TYPINGS: [f64; 3] = [0.0, 0.1, 1.0];

/// The least share of a step's tolerance its largest simulated
/// deviation must reach.
const TIGHT: f64 = 0.7;

type VelocityPlan = fn(&Ctx, &mut Sheet, How) -> Read;
type AccelerationPlan = fn(&Ctx, &mut Sheet, How, &Values);

struct Scene {
    case: Case,
    velocity: VelocityPlan,
    acceleration: AccelerationPlan,
}

fn fixture(name: &str) -> Case {
    let path = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let v = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    three_positions(name, &v)
}

/// The six-link with S2 moved to the right of A→B (named so).
fn right_of_ab(mut case: Case) -> Case {
    case.name.push_str("_right");
    case
}

fn scenes() -> Vec<Scene> {
    let scene = |case, velocity, acceleration| Scene {
        case,
        velocity,
        acceleration,
    };
    let six: (VelocityPlan, AccelerationPlan) = (mech::six_link_v, mech::six_link_a);
    vec![
        scene(fixture("four_bar"), mech::four_bar_v, mech::four_bar_a),
        scene(fixture("six_link_fig2_10"), six.0, six.1),
        scene(six_link_s2_off_the_rod(160.0, 1.0), six.0, six.1),
        scene(
            right_of_ab(six_link_s2_off_the_rod(165.0, -1.0)),
            six.0,
            six.1,
        ),
        scene(six_link_s2_off_the_rod(170.0, 1.0), six.0, six.1),
        scene(
            right_of_ab(six_link_s2_off_the_rod(170.0, -1.0)),
            six.0,
            six.1,
        ),
        scene(
            fixture("rrp_rotating_guide_002"),
            mech::rotating_guide_v,
            mech::rotating_guide_a,
        ),
        scene(fixture("shaper_fig2_11"), mech::shaper_v, mech::shaper_a),
    ]
}

/// The worst of one kind of step at one typing.
#[derive(Default)]
struct Stat {
    draws: usize,
    misfit: f64,
    own: f64,
    worst: String,
}

/// Coverage failures, and the statistics by kind and typing.
#[derive(Default)]
struct Tally {
    stats: BTreeMap<(Kind, usize), Stat>,
    failures: Vec<String>,
}

/// The judge's replay of the points handed in (typed with `rounding`),
/// at scale `mu`; an acceleration plan on the velocity plan `vel`.
fn judge(
    an: &Analysis,
    s: &Solved,
    mu: f64,
    handed: &[Handed],
    rounding: f64,
    vel: Option<&Plan>,
) -> Plan {
    let drawing = Drawing {
        points: handed
            .iter()
            .map(|h| (h.id, 0, h.typed, rounding))
            .collect(),
        triads: Vec::new(),
        circles: Vec::new(),
    };
    let kind = if vel.is_some() {
        PlanKind::Acceleration
    } else {
        PlanKind::Velocity
    };
    let d = Drafting {
        mu_v: Some(vel.map_or(mu, |v| v.mu)),
        mu_a: Some(mu),
        delta: DELTA,
        ..Drafting::default()
    };
    replay(&an.setup(), &s.config, s.drives, (kind, vel), d, drawing)
        .expect("the honest drawing replays")
}

/// The deviation of a handed-in point over the tolerance of the route it
/// was drawn by: the lines for a point where two lines meet; the figure
/// on the points the student took, or the relative vector from the point
/// they took (found by its place), among the judge's right routes (of two
/// at that place, the one the judge reckons the wider: the figure by two
/// arcs, which the judge also lists as the division it may be); else the
/// step's own construction.
fn own_ratio(plan: &Plan, j: &Judged, h: &Handed, what: &str) -> (f64, f64) {
    if h.kind == Kind::Lines {
        assert!(
            !j.lines.is_empty(),
            "a point where two lines meet is judged by them"
        );
        let (off, tol) = j.apart(j.given);
        return (off / tol, tol);
    }
    let at = |id: Option<PointId>| {
        id.map_or(Vec2::ZERO, |id| {
            plan.points
                .iter()
                .find(|p| p.id == id)
                .expect("a plan point")
                .at
        })
    };
    let routes = match h.route {
        None if h.kind == Kind::Relation => return (j.misfit(), j.nearest().1),
        None => return ((j.given - j.predicted).hypot() / j.tol, j.tol),
        Some(Route::Relation(place, without)) => [place, without],
        Some(Route::Figure(a, b, ratio)) => [at(a) + (at(b) - at(a)).rotate_scale(ratio); 2],
    };
    let route = routes[0];
    let found = std::iter::once((j.predicted, j.tol))
        .chain(j.others.iter().copied())
        .filter(|r| {
            routes
                .iter()
                .any(|&q| (r.0 - q).hypot() <= 1e-6 * (1.0 + q.hypot()))
        })
        .max_by(|a, b| a.1.total_cmp(&b.1));
    match found {
        Some((place, tol)) => ((j.given - place).hypot() / tol, tol),
        // The judge reads no rate whose sense the plan does not show (its
        // relative segment within its error of the link's line): no
        // relative vector then; the point is judged by the figures.
        None if h.kind == Kind::Relation => (j.misfit(), j.nearest().1),
        None => panic!(
            "{what}: the route at {route:?} is none of the judge's: {:?} {:?}",
            (j.predicted, j.tol),
            j.others
        ),
    }
}

/// Judge every point handed in, into the tally.
fn tally(t: &mut Tally, plan: &Plan, handed: &[Handed], (q, what): (usize, &str)) {
    for h in handed {
        let j = plan
            .judged
            .iter()
            .find(|j| j.id == h.id && j.nth == 0)
            .unwrap_or_else(|| panic!("{what}: {:?} handed in but not judged", h.id));
        let (misfit, (own, tol)) = (j.misfit(), own_ratio(plan, j, h, what));
        let key = plan.points[j.point].key.clone();
        let line = format!(
            "{what} {key} ({:?}): misfit {misfit:.4}, its route {own:.4} of {tol:.3} mm (the step's own {:.3} mm)",
            h.kind, j.tol
        );
        if misfit > 1.0 + 1e-9 || own > 1.0 + 1e-9 {
            t.failures.push(line.clone());
        }
        let s = t.stats.entry((h.kind, q)).or_default();
        s.draws += 1;
        s.misfit = s.misfit.max(misfit);
        if own > s.own {
            s.own = own;
            s.worst = line;
        }
    }
}

/// The ω an acceleration plan is drawn with: the student computes with
/// what they read (at the corners, a value anywhere its written digits
/// allow); the judge takes the digits written (`stated`: each link's,
/// and the links that turn with it), else its own velocity plan's.
/// Also the rates to set in the judge's velocity plan.
fn values(
    read: &Read,
    stated: bool,
    hand: &mut Hand,
    vel: &Plan,
    m: &Model,
) -> (Values, Vec<(usize, f64, f64)>) {
    let (mut student, mut judge, mut set) = (Vec::new(), Vec::new(), Vec::new());
    for &(l, w) in &read.omega {
        let (ws, rounding) = three_digits(w);
        let computed = if stated && hand.corner {
            ws + hand.unit() * rounding * (1.0 - 1e-9)
        } else {
            w
        };
        let mut with = vec![l];
        for p in &m.pairs {
            if p.guide == l && p.slider != m.frame {
                with.push(p.slider);
            }
            if p.slider == l && p.guide != m.frame {
                with.push(p.guide);
            }
        }
        for k in with {
            student.push((k, computed));
            if stated {
                judge.push((k, ws));
                set.push((k, ws, rounding));
            } else {
                judge.push((k, vel.rates[k].expect("a rate").0));
            }
        }
    }
    let slide = read.slide.clone();
    (
        Values {
            student,
            judge,
            slide,
        },
        set,
    )
}

/// Many draws of both plans of one scene at one position, scale and
/// typing.
fn draws(
    t: &mut Tally,
    sc: &Scene,
    (pos, s): (usize, &Solved),
    (scale, q): (f64, usize),
    hand: &mut Hand,
    n: usize,
) {
    let an = &sc.case.an;
    let m = Model::new(&sc.case.json, an, s);
    let ctx = Ctx { an, m: m.clone() };
    let standard = build_plans(
        &an.setup(),
        &s.config,
        s.drives,
        Order::Acceleration,
        Drafting::default(),
    )
    .unwrap();
    let (mu_v, mu_a) = (
        standard.velocity.mu * scale,
        standard.acceleration.unwrap().mu * scale,
    );
    let d = Drafting {
        mu_v: Some(mu_v),
        delta: DELTA,
        ..Drafting::default()
    };
    let vel_true = build_plans(&an.setup(), &s.config, s.drives, Order::Velocity, d)
        .unwrap()
        .velocity;
    for k in 0..n {
        hand.start(k % 2 == 1);
        let how = if hand.chance(0.3) {
            How::Relation
        } else {
            How::Figure
        };
        let handing = [Handing::All, Handing::Named, Handing::NoMeetings][k / 2 % 3];
        let stated = hand.chance(0.5);
        let corner = hand.corner;
        let what = |plan: &str| {
            format!(
                "{} pos {pos} ×{} typed {} {plan} {how:?}{}{}{}",
                sc.case.name,
                1.0 / scale,
                TYPINGS[q],
                match handing {
                    Handing::All => " all points",
                    Handing::Named => " named points",
                    Handing::NoMeetings => " no meetings",
                },
                if stated { " ω stated" } else { "" },
                if corner { " corners" } else { "" },
            )
        };
        let mut sv = Sheet {
            mu: mu_v,
            q: TYPINGS[q],
            hand: &mut *hand,
            handed: Vec::new(),
            handing,
        };
        let read = (sc.velocity)(&ctx, &mut sv, how);
        let (handed, rounding) = (std::mem::take(&mut sv.handed), sv.rounding());
        let plan = judge(an, s, mu_v, &handed, rounding, None);
        tally(t, &plan, &handed, (q, &what("velocity")));
        let (v, set) = values(&read, stated, hand, &vel_true, &m);
        let mut sa = Sheet {
            mu: mu_a,
            q: TYPINGS[q],
            hand: &mut *hand,
            handed: Vec::new(),
            handing,
        };
        (sc.acceleration)(&ctx, &mut sa, how, &v);
        let mut handed = std::mem::take(&mut sa.handed);
        if !stated {
            for h in &mut handed {
                h.kind = match h.kind {
                    Kind::Normal => Kind::NormalFromPlan,
                    Kind::Coriolis => Kind::CoriolisFromPlan,
                    k => k,
                };
            }
        }
        let mut vel = vel_true.clone();
        for (l, w, r) in set {
            vel.rates[l] = Some((w, r));
            vel.rate_sense[l] = true;
        }
        let plan = judge(an, s, mu_a, &handed, rounding, Some(&vel));
        tally(t, &plan, &handed, (q, &what("acceleration")));
    }
}

#[test]
fn each_steps_tolerance_covers_the_construction_drawn_and_is_tight() {
    let n: usize = std::env::var("TOLERANCE_DRAWS")
        .ok()
        .and_then(|x| x.parse().ok())
        .unwrap_or(1500);
    let mut t = Tally::default();
    let mut hand = Hand::new(37);
    for sc in scenes() {
        for (pos, s) in sc.case.solved.iter().enumerate() {
            for scale in [1.0, 0.5] {
                for q in 0..TYPINGS.len() {
                    draws(&mut t, &sc, (pos, s), (scale, q), &mut hand, n);
                }
            }
        }
    }
    println!(
        "{:<42} {:>7} {:>8} {:>8} {:>8}",
        "step", "typed", "draws", "misfit", "reaches"
    );
    let mut by_kind: BTreeMap<Kind, (usize, f64, f64)> = BTreeMap::new();
    for (&(kind, q), s) in &t.stats {
        let typed = if TYPINGS[q] == 0.0 {
            "exact".to_string()
        } else {
            format!("{} mm", TYPINGS[q])
        };
        println!(
            "{:<42} {:>7} {:>8} {:>8.3} {:>8.3}",
            kind.name(),
            typed,
            s.draws,
            s.misfit,
            s.own
        );
        let k = by_kind.entry(kind).or_default();
        *k = (k.0 + s.draws, k.1.max(s.misfit), k.2.max(s.own));
    }
    for (kind, (draws, misfit, own)) in &by_kind {
        println!(
            "{:<42} {:>7} {:>8} {:>8.3} {:>8.3}",
            kind.name(),
            "all",
            draws,
            misfit,
            own
        );
    }
    for ((kind, q), s) in &t.stats {
        println!("worst of {kind:?} typed {}: {}", TYPINGS[*q], s.worst);
    }
    let shown: Vec<&String> = t.failures.iter().take(20).collect();
    assert!(
        t.failures.is_empty(),
        "{} honest points off their step's tolerance: {shown:#?}",
        t.failures.len()
    );
    for (kind, (_, _, own)) in &by_kind {
        assert!(
            *own >= TIGHT,
            "{kind:?}: the largest deviation reaches only {own:.3} of its tolerance"
        );
    }
}
