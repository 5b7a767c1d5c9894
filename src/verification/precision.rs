//! The work-precision report (`mechplan precision`): for every way of
//! finding the velocities and accelerations, its error against the
//! extended-precision reference ([`crate::verification::reference`]) and its run time per
//! position.
//!
//! Methods:
//! - the construction kernel (plan values = segment × μ; the drafting error
//!   is not counted: this is the kernel's floating-point error);
//! - route (a), the group-wise closed vector contours;
//! - route (b), the constraint solver, at Newton tolerances 1e-4 … 1e-14;
//! - kinematic diagrams: numerical differentiation of the position
//!   function with N positions per revolution, as the lecture draws them
//!   (chords, whose slopes are carried to the interval midpoints, then
//!   chords of that diagram back at the nodes) and by central differences
//!   at the nodes; each evaluation position is taken as a midpoint (chord
//!   velocities) or a node (the rest) of its diagram;
//! - hand drafting emulated: the kernel with pencil noise of δ (every laid
//!   off point, line and constructed point moved by at most δ mm on the
//!   scene's scales), Monte Carlo over seeds.
//!
//! Errors per position are relative as in the cross-check: places to the
//! sketch size; v and ω·size to the largest of them at that position; a and
//! ε·size likewise. Each row gives the maximum and the median over the
//! positions (and seeds) and the items.

use crate::error::{Error, Result};
use crate::geom::wrap_pi;
use crate::kinematics::analytic::constraint::{ConstraintSolver, Settings as NewtonSettings};
use crate::kinematics::analytic::{Drive, Motion, Order, contour};
use crate::kinematics::construction::{Drafting, Setup, Variant, build_plans_numbers};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::Analysis;
use crate::model::scene::{InputSpec, PositionsSpec};
use crate::verification::reference::{Real, RefState, Reference};
use kurbo::{Point, Vec2};
use std::time::Instant;

/// What to run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Newton tolerances of route (b).
    pub newton_tols: Vec<f64>,
    /// Positions per revolution of the kinematic diagrams.
    pub diagram_ns: Vec<usize>,
    /// Monte Carlo seeds of the emulated hand drafting.
    pub seeds: u64,
    /// Pencil precision, mm.
    pub delta: f64,
    /// Positions compared: `None` the scene's own (36 of a revolution
    /// when it gives one), `Some(k)` k of a revolution from its input.
    pub positions: Option<usize>,
    /// Least wall time of one timing batch, seconds (three batches, the
    /// fastest counts).
    pub min_time: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            newton_tols: vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14],
            diagram_ns: vec![12, 24, 48, 96, 180, 360, 720, 1800, 3600],
            seeds: 200,
            delta: 0.5,
            positions: None,
            min_time: 0.1,
        }
    }
}

/// Maximum and median of one kind of error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stat {
    pub max: f64,
    pub median: f64,
}

/// The kinds of output quantity, in the order of [`Row::err`].
pub const KINDS: [&str; 5] = ["place", "v", "a", "ω", "ε"];

/// One method at one setting.
#[derive(Clone, Debug)]
pub struct Row {
    /// "kernel", "contour", "newton", "chords", "central", "hand".
    pub method: String,
    /// "tol 1e-8", "N = 360", "δ = 0.5 mm, 200 seeds", or "".
    pub setting: String,
    /// Run time per position, seconds.
    pub time: f64,
    /// Per kind of [`KINDS`]; `None` where the method does not give it.
    pub err: [Option<Stat>; 5],
    /// Positions (× seeds) compared.
    pub compared: usize,
}

impl Row {
    /// The largest of the row's maximum errors.
    pub fn worst(&self) -> f64 {
        self.err.iter().flatten().map(|s| s.max).fold(0.0, f64::max)
    }
    /// The worst error among the rates (v, a, ω, ε), the plot's ordinate.
    pub fn worst_rates(&self) -> f64 {
        self.err[1..]
            .iter()
            .flatten()
            .map(|s| s.max)
            .fold(0.0, f64::max)
    }
}

