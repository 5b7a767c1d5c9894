//! Kinematic diagrams (lecture `000`, "Дослідження руху механізмів методом
//! кінематичних діаграм"): the displacement diagram of an output over one
//! revolution of the crank from the start of the working stroke, and its
//! graphical differentiation by chords, as the lecture draws it:
//!
//! - the displacement curve through N + 1 points 0, 1′, 2′ … at equal crank
//!   angles (scales μ_s, μ_φ = 2π/l);
//! - its chords; from the pole P1 at distance H1 left of the origin, rays
//!   parallel to the chords cut the ordinate axis at y′ᵢ = H1·Δy/Δx: the
//!   mean velocity analogue of each interval, carried to the interval's
//!   midpoint, at scale μ_s′ = μ_s/(H1·μ_φ);
//! - the same from the velocity diagram with the pole P2 at H2 for the
//!   acceleration analogue (μ_s″ = μ_s′/(H2·μ_φ)), at the nodes;
//! - graphical integration by chords back: through each interval a segment
//!   parallel to the ray from P to the interval's midpoint ordinate
//!   (μ_s = μ_s′·μ_φ·H);
//! - the lecture's numerical formulas: central differences with three-point
//!   one-sided formulas at the ends, and trapezoids.
//!
//! Every numerical curve is compared with the analytic one (route (a)'s
//! transfer functions). The diagrams are of analogues (per radian of the
//! crank); with a constant ω1 the time diagrams follow by μ_t = μ_φ/ω1,
//! v = ω1·s′, a = ω1²·s″.
//!
//! With a driving slider (a hydraulic cylinder) the abscissa is its slide
//! s over the stroke the scene's positions span (from the least to the
//! greatest), N intervals, and the analogues are per metre of the slide;
//! the curves do not close, so the acceleration's chord at node 0 is the
//! first chord of the velocity diagram (a one-sided difference).

use crate::error::{Error, Result};
use crate::kinematics::construction::scale::standard_scale;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::studies::invariants::Output;
use std::f64::consts::TAU;

