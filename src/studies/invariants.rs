//! Motion-law invariants of an output (paper `003`): the phases of the
//! output over a crank revolution (recess, dwell, approach) and, for each
//! moving phase of stroke S over crank angle φ_p, with x = (φ − φ_start)/φ_p:
//!
//! - displacement a(x) = s/S, velocity b(x) = (ds/dx)/S,
//!   acceleration c(x) = (d²s/dx²)/S, kinetic power d(x) = b·c;
//! - their peak constants B = max|b|, C = max|c|, D = max|d|.
//!
//! The derivatives are the route's transfer functions (ds/dφ, d²s/dφ² at
//! unit crank rate, exact to rounding), not differences of samples; a
//! peak is located on a grid and refined by golden-section search, so the
//! constants are exact to about 1e-12 for smooth laws.

use crate::error::{Error, Result};
use crate::geom::{Pose, wrap_pi};
use crate::kinematics::analytic::{Order, contour};
use crate::kinematics::positions::PositionSolver;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use std::f64::consts::TAU;

/// A motion law on x ∈ [0, 1]: (a, b, c) = (s/S, s'/S, s''/S) at x.
pub trait Law {
    fn at(&self, x: f64) -> (f64, f64, f64);
}

impl<F: Fn(f64) -> (f64, f64, f64)> Law for F {
    fn at(&self, x: f64) -> (f64, f64, f64) {
        self(x)
    }
}

/// The peak constants of a law and where they are.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Peaks {
    /// B = max|b|, C = max|c|, D = max|d| …
    pub b: f64,
    pub c: f64,
    pub d: f64,
    /// … at these x.
    pub x_b: f64,
    pub x_c: f64,
    pub x_d: f64,
}

/// Golden-section search for the maximum of `f` on [lo, hi].
fn golden_max(f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..80 {
        if hi - lo <= 1e-13 {
            break;
        }
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        }
    }
    if f1 > f2 { (x1, f1) } else { (x2, f2) }
}

/// The maximum of |g| on [0, 1]: the best of `n + 1` grid points, refined
/// between its neighbours; the ends count as they are.
fn peak(g: &dyn Fn(f64) -> f64, n: usize) -> (f64, f64) {
    let h = 1.0 / n as f64;
    let (mut k, mut best) = (0, f64::NEG_INFINITY);
    for i in 0..=n {
        let v = g(i as f64 * h).abs();
        if v > best {
            (k, best) = (i, v);
        }
    }
    let lo = (k as f64 - 1.0).max(0.0) * h;
    let hi = ((k + 1) as f64 * h).min(1.0);
    let (x, v) = golden_max(&|x| g(x).abs(), lo, hi);
    if v > best {
        (x, v)
    } else {
        (k as f64 * h, best)
    }
}

/// B, C, D of a law, from `n` grid intervals and refinement.
pub fn peaks(law: &dyn Law, n: usize) -> Peaks {
    let (x_b, b) = peak(&|x| law.at(x).1, n);
    let (x_c, c) = peak(&|x| law.at(x).2, n);
    let (x_d, d) = peak(
        &|x| {
            let (_, b, c) = law.at(x);
            b * c
        },
        n,
    );
    Peaks {
        b,
        c,
        d,
        x_b,
        x_c,
        x_d,
    }
}

/// The phases of an output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhaseKind {
    /// Moving away from the lower extreme (the working stroke).
    Recess,
    /// At rest at an extreme, within the tolerance.
    Dwell,
    /// Returning.
    Approach,
}

impl PhaseKind {
    pub fn name(&self) -> &'static str {
        match self {
            PhaseKind::Recess => "recess",
            PhaseKind::Dwell => "dwell",
            PhaseKind::Approach => "approach",
        }
    }
}

/// One phase: from crank angle `start` through `span` (rad, in the sense
/// of rotation), its stroke and, for a moving phase, the peak constants.
#[derive(Clone, Debug)]
pub struct Phase {
    pub kind: PhaseKind,
    pub start: f64,
    pub span: f64,
    /// Output coordinate at the start and at the end (m or rad).
    pub s0: f64,
    pub s1: f64,
    /// Stroke |s1 − s0| (for a dwell: the largest deviation within it).
    pub stroke: f64,
    pub peaks: Option<Peaks>,
}