/// The whole report of one scene.
#[derive(Clone, Debug)]
pub struct Report {
    pub title: String,
    pub positions: usize,
    pub rows: Vec<Row>,
}

/// Errors of one method collected over positions, per kind.
#[derive(Default)]
struct Errors {
    e: [Vec<f64>; 5],
    n: usize,
}

impl Errors {
    fn stats(mut self) -> ([Option<Stat>; 5], usize) {
        let mut out = [None; 5];
        for (k, v) in self.e.iter_mut().enumerate() {
            if v.is_empty() {
                continue;
            }
            v.sort_by(|a, b| a.total_cmp(b));
            let med = if v.len() % 2 == 1 {
                v[v.len() / 2]
            } else {
                0.5 * (v[v.len() / 2 - 1] + v[v.len() / 2])
            };
            out[k] = Some(Stat {
                max: *v.last().unwrap(),
                median: med,
            });
        }
        (out, self.n)
    }
}

/// The reference at one position, rounded for comparisons, plus the
/// scales of that position.
struct Truth {
    q: f64,
    /// Per reported point: (place, v, a) in extended precision.
    points: Vec<crate::verification::reference::RefPoint>,
    /// Per solved link (in `links` order): ω, ε.
    rates: Vec<(Real, Real)>,
    sv: f64,
    sa: f64,
}

/// What a method gives at one position; `None` entries are not given.
#[derive(Default)]
struct Got {
    places: Option<Vec<Point>>,
    v: Option<Vec<Vec2>>,
    a: Option<Vec<Vec2>>,
    omega: Option<Vec<f64>>,
    epsilon: Option<Vec<f64>>,
}

fn d_real(x: &Real, y: f64) -> f64 {
    (x - &Real::from_f64(y)).abs().to_f64()
}

impl Errors {
    fn add(&mut self, t: &Truth, g: &Got, size: f64) {
        self.n += 1;
        if let Some(p) = &g.places {
            for (r, p) in t.points.iter().zip(p) {
                self.e[0].push(r.at.dist_f64(p.to_vec2()) / size);
            }
        }
        if let Some(v) = &g.v {
            for (r, v) in t.points.iter().zip(v) {
                self.e[1].push(r.v.dist_f64(*v) / t.sv);
            }
        }
        if let Some(a) = &g.a {
            for (r, a) in t.points.iter().zip(a) {
                self.e[2].push(r.a.dist_f64(*a) / t.sa);
            }
        }
        if let Some(w) = &g.omega {
            for (r, w) in t.rates.iter().zip(w) {
                self.e[3].push(d_real(&r.0, *w) * size / t.sv);
            }
        }
        if let Some(e) = &g.epsilon {
            for (r, e) in t.rates.iter().zip(e) {
                self.e[4].push(d_real(&r.1, *e) * size / t.sa);
            }
        }
    }
}

/// Best of three batches, each repeated for at least `min_time / 3`:
/// seconds per call of `f`.
fn time_per_call(min_time: f64, mut f: impl FnMut() -> Result<()>) -> Result<f64> {
    f()?;
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let t0 = Instant::now();
        let mut n = 0u64;
        loop {
            f()?;
            n += 1;
            let e = t0.elapsed().as_secs_f64();
            if e >= min_time / 3.0 {
                best = best.min(e / n as f64);
                break;
            }
        }
    }
    Ok(best)
}

