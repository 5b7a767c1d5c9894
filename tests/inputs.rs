//! Hydraulic cylinders and several inputs: a driving slider on a moving
//! guide (the boom), two cylinders (the arm, W = 2), two cranks (the
//! five-bar, W = 2), and a crank carrying a telescopic slider (a chained
//! input). Both analytic routes and the plans agree over a sweep of each;
//! the rates agree with finite differences of the positions, and the
//! boom's cylinder with a derivation by hand; the features that need one
//! input refuse several clearly.

mod common;
use common::*;
use kurbo::{Point, Vec2};
use mechplan::Analysis;
use mechplan::analytic::constraint::{ConstraintSolver, Settings};
use mechplan::analytic::{Coords, Order};
use mechplan::positions::PositionSolver;
use serde_json::{Value, json};

const NEW: &[&str] = &["boom_cylinder", "arm_two_cylinders", "five_bar_two_cranks"];

/// A crank 1 turning about O carries the guide of a telescopic arm 2 (a
/// manipulator's radial axis): the arm's slide on the crank is the second
/// input, placed on the crank (a chained input, I(0,1) -> I(1,2)).
fn manipulator() -> Value {
    json!({
        "mechplan": 1,
        "title": "Telescopic arm on a turning crank (two inputs)",
        "points": {
            "O": [0.0, 0.0],
            "K": [0.8660254037844387, 0.5],
            "A": [0.4330127018922193, 0.25],
            "T": [1.0392304845413265, 0.6],
            "M": [0.7294228634059948, 0.7330127018922193]
        },
        "links": {
            "0": { "points": ["O"] },
            "1": { "points": ["O", "K"] },
            "2": { "points": ["A", "T", "M"] }
        },
        "sliders": [
            { "slider": "2", "guide": "1", "point": "A", "line": { "through": "O", "along": ["O", "K"] } }
        ],
        "input": [
            { "link": "1", "pivot": "O", "angle": 30, "omega": 0.5, "epsilon": 0.2 },
            { "link": "2", "slider": true, "s": 0, "v": 0.3, "a": -0.1 }
        ],
        "positions": { "values": [[30, 0]] }
    })
}

/// Input values (scene units) sweeping each scene: the boom's stroke in
/// 200 steps; the arm's two cylinders and the five-bar's two cranks along
/// a path on which neither input is a function of the other.
fn sweep_of(name: &str) -> Value {
    match name {
        "boom_cylinder" => {
            json!({ "s": (0..=200).map(|k| -0.15 + 0.5 * k as f64 / 200.0).collect::<Vec<_>>() })
        }
        "arm_two_cylinders" => {
            let t = |k: usize| k as f64 / 120.0;
            json!({ "values": (0..=120).map(|k| vec![
                -0.15 + 0.5 * t(k),
                0.15 - 0.3 * t(k) + 0.05 * (4.0 * std::f64::consts::PI * t(k)).sin(),
            ]).collect::<Vec<_>>() })
        }
        "five_bar_two_cranks" => json!({ "values": (0..=360).map(|k| {
            let k = k as f64;
            vec![60.0 + k, 120.0 - 0.6 * k + 20.0 * (3.0 * k).to_radians().sin()]
        }).collect::<Vec<_>>() }),
        "manipulator" => json!({ "values": (0..=90).map(|k| {
            let k = k as f64;
            vec![30.0 + 4.0 * k, 0.3 * (k / 10.0).sin()]
        }).collect::<Vec<_>>() }),
        _ => unreachable!(),
    }
}

fn scene_of(name: &str) -> Value {
    if name == "manipulator" {
        manipulator()
    } else {
        fixture(name)
    }
}

/// Every input's coordinates (rad, m) of the positions of a sweep.
fn coords(an: &Analysis) -> Vec<Coords> {
    an.input_coords().unwrap()
}

