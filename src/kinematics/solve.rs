//! The whole analysis of a scene: which groups the wanted output needs,
//! the input values of the positions (with the extreme position found
//! exactly for `positions.count`), both analytic routes at every position,
//! and their cross-check.

use crate::error::{Error, Result};
use crate::geom::{Pose, perp, wrap_pi};
use crate::kinematics::analytic::constraint::{ConstraintSolver, Settings};
use crate::kinematics::analytic::{Drive, Motion, Order, contour};
use crate::kinematics::construction::{Drafting, Plans, Setup, build_plans};
use crate::kinematics::positions::{Configuration, PositionSolver, describe_input};
use crate::model::mechanism::Mechanism;
use crate::model::scene::{InputSpec, PositionsSpec, Scene};
use crate::model::structure::{Structure, analyse};
use kurbo::{Point, Vec2};
use std::time::Instant as Clock;

/// A scene made ready: mechanism, structure, and what is to be computed.
#[derive(Clone, Debug)]
pub struct Analysis {
    pub mech: Mechanism,
    pub structure: Structure,
    /// Groups to solve.
    pub need: Vec<bool>,
    /// Links solved (frame, input and the needed groups' links).
    pub include: Vec<bool>,
    /// Points reported, in scene order.
    pub points: Vec<usize>,
    /// None: positions only (no plans wanted).
    pub order: Option<Order>,
    /// Fixed scales and the pencil precision of the plans.
    pub drafting: Drafting,
    /// Scale of the plan of the mechanism, m/mm: `want.scales.mu_l`, else
    /// the standard value that draws the sketch's extent within 200 mm.
    pub mu_l: f64,
}

/// (what, |difference|, |value|) of one kind of quantity.
type Diffs = Vec<(String, f64, f64)>;

/// Both routes' agreement at one position and what each cost.
#[derive(Clone, Debug)]
pub struct CrossCheck {
    /// Largest difference between the routes, each quantity relative to
    /// the largest magnitude of its kind at that position.
    pub max_rel_diff: f64,
    /// Which quantity it was ("v of B").
    pub worst: String,
    /// Wall time of route (a) (positions + contours), seconds.
    pub contour_time: f64,
    /// Wall time of route (b) (Newton + linear solves), seconds.
    pub constraint_time: f64,
    /// σ_min/σ_max of the scaled constraint Jacobian.
    pub conditioning: f64,
    /// Wall time of the plans' construction, seconds (0 without plans).
    pub plan_time: f64,
    /// How far the answer moves when the scene's data change by a few
    /// units of rounding, relative as `max_rel_diff` (`None` only before
    /// it is measured).
    pub data_sensitivity: Option<f64>,
    /// The error bound of every reported number of each kind, in SI
    /// (`None` only before the data sensitivity is measured).
    pub bound: Option<Bounds>,
}

/// The error bound of every number of one position that the routes report,
/// by kind, in SI: each reported value lies within its kind's bound of the
/// exact answer for the scene's data.
///
/// Each is (c·ε·κ + 4·d + 4·σ)·S: κ = 1/conditioning (the scaled
/// Jacobian's σ_max/σ_min: how much rounding of the linear systems is
/// amplified; c = 256 covers the few dozen roundings per equation and
/// their accumulation through the groups), d the routes' disagreement (the
/// part of their own arithmetic that κ misses near a dead point), σ the
/// data sensitivity (the part the data's rounding decides, which both
/// routes share); S the position's scale of that kind: the sketch's size
/// for places, the largest |v| or |ω|·size for velocities, the largest
/// |a|, |ε|·size or ω²·size for accelerations, the same at unit input rate
/// for the transfer functions. Angles, ω, ε and their transfer functions:
/// the same over the size.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bounds {
    pub p: f64,
    pub v: f64,
    pub a: f64,
    pub v_q: f64,
    pub a_q: f64,
    pub angle: f64,
    pub omega: f64,
    pub epsilon: f64,
    pub phi_q: f64,
    pub phi_qq: f64,
}

/// The constant c of [`Bounds`].
pub const BOUND_ROUNDINGS: f64 = 256.0;

/// Positions found and finished at a time by [`Analysis::run_each`]:
/// enough to keep both cores busy, few enough that a sweep of the largest
/// count allowed needs no more memory than a short one.
pub const RUN_CHUNK: usize = 512;

/// The largest data sensitivity accepted, as the routes' disagreement.
pub const MAX_REL_DIFF: f64 = 1e-6;

/// The change of the data for the sensitivity check: every length and
/// sketch coordinate by this many units of rounding (relative).
const DATA_PERTURBATION: f64 = 8.0 * f64::EPSILON;