/// Run every method on the scene.
pub fn run(an: &Analysis, set: &Settings) -> Result<Report> {
    let m = &an.mech;
    let crank = matches!(m.scene.input, InputSpec::Crank { .. });
    let qs = eval_positions(an, set)?;
    if qs.is_empty() {
        return Err(Error::scene(
            "/positions",
            "no position of the scene assembles for the precision report",
        ));
    }
    let (rate, rate2) = m.scene.input.rates();
    let links: Vec<usize> = (0..m.links.len())
        .filter(|&l| an.include[l] && l != m.frame())
        .collect();
    // The reference at every evaluation position: the starts in order (on
    // the sketch's branch), then each refined on its own, in parallel.
    let mut re = Reference::new(an)?;
    let starts: Vec<(f64, Configuration)> = qs.iter().copied().zip(re.starts(&qs)?).collect();
    let truth = crate::progress::map(&starts, "reference", |(q, c)| -> Result<Truth> {
        let st: RefState = re.refine(&Real::from_f64(*q), c)?;
        let q = *q;
        let points: Vec<_> = an.points.iter().map(|&p| st.point(an, p)).collect();
        let rates: Vec<(Real, Real)> = links
            .iter()
            .map(|&l| {
                let mo = st.links[l].as_ref().expect("solved");
                (mo.omega.clone(), mo.epsilon.clone())
            })
            .collect();
        let mut sv = 0.0f64;
        let mut sa = 0.0f64;
        for p in &points {
            sv = sv.max(p.v.norm().to_f64());
            sa = sa.max(p.a.norm().to_f64());
        }
        for (w, e) in &rates {
            sv = sv.max(w.abs().to_f64() * m.size);
            sa = sa.max(e.abs().to_f64() * m.size);
        }
        Ok(Truth {
            q,
            points,
            rates,
            sv: sv.max(f64::MIN_POSITIVE),
            sa: sa.max(f64::MIN_POSITIVE),
        })
    })
    .into_iter()
    .collect::<Result<Vec<Truth>>>()?;
    let setup = Setup {
        m,
        s: &an.structure,
        need: &an.need,
        points: &an.points,
        include: &an.include,
    };
    let drive = |q: f64| Drive { q, rate, rate2 };
    let from_motion = |c: Option<&Configuration>, mo: &[Option<Motion>]| -> Got {
        let mut g = Got::default();
        let mut pl = Vec::new();
        let (mut v, mut a) = (Vec::new(), Vec::new());
        for &p in &an.points {
            let l = an.carrier(p);
            let x = mo[l].expect("solved");
            let at = match c {
                Some(c) => c.point(m, l, p),
                None => x.pose.apply(m.local(l, p)),
            };
            pl.push(at);
            v.push(x.velocity(at));
            a.push(x.acceleration(at));
        }
        g.places = Some(pl);
        g.v = Some(v);
        g.a = Some(a);
        g.omega = Some(links.iter().map(|&l| mo[l].unwrap().omega).collect());
        g.epsilon = Some(links.iter().map(|&l| mo[l].unwrap().epsilon).collect());
        g
    };
    let mut rows = Vec::new();
    let npos = qs.len();

    // The construction kernel, without pencil noise.
    let drafting = Drafting {
        delta: set.delta,
        ..an.drafting
    };
    let kernel_got = |c: &Configuration, q: f64, d: Drafting| -> Result<Got> {
        let plans = build_plans_numbers(&setup, c, drive(q), Order::Acceleration, d)?;
        let acc = plans.acceleration.as_ref().expect("asked for");
        let mut g = Got {
            places: Some(
                an.points
                    .iter()
                    .map(|&p| c.point(m, an.carrier(p), p))
                    .collect(),
            ),
            ..Got::default()
        };
        let vals = |plan: &crate::kinematics::construction::Plan| -> Option<Vec<Vec2>> {
            an.points.iter().map(|&p| plan.value_of(p)).collect()
        };
        g.v = vals(&plans.velocity);
        g.a = vals(acc);
        let rates = |plan: &crate::kinematics::construction::Plan| -> Option<Vec<f64>> {
            links.iter().map(|&l| plan.rates[l].map(|r| r.0)).collect()
        };
        g.omega = rates(&plans.velocity);
        g.epsilon = rates(acc);
        Ok(g)
    };
    {
        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
        let mut errs = Errors::default();
        for t in &truth {
            let c = ps.solve(t.q)?;
            errs.add(t, &kernel_got(&c, t.q, drafting)?, m.size);
        }
        let time = time_per_call(set.min_time, || {
            for &q in &qs {
                let c = ps.solve(q)?;
                build_plans_numbers(&setup, &c, drive(q), Order::Acceleration, drafting)?;
            }
            Ok(())
        })? / npos as f64;
        let (err, compared) = errs.stats();
        rows.push(Row {
            method: "kernel".into(),
            setting: String::new(),
            time,
            err,
            compared,
        });
    }

    // Route (a).
    {
        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
        let mut errs = Errors::default();
        for t in &truth {
            let c = ps.solve(t.q)?;
            let mo = contour::solve(
                m,
                &an.structure,
                &an.need,
                &c,
                drive(t.q),
                Order::Acceleration,
            )?;
            errs.add(t, &from_motion(Some(&c), &mo), m.size);
        }
        let time = time_per_call(set.min_time, || {
            for &q in &qs {
                let c = ps.solve(q)?;
                contour::solve(
                    m,
                    &an.structure,
                    &an.need,
                    &c,
                    drive(q),
                    Order::Acceleration,
                )?;
            }
            Ok(())
        })? / npos as f64;
        let (err, compared) = errs.stats();
        rows.push(Row {
            method: "contour".into(),
            setting: String::new(),
            time,
            err,
            compared,
        });
    }

    // Route (b) at each Newton tolerance.
    for &tol in &set.newton_tols {
        let ns = NewtonSettings {
            tol,
            ..NewtonSettings::default()
        };
        let mut cs = ConstraintSolver::new(m, &an.include, ns);
        let mut errs = Errors::default();
        for t in &truth {
            cs.solve_positions(t.q)?;
            let mo = cs.solve_rates(rate, rate2, Order::Acceleration)?;
            errs.add(t, &from_motion(None, &mo), m.size);
        }
        let time = time_per_call(set.min_time, || {
            let mut cs = ConstraintSolver::new(m, &an.include, ns);
            for &q in &qs {
                cs.solve_positions(q)?;
                cs.solve_rates(rate, rate2, Order::Acceleration)?;
            }
            Ok(())
        })? / npos as f64;
        let (err, compared) = errs.stats();
        rows.push(Row {
            method: "newton".into(),
            setting: format!("tol {}", sci(tol)),
            time,
            err,
            compared,
        });
    }

    // Kinematic diagrams by numerical differentiation (a crank only).
    if crank {
        for chords in [true, false] {
            for &n in &set.diagram_ns {
                let h = std::f64::consts::TAU / n as f64;
                // Stencil offsets in steps of h.
                let offs: &[f64] = if chords {
                    &[-1.0, -0.5, 0.0, 0.5, 1.0]
                } else {
                    &[-1.0, 0.0, 1.0]
                };
                let mut ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
                let mut errs = Errors::default();
                let mut evals = 0usize;
                let diff = |ps: &mut PositionSolver, q: f64| -> Option<Got> {
                    let mut samples = Vec::with_capacity(offs.len());
                    for &o in offs {
                        samples.push(sample(an, &links, ps.solve(q + o * h).ok()?));
                    }
                    Some(differentiate(&samples, h, chords, rate, rate2))
                };
                for t in &truth {
                    if let Some(g) = diff(&mut ps, t.q) {
                        errs.add(t, &g, m.size);
                        evals += 1;
                    }
                    // Back on the path for the next position.
                    let _ = ps.solve(t.q);
                }
                if evals == 0 {
                    continue;
                }
                let time = time_per_call(set.min_time, || {
                    for &q in &qs {
                        let _ = diff(&mut ps, q);
                    }
                    Ok(())
                })? / (npos * offs.len()) as f64;
                let (err, compared) = errs.stats();
                rows.push(Row {
                    method: if chords { "chords" } else { "central" }.into(),
                    setting: format!("N = {n}"),
                    time,
                    err,
                    compared,
                });
            }
        }
    }

    // Hand drafting emulated: the kernel with pencil noise.
    if set.seeds > 0 {
        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
        let configs: Vec<Configuration> = qs.iter().map(|&q| ps.solve(q)).collect::<Result<_>>()?;
        let mut errs = Errors::default();
        let t0 = Instant::now();
        let mut built = 0usize;
        for seed in 0..set.seeds {
            let d = Drafting {
                variant: Variant {
                    jitter: Some(seed),
                    ..Variant::default()
                },
                ..drafting
            };
            for (t, c) in truth.iter().zip(&configs) {
                if let Ok(mut g) = kernel_got(c, t.q, d) {
                    // The plan of the mechanism is not drawn by hand here.
                    g.places = None;
                    errs.add(t, &g, m.size);
                    built += 1;
                }
            }
        }
        let time = t0.elapsed().as_secs_f64() / built.max(1) as f64;
        let (err, compared) = errs.stats();
        rows.push(Row {
            method: "hand".into(),
            setting: format!("δ = {} mm, {} seeds", set.delta, set.seeds),
            time,
            err,
            compared,
        });
    }
    Ok(Report {
        title: m.scene.title.clone(),
        positions: npos,
        rows,
    })
}