/// Route (a) (and the plans, inside `run`) against route (b) driven here
/// by the test, at every position of each sweep: places relative to the
/// sketch's size, velocities and ω·size relative to their largest at the
/// position, accelerations and ε·size likewise; and the plans' measured
/// values against route (a) the same way. All to 1e-12.
#[test]
fn routes_and_plans_agree_over_every_sweep() {
    for name in NEW.iter().copied().chain(["manipulator"]) {
        let (an, solved) = solve(scene_with(scene_of(name), sweep_of(name)));
        let m = &an.mech;
        let rates = an.input_rates();
        let mut cs = ConstraintSolver::new(m, &an.include, Settings::default());
        let (mut worst_routes, mut worst_plans) = (0.0f64, 0.0f64);
        for (s, q) in solved.iter().zip(coords(&an)) {
            cs.solve_positions_at(q).unwrap();
            let b = cs.solve_rates_of(&rates, Order::Acceleration).unwrap();
            let plans = s.plans.as_ref().unwrap();
            let acc = plans.acceleration.as_ref().unwrap();
            let mut rows = Vec::new();
            for &p in &an.points {
                let l = an.carrier(p);
                let st = s.point(&an, p);
                let (va, aa) = st.rates.unwrap();
                let mb = b[l].unwrap();
                let pb = mb.pose.apply(m.local(l, p));
                assert!(
                    (st.at - pb).hypot() <= 1e-12 * m.size,
                    "{name}: place of {}",
                    m.point_name(p)
                );
                let vp = plans.velocity.value_of(p).unwrap();
                let ap = acc.value_of(p).unwrap();
                rows.push((
                    va,
                    aa,
                    (va - mb.velocity(pb)).hypot(),
                    (aa - mb.acceleration(pb)).hypot(),
                    (vp - va).hypot(),
                    (ap - aa).hypot(),
                ));
            }
            for (l, (x, y)) in s.motion.iter().zip(&b).enumerate() {
                let (Some(x), Some(y)) = (x, y) else { continue };
                let w = Vec2::new(x.omega * m.size, 0.0);
                let e = Vec2::new(x.epsilon * m.size, 0.0);
                let (wp, ep) = (
                    plans.velocity.rates[l].map_or(x.omega, |r| r.0),
                    acc.rates[l].map_or(x.epsilon, |r| r.0),
                );
                rows.push((
                    w,
                    e,
                    (x.omega - y.omega).abs() * m.size,
                    (x.epsilon - y.epsilon).abs() * m.size,
                    (wp - x.omega).abs() * m.size,
                    (ep - x.epsilon).abs() * m.size,
                ));
            }
            let sv = rows.iter().map(|r| r.0.hypot()).fold(1e-300, f64::max);
            let sa = rows.iter().map(|r| r.1.hypot()).fold(1e-300, f64::max);
            for r in &rows {
                let (dv, da, pv, pa) = (r.2 / sv, r.3 / sa, r.4 / sv, r.5 / sa);
                worst_routes = worst_routes.max(dv).max(da);
                worst_plans = worst_plans.max(pv).max(pa);
                assert!(
                    dv <= 1e-12 && da <= 1e-12,
                    "{name} at {:?}: routes v {dv:e}, a {da:e}",
                    &q[..]
                );
                assert!(
                    pv <= 1e-12 && pa <= 1e-12,
                    "{name} at {:?}: plans v {pv:e}, a {pa:e}",
                    &q[..]
                );
            }
            assert!(s.check.as_ref().unwrap().max_rel_diff <= 1e-12, "{name}");
        }
        eprintln!(
            "{name}: {} positions, routes agree to {worst_routes:.1e}, plans to {worst_plans:.1e}",
            solved.len()
        );
    }
}

/// Positions of every point (route (a)'s closed forms) at input
/// coordinates `q`, reached continuously by `ps`.
fn places(an: &Analysis, ps: &mut PositionSolver, q: &[f64]) -> Vec<Point> {
    let c = ps.solve_coords(Coords::new(q)).unwrap();
    an.points
        .iter()
        .map(|&p| c.point(&an.mech, an.carrier(p), p))
        .collect()
}

