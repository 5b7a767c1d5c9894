//! The force analysis (docs/kinetostatics.md), judged from the result file
//! as the contract states it, by sums written here and not by the code
//! that produced it: (a) every moving link's d'Alembert equilibrium; (b)
//! the balancing moment against virtual power from the reported transfer
//! functions; (c) Newton's third law and the signs by hand; (d) the worked
//! example's printed digits; (e) M_b·ω1 = dT/dt by central differences.

use mechplan::scene::Scene;
use mechplan::{Analysis, report};
use serde_json::{Value, json};

const FIXTURES: [&str; 5] = [
    "worked_slider_crank",
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "arm_two_cylinders",
];

fn fixture(name: &str) -> Value {
    let path = format!(
        "{}/fixtures/dynamics/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Every position of the result file of `scene`.
fn positions(scene: &Value) -> Vec<Value> {
    let an = Analysis::new(Scene::from_json(&scene.to_string()).unwrap()).unwrap();
    an.run()
        .unwrap()
        .iter()
        .enumerate()
        .map(|(k, s)| report::position_json(&an, k, s))
        .collect()
}

type V = [f64; 2];

fn v(x: &Value) -> V {
    [x[0].as_f64().unwrap(), x[1].as_f64().unwrap()]
}
fn cross(r: V, f: V) -> f64 {
    r[0] * f[1] - r[1] * f[0]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1]]
}
fn norm(a: V) -> f64 {
    a[0].hypot(a[1])
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// A scene's load value at position `k`: one value or a list per position.
fn at_position(x: &Value, k: usize, listed: bool) -> Value {
    if listed { x[k].clone() } else { x.clone() }
}

/// One force or couple on a link as the result and the scene state it.
struct Load {
    link: String,
    /// Where a force acts (None: a couple).
    at: Option<V>,
    f: V,
    m: f64,
}

/// Every load on every link at position `k` of result `p`, the pairs'
/// reactions and the drives' balancing included: the complete free-body
/// diagrams, read from the result and the scene alone.
fn free_bodies(scene: &Value, p: &Value, k: usize) -> Vec<Load> {
    let d = &scene["dynamics"];
    let dy = &p["dynamics"];
    let place = |name: &str| v(&p["points"][name]["p"]);
    let mut out = Vec::new();
    let g = d.get("g").map_or([0.0, 0.0], v);
    for (id, lm) in d["links"].as_object().unwrap() {
        let c = place(lm["centre"].as_str().unwrap());
        let m = lm["m"].as_f64().unwrap();
        let inertia = &dy["inertia"][id];
        // The inertia as reported is −m·a_S and −J·ε of the reported motion.
        let a_s = v(&p["points"][lm["centre"].as_str().unwrap()]["a"]);
        let f_in = v(&inertia["F"]);
        let eps = p["links"][id]["epsilon"].as_f64().unwrap();
        let m_in = inertia["M"].as_f64().unwrap();
        let scale = (m * norm(a_s)).max(1e-300);
        assert!(norm([f_in[0] + m * a_s[0], f_in[1] + m * a_s[1]]) <= 1e-13 * scale);
        let j = lm["J"].as_f64().unwrap();
        assert!((m_in + j * eps).abs() <= 1e-13 * (j * eps).abs().max(1e-300));
        out.push(Load {
            link: id.clone(),
            at: Some(c),
            f: f_in,
            m: 0.0,
        });
        out.push(Load {
            link: id.clone(),
            at: None,
            f: [0.0; 2],
            m: m_in,
        });
        out.push(Load {
            link: id.clone(),
            at: Some(c),
            f: [g[0] * m, g[1] * m],
            m: 0.0,
        });
    }
    for f in d
        .get("forces")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
    {
        let listed = f["F"][0].is_array();
        out.push(Load {
            link: f["link"].as_str().unwrap().into(),
            at: Some(place(f["point"].as_str().unwrap())),
            f: v(&at_position(&f["F"], k, listed)),
            m: 0.0,
        });
    }
    for c in d
        .get("moments")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
    {
        let listed = c["M"].is_array();
        out.push(Load {
            link: c["link"].as_str().unwrap().into(),
            at: None,
            f: [0.0; 2],
            m: at_position(&c["M"], k, listed).as_f64().unwrap(),
        });
    }
    for pair in dy["pairs"].as_array().unwrap() {
        if let Some(links) = pair.get("links") {
            // The force of the first link on the second, and back.
            let at = place(pair["point"].as_str().unwrap());
            let r = v(&pair["R"]);
            let (a, b) = (links[0].as_str().unwrap(), links[1].as_str().unwrap());
            out.push(Load {
                link: b.into(),
                at: Some(at),
                f: r,
                m: 0.0,
            });
            out.push(Load {
                link: a.into(),
                at: Some(at),
                f: [-r[0], -r[1]],
                m: 0.0,
            });
        } else {
            // The guide's force on the slider: through `at` when given,
            // else at the pair's point with the couple M.
            let q = place(pair["point"].as_str().unwrap());
            let n = v(&pair["N"]);
            let m = pair["M"].as_f64().unwrap();
            let (at, m) = match pair["at"].as_array() {
                Some(_) => (v(&pair["at"]), 0.0),
                None => (q, m),
            };
            if pair["at"].is_array() {
                // `at` and M say the same: n through `at` has moment M about q.
                let moment = cross(sub(at, q), n);
                let m_pair = pair["M"].as_f64().unwrap();
                assert!((moment - m_pair).abs() <= 1e-9 * m_pair.abs().max(norm(n) * 1e-3));
            }
            let (s, g) = (
                pair["slider"].as_str().unwrap(),
                pair["guide"].as_str().unwrap(),
            );
            for (link, sign) in [(s, 1.0), (g, -1.0)] {
                out.push(Load {
                    link: link.into(),
                    at: Some(at),
                    f: [sign * n[0], sign * n[1]],
                    m: 0.0,
                });
                out.push(Load {
                    link: link.into(),
                    at: None,
                    f: [0.0; 2],
                    m: sign * m,
                });
            }
        }
    }
    let inputs: Vec<Value> = match &scene["input"] {
        Value::Array(a) => a.clone(),
        one => vec![one.clone()],
    };
    let balancing: Vec<Value> = match &dy["balancing"] {
        Value::Array(a) => a.clone(),
        one => vec![one.clone()],
    };
    for (input, b) in inputs.iter().zip(&balancing) {
        let link = input["link"].as_str().unwrap();
        if let Some(m) = b.get("M") {
            out.push(Load {
                link: link.into(),
                at: None,
                f: [0.0; 2],
                m: m.as_f64().unwrap(),
            });
        } else {
            // Along the guide (the line "along" two of its points), on the
            // slider, and back on the guide.
            let f = b["F"].as_f64().unwrap();
            let pr = scene["sliders"]
                .as_array()
                .unwrap()
                .iter()
                .find(|s| s["slider"] == input["link"])
                .unwrap();
            let along = &pr["line"]["along"];
            let d = sub(
                place(along[1].as_str().unwrap()),
                place(along[0].as_str().unwrap()),
            );
            let u = [d[0] / norm(d), d[1] / norm(d)];
            let q = place(pr["point"].as_str().unwrap());
            let guide = pr["guide"].as_str().unwrap();
            out.push(Load {
                link: link.into(),
                at: Some(q),
                f: [f * u[0], f * u[1]],
                m: 0.0,
            });
            out.push(Load {
                link: guide.into(),
                at: Some(q),
                f: [-f * u[0], -f * u[1]],
                m: 0.0,
            });
        }
    }
    out
}

/// (a) Every moving link in equilibrium with its inertia, at every
/// position of every fixture; the largest residual relative to the
/// position's largest force (a couple over the mechanism's size).
#[test]
fn every_link_in_equilibrium() {
    let mut worst: f64 = 0.0;
    for name in FIXTURES {
        let scene = fixture(name);
        for (k, p) in positions(&scene).iter().enumerate() {
            let loads = free_bodies(&scene, p, k);
            let pts: Vec<V> = p["points"]
                .as_object()
                .unwrap()
                .values()
                .map(|x| v(&x["p"]))
                .collect();
            let lo = pts
                .iter()
                .fold([f64::MAX; 2], |a, b| [a[0].min(b[0]), a[1].min(b[1])]);
            let hi = pts
                .iter()
                .fold([f64::MIN; 2], |a, b| [a[0].max(b[0]), a[1].max(b[1])]);
            let size = norm(sub(hi, lo));
            let force = loads
                .iter()
                .map(|l| norm(l.f).max(l.m.abs() / size))
                .fold(0.0, f64::max);
            for id in scene["links"]
                .as_object()
                .unwrap()
                .keys()
                .filter(|id| *id != "0")
            {
                let o = pts[0];
                let (mut f, mut m) = ([0.0; 2], 0.0);
                for l in loads.iter().filter(|l| &l.link == id) {
                    f = [f[0] + l.f[0], f[1] + l.f[1]];
                    m += l.m + l.at.map_or(0.0, |a| cross(sub(a, o), l.f));
                }
                let r = (norm(f) / force).max(m.abs() / (force * size));
                assert!(
                    r <= 1e-12,
                    "{name} position {}: link {id} off equilibrium by {r:e} (F {f:?}, M {m})",
                    k + 1
                );
                worst = worst.max(r);
            }
        }
    }
    eprintln!("largest equilibrium residual over the fixtures: {worst:.2e}");
}

/// (b) The balancing moment (force) equals the virtual power's, summed
/// here from the reported transfer functions v_q, φ' (route (a)'s).
#[test]
fn balancing_by_virtual_power() {
    let mut worst: f64 = 0.0;
    for name in FIXTURES {
        let scene = fixture(name);
        let w = scene["input"].as_array().map_or(1, Vec::len);
        for (k, p) in positions(&scene).iter().enumerate() {
            // The known loads only: reactions do no work, and the drives'
            // power is what is sought.
            let d = &scene["dynamics"];
            let dy = &p["dynamics"];
            let g = d.get("g").map_or([0.0, 0.0], v);
            for i in 0..w {
                let vq = |pt: &str| {
                    let x = &p["points"][pt]["v_q"];
                    if w > 1 { v(&x[i]) } else { v(x) }
                };
                let phi_q = |l: &str| {
                    let x = &p["links"][l]["phi_q"];
                    if w > 1 {
                        x[i].as_f64().unwrap()
                    } else {
                        x.as_f64().unwrap()
                    }
                };
                let mut terms = Vec::new();
                for (id, lm) in d["links"].as_object().unwrap() {
                    let c = lm["centre"].as_str().unwrap();
                    let m = lm["m"].as_f64().unwrap();
                    let inertia = &dy["inertia"][id];
                    terms.push(dot(v(&inertia["F"]), vq(c)));
                    terms.push(dot([g[0] * m, g[1] * m], vq(c)));
                    terms.push(inertia["M"].as_f64().unwrap() * phi_q(id));
                }
                for f in d
                    .get("forces")
                    .and_then(Value::as_array)
                    .into_iter()
                    .flatten()
                {
                    let listed = f["F"][0].is_array();
                    terms.push(dot(
                        v(&at_position(&f["F"], k, listed)),
                        vq(f["point"].as_str().unwrap()),
                    ));
                }
                for c in d
                    .get("moments")
                    .and_then(Value::as_array)
                    .into_iter()
                    .flatten()
                {
                    let listed = c["M"].is_array();
                    let m = at_position(&c["M"], k, listed).as_f64().unwrap();
                    terms.push(m * phi_q(c["link"].as_str().unwrap()));
                }
                let expected = -terms.iter().sum::<f64>();
                let scale: f64 = terms.iter().map(|t| t.abs()).sum();
                let b = if w > 1 {
                    &dy["balancing"][i]
                } else {
                    &dy["balancing"]
                };
                let got = b.get("M").or(b.get("F")).unwrap().as_f64().unwrap();
                let rel = (got - expected).abs() / scale;
                assert!(
                    rel <= 1e-10,
                    "{name} position {} input {i}: {got} against {expected} ({rel:e})",
                    k + 1
                );
                worst = worst.max(rel);
            }
        }
    }
    eprintln!("largest disagreement of the balancing with virtual power: {worst:.2e}");
}

/// The worked example's only position.
fn worked() -> Value {
    positions(&fixture("worked_slider_crank")).remove(0)
}

fn pair<'a>(p: &'a Value, point: &str) -> &'a Value {
    p["dynamics"]["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|x| x["point"] == point && x.get("links").is_some())
        .unwrap()
}