/// (reported points' places, angles of the solved links) at one position.
type Sample = (Vec<Point>, Vec<f64>);

fn sample(an: &Analysis, links: &[usize], c: Configuration) -> Sample {
    let m = &an.mech;
    (
        an.points
            .iter()
            .map(|&p| c.point(m, an.carrier(p), p))
            .collect(),
        links.iter().map(|&l| c.pose(l).angle).collect(),
    )
}

/// Velocities and accelerations from positions on a stencil of step h:
/// `samples` at −h, −h/2, 0, h/2, h (chords) or −h, 0, h (central).
/// With ω1 and ε1: v = ω1·x', a = ω1²·x'' + ε1·x'.
fn differentiate(s: &[Sample], h: f64, chords: bool, w1: f64, e1: f64) -> Got {
    let (lo, mid, hi) = if chords { (0, 2, 4) } else { (0, 1, 2) };
    let pt = |k: usize, i: usize| s[k].0[i].to_vec2();
    let ang = |k: usize, i: usize| s[k].1[i];
    let np = s[0].0.len();
    let nl = s[0].1.len();
    // First derivative: chords over [−h/2, h/2] (the midpoint's own chord),
    // or the central difference over [−h, h].
    let d1p = |i: usize| -> Vec2 {
        if chords {
            (pt(3, i) - pt(1, i)) / h
        } else {
            (pt(hi, i) - pt(lo, i)) / (2.0 * h)
        }
    };
    let d1a = |i: usize| -> f64 {
        if chords {
            wrap_pi(ang(3, i) - ang(1, i)) / h
        } else {
            wrap_pi(ang(hi, i) - ang(lo, i)) / (2.0 * h)
        }
    };
    // Second derivative at the node: the chord of the chords' diagram
    // (= the second central difference).
    let d2p = |i: usize| (pt(hi, i) - pt(mid, i) * 2.0 + pt(lo, i)) / (h * h);
    let d2a = |i: usize| {
        (wrap_pi(ang(hi, i) - ang(mid, i)) - wrap_pi(ang(mid, i) - ang(lo, i))) / (h * h)
    };
    // x' at the node for the ε1 term: the mean of the two adjacent chords.
    let d1p_node = |i: usize| (pt(hi, i) - pt(lo, i)) / (2.0 * h);
    let d1a_node = |i: usize| wrap_pi(ang(hi, i) - ang(lo, i)) / (2.0 * h);
    Got {
        places: None,
        v: Some((0..np).map(|i| d1p(i) * w1).collect()),
        a: Some(
            (0..np)
                .map(|i| d2p(i) * (w1 * w1) + d1p_node(i) * e1)
                .collect(),
        ),
        omega: Some((0..nl).map(|i| d1a(i) * w1).collect()),
        epsilon: Some(
            (0..nl)
                .map(|i| d2a(i) * (w1 * w1) + d1a_node(i) * e1)
                .collect(),
        ),
    }
}

