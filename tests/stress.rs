//! The stress catalogue `fixtures/stress/*.json`: dead centres, branch
//! points, extreme link-length ratios and speeds, nearly parallel guides and
//! leashes, coincident points. For every file, `mechplan solve` must either
//! succeed with every reported number within its own error bound of an
//! independent reference, or refuse with a clear message ("singular
//! position" / "cannot be assembled"): never a silently wrong number.
//!
//! **The reference.** The extended-precision reference
//! (`mechplan::reference`, about 50 digits) of the scene, and of the same
//! scene driven at unit rate without acceleration (its rates are the
//! transfer functions). Where it does not solve a position: route (b)'s
//! formulation re-solved with a tighter Newton tolerance (corrections down
//! to 1e-16 of the sketch size, no conditioning limit) and central finite
//! differences of those positions, v = ω1·P', a = ω1²·P'' + ε1·P', with the
//! step chosen per quantity from h, h/4, h/16 … as the one whose estimate
//! changes least to the next step (that change ×2 is its error estimate).
//!
//! **The bounds.** Plans: each measured value against the reference within
//! the plan's own drafting bound (`measured[].bound`). Analytic routes (the
//! reported `p`, `v`, `a`, angles, ω, ε and their transfer functions):
//! within the bound of their kind that mechplan prints (`crosscheck.bound`,
//! `mechplan::solve::Bounds`, where its formula is explained).

use mechplan::analytic::constraint::{ConstraintSolver, Settings};
use mechplan::scene::{InputSpec, PositionsSpec};
use mechplan::{Analysis, Scene};
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn stress_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/stress");
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    // STRESS_ONLY=prefix: a part of the catalogue (the table then
    // compares with docs/precision.md only in full).
    if let Some(only) = std::env::var_os("STRESS_ONLY") {
        let only = only.to_string_lossy().into_owned();
        v.retain(|p| p.file_name().unwrap().to_string_lossy().starts_with(&only));
    }
    v
}

/// The reference state of one position: every reported point's place and
/// the angle of every solved link, as functions of the input coordinate.
struct Probe<'a> {
    an: &'a Analysis,
    cs: ConstraintSolver<'a>,
}

impl<'a> Probe<'a> {
    fn new(an: &'a Analysis) -> Self {
        let settings = Settings {
            tol: 1e-16,
            max_iter: 200,
            min_conditioning: 0.0,
        };
        Probe {
            an,
            cs: ConstraintSolver::new(&an.mech, &an.include, settings),
        }
    }

    /// [x, y of every reported point…, θ of every solved link…] at q
    /// (angles unwrapped near `near`).
    fn state(&mut self, q: f64, near: Option<&[f64]>) -> Option<Vec<f64>> {
        self.cs.solve_positions(q).ok()?;
        let mo = self
            .cs
            .solve_rates(1.0, 0.0, mechplan::analytic::Order::Velocity)
            .ok()?;
        let m = &self.an.mech;
        let mut out = Vec::new();
        for &p in &self.an.points {
            let l = self.an.carrier(p);
            let at = mo[l].unwrap().pose.apply(m.local(l, p));
            out.extend([at.x, at.y]);
        }
        let k0 = out.len();
        for l in (0..m.links.len()).filter(|&l| self.an.include[l]) {
            out.push(mo[l].unwrap().pose.angle);
        }
        if let Some(near) = near {
            for k in k0..out.len() {
                let d = out[k] - near[k];
                out[k] -= (d / std::f64::consts::TAU).round() * std::f64::consts::TAU;
            }
        }
        Some(out)
    }
}

/// Reference values at q, each with its error estimate: the state
/// (points' x, y, then links' angles), its real rates (v, a; ω, ε) and its
/// transfer functions (first and second derivatives in q).
struct Reference {
    x: Vec<f64>,
    v: Vec<f64>,
    ev: Vec<f64>,
    a: Vec<f64>,
    ea: Vec<f64>,
    d1: Vec<f64>,
    e1: Vec<f64>,
    d2: Vec<f64>,
    e2: Vec<f64>,
}

/// The extended-precision reference (`mechplan::reference`, about 50
/// digits) when it solves the position; the finite differences otherwise.
fn reference(an: &Analysis, unit: &Analysis, q: f64) -> Option<(Reference, &'static str)> {
    if let Some(r) = extended(an, unit, q) {
        return Some((r, "extended precision"));
    }
    finite_differences(an, q).map(|r| (r, "finite differences"))
}

