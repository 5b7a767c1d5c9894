//! Speed of mechplan per position, against a hand-written closed form.
//!
//! `cargo bench --bench speed` (docs/performance.md has the figures). The
//! fixtures are the tests' own (`fixtures/*.json`). Every per-position
//! bench cycles through the fixture's full turn at 1° steps, one position
//! per iteration, so criterion's time is the time of one position:
//!
//! - `contour/*`: positions (`PositionSolver::solve`) and route (a)
//!   (`contour::solve`, velocities and accelerations);
//! - `construction/*`: the construction kernel (`build_plans`, both plans,
//!   with the names, labels and steps a drawing needs; step sentences are
//!   rendered only on demand, so none here);
//! - `construction_numbers/*`: the same constructions without names,
//!   labels or steps (`build_plans_numbers`), the kernel "without step text";
//! - `constraint/*`: route (b) (`solve_positions` + `solve_rates`);
//! - `draw/six_link_12`: `Analysis::run` + `drawing::sheets` of the
//!   six-link fixture with its 12 positions (the whole `draw` but writing);
//! - `positions_sheet/six_link_{200,2000}`: `drawing::sheets` of the
//!   positions sheet alone (the mechanism in every position, trajectories,
//!   numbering), positions solved beforehand;
//! - `sweep/six_link_3600/{1,2}_threads`: `Analysis::run` over 3600
//!   positions of the six-link fixture on a rayon pool of one thread and of
//!   two (the per-position work runs in parallel, `mechplan::progress`);
//! - `limit/four_bar`: a minimal closed-form four-bar (positions,
//!   velocities, accelerations of the same quantities, no allocation),
//!   the practical limit for the four-bar fixture;
//! - `compiled/*`: positions and route (a) by the program compiled for the
//!   mechanism (`mechplan::compiled::Program`), the same numbers to the bit.
//!
//! At the end the bench prints the ratios to the limit on the four-bar
//! (issue 16's targets: route (a) within 2×, the numbers-only kernel
//! within 10×) twice: from criterion's medians of this run, and from its
//! own interleaved rounds (limit, route (a), kernel, each over a full turn,
//! one after the other, the median of the rounds' ratios: a load that
//! comes and goes during the run slows all three alike).

use criterion::{Criterion, criterion_group, criterion_main};
use mechplan::analytic::constraint::{ConstraintSolver, Settings};
use mechplan::analytic::{Drive, Order, contour};
use mechplan::compiled::Program;
use mechplan::construction::{Setup, build_plans, build_plans_numbers};
use mechplan::drawing::{self, DrawOptions};
use mechplan::positions::{Configuration, PositionSolver};
use mechplan::{Analysis, Scene};
use std::hint::black_box;

const FIXTURES: [&str; 3] = ["four_bar", "six_link_fig2_10", "shaper_fig2_11"];