/// The evaluation positions: the scene's (when it gives more than one),
/// else k of a revolution from the scene's input, those that assemble.
fn eval_positions(an: &Analysis, set: &Settings) -> Result<Vec<f64>> {
    let m = &an.mech;
    let own = an.input_values()?;
    let k = match (set.positions, &m.scene.positions) {
        (Some(k), _) => k,
        (None, PositionsSpec::Single) => 36,
        (None, _) => return Ok(own),
    };
    let InputSpec::Crank { angle, .. } = m.scene.input else {
        return Ok(own);
    };
    let mut out = Vec::new();
    for j in 0..k {
        let q = angle + std::f64::consts::TAU * j as f64 / k as f64;
        let q = crate::geom::wrap_pi(q);
        let mut ps = PositionSolver::new(m, &an.structure, an.need.clone())?;
        let mut cs = ConstraintSolver::new(m, &an.include, NewtonSettings::default());
        let ok = ps.solve(q).is_ok()
            && cs.solve_positions(q).is_ok()
            && cs.solve_rates(1.0, 0.0, Order::Acceleration).is_ok();
        if ok {
            out.push(q);
        }
    }
    Ok(out)
}

/// 1e-8, 2.5e-3: a compact scientific number.
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:.1e}");
    s.replace(".0e", "e")
}

