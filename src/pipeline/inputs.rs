//! The input values of the positions asked for, each with how far it may
//! be from the value the scene means: half an ulp of a written value, or,
//! for `positions.count`, the error of the extreme position the steps
//! start from. The cross-check moves every input by that much with the
//! data ([`Analysis::cross_check`]), so every printed bound covers it.

use super::Analysis;
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Pose, wrap_pi};
use crate::kinematics::analytic::Coords;
use crate::kinematics::positions::describe_input;
use crate::kinematics::solve::inputs::{Found, count_step, in_line_extremes};
use crate::model::scene::{MAX_INPUTS, PositionsSpec, Scene};
use std::f64::consts::TAU;

/// The positions asked for, made one at a time as a sweep reaches them
/// (a sweep of a million positions keeps no list of them): every input's
/// coordinates (rad or m) and, position by position, a bound on each
/// one's error.
#[derive(Clone, Debug)]
pub struct InputPositions<'a> {
    scene: &'a Scene,
    /// `positions.count`'s steps; `None`: the values the scene lists.
    steps: Option<Steps>,
}

/// One position asked for: every input's coordinates and how far each
/// may be from the value the scene means.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InputPosition {
    pub value: Coords,
    pub rounding: Coords,
}

/// `positions.count`: equal steps of a revolution of the crank from the
/// start of the working stroke, each with the start's error bound.
#[derive(Clone, Copy, Debug)]
struct Steps {
    start: f64,
    count: usize,
    /// The sense of the crank's turning, ±1.
    sense: f64,
    rounding: f64,
}

impl InputPositions<'_> {
    /// How many positions the scene asks for.
    pub(crate) fn len(&self) -> usize {
        match (&self.steps, &self.scene.positions) {
            (Some(steps), _) => steps.count,
            (None, PositionsSpec::List(v)) => v.len(),
            (None, PositionsSpec::Values(v)) => v.len(),
            (None, PositionsSpec::Single | PositionsSpec::Count { .. }) => 1,
        }
    }

    /// Position `k` (from 0, in the sweep's order); `None` past the last.
    pub fn get(&self, k: usize) -> Option<InputPosition> {
        (k < self.len()).then(|| self.at(k))
    }

    /// Every position in order, each made as it is reached.
    pub fn iter(&self) -> impl Iterator<Item = InputPosition> + '_ {
        (0..self.len()).filter_map(|k| self.get(k))
    }

    /// Position `k`, which is one of the positions asked for.
    fn at(&self, k: usize) -> InputPosition {
        let sc = self.scene;
        if let Some(s) = &self.steps {
            return InputPosition {
                value: Coords::one(count_step(s.start, s.sense, k, s.count)),
                rounding: Coords::one(s.rounding),
            };
        }
        let value = match &sc.positions {
            PositionsSpec::List(v) => Coords::one(v[k]),
            PositionsSpec::Values(v) => Coords::new(&v[k]),
            PositionsSpec::Single | PositionsSpec::Count { .. } => {
                // The inputs' own values, as the scene states them.
                let mut own = [0.0; MAX_INPUTS];
                for (x, i) in own.iter_mut().zip(sc.inputs()) {
                    *x = i.coordinate();
                }
                Coords::new(&own[..sc.input_count()])
            }
        };
        // The rounding of the values as the file writes them, where the
        // reader recorded it; none for values made in the program.
        let w = value.len();
        let rounding = match sc.input_rounding.get(k * w..(k + 1) * w) {
            Some(r) if sc.input_rounding.len() == self.len() * w => Coords::new(r),
            _ => Coords::new(&[0.0; MAX_INPUTS][..w]),
        };
        InputPosition { value, rounding }
    }
}