fn text(name: &str) -> String {
    let path = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn analysis(name: &str) -> Analysis {
    Analysis::new(Scene::from_json(&text(name)).expect("fixture accepted")).expect("fixture solves")
}

/// A full turn at 1° from the fixture's own crank angle, in rad.
fn turn(an: &Analysis) -> Vec<f64> {
    let q0 = an.mech.scene.input.coordinate();
    (0..360).map(|k| q0 + (k as f64).to_radians()).collect()
}

/// The hand-written closed form of the four-bar fixture: crank O1A, coupler
/// AB with the coupler point M, rocker O3B. Everything is precomputed that
/// does not depend on the crank angle.
#[derive(Clone, Copy, Debug)]
struct FourBar {
    o1: [f64; 2],
    o3: [f64; 2],
    a: f64,
    b: f64,
    c: f64,
    /// M in the coupler's frame (x along AB), relative to A.
    m: [f64; 2],
    sign: f64,
    omega1: f64,
    eps1: f64,
}

/// Angles, ω, ε of coupler and rocker; place, velocity, acceleration of A,
/// B, M.
#[derive(Clone, Copy, Debug, Default)]
struct FourBarState {
    theta: [f64; 2],
    omega: [f64; 2],
    eps: [f64; 2],
    p: [[f64; 2]; 3],
    v: [[f64; 2]; 3],
    acc: [[f64; 2]; 3],
}

impl FourBar {
    fn from_fixture() -> FourBar {
        let v: serde_json::Value = serde_json::from_str(&text("four_bar")).unwrap();
        let pt = |n: &str| {
            [
                v["points"][n][0].as_f64().unwrap(),
                v["points"][n][1].as_f64().unwrap(),
            ]
        };
        let len = |n: &str| v["lengths"][n].as_f64().unwrap();
        let (o1, a, b, m, o3) = (pt("O1"), pt("A"), pt("B"), pt("M"), pt("O3"));
        let ab = [b[0] - a[0], b[1] - a[1]];
        let l = ab[0].hypot(ab[1]);
        let e = [ab[0] / l, ab[1] / l];
        let am = [m[0] - a[0], m[1] - a[1]];
        // The branch: the side of B from the directed line A → O3.
        let ad = [o3[0] - a[0], o3[1] - a[1]];
        FourBar {
            o1,
            o3,
            a: len("O1-A"),
            b: len("A-B"),
            c: len("O3-B"),
            m: [am[0] * e[0] + am[1] * e[1], -am[0] * e[1] + am[1] * e[0]],
            sign: (ad[0] * ab[1] - ad[1] * ab[0]).signum(),
            omega1: v["input"]["omega"].as_f64().unwrap(),
            eps1: v["input"]["epsilon"].as_f64().unwrap(),
        }
    }

    #[inline(never)]
    fn solve(&self, phi: f64) -> FourBarState {
        let perp = |r: [f64; 2]| [-r[1], r[0]];
        let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
        let (s, c) = phi.sin_cos();
        let ra = [self.a * c, self.a * s];
        let pa = [self.o1[0] + ra[0], self.o1[1] + ra[1]];
        // B = circle (A, b) ∩ circle (O3, c) on the sketch's side.
        let d = [self.o3[0] - pa[0], self.o3[1] - pa[1]];
        let l2 = dot(d, d);
        let l = l2.sqrt();
        let x = (self.b * self.b - self.c * self.c + l2) / (2.0 * l);
        let h = self.sign * (self.b * self.b - x * x).max(0.0).sqrt();
        let pb = [
            pa[0] + (d[0] * x - d[1] * h) / l,
            pa[1] + (d[1] * x + d[0] * h) / l,
        ];
        let r2 = [pb[0] - pa[0], pb[1] - pa[1]];
        let r3 = [pb[0] - self.o3[0], pb[1] - self.o3[1]];
        let e2 = [r2[0] / self.b, r2[1] / self.b];
        let rm = [
            self.m[0] * e2[0] - self.m[1] * e2[1],
            self.m[0] * e2[1] + self.m[1] * e2[0],
        ];
        let pm = [pa[0] + rm[0], pa[1] + rm[1]];
        // Velocities: ω2·k×r2 − ω3·k×r3 = −v_A.
        let w1 = self.omega1;
        let va = [-w1 * ra[1], w1 * ra[0]];
        let d23 = dot(perp(r2), r3);
        let w2 = -dot(va, r3) / d23;
        let w3 = -dot(va, r2) / d23;
        let vb = [va[0] - w2 * r2[1], va[1] + w2 * r2[0]];
        let vm = [va[0] - w2 * rm[1], va[1] + w2 * rm[0]];
        // Accelerations: ε2·k×r2 − ε3·k×r3 = −a_A + ω2²·r2 − ω3²·r3.
        let aa = [
            -self.eps1 * ra[1] - w1 * w1 * ra[0],
            self.eps1 * ra[0] - w1 * w1 * ra[1],
        ];
        let rhs = [
            -aa[0] + w2 * w2 * r2[0] - w3 * w3 * r3[0],
            -aa[1] + w2 * w2 * r2[1] - w3 * w3 * r3[1],
        ];
        let e2r = dot(rhs, r3) / d23;
        let e3r = dot(rhs, r2) / d23;
        let ab = [
            aa[0] - e2r * r2[1] - w2 * w2 * r2[0],
            aa[1] + e2r * r2[0] - w2 * w2 * r2[1],
        ];
        let am = [
            aa[0] - e2r * rm[1] - w2 * w2 * rm[0],
            aa[1] + e2r * rm[0] - w2 * w2 * rm[1],
        ];
        FourBarState {
            theta: [r2[1].atan2(r2[0]), r3[1].atan2(r3[0])],
            omega: [w2, w3],
            eps: [e2r, e3r],
            p: [pa, pb, pm],
            v: [va, vb, vm],
            acc: [aa, ab, am],
        }
    }
}

/// The closed form must compute what mechplan computes, or it is no limit.
fn check_limit(an: &Analysis, fb: &FourBar) {
    let m = &an.mech;
    let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
    let idx = |n: &str| m.scene.points.iter().position(|p| p.name == n).unwrap();
    let link = |n: &str| m.scene.links.iter().position(|l| l.id == n).unwrap();
    let (rate, rate2) = m.scene.input.rates();
    for q in turn(an).into_iter().step_by(7) {
        let c = ps.solve(q).unwrap();
        let mo = contour::solve(
            m,
            &an.structure,
            &an.need,
            &c,
            Drive { q, rate, rate2 },
            Order::Acceleration,
        )
        .unwrap();
        let st = fb.solve(q);
        for (k, name) in ["A", "B", "M"].into_iter().enumerate() {
            let p = idx(name);
            let l = an.carrier(p);
            let at = c.point(m, l, p);
            let (v, a) = (mo[l].unwrap().velocity(at), mo[l].unwrap().acceleration(at));
            let close = |x: [f64; 2], y: kurbo::Vec2, scale: f64| {
                assert!(
                    (x[0] - y.x).hypot(x[1] - y.y) <= 1e-9 * scale,
                    "{name}: {x:?} vs {y:?}"
                );
            };
            close(st.p[k], at.to_vec2(), 1.0);
            close(st.v[k], v, 10.0);
            close(st.acc[k], a, 100.0);
        }
        for (k, l) in [link("2"), link("3")].into_iter().enumerate() {
            let x = mo[l].unwrap();
            assert!((x.omega - st.omega[k]).abs() <= 1e-9 * 10.0);
            assert!((x.epsilon - st.eps[k]).abs() <= 1e-9 * 100.0);
            // Each link's frame has its x-axis from its first point to its second.
            let dth = mechplan::geom::wrap_pi(x.pose.angle - st.theta[k]);
            assert!(dth.abs() <= 1e-9, "angle of link {}: {dth}", k + 2);
        }
    }
}

/// When this run started: criterion's medians written since are this run's.
static STARTED: std::sync::OnceLock<std::time::SystemTime> = std::sync::OnceLock::new();

fn per_position(cr: &mut Criterion) {
    STARTED.get_or_init(std::time::SystemTime::now);
    let fb = FourBar::from_fixture();
    {
        let an = analysis("four_bar");
        check_limit(&an, &fb);
        let qs = turn(&an);
        let mut k = 0;
        cr.bench_function("limit/four_bar", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(fb.solve(black_box(qs[k])))
            })
        });
    }
    for name in FIXTURES {
        let an = analysis(name);
        let m = &an.mech;
        let qs = turn(&an);
        let (rate, rate2) = m.scene.input.rates();

        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
        let mut k = 0;
        cr.bench_function(&format!("contour/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                let q = qs[k];
                let c = ps.solve(q).unwrap();
                let mo = contour::solve(
                    m,
                    &an.structure,
                    &an.need,
                    &c,
                    Drive { q, rate, rate2 },
                    Order::Acceleration,
                )
                .unwrap();
                black_box((c, mo))
            })
        });

        let prog = Program::new(m, &an.structure, &an.need).unwrap();
        let mut st = prog.state();
        let mut k = 0;
        cr.bench_function(&format!("compiled/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                let q = qs[k];
                prog.solve_one(&mut st, Drive { q, rate, rate2 }, Order::Acceleration)
                    .unwrap();
                black_box(&st.motion);
            })
        });

        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
        let configs: Vec<Configuration> = qs.iter().map(|&q| ps.solve(q).unwrap()).collect();
        let setup = Setup {
            m,
            s: &an.structure,
            need: &an.need,
            points: &an.points,
            include: &an.include,
        };
        let mut k = 0;
        cr.bench_function(&format!("construction/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                let q = qs[k];
                black_box(
                    build_plans(
                        &setup,
                        &configs[k],
                        Drive { q, rate, rate2 },
                        Order::Acceleration,
                        an.drafting,
                    )
                    .unwrap(),
                )
            })
        });

        let mut k = 0;
        cr.bench_function(&format!("construction_numbers/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                let q = qs[k];
                black_box(
                    build_plans_numbers(
                        &setup,
                        &configs[k],
                        Drive { q, rate, rate2 },
                        Order::Acceleration,
                        an.drafting,
                    )
                    .unwrap(),
                )
            })
        });

        let mut cs = ConstraintSolver::new(m, &an.include, Settings::default());
        let mut k = 0;
        cr.bench_function(&format!("constraint/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                cs.solve_positions(qs[k]).unwrap();
                black_box(cs.solve_rates(rate, rate2, Order::Acceleration).unwrap())
            })
        });
    }
}