/// The scene with its data changed by a few units of rounding, both ways
/// ([`Analysis::changed_data`]).
type ChangedData = Vec<std::result::Result<Analysis, String>>;

/// A position found in order by both routes, before its rates.
struct Placed<'a> {
    q: f64,
    /// The rounding of q as the file writes it (rad or m).
    q_rounding: f64,
    config: Configuration,
    /// Route (b) at this position (its state continues from the last).
    constraint: ConstraintSolver<'a>,
    /// Time of finding the position, seconds, by route (a) and route (b).
    contour_time: f64,
    constraint_time: f64,
}

/// One solved position.
#[derive(Clone, Debug)]
pub struct Solved {
    /// The input coordinate (rad or m) and its rates.
    pub q: f64,
    pub rate: f64,
    pub rate2: f64,
    pub config: Configuration,
    /// Route (a) motions; `None` for links not solved.
    pub motion: Vec<Option<Motion>>,
    /// Route (a) with unit input rate and zero input acceleration: the
    /// transfer functions (analogues of velocity and acceleration).
    pub analogue: Vec<Option<Motion>>,
    /// The plans of velocities and accelerations, as constructions.
    pub plans: Option<Plans>,
    pub check: Option<CrossCheck>,
}

impl Analysis {
    pub fn new(scene: Scene) -> Result<Analysis> {
        Analysis::of(Mechanism::new(scene)?)
    }

    /// The analysis of a mechanism already built.
    fn of(mech: Mechanism) -> Result<Analysis> {
        let structure = analyse(&mech)?;
        let sc = &mech.scene;
        let points: Vec<usize> = match &sc.want.points {
            Some(p) => {
                let mut p = p.clone();
                p.sort_unstable();
                p
            }
            None => (0..sc.points.len()).collect(),
        };
        let carriers: Vec<usize> = points.iter().map(|&p| mech.links_of_point(p)[0]).collect();
        let need = if sc.want.points.is_some() {
            structure.needed_for(&carriers)
        } else {
            vec![true; structure.groups.len()]
        };
        let mut include = vec![false; mech.links.len()];
        include[mech.frame()] = true;
        include[sc.input.link()] = true;
        for (g, grp) in structure.groups.iter().enumerate() {
            if need[g] {
                for l in grp.links() {
                    include[l] = true;
                }
            }
        }
        let order = match (sc.want.velocity, sc.want.acceleration) {
            (_, true) => Some(Order::Acceleration),
            (true, false) => Some(Order::Velocity),
            (false, false) => None,
        };
        let mu_l = sc.want.scales.mu_l.unwrap_or_else(|| {
            crate::kinematics::construction::scale::standard_scale(mech.size, 200.0)
        });
        let drafting = Drafting {
            mu_v: sc.want.scales.mu_v,
            mu_a: sc.want.scales.mu_a,
            ..Drafting::default()
        };
        Ok(Analysis {
            mech,
            structure,
            need,
            include,
            points,
            order,
            drafting,
            mu_l,
        })
    }

    /// The link that reports point `p`: the first solved link carrying it.
    pub fn carrier(&self, p: usize) -> usize {
        self.mech
            .links_of_point(p)
            .into_iter()
            .find(|&l| self.include[l])
            .expect("reported points are carried by solved links")
    }

    /// Input coordinates of the positions asked for (rad or m).
    pub fn input_values(&self) -> Result<Vec<f64>> {
        let sc = &self.mech.scene;
        Ok(match &sc.positions {
            PositionsSpec::Single => vec![sc.input.coordinate()],
            PositionsSpec::List(v) => v.clone(),
            PositionsSpec::Count { count, output } => {
                let out = output.unwrap_or_else(|| {
                    *self
                        .structure
                        .groups
                        .last()
                        .map(|g| g.links())
                        .unwrap_or_default()
                        .last()
                        .unwrap_or(&sc.input.link())
                });
                let start = self.working_stroke_start(out)?;
                let (omega, _) = sc.input.rates();
                let dir = if omega < 0.0 { -1.0 } else { 1.0 };
                (0..*count)
                    .map(|k| {
                        (start + dir * std::f64::consts::TAU * k as f64 / *count as f64)
                            .rem_euclid(std::f64::consts::TAU)
                    })
                    .collect()
            }
        })
    }