/// What to analyse and how.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Output link (index): a slider on a frame guide (its slide) or any
    /// link (its angle).
    pub output: usize,
    /// Dwell tolerance E, relative to the whole stroke.
    pub tolerance: f64,
    /// Shortest dwell reported, rad: a smooth extreme stays within E over
    /// a few degrees without being a dwell.
    pub min_dwell: f64,
    /// Grid intervals over a revolution for the phases, and per phase for
    /// the peaks.
    pub n: usize,
}

/// The output coordinate and its two transfer functions at crank angle φ.
pub struct Output<'a> {
    an: &'a Analysis,
    ps: PositionSolver<'a>,
    need: Vec<bool>,
    out: usize,
    /// For a slider on a frame guide: the guide's direction.
    slide: Option<kurbo::Vec2>,
    /// A point of the slider on the guide (its local coordinates).
    local: kurbo::Vec2,
    /// For a point's path: the point, and the sense of the crank (±1).
    point: Option<(usize, f64)>,
}

impl<'a> Output<'a> {
    pub fn new(an: &'a Analysis, out: usize) -> Result<Output<'a>> {
        let m = &an.mech;
        if m.scene.several_inputs() {
            return Err(Error::scene(
                "/input",
                "motion-law invariants and kinematic diagrams are functions of one input (a crank's angle or a slider's slide); this scene has several inputs",
            ));
        }
        if out == m.frame() || out >= m.links.len() {
            return Err(Error::scene("output", "the output must be a moving link"));
        }
        let mut need = an.structure.needed_for(&[out]);
        for (n, own) in need.iter_mut().zip(&an.need) {
            *n |= *own;
        }
        let pr = m
            .prismatics
            .iter()
            .find(|p| p.slider == out && p.guide == m.frame());
        Ok(Output {
            an,
            ps: PositionSolver::new(m, &an.structure, need.clone())?,
            need,
            out,
            slide: pr.map(|p| p.line(&Pose::IDENTITY).dir),
            local: pr.map(|p| p.slider_local).unwrap_or_default(),
            point: None,
        })
    }

    /// A point's motion along its path: `at` gives the derivatives of the
    /// arc length in the sense of the crank's rotation, ds/dψ = |v| and
    /// d²s/dψ² = v·a/|v| (ψ = ±φ), returned as the link outputs are
    /// (times the sense, so that callers treat both alike); the arc length
    /// itself (NaN here) is the integral of |v|.
    pub fn point(an: &'a Analysis, p: usize) -> Result<Output<'a>> {
        let m = &an.mech;
        let omega = m.scene.input.rates().0;
        let carrier = m
            .links_of_point(p)
            .into_iter()
            .find(|&l| l != m.frame())
            .ok_or_else(|| Error::scene("point", "a point of the frame does not move"))?;
        let mut out = Output::new(an, carrier)?;
        out.slide = None;
        out.point = Some((p, if omega < 0.0 { -1.0 } else { 1.0 }));
        Ok(out)
    }

    /// (s, ds/dφ, d²s/dφ²) at crank angle φ, reached continuously.
    pub fn at(&mut self, phi: f64) -> Result<(f64, f64, f64)> {
        let m = &self.an.mech;
        let c = self.ps.solve(phi)?;
        let mo = contour::transfer(
            m,
            &self.an.structure,
            &self.need,
            &c,
            phi,
            Order::Acceleration,
        )?;
        let x = mo[self.out].expect("output solved");
        if let Some((p, dir)) = self.point {
            let at = c.point(m, self.out, p);
            let (v, a) = (x.velocity(at), x.acceleration(at));
            let speed = v.hypot();
            let tangential = if speed > 0.0 { v.dot(a) / speed } else { 0.0 };
            return Ok((f64::NAN, dir * speed, dir * tangential));
        }
        Ok(match self.slide {
            Some(u) => {
                let p = c.pose(self.out).apply(self.local);
                (
                    u.dot(p.to_vec2()),
                    u.dot(x.velocity(p)),
                    u.dot(x.acceleration(p)),
                )
            }
            None => (c.pose(self.out).angle, x.omega, x.epsilon),
        })
    }
}

/// The phases of the output over one revolution and their invariants.
pub fn phases(an: &Analysis, set: &Settings) -> Result<Vec<Phase>> {
    let m = &an.mech;
    let mut out = Output::new(an, set.output)?;
    let InputSpec::Crank { omega, .. } = m.scene.input else {
        return Err(Error::scene(
            "/input",
            "motion-law invariants need a crank input (phases over a revolution)",
        ));
    };
    let dir = if omega < 0.0 { -1.0 } else { 1.0 };
    let n = set.n.max(36);
    let turning = out.slide.is_none();
    let grid = Grid {
        an,
        set,
        dir,
        n,
        turning,
    };
    // Start at the lower extreme of the output, found exactly.
    let (start, s) = grid.start_at_lower_extreme(&mut out)?;
    let (lo, hi) = s
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    let total = hi - lo;
    if total <= 1e-12 * m.size.max(1.0) {
        return Err(Error::scene("output", "the output does not move"));
    }
    let sw = Sweep {
        grid,
        start,
        s,
        lo,
        hi,
        e: set.tolerance * total,
        h: TAU / n as f64,
    };
    let (e, h) = (sw.e, sw.h);
    let high = sw.high_dwell();
    let low = sw.low_dwell();
    let x_hi = sw.upper_extreme();
    // Phase boundaries in grid units from the start (the lower extreme).
    let recess_from = match low {
        Some((b, _)) => sw.cross(&mut out, b, lo + e)?,
        None => 0.0,
    };
    let (recess_to, approach_from) = match high {
        Some((a, b)) => (
            sw.cross(&mut out, a - 1, hi - e)?,
            sw.cross(&mut out, b, hi - e)?,
        ),
        None => (x_hi, x_hi),
    };
    let approach_to = match low {
        Some((_, a)) => sw.cross(&mut out, a - 1, lo + e)?,
        None => n as f64,
    };
    let mut list = Vec::new();
    for (kind, x0, x1) in [
        (PhaseKind::Recess, recess_from, recess_to),
        (PhaseKind::Approach, approach_from, approach_to),
    ] {
        if kind == PhaseKind::Approach && high.is_some() {
            let span = h * (approach_from - recess_to);
            list.push(sw.dwell(&mut out, recess_to, approach_from, span)?);
        }
        list.push(sw.phase(&mut out, kind, x0, x1)?);
    }
    if low.is_some() {
        // Around the lower extreme, over the start of the revolution.
        let span = h * (n as f64 - approach_to + recess_from);
        list.push(sw.dwell(&mut out, approach_to, recess_from, span)?);
    }
    Ok(list)
}

/// The output at crank angle φ; a link's angle (`turning`) kept near
/// `near`.
fn value(out: &mut Output, phi: f64, near: f64, turning: bool) -> Result<f64> {
    let v = out.at(phi)?.0;
    Ok(if turning { near + wrap_pi(v - near) } else { v })
}

/// The grid the output is sampled on: `n` steps of a revolution in the
/// sense `dir` of the crank; `turning`: the output is a link's angle.
#[derive(Clone, Copy)]
struct Grid<'a> {
    an: &'a Analysis,
    set: &'a Settings,
    dir: f64,
    n: usize,
    turning: bool,
}

impl<'a> Grid<'a> {
    /// The output over a revolution from crank angle `start`, a link's
    /// angle continued from one grid point to the next.
    fn sample(&self, out: &mut Output, start: f64) -> Result<Vec<f64>> {
        let (n, dir) = (self.n, self.dir);
        let mut s: Vec<f64> = Vec::with_capacity(n + 1);
        for k in 0..=n {
            let near = s.last().copied().unwrap_or(0.0);
            let phi = start + dir * TAU * k as f64 / n as f64;
            let v = out.at(phi)?.0;
            s.push(if self.turning && k > 0 {
                near + wrap_pi(v - near)
            } else {
                v
            });
        }
        Ok(s)
    }