/// The report as a markdown table.
pub fn to_markdown(r: &Report) -> String {
    let mut s = String::new();
    s.push_str("| method | setting | time/position | place max | v max | v median | a max | a median | ω max | ε max | ε median |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    let cell = |st: &Option<Stat>, med: bool| match st {
        None => "—".to_string(),
        Some(st) => sci(if med { st.median } else { st.max }),
    };
    for row in &r.rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            row.method,
            row.setting,
            time_str(row.time),
            cell(&row.err[0], false),
            cell(&row.err[1], false),
            cell(&row.err[1], true),
            cell(&row.err[2], false),
            cell(&row.err[2], true),
            cell(&row.err[3], false),
            cell(&row.err[4], false),
            cell(&row.err[4], true),
        ));
    }
    s
}

/// 3.2 µs, 41 ns, 1.5 ms.
pub fn time_str(t: f64) -> String {
    let (v, unit) = if t >= 1e-3 {
        (t * 1e3, "ms")
    } else if t >= 1e-6 {
        (t * 1e6, "µs")
    } else {
        (t * 1e9, "ns")
    };
    if v >= 100.0 {
        format!("{v:.0} {unit}")
    } else if v >= 10.0 {
        format!("{v:.1} {unit}")
    } else {
        format!("{v:.2} {unit}")
    }
}

/// Marker shape and colour of a method.
fn style(method: &str) -> (&'static str, &'static str, &'static str) {
    match method {
        "kernel" => (
            "square",
            "#1f77b4",
            "construction kernel: plans × μ, no pencil error",
        ),
        "contour" => ("diamond", "#2ca02c", "route (a): closed vector contours"),
        "newton" => ("circle", "#d62728", "route (b): Newton, tol 1e-4 … 1e-14"),
        "chords" => (
            "triangle",
            "#9467bd",
            "diagrams: chords to midpoints, N = 12 … 3600",
        ),
        "central" => (
            "tri-down",
            "#8c564b",
            "diagrams: central differences, N = 12 … 3600",
        ),
        _ => (
            "cross",
            "#ff7f0e",
            "hand drafting emulated: pencil δ on the plans' μ",
        ),
    }
}

fn marker(s: &mut String, shape: &str, colour: &str, x: f64, y: f64) {
    use crate::presentation::drawing::canvas::fmt;
    let r = 1.4;
    let el = match shape {
        "square" => format!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"",
            fmt(x - r),
            fmt(y - r),
            fmt(2.0 * r),
            fmt(2.0 * r)
        ),
        "circle" => format!(
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
            fmt(x),
            fmt(y),
            fmt(r)
        ),
        "diamond" => format!(
            "<polygon points=\"{},{} {},{} {},{} {},{}\"",
            fmt(x),
            fmt(y - 1.3 * r),
            fmt(x + 1.3 * r),
            fmt(y),
            fmt(x),
            fmt(y + 1.3 * r),
            fmt(x - 1.3 * r),
            fmt(y)
        ),
        "triangle" => format!(
            "<polygon points=\"{},{} {},{} {},{}\"",
            fmt(x),
            fmt(y - 1.3 * r),
            fmt(x + 1.2 * r),
            fmt(y + 0.8 * r),
            fmt(x - 1.2 * r),
            fmt(y + 0.8 * r)
        ),
        "tri-down" => format!(
            "<polygon points=\"{},{} {},{} {},{}\"",
            fmt(x),
            fmt(y + 1.3 * r),
            fmt(x + 1.2 * r),
            fmt(y - 0.8 * r),
            fmt(x - 1.2 * r),
            fmt(y - 0.8 * r)
        ),
        _ => {
            s.push_str(&format!(
                "<path d=\"M{} {}L{} {}M{} {}L{} {}\" stroke=\"{colour}\" stroke-width=\"0.6\" fill=\"none\"/>\n",
                fmt(x - r),
                fmt(y - r),
                fmt(x + r),
                fmt(y + r),
                fmt(x - r),
                fmt(y + r),
                fmt(x + r),
                fmt(y - r)
            ));
            return;
        }
    };
    s.push_str(&format!(
        "{el} fill=\"{colour}\" fill-opacity=\"0.75\" stroke=\"{colour}\" stroke-width=\"0.3\"/>\n"
    ));
}

