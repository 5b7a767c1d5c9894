//! The force plan of a class III group (issue 42): the three-leash group
//! of paper 004 with masses and a load on its base
//! (fixtures/dynamics/class3_004.json) against the links' equilibrium
//! (`kinetostatics::newton_euler`); every link's equilibrium closes with
//! the plan's reactions; two parallel leash axes (Assur's point of that
//! pair at infinity) take another pair; the plan is drawn on the force
//! sheet and checked by `check`.

use kurbo::{Point, Vec2};
use mechplan::check::forces::{ForceAnswer, check};
use mechplan::check::position::StatedPosition;
use mechplan::kinetostatics::force_plan::{self, Force, ForcePlan, ForcePlans, ForceStep, Part};
use mechplan::kinetostatics::loads::{self, Load};
use mechplan::kinetostatics::newton_euler::{self, Unknowns};
use mechplan::model::structure::Joint;
use mechplan::scene::Scene;
use mechplan::words::construction::Lang;
use mechplan::words::forces::force_name;
use mechplan::{Analysis, Solved};
use std::process::Command;

fn scene_path() -> String {
    format!(
        "{}/fixtures/dynamics/class3_004.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn fixture() -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(scene_path()).unwrap()).unwrap()
}

fn solved_of(v: &serde_json::Value) -> (Analysis, Vec<Solved>) {
    let an = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let s = an.run().unwrap();
    (an, s)
}

/// The class III group's index and plan.
fn triad_plan(an: &Analysis, fp: &ForcePlans) -> (usize, ForcePlan) {
    let g = an
        .structure
        .groups
        .iter()
        .position(|g| g.class() == 3)
        .expect("a class III group");
    let plan = fp.plans.iter().find(|p| p.group == Some(g)).unwrap();
    (g, plan.clone())
}

/// The links' equilibrium's value of reaction `f` (whole): the force of
/// `from` on `to` in a revolute pair.
fn analytic(an: &Analysis, ne: &Unknowns, f: Force) -> Option<Vec2> {
    let Force::Reaction {
        from,
        to,
        joint: Joint::R(p),
        part: Part::Whole,
    } = f
    else {
        return None;
    };
    an.mech.revolutes.iter().enumerate().find_map(|(k, rv)| {
        (rv.point == p && (rv.a, rv.b) == (from, to))
            .then(|| ne.revolute[k])
            .or_else(|| (rv.point == p && (rv.a, rv.b) == (to, from)).then(|| -ne.revolute[k]))
    })
}

/// Every reaction of the group read off its plan, and the crank's
/// balancing moment, agree with the links' equilibrium to 1e-9 of the
/// position's largest force, far inside the plan's own stated bound
/// ((err_from + err_to + δ)·μ_F for a segment measured).
#[test]
fn class3_plan_agrees_with_the_links_equilibrium() {
    let (an, solved) = solved_of(&fixture());
    let size = an.mech.size;
    let (mut worst, mut measured) = (0.0f64, 0);
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let ne = newton_euler::solve(&an, s, &loads).unwrap();
        let fp = force_plan::solve(&an, s, &loads, 0.5).unwrap();
        let scale = s.dynamics.as_ref().unwrap().force_scale;
        let (_, plan) = triad_plan(&an, &fp);
        for step in &plan.steps {
            let ForceStep::Measure(i) = *step else {
                continue;
            };
            let v = plan.vectors[i];
            let want = analytic(&an, &ne, v.force).expect("a revolute reaction, whole");
            let d = (v.value - want).hypot();
            let bound = (plan.err[v.from] + plan.err[v.to] + plan.delta) * plan.mu;
            assert!(
                d <= bound,
                "position {k}: {:?} off by {d} > {bound}",
                v.force
            );
            worst = worst.max(d / scale);
            measured += 1;
            assert!(d <= 1e-9 * scale, "position {k}: {:?}: {d}", v.force);
        }
        // Six reactions: three outer, three inner.
        assert_eq!(plan.vectors.len() - laid(&plan).len(), 6);
        for (r, p) in ne.revolute.iter().zip(&fp.revolute) {
            let p = p.expect("every pair's reaction from the plans");
            assert!((*r - p).hypot() <= 1e-9 * scale, "{r:?} {p:?}");
        }
        let mb = fp.drives[0].unwrap();
        assert!(
            (mb - ne.drives[0]).abs() / size <= 1e-9 * scale,
            "position {k}: M_b {mb} vs {}",
            ne.drives[0]
        );
        assert!(plan.worst_sin > 0.0 && plan.worst_sin <= 1.0);
    }
    assert_eq!(measured, 6 * solved.len());
    eprintln!(
        "{measured} reactions of the class III plan over {} positions: worst {worst:.1e} of the force scale",
        solved.len()
    );
}