impl Analysis {
    /// The positions asked for with their error bounds
    /// ([`InputPositions`]): for `positions.count`, the start of the
    /// working stroke and its error found here, the steps made as the
    /// sweep reaches them.
    pub fn input_positions(&self) -> Result<InputPositions<'_>> {
        let sc = &self.mech.scene;
        let PositionsSpec::Count { count, output } = sc.positions else {
            return Ok(InputPositions { scene: sc, steps: None });
        };
        let out = output.unwrap_or_else(|| self.default_output());
        let start = self.stroke_start(out)?;
        let error = match start.found {
            // The input's angle as written: its own rounding.
            Found::Input => sc.input_rounding.first().copied().unwrap_or(0.0),
            Found::InLine => self.in_line_error(out, start.angle)?,
            Found::Root => self.root_error(out, start.angle)?,
        };
        // With the rounding of the steps and of the reduction to a turn.
        let steps = Steps {
            start: start.angle,
            count,
            sense: sc.input.sense(),
            rounding: error + 4.0 * f64::EPSILON * TAU,
        };
        Ok(InputPositions {
            scene: sc,
            steps: Some(steps),
        })
    }

    /// The error of a start where crank and coupler lie in line: what the
    /// data's rounding moves it — the collinearity solved again with each
    /// datum alone changed by [`ACCURACY`]`.data_roundings` units, the
    /// moves summed (changed together, the data's changes may cancel in
    /// the one quantity that matters near a flat triangle, the gap
    /// r + l − (|OC| + c)), per unit — twice over for the few roundings of
    /// the closed form itself (the sums r + l, the distance |OC|), each of
    /// the size of a datum's.
    fn in_line_error(&self, out: usize, q: f64) -> Result<f64> {
        let mut moved = 0.0f64;
        let mut i = 1;
        while let Some(changed) = self.changed_datum(i) {
            i += 1;
            let changed = changed.map_err(|e| {
                Error::scene(
                    "/positions/count",
                    format!("the extreme position that begins the working stroke: {e}"),
                )
            })?;
            let near = in_line_extremes(&changed, out)
                .into_iter()
                .map(|c| wrap_pi(c - q).abs())
                .fold(f64::INFINITY, f64::min);
            moved += near;
        }
        if !moved.is_finite() {
            return Err(Error::singular(
                describe_input(&self.mech, &[q]),
                "the extreme position that begins the working stroke (for /positions/count) is decided by the rounding of the data: with the data changed by a few units of rounding the crank and the coupler no longer lie in line there; give the positions as angles",
            ));
        }
        Ok(2.0 * moved / ACCURACY.data_roundings)
    }

    /// The error of a root `phi` of the output's first transfer function
    /// T: (|T(φ)| + T's printed bound) / |T'(φ)|, the position there
    /// solved and checked as any other (its bound covers the rounding of
    /// the arithmetic and of the data); a refusal there refuses the start.
    fn root_error(&self, out: usize, phi: f64) -> Result<f64> {
        let m = &self.mech;
        let mut scene = m.scene.clone();
        scene.positions = PositionsSpec::List(vec![phi]);
        scene.input_rounding = vec![4.0 * f64::EPSILON * TAU];
        scene.want.velocity = true;
        scene.want.acceleration = true;
        scene.want.plans = false;
        // Every point, so that the output is solved whatever the scene
        // reports.
        scene.want.points = None;
        scene.dynamics = None;
        let refusal = |e: Error| {
            Error::singular(
                describe_input(m, &[phi]),
                format!(
                    "the extreme position that begins the working stroke (for /positions/count) cannot be found reliably ({e}); give the positions as angles"
                ),
            )
        };
        let one = Analysis::new(scene).map_err(refusal)?;
        let solved = one.run().map_err(refusal)?;
        let s = &solved[0];
        let bound = s
            .check
            .as_ref()
            .and_then(|c| c.bound)
            .expect("a checked position has its bounds");
        let mo = s.analogue[out].expect("the output is solved");
        let (t, dt, b) = match m
            .prismatics
            .iter()
            .find(|p| p.slider == out && p.guide == m.frame())
        {
            Some(pr) => {
                let u = pr.line(&Pose::IDENTITY).dir;
                let at = s.config.pose(out).apply(pr.slider_local);
                (u.dot(mo.velocity(at)), u.dot(mo.acceleration(at)), bound.v_q)
            }
            None => (mo.omega, mo.epsilon, bound.phi_q),
        };
        let error = (t.abs() + b) / dt.abs();
        if !error.is_finite() {
            return Err(refusal(Error::singular(
                describe_input(m, &[phi]),
                "the output's second transfer function vanishes there too",
            )));
        }
        Ok(error)
    }
}