fn draw(cr: &mut Criterion) {
    let an = analysis("six_link_fig2_10");
    assert_eq!(an.input_values().unwrap().len(), 12);
    let opt = DrawOptions::default();
    let mut g = cr.benchmark_group("draw");
    g.sample_size(20);
    g.bench_function("six_link_12", |b| {
        b.iter(|| {
            let solved = an.run().unwrap();
            black_box(drawing::sheets(&an, &solved, &opt))
        })
    });
    g.finish();
}

/// The positions sheet (the mechanism in all its positions with the
/// trajectories) of the six-link at 200 and at 2 000 positions: linear in
/// the positions (issue 13 asks 2 000 within 15× of 200).
fn positions_sheet(cr: &mut Criterion) {
    let mut g = cr.benchmark_group("positions_sheet");
    g.sample_size(10);
    for n in [200usize, 2000] {
        let mut v: serde_json::Value = serde_json::from_str(&text("six_link_fig2_10")).unwrap();
        v["positions"] = serde_json::json!({ "count": n });
        v["want"] = serde_json::json!({ "plans": [], "drawings": ["positions"] });
        let an = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
        let solved = an.run().unwrap();
        let opt = DrawOptions::default();
        assert_eq!(drawing::sheets(&an, &solved, &opt).len(), 1);
        g.bench_function(format!("six_link_{n}"), |b| {
            b.iter(|| black_box(drawing::sheets(&an, &solved, &opt)))
        });
    }
    g.finish();
}