    /// The crank angle of the output's lower extreme, found exactly, and
    /// the output sampled from there (`out` afresh when the start moved).
    fn start_at_lower_extreme(&self, out: &mut Output<'a>) -> Result<(f64, Vec<f64>)> {
        let (an, set, n, dir) = (self.an, self.set, self.n, self.dir);
        let mut start = an.working_stroke_start(set.output)?;
        let mut s = self.sample(out, start)?;
        if self.turning && (s[n] - s[0]).abs() > 1.0 {
            return Err(Error::scene(
                "output",
                "the output link turns fully: it has no recess and approach (choose a rocking link or a slider)",
            ));
        }
        let k_lo = (0..=n).min_by(|&a, &b| s[a].total_cmp(&s[b])).unwrap();
        if k_lo != 0 && k_lo != n {
            let h = TAU / n as f64;
            let base = s[k_lo];
            let c0 = start + dir * h * k_lo as f64;
            let (t, _) = golden_max(
                &|t| {
                    let mut o = Output::new(an, set.output).expect("checked");
                    o.at(c0).ok();
                    -value(&mut o, c0 + dir * t, base, self.turning).unwrap_or(f64::INFINITY)
                },
                -h,
                h,
            );
            start = c0 + dir * t;
            *out = Output::new(an, set.output)?;
            s = self.sample(out, start)?;
        }
        Ok((start, s))
    }
}

/// The output sampled over a revolution from its lower extreme: the
/// samples `s`, their range [lo, hi], the dwell tolerance `e`, the step
/// `h` of the grid.
struct Sweep<'a> {
    grid: Grid<'a>,
    start: f64,
    s: Vec<f64>,
    lo: f64,
    hi: f64,
    e: f64,
    h: f64,
}

