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
//!   labels or steps, as a sweep makes them (`construction::Kernel`: the
//!   buffers and the last scales kept from one position to the next, the
//!   same plans to the bit), the kernel "without step text";
//! - `construction_numbers_alone/*`: the same, each position on its own
//!   (`build_plans_numbers`: new buffers, a first construction for the
//!   scale);
//! - `constraint/*`: route (b) (`solve_positions` + `solve_rates`);
//! - `draw/six_link_12`: `Analysis::run` + `drawing::sheets` of the
//!   six-link fixture with its 12 positions (the whole `draw` but writing);
//! - `positions_sheet/six_link_{200,2000}`: `studies::sheet_data` +
//!   `drawing::sheets` of the positions sheet alone (the mechanism in every
//!   position, trajectories, numbering), positions solved beforehand;
//! - `sweep/six_link_3600/{1,2}_threads`: `Analysis::run` over 3600
//!   positions of the six-link fixture on a rayon pool of one thread and of
//!   two (the per-position work runs in parallel, `mechplan::progress`);
//! - `limit/four_bar`: a minimal closed-form four-bar (positions,
//!   velocities, accelerations of the same quantities, no allocation),
//!   the practical limit for the four-bar fixture;
//! - `compiled/*`: positions and route (a) by the program compiled for the
//!   mechanism (`mechplan::compiled::Program`), the same numbers to the bit;
//! - `command_fast_path/{interpreted,compiled}`, `command_plan_sweep/*`
//!   (issue 24): the command's run over 3600 positions of the six-link
//!   fixture (`Analysis::run_each`, what `solve` calls; each position
//!   dropped as the writer drops it, nothing written), before and after in
//!   the same run: the fast path (`want.plans: []`) by route (a)
//!   interpreted (the reference twin, `Analysis::reference`) and compiled;
//!   a sweep with plans whose result keeps none (`solve`'s table and CSV)
//!   with the plans named as before (`builder`), numbers only as now
//!   (`numbers`), by the sweep's kernel (`kernel`, not taken: it changes
//!   the table's check line at some positions), and with the plans kept
//!   (`kept`: the JSON result, route (a) compiled). At the end of the
//!   groups each variant's time per position, by criterion's median and
//!   by interleaved rounds, with its ratio to the group's first (before).
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
use mechplan::construction::{Kernel, Setup, build_plans, build_plans_numbers};
use mechplan::drawing::{self, DrawOptions};
use mechplan::positions::{Configuration, PositionSolver};
use mechplan::studies::sheet_data::SheetData;
use mechplan::{Analysis, Scene};
use std::hint::black_box;