fn laid(plan: &ForcePlan) -> Vec<usize> {
    plan.steps
        .iter()
        .filter_map(|s| match *s {
            ForceStep::LayOff(i) => Some(i),
            _ => None,
        })
        .collect()
}

/// Each moving link's forces and moments vanish with the loads, the
/// plans' reactions and the balancing moment (on the crank).
#[test]
fn every_links_equilibrium_closes_with_the_plans_reactions() {
    let (an, solved) = solved_of(&fixture());
    let m = &an.mech;
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let fp = force_plan::solve(&an, s, &loads, 0.5).unwrap();
        let scale = s.dynamics.as_ref().unwrap().force_scale;
        let n = m.links.len();
        let (mut f, mut mo) = (vec![Vec2::ZERO; n], vec![0.0; n]);
        let mut add = |l: usize, at: Point, v: Vec2, c: f64| {
            f[l] += v;
            mo[l] += at.to_vec2().cross(v) + c;
        };
        for l in &loads {
            match *l {
                Load::Force { link, at, f, .. } => add(link, at, f, 0.0),
                Load::Couple { link, m, .. } => add(link, Point::ORIGIN, Vec2::ZERO, m),
            }
        }
        for (rv, r) in m.revolutes.iter().zip(&fp.revolute) {
            let (r, at) = (r.unwrap(), s.config.point(m, rv.b, rv.point));
            add(rv.b, at, r, 0.0);
            add(rv.a, at, -r, 0.0);
        }
        let crank = m.scene.input_at(0).link();
        add(crank, Point::ORIGIN, Vec2::ZERO, fp.drives[0].unwrap());
        for l in (0..n).filter(|&l| l != m.frame()) {
            assert!(
                f[l].hypot() <= 1e-9 * scale,
                "position {k} link {l}: ΣF = {:?}",
                f[l]
            );
            assert!(
                mo[l].abs() <= 1e-9 * scale * m.size * 10.0,
                "position {k} link {l}: ΣM = {}",
                mo[l]
            );
        }
    }
}

/// The group's polygon closes: the laid-off vectors (components of the
/// outer reactions counted whole once) and the two closing components sum
/// to zero; every inner reaction closes its leash's own polygon.
#[test]
fn the_class3_polygon_closes() {
    let (an, solved) = solved_of(&fixture());
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let fp = force_plan::solve(&an, s, &loads, 0.5).unwrap();
        let (_, plan) = triad_plan(&an, &fp);
        let mut at = 0;
        let mut sum = Vec2::ZERO;
        for i in laid(&plan) {
            assert_eq!(plan.vectors[i].from, at, "head to tail");
            at = plan.vectors[i].to;
            sum += plan.vectors[i].value;
        }
        // The two lines' components: from the end to the meeting point and
        // on back to the start.
        let meet = plan
            .steps
            .iter()
            .find_map(|s| match *s {
                ForceStep::Intersect { out, .. } => Some(out),
                _ => None,
            })
            .unwrap();
        let closing = (plan.points[meet] - plan.points[at]) + (plan.points[0] - plan.points[meet]);
        let total = sum + closing * plan.mu;
        let big = plan
            .vectors
            .iter()
            .map(|v| v.value.hypot())
            .fold(0.0, f64::max);
        assert!(total.hypot() <= 1e-12 * big, "position {k}: {total:?}");
        assert!(
            plan.points.iter().all(|p| p.hypot() <= 150.0),
            "the plan fits its field"
        );
        // ΣM about Assur's point gave the third leash's normal component.
        assert!(plan.steps.iter().any(|s| matches!(
            s,
            ForceStep::Moment {
                about_name: None,
                force: Force::Reaction {
                    part: Part::Normal,
                    ..
                },
                ..
            }
        )));
    }
}