/// The log-log plot (mm): worst relative error of the rates against the
/// run time per position, one marker per method and setting.
pub fn to_svg(r: &Report, title: &str) -> String {
    use crate::presentation::drawing::canvas::{fmt, xml};
    let (w, h) = (215.0, 140.0);
    let (x0, x1, y0, y1) = (22.0, 128.0, 14.0, 122.0);
    let floor = 1e-17;
    let pts: Vec<(f64, f64, &Row)> = r
        .rows
        .iter()
        .map(|row| (row.time.max(1e-12), row.worst_rates().max(floor), row))
        .collect();
    let dec = |v: f64| v.log10();
    let (mut tx0, mut tx1) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut ey0, mut ey1) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(t, e, _) in &pts {
        tx0 = tx0.min(dec(t).floor());
        tx1 = tx1.max(dec(t).ceil());
        ey0 = ey0.min(dec(e).floor());
        ey1 = ey1.max(dec(e).ceil());
    }
    if tx1 <= tx0 {
        tx1 = tx0 + 1.0;
    }
    if ey1 <= ey0 {
        ey1 = ey0 + 1.0;
    }
    let px = |t: f64| x0 + (dec(t) - tx0) / (tx1 - tx0) * (x1 - x0);
    let py = |e: f64| y1 - (dec(e) - ey0) / (ey1 - ey0) * (y1 - y0);
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n"
    );
    s.push_str(&format!(
        "<text x=\"{}\" y=\"7\" font-size=\"3.6\">{}</text>\n",
        fmt(x0),
        xml(title)
    ));
    // Grid and decades.
    let mut k = tx0;
    while k <= tx1 + 1e-9 {
        let x = x0 + (k - tx0) / (tx1 - tx0) * (x1 - x0);
        s.push_str(&format!(
            "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#ccc\" stroke-width=\"0.2\"/>\n<text x=\"{0}\" y=\"{3}\" font-size=\"2.8\" text-anchor=\"middle\">10<tspan dy=\"-1.2\" font-size=\"2\">{4}</tspan></text>\n",
            fmt(x),
            fmt(y0),
            fmt(y1),
            fmt(y1 + 4.5),
            k as i32
        ));
        k += 1.0;
    }
    let step = if ey1 - ey0 > 10.0 { 2.0 } else { 1.0 };
    let mut k = ey0;
    while k <= ey1 + 1e-9 {
        let y = y1 - (k - ey0) / (ey1 - ey0) * (y1 - y0);
        s.push_str(&format!(
            "<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\" stroke=\"#ccc\" stroke-width=\"0.2\"/>\n",
            fmt(y),
            fmt(x0),
            fmt(x1)
        ));
        if ((k - ey0) / step).fract().abs() < 1e-9 {
            s.push_str(&format!(
                "<text x=\"{}\" y=\"{}\" font-size=\"2.8\" text-anchor=\"end\">10<tspan dy=\"-1.2\" font-size=\"2\">{}</tspan></text>\n",
                fmt(x0 - 1.5),
                fmt(y + 1.0),
                k as i32
            ));
        }
        k += 1.0;
    }
    s.push_str(&format!(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\" stroke-width=\"0.35\"/>\n",
        fmt(x0),
        fmt(y0),
        fmt(x1 - x0),
        fmt(y1 - y0)
    ));
    s.push_str(&format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"3\" text-anchor=\"middle\">run time per position, s</text>\n",
        fmt(0.5 * (x0 + x1)),
        fmt(y1 + 10.0)
    ));
    s.push_str(&format!(
        "<text transform=\"translate(6 {}) rotate(-90)\" font-size=\"3\" text-anchor=\"middle\">largest relative error of v, a, ω, ε</text>\n",
        fmt(0.5 * (y0 + y1))
    ));
    // Lines joining the settings of one method, then the markers.
    for method in ["newton", "chords", "central"] {
        let line: Vec<String> = pts
            .iter()
            .filter(|p| p.2.method == method)
            .map(|&(t, e, _)| format!("{},{}", fmt(px(t)), fmt(py(e))))
            .collect();
        if line.len() > 1 {
            let (_, colour, _) = style(method);
            s.push_str(&format!(
                "<polyline points=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"0.25\" stroke-dasharray=\"1 0.8\"/>\n",
                line.join(" ")
            ));
        }
    }
    for &(t, e, row) in &pts {
        let (shape, colour, _) = style(&row.method);
        marker(&mut s, shape, colour, px(t), py(e));
    }
    // Labels: the settings of a method whose errors agree within a factor
    // of 3 share one label, at the first of them.
    for method in ["newton", "chords", "central"] {
        let run: Vec<&(f64, f64, &Row)> = pts.iter().filter(|p| p.2.method == method).collect();
        let mut i = 0;
        while i < run.len() {
            let mut j = i;
            while j + 1 < run.len() && (run[j + 1].1 / run[i].1).log10().abs() < 0.48 {
                j += 1;
            }
            let short = |r: &Row| r.setting.replace("tol ", "").replace("N = ", "");
            let mut note = short(run[i].2);
            if j > i {
                note = format!("{note} … {}", short(run[j].2));
            }
            if method != "newton" {
                note = format!("N = {note}");
            }
            // Diagrams: only the coarsest and the finest, to stay readable.
            if method != "newton" && i != 0 && j + 1 != run.len() {
                i = j + 1;
                continue;
            }
            let (x, y) = (px(run[i].0), py(run[i].1));
            let (_, colour, _) = style(method);
            let left = method == "central";
            s.push_str(&format!(
                "<text x=\"{}\" y=\"{}\" font-size=\"2.1\" fill=\"{colour}\" text-anchor=\"{}\">{}</text>\n",
                fmt(if left { x - 2.4 } else { x + 2.4 }),
                fmt(y + 0.8),
                if left { "end" } else { "start" },
                xml(&note)
            ));
            i = j + 1;
        }
    }
    // Legend on the right.
    let mut seen: Vec<&str> = Vec::new();
    let mut ly = y0 + 4.0;
    for row in &r.rows {
        if seen.contains(&row.method.as_str()) {
            continue;
        }
        seen.push(&row.method);
        let (shape, colour, label) = style(&row.method);
        marker(&mut s, shape, colour, x1 + 5.0, ly - 0.9);
        let words: Vec<&str> = label.split(": ").collect();
        s.push_str(&format!(
            "<text x=\"{}\" y=\"{}\" font-size=\"2.6\">{}</text>\n",
            fmt(x1 + 8.5),
            fmt(ly),
            xml(words[0])
        ));
        if words.len() > 1 {
            ly += 3.4;
            s.push_str(&format!(
                "<text x=\"{}\" y=\"{}\" font-size=\"2.3\" fill=\"#444\">{}</text>\n",
                fmt(x1 + 8.5),
                fmt(ly),
                xml(words[1])
            ));
        }
        ly += 6.5;
    }
    s.push_str(&format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"2.2\" fill=\"#444\">{} positions; errors below 1e-17 drawn at 1e-17</text>\n",
        fmt(x1 + 3.0),
        fmt(y1),
        r.positions
    ));
    s.push_str("</svg>\n");
    s
}