    /// The output coordinate of link `out` and its first transfer function:
    /// the slide along a frame guide for a slider, else the link's angle.
    fn output_coordinate(
        &self,
        out: usize,
        c: &Configuration,
        an: &[Option<Motion>],
    ) -> (f64, f64) {
        let m = &self.mech;
        if let Some(pr) = m
            .prismatics
            .iter()
            .find(|p| p.slider == out && p.guide == m.frame())
        {
            let u = pr.line(&Pose::IDENTITY).dir;
            let q = c.pose(out).apply(pr.slider_local);
            let v = an[out].unwrap().velocity(q);
            (u.dot(q.to_vec2()), u.dot(v))
        } else {
            (c.pose(out).angle, an[out].unwrap().omega)
        }
    }

    /// The crank angle of the extreme position of `out` that begins the
    /// working stroke (the stroke taking the larger crank angle), found as
    /// a root of the output's transfer function to machine precision.
    pub fn working_stroke_start(&self, out: usize) -> Result<f64> {
        let m = &self.mech;
        let sc = &m.scene;
        let InputSpec::Crank { omega, angle, .. } = sc.input else {
            return Err(Error::scene(
                "/positions/count",
                "equal steps over a revolution need a crank input",
            ));
        };
        let mut need = self.structure.needed_for(&[out]);
        for (n, own) in need.iter_mut().zip(&self.need) {
            *n |= *own;
        }
        let mut ps = PositionSolver::new(m, &self.structure, need.clone())?;
        let eval = |ps: &mut PositionSolver, phi: f64, step: bool| -> Result<(f64, f64)> {
            let c = if step {
                ps.solve(phi)?
            } else {
                ps.solve_at(phi)?
            };
            let an = contour::solve(
                m,
                &self.structure,
                &need,
                &c,
                Drive {
                    q: phi,
                    rate: 1.0,
                    rate2: 0.0,
                },
                Order::Velocity,
            )?;
            Ok(self.output_coordinate(out, &c, &an))
        };
        let n = 720;
        let mut samples = Vec::with_capacity(n + 1);
        for k in 0..=n {
            let phi = angle + std::f64::consts::TAU * k as f64 / n as f64;
            let v = eval(&mut ps, phi, true).map_err(|e| match e {
                Error::Assembly { group, at, why } => Error::Assembly {
                    group,
                    at,
                    why: format!("{why}; the crank cannot turn fully, so /positions/count (a full revolution) is impossible"),
                },
                e => e,
            })?;
            samples.push((phi, v.0, v.1));
        }
        let angular = !m
            .prismatics
            .iter()
            .any(|p| p.slider == out && p.guide == m.frame());
        // Unwrap an angular output so that min/max compare.
        let mut extremes: Vec<(f64, f64)> = Vec::new();
        let mut offset = 0.0;
        for k in 0..n {
            let (p0, _, d0) = samples[k];
            let (p1, _, d1) = samples[k + 1];
            if d0 == 0.0 || d0.signum() != d1.signum() {
                ps.solve(p0)?;
                // Bisection on the transfer function, then polish to the last ulp.
                let (mut a, mut b, mut fa) = (p0, p1, d0);
                for _ in 0..200 {
                    let mid = 0.5 * (a + b);
                    if mid <= a || mid >= b {
                        break;
                    }
                    let (_, fm) = eval(&mut ps, mid, false)?;
                    if fm == 0.0 {
                        a = mid;
                        b = mid;
                        break;
                    }
                    if fm.signum() == fa.signum() {
                        a = mid;
                        fa = fm;
                    } else {
                        b = mid;
                    }
                }
                let root = 0.5 * (a + b);
                let (x, _) = eval(&mut ps, root, false)?;
                let x = if angular {
                    let base = samples[0].1;
                    offset = base + wrap_pi(x - base);
                    offset
                } else {
                    x
                };
                extremes.push((root, x));
            }
        }
        let _ = offset;
        if extremes.len() < 2 {
            // No extreme positions: the output turns fully; start at the input.
            return Ok(angle);
        }
        let lo =
            extremes.iter().copied().fold(
                (0.0, f64::INFINITY),
                |acc, e| if e.1 < acc.1 { e } else { acc },
            );
        let hi = extremes
            .iter()
            .copied()
            .fold(
                (0.0, f64::NEG_INFINITY),
                |acc, e| if e.1 > acc.1 { e } else { acc },
            );
        let dir = if omega < 0.0 { -1.0 } else { 1.0 };
        // Crank angle of the stroke lo → hi in the sense of rotation.
        let d_lo_hi = (dir * (hi.0 - lo.0)).rem_euclid(std::f64::consts::TAU);
        let d_hi_lo = std::f64::consts::TAU - d_lo_hi;
        // The larger stroke begins the working stroke; at a tie (180° each)
        // the extreme with the smallest output coordinate.
        let start = if d_lo_hi >= d_hi_lo - 1e-9 {
            lo.0
        } else {
            hi.0
        };
        Ok(start.rem_euclid(std::f64::consts::TAU))
    }