/// (c) Newton's third law and the signs, by hand: the slider 3 of the
/// worked example is pushed back by the rod (the rod's force on it points
/// to the crank, −x) against the resistance and its inertia; listing the
/// links the other way round names the pair the other way round and
/// reverses R, and nothing else changes.
#[test]
fn third_law_and_signs() {
    let p = worked();
    let b = pair(&p, "B");
    assert_eq!(b["links"], json!(["2", "3"]));
    let r23 = v(&b["R"]);
    // Slider's x: R23x + F_in3x + 2000 = 0, F_in3x = −3·a_B = −774.597 N.
    assert!(
        (r23[0] - (774.5966692414834 - 2000.0)).abs() < 1e-9,
        "{r23:?}"
    );
    assert!(r23[0] < 0.0);
    // The guide holds the slider down: the rod presses it up (+573 N).
    let guide = &p["dynamics"]["pairs"][3];
    assert_eq!(guide["slider"], "3");
    assert!(v(&guide["N"])[1] < 0.0 && r23[1] > 0.0);
    // The same mechanism with link 3 listed before link 2.
    let mut scene = fixture("worked_slider_crank");
    let links = scene["links"].as_object().unwrap().clone();
    let mut swapped = serde_json::Map::new();
    for id in ["0", "1", "3", "2"] {
        swapped.insert(id.into(), links[id].clone());
    }
    scene["links"] = Value::Object(swapped);
    let q = positions(&scene).remove(0);
    let b2 = pair(&q, "B");
    assert_eq!(b2["links"], json!(["3", "2"]));
    let r32 = v(&b2["R"]);
    assert_eq!(r32, [-r23[0], -r23[1]]);
    assert_eq!(q["dynamics"]["balancing"], p["dynamics"]["balancing"]);
}