/// State, first and second time derivatives from the extended reference.
fn extended_state(an: &Analysis, q: f64) -> Option<[Vec<f64>; 3]> {
    let st = mechplan::reference::solve(an, q).ok()?;
    let m = &an.mech;
    let mut out = [Vec::new(), Vec::new(), Vec::new()];
    for &p in &an.points {
        let (at, v, a) = st.point(an, p).to_f64();
        out[0].extend([at.x, at.y]);
        out[1].extend([v.x, v.y]);
        out[2].extend([a.x, a.y]);
    }
    for l in (0..m.links.len()).filter(|&l| an.include[l]) {
        let mo = st.links[l].as_ref()?;
        out[0].push(mo.angle.to_f64());
        out[1].push(mo.omega.to_f64());
        out[2].push(mo.epsilon.to_f64());
    }
    Some(out)
}

/// `unit`: the same scene driven at unit rate without acceleration, whose
/// rates are the transfer functions.
fn extended(an: &Analysis, unit: &Analysis, q: f64) -> Option<Reference> {
    let [x, v, a] = extended_state(an, q)?;
    let [_, d1, d2] = extended_state(unit, q)?;
    // Rounded to f64 once: an ulp or two.
    let ulps = |v: &[f64]| v.iter().map(|y| 2.0 * f64::EPSILON * y.abs()).collect();
    Some(Reference {
        ev: ulps(&v),
        ea: ulps(&a),
        e1: ulps(&d1),
        e2: ulps(&d2),
        x,
        v,
        a,
        d1,
        d2,
    })
}