/// Leash 5 turned parallel to leash 4 at the sketch (F above D): Assur's
/// point of that pair is at infinity, so the plan takes a pair with leash
/// 2 and still agrees with the links' equilibrium.
#[test]
fn parallel_leashes_take_another_pair() {
    let mut v = fixture();
    v["points"]["F"] = serde_json::json!([1.0, 1.0]);
    v["points"]["S5"] = serde_json::json!([1.0, 0.5]);
    v["positions"] = serde_json::json!({ "angles": [30, 29.5, 29] });
    v["dynamics"]["forces"][0]["F"] = serde_json::json!([-173.2, -100.0]);
    let (an, solved) = solved_of(&v);
    let leash = |id: &str| {
        (0..an.mech.links.len())
            .find(|&l| an.mech.link_id(l) == id)
            .unwrap()
    };
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let ne = newton_euler::solve(&an, s, &loads).unwrap();
        let fp = force_plan::solve(&an, s, &loads, 0.5).unwrap();
        let scale = s.dynamics.as_ref().unwrap().force_scale;
        for (r, p) in ne.revolute.iter().zip(&fp.revolute) {
            assert!((*r - p.unwrap()).hypot() <= 1e-9 * scale, "{r:?} {p:?}");
        }
        let (_, plan) = triad_plan(&an, &fp);
        let third = plan
            .steps
            .iter()
            .find_map(|s| match s {
                ForceStep::Moment {
                    about_name: None,
                    force: Force::Reaction { to, .. },
                    ..
                } => Some(*to),
                _ => None,
            })
            .unwrap();
        // The third leash (from the moments about S) is 4 or 5: the pair
        // whose axes meet includes leash 2.
        assert_ne!(third, leash("2"), "position {k}");
        assert!(plan.worst_sin > 0.3, "position {k}: {}", plan.worst_sin);
    }
}

/// The answer a careful student reads off the class III plan at
/// μ_F = `mu`: the reactions' segments to 0.1 mm, directions to 0.5°.
fn answer(an: &Analysis, s: &Solved, k: usize, mu: f64) -> ForceAnswer {
    let loads = loads::loads(an, s, k);
    let g = an
        .structure
        .groups
        .iter()
        .position(|g| g.class() == 3)
        .unwrap();
    let which = force_plan::Which::Group(g);
    let fp = force_plan::solve_at(an, s, &loads, 0.5, Some((which, mu))).unwrap();
    let (_, plan) = triad_plan(an, &fp);
    let (mut segments, mut angles) = (Vec::new(), Vec::new());
    for step in &plan.steps {
        if let ForceStep::Measure(i) = *step {
            let v = plan.vectors[i];
            let name = force_name(&an.mech, &loads, v.force, Lang::En);
            let seg = plan.points[v.to] - plan.points[v.from];
            let len = (seg.hypot() * 10.0).round() / 10.0;
            segments.push((format!("/segments/{name}"), name.clone(), len));
            let deg = seg.y.atan2(seg.x).to_degrees().rem_euclid(360.0);
            angles.push((format!("/angles/{name}"), name, (deg * 2.0).round() / 2.0));
        }
    }
    ForceAnswer {
        position: StatedPosition::new(an.numbering.number(k)),
        links: plan
            .links
            .iter()
            .map(|&l| an.mech.link_id(l).to_string())
            .collect(),
        mu,
        delta: 0.5,
        mu_l: None,
        segments,
        angles,
        values: Vec::new(),
    }
}