/// (d) The worked example of docs/kinetostatics.md: the digits printed
/// there, step by step.
#[test]
fn worked_example_digits() {
    let p = worked();
    let f = |x: f64, d: usize| format!("{x:.d$}");
    let link = |id: &str, k: &str| p["links"][id][k].as_f64().unwrap();
    let point = |n: &str, k: &str| v(&p["points"][n][k]);
    assert_eq!(f(link("2", "angle"), 3), "-14.478");
    assert_eq!(f(link("2", "omega"), 3), "0.000");
    assert_eq!(f(link("2", "epsilon"), 2), "2581.99");
    assert_eq!(f(point("B", "a")[0], 2), "258.20");
    let a_s2 = point("S2", "a");
    assert_eq!(
        (f(a_s2[0], 2), f(a_s2[1], 2)),
        ("129.10".into(), "-500.00".into())
    );
    let dy = &p["dynamics"];
    let fi2 = v(&dy["inertia"]["2"]["F"]);
    assert_eq!(
        (f(fi2[0], 2), f(fi2[1], 2)),
        ("-258.20".into(), "1000.00".into())
    );
    assert_eq!(f(dy["inertia"]["2"]["M"].as_f64().unwrap(), 2), "-77.46");
    assert_eq!(f(v(&dy["inertia"]["3"]["F"])[0], 2), "-774.60");
    let r = |pt: &str| v(&pair(&p, pt)["R"]);
    assert_eq!(
        (f(r("B")[0], 2), f(r("B")[1], 2)),
        ("-1225.40".into(), "573.25".into())
    );
    assert_eq!(
        (f(r("A")[0], 2), f(r("A")[1], 2)),
        ("-967.20".into(), "-407.13".into())
    );
    assert_eq!(
        (f(r("O")[0], 2), f(r("O")[1], 2)),
        ("-967.20".into(), "-397.32".into())
    );
    let guide = &dy["pairs"][3];
    assert_eq!(f(v(&guide["N"])[1], 2), "-543.82");
    assert_eq!(f(guide["M"].as_f64().unwrap(), 9), "0.000000000");
    assert_eq!(f(v(&guide["at"])[0], 4), "0.3873");
    assert_eq!(f(dy["balancing"]["M"].as_f64().unwrap(), 2), "96.72");
}

