//! Route (b)'s path follower: the assembly followed along the inputs by a
//! predictor along the path's tangent, Newton's corrector and step
//! control.

use super::{ConstraintSolver, MAX_TURN};
use crate::accuracy::ACCURACY;
use crate::kinematics::analytic::Coords;
use crate::kinematics::positions::describe_input;
use nalgebra::DVector;

/// The path a walk follows. Its parameter x: a single input's own
/// coordinate; several inputs move together, straight from the start to
/// the end, as x goes from 0 to 1.
struct Path<'s> {
    /// The inputs at the start, and their change.
    from: Coords,
    span: &'s [f64],
    several: bool,
    /// x at the start and at the end.
    start: f64,
    end: f64,
    /// The inputs' rates along x, and the same over their scales.
    rates: Coords,
    scaled: Vec<f64>,
    /// The largest step and the smallest worth taking.
    max_step: f64,
    min_step: f64,
    /// The length of the way in x and its direction.
    length: f64,
    dir: f64,
    /// Every input stands to its rounding: no path, only the corrector.
    standing: bool,
}

impl Path<'_> {
    /// The inputs at x.
    fn at(&self, x: f64) -> Coords {
        if self.several {
            let mut q = self.from;
            for (q, d) in q.iter_mut().zip(self.span) {
                *q += x * d;
            }
            q
        } else {
            Coords::one(x)
        }
    }
}