fn sweep(cr: &mut Criterion) {
    let mut v: serde_json::Value = serde_json::from_str(&text("six_link_fig2_10")).unwrap();
    let a0 = v["input"]["angle"].as_f64().unwrap();
    v["positions"] = serde_json::json!({ "angles": (0..3600).map(|k| a0 + k as f64 / 10.0).collect::<Vec<_>>() });
    let an = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let mut g = cr.benchmark_group("sweep");
    g.sample_size(10);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        g.bench_function(format!("six_link_3600/{threads}_threads"), |b| {
            b.iter(|| pool.install(|| black_box(an.run().unwrap())))
        });
    }
    g.finish();
}

/// Criterion's median of bench `id` (ns), if this run measured it.
fn criterion_median(id: &str) -> Option<f64> {
    let home = std::env::var_os("CRITERION_HOME")
        .map(std::path::PathBuf::from)
        .or_else(|| {
            std::env::var_os("CARGO_TARGET_DIR")
                .map(|t| std::path::PathBuf::from(t).join("criterion"))
        })
        .unwrap_or_else(|| {
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/criterion")
        });
    let path = home.join(id.replace('/', "_")).join("new/estimates.json");
    let written = std::fs::metadata(&path).ok()?.modified().ok()?;
    if written < *STARTED.get()? {
        return None;
    }
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    v["median"]["point_estimate"].as_f64()
}