/// Gauss–Legendre nodes and weights on [−1, 1], 8 points: exact for
/// polynomials of degree 15 (the independent mean of s′ over an interval).
const GAUSS8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_65, 0.362_683_783_378_362),
    (0.183_434_642_495_65, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// Room for the displacement curve, and for each derived curve either side
/// of its abscissa, mm: the three diagrams fit an A4 sheet one above the
/// other.
const HEIGHT_S: f64 = 40.0;
const HEIGHT_DERIVED: f64 = 25.0;

/// Samples per interval of the analytic curves drawn for comparison.
pub const DENSE: usize = 12;

/// The diagrams of one output with N intervals per revolution.
#[derive(Clone, Debug)]
pub struct Diagrams {
    /// The output link (a slider on a frame guide: its slide; else its
    /// angle), or the link carrying `point`.
    pub output: usize,
    /// A point's path (its arc length), instead of the link's coordinate.
    pub point: Option<usize>,
    /// It is a slide (m), not an angle (rad).
    pub slide: bool,
    pub n: usize,
    /// Crank angle of node 0 (the start of the working stroke) and the
    /// sense of rotation (±1); a driving slider: its slide at node 0 (the
    /// start of the stroke), +1.
    pub phi0: f64,
    pub dir: f64,
    /// +1 or −1: the output's coordinate turned so that the displacement
    /// from the extreme position is positive (the working stroke's sense).
    #[cfg(feature = "internals")]
    pub along: f64,
    /// Crank angle step, rad (a driving slider: the slide's step, m).
    pub h: f64,
    /// The abscissa's extent: a revolution, 2π rad (a driving slider: its
    /// stroke, m).
    pub span: f64,
    /// The abscissa is a driving slider's slide over its stroke (m), not
    /// a crank's revolution: the curves do not close.
    pub stroke: bool,
    /// Displacement from node 0 at the nodes, and the analytic s′, s″ there
    /// (per rad of the crank, in the sense of rotation).
    pub s: Vec<f64>,
    pub ds: Vec<f64>,
    pub dds: Vec<f64>,
    /// Analytic s′ at the interval midpoints.
    pub ds_mid: Vec<f64>,
    /// The analytic (s, s′, s″) at DENSE samples per interval, for drawing.
    pub dense: Vec<(f64, f64, f64)>,
    /// Scales: μ_s (m/mm or rad/mm), μ_φ (rad/mm), the pole distances (mm),
    /// μ_s′ = μ_s/(H1·μ_φ), μ_s″ = μ_s′/(H2·μ_φ).
    pub mu_s: f64,
    pub mu_phi: f64,
    pub h1: f64,
    pub h2: f64,
    pub mu_v: f64,
    pub mu_a: f64,
    /// The rays' ordinates on the drawing (mm): y′ at the interval
    /// midpoints (P1), y″ at the nodes 0…N−1 (P2, periodic).
    pub y1: Vec<f64>,
    pub y2: Vec<f64>,
}

/// Errors of the numerical curves against the analytic ones: the largest
/// absolute error, relative to the largest magnitude of the quantity, and
/// where (node or midpoint index).
#[derive(Clone, Copy, Debug, Default)]
pub struct Errors {
    /// Chords: s′ at the midpoints.
    pub chord_v: (f64, usize),
    /// Chords of the chord velocities: s″ at the nodes.
    pub chord_a: (f64, usize),
    /// Central differences (three-point ends): s′ at the nodes; s″ (the
    /// formulas applied twice) inside, and at the two nodes next to each
    /// end, where the one-sided formula of a one-sided result is of the
    /// first order only.
    pub central_v: (f64, usize),
    pub central_a: (f64, usize),
    pub central_a_ends: (f64, usize),
    /// Graphical integration by chords of the analytic s′ at the midpoints,
    /// and trapezoids of the analytic s′ at the nodes: s at the nodes.
    pub chord_s: (f64, usize),
    pub trapezoid_s: (f64, usize),
}

/// The displacements `s` from node 0 (the value there returned), measured
/// along the working stroke: the displacement from the extreme position
/// positive (s ≥ 0 for a slider or a rocker that goes out and back over
/// a `cycle`), as the lecture draws it; its rates `ds`, `dds` follow. The
/// sense returned: ±1.
fn along_working_stroke(s: &mut [f64], ds: &mut [f64], dds: &mut [f64], cycle: bool) -> (f64, f64) {
    let s0 = s[0];
    for x in s.iter_mut() {
        *x -= s0;
    }
    let far = s
        .iter()
        .fold(0.0f64, |a, &x| if x.abs() > a.abs() { x } else { a });
    let along = if cycle && far < 0.0 { -1.0 } else { 1.0 };
    for x in s.iter_mut().chain(ds.iter_mut()).chain(dds.iter_mut()) {
        // (+ 0.0: no −0 printed at the extreme position.)
        *x = *x * along + 0.0;
    }
    (s0, along)
}

/// The output sampled along the abscissa: from `phi0` in steps of `h`
/// in the sense `dir`, `n` intervals; a point's `path` (its arc length),
/// a `slide`, or a link's angle (continued).
struct Sampling<'a> {
    out: Output<'a>,
    phi0: f64,
    dir: f64,
    h: f64,
    n: usize,
    path: bool,
    slide: bool,
}