/// The transfer functions are partial derivatives of the positions by each
/// input (central differences: first at h1, second and mixed at h2); the
/// physical rates are made of them: v = Σ ∂P/∂q_i·q̇_i, a = Σ
/// ∂²P/∂q_i∂q_j·q̇_i·q̇_j + Σ ∂P/∂q_i·q̈_i; and they are the derivatives in
/// time of the positions along the inputs' motion q(t) = q + q̇·t + q̈·t²/2.
#[test]
fn rates_are_derivatives_of_the_positions() {
    for name in NEW.iter().copied().chain(["manipulator"]) {
        let (an, solved) = solve(scene_with(scene_of(name), sweep_of(name)));
        let m = &an.mech;
        let specs: Vec<_> = m.scene.inputs().cloned().collect();
        let w = specs.len();
        let h = |_: usize, k: f64| k;
        let all = coords(&an);
        for (s, q0) in solved.iter().zip(&all).step_by(17) {
            let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
            places(&an, &mut ps, q0);
            let at = |ps: &mut PositionSolver, d: &[(usize, f64)]| {
                let mut q = q0.to_vec();
                for &(i, x) in d {
                    q[i] += x;
                }
                places(&an, ps, &q)
            };
            let p0 = at(&mut ps, &[]);
            for (k, &p) in an.points.iter().enumerate() {
                let st = s.point(&an, p);
                let (v, a) = st.rates.unwrap();
                let (jac, hes): (Vec<Vec2>, Vec<Vec<Vec2>>) = if w == 1 {
                    let (vq, aq) = st.analogue.unwrap();
                    (vec![vq], vec![vec![aq]])
                } else {
                    let pp = s.point_partials(&an, p).unwrap();
                    (pp.first, pp.second.unwrap())
                };
                let scale1 = m
                    .size
                    .max(jac.iter().map(|x| x.hypot()).fold(0.0, f64::max));
                let scale2 = m
                    .size
                    .max(hes.iter().flatten().map(|x| x.hypot()).fold(0.0, f64::max));
                for i in 0..w {
                    let h1 = h(i, 1e-6);
                    let d1 =
                        (at(&mut ps, &[(i, h1)])[k] - at(&mut ps, &[(i, -h1)])[k]) / (2.0 * h1);
                    assert!(
                        (d1 - jac[i]).hypot() <= 1e-8 * scale1,
                        "{name} {}: dP/dq{i} {d1:?} vs {:?}",
                        m.point_name(p),
                        jac[i]
                    );
                    for (j, hij) in hes[i].iter().enumerate() {
                        let (hi, hj) = (h(i, 1e-4), h(j, 1e-4));
                        let f = |ps: &mut PositionSolver, a: f64, b: f64| {
                            at(ps, &[(i, a * hi), (j, b * hj)])[k].to_vec2()
                        };
                        let d2 = if i == j {
                            (f(&mut ps, 0.5, 0.5) - p0[k].to_vec2() * 2.0 + f(&mut ps, -0.5, -0.5))
                                / (hi * hi)
                        } else {
                            (f(&mut ps, 1.0, 1.0) - f(&mut ps, 1.0, -1.0) - f(&mut ps, -1.0, 1.0)
                                + f(&mut ps, -1.0, -1.0))
                                / (4.0 * hi * hj)
                        };
                        assert!(
                            (d2 - *hij).hypot() <= 1e-4 * scale2,
                            "{name} {}: d2P/dq{i}dq{j} {d2:?} vs {hij:?}",
                            m.point_name(p),
                        );
                    }
                }
                // The physical rates from the partial derivatives.
                let d = &s.drives;
                let mut v_sum = Vec2::ZERO;
                let mut a_sum = Vec2::ZERO;
                for i in 0..w {
                    v_sum += jac[i] * d[i].rate;
                    a_sum += jac[i] * d[i].rate2;
                    for j in 0..w {
                        a_sum += hes[i][j] * (d[i].rate * d[j].rate);
                    }
                }
                let sv = scale1 * d.iter().map(|x| x.rate.abs()).sum::<f64>();
                let sa = scale2 * d.iter().map(|x| x.rate * x.rate).sum::<f64>()
                    + scale1 * d.iter().map(|x| x.rate2.abs()).sum::<f64>();
                assert!(
                    (v - v_sum).hypot() <= 1e-12 * sv,
                    "{name}: v of {}",
                    m.point_name(p)
                );
                assert!(
                    (a - a_sum).hypot() <= 1e-11 * sa,
                    "{name}: a of {}",
                    m.point_name(p)
                );
                // In time, along the inputs' motion.
                let dt = 1e-4;
                let along = |ps: &mut PositionSolver, t: f64| {
                    let moved: Vec<(usize, f64)> = (0..w)
                        .map(|i| (i, d[i].rate * t + d[i].rate2 * t * t / 2.0))
                        .collect();
                    at(ps, &moved)[k].to_vec2()
                };
                let (back, fwd) = (along(&mut ps, -dt), along(&mut ps, dt));
                let vt = (fwd - back) / (2.0 * dt);
                let at_ = (fwd - p0[k].to_vec2() * 2.0 + back) / (dt * dt);
                assert!(
                    (vt - v).hypot() <= 1e-7 * sv.max(1e-300),
                    "{name}: dP/dt of {}",
                    m.point_name(p)
                );
                assert!(
                    (at_ - a).hypot() <= 1e-4 * sa.max(1e-300),
                    "{name}: d2P/dt2 of {}",
                    m.point_name(p)
                );
            }
        }
    }
}