    /// Solve every position asked for, both routes, with the cross-check.
    ///
    /// The positions are found in order (both routes continue from one
    /// position to the next, which keeps them on the sketch's branch);
    /// then each position's velocities, accelerations, plans and checks are
    /// independent, and long sweeps do them in parallel
    /// ([`crate::progress::map_on`], a chunk at a time). The result, and
    /// the first error in the order of the positions, are those of a
    /// sequential run.
    pub fn run(&self) -> Result<Vec<Solved>> {
        let mut out = Vec::new();
        self.run_each(|s| {
            out.push(s);
            Ok(())
        })?;
        Ok(out)
    }

    /// As [`Analysis::run`], each solved position handed to `f` in order
    /// instead of kept: the positions are found and finished
    /// [`RUN_CHUNK`] at a time, so that memory does not grow with their
    /// number. The positions before the first error are handed over; an
    /// error of `f` stops the run and is returned.
    pub fn run_each(&self, mut f: impl FnMut(Solved) -> Result<()>) -> Result<()> {
        let values = self.input_values()?;
        let m = &self.mech;
        let mut ps = PositionSolver::new(m, &self.structure, self.need.clone())?;
        let mut cs = ConstraintSolver::new(m, &self.include, Settings::default());
        let changed = self.changed_data();
        let bar = crate::progress::bar(values.len(), "positions");
        // The rounding of each input value as written (none for `count`).
        let rounding = if m.scene.input_rounding.len() == values.len() {
            m.scene.input_rounding.clone()
        } else {
            vec![0.0; values.len()]
        };
        let done = values
            .chunks(RUN_CHUNK)
            .zip(rounding.chunks(RUN_CHUNK))
            .try_for_each(|(chunk, rounding)| {
                self.run_chunk(chunk, rounding, &mut ps, &mut cs, &changed, &bar, &mut f)
            });
        bar.finish_and_clear();
        done
    }