impl Sampling<'_> {
    /// A path's arc length: Gauss–Legendre over each step of |v|.
    fn arc(&mut self, from: f64, step: f64) -> Result<f64> {
        let dir = self.dir;
        let mut sum = 0.0;
        for (x, w) in GAUSS8 {
            let phi = from + dir * step * 0.5 * (1.0 + x);
            sum += w * dir * self.out.at(phi)?.1;
        }
        Ok(0.5 * step * sum)
    }

    /// The output and its analytic s′, s″ at the nodes.
    fn nodes(&mut self) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>)> {
        let (phi0, dir, h, n) = (self.phi0, self.dir, self.h, self.n);
        let mut s = Vec::with_capacity(n + 1);
        let (mut ds, mut dds) = (Vec::new(), Vec::new());
        let mut prev: Option<f64> = None;
        for k in 0..=n {
            let (v, v1, v2) = self.out.at(phi0 + dir * h * k as f64)?;
            let v = match (self.slide, prev) {
                _ if self.path => match prev {
                    None => 0.0,
                    Some(p) => p + self.arc(phi0 + dir * h * (k - 1) as f64, h)?,
                },
                (false, Some(p)) => p + crate::geom::wrap_pi(v - p),
                _ => v,
            };
            prev = Some(v);
            s.push(v);
            ds.push(dir * v1);
            dds.push(v2);
        }
        Ok((s, ds, dds))
    }

    /// The analytic s′ at the interval midpoints (turned by `along`).
    fn midpoints(&mut self, along: f64) -> Result<Vec<f64>> {
        let (phi0, dir, h, n) = (self.phi0, self.dir, self.h, self.n);
        let mut ds_mid = Vec::with_capacity(n);
        for k in 0..n {
            let (_, v1, _) = self.out.at(phi0 + dir * h * (k as f64 + 0.5))?;
            ds_mid.push(along * dir * v1);
        }
        Ok(ds_mid)
    }

    /// The analytic (s, s′, s″) at DENSE samples per interval, s from `s0`
    /// (turned by `along`).
    fn dense(&mut self, s0: f64, along: f64) -> Result<Vec<(f64, f64, f64)>> {
        let (phi0, dir, h, n) = (self.phi0, self.dir, self.h, self.n);
        let mut dense = Vec::with_capacity(n * DENSE + 1);
        let mut near = s0;
        let hd = h / DENSE as f64;
        for j in 0..=n * DENSE {
            let (v, v1, v2) = self.out.at(phi0 + dir * hd * j as f64)?;
            let v = if self.path {
                if j == 0 {
                    s0
                } else {
                    near + self.arc(phi0 + dir * hd * (j - 1) as f64, hd)?
                }
            } else if self.slide {
                v
            } else {
                near + crate::geom::wrap_pi(v - near)
            };
            near = v;
            dense.push((along * (v - s0), along * dir * v1, along * v2));
        }
        Ok(dense)
    }
}

/// The graphical differentiation by chords: μ_s standard, the curve within
/// its room; the poles so that the derived curves fit theirs; the rays'
/// ordinates.
struct Chords {
    mu_s: f64,
    h1: f64,
    h2: f64,
    y1: Vec<f64>,
    y2: Vec<f64>,
}

impl Chords {
    /// Of the displacements `s` at the nodes (largest magnitude `range`),
    /// an interval `dx` mm long; `stroke`: a slide's stroke, not a cycle.
    fn of(s: &[f64], range: f64, dx: f64, stroke: bool) -> Chords {
        let n = s.len() - 1;
        let mu_s = standard_scale(range.max(f64::MIN_POSITIVE), HEIGHT_S);
        let slope1 = (0..n)
            .map(|k| ((s[k + 1] - s[k]) / mu_s / dx).abs())
            .fold(0.0, f64::max);
        let h1 = pole_distance(slope1, HEIGHT_DERIVED);
        // The construction: rays from P1 = (−H1, 0) parallel to the chords
        // meet the ordinate axis at y′ = H1·Δy/Δx.
        let y1: Vec<f64> = (0..n)
            .map(|k| ray_ordinate(h1, dx, (s[k + 1] - s[k]) / mu_s))
            .collect();
        // Chords of the velocity diagram: between the midpoints k − ½ and
        // k + ½ (the cycle closes: the midpoint before node 0 is the last;
        // over a stroke node 0 takes the first chord).
        let chord = |k: usize| {
            if stroke {
                y1[k.max(1)] - y1[k.max(1) - 1]
            } else {
                y1[k] - y1[(k + n - 1) % n]
            }
        };
        let slope2 = (0..n).map(|k| (chord(k) / dx).abs()).fold(0.0, f64::max);
        let h2 = pole_distance(slope2, HEIGHT_DERIVED);
        let y2: Vec<f64> = (0..n).map(|k| ray_ordinate(h2, dx, chord(k))).collect();
        Chords {
            mu_s,
            h1,
            h2,
            y1,
            y2,
        }
    }
}