/// The boom by hand, from the triangle O C B alone: the boom's pin B at
/// r = OB from O, the cylinder's length CB = L0 + s (L0 the sketch's, s
/// the rod's slide); by the law of cosines r² + ρ² − 2rρ·cos(θ − γ) = L²
/// (C at distance ρ and angle γ from O); differentiated in time, θ̇ =
/// L·L̇/(rρ·sin(θ − γ)) and θ̈ = (L̇² + L·L̈ − rρ·cos(θ − γ)·θ̇²)/(rρ·sin(θ
/// − γ)). The cylinder turns at ω_cyl = u × v_B / L (u the unit vector C
/// → B); the rod's velocity relative to the cylinder is v_rel = L̇·u, and
/// its Coriolis acceleration a^k = 2·ω_cyl × v_rel = 2·ω_cyl·L̇·(k × u).
#[test]
fn the_boom_cylinder_by_hand() {
    let v = fixture("boom_cylinder");
    let get = |n: &str| {
        let p = &v["points"][n];
        Vec2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap())
    };
    let (c, b_sk, k_sk) = (get("C"), get("B"), get("K"));
    let r = v["lengths"]["O-B"].as_f64().unwrap();
    let axis = (k_sk - c).normalize();
    let l0 = (b_sk - c).dot(axis);
    let (ld, ldd) = (
        v["input"]["v"].as_f64().unwrap(),
        v["input"]["a"].as_f64().unwrap(),
    );
    let (rho, gamma) = (c.hypot(), c.atan2());
    // The sketch's branch: B on the side of OC where the sketch has it.
    let branch = (b_sk.atan2() - gamma).sin().signum();
    let (an, solved) = solve(scene_with(v.clone(), sweep_of("boom_cylinder")));
    let m = &an.mech;
    let b = m.scene.point_index("B").unwrap();
    let (boom, cyl) = (
        m.scene.link_index("1").unwrap(),
        m.scene.link_index("2").unwrap(),
    );
    for s in &solved {
        let l = l0 + s.q;
        let cos = (r * r + rho * rho - l * l) / (2.0 * r * rho);
        let theta = gamma + branch * cos.acos();
        let sin = (theta - gamma).sin();
        let td = l * ld / (r * rho * sin);
        let tdd = (ld * ld + l * ldd - r * rho * cos * td * td) / (r * rho * sin);
        let e = Vec2::new(theta.cos(), theta.sin());
        let n = Vec2::new(-e.y, e.x);
        let pb = e * r;
        let vb = n * (r * td);
        let ab = n * (r * tdd) - e * (r * td * td);
        let u = (pb - c).normalize();
        let w_cyl = u.cross(vb) / l;
        let v_rel = u * ld;
        let coriolis = Vec2::new(-u.y, u.x) * (2.0 * w_cyl * ld);
        let st = s.point(&an, b);
        let (vm, am) = st.rates.unwrap();
        let size = 1.0;
        assert!(
            (st.at.to_vec2() - pb).hypot() <= 1e-13 * size,
            "B at s = {}",
            s.q
        );
        assert!((vm - vb).hypot() <= 1e-13 * size, "v_B at s = {}", s.q);
        assert!((am - ab).hypot() <= 1e-13 * size, "a_B at s = {}", s.q);
        assert!((s.motion[boom].unwrap().omega - td).abs() <= 1e-13);
        assert!((s.motion[boom].unwrap().epsilon - tdd).abs() <= 1e-13);
        assert!((s.motion[cyl].unwrap().omega - w_cyl).abs() <= 1e-13);
        let slide = &s.slides(&an)[0];
        assert!(
            (slide.s - s.q).abs() <= 1e-13,
            "the reported slide is the input's"
        );
        // The rod's velocity relative to the cylinder at B: v_rel.
        assert!((u * slide.v - v_rel).hypot() <= 1e-13);
        assert!(
            (slide.coriolis - coriolis).hypot() <= 1e-13,
            "a^k at s = {}",
            s.q
        );
        assert!((slide.a - ldd).abs() <= 1e-13);
        // The acceleration plan lays off the same Coriolis vector (its k).
        let plan = s.plans.as_ref().unwrap().acceleration.as_ref().unwrap();
        let k3 = plan.points.iter().position(|p| p.key == "k_3").unwrap();
        let n2 = plan.points.iter().position(|p| p.key == "n_2").unwrap();
        let k_vec = (plan.points[k3].at - plan.points[n2].at) * plan.mu;
        assert!(
            (k_vec - coriolis).hypot() <= 1e-12,
            "k on the plan at s = {}",
            s.q
        );
    }
}

/// The manipulator by hand: its arm's tip T at the radius R = OT0 + s on
/// the crank's ray at φ has, in polar form, v = Ṙ·e_r + R·φ̇·e_φ and
/// a = (R̈ − R·φ̇²)·e_r + (R·φ̈ + 2·Ṙ·φ̇)·e_φ (the Coriolis term 2·Ṙ·φ̇).
#[test]
fn the_chained_slider_by_hand() {
    let v = manipulator();
    let (an, solved) = solve(scene_with(v.clone(), sweep_of("manipulator")));
    assert_eq!(an.structure.formula(&an.mech), "I(0,1) -> I(1,2)");
    let m = &an.mech;
    let t = m.scene.point_index("T").unwrap();
    let r0 = 1.2;
    let (w, e) = (0.5, 0.2);
    let (rd, rdd) = (0.3, -0.1);
    for s in &solved {
        let (phi, x) = (s.drives[0].q, s.drives[1].q);
        let rr = r0 + x;
        let er = Vec2::new(phi.cos(), phi.sin());
        let ep = Vec2::new(-er.y, er.x);
        let st = s.point(&an, t);
        let (vm, am) = st.rates.unwrap();
        assert!((st.at.to_vec2() - er * rr).hypot() <= 1e-13);
        assert!((vm - (er * rd + ep * (rr * w))).hypot() <= 1e-13);
        let a = er * (rdd - rr * w * w) + ep * (rr * e + 2.0 * rd * w);
        assert!((am - a).hypot() <= 1e-13, "a_T at {:?}", (phi, x));
    }
}