    /// One chunk of [`Analysis::run_each`]: its positions found in order,
    /// then finished (in parallel when long) and handed to `f` in order.
    #[allow(clippy::too_many_arguments)]
    fn run_chunk<'a>(
        &'a self,
        values: &[f64],
        rounding: &[f64],
        ps: &mut PositionSolver,
        cs: &mut ConstraintSolver<'a>,
        changed: &ChangedData,
        bar: &indicatif::ProgressBar,
        f: &mut impl FnMut(Solved) -> Result<()>,
    ) -> Result<()> {
        let mut placed = Vec::with_capacity(values.len());
        let mut stop = None;
        for (&q, &q_rounding) in values.iter().zip(rounding) {
            let t0 = Clock::now();
            let config = match ps.solve(q) {
                Ok(c) => c,
                Err(e) => {
                    stop = Some(e);
                    break;
                }
            };
            let contour_time = t0.elapsed().as_secs_f64();
            let t1 = Clock::now();
            let span = self.path_span(ps, cs.last_input(), q);
            if let Err(e) = cs.solve_positions_by(q, span) {
                // Route (a)'s rates come first at a position: its error,
                // if it has one here, is the one a sequential run reports.
                stop = Some(self.contour_error(q, &config).unwrap_or(e));
                break;
            }
            let constraint_time = t1.elapsed().as_secs_f64();
            placed.push(Placed {
                q,
                q_rounding,
                config,
                constraint: cs.clone(),
                contour_time,
                constraint_time,
            });
        }
        for s in crate::progress::map_on(&placed, bar, |p| self.finish(p, changed)) {
            f(s?)?;
        }
        match stop {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// Which way the input goes from `from` to `to`: a slider straight; a
    /// crank the short way round, unless the mechanism does not assemble
    /// on it (a crank that only rocks) and does the other way. Route (a)'s
    /// closed forms, tried every 5°, tell; route (b) then continues along
    /// that way, so a valid sequence of a rocking crank is never refused.
    fn path_span(&self, ps: &PositionSolver, from: f64, to: f64) -> f64 {
        let InputSpec::Crank { .. } = self.mech.scene.input else {
            return to - from;
        };
        let short = wrap_pi(to - from);
        let assembles = |span: f64| {
            let mut probe = ps.clone();
            let n = (span.abs() / 5f64.to_radians()).ceil().max(1.0) as usize;
            (1..n).all(|i| probe.solve_at(from + span * i as f64 / n as f64).is_ok())
        };
        if short == 0.0 || assembles(short) {
            return short;
        }
        let long = short - std::f64::consts::TAU.copysign(short);
        if assembles(long) { long } else { short }
    }

    /// Route (a)'s error at a position, if its contours are singular there.
    fn contour_error(&self, q: f64, config: &Configuration) -> Option<Error> {
        let order = self.order?;
        let (rate, rate2) = self.mech.scene.input.rates();
        contour::solve(
            &self.mech,
            &self.structure,
            &self.need,
            config,
            Drive { q, rate, rate2 },
            order,
        )
        .err()
    }

    /// One placed position: both routes' rates, the plans, the cross-check.
    fn finish(&self, p: &Placed, changed: &ChangedData) -> Result<Solved> {
        let m = &self.mech;
        let (rate, rate2) = m.scene.input.rates();
        let (q, config) = (p.q, p.config.clone());
        let mut cs = p.constraint.clone();
        let t0 = Clock::now();
        let (motion, analogue) = match self.order {
            Some(order) => (
                contour::solve(
                    m,
                    &self.structure,
                    &self.need,
                    &config,
                    Drive { q, rate, rate2 },
                    order,
                )?,
                contour::solve(
                    m,
                    &self.structure,
                    &self.need,
                    &config,
                    Drive {
                        q,
                        rate: 1.0,
                        rate2: 0.0,
                    },
                    order,
                )?,
            ),
            None => (vec![None; m.links.len()], vec![None; m.links.len()]),
        };
        let contour_time = p.contour_time + t0.elapsed().as_secs_f64();
        let t1 = Clock::now();
        let other = cs.solve_rates(rate, rate2, self.order.unwrap_or(Order::Velocity))?;
        let constraint_time = p.constraint_time + t1.elapsed().as_secs_f64();
        let t2 = Clock::now();
        let plans = match self.order {
            Some(order) => {
                let setup = Setup {
                    m,
                    s: &self.structure,
                    need: &self.need,
                    points: &self.points,
                    include: &self.include,
                };
                Some(build_plans(
                    &setup,
                    &config,
                    Drive { q, rate, rate2 },
                    order,
                    self.drafting,
                )?)
            }
            None => None,
        };
        let plan_time = t2.elapsed().as_secs_f64();
        let mut solved = Solved {
            q,
            rate,
            rate2,
            config,
            motion,
            analogue,
            plans,
            check: None,
        };
        let (mut d, mut worst) = self.compare(&solved, &other);
        for (route, mo) in [("contour", &solved.motion), ("constraint", &other)] {
            let (dp, wp) = self.compare_plans(&solved, mo);
            if dp > d || dp.is_nan() {
                (d, worst) = (dp, format!("{wp} (plan against the {route} route)"));
            }
        }
        solved.check = Some(CrossCheck {
            max_rel_diff: d,
            worst: worst.clone(),
            contour_time,
            constraint_time,
            conditioning: cs.conditioning,
            plan_time,
            data_sensitivity: None,
            bound: None,
        });
        if d.is_nan() || d > MAX_REL_DIFF {
            return Err(Error::Singular {
                at: describe_input(m, q),
                why: format!(
                    "the two analytic routes disagree ({worst}: relative difference {d:.2e}); the position is too close to a singular one to trust either"
                ),
            });
        }
        let sens = self
            .data_sensitivity(&solved, p.q_rounding, changed)
            .map_err(|why| Error::Singular {
                at: describe_input(m, q),
                why,
            })?;
        let bound = self.bounds(&solved, cs.conditioning, d, sens);
        if let Some(c) = solved.check.as_mut() {
            c.data_sensitivity = Some(sens);
            c.bound = Some(bound);
        }
        Ok(solved)
    }

    /// The bounds of a solved position ([`Bounds`]).
    fn bounds(&self, s: &Solved, conditioning: f64, diff: f64, sens: f64) -> Bounds {
        let m = &self.mech;
        let size = m.size;
        let rel = BOUND_ROUNDINGS * f64::EPSILON / conditioning + 4.0 * diff + 4.0 * sens;
        // The scale of one kind: the points' magnitudes and the links'
        // rates × size (and ω²·size for accelerations).
        let scale = |mo: &[Option<Motion>], acc: bool| -> f64 {
            let mut x = f64::MIN_POSITIVE;
            for &p in &self.points {
                let l = self.carrier(p);
                if let Some(k) = mo[l] {
                    let at = s.config.point(m, l, p);
                    x = x.max(
                        if acc {
                            k.acceleration(at)
                        } else {
                            k.velocity(at)
                        }
                        .hypot(),
                    );
                }
            }
            for k in mo.iter().flatten() {
                x = x.max(if acc { k.epsilon } else { k.omega }.abs() * size);
                if acc {
                    x = x.max(k.omega * k.omega * size);
                }
            }
            x
        };
        let (sv, sa) = (scale(&s.motion, false), scale(&s.motion, true));
        let (sq, sqq) = (scale(&s.analogue, false), scale(&s.analogue, true));
        Bounds {
            p: rel * size,
            v: rel * sv,
            a: rel * sa,
            v_q: rel * sq,
            a_q: rel * sqq,
            angle: rel,
            omega: rel * sv / size,
            epsilon: rel * sa / size,
            phi_q: rel * sq / size,
            phi_qq: rel * sqq / size,
        }
    }

    /// The scene with every datum (length, sketch coordinate, guide line)
    /// changed by a few units of its own rounding, in a fixed alternating
    /// pattern, both ways; built once per run, its shapes with this
    /// mechanism's decisions (rounding must not change which rule places a
    /// point). An error when such a change already makes the mechanism
    /// another one (a structure decided by rounding).
    fn changed_data(&self) -> ChangedData {
        let m = &self.mech;
        [1.0, -1.0]
            .iter()
            .map(|sign| {
                let mut scene = m.scene.clone();
                let k = sign * DATA_PERTURBATION;
                let mut n = 0usize;
                // Each datum relative to its own magnitude: a coordinate
                // near the origin is known better than one far from it.
                let mut moved = |x: &mut f64| {
                    n += 1;
                    *x *= 1.0 + if n.is_multiple_of(2) { k } else { -k };
                };
                for l in scene.lengths.iter_mut() {
                    moved(&mut l.value);
                }
                for p in scene.points.iter_mut() {
                    let (mut x, mut y) = (p.sketch.x, p.sketch.y);
                    moved(&mut x);
                    moved(&mut y);
                    p.sketch = Point::new(x, y);
                }
                for sl in scene.sliders.iter_mut() {
                    if let crate::model::scene::Through::Coords(c) = &mut sl.line.through {
                        let (mut x, mut y) = (c.x, c.y);
                        moved(&mut x);
                        moved(&mut y);
                        *c = Point::new(x, y);
                    }
                    if let crate::model::scene::Direction::Angle(a) = &mut sl.line.direction {
                        moved(a);
                    }
                    moved(&mut sl.line.offset);
                }
                m.with_data(scene)
                    .and_then(Analysis::of)
                    .map_err(|e| e.to_string())
            })
            .collect()
    }

    /// How far the answer at a solved position moves with the data changed
    /// by a few units of rounding ([`Analysis::changed_data`]): the largest
    /// relative change, as the routes' comparison measures it, each scene's
    /// points on its own shapes. Both routes start from the same rounded
    /// data, so their agreement cannot show this. An error (a refusal) when
    /// the data's rounding decides the answer: the changed mechanism does
    /// not assemble here, or the answer moves by more than [`MAX_REL_DIFF`].
    fn data_sensitivity(
        &self,
        s: &Solved,
        q_rounding: f64,
        changed: &ChangedData,
    ) -> std::result::Result<f64, String> {
        let order = self.order.unwrap_or(Order::Velocity);
        let units = DATA_PERTURBATION / f64::EPSILON;
        let mut worst = (0.0f64, String::new());
        for (an, sign) in changed.iter().zip([1.0, -1.0]) {
            // The input moves with the data, by as many units of its own
            // rounding (exact reductions leave an ulp of the angle).
            let q = s.q + sign * units * q_rounding;
            let moved = an
                .as_ref()
                .map_err(|e| e.clone())
                .and_then(|an| {
                    let mut ps = PositionSolver::new(&an.mech, &an.structure, an.need.clone())
                        .map_err(|e| e.to_string())?;
                    let c = ps.solve(q).map_err(|e| e.to_string())?;
                    contour::solve(
                        &an.mech,
                        &an.structure,
                        &an.need,
                        &c,
                        Drive {
                            q,
                            rate: s.rate,
                            rate2: s.rate2,
                        },
                        order,
                    )
                    .map(|mo| (an, mo))
                    .map_err(|e| e.to_string())
                })
                .map_err(|e| {
                    format!(
                        "the position is within rounding of a dead point: with the data changed by {units} units of rounding the mechanism has no answer here ({e})"
                    )
                })?;
            let (d, what) = self.compare_with(s, &moved.1, &moved.0.mech);
            if d > worst.0 || d.is_nan() {
                worst = (d, what);
            }
        }
        if worst.0.is_nan() || worst.0 > MAX_REL_DIFF {
            return Err(format!(
                "the answer is decided by the rounding of the data: a change of {units} units of rounding in the data moves {} by {:.2e} (relative); the position is too close to a dead point",
                worst.1, worst.0
            ));
        }
        Ok(worst.0)
    }

    /// Largest relative difference between the plans (measured values × μ)
    /// and an analytic route.
    fn compare_plans(&self, s: &Solved, mo: &[Option<Motion>]) -> (f64, String) {
        let Some(plans) = &s.plans else {
            return (0.0, String::new());
        };
        let m = &self.mech;
        let mut worst = (0.0f64, String::new());
        for (plan, acc) in [
            (Some(&plans.velocity), false),
            (plans.acceleration.as_ref(), true),
        ] {
            let Some(plan) = plan else { continue };
            let mut items: Vec<(String, f64, f64)> = Vec::new();
            for &p in &self.points {
                let l = self.carrier(p);
                let at = s.config.point(m, l, p);
                let exact = if acc {
                    mo[l].unwrap().acceleration(at)
                } else {
                    mo[l].unwrap().velocity(at)
                };
                if let Some(got) = plan.value_of(p) {
                    items.push((
                        format!("{} of {}", if acc { "a" } else { "v" }, m.point_name(p)),
                        (got - exact).hypot(),
                        exact.hypot(),
                    ));
                }
            }
            for (l, (rate, x)) in plan.rates.iter().zip(mo).enumerate() {
                if let (Some((r, _)), Some(x)) = (rate, x) {
                    let exact = if acc { x.epsilon } else { x.omega };
                    items.push((
                        format!("{} of link {}", if acc { "ε" } else { "ω" }, m.link_id(l)),
                        (r - exact).abs() * m.size,
                        exact.abs() * m.size,
                    ));
                }
            }
            let scale = items.iter().map(|e| e.2).fold(f64::MIN_POSITIVE, f64::max);
            for (what, d, _) in items {
                if d / scale > worst.0 || d.is_nan() {
                    worst = (d / scale, what);
                }
            }
        }
        worst
    }

    /// Largest relative difference between route (a) and route (b).
    fn compare(&self, s: &Solved, other: &[Option<Motion>]) -> (f64, String) {
        self.compare_with(s, other, &self.mech)
    }

    /// As [`Analysis::compare`], the other motions belonging to mechanism
    /// `om` (the same links and points, its own shapes: a scene with its
    /// data changed).
    fn compare_with(&self, s: &Solved, other: &[Option<Motion>], om: &Mechanism) -> (f64, String) {
        let m = &self.mech;
        let mut worst = (0.0f64, String::from("none"));
        let mut note = |d: f64, what: String| {
            if d > worst.0 || d.is_nan() {
                worst = (d, what);
            }
        };
        let pts: Vec<(usize, usize)> = self.points.iter().map(|&p| (p, self.carrier(p))).collect();
        let place_b = |p: usize, l: usize| other[l].unwrap().pose.apply(om.local(l, p));
        for &(p, l) in &pts {
            let d = (s.config.point(m, l, p) - place_b(p, l)).hypot() / m.size;
            note(d, format!("position of {}", m.point_name(p)));
        }
        let links: Vec<usize> = (0..m.links.len()).filter(|&l| self.include[l]).collect();
        for &l in &links {
            let d = wrap_pi(s.config.pose(l).angle - other[l].unwrap().pose.angle).abs();
            note(d, format!("angle of link {}", m.link_id(l)));
        }
        let Some(order) = self.order else {
            return worst;
        };
        // Each motion at its own place of the point.
        let a_of = |mo: &[Option<Motion>], l: usize, at: Point| {
            (mo[l].unwrap().velocity(at), mo[l].unwrap().acceleration(at))
        };
        let mut kinds: Vec<(&str, Diffs)> = vec![("v", vec![]), ("ω", vec![])];
        if order == Order::Acceleration {
            kinds.push(("a", vec![]));
            kinds.push(("ε", vec![]));
        }
        for &(p, l) in &pts {
            let (va, aa) = a_of(&s.motion, l, s.config.point(m, l, p));
            let (vb, ab) = a_of(other, l, place_b(p, l));
            kinds[0]
                .1
                .push((m.point_name(p).to_string(), (va - vb).hypot(), va.hypot()));
            if order == Order::Acceleration {
                kinds[2]
                    .1
                    .push((m.point_name(p).to_string(), (aa - ab).hypot(), aa.hypot()));
            }
        }
        for &l in &links {
            let (ma, mb) = (s.motion[l].unwrap(), other[l].unwrap());
            kinds[1].1.push((
                format!("link {}", m.link_id(l)),
                (ma.omega - mb.omega).abs(),
                ma.omega.abs(),
            ));
            if order == Order::Acceleration {
                kinds[3].1.push((
                    format!("link {}", m.link_id(l)),
                    (ma.epsilon - mb.epsilon).abs(),
                    ma.epsilon.abs(),
                ));
            }
        }
        // Velocities and angular velocities share a scale (ω·size), as do
        // accelerations and angular accelerations (ε·size).
        let scale = |a: &[(String, f64, f64)], b: &[(String, f64, f64)]| {
            let x = a.iter().map(|e| e.2).fold(0.0, f64::max);
            let y = b.iter().map(|e| e.2 * m.size).fold(0.0, f64::max);
            x.max(y).max(f64::MIN_POSITIVE)
        };
        let sv = scale(&kinds[0].1, &kinds[1].1);
        for (name, d, _) in &kinds[0].1 {
            note(d / sv, format!("v of {name}"));
        }
        for (name, d, _) in &kinds[1].1 {
            note(d * m.size / sv, format!("ω of {name}"));
        }
        if order == Order::Acceleration {
            let sa = scale(&kinds[2].1, &kinds[3].1);
            for (name, d, _) in &kinds[2].1 {
                note(d / sa, format!("a of {name}"));
            }
            for (name, d, _) in &kinds[3].1 {
                note(d * m.size / sa, format!("ε of {name}"));
            }
        }
        worst
    }
}

/// A point's place and, when velocities were computed, its (v, a) and
/// their transfer functions (v_q, a_q).
#[derive(Clone, Copy, Debug)]
pub struct PointState {
    pub at: Point,
    pub rates: Option<(Vec2, Vec2)>,
    pub analogue: Option<(Vec2, Vec2)>,
}

/// A prismatic pair's relative motion at one position.
#[derive(Clone, Debug)]
pub struct Slide {
    pub pair: usize,
    /// Displacement of the slider's point along the guide from the sketch (m).
    pub s: f64,
    /// Relative velocity and acceleration along the guide.
    pub v: f64,
    pub a: f64,
    /// Coriolis acceleration 2·ω_guide × v_rel (zero on a fixed guide).
    pub coriolis: Vec2,
    /// Transfer functions s' and s''.
    pub s_q: f64,
    pub s_qq: f64,
}

impl Solved {
    /// Relative motion in every prismatic pair between solved links.
    pub fn slides(&self, an: &Analysis) -> Vec<Slide> {
        let m = &an.mech;
        let mut out = Vec::new();
        for (k, pr) in m.prismatics.iter().enumerate() {
            if !(an.include[pr.slider] && an.include[pr.guide]) {
                continue;
            }
            let (ps, pg) = (self.config.pose(pr.slider), self.config.pose(pr.guide));
            let u = pg.dir(pr.line_dir);
            let q = ps.apply(pr.slider_local);
            let gs = m.links[pr.guide].sketch_pose;
            let q_local = crate::geom::rotate(q - pg.origin, -pg.angle);
            let q0_local =
                crate::geom::rotate(m.scene.points[pr.point].sketch - gs.origin, -gs.angle);
            let s = pr.line_dir.dot(q_local - q0_local);
            let rel = |mo: &[Option<Motion>]| -> Option<(f64, f64, Vec2)> {
                let (a, b) = (mo[pr.slider]?, mo[pr.guide]?);
                let v = u.dot(a.velocity(q) - b.velocity(q));
                let cor = perp(u) * (2.0 * b.omega * v);
                let acc = u.dot(a.acceleration(q) - b.acceleration(q) - cor);
                Some((v, acc, cor))
            };
            let (v, a, coriolis) = rel(&self.motion).unwrap_or((0.0, 0.0, Vec2::ZERO));
            let (s_q, s_qq, _) = rel(&self.analogue).unwrap_or((0.0, 0.0, Vec2::ZERO));
            out.push(Slide {
                pair: k,
                s,
                v,
                a,
                coriolis,
                s_q,
                s_qq,
            });
        }
        out
    }

    /// Place, velocity, acceleration of point `p` (route (a)).
    pub fn point(&self, an: &Analysis, p: usize) -> PointState {
        let l = an.carrier(p);
        let at = self.config.point(&an.mech, l, p);
        let st = |mo: &[Option<Motion>]| mo[l].map(|x| (x.velocity(at), x.acceleration(at)));
        PointState {
            at,
            rates: st(&self.motion),
            analogue: st(&self.analogue),
        }
    }
}