/// A round pole distance (mm) that keeps the largest ordinate H·|slope|
/// within `room` mm.
fn pole_distance(max_slope: f64, room: f64) -> f64 {
    let choices = [50.0, 40.0, 30.0, 25.0, 20.0, 15.0, 10.0, 8.0, 5.0];
    for h in choices {
        if h * max_slope <= room {
            return h;
        }
    }
    5.0
}

impl Diagrams {
    /// The diagrams of the output link `output` with `n` intervals, the
    /// abscissa `l` mm long for the revolution.
    pub fn build(an: &Analysis, output: usize, n: usize, l: f64) -> Result<Diagrams> {
        let out = Output::new(an, output)?;
        let start = match stroke(an)? {
            Some((lo, _)) => lo,
            None => an.working_stroke_start(output)?,
        };
        Diagrams::from_output(an, out, output, None, start, n, l)
    }

    /// The diagrams of point `p` along its path (the arc length from the
    /// start of the working stroke of the mechanism's output), of its speed
    /// analogue and its tangential acceleration analogue.
    pub fn build_point(an: &Analysis, p: usize, n: usize, l: f64) -> Result<Diagrams> {
        let out = Output::point(an, p)?;
        let start = match stroke(an)? {
            Some((lo, _)) => lo,
            None => an.working_stroke_start(crate::studies::invariants::default_output(an))?,
        };
        let carrier = an.carrier(p);
        Diagrams::from_output(an, out, carrier, Some(p), start, n, l)
    }

    fn from_output(
        an: &Analysis,
        out: Output,
        output: usize,
        point: Option<usize>,
        phi0: f64,
        n: usize,
        l: f64,
    ) -> Result<Diagrams> {
        let m = &an.mech;
        if n < 4 {
            return Err(Error::scene("-n", "a diagram needs at least 4 intervals"));
        }
        let stroke = stroke(an)?;
        let dir = match (&m.scene.input, stroke) {
            (_, Some(_)) => 1.0,
            (InputSpec::Crank { omega, .. }, None) if *omega < 0.0 => -1.0,
            _ => 1.0,
        };
        let path = point.is_some();
        let slide = path
            || m.prismatics
                .iter()
                .any(|p| p.slider == output && p.guide == m.frame());
        let h = match stroke {
            Some((lo, hi)) => (hi - lo) / n as f64,
            None => TAU / n as f64,
        };
        let mut sm = Sampling {
            out,
            phi0,
            dir,
            h,
            n,
            path,
            slide,
        };
        let (mut s, mut ds, mut dds) = sm.nodes()?;
        if stroke.is_none() && !slide && (s[n] - s[0]).abs() > 1.0 {
            return Err(Error::scene(
                "output",
                "the output link turns fully: choose a rocking link or a slider",
            ));
        }
        let (s0, along) = along_working_stroke(&mut s, &mut ds, &mut dds, stroke.is_none());
        let ds_mid = sm.midpoints(along)?;
        let dense = sm.dense(s0, along)?;
        let range = s.iter().fold(0.0f64, |a, &x| a.max(x.abs()));
        if range.is_nan() || range <= 1e-12 * m.size {
            return Err(Error::scene(
                if path { "point" } else { "output" },
                "it does not move over the revolution: there is no diagram to draw",
            ));
        }
        // The sampled curves; their scales are chosen by `at_length`.
        let sampled = Diagrams {
            output,
            point,
            slide,
            n,
            phi0,
            dir,
            #[cfg(feature = "internals")]
            along,
            h,
            span: match stroke {
                Some((lo, hi)) => hi - lo,
                None => TAU,
            },
            stroke: stroke.is_some(),
            s,
            ds,
            dds,
            ds_mid,
            dense,
            mu_s: 0.0,
            mu_phi: 0.0,
            h1: 0.0,
            h2: 0.0,
            mu_v: 0.0,
            mu_a: 0.0,
            y1: Vec::new(),
            y2: Vec::new(),
        };
        Ok(sampled.at_length(l))
    }