impl Sweep<'_> {
    /// The crank angle at `k` grid steps from the start.
    fn angle(&self, k: f64) -> f64 {
        self.start + self.grid.dir * self.h * k
    }

    /// The output `x` grid steps from the start, kept near the lower
    /// extreme.
    fn level(&self, out: &mut Output, x: f64) -> Result<f64> {
        value(out, self.angle(x), self.lo, self.grid.turning)
    }

    /// The dwell at the upper extreme: the longest run of grid points
    /// within E of it, if long enough.
    fn high_dwell(&self) -> Option<(usize, usize)> {
        let (n, s) = (self.grid.n, &self.s);
        let inside = |k: usize| self.hi - s[k] <= self.e;
        let mut best: Option<(usize, usize)> = None;
        let mut k = 0;
        while k <= n {
            if inside(k) {
                let k0 = k;
                while k < n && inside(k + 1) {
                    k += 1;
                }
                if best.is_none_or(|(a, b)| k - k0 > b - a) {
                    best = Some((k0, k));
                }
            }
            k += 1;
        }
        best.filter(|(a, b)| self.h * (b - a) as f64 >= self.grid.set.min_dwell)
    }

    /// The dwell at the lower extreme runs over the start: the grid points
    /// within E at the start and at the end of the revolution.
    fn low_dwell(&self) -> Option<(usize, usize)> {
        let (n, s, lo, e) = (self.grid.n, &self.s, self.lo, self.e);
        let first_out = (0..=n).find(|&k| s[k] - lo > e);
        let last_out = (0..=n).rev().find(|&k| s[k] - lo > e);
        match (first_out, last_out) {
            (Some(f), Some(l))
                if self.h * ((f - 1) + (n - l - 1)) as f64 >= self.grid.set.min_dwell =>
            {
                Some((f - 1, l + 1))
            }
            _ => None,
        }
    }

    /// Where the output crosses `level` between grid points k and k + 1.
    fn cross(&self, out: &mut Output, k: usize, level: f64) -> Result<f64> {
        let s = &self.s;
        let (mut a, mut b) = (k as f64, k as f64 + 1.0);
        let fa = s[k] - level;
        for _ in 0..60 {
            let mid = 0.5 * (a + b);
            let f = value(out, self.angle(mid), s[k], self.grid.turning)? - level;
            if (f < 0.0) == (fa < 0.0) {
                a = mid;
            } else {
                b = mid;
            }
        }
        Ok(0.5 * (a + b))
    }

    /// The upper extreme in grid steps, refined (when it is not a dwell).
    fn upper_extreme(&self) -> f64 {
        let (an, set, n, s) = (self.grid.an, self.grid.set, self.grid.n, &self.s);
        let k_hi = (0..=n).max_by(|&a, &b| s[a].total_cmp(&s[b])).unwrap();
        let base = s[k_hi];
        let (t, _) = golden_max(
            &|t| {
                let mut o = Output::new(an, set.output).expect("checked");
                o.at(self.angle(k_hi as f64)).ok();
                value(&mut o, self.angle(k_hi as f64 + t), base, self.grid.turning)
                    .unwrap_or(f64::NEG_INFINITY)
            },
            -1.0,
            1.0,
        );
        k_hi as f64 + t
    }

    /// A dwell from `x0` to `x1` grid steps from the start, `span` long.
    fn dwell(&self, out: &mut Output, x0: f64, x1: f64, span: f64) -> Result<Phase> {
        let (s0, s1) = (self.level(out, x0)?, self.level(out, x1)?);
        Ok(Phase {
            kind: PhaseKind::Dwell,
            start: self.angle(x0),
            span,
            s0,
            s1,
            stroke: self.e,
            peaks: None,
        })
    }

    /// The phase `kind` from `x0` to `x1` grid steps from the start, with
    /// the peaks of its law.
    fn phase(&self, out: &mut Output, kind: PhaseKind, x0: f64, x1: f64) -> Result<Phase> {
        let (dir, turning, n) = (self.grid.dir, self.grid.turning, self.grid.n);
        let (p0, span) = (self.angle(x0), self.h * (x1 - x0));
        let (s0, s1) = (self.level(out, x0)?, self.level(out, x1)?);
        let stroke = (s1 - s0).abs();
        let sign = (s1 - s0).signum();
        // The law of the phase in x: a = (s − s0)/S, b = s'·φ_p/S, c = s''·φ_p²/S.
        let cell = std::cell::RefCell::new(out);
        let law = |x: f64| -> (f64, f64, f64) {
            let o: &mut Output = &mut cell.borrow_mut();
            match o.at(p0 + dir * span * x) {
                Ok((v, v1, v2)) => {
                    let v = if turning { s0 + wrap_pi(v - s0) } else { v };
                    (
                        sign * (v - s0) / stroke,
                        sign * dir * v1 * span / stroke,
                        sign * v2 * span * span / stroke,
                    )
                }
                Err(_) => (f64::NAN, f64::NAN, f64::NAN),
            }
        };
        let pk = peaks(&law, (n / 4).max(64));
        if !(pk.b.is_finite() && pk.c.is_finite() && pk.d.is_finite()) {
            return Err(Error::singular(
                crate::kinematics::positions::describe_input(&self.grid.an.mech, &[p0]),
                format!("the {} phase could not be evaluated", kind.name()),
            ));
        }
        Ok(Phase {
            kind,
            start: p0,
            span,
            s0,
            s1,
            stroke,
            peaks: Some(pk),
        })
    }
}

/// The default output: the last link of the last group, passing over a
/// hydraulic cylinder's barrel and rod (a driving slider on a moving
/// guide: they are the input, the link they move is the output).
pub fn default_output(an: &Analysis) -> usize {
    let m = &an.mech;
    let cylinder = |l: usize| {
        m.scene.inputs().any(|i| match *i {
            InputSpec::Slider { pair, .. } => {
                let pr = &m.prismatics[pair];
                pr.guide != m.frame() && (pr.guide == l || pr.slider == l)
            }
            InputSpec::Crank { .. } => false,
        })
    };
    let links = an
        .structure
        .groups
        .last()
        .map(|g| g.links())
        .unwrap_or_default();
    links
        .iter()
        .rev()
        .copied()
        .find(|&l| !cylinder(l))
        .or(links.last().copied())
        .unwrap_or(m.scene.input.link())
}
