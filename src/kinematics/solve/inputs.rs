//! The input values of the positions asked for, and the extreme position
//! that begins the working stroke (`positions.count`).

use super::Analysis;
use crate::error::{Error, Result};
use crate::geom::{Pose, wrap_pi};
use crate::kinematics::analytic::{Coords, Motion, Order, contour};
use crate::kinematics::positions::{Configuration, PositionSolver};
use crate::model::scene::{InputSpec, PositionsSpec};

impl Analysis {
    /// The first input's coordinates of the positions asked for (rad or
    /// m): with one input, the positions' input values.
    pub fn input_values(&self) -> Result<Vec<f64>> {
        Ok(self.input_coords()?.iter().map(|q| q.first()).collect())
    }

    /// Every input's coordinates at each position asked for (rad or m).
    pub fn input_coords(&self) -> Result<Vec<Coords>> {
        let sc = &self.mech.scene;
        if let PositionsSpec::Values(v) = &sc.positions {
            return Ok(v.iter().map(|q| Coords::new(q)).collect());
        }
        if let PositionsSpec::Single = &sc.positions {
            let q: Vec<f64> = sc.inputs().map(|i| i.coordinate()).collect();
            return Ok(vec![Coords::new(&q)]);
        }
        Ok(match &sc.positions {
            PositionsSpec::Single | PositionsSpec::Values(_) => unreachable!("returned above"),
            PositionsSpec::List(v) => v.iter().map(|&q| Coords::one(q)).collect(),
            PositionsSpec::Count { count, output } => {
                let out = output.unwrap_or_else(|| self.default_output());
                let start = self.working_stroke_start(out)?;
                let dir = sc.input.sense();
                (0..*count)
                    .map(|k| {
                        Coords::one(
                            (start + dir * std::f64::consts::TAU * k as f64 / *count as f64)
                                .rem_euclid(std::f64::consts::TAU),
                        )
                    })
                    .collect()
            }
        })
    }

    /// The output whose extreme position starts `positions.count`: the
    /// last link of the last group.
    pub fn default_output(&self) -> usize {
        *self
            .structure
            .groups
            .last()
            .map(|g| g.links())
            .unwrap_or_default()
            .last()
            .unwrap_or(&self.mech.scene.input.link())
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
        Ok(self.working_stroke(out)?.0)
    }

    /// The crank angle at which the working stroke of `out` begins (as
    /// [`Analysis::working_stroke_start`]) and the crank angle it takes
    /// (a full turn for an output without extreme positions).
    pub fn working_stroke(&self, out: usize) -> Result<(f64, f64)> {
        let m = &self.mech;
        let sc = &m.scene;
        if sc.several_inputs() {
            return Err(Error::scene(
                "/input",
                "the extreme positions of an output over a revolution of the crank are defined for a single crank input; this scene has several inputs",
            ));
        }
        let InputSpec::Crank { angle, .. } = sc.input else {
            return Err(Error::scene(
                "/positions/count",
                "equal steps over a revolution need a crank input",
            ));
        };
        let mut need = self.structure.needed_for(&[out]);
        for (n, own) in need.iter_mut().zip(&self.need) {
            *n |= *own;
        }
        let mut tf = Transfer {
            an: self,
            ps: PositionSolver::new(m, &self.structure, need.clone())?,
            need,
            out,
        };
        let n = 720;
        let samples = tf.revolution(angle, n)?;
        let angular = !m
            .prismatics
            .iter()
            .any(|p| p.slider == out && p.guide == m.frame());
        // Unwrap an angular output so that min/max compare.
        let mut extremes: Vec<(f64, f64)> = Vec::new();
        for k in 0..n {
            let (p0, _, d0) = samples[k];
            let (p1, _, d1) = samples[k + 1];
            if d0 == 0.0 || d0.signum() != d1.signum() {
                let (root, x) = tf.extreme(p0, p1, d0)?;
                let x = if angular {
                    let base = samples[0].1;
                    base + wrap_pi(x - base)
                } else {
                    x
                };
                extremes.push((root, x));
            }
        }
        if extremes.len() < 2 {
            // No extreme positions: the output turns fully; start at the input.
            return Ok((angle, std::f64::consts::TAU));
        }
        Ok(working_stroke_of(&extremes, sc.input.sense()))
    }
}

/// The working stroke from the output's extreme positions (crank angle,
/// output), the crank turning in the sense `dir`: the crank angle it
/// begins at and the crank angle it takes.
fn working_stroke_of(extremes: &[(f64, f64)], dir: f64) -> (f64, f64) {
    let lo = extremes.iter().copied().fold(
        (0.0, f64::INFINITY),
        |acc, e| if e.1 < acc.1 { e } else { acc },
    );
    let hi =
        extremes.iter().copied().fold(
            (0.0, f64::NEG_INFINITY),
            |acc, e| if e.1 > acc.1 { e } else { acc },
        );
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
    (
        start.rem_euclid(std::f64::consts::TAU),
        d_lo_hi.max(d_hi_lo),
    )
}

/// The output `out` and its first transfer function over the crank
/// angle, the positions followed continuously (`need`: the groups solved).
struct Transfer<'a> {
    an: &'a Analysis,
    ps: PositionSolver<'a>,
    need: Vec<bool>,
    out: usize,
}

impl Transfer<'_> {
    /// The output and its transfer function at crank angle φ, reached in
    /// steps from the last position (`step`) or at once.
    fn eval(&mut self, phi: f64, step: bool) -> Result<(f64, f64)> {
        let an = self.an;
        let m = &an.mech;
        let c = if step {
            self.ps.solve(phi)?
        } else {
            self.ps.solve_at(phi)?
        };
        let mo = contour::transfer(m, &an.structure, &self.need, &c, phi, Order::Velocity)?;
        Ok(an.output_coordinate(self.out, &c, &mo))
    }

    /// (φ, output, transfer function) at `n` + 1 crank angles over a
    /// revolution from `angle`.
    fn revolution(&mut self, angle: f64, n: usize) -> Result<Vec<(f64, f64, f64)>> {
        let mut samples = Vec::with_capacity(n + 1);
        for k in 0..=n {
            let phi = angle + std::f64::consts::TAU * k as f64 / n as f64;
            let v = self.eval(phi, true).map_err(|e| match e {
                Error::Unsolvable(crate::error::Unsolvable::Assembly { group, at, why }) => Error::assembly(group, at, format!("{why}; the crank cannot turn fully, so /positions/count (a full revolution) is impossible")),
                e => e,
            })?;
            samples.push((phi, v.0, v.1));
        }
        Ok(samples)
    }

    /// The extreme position between crank angles `p0` and `p1` (the
    /// transfer function `d0` at p0 changes sign): its crank angle, by
    /// bisection polished to the last ulp, and the output there.
    fn extreme(&mut self, p0: f64, p1: f64, d0: f64) -> Result<(f64, f64)> {
        self.ps.solve(p0)?;
        let (mut a, mut b, mut fa) = (p0, p1, d0);
        for _ in 0..200 {
            let mid = 0.5 * (a + b);
            if mid <= a || mid >= b {
                break;
            }
            let (_, fm) = self.eval(mid, false)?;
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
        let (x, _) = self.eval(root, false)?;
        Ok((root, x))
    }
}