/// (e) With no external loads and no gravity, the drive's power is the
/// rate of the kinetic energy: M_b·ω1 = dT/dt = ω1·dT/dφ (ε1 = 0), T =
/// Σ(½·m·v_S² + ½·J·ω²), dT/dφ by central differences over φ ± h.
#[test]
fn balancing_power_is_the_rate_of_kinetic_energy() {
    let h: f64 = 1e-3; // rad
    for name in [
        "worked_slider_crank",
        "six_link_fig2_10",
        "shaper_fig2_11",
        "compressor_fig2_12",
    ] {
        let mut scene = fixture(name);
        let d = scene["dynamics"].as_object_mut().unwrap();
        d.remove("g");
        d.remove("forces");
        d.remove("moments");
        let links = d["links"].clone();
        let omega1 = scene["input"]["omega"].as_f64().unwrap_or_else(|| {
            scene["input"]["rpm"].as_f64().unwrap() * std::f64::consts::PI / 30.0
        });
        let mut worst: f64 = 0.0;
        for phi in [20.0f64, 75.0, 140.0, 200.0, 290.0] {
            let deg = h.to_degrees();
            let offsets = [-1.0, -0.5, 0.0, 0.5, 1.0];
            let angles: Vec<f64> = offsets.iter().map(|o| phi + o * deg).collect();
            scene["positions"] = json!({ "angles": angles });
            let ps = positions(&scene);
            let energy = |p: &Value| -> f64 {
                links
                    .as_object()
                    .unwrap()
                    .iter()
                    .map(|(id, lm)| {
                        let vs = v(&p["points"][lm["centre"].as_str().unwrap()]["v"]);
                        let w = p["links"][id]["omega"].as_f64().unwrap();
                        0.5 * lm["m"].as_f64().unwrap() * dot(vs, vs)
                            + 0.5 * lm["J"].as_f64().unwrap() * w * w
                    })
                    .sum()
            };
            // Central differences over h and h/2, extrapolated (Richardson):
            // the error falls from h²·T‴/6 (2e-6 of the rate here) to O(h⁴).
            let wide = (energy(&ps[4]) - energy(&ps[0])) / (2.0 * h);
            let narrow = (energy(&ps[3]) - energy(&ps[1])) / h;
            let dt_dphi = (4.0 * narrow - wide) / 3.0;
            let ps = &ps[1..];
            let power = ps[1]["dynamics"]["balancing"]["M"].as_f64().unwrap() * omega1;
            let rate = omega1 * dt_dphi;
            // The scale: the kinetic energy's own rate of change, ω1·T.
            let scale = omega1.abs() * energy(&ps[1]);
            let rel = (power - rate).abs() / scale;
            assert!(
                rel < 1e-6,
                "{name} at {phi}°: M_b·ω1 = {power}, dT/dt = {rate} ({rel:e})"
            );
            worst = worst.max(rel);
        }
        eprintln!("{name}: M_b·ω1 against dT/dt by central differences within {worst:.1e} of ω1·T");
    }
}

/// A piston's guide force has no line exactly at the dead centres, where
/// the rod lies along the cylinder's axis (`at` null, N ≈ 0), and one
/// everywhere else: the compressor's positions 1 and 7 (φ1 = 90°, 270°).
#[test]
fn no_point_of_application_at_dead_centres() {
    for (k, p) in positions(&fixture("compressor_fig2_12")).iter().enumerate() {
        let dead = k == 0 || k == 6;
        for pair in p["dynamics"]["pairs"].as_array().unwrap() {
            if pair.get("slider").is_none() {
                continue;
            }
            assert_eq!(pair["at"].is_null(), dead, "position {}: {pair}", k + 1);
            if !dead {
                // On the axis x = 0, the piston's own pin: the rod's force
                // passes through it and so does the guide's.
                let at = v(&pair["at"]);
                let q = v(&p["points"][pair["point"].as_str().unwrap()]["p"]);
                assert!(norm(sub(at, q)) < 1e-12, "position {}: {pair}", k + 1);
            }
        }
    }
}