    /// The same diagrams drawn with the abscissa `l` mm long for the
    /// revolution (the stroke): their scales and the rays' ordinates
    /// chosen anew, the sampled curves kept. Arithmetic only, no solving:
    /// a sheet scales the diagrams the study sampled to its own room.
    pub fn at_length(&self, l: f64) -> Diagrams {
        let mu_phi = self.span / l;
        let range = self.s.iter().fold(0.0f64, |a, &x| a.max(x.abs()));
        let cons = Chords::of(&self.s, range, self.h / mu_phi, self.stroke);
        let mu_v = cons.mu_s / (cons.h1 * mu_phi);
        let mu_a = mu_v / (cons.h2 * mu_phi);
        Diagrams {
            mu_s: cons.mu_s,
            mu_phi,
            h1: cons.h1,
            h2: cons.h2,
            mu_v,
            mu_a,
            y1: cons.y1,
            y2: cons.y2,
            ..self.clone()
        }
    }

    /// The abscissa's symbol (letters, subscript) and unit: φ1 in rad, or
    /// a driving slider's slide in m, subscript its link's id (s3).
    pub fn abscissa(&self, an: &Analysis) -> (String, String, &'static str) {
        if self.stroke {
            let id = an.mech.link_id(an.mech.scene.input.link());
            ("s".into(), id.into(), "m")
        } else {
            ("φ".into(), "1".into(), "rad")
        }
    }

    /// s′ by chords at the interval midpoints (ordinate × μ_s′).
    pub fn chord_velocity(&self) -> Vec<f64> {
        self.y1.iter().map(|y| y * self.mu_v).collect()
    }

    /// s″ by chords of the velocity diagram at the nodes 0…N−1.
    pub fn chord_acceleration(&self) -> Vec<f64> {
        self.y2.iter().map(|y| y * self.mu_a).collect()
    }

    /// Graphical integration by chords of velocities `v` given at the
    /// interval midpoints: through each interval a segment parallel to the
    /// ray from the pole (at `pole` mm) to the midpoint's ordinate; the
    /// result at the nodes, scale μ_s = μ_s′·μ_φ·H.
    pub fn integrate_by_chords(&self, v: &[f64], pole: f64) -> Vec<f64> {
        let dx = self.h / self.mu_phi;
        let mu_v = self.mu_s / (pole * self.mu_phi);
        let mut y = vec![0.0];
        for vk in v {
            // The ray to (0, v/μ_v) from (−H, 0) has slope v/(μ_v·H).
            let last = *y.last().expect("starts at 0");
            y.push(last + vk / mu_v / pole * dx);
        }
        y.iter().map(|yk| yk * self.mu_s).collect()
    }

    /// The mean of the analytic s′ over interval k (Gauss–Legendre on the
    /// transfer function): what the chord's ray gives by the mean value
    /// theorem the lecture cites.
#[cfg(feature = "internals")]
    pub fn mean_velocity(&self, out: &mut Output, k: usize) -> Result<f64> {
        let mut sum = 0.0;
        for (x, w) in GAUSS8 {
            let phi = self.phi0 + self.dir * self.h * (k as f64 + 0.5 + 0.5 * x);
            sum += w * self.dir * out.at(phi)?.1;
        }
        Ok(0.5 * self.along * sum)
    }