#[path = "peers/closed_form.rs"]
mod closed_form;
use closed_form::FourBar;

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
    let fb = FourBar::from_scene(&serde_json::from_str(&text("four_bar")).unwrap());
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
        let mut kernel = Kernel::new();
        cr.bench_function(&format!("construction_numbers/{name}"), |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                let q = qs[k];
                let (v, a) = kernel
                    .build(
                        &setup,
                        &configs[k],
                        Drive { q, rate, rate2 },
                        Order::Acceleration,
                        an.drafting,
                    )
                    .unwrap();
                black_box((v.points.len(), a.map(|a| a.points.len())));
            })
        });

        let mut k = 0;
        cr.bench_function(&format!("construction_numbers_alone/{name}"), |b| {
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
            let needs = drawing::sheet_needs(&an, &solved, &opt, true);
            let data = SheetData::solve(&an, &solved, needs).unwrap();
            black_box(drawing::sheets(&an, &solved, &data, &opt))
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
        // The trajectories solved (studies::sheet_data) and drawn, as
        // `mechplan draw` does.
        let sheets = || {
            let needs = drawing::sheet_needs(&an, &solved, &opt, true);
            let data = SheetData::solve(&an, &solved, needs).unwrap();
            drawing::sheets(&an, &solved, &data, &opt)
        };
        assert_eq!(sheets().len(), 1);
        g.bench_function(format!("six_link_{n}"), |b| b.iter(|| black_box(sheets())));
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
    // A bench of a group is in the group's folder; one named `a/b`
    // outside a group in `a_b`.
    let path = [home.join(id), home.join(id.replace('/', "_"))]
        .into_iter()
        .map(|p| p.join("new/estimates.json"))
        .find(|p| p.exists())?;
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
    let fb = FourBar::from_scene(&serde_json::from_str(&text("four_bar")).unwrap());
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
    let mut sweep_kernel = Kernel::new();
    let mut kernel = |k: usize| {
        let q = qs[k];
        let (v, a) = sweep_kernel
            .build(
                &setup,
                &configs[k],
                Drive { q, rate, rate2 },
                Order::Acceleration,
                an.drafting,
            )
            .unwrap();
        black_box((v.points.len(), a.map(|a| a.points.len())));
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

/// The positions of the command benches.
const COMMAND_POSITIONS: usize = 3600;

/// Issue 24: the command's cost per position before and after, in one run
/// (see the module's documentation).
fn command(cr: &mut Criterion) {
    STARTED.get_or_init(std::time::SystemTime::now);
    let mut v: serde_json::Value = serde_json::from_str(&text("six_link_fig2_10")).unwrap();
    let a0 = v["input"]["angle"].as_f64().unwrap();
    let n = COMMAND_POSITIONS;
    v["positions"] = serde_json::json!({
        "angles": (0..n).map(|k| a0 + 360.0 * k as f64 / n as f64).collect::<Vec<_>>()
    });
    let full = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    v["want"]["plans"] = serde_json::json!([]);
    v["want"]["rates"] = serde_json::json!(["velocity", "acceleration"]);
    let fast = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    assert!(full.plans && !fast.plans);
    // The run `solve` makes, each position dropped as it is handed over.
    let run = |an: &Analysis| {
        let mut count = 0;
        an.run_each(|s| {
            black_box(&s);
            count += 1;
            Ok(())
        })
        .unwrap();
        assert_eq!(count, n);
    };
    let with = |an: &Analysis, f: &dyn Fn(&mut Analysis)| {
        let mut an = an.clone();
        f(&mut an);
        an
    };
    let groups: [(&str, Vec<(&str, Analysis)>); 2] = [
        (
            "command_fast_path",
            vec![
                ("interpreted", with(&fast, &|a| a.reference = true)),
                ("compiled", fast.clone()),
            ],
        ),
        (
            "command_plan_sweep",
            vec![
                (
                    "builder",
                    with(&full, &|a| {
                        a.keep_plans = false;
                        a.reference = true;
                    }),
                ),
                ("numbers", with(&full, &|a| a.keep_plans = false)),
                (
                    "kernel",
                    with(&full, &|a| {
                        a.keep_plans = false;
                        a.sweep_kernel = true;
                    }),
                ),
                ("kept", full.clone()),
            ],
        ),
    ];
    for (group, variants) in &groups {
        let mut g = cr.benchmark_group(*group);
        g.sample_size(10);
        g.sampling_mode(criterion::SamplingMode::Flat);
        g.measurement_time(std::time::Duration::from_secs(10));
        for (name, an) in variants {
            g.bench_function(*name, |b| b.iter(|| run(an)));
        }
        g.finish();
    }
    // Per position: criterion's medians, and interleaved rounds (every
    // variant once a round, the median of the times and of the rounds'
    // ratios to the group's first: a load that comes and goes slows all
    // alike).
    const ROUNDS: usize = 15;
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!();
    println!(
        "The command per position ({n} positions of the six-link, {} threads), load average {load}",
        rayon::current_num_threads()
    );
    for (group, variants) in &groups {
        let mut rounds: Vec<Vec<f64>> = Vec::new();
        for _ in 0..ROUNDS {
            let times = variants
                .iter()
                .map(|(_, an)| {
                    let t = std::time::Instant::now();
                    run(an);
                    t.elapsed().as_secs_f64() / n as f64 * 1e6
                })
                .collect();
            rounds.push(times);
        }
        let median = |f: &dyn Fn(&Vec<f64>) -> f64| {
            let mut v: Vec<f64> = rounds.iter().map(f).collect();
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let first = criterion_median(&format!("{group}/{}", variants[0].0));
        println!("  {group}: criterion's median; interleaved, {ROUNDS} rounds");
        for (i, (name, _)) in variants.iter().enumerate() {
            let crit = criterion_median(&format!("{group}/{name}")).map_or_else(
                || "        –".to_string(),
                |t| {
                    let r = first.map_or(String::new(), |f| format!(" = {:.2}×", t / f));
                    format!("{:7.1} µs{r}", t / n as f64 / 1000.0)
                },
            );
            println!(
                "    {name:12} {crit};  {:7.1} µs = {:.2}×",
                median(&|t| t[i]),
                median(&|t| t[i] / t[0])
            );
        }
    }
}

criterion_group!(
    benches,
    per_position,
    draw,
    positions_sheet,
    sweep,
    command,
    summary
);
criterion_main!(benches);