/// `check` judges an answer read off the class III plan (never "no force
/// plans"): right at every position; its longest segment half as long
/// again wrong.
#[test]
fn check_judges_a_class3_force_answer() {
    let (an, solved) = solved_of(&fixture());
    // Each position at the plan's own standard μ_F (the forces grow
    // tenfold towards the dead point).
    let mu = |k: usize, s: &Solved| {
        let fp = force_plan::solve(&an, s, &loads::loads(&an, s, k), 0.5).unwrap();
        triad_plan(&an, &fp).1.mu
    };
    for (k, s) in solved.iter().enumerate() {
        let ans = answer(&an, s, k, mu(k, s));
        let r = check(&an, &solved, &ans).unwrap();
        let text = mechplan::presentation::verdict::force_to_text(&r);
        assert_eq!(r.wrong(), 0, "position {}: {text}", k + 1);
        assert_eq!(r.verdicts.len(), 12, "{text}");
        // Its longest reaction half as long again.
        let mut wrong = ans.clone();
        let longest = (0..wrong.segments.len())
            .max_by(|&a, &b| wrong.segments[a].2.total_cmp(&wrong.segments[b].2))
            .unwrap();
        wrong.segments[longest].2 *= 1.5;
        assert!(check(&an, &solved, &wrong).unwrap().wrong() >= 1);
    }
    // The command: the answer judged, status 0 (right) or 4 (not all
    // judged), not refused (2).
    let dir = std::env::temp_dir().join(format!("mechplan_class3_check_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let a = answer(&an, &solved[3], 3, mu(3, &solved[3]));
    let seg: serde_json::Map<String, serde_json::Value> = a
        .segments
        .iter()
        .map(|(_, k, v)| (k.clone(), (*v).into()))
        .collect();
    let text = serde_json::json!({ "plan": "force", "position": a.position.number, "links": a.links, "mu": a.mu, "segments": seg });
    let p = dir.join("answer.json");
    std::fs::write(&p, text.to_string()).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["check", &scene_path(), p.to_str().unwrap()])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        matches!(out.status.code(), Some(0 | 4)),
        "{said}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `mechplan draw` writes the force sheet of every position with the
/// class III group's panel: its caption, its polygon and free body.
#[test]
fn draw_writes_the_class3_force_sheets() {
    let dir = std::env::temp_dir().join(format!("mechplan_class3_draw_{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["draw", &scene_path(), "-o", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (an, solved) = solved_of(&fixture());
    for k in 0..solved.len() {
        let n = an.numbering.number(k);
        let svg = std::fs::read_to_string(dir.join(format!("forces_{n}.svg")))
            .unwrap_or_else(|e| panic!("forces_{n}.svg: {e}"));
        assert!(
            svg.contains("class III"),
            "position {n}: no class III panel"
        );
        assert!(svg.contains("-polygon"), "position {n}: no polygon");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Towards the group's dead point (its three leash axes meeting in one
/// point near φ1 = 34.6°: Σ's arm to the third axis vanishes, the
/// reactions and the inertia forces grow without bound) the plan still
/// agrees with the links' equilibrium to 1e-9 of the position's largest
/// force, every reaction within its stated bound; past it the position is
/// refused, never a number.
#[test]
fn towards_the_dead_point_bounded_then_refused() {
    let mut v = fixture();
    v["positions"] = serde_json::json!({ "angles": [33, 34, 34.4, 34.5, 34.52] });
    let (an, solved) = solved_of(&v);
    for (k, s) in solved.iter().enumerate() {
        let loads = loads::loads(&an, s, k);
        let ne = newton_euler::solve(&an, s, &loads).unwrap();
        let fp = force_plan::solve(&an, s, &loads, 0.5).unwrap();
        let scale = s.dynamics.as_ref().unwrap().force_scale;
        let (_, plan) = triad_plan(&an, &fp);
        for step in &plan.steps {
            let ForceStep::Measure(i) = *step else {
                continue;
            };
            let v = plan.vectors[i];
            let d = (v.value - analytic(&an, &ne, v.force).unwrap()).hypot();
            let bound = (plan.err[v.from] + plan.err[v.to] + plan.delta) * plan.mu;
            assert!(d <= bound && d <= 1e-9 * scale, "position {k}: {d}");
        }
    }
    v["positions"] = serde_json::json!({ "angles": [33, 34.5, 34.6] });
    let an = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let e = an.run().unwrap_err().to_string();
    assert!(e.contains("class III"), "{e}");
}
