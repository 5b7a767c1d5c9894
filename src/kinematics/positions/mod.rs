//! Positions: the input placed exactly, then every group in the order of
//! attachment by its closed form (circle∩circle, circle∩line, line∩line, the
//! rocking-guide angle) on the branch the sketch shows. A class III group is
//! solved by a one-dimensional root search in its base angle, tracked
//! continuously from the sketch.

mod configuration;
mod dyad;
mod input;
mod triad;

use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Pose, sign_tol, wrap_pi};
use crate::kinematics::analytic::Coords;
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Dyad, DyadKind, Step, Structure};

pub(crate) use dyad::{rocking_guide, rrr_points, solve_group_dyad};
pub(crate) use input::{CrankFrame, crank_frame};
pub use input::{
    place_across, place_input, sketch_input, sketch_slider_ref, slide_pose,
};
use triad::triad_scale;
pub use configuration::*;
pub(crate) use triad::{solve_triad, triad_error};

/// Branch of each group as the sketch shows it, plus the tracked state of
/// class III groups (their base angle).
#[derive(Clone, Debug)]
pub struct Branches {
    pub sign: Vec<f64>,
    /// Tracked base pose of each class III group.
    pub triad_pose: Vec<Pose>,
}

impl Branches {
    /// Read every group's branch off the sketch.
    pub fn from_sketch(m: &Mechanism, s: &Structure) -> Result<Branches> {
        // Relative to the group's own lengths (`dyad_sign` is a sine or a
        // cosine), not to the sketch's size: a far point of some other link
        // must not make a group in general position look like a dead point.
        let tol = ACCURACY.branch_dead_band;
        let mut sign = Vec::new();
        let mut triad_pose = Vec::new();
        for g in &s.groups {
            let (sg, pose) = match g {
                AssurGroup::Dyad(d) => (dyad_sign(m, d), Pose::IDENTITY),
                // A class III group's branch is tracked continuously from the sketch.
                AssurGroup::Triad(t) => (1.0, m.links[t.base].sketch_pose),
            };
            let sg_tol = sign_tol(sg, tol);
            if sg_tol == 0.0 && sg.is_finite() && needs_sign(g) {
                return Err(Error::structure(format!(
                    "the sketch shows group {} at a dead point (its branch cannot be read off the drawing); draw it in a general position",
                    g.label(m)
                )));
            }
            sign.push(if needs_sign(g) { sg_tol } else { 1.0 });
            triad_pose.push(pose);
        }
        Ok(Branches { sign, triad_pose })
    }
}

fn needs_sign(g: &AssurGroup) -> bool {
    match g {
        AssurGroup::Dyad(d) => !matches!(d.kind, DyadKind::Prp | DyadKind::Rpp),
        AssurGroup::Triad(_) => false,
    }
}

fn dyad_sign(m: &Mechanism, d: &Dyad) -> f64 {
    match d.kind {
        DyadKind::Rrr => {
            let (b, c, dd) = (
                sketch(m, point_of(d.ext1.joint)),
                sketch(m, point_of(d.mid.joint)),
                sketch(m, point_of(d.ext2.joint)),
            );
            (dd - b).cross(c - b) / ((dd - b).hypot() * (c - b).hypot()).max(f64::MIN_POSITIVE)
        }
        DyadKind::Rrp => {
            let b = sketch(m, point_of(d.ext1.joint));
            let c = sketch(m, point_of(d.mid.joint));
            (c - b).dot(sketch_guide_dir(m, pair_of(d.ext2.joint)))
                / (c - b).hypot().max(f64::MIN_POSITIVE)
        }
        DyadKind::Rpr => {
            let rg = rocking_guide(m, d);
            let u = sketch_guide_dir(m, pair_of(d.mid.joint));
            let w = sketch(m, rg.pin_slider) - sketch(m, rg.pin_guide);
            u.dot(w) / w.hypot().max(f64::MIN_POSITIVE)
        }
        DyadKind::Prp | DyadKind::Rpp => 1.0,
    }
}

/// The largest step of input `i` in which class III groups are tracked: 2°
/// of a crank, a hundredth of the smallest class III group of a slider.
pub(crate) fn triad_step(m: &Mechanism, s: &Structure, need: &[bool], i: usize) -> f64 {
    match m.scene.input_at(i) {
        InputSpec::Crank { .. } => 2f64.to_radians(),
        // A hundredth of the smallest class III group: the groups'
        // own size, not the sketch's.
        InputSpec::Slider { .. } => {
            0.01 * s
                .groups
                .iter()
                .zip(need)
                .filter_map(|(g, &n)| match g {
                    AssurGroup::Triad(t) if n => Some(triad_scale(m, t)),
                    _ => None,
                })
                .fold(f64::INFINITY, f64::min)
        }
    }
}

/// The change of the input coordinates from `from` to `to`: a crank the
/// short way round, a slider straight.
pub fn span(m: &Mechanism, from: &[f64], to: &[f64]) -> Coords {
    let mut d = Coords::new(to);
    for ((d, &a), spec) in d.iter_mut().zip(from).zip(m.scene.inputs()) {
        *d = match spec {
            InputSpec::Crank { .. } => wrap_pi(*d - a),
            InputSpec::Slider { .. } => *d - a,
        };
    }
    d
}