/// The ratios to the limit on the four-bar, printed by the bench itself.
fn summary(_: &mut Criterion) {
    STARTED.get_or_init(std::time::SystemTime::now);
    let load = std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into());
    let fb = FourBar::from_fixture();
    let an = analysis("four_bar");
    let m = &an.mech;
    let qs = turn(&an);
    let (rate, rate2) = m.scene.input.rates();
    let prog = Program::new(m, &an.structure, &an.need).unwrap();
    let mut st = prog.state();
    let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
    let configs: Vec<Configuration> = qs.iter().map(|&q| ps.solve(q).unwrap()).collect();
    let setup = Setup {
        m,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
    // Seconds per position of one full turn.
    let time = |f: &mut dyn FnMut(usize)| {
        let t = std::time::Instant::now();
        for k in 0..qs.len() {
            f(k);
        }
        t.elapsed().as_secs_f64() / qs.len() as f64
    };
    let mut limit = |k: usize| {
        black_box(fb.solve(black_box(qs[k])));
    };
    let mut compiled = |k: usize| {
        let q = qs[k];
        prog.solve_one(&mut st, Drive { q, rate, rate2 }, Order::Acceleration)
            .unwrap();
        black_box(&st.motion);
    };
    let mut interpreted = |k: usize| {
        let q = qs[k];
        let c = ps.solve(q).unwrap();
        let mo = contour::solve(
            m,
            &an.structure,
            &an.need,
            &c,
            Drive { q, rate, rate2 },
            Order::Acceleration,
        )
        .unwrap();
        black_box((c, mo));
    };
    let mut kernel = |k: usize| {
        let q = qs[k];
        black_box(
            build_plans_numbers(
                &setup,
                &configs[k],
                Drive { q, rate, rate2 },
                Order::Acceleration,
                an.drafting,
            )
            .unwrap(),
        );
    };
    const ROUNDS: usize = 201;
    let mut rounds: Vec<[f64; 4]> = Vec::with_capacity(ROUNDS);
    for r in 0..=ROUNDS {
        let t = [
            time(&mut limit),
            time(&mut compiled),
            time(&mut interpreted),
            time(&mut kernel),
        ];
        if r > 0 {
            // (The first round warms up.)
            rounds.push(t);
        }
    }
    let median = |f: &dyn Fn(&[f64; 4]) -> f64| {
        let mut v: Vec<f64> = rounds.iter().map(f).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let per = |i: usize| median(&|t| t[i]) * 1e9;
    let ratio = |i: usize| median(&|t| t[i] / t[0]);
    let verdict = |r: f64, target: f64| {
        if r <= target {
            format!("target ≤ {target}×: met")
        } else {
            format!("target ≤ {target}×: missed")
        }
    };
    let ns = |x: f64| {
        if x >= 1000.0 {
            format!("{:.2} µs", x / 1000.0)
        } else {
            format!("{x:.1} ns")
        }
    };
    println!();
    println!(
        "Summary: the four-bar, one position with velocities and accelerations (load average {load})"
    );
    let ids = [
        "limit/four_bar",
        "compiled/four_bar",
        "contour/four_bar",
        "construction_numbers/four_bar",
    ];
    match ids.map(criterion_median) {
        [Some(l), Some(c), Some(i), Some(k)] => {
            println!("  criterion's medians of this run:");
            println!("    limit (closed form)          {}", ns(l));
            println!(
                "    route (a) compiled           {}  = {:.2}× the limit ({})",
                ns(c),
                c / l,
                verdict(c / l, 2.0)
            );
            println!(
                "    route (a) interpreted        {}  = {:.2}× the limit",
                ns(i),
                i / l
            );
            println!(
                "    kernel, numbers only         {}  = {:.1}× the limit ({})",
                ns(k),
                k / l,
                verdict(k / l, 10.0)
            );
        }
        _ => println!(
            "  (criterion did not measure all of {} in this run: no ratios of its medians)",
            ids.join(", ")
        ),
    }
    println!(
        "  interleaved, {ROUNDS} rounds of a full turn each, medians (of the times; of the rounds' ratios):"
    );
    println!("    limit (closed form)          {}", ns(per(0)));
    println!(
        "    route (a) compiled           {}  = {:.2}× the limit ({})",
        ns(per(1)),
        ratio(1),
        verdict(ratio(1), 2.0)
    );
    println!(
        "    route (a) interpreted        {}  = {:.2}× the limit",
        ns(per(2)),
        ratio(2)
    );
    println!(
        "    kernel, numbers only         {}  = {:.1}× the limit ({})",
        ns(per(3)),
        ratio(3),
        verdict(ratio(3), 10.0)
    );
}

criterion_group!(benches, per_position, draw, positions_sheet, sweep, summary);
criterion_main!(benches);