/// Two inputs in the result: `input` a list in the order of the scene,
/// transfer functions by input; one input keeps the object.
#[test]
fn several_inputs_in_the_result_file() {
    let (an, solved) = solve(scene_with(
        fixture("five_bar_two_cranks"),
        json!({ "values": [[90, 45]] }),
    ));
    let doc = mechplan::report::to_json(&an, &solved);
    let p = &doc["positions"][0];
    assert_eq!(doc["structure"]["dof"], 2);
    assert_eq!(doc["structure"]["formula"], "I(0,1) + I(0,4) -> II(2,3)");
    let input = p["input"].as_array().unwrap();
    assert_eq!(input.len(), 2);
    assert!((input[0]["angle"].as_f64().unwrap() - 90.0).abs() < 1e-12);
    assert!((input[1]["angle"].as_f64().unwrap() - 45.0).abs() < 1e-12);
    assert_eq!(input[1]["omega"], -6.0);
    assert_eq!(p["points"]["C"]["v_q"].as_array().unwrap().len(), 2);
    assert_eq!(p["links"]["2"]["phi_qq"].as_array().unwrap().len(), 2);
    let (an1, s1) = solve(scene_with(fixture("boom_cylinder"), json!({ "s": [0.1] })));
    let doc1 = mechplan::report::to_json(&an1, &s1);
    let p1 = &doc1["positions"][0];
    assert!(p1["input"].is_object());
    assert_eq!(p1["input"]["s"], 0.1);
    assert_eq!(doc1["structure"]["formula"], "I(2,3) -> II(1,2-3)");
    assert_eq!(
        doc1["structure"]["groups"][0]["cylinder"],
        json!(["2", "3"])
    );
    let slider = &p1["sliders"][0];
    assert_eq!(slider["guide"], "2");
    assert!(slider["coriolis"].is_array());
}

/// The plans with a cylinder as the lecture's steps: the relative
/// velocity laid off first along the cylinder, then the line ⊥ CB; on the
/// acceleration plan the normal component, the Coriolis acceleration and
/// the given relative acceleration, then the tangential line.
#[test]
fn the_cylinder_in_the_steps() {
    let (an, solved) = solve(scene_with(fixture("boom_cylinder"), json!({ "s": [0.1] })));
    let text = mechplan::report::to_steps(&an, &solved, mechplan::words::construction::Lang::En);
    for want in [
        "v_B = v̳_̳C̳ + v̳_̳B̳3̳B̳2̳ + v̲_̲B̲2̲C̲",
        "From p_v lay off p_vr3 = v_B3B2/μ_v",
        "through r3 a line ⊥ CB2",
        // The boom's point K is not on the cylinder's pair: the Coriolis
        // point is the lecture's k3.
        "n2k3 = a^K_B3B2 = 2·ω2·v_B3B2/μ_a",
        "k3r3 = a^r_B3B2/μ_a",
        "ω3 = ω2: links 3 and 2 form a prismatic pair",
    ] {
        assert!(text.contains(want), "missing {want:?} in\n{text}");
    }
    for lang in [
        mechplan::words::construction::Lang::Uk,
        mechplan::words::construction::Lang::Ru,
    ] {
        let t = mechplan::report::to_steps(&an, &solved, lang);
        assert!(t.contains("a^K_B3B2 = 2·ω2·v_B3B2"), "{t}");
    }
}