/// The input coordinates between two positions at which class III groups
/// are tracked so that they stay on their branch: the change
/// ([`span`]) cut into equal steps, none longer than the largest step
/// of its input; the last position itself is not among them.
pub(crate) struct Tracking {
    from: Coords,
    span: Coords,
    k: usize,
    n: usize,
}

impl Tracking {
    /// From `from` to `to`, input i in steps of at most `step(i)`.
    pub(crate) fn new(
        m: &Mechanism,
        from: Coords,
        to: &Coords,
        step: impl Fn(usize) -> f64,
    ) -> Tracking {
        let span = span(m, &from, to);
        let n = span
            .iter()
            .enumerate()
            .map(|(i, d)| (d.abs() / step(i)).ceil())
            .fold(0.0, f64::max) as usize;
        Tracking {
            from,
            span,
            k: 1,
            n,
        }
    }
}

impl Iterator for Tracking {
    type Item = Coords;
    fn next(&mut self) -> Option<Coords> {
        if self.k >= self.n {
            return None;
        }
        let (k, n) = (self.k, self.n);
        let mut qk = self.from;
        for (x, d) in qk.iter_mut().zip(self.span.iter()) {
            *x += d * k as f64 / n as f64;
        }
        self.k += 1;
        Some(qk)
    }
}

/// The position solver: closed forms per group with the sketch's branches.
#[derive(Clone, Debug)]
pub struct PositionSolver<'a> {
    pub m: &'a Mechanism,
    pub s: &'a Structure,
    /// Which groups to solve (demand-driven).
    pub need: Vec<bool>,
    pub branches: Branches,
    /// The input coordinates of the last solved position (for tracking).
    pub last_q: Coords,
}

impl<'a> PositionSolver<'a> {
    pub fn new(m: &'a Mechanism, s: &'a Structure, need: Vec<bool>) -> Result<Self> {
        Ok(PositionSolver {
            m,
            s,
            need,
            branches: Branches::from_sketch(m, s)?,
            last_q: sketch_input(m),
        })
    }

    /// Whether a class III group is tracked (its positions by continuation).
    pub fn has_triads(&self) -> bool {
        self.s
            .groups
            .iter()
            .zip(&self.need)
            .any(|(g, &n)| n && matches!(g, AssurGroup::Triad(_)))
    }

    /// Solve at input coordinate `q` (a single input), reached
    /// continuously from the last solved position (from the sketch at
    /// first), the short way round.
    pub fn solve(&mut self, q: f64) -> Result<Configuration> {
        self.solve_coords(Coords::one(q))
    }

    /// Solve at the input coordinates `q`, reached continuously from the
    /// last solved position (from the sketch at first), each crank the
    /// short way round.
    pub fn solve_coords(&mut self, q: Coords) -> Result<Configuration> {
        if self.has_triads() {
            // Track class III groups in small steps so they stay on their branch.
            let (m, st, need) = (self.m, self.s, &self.need);
            let steps = Tracking::new(m, self.last_q, &q, |i| triad_step(m, st, need, i));
            for qk in steps {
                self.solve_at_coords(qk)?;
            }
        }
        let c = self.solve_at_coords(q)?;
        self.last_q = q;
        Ok(c)
    }

    /// Solve at `q` (a single input) from the current tracked state
    /// without stepping.
    pub fn solve_at(&mut self, q: f64) -> Result<Configuration> {
        self.solve_at_coords(Coords::one(q))
    }

    /// Solve at the input coordinates `q` from the current tracked state
    /// without stepping.
    pub fn solve_at_coords(&mut self, q: Coords) -> Result<Configuration> {
        let (m, s) = (self.m, self.s);
        let mut c = Configuration {
            poses: vec![None; m.links.len()],
        };
        c.poses[m.frame()] = Some(Pose::IDENTITY);
        for step in s.steps(m) {
            match step {
                Step::Frame { input, link } => {
                    c.poses[link] = Some(place_input(m, input, q[input]))
                }
                Step::Chained(ch) => {
                    let Some(kp) = c.poses[ch.known] else {
                        continue;
                    };
                    c.poses[ch.other] = Some(place_across(m, ch.pair, ch.known, &kp, q[ch.input]));
                }
                Step::Group { index, .. } if !self.need[index] => {}
                Step::Group {
                    index,
                    group: AssurGroup::Dyad(d),
                } => solve_group_dyad(m, s, index, d, self.branches.sign[index], &q, &mut c)?,
                Step::Group {
                    index,
                    group: AssurGroup::Triad(t),
                } => {
                    let pose = solve_triad(m, t, self.branches.triad_pose[index], &mut c)
                        .map_err(|why| triad_error(m, s, index, &q, why))?;
                    self.branches.triad_pose[index] = pose;
                }
            }
        }
        Ok(c)
    }
}