fn finite_differences(an: &Analysis, q: f64) -> Option<Reference> {
    let mut probe = Probe::new(an);
    let x = probe.state(q, None)?;
    let crank = matches!(an.mech.scene.input, InputSpec::Crank { .. });
    let h0 = if crank { 1e-2 } else { 1e-2 * an.mech.size };
    let n = x.len();
    let mut est: Vec<(Vec<f64>, Vec<f64>, f64)> = Vec::new();
    let mut h = h0;
    for _ in 0..20 {
        let a = probe.state(q + h, Some(&x));
        let b = probe.state(q - h, Some(&x));
        probe.state(q, None);
        if let (Some(a), Some(b)) = (a, b) {
            let d1: Vec<f64> = (0..n).map(|k| (a[k] - b[k]) / (2.0 * h)).collect();
            let d2: Vec<f64> = (0..n)
                .map(|k| (a[k] - 2.0 * x[k] + b[k]) / (h * h))
                .collect();
            est.push((d1, d2, h));
        }
        h /= 4.0;
    }
    if est.len() < 2 {
        return None;
    }
    let pick = |which: usize, k: usize| -> (f64, f64) {
        let val = |e: &(Vec<f64>, Vec<f64>, f64)| if which == 1 { e.0[k] } else { e.1[k] };
        let mut best = (f64::NAN, f64::INFINITY);
        for w in est.windows(2) {
            let change = (val(&w[1]) - val(&w[0])).abs();
            // Rounding floor: ε·|x|/h (first) or 4ε·|x|/h² (second).
            let h = w[1].2;
            let floor = if which == 1 {
                f64::EPSILON * x[k].abs().max(an.mech.size) / h
            } else {
                4.0 * f64::EPSILON * x[k].abs().max(an.mech.size) / (h * h)
            };
            let e = 2.0 * change + floor;
            if e < best.1 {
                best = (val(&w[1]), e);
            }
        }
        best
    };
    let (mut d1, mut e1, mut d2, mut e2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for k in 0..n {
        (d1[k], e1[k]) = pick(1, k);
        (d2[k], e2[k]) = pick(2, k);
    }
    let (w1, r2) = an.mech.scene.input.rates();
    Some(Reference {
        v: d1.iter().map(|d| w1 * d).collect(),
        ev: e1.iter().map(|e| w1.abs() * e).collect(),
        a: (0..n).map(|k| w1 * w1 * d2[k] + r2 * d1[k]).collect(),
        ea: (0..n).map(|k| w1 * w1 * e2[k] + r2.abs() * e1[k]).collect(),
        x,
        d1,
        e1,
        d2,
        e2,
    })
}

/// One compared number: what, reported, reference, allowed difference.
struct Item {
    what: String,
    got: f64,
    want: f64,
    allowed: f64,
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// Every number of one reported position against the reference, each
/// allowed its kind's printed bound (`crosscheck.bound`) plus the
/// reference's own error estimate.
fn items(an: &Analysis, pos: &Value, r: &Reference) -> Vec<Item> {
    let m = &an.mech;
    let np = an.points.len();
    let links: Vec<usize> = (0..m.links.len()).filter(|&l| an.include[l]).collect();
    let bound = |k: &str| -> f64 {
        pos["crosscheck"]["bound"][k]
            .as_f64()
            .unwrap_or_else(|| panic!("crosscheck.bound.{k} missing"))
    };
    let mut out = Vec::new();
    for (k, &p) in an.points.iter().enumerate() {
        let name = m.point_name(p);
        let rp = &pos["points"][name];
        for c in 0..2 {
            let i = 2 * k + c;
            for (key, want, err) in [
                ("p", r.x[i], 0.0),
                ("v", r.v[i], r.ev[i]),
                ("a", r.a[i], r.ea[i]),
                ("v_q", r.d1[i], r.e1[i]),
                ("a_q", r.d2[i], r.e2[i]),
            ] {
                if let Some(x) = rp[key].get(c) {
                    out.push(Item {
                        what: format!("{key}[{c}] of {name}"),
                        got: num(x),
                        want,
                        allowed: bound(key) + err,
                    });
                }
            }
        }
    }
    for (j, &l) in links.iter().enumerate() {
        let i = 2 * np + j;
        let id = m.link_id(l);
        let rl = &pos["links"][id];
        // Angles are reported in degrees, in (−180°, 180°], their bound in
        // radians: compared in degrees, no floor; the reference's own
        // error its rounding to f64 and to degrees (three roundings).
        let got = num(&rl["angle"]);
        let want = r.x[i].to_degrees();
        let d = want - got;
        let want = got + (d - (d / 360.0).round() * 360.0);
        out.push(Item {
            what: format!("angle of link {id} (deg)"),
            got,
            want,
            allowed: bound("angle").to_degrees() + 3.0 * f64::EPSILON * want.abs(),
        });
        for (key, want, err) in [
            ("omega", r.v[i], r.ev[i]),
            ("epsilon", r.a[i], r.ea[i]),
            ("phi_q", r.d1[i], r.e1[i]),
            ("phi_qq", r.d2[i], r.e2[i]),
        ] {
            if let Some(x) = rl.get(key) {
                out.push(Item {
                    what: format!("{key} of link {id}"),
                    got: num(x),
                    want,
                    allowed: bound(key) + err,
                });
            }
        }
    }
    // The plans: every measured quantity whose segment joins named points
    // (or the pole), and every ω, ε measured, within its drafting bound.
    let key_of: BTreeMap<String, usize> = an
        .points
        .iter()
        .enumerate()
        .map(|(k, &p)| (m.point_name(p).to_lowercase(), k))
        .collect();
    for (plan, acc) in [("velocity", false), ("acceleration", true)] {
        let Some(pl) = pos["plans"].get(plan) else {
            continue;
        };
        for meas in pl["measured"].as_array().unwrap() {
            let q = meas["quantity"].as_str().unwrap();
            let value = num(&meas["value"]);
            let bound = num(&meas["bound"]);
            let (from, to) = (meas["from"].as_str().unwrap(), meas["to"].as_str().unwrap());
            let link_rate = q
                .strip_prefix(if acc { "ε" } else { "ω" })
                .and_then(|id| links.iter().position(|&l| m.link_id(l) == id));
            if let Some(j) = link_rate {
                let i = 2 * np + j;
                out.push(Item {
                    what: format!("plan {q}"),
                    got: value,
                    want: if acc { r.a[i] } else { r.v[i] },
                    allowed: bound + if acc { r.ea[i] } else { r.ev[i] },
                });
                continue;
            }
            // A vector between two named plan points (or the pole).
            let at = |key: &str| -> Option<((f64, f64), f64)> {
                if key.starts_with("p_") || frame_key(an, key) {
                    return Some(((0.0, 0.0), 0.0));
                }
                let k = *key_of.get(key)?;
                let (i, j) = (2 * k, 2 * k + 1);
                Some(if acc {
                    ((r.a[i], r.a[j]), r.ea[i].hypot(r.ea[j]))
                } else {
                    ((r.v[i], r.v[j]), r.ev[i].hypot(r.ev[j]))
                })
            };
            if let (Some((a, ea)), Some((b, eb))) = (at(from), at(to)) {
                out.push(Item {
                    what: format!("plan {q} ({from}{to})"),
                    got: value.abs(),
                    want: (b.0 - a.0).hypot(b.1 - a.1),
                    allowed: bound + ea + eb,
                });
            }
        }
    }
    out
}

fn frame_key(an: &Analysis, key: &str) -> bool {
    let m = &an.mech;
    m.links[m.frame()]
        .points
        .iter()
        .any(|&p| m.point_name(p).to_lowercase() == key)
}

fn clear_refusal(msg: &str) -> bool {
    msg.contains("singular position") || msg.contains("cannot be assembled")
}

/// Every file through the binary (`solve --format json`): it never panics;
/// it answers with valid JSON for every position, or refuses with exit
/// status 2 and a clear message ("singular position" / "cannot be
/// assembled"). The numbers are judged against the independent reference
/// in [`stress_catalogue_against_the_independent_reference`].
#[test]
fn stress_catalogue_through_the_binary() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let files = stress_files();
    assert!(
        files.len() >= 60 || std::env::var_os("STRESS_ONLY").is_some(),
        "the stress catalogue is missing"
    );
    let mut failures = Vec::new();
    for path in &files {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(path).unwrap();
        let raw: Value = serde_json::from_str(&text).unwrap();
        let title = raw["title"].as_str().unwrap_or("");
        assert!(
            title.starts_with("Stress: "),
            "{name}: the title says what it stresses"
        );
        let out = Command::new(exe)
            .args(["solve", path.to_str().unwrap(), "--format", "json"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !stderr.contains("panicked"),
            "{name}: the binary panicked: {stderr}"
        );
        if out.status.success() {
            let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
            let an = Analysis::new(Scene::from_json(&text).unwrap()).unwrap();
            assert_eq!(
                doc["positions"].as_array().unwrap().len(),
                an.input_values().unwrap().len(),
                "{name}"
            );
        } else {
            let msg = stderr.trim().to_string();
            assert_eq!(out.status.code(), Some(2), "{name}: {msg}");
            let reader = Scene::from_json(&text).is_err();
            if !(clear_refusal(&msg) || reader && msg.contains('/')) {
                failures.push(format!("{name}: unclear refusal: {msg}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn first_line(s: &str) -> String {
    let l = s.lines().next().unwrap_or("");
    l.strip_prefix("mechplan: ").unwrap_or(l).to_string()
}

mod common;

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 48,
        .. proptest::prelude::ProptestConfig::default()
    })]

    /// Random mechanisms: a fixture with every length changed by up to
    /// ±4 %, a random position of its sweep, random ω1 (ε1) over twelve
    /// orders of magnitude. Either mechplan refuses with a clear message,
    /// or every number it reports (places, v, a, angles, ω, ε, transfer
    /// functions, plan values) is within its own reported bound of the
    /// extended-precision reference.
    #[test]
    fn reported_bounds_cover_the_error_on_random_mechanisms(
        f in 0..common::FIXTURES.len(),
        t in 0.0..1.0f64,
        lengths in proptest::collection::vec(-0.04..0.04f64, 16),
        log_omega in -6.0..6.0f64,
        eps_ratio in -2.0..2.0f64,
    ) {
        let name = common::FIXTURES[f];
        let mut v = common::fixture(name);
        let fixture = v.clone();
        if let Some(l) = v.get_mut("lengths").and_then(Value::as_object_mut) {
            for (k, (_, x)) in l.iter_mut().enumerate() {
                *x = serde_json::json!(x.as_f64().unwrap() * (1.0 + lengths[k % lengths.len()]));
            }
        }
        // Changed lengths that contradict the sketch (a point drawn on a
        // line its distances put off it) are refused by the reader with
        // the field named; then the fixture's own lengths are used.
        if let Err(e) = Scene::from_json(&v.to_string()).and_then(Analysis::new) {
            proptest::prop_assert!(e.to_string().contains("/"), "{name}: {e}");
            v["lengths"] = fixture["lengths"].clone();
        }
        let omega = 10f64.powf(log_omega);
        if v["input"].get("slider").is_some() {
            v["input"]["v"] = serde_json::json!(omega * 0.05);
            v["input"]["a"] = serde_json::json!(eps_ratio * omega * omega * 0.05);
        } else {
            v["input"]["omega"] = serde_json::json!(omega);
            v["input"].as_object_mut().unwrap().remove("rpm");
            v["input"]["epsilon"] = serde_json::json!(eps_ratio * omega * omega);
        }
        let sw = common::sweep(name, &v);
        let (key, list) = sw.as_object().unwrap().iter().next().unwrap();
        let list = list.as_array().unwrap();
        let x = list[((list.len() - 1) as f64 * t) as usize].as_f64().unwrap();
        v["positions"] = serde_json::json!({ key.as_str(): [x] });
        let scene = match Scene::from_json(&v.to_string()) {
            Ok(s) => s,
            Err(e) => {
                proptest::prop_assert!(e.to_string().contains('/'), "{name}: {e}");
                return Ok(());
            }
        };
        let an = match Analysis::new(scene.clone()) {
            Ok(an) => an,
            Err(e) => {
                proptest::prop_assert!(clear_refusal(&e.to_string()), "{name}: {e}");
                return Ok(());
            }
        };
        let solved = match an.run() {
            Ok(s) => s,
            Err(e) => {
                proptest::prop_assert!(clear_refusal(&e.to_string()), "{name}: {e}");
                return Ok(());
            }
        };
        let doc = mechplan::report::to_json(&an, &solved);
        let pos = &doc["positions"][0];
        let q = solved[0].q;
        let unit = {
            let mut u = scene.clone();
            match &mut u.input {
                InputSpec::Crank { omega, epsilon, .. } => (*omega, *epsilon) = (1.0, 0.0),
                InputSpec::Slider { v, a, .. } => (*v, *a) = (1.0, 0.0),
            }
            Analysis::new(u).unwrap()
        };
        let r = extended(&an, &unit, q);
        proptest::prop_assert!(r.is_some(), "{name} at q = {q}: no extended-precision reference");
        let r = r.unwrap();
        for it in items(&an, pos, &r) {
            let d = (it.got - it.want).abs();
            proptest::prop_assert!(
                d <= it.allowed,
                "{name} at q = {q}: {}: reported {:e}, reference {:e}, difference {d:.3e} > allowed {:.3e}",
                it.what, it.got, it.want, it.allowed
            );
        }
    }
}

use proptest::prelude::*;
use serde_json::json;

fn rate() -> impl Strategy<Value = f64> {
    (any::<bool>(), -3.0..3.0f64).prop_map(|(neg, e)| if neg { -1.0 } else { 1.0 } * 10f64.powf(e))
}

/// Solve `scene` (one position); if it is answered, every number within
/// its reported bound of the reference, else a clear refusal.
fn bound_covers_error(name: &str, scene: Scene) -> Result<(), TestCaseError> {
    let an = Analysis::new(scene.clone()).unwrap();
    let solved = match an.run() {
        Ok(s) => s,
        Err(err) => {
            let msg = err.to_string();
            prop_assert!(clear_refusal(&msg), "{name}: unclear refusal: {msg}");
            return Ok(());
        }
    };
    let q = solved[0].q;
    let unit = {
        let mut u = scene;
        match &mut u.input {
            InputSpec::Crank { omega, epsilon, .. } => (*omega, *epsilon) = (1.0, 0.0),
            InputSpec::Slider { v, a, .. } => (*v, *a) = (1.0, 0.0),
        }
        Analysis::new(u).unwrap()
    };
    let doc = mechplan::report::to_json(&an, &solved);
    let Some((r, _)) = reference(&an, &unit, q) else {
        return Err(TestCaseError::fail(format!(
            "{name} at q = {q}: no reference"
        )));
    };
    for it in items(&an, &doc["positions"][0], &r) {
        let d = (it.got - it.want).abs();
        prop_assert!(
            d <= it.allowed,
            "{name} at q = {q:.17}: {}: reported {:e}, reference {:e}, difference {d:.3e} > allowed {:.3e}",
            it.what,
            it.got,
            it.want,
            it.allowed
        );
    }
    Ok(())
}

/// A random four-bar (`slider` false) or offset slider-crank (true) at
/// crank angle φ, with a coupler point, in metres and radians: `dims` are
/// in (0, 1) and set the crank, rod (coupler), rocker and the coupler
/// point; `branch` picks the assembly. None where it does not assemble.
fn random_mechanism(
    slider: bool,
    dims: [f64; 5],
    phi: f64,
    branch: bool,
    w: f64,
    e: f64,
) -> Option<Scene> {
    let [k1, k2, k3, u, v] = dims;
    let (r, l) = (0.05 + 0.9 * k1, 0.2 + 1.8 * k2);
    let a = (r * phi.cos(), r * phi.sin());
    let sign = if branch { 1.0 } else { -1.0 };
    let (b, extra) = if slider {
        let offset = (k3 - 0.5) * l;
        let dy = offset - a.1;
        let h2 = l * l - dy * dy;
        if h2 <= 1e-6 * l * l {
            return None;
        }
        let b = (a.0 + sign * h2.sqrt(), offset);
        let extra = json!({
            "sliders": [{ "slider": "3", "guide": "0", "point": "B",
                          "line": { "through": [0.0, 0.0], "angle": 0.0, "offset": offset } }],
            "links": { "0": { "points": ["O"] }, "1": { "points": ["O", "A"] },
                       "2": { "points": ["A", "B", "M"] }, "3": { "points": ["B"] } },
        });
        (b, extra)
    } else {
        // Rocker of length c about O3 = (1, 0): B on both circles.
        let c = 0.2 + 1.8 * k3;
        let (dx, dy) = (1.0 - a.0, -a.1);
        let d = dx.hypot(dy);
        let x = (d * d + l * l - c * c) / (2.0 * d);
        let h2 = l * l - x * x;
        if h2 <= 1e-6 * l * l {
            return None;
        }
        let h = sign * h2.sqrt();
        let b = (a.0 + (x * dx - h * dy) / d, a.1 + (x * dy + h * dx) / d);
        let extra = json!({
            "links": { "0": { "points": ["O", "O3"] }, "1": { "points": ["O", "A"] },
                       "2": { "points": ["A", "B", "M"] }, "3": { "points": ["O3", "B"] } },
        });
        (b, extra)
    };
    let (ex, ey) = (b.0 - a.0, b.1 - a.1);
    let m = (a.0 + u * ex - (v - 0.5) * ey, a.1 + u * ey + (v - 0.5) * ex);
    let mut scene = json!({
        "mechplan": 1,
        "title": "random",
        "units": { "length": "m", "angle": "rad" },
        "points": { "O": [0.0, 0.0], "A": [a.0, a.1], "B": [b.0, b.1], "M": [m.0, m.1] },
        "input": { "link": "1", "pivot": "O", "angle": phi, "omega": w, "epsilon": e },
        "positions": { "angles": [phi] },
    });
    if !slider {
        scene["points"]["O3"] = json!([1.0, 0.0]);
    }
    for (k, x) in extra.as_object().unwrap() {
        scene[k] = x.clone();
    }
    Some(Scene::from_json(&scene.to_string()).expect("a valid random scene"))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    /// Random mechanisms (after the robustness review): four-bars (crank-rockers, double
    /// cranks, triple rockers) and offset slider-cranks of random
    /// proportions with a random coupler point, at a random crank angle on
    /// either branch.
    #[test]
    fn reported_bound_covers_the_actual_error_on_random_mechanisms(
        slider in any::<bool>(),
        dims in proptest::array::uniform5(0.0..1.0f64),
        phi in -std::f64::consts::PI..std::f64::consts::PI,
        branch in any::<bool>(),
        w in rate(),
        e in prop_oneof![Just(0.0), rate()],
    ) {
        let Some(scene) = random_mechanism(slider, dims, phi, branch, w, e) else {
            return Ok(());
        };
        bound_covers_error(&format!("random {} {dims:?} φ = {phi} branch {branch} ω = {w:e} ε = {e:e}", if slider { "slider-crank" } else { "four-bar" }), scene)?;
    }
}

/// One position of the independent reference (`tests/reference/mpref.py`,
/// 50 digits, written from the scene contract alone): its status, values
/// in the order of [`Reference`], and how far the data's own rounding (half
/// an ulp of every datum) moves the exact answer, relative to the kind's
/// scale.
struct Independent {
    assembles: bool,
    reference: Option<Reference>,
    sensitivity: f64,
}

fn independent(an: &Analysis, pos: &Value) -> Independent {
    let m = &an.mech;
    let f = |v: &Value| -> f64 {
        v.as_str()
            .map(|s| s.parse().unwrap())
            .unwrap_or_else(|| v.as_f64().unwrap())
    };
    let sensitivity = pos["sensitivity"]["max"]
        .as_str()
        .map(|s| s.parse::<f64>().unwrap_or(f64::INFINITY))
        .unwrap_or(f64::INFINITY);
    if pos["status"] != "ok" {
        return Independent {
            assembles: false,
            reference: None,
            sensitivity,
        };
    }
    let mut out: [Vec<f64>; 5] = Default::default();
    for &p in &an.points {
        let rp = &pos["points"][m.point_name(p)];
        for (k, key) in ["p", "v", "a", "v_q", "a_q"].iter().enumerate() {
            out[k].extend([f(&rp[key][0]), f(&rp[key][1])]);
        }
    }
    for l in (0..m.links.len()).filter(|&l| an.include[l]) {
        let rl = &pos["links"][m.link_id(l)];
        for (k, key) in ["angle", "omega", "epsilon", "phi_q", "phi_qq"]
            .iter()
            .enumerate()
        {
            out[k].push(f(&rl[key]));
        }
    }
    // 25 correct digits, rounded to f64 once: an ulp or two.
    let ulps = |v: &[f64]| v.iter().map(|y| 2.0 * f64::EPSILON * y.abs()).collect();
    let [x, v, a, d1, d2] = out;
    Independent {
        assembles: true,
        reference: Some(Reference {
            ev: ulps(&v),
            ea: ulps(&a),
            e1: ulps(&d1),
            e2: ulps(&d2),
            x,
            v,
            a,
            d1,
            d2,
        }),
        sensitivity,
    }
}

/// A refused position: its message must be clear, and the position one
/// the data do not determine (counted in `c[1]`; else a false refusal,
/// `c[2]`).
fn judge_refusal(
    at: &str,
    ind: &Independent,
    msg: &str,
    c: &mut [usize; 5],
    failures: &mut Vec<String>,
) {
    if !clear_refusal(msg) {
        failures.push(format!("{at}: unclear refusal: {msg}"));
    }
    if ind.assembles && ind.sensitivity < DETERMINED {
        c[2] += 1;
        failures.push(format!(
            "{at}: refused although the data's rounding moves the answer by only {:.1e}: {msg}",
            ind.sensitivity
        ));
    } else {
        c[1] += 1;
    }
}

/// The refusal threshold of the issue: a position whose exact answer the
/// data's rounding moves by less than this must be answered.
const DETERMINED: f64 = 1e-10;

/// The stiff catalogue against the independent reference
/// (`fixtures/stress/reference/NAME.json`, made by
/// `tests/reference/make.sh` from each scene's exact decimals): every
/// position mechplan answers is within its printed bound of the reference,
/// every position it refuses is one the data's rounding moves by 1e-10 or
/// more (or that does not assemble), and every position that does not
/// assemble is refused. Position k is solved as the file reaches it: from
/// the sketch through the positions before it that mechplan answers.
/// The counts are the table in docs/precision.md (UPDATE_GOLDEN=1 rewrites
/// it).
#[test]
fn stress_catalogue_against_the_independent_reference() {
    use sha2::{Digest, Sha256};
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut failures = Vec::new();
    let mut rows = Vec::new();
    let mut total = [0usize; 5];
    for path in stress_files() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        let refpath = root.join(format!("fixtures/stress/reference/{name}.json"));
        let Ok(reftext) = std::fs::read_to_string(&refpath) else {
            failures.push(format!("{name}: no reference; run tests/reference/make.sh"));
            continue;
        };
        let refdoc: Value = serde_json::from_str(&reftext).unwrap();
        let sha: String = Sha256::digest(&bytes)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        if refdoc["scene_sha256"] != sha.as_str() {
            failures.push(format!(
                "{name}: the reference is stale (the scene changed); run tests/reference/make.sh"
            ));
            continue;
        }
        let text = String::from_utf8(bytes).unwrap();
        let built = Scene::from_json(&text).and_then(|s| Analysis::new(s.clone()).map(|a| (s, a)));
        if let Some(why) = refdoc["rejected"].as_str() {
            match built {
                Err(e) => rows.push(format!(
                    "| {name} | rejected: {} | | | | |",
                    first_line(&e.to_string())
                )),
                Ok(_) => failures.push(format!(
                    "{name}: the reference rejects the scene ({why}) but mechplan builds it"
                )),
            }
            continue;
        }
        let (scene, an) = match built {
            Ok(x) => x,
            Err(e) => {
                failures.push(format!(
                    "{name}: mechplan rejects a scene the reference builds: {e}"
                ));
                continue;
            }
        };
        // The input values with their error bounds: half an ulp of a
        // written value, the start's error for `count`.
        let inputs = match an.input_positions() {
            Ok(x) => x,
            Err(e) => {
                // The start of `count` refused: every position refused.
                let msg = e.to_string();
                let refs = refdoc["positions"].as_array().unwrap();
                let mut c = [0usize; 5];
                for (k, r) in refs.iter().enumerate() {
                    let at = format!("{name} position {}", k + 1);
                    judge_refusal(&at, &independent(&an, r), &msg, &mut c, &mut failures);
                }
                for i in 0..5 {
                    total[i] += c[i];
                }
                rows.push(format!(
                    "| {name} | {} | 0 | {} | {} | |",
                    refs.len(),
                    c[1],
                    c[2]
                ));
                continue;
            }
        };
        let qs: Vec<f64> = inputs.iter().map(|p| p.value.first()).collect();
        let rounding: Vec<f64> = inputs.iter().map(|p| p.rounding.first()).collect();
        let refs = refdoc["positions"].as_array().unwrap();
        assert_eq!(refs.len(), qs.len(), "{name}: positions");
        // `count`: mechplan's start within its own error bound of the
        // reference's (found at 50 digits from the format's rule alone).
        if matches!(scene.positions, PositionsSpec::Count { .. })
            && let Some(want) = refs[0]["q"].as_str()
        {
            let want: f64 = want.parse().unwrap();
            let d = (want - qs[0]).rem_euclid(std::f64::consts::TAU);
            let d = d.min(std::f64::consts::TAU - d);
            let allowed = rounding[0] + 2.0 * f64::EPSILON * std::f64::consts::TAU;
            if d > allowed {
                failures.push(format!(
                    "{name}: the start of the working stroke {:.17} is {d:.3e} from the reference's {want:.17}, its bound {allowed:.3e}",
                    qs[0]
                ));
            }
        }
        // Counts: answered within the bound, refused rightly, refused
        // wrongly, answered outside the bound or where nothing assembles.
        let mut c = [0usize; 5];
        let mut worst = 0.0f64;
        let mut accepted: Vec<usize> = Vec::new();
        for (k, &q) in qs.iter().enumerate() {
            let ind = independent(&an, &refs[k]);
            let mut one = scene.clone();
            let path: Vec<usize> = accepted.iter().copied().chain([k]).collect();
            one.positions = PositionsSpec::List(path.iter().map(|&i| qs[i]).collect());
            one.input_rounding = path.iter().map(|&i| rounding[i]).collect();
            let a1 = Analysis::new(one).unwrap();
            let last = path.len() - 1;
            match a1.run() {
                Ok(solved) => {
                    accepted.push(k);
                    let Some(r) = ind.reference else {
                        c[4] += 1;
                        failures.push(format!(
                            "{name} position {}: mechplan answers where the mechanism does not assemble",
                            k + 1
                        ));
                        continue;
                    };
                    let doc = mechplan::report::to_json(&a1, &solved);
                    let mut outside = false;
                    for it in items(&a1, &doc["positions"][last], &r) {
                        let d = (it.got - it.want).abs();
                        worst = worst.max(d / it.allowed);
                        if d > it.allowed || d.is_nan() {
                            outside = true;
                            failures.push(format!(
                                "{name} position {} (q = {q:e}): {}: reported {:e}, reference {:e}, difference {d:.3e} > bound {:.3e}",
                                k + 1,
                                it.what,
                                it.got,
                                it.want,
                                it.allowed
                            ));
                        }
                    }
                    c[if outside { 4 } else { 0 }] += 1;
                }
                Err(e) => {
                    let at = format!("{name} position {} (q = {q:e})", k + 1);
                    judge_refusal(&at, &ind, &e.to_string(), &mut c, &mut failures);
                }
            }
        }
        for i in 0..5 {
            total[i] += c[i];
        }
        rows.push(format!(
            "| {name} | {} | {} | {} | {} | {} |",
            qs.len(),
            c[0],
            c[1],
            c[2] + c[4],
            if c[0] > 0 {
                format!("{worst:.1e}")
            } else {
                String::new()
            }
        ));
    }
    let table = format!(
        "| scene | positions | within the bound | refused (rounding decides, or no assembly) | wrong (false refusal or outside the bound) | worst error / bound |\n|---|---|---|---|---|---|\n{}\n| **all** | {} | {} | {} | {} | |\n",
        rows.join("\n"),
        total.iter().sum::<usize>(),
        total[0],
        total[1],
        total[2] + total[4],
    );
    let doc_path = root.join("docs/precision.md");
    let doc = std::fs::read_to_string(&doc_path).unwrap();
    let (begin, end) = (
        "<!-- stiff catalogue: begin -->\n",
        "<!-- stiff catalogue: end -->",
    );
    let block = |d: &str| -> Option<(usize, usize)> {
        let a = d.find(begin)? + begin.len();
        Some((a, a + d[a..].find(end)?))
    };
    if std::env::var_os("STRESS_ONLY").is_some() {
        // A part: the table is not the document's.
    } else if std::env::var_os("UPDATE_GOLDEN").is_some() {
        let new = match block(&doc) {
            Some((a, b)) => format!("{}{table}{}", &doc[..a], &doc[b..]),
            None => format!("{doc}\n{begin}{table}{end}\n"),
        };
        std::fs::write(&doc_path, new).unwrap();
    } else {
        match block(&doc) {
            Some((a, b)) if doc[a..b] == table => {}
            _ => failures.push(format!(
                "docs/precision.md does not show the current counts (UPDATE_GOLDEN=1 rewrites them):\n{table}"
            )),
        }
    }
    eprintln!("{table}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