impl ConstraintSolver<'_> {
    /// The tangent of the path, dq/dx from Φ_q·q' = −∂Φ/∂x (the drivers'
    /// rows alone depend on x: each by its input's rate along the path,
    /// `dx`), and the sign of det Φ_q: the sign of the assembly's
    /// orientation, which changes only where the path meets a singular
    /// position (where two assemblies meet).
    fn tangent(&self, dx: &[f64]) -> Option<(DVector<f64>, f64)> {
        let j = self.jacobian(&self.q);
        let mut b = DVector::zeros(self.rows());
        for &(i, row) in &self.driver_rows {
            b[row] = dx[i];
        }
        let lu = j.lu();
        let u = lu.u();
        let mut sign: f64 = lu.p().determinant();
        for i in 0..u.nrows().min(u.ncols()) {
            sign *= u[(i, i)].signum();
        }
        Some((lu.solve(&b)?, sign))
    }

    /// A direction on the path in the links' own lengths (x, y over the
    /// link's size, θ, and each input over its own scale), of unit length,
    /// to measure how the path turns: `t` the tangent, `dx` the inputs'
    /// rates along the path over their scales.
    fn unit_direction(&self, t: &DVector<f64>, dx: &[f64]) -> DVector<f64> {
        let mut d = DVector::zeros(t.len() + dx.len());
        for i in 0..self.eq.links.len() {
            d[3 * i] = t[3 * i] / self.scale[i];
            d[3 * i + 1] = t[3 * i + 1] / self.scale[i];
            d[3 * i + 2] = t[3 * i + 2];
        }
        for (k, x) in dx.iter().enumerate() {
            d[t.len() + k] = *x;
        }
        let n = d.norm();
        if n > 0.0 { d / n } else { d }
    }

    /// Input i's own scale: a crank in radians, a slider in its link's size.
    fn input_scale(&self, i: usize) -> f64 {
        let m = self.m;
        let spec = m.scene.input_at(i);
        if spec.is_crank() {
            1.0
        } else {
            let l = spec.link();
            self.eq.slot[l].map_or(m.size, |k| self.scale[k])
        }
    }

    /// Input i's largest step along the path.
    fn input_step(&self, i: usize) -> f64 {
        if self.m.scene.input_at(i).is_crank() {
            ACCURACY.max_path_step.to_radians()
        } else {
            0.01 * ACCURACY.max_path_step * self.input_scale(i)
        }
    }

    /// The path from the last solved inputs by `span`.
    fn path<'s>(&self, span: &'s [f64]) -> Path<'s> {
        let from = self.last_inputs();
        let several = span.len() > 1;
        let scale_of = |i: usize| self.input_scale(i);
        let step_of = |i: usize| self.input_step(i);
        // (start, end), the inputs' rates along x.
        let (start, end, rates) = if several {
            (0.0, 1.0, Coords::new(span))
        } else {
            (from[0], from[0] + span[0], Coords::one(1.0))
        };
        let scaled: Vec<f64> = rates
            .iter()
            .enumerate()
            .map(|(i, r)| r / scale_of(i))
            .collect();
        // Inputs standing to their rounding: no path, only the corrector.
        let rounding = |i: usize| {
            64.0 * f64::EPSILON * (from[i].abs() + (from[i] + span[i]).abs() + scale_of(i))
        };
        let standing = several && (0..span.len()).all(|i| span[i].abs() <= rounding(i));
        let (max_step, min_step) = if several {
            let moving = (0..span.len()).filter(|&i| span[i] != 0.0);
            let max = moving
                .clone()
                .map(|i| step_of(i) / span[i].abs())
                .fold(1.0, f64::min);
            // The smallest step worth taking: the rounding of the inputs.
            let min = moving
                .map(|i| {
                    64.0 * f64::EPSILON
                        * (from[i].abs().max((from[i] + span[i]).abs()) + scale_of(i))
                        / span[i].abs()
                })
                .fold(64.0 * f64::EPSILON, f64::max);
            (max, min)
        } else {
            (
                step_of(0),
                64.0 * f64::EPSILON * (start.abs().max(end.abs()) + scale_of(0)),
            )
        };
        let (length, dir) = if several {
            (1.0, 1.0)
        } else {
            (span[0].abs(), span[0].signum())
        };
        Path {
            from,
            span,
            several,
            start,
            end,
            rates,
            scaled,
            max_step,
            min_step,
            length,
            dir,
            standing,
        }
    }

    /// Follow the assembly along the inputs from the last solved
    /// coordinates by `span`: a predictor along the path's tangent,
    /// Newton's corrector, and step control. A step is halved when the
    /// path turns by more than [`MAX_TURN`] over it, when the corrector
    /// does not contract (each correction at most half the last), or when
    /// the Jacobian is singular on the way; it grows again after easy
    /// steps. So a narrow neck (a near-toggle, a change point passed at
    /// 1e-11) is passed on the same assembly in steps as small as the
    /// neck, and open country in steps up to 5° (or 5 % of the input
    /// link's size).
    ///
    /// This is the same branch that route (a) takes by its sign rule: the
    /// orientation sign of a group (docs/analysis.md) changes only through
    /// a toggle, where the two assemblies meet; a path that never meets
    /// the other assembly keeps its sign.
    ///
    /// The path's parameter x: a single input's own coordinate; several
    /// inputs move together, straight from the start to the end, as x goes
    /// from 0 to 1.
    pub(super) fn walk(&mut self, span: &[f64]) -> std::result::Result<(), String> {
        let path = self.path(span);
        if path.standing {
            self.steps = 0;
            return self.newton(&path.at(path.end), false).map(|_| ());
        }
        let (end, dir) = (path.end, path.dir);
        let mut x = path.start;
        let mut h = path.max_step.min(path.length);
        self.steps = 0;
        let Some((mut t, sign)) = self.tangent(&path.rates) else {
            return Err("the constraint Jacobian is singular at the start of the path".into());
        };
        while (end - x) * dir > 0.0 {
            let to = if (end - x).abs() <= h {
                end
            } else {
                x + dir * h
            };
            match self.path_step(&path, &t, sign, x, to) {
                Some((t_new, turn)) => {
                    x = to;
                    t = t_new;
                    self.steps += 1;
                    if turn < 0.25 * MAX_TURN {
                        h = (h * 1.5).min(path.max_step);
                    }
                }
                None => {
                    h *= 0.5;
                    if h < path.min_step {
                        return Err(self.stuck(&path, x, h));
                    }
                }
            }
        }
        Ok(())
    }

    /// One step of the walk from x to `to` (the tangent `t` at x, the
    /// orientation `sign`): the tangent at `to` and how far the path
    /// turned, or `None` (the state left at x) when the step does not
    /// stand.
    fn path_step(
        &mut self,
        path: &Path,
        t: &DVector<f64>,
        sign: f64,
        x: f64,
        to: f64,
    ) -> Option<(DVector<f64>, f64)> {
        let dx = to - x;
        let saved = self.q.clone();
        // Predictor along the tangent, then Newton's corrector.
        self.q += t * dx;
        // The step stands if the corrector contracts, the path turns
        // little over it, and the orientation keeps its sign: a step
        // over a narrow neck, whose ends may look alike, lands on the
        // other assembly, of the other sign.
        let accepted = match self.newton(&path.at(to), true) {
            Ok(_) => match self.tangent(&path.rates) {
                Some((t_new, sign_new)) => {
                    let a = self.unit_direction(t, &path.scaled);
                    let b = self.unit_direction(&t_new, &path.scaled);
                    let turn = a.dot(&b).clamp(-1.0, 1.0).acos();
                    (turn <= MAX_TURN && sign_new == sign).then_some((t_new, turn))
                }
                None => None,
            },
            Err(_) => None,
        };
        if accepted.is_none() {
            self.q = saved;
        }
        accepted
    }

    /// The failure of a walk stuck at x: steps down to `h` do not converge.
    fn stuck(&self, path: &Path, x: f64, h: f64) -> String {
        let m = self.m;
        let unit = if path.several {
            " of the way"
        } else if m.scene.input.is_crank() {
            " rad"
        } else {
            " m"
        };
        format!(
            "the assembly cannot be followed past {} (steps down to {}{unit} do not converge on it)",
            describe_input(m, &path.at(x)),
            crate::format::format_quantity(h, "")
        )
    }
}