    /// The errors of every numerical curve against the analytic one.
    pub fn errors(&self) -> Errors {
        let n = self.n;
        let worst = |got: &[f64], want: &[f64]| -> (f64, usize) {
            let scale = want.iter().fold(f64::MIN_POSITIVE, |a, x| a.max(x.abs()));
            let mut w = (0.0, 0);
            for (k, (g, x)) in got.iter().zip(want).enumerate() {
                let d = (g - x).abs() / scale;
                if d > w.0 {
                    w = (d, k);
                }
            }
            w
        };
        let (cv, ca) = central(&self.s, self.h);
        Errors {
            chord_v: worst(&self.chord_velocity(), &self.ds_mid),
            chord_a: worst(&self.chord_acceleration(), &self.dds[..n]),
            central_v: worst(&cv, &self.ds),
            central_a: {
                let (e, k) = worst(&ca[2..n - 1], &self.dds[2..n - 1]);
                (
                    e * scale_of(&self.dds[2..n - 1]) / scale_of(&self.dds),
                    k + 2,
                )
            },
            central_a_ends: {
                let ends = [0, 1, n - 1, n];
                let got: Vec<f64> = ends.iter().map(|&k| ca[k]).collect();
                let want: Vec<f64> = ends.iter().map(|&k| self.dds[k]).collect();
                let (e, k) = worst(&got, &want);
                (e * scale_of(&want) / scale_of(&self.dds), ends[k])
            },
            chord_s: worst(&self.integrate_by_chords(&self.ds_mid, self.h1), &self.s),
            trapezoid_s: worst(&trapezoid(&self.ds, self.h), &self.s),
        }
    }
}

/// The stroke of a hydraulic cylinder input over which its diagrams are
/// drawn: from the least to the greatest slide of the scene's positions
/// (None for a crank). An error when the positions do not span a stroke,
/// and for a driving slider on a guide of the frame.
fn stroke(an: &Analysis) -> Result<Option<(f64, f64)>> {
    let m = &an.mech;
    let InputSpec::Slider { pair, .. } = m.scene.input else {
        return Ok(None);
    };
    if m.prismatics[pair].guide == m.frame() {
        // (Diagrams against a slide on a guide of the frame are not yet
        // offered: tests/diagrams.rs pins the refusal.)
        return Err(Error::scene(
            "/input",
            "kinematic diagrams need a crank input (over a revolution) or a hydraulic cylinder (a driving slider on a moving guide, over its stroke)",
        ));
    }
    let s = an.input_values()?;
    let (lo, hi) = s
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return Err(Error::scene(
            "/positions",
            "diagrams against a driving slider's slide are drawn over the stroke its positions span: give positions.s with at least two different slides",
        ));
    }
    Ok(Some((lo, hi)))
}

/// The largest magnitude of a list (at least the smallest positive number).
fn scale_of(v: &[f64]) -> f64 {
    v.iter().fold(f64::MIN_POSITIVE, |a, x| a.max(x.abs()))
}

/// Where the ray from the pole (−H, 0) parallel to a chord rising `dy` mm
/// over `dx` mm meets the ordinate axis: the intersection of that line with
/// x = 0.
fn ray_ordinate(pole: f64, dx: f64, dy: f64) -> f64 {
    let (p, d) = ((-pole, 0.0), (dx, dy));
    // p + t·d on x = 0.
    let t = -p.0 / d.0;
    p.1 + t * d.1
}

/// The lecture's numerical derivatives of a table at step h: central
/// differences inside, three-point one-sided formulas at the ends; first
/// and second derivatives.
pub fn central(y: &[f64], h: f64) -> (Vec<f64>, Vec<f64>) {
    let n = y.len();
    let d1 = |y: &[f64]| -> Vec<f64> {
        (0..n)
            .map(|i| {
                if i == 0 {
                    (-y[2] + 4.0 * y[1] - 3.0 * y[0]) / (2.0 * h)
                } else if i == n - 1 {
                    (3.0 * y[n - 1] - 4.0 * y[n - 2] + y[n - 3]) / (2.0 * h)
                } else {
                    (y[i + 1] - y[i - 1]) / (2.0 * h)
                }
            })
            .collect()
    };
    let v = d1(y);
    let a = d1(&v);
    (v, a)
}

/// Trapezoids: I₀ = 0, Iᵢ = Iᵢ₋₁ + h/2·(yᵢ + yᵢ₋₁).
pub fn trapezoid(y: &[f64], h: f64) -> Vec<f64> {
    let mut out = vec![0.0];
    for i in 1..y.len() {
        let last = out[i - 1];
        out.push(last + h / 2.0 * (y[i] + y[i - 1]));
    }
    out
}
