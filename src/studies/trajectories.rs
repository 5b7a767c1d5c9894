//! The trajectories of a solved mechanism's points and its output's
//! extreme positions, for the drawings of its positions (the positions
//! sheet, the course sheet): the paths of the coupler points through 72
//! positions per revolution of a crank turning fully (else through the
//! solved ones), the crank's circle, and the output's extreme positions
//! the solved ones leave out, each solved on the branch of the first
//! position. Computed here, with the position solver, only when such a
//! drawing is asked for: the drawing reads them.

use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::kinematics::solve::{Analysis, Position};
use crate::model::mechanism::Mechanism;
use crate::model::scene::{InputSpec, PositionsSpec};
use kurbo::Point;
use std::ops::Deref;

/// What the trajectories read of a solved position: its (first) input's
/// coordinate and its configuration.
pub trait Placed {
    fn q(&self) -> f64;
    fn config(&self) -> &Configuration;
}

impl<S: Deref<Target = Position>> Placed for S {
    fn q(&self) -> f64 {
        self.deref().q
    }
    fn config(&self) -> &Configuration {
        &self.deref().config
    }
}

/// A solved position as the trajectories read it, and no more: what a
/// long sweep drawn without holding its positions keeps of each.
#[derive(Clone, Debug)]
pub struct Sketch {
    pub q: f64,
    pub config: Configuration,
}

impl Placed for Sketch {
    fn q(&self) -> f64 {
        self.q
    }
    fn config(&self) -> &Configuration {
        &self.config
    }
}

/// The trajectories of the coupler points (m), the crank's circle and
/// the output's extreme positions ([`trajectories`]).
#[derive(Clone, Debug, Default)]
pub struct Trajectories {
    /// Each tracked point's path, m.
    pub paths: Vec<Vec<Point>>,
    /// The crank's pivot and radius, m, when it turns fully.
    pub circle: Option<(Point, f64)>,
    /// The output's extreme positions not among the positions solved (the
    /// end of the working stroke, and its start where the positions do
    /// not begin there), each with its sign: 0 for the start, 1 the end.
    pub extremes: Vec<(Configuration, usize)>,
}

/// The input link's point off the frame (a crank's end), if it has one.
pub fn crank_tip(m: &Mechanism) -> Option<usize> {
    m.links[m.scene.input.link()]
        .points
        .iter()
        .copied()
        .find(|&p| !m.links_of_point(p).contains(&m.frame()))
}

/// The trajectories of the points of the `solved` positions that are
/// neither on the frame, nor on a link turning about a fixed pivot, nor on
/// a slider of a frame guide: through 72 positions per revolution of a
/// crank turning fully, else through the solved ones; with the crank's
/// circle and the output's extreme positions when the crank turns fully.
pub fn trajectories<S: Placed>(an: &Analysis, solved: &[S]) -> Trajectories {
    let m = &an.mech;
    if solved.is_empty() {
        return Trajectories::default();
    }
    let full_turn = matches!(m.scene.input, InputSpec::Crank { .. })
        && !m.scene.several_inputs()
        && solved.len() >= 12;
    let tracked = tracked(an);
    let mut paths: Vec<Vec<Point>> = Vec::new();
    if full_turn && let Ok(mut ps) = PositionSolver::new(m, &an.structure, an.need.clone()) {
        let q0 = solved[0].q();
        let dir = m.scene.input.sense();
        let mut ok = true;
        let mut samples: Vec<Vec<Point>> = vec![Vec::new(); tracked.len()];
        for k in 0..=72 {
            match ps.solve(q0 + dir * std::f64::consts::TAU * k as f64 / 72.0) {
                Ok(cfg) => {
                    for (i, &(p, l)) in tracked.iter().enumerate() {
                        samples[i].push(cfg.point(m, l, p));
                    }
                }
                Err(_) => {
                    ok = false;
                    break;
                }
            }
        }
        if ok {
            paths = samples;
        }
    }
    if paths.is_empty() {
        paths = tracked
            .iter()
            .map(|&(p, l)| solved.iter().map(|s| s.config().point(m, l, p)).collect())
            .collect();
    }
    let input = m.scene.input.link();
    let circle = match (&m.scene.input, crank_tip(m)) {
        (InputSpec::Crank { pivot, .. }, Some(p)) if full_turn => {
            let o = solved[0].config().point(m, m.frame(), *pivot);
            Some((o, (solved[0].config().point(m, input, p) - o).hypot()))
        }
        _ => None,
    };
    let extremes = if full_turn {
        extremes(an, solved)
    } else {
        Vec::new()
    };
    Trajectories {
        paths,
        circle,
        extremes,
    }
}

/// The points tracked, each with the link it is read on: those neither on
/// the frame, nor on a link turning about a fixed pivot, nor on a slider
/// of a frame guide.
fn tracked(an: &Analysis) -> Vec<(usize, usize)> {
    let m = &an.mech;
    (0..m.scene.points.len())
        .filter_map(|p| {
            let ls = m.links_of_point(p);
            let l = *ls.iter().find(|&&l| an.link(l))?;
            let pivoted = |l: usize| {
                l == m.frame()
                    || m.links[l]
                        .points
                        .iter()
                        .any(|&q| m.links_of_point(q).contains(&m.frame()))
            };
            let slides_on_frame = m
                .prismatics
                .iter()
                .any(|pr| pr.slider == l && pr.guide == m.frame());
            (!ls.iter().all(|&l| pivoted(l)) && !slides_on_frame).then_some((p, l))
        })
        .collect()
}

/// The output's two extreme positions (the start and the end of its
/// working stroke) that are not among the `solved` ones, followed from
/// the first solved position on its branch; none where the output turns
/// fully or a position cannot be reached.
fn extremes<S: Placed>(an: &Analysis, solved: &[S]) -> Vec<(Configuration, usize)> {
    let m = &an.mech;
    let out = match m.scene.positions {
        PositionsSpec::Count {
            output: Some(out), ..
        } => out,
        _ => an.default_output(),
    };
    let Ok((start, stroke)) = an.working_stroke(out) else {
        return Vec::new();
    };
    if stroke >= std::f64::consts::TAU {
        return Vec::new();
    }
    let Ok(mut ps) = PositionSolver::new(m, &an.structure, an.need.clone()) else {
        return Vec::new();
    };
    let dir = m.scene.input.sense();
    let q0 = solved[0].q();
    // The start, unwound to within a turn after the first position.
    let start = q0 + dir * (dir * (start - q0)).rem_euclid(std::f64::consts::TAU);
    let drawn = |q: f64| {
        solved.iter().any(|s| {
            let d = (s.q() - q).rem_euclid(std::f64::consts::TAU);
            d.min(std::f64::consts::TAU - d) < 1e-9
        })
    };
    let mut out = Vec::new();
    if ps.solve(q0).is_err() {
        return out;
    }
    for (which, q) in [(0, start), (1, start + dir * stroke)] {
        match ps.solve(q) {
            Ok(config) if !drawn(q) => out.push((config, which)),
            Ok(_) => {}
            Err(_) => return Vec::new(),
        }
    }
    out
}