/// A student's acceleration plan of the boom checked: right values are
/// right; the same plan drawn without the Coriolis acceleration is wrong,
/// and the mistake named (the rod driven fast, 0.5 m/s, so that the
/// Coriolis acceleration shows beyond the pencil's tolerance).
#[test]
fn a_hand_drawn_boom_plan_is_checked() {
    use mechplan::check::check;
    use mechplan::construction::{Drafting, Mistake, Setup, Variant, build_plans};
    let mut v = fixture("boom_cylinder");
    v["input"]["v"] = json!(0.5);
    v["input"]["a"] = json!(0);
    let (an, solved) = solve(scene_with(v, json!({ "s": [0.2] })));
    let m = &an.mech;
    let s = &solved[0];
    let good = s.plans.as_ref().unwrap();
    let setup = Setup {
        m: &an.mech,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let wrong = build_plans(
        &setup,
        &s.config,
        s.drives,
        Order::Acceleration,
        Drafting {
            mu_v: Some(good.velocity.mu),
            mu_a: Some(good.acceleration.as_ref().unwrap().mu),
            variant: Variant {
                mistake: Some(Mistake::CoriolisForgotten),
                ..Variant::default()
            },
            ..Drafting::default()
        },
    )
    .unwrap();
    // The points drawn, and the values read off them: a table of values
    // alone leaves the directions open, and with the plan's worst-case
    // tolerances it cannot decide here (a Coriolis acceleration ⊥ the
    // cylinder moves b along the line its tangential part draws).
    let answer = |plans: &mechplan::construction::Plans| {
        let a = plans.acceleration.as_ref().unwrap();
        let mut values = serde_json::Map::new();
        let mut points = serde_json::Map::new();
        for n in ["B", "E", "K", "P"] {
            let at = a.points[a.of_point[m.scene.point_index(n).unwrap()].unwrap()].at;
            points.insert(n.to_lowercase(), json!([at.x, at.y]));
            let x = a.value_of(m.scene.point_index(n).unwrap()).unwrap().hypot();
            values.insert(format!("a_{n}"), json!(x));
        }
        // The Coriolis acceleration is ⊥ the cylinder, as its tangential
        // part is: forgetting it leaves b in place and changes ε2.
        let cyl = m.scene.link_index("2").unwrap();
        values.insert("eps2".into(), json!(a.rates[cyl].unwrap().0));
        let text = json!({
            "plan": "acceleration",
            "mu": a.mu,
            "velocity": { "mu": plans.velocity.mu },
            "points": points,
            "values": values
        })
        .to_string();
        mechplan::check::answer::from_json(&text).unwrap()
    };
    let right = check(&an, &solved, &answer(good)).unwrap();
    assert_eq!(
        right.wrong(),
        0,
        "{}",
        mechplan::presentation::verdict::to_text(&right)
    );
    let r = check(&an, &solved, &answer(&wrong)).unwrap();
    assert!(
        r.wrong() > 0,
        "{}",
        mechplan::presentation::verdict::to_text(&r)
    );
    let d = r.diagnosis.unwrap().mistake.unwrap();
    assert!(d.contains("Coriolis acceleration is forgotten"), "{d}");
}

/// What needs one input refuses several with a message naming `/input`:
/// the extreme positions (`count` is refused as bad input), invariants,
/// diagrams, the precision report.
#[test]
fn one_input_features_refuse_several() {
    let study = mechplan::Study::from_json(&fixture("five_bar_two_cranks").to_string()).unwrap();
    let inv = study
        .invariants(Some("3"), 0.01, 5.0, 360)
        .unwrap_err()
        .to_string();
    assert!(
        inv.contains("/input") && inv.contains("several inputs"),
        "{inv}"
    );
    let dia = study.diagram(Some("3"), None, 12).unwrap_err().to_string();
    assert!(
        dia.contains("/input") && dia.contains("several inputs"),
        "{dia}"
    );
    let pre = study
        .precision(&mechplan::precision::Settings::default())
        .unwrap_err()
        .to_string();
    assert!(
        pre.contains("/input") && pre.contains("several inputs"),
        "{pre}"
    );
    // Diagrams of the boom: over the cylinder's stroke, against its slide.
    let boom = mechplan::Study::from_json(&fixture("boom_cylinder").to_string()).unwrap();
    let t = boom.diagram(Some("1"), None, 10).unwrap().to_table();
    assert!(t.contains("over the stroke s3 = -0.15 … 0.35 m"), "{t}");
    let d = mechplan::diagrams::Diagrams::build(
        boom.analysis(),
        boom.analysis().mech.scene.link_index("1").unwrap(),
        50,
        180.0,
    )
    .unwrap();
    let e = d.errors();
    assert!(e.chord_v.0 < 1e-4 && e.trapezoid_s.0 < 1e-4, "{e:?}");
}

// ---- bad input of the new forms, through the binary ----------------------

/// Run `mechplan solve SCENE --format json -o OUT` on a bad scene: exit
/// status 2, no panic, a message starting "mechplan: " that holds every
/// one of `names` (the field's JSON pointer first), and no output file.
fn reject(case: &str, v: &Value, names: &[&str]) -> String {
    let dir = std::env::temp_dir();
    let tag = format!("mechplan-inputs-{case}-{}", std::process::id());
    let (scene, out) = (
        dir.join(format!("{tag}.json")),
        dir.join(format!("{tag}-out.json")),
    );
    std::fs::write(&scene, serde_json::to_string_pretty(v).unwrap()).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("solve")
        .arg(&scene)
        .args(["--format", "json", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    let _ = std::fs::remove_file(&scene);
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "{case}: {stderr}");
    assert_eq!(o.status.code(), Some(2), "{case}: {stderr}");
    assert!(stderr.starts_with("mechplan: "), "{case}: {stderr}");
    for n in names {
        assert!(stderr.contains(n), "{case}: no {n:?} in {stderr}");
    }
    assert!(!out.exists(), "{case}: wrote {}", out.display());
    stderr
}

#[test]
fn a_position_with_the_wrong_number_of_values() {
    let mut v = fixture("arm_two_cylinders");
    v["positions"] = json!({ "values": [[0.1, 0.0], [0.2], [0.1, 0.0, 0.3]] });
    let e = reject(
        "values_count",
        &v,
        &[
            "/positions/values/1",
            "1 value, but the scene has 2 inputs",
            "/positions/values/2",
            "3 values",
        ],
    );
    assert!(!e.contains("/positions/values/0"), "{e}");
    // Not a list of values.
    v["positions"] = json!({ "values": [0.1, 0.2] });
    reject(
        "values_flat",
        &v,
        &["/positions/values/0", "a list of 2 values"],
    );
    // A list of values per position for one input: one value each.
    let mut b = fixture("boom_cylinder");
    b["positions"] = json!({ "values": [[0.1], [0.1, 0.2]] });
    reject(
        "values_one_input",
        &b,
        &["/positions/values/1", "2 values, but the scene has 1 input"],
    );
}

#[test]
fn count_and_angles_with_two_inputs() {
    let mut v = fixture("five_bar_two_cranks");
    v["positions"] = json!({ "count": 12 });
    reject(
        "count_two_inputs",
        &v,
        &[
            "/positions/count",
            "the scene has 2 inputs",
            "give \"values\"",
        ],
    );
    v["positions"] = json!({ "angles": [10, 20] });
    reject(
        "angles_two_inputs",
        &v,
        &["/positions/angles", "the scene has 2 inputs"],
    );
}

#[test]
fn a_slider_input_whose_guide_is_its_own_link() {
    // The cylinder named as the driving slider: it is the guide of its pair.
    let mut v = fixture("boom_cylinder");
    v["input"]["link"] = json!("2");
    reject(
        "input_is_the_guide",
        &v,
        &[
            "/input/link",
            "link \"2\" is the guide of /sliders/0",
            "the link that slides",
        ],
    );
    // A pair whose slider is its own guide.
    let mut w = fixture("boom_cylinder");
    w["sliders"][0]["guide"] = json!("3");
    reject(
        "slides_on_itself",
        &w,
        &["/sliders/0/guide", "cannot slide on itself"],
    );
    // In a list of inputs, the pointer names the input.
    let mut a = fixture("arm_two_cylinders");
    a["input"][1]["link"] = json!("5");
    reject(
        "second_input_is_the_guide",
        &a,
        &["/input/1/link", "is the guide of /sliders/1"],
    );
    // A driving slider that slides in no pair.
    let mut n = fixture("boom_cylinder");
    n["input"]["link"] = json!("1");
    reject(
        "input_slides_nowhere",
        &n,
        &["/input/link", "slides in no prismatic pair"],
    );
}

#[test]
fn mobility_other_than_the_number_of_inputs() {
    // W = 2, one input given.
    let mut v = fixture("five_bar_two_cranks");
    v["input"] = v["input"][0].clone();
    v["positions"] = json!({ "angles": [60] });
    let e = reject("five_bar_one_input", &v, &["/links", "mobility W", "= 2"]);
    assert!(e.contains("one input"), "{e}");
    // W = 2, the arm's first cylinder alone, as a list of one.
    let mut a = fixture("arm_two_cylinders");
    a["input"] = json!([a["input"][0].clone()]);
    a["positions"] = json!({ "values": [[0.1]] });
    reject("arm_one_input", &a, &["/links", "mobility W", "= 2"]);
    // W = 1, two inputs: the boom's cylinder and a crank on the boom.
    let mut b = fixture("boom_cylinder");
    b["input"] = json!([
        b["input"].clone(),
        { "link": "1", "pivot": "O", "angle": 20, "omega": 1 }
    ]);
    b["positions"] = json!({ "values": [[0, 20]] });
    reject(
        "boom_two_inputs",
        &b,
        &["/input", "gives 2 inputs", "mobility W", "= 1", "too many"],
    );
    // One link driven twice.
    let mut d = fixture("five_bar_two_cranks");
    d["input"][1] = d["input"][0].clone();
    reject(
        "driven_twice",
        &d,
        &["/input/1/link", "driven by /input/0 already"],
    );
    // An input of a list with a field missing.
    let mut f = fixture("arm_two_cylinders");
    f["input"][1].as_object_mut().unwrap().remove("v");
    reject("missing_rate", &f, &["/input/1/v", "missing"]);
    // An empty list.
    let mut g = fixture("arm_two_cylinders");
    g["input"] = json!([]);
    reject("no_inputs", &g, &["/input", "empty list"]);
}

// ---- the course sheet and the handout -----------------------------------

/// The rendered box of every figure of a course sheet (mm, page
/// coordinates), by its id.
fn course_figures(svg: &str) -> Vec<(String, kurbo::Rect)> {
    fn walk(g: &usvg::Group, out: &mut Vec<(String, kurbo::Rect)>) {
        let k = 25.4 / 96.0;
        for n in g.children() {
            if let usvg::Node::Group(g) = n {
                if g.id().starts_with("fig-") {
                    let b = n.abs_stroke_bounding_box();
                    out.push((
                        g.id().to_string(),
                        kurbo::Rect::new(
                            b.left() as f64 * k,
                            b.top() as f64 * k,
                            b.right() as f64 * k,
                            b.bottom() as f64 * k,
                        ),
                    ));
                } else {
                    walk(g, out);
                }
            }
        }
    }
    let t = mechplan::drawing::tree(svg).unwrap();
    let mut out = Vec::new();
    walk(t.root(), &mut out);
    out
}

/// `mechplan draw SCENE --course`: the course sheet of the boom (one
/// input, a cylinder on a moving guide) has its positions, velocity plans,
/// acceleration plans, the diagrams of the boom over the cylinder's
/// stroke and both tables; the two-input scenes' sheets have the same
/// without the diagrams (they need one input). Every figure lies inside
/// the frame, off the title block, apart from the others.
#[test]
fn the_course_sheet_of_every_new_fixture() {
    for name in NEW {
        let dir =
            std::env::temp_dir().join(format!("mechplan-course-{name}-{}", std::process::id()));
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args([
                "draw",
                &format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR")),
            ])
            .arg("--course")
            .arg("-o")
            .arg(&dir)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
        assert_eq!(o.status.code(), Some(0), "{name}: {stderr}");
        let svg = std::fs::read_to_string(dir.join("course.svg")).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        let figs = course_figures(&svg);
        let ids: Vec<&str> = figs.iter().map(|f| f.0.as_str()).collect();
        let mut want = vec![
            "fig-positions",
            "fig-velocity",
            "fig-acceleration-1",
            "fig-table-velocity",
            "fig-table-acceleration",
        ];
        if *name == "boom_cylinder" {
            want.push("fig-diagrams");
            assert!(
                svg.contains("Kinematic diagrams of link 1"),
                "{name}: the boom's diagrams"
            );
        } else {
            assert!(
                !ids.contains(&"fig-diagrams"),
                "{name}: diagrams of several inputs"
            );
        }
        for w in want {
            assert!(ids.contains(&w), "{name}: no {w} in {ids:?}");
        }
        let (w, h) = mechplan::drawing::SheetSize::A1.mm();
        let frame = kurbo::Rect::new(20.0, 5.0, w - 5.0, h - 5.0);
        let block = kurbo::Rect::new(frame.x1 - 185.0, frame.y1 - 55.0, frame.x1, frame.y1);
        for (i, (a, ra)) in figs.iter().enumerate() {
            assert!(
                frame.inset(-1.0).contains(ra.origin())
                    && frame.inset(-1.0).contains(Point::new(ra.x1, ra.y1)),
                "{name}: {a} {ra:?} leaves the frame"
            );
            assert!(
                ra.intersect(block).area() == 0.0,
                "{name}: {a} on the title block"
            );
            for (b, rb) in &figs[i + 1..] {
                assert!(
                    ra.intersect(*rb).area() == 0.0,
                    "{name}: {a} and {b} overlap"
                );
            }
        }
    }
}

/// The boom's acceleration plan in a table names what the cylinder lays
/// off: the given relative acceleration a^r_B3B2 (not a tangential part),
/// and the points K of the cylinder and P of the rod from their links'
/// rates: a^n_KC, a^t_KC, a^n_PB, a^t_PB.
#[test]
fn the_boom_plan_table_names_the_cylinder() {
    let (_, solved) = solve(scene_with(fixture("boom_cylinder"), json!({ "s": [0.1] })));
    let plan = solved[0]
        .plans
        .as_ref()
        .unwrap()
        .acceleration
        .clone()
        .unwrap();
    let rows = mechplan::drawing::table::plan_rows(&plan);
    let names: Vec<&str> = rows.iter().map(|r| r.quantity.as_str()).collect();
    for want in [
        "a^K_B3B2", "a^r_B3B2", "a^n_KC", "a^t_KC", "a^n_PB", "a^t_PB",
    ] {
        assert!(names.contains(&want), "no {want} in {names:?}");
    }
    let r = rows.iter().find(|r| r.quantity == "a^r_B3B2").unwrap();
    assert!((r.value - 0.05).abs() < 1e-12, "a^r is the rod's given a");
    assert!(
        !names
            .iter()
            .any(|n| n.starts_with("a^t_R") || n.contains('′')),
        "{names:?}"
    );
}

/// The handout of the boom: one page, the cylinder's steps in it.
#[test]
fn the_boom_handout() {
    let dir = std::env::temp_dir().join(format!("mechplan-handout-boom-{}", std::process::id()));
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args([
            "draw",
            &format!("{}/fixtures/boom_cylinder.json", env!("CARGO_MANIFEST_DIR")),
        ])
        .arg("--html")
        .arg("-o")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let html = std::fs::read_to_string(dir.join("handout.html")).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(html.contains("I(2,3)"), "the cylinder as the input pair");
    assert!(
        html.contains("the guide of link 2"),
        "the relative velocity along the cylinder"
    );
}
