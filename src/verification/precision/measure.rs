//! The measurement: every method run on the scene's positions, its errors
//! against the extended-precision reference and its run time, as rows.

use super::{Report, Row, Settings, Stat};
use crate::error::{Error, Result};
use crate::format::sci;
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

/// Errors of one method collected over positions, per kind.
#[derive(Default)]
struct Errors {
    e: [Vec<f64>; 5],
    /// Positions (× seeds) compared ([`Row::compared`], tests only).
    #[cfg(feature = "internals")]
    n: usize,
}

impl Errors {
    fn stats(&mut self) -> [Option<Stat>; 5] {
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
        out
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
        #[cfg(feature = "internals")]
        {
            self.n += 1;
        }
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

/// Run every method on the scene (as [`run_watched`], watched by no one).
#[cfg(feature = "internals")]
pub fn run(an: &Analysis, set: &Settings) -> Result<Report> {
    run_watched(an, set, &crate::progress::Silent)
}

/// Run every method on the scene, the reference solutions' sweep told
/// to `progress`.
pub fn run_watched(
    an: &Analysis,
    set: &Settings,
    progress: &dyn crate::progress::Progress,
) -> Result<Report> {
    let m = &an.mech;
    if m.scene.several_inputs() {
        return Err(Error::scene(
            "/input",
            "the precision report measures its methods along one input (finite differences and sweeps in its coordinate); this scene has several inputs",
        ));
    }
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
        .filter(|&l| an.link(l) && l != m.frame())
        .collect();
    let truth = truths(an, &qs, &links, progress)?;
    let bench = Bench {
        an,
        set,
        setup: an.setup(),
        truth,
        qs,
        links,
        rate,
        rate2,
        // The construction kernel, without pencil noise.
        drafting: Drafting {
            delta: set.delta,
            ..an.drafting
        },
    };
    let mut rows = vec![bench.kernel()?, bench.contour()?];
    // Route (b) at each Newton tolerance.
    for &tol in &set.newton_tols {
        rows.push(bench.newton(tol)?);
    }
    // Kinematic diagrams by numerical differentiation (a crank only).
    if crank {
        for chords in [true, false] {
            for &n in &set.diagram_ns {
                rows.extend(bench.diagram(chords, n)?);
            }
        }
    }
    // Hand drafting emulated: the kernel with pencil noise.
    if set.seeds > 0 {
        rows.push(bench.hand()?);
    }
    Ok(Report {
        positions: bench.qs.len(),
        rows,
    })
}

/// The reference at every evaluation position `qs`: the starts in order
/// (on the sketch's branch), then each refined on its own, in parallel,
/// the sweep told to `progress`.
fn truths(
    an: &Analysis,
    qs: &[f64],
    links: &[usize],
    progress: &dyn crate::progress::Progress,
) -> Result<Vec<Truth>> {
    let m = &an.mech;
    let mut re = Reference::new(an)?;
    let starts: Vec<(f64, Configuration)> = qs.iter().copied().zip(re.starts(qs)?).collect();
    crate::progress::map(&starts, "reference", progress, |(q, c)| -> Result<Truth> {
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
    .collect::<Result<Vec<Truth>>>()
}

/// The methods' bench: the scene, the evaluation positions `qs` with the
/// reference there, the solved links, the input's rates.
struct Bench<'a> {
    an: &'a Analysis,
    set: &'a Settings,
    setup: Setup<'a>,
    truth: Vec<Truth>,
    qs: Vec<f64>,
    links: Vec<usize>,
    rate: f64,
    rate2: f64,
    drafting: Drafting,
}

/// A method's row: its errors' statistics and its time per position.
fn row(method: &str, setting: String, time: f64, mut errs: Errors) -> Row {
    Row {
        method: method.into(),
        setting,
        time,
        err: errs.stats(),
        #[cfg(feature = "internals")]
        compared: errs.n,
    }
}

impl Bench<'_> {
    fn drive(&self, q: f64) -> Drive {
        Drive {
            q,
            rate: self.rate,
            rate2: self.rate2,
        }
    }

    fn positions(&self) -> Result<PositionSolver<'_>> {
        let an = self.an;
        PositionSolver::new(&an.mech, &an.structure, an.need.clone())
    }

    /// What a route's motions `mo` give (the points on the positions `c`,
    /// else on the motions' poses).
    fn got_of_motion(&self, c: Option<&Configuration>, mo: &[Option<Motion>]) -> Got {
        let (an, links) = (self.an, &self.links);
        let m = &an.mech;
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
    }

    /// What the construction kernel gives at `q` (positions `c`) drafted
    /// as `d`.
    fn kernel_got(&self, c: &Configuration, q: f64, d: Drafting) -> Result<Got> {
        let (an, links) = (self.an, &self.links);
        let m = &an.mech;
        let plans = build_plans_numbers(&self.setup, c, self.drive(q), Order::Acceleration, d)?;
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
    }

    /// The construction kernel, without pencil noise.
    fn kernel(&self) -> Result<Row> {
        let size = self.an.mech.size;
        let mut ps = self.positions()?;
        let mut errs = Errors::default();
        for t in &self.truth {
            let c = ps.solve(t.q)?;
            errs.add(t, &self.kernel_got(&c, t.q, self.drafting)?, size);
        }
        let time = time_per_call(self.set.min_time, || {
            for &q in &self.qs {
                let c = ps.solve(q)?;
                let drive = self.drive(q);
                build_plans_numbers(&self.setup, &c, drive, Order::Acceleration, self.drafting)?;
            }
            Ok(())
        })? / self.qs.len() as f64;
        Ok(row("kernel", String::new(), time, errs))
    }

    /// Route (a).
    fn contour(&self) -> Result<Row> {
        let an = self.an;
        let m = &an.mech;
        let mut ps = self.positions()?;
        let mut errs = Errors::default();
        let solve = |c: &Configuration, q: f64| {
            let order = Order::Acceleration;
            contour::solve(m, &an.structure, &an.need, c, self.drive(q), order)
        };
        for t in &self.truth {
            let c = ps.solve(t.q)?;
            let mo = solve(&c, t.q)?;
            errs.add(t, &self.got_of_motion(Some(&c), &mo), m.size);
        }
        let time = time_per_call(self.set.min_time, || {
            for &q in &self.qs {
                let c = ps.solve(q)?;
                solve(&c, q)?;
            }
            Ok(())
        })? / self.qs.len() as f64;
        Ok(row("contour", String::new(), time, errs))
    }

    /// Route (b) at the Newton tolerance `tol`.
    fn newton(&self, tol: f64) -> Result<Row> {
        let an = self.an;
        let m = &an.mech;
        let (rate, rate2) = (self.rate, self.rate2);
        let ns = NewtonSettings {
            tol,
            ..NewtonSettings::default()
        };
        let mut cs = ConstraintSolver::new(m, &an.include, ns);
        let mut errs = Errors::default();
        for t in &self.truth {
            cs.solve_positions(t.q)?;
            let mo = cs.solve_rates(rate, rate2, Order::Acceleration)?;
            errs.add(t, &self.got_of_motion(None, &mo), m.size);
        }
        let time = time_per_call(self.set.min_time, || {
            let mut cs = ConstraintSolver::new(m, &an.include, ns);
            for &q in &self.qs {
                cs.solve_positions(q)?;
                cs.solve_rates(rate, rate2, Order::Acceleration)?;
            }
            Ok(())
        })? / self.qs.len() as f64;
        Ok(row("newton", format!("tol {}", sci(tol)), time, errs))
    }

    /// A kinematic diagram by numerical differentiation over `n` steps a
    /// revolution (`chords`, else central differences); none when no
    /// position's stencil assembles.
    fn diagram(&self, chords: bool, n: usize) -> Result<Option<Row>> {
        let an = self.an;
        let (rate, rate2) = (self.rate, self.rate2);
        let h = std::f64::consts::TAU / n as f64;
        // Stencil offsets in steps of h.
        let offs: &[f64] = if chords {
            &[-1.0, -0.5, 0.0, 0.5, 1.0]
        } else {
            &[-1.0, 0.0, 1.0]
        };
        let mut ps = self.positions()?;
        let mut errs = Errors::default();
        let mut evals = 0usize;
        let diff = |ps: &mut PositionSolver, q: f64| -> Option<Got> {
            let mut samples = Vec::with_capacity(offs.len());
            for &o in offs {
                samples.push(sample(an, &self.links, ps.solve(q + o * h).ok()?));
            }
            Some(differentiate(&samples, h, chords, rate, rate2))
        };
        for t in &self.truth {
            if let Some(g) = diff(&mut ps, t.q) {
                errs.add(t, &g, an.mech.size);
                evals += 1;
            }
            // Back on the path for the next position.
            let _ = ps.solve(t.q);
        }
        if evals == 0 {
            return Ok(None);
        }
        let time = time_per_call(self.set.min_time, || {
            for &q in &self.qs {
                let _ = diff(&mut ps, q);
            }
            Ok(())
        })? / (self.qs.len() * offs.len()) as f64;
        let method = if chords { "chords" } else { "central" };
        Ok(Some(row(method, format!("N = {n}"), time, errs)))
    }

    /// Hand drafting emulated: the kernel with pencil noise.
    fn hand(&self) -> Result<Row> {
        let set = self.set;
        let mut ps = self.positions()?;
        let configs: Vec<Configuration> = self
            .qs
            .iter()
            .map(|&q| ps.solve(q))
            .collect::<Result<_>>()?;
        let mut errs = Errors::default();
        let t0 = Instant::now();
        let mut built = 0usize;
        for seed in 0..set.seeds {
            let d = Drafting {
                variant: Variant {
                    jitter: Some(seed),
                    ..Variant::default()
                },
                ..self.drafting
            };
            for (t, c) in self.truth.iter().zip(&configs) {
                if let Ok(mut g) = self.kernel_got(c, t.q, d) {
                    // The plan of the mechanism is not drawn by hand here.
                    g.places = None;
                    errs.add(t, &g, self.an.mech.size);
                    built += 1;
                }
            }
        }
        let time = t0.elapsed().as_secs_f64() / built.max(1) as f64;
        let setting = format!("δ = {} mm, {} seeds", set.delta, set.seeds);
        Ok(row("hand", setting, time, errs))
    }
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
