//! Route (b): the constraint solver, its settings, and the path followed from position to position with step control.

use crate::kinematics::analytic::equations::{Constraint, Equations, Pose as PoseOf, Prism, Rows, Vector};
use crate::kinematics::analytic::{Coords, Motion, Order};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::Pose;
use crate::kinematics::positions::{describe_input, sketch_input, span as input_span};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use kurbo::{Point, Vec2};
use nalgebra::{DMatrix, DVector};

/// Newton's stopping rule and the limit of conditioning accepted.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Stop when every correction is below `tol` × its unknown's own scale
    /// (a coordinate: its link's size and magnitude; an angle: one radian).
    pub tol: f64,
    pub max_iter: usize,
    /// Smallest accepted ratio σ_min/σ_max of the scaled Jacobian.
    pub min_conditioning: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            tol: 1e-15,
            max_iter: 60,
            min_conditioning: ACCURACY.min_conditioning,
        }
    }
}

/// The largest turn of the path over one step of the path follower (in
/// the links' own lengths): small enough that the predictor stays closer
/// to its assembly than to any other (at a neck of width δ the radius of
/// the path is about δ, so a step is a few hundredths of δ).
pub(super) const MAX_TURN: f64 = ACCURACY.max_path_turn;

/// The solver over a subset of links (those the wanted output needs).
#[derive(Clone, Debug)]
pub struct ConstraintSolver<'a> {
    pub(super) m: &'a Mechanism,
    /// The unknowns and equations ([`crate::kinematics::analytic::equations`], in f64).
    pub(super) eq: Equations<f64>,
    pub(super) q: DVector<f64>,
    /// The input coordinates of the last solved position (None before
    /// the first).
    pub(super) last_input: Option<Coords>,
    /// (input, row) of each driver's equation.
    pub(super) driver_rows: Vec<(usize, usize)>,
    pub(super) settings: Settings,
    /// Each solved link's own size ([`Mechanism::link_scale`]), parallel to
    /// the links solved.
    pub(super) scale: Vec<f64>,
    /// σ_min/σ_max of the scaled Jacobian at the last solve.
    pub conditioning: f64,
    /// Steps the last walk along the input took (path following).
    pub steps: usize,
}

impl<'a> ConstraintSolver<'a> {
    /// `include[l]`: link l is solved (the frame is always fixed).
    pub fn new(m: &'a Mechanism, include: &[bool], settings: Settings) -> ConstraintSolver<'a> {
        let v = |v: Vec2| Vector::new(v.x, v.y);
        let eq = Equations::new(
            m,
            include,
            |l, p| v(m.local(l, p)),
            |k| {
                let pr = &m.prismatics[k];
                Prism {
                    slider: pr.slider,
                    guide: pr.guide,
                    slider_local: v(pr.slider_local),
                    line_point: v(pr.line_point),
                    line_dir: v(pr.line_dir),
                    delta: pr.delta,
                }
            },
            |p| v(m.scene.points[p].sketch.to_vec2()),
            |l| {
                let p = m.links[l].sketch_pose;
                crate::kinematics::analytic::equations::Pose::new(Vector::new(p.origin.x, p.origin.y), p.angle)
            },
        );
        let mut q = DVector::zeros(3 * eq.links.len());
        for (i, &l) in eq.links.iter().enumerate() {
            let p = m.links[l].sketch_pose;
            q[3 * i] = p.origin.x;
            q[3 * i + 1] = p.origin.y;
            q[3 * i + 2] = p.angle;
        }
        let scale = eq.links.iter().map(|&l| m.link_scale(l)).collect();
        let mut driver_rows = Vec::new();
        let mut row = 0;
        for c in &eq.cons {
            match c {
                Constraint::Driver(i) => {
                    driver_rows.push((*i, row));
                    row += 1;
                }
                _ => row += 2,
            }
        }
        ConstraintSolver {
            m,
            eq,
            q,
            last_input: None,
            driver_rows,
            settings,
            scale,
            conditioning: 1.0,
            steps: 0,
        }
    }

    pub(super) fn rows(&self) -> usize {
        self.eq.rows()
    }

    /// Constraint residuals Φ(q) at input coordinates `x`.
    pub(super) fn residual(&self, q: &DVector<f64>, x: &[f64]) -> DVector<f64> {
        DVector::from_column_slice(&self.eq.residual(&self.eq.poses(q.as_slice()), x))
    }

    /// The Jacobian ∂Φ/∂q (analytic).
    pub(super) fn jacobian(&self, q: &DVector<f64>) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(self.rows(), q.len());
        self.eq
            .jacobian(&self.eq.poses(q.as_slice()), |r, c, v| j[(r, c)] += v);
        j
    }

    /// γ of the acceleration equations Φ_q·q̈ = γ (the terms quadratic in q̇).
    pub(super) fn gamma(&self, q: &DVector<f64>, qd: &DVector<f64>, input_acc: &[f64]) -> DVector<f64> {
        let p = self.eq.poses(q.as_slice());
        DVector::from_column_slice(&self.eq.gamma(&p, qd.as_slice(), input_acc))
    }

    /// The scale of each row: a length for the rows that close points, a
    /// link's size for the rows of angles (a prismatic pair's relative
    /// angle, a crank's angle).
    pub(super) fn row_scales(&self) -> Rows<f64> {
        let m = self.m;
        let size_of = |l: usize| self.eq.slot[l].map_or(0.0, |i| self.scale[i]);
        let mut out = Rows::with_capacity(self.rows());
        for c in &self.eq.cons {
            match c {
                Constraint::Revolute { .. } => out.extend([1.0, 1.0]),
                Constraint::Prismatic(pr) => {
                    let l = size_of(pr.slider).max(size_of(pr.guide));
                    out.extend([l.max(f64::MIN_POSITIVE), 1.0]);
                }
                Constraint::Driver(i) => out.push(match *m.scene.input_at(*i) {
                    InputSpec::Crank { link, .. } => size_of(link),
                    InputSpec::Slider { .. } => 1.0,
                }),
            }
        }
        out
    }

    /// σ_min/σ_max of the Jacobian with every unknown and every equation
    /// in the lengths of the links it concerns: θ columns times their
    /// link's size, angle rows likewise, then each column to unit norm
    /// (a small linkage in a large sketch is as well conditioned as the
    /// same linkage alone).
    pub(super) fn scaled_conditioning(&self, j: &DMatrix<f64>) -> f64 {
        let mut js = j.clone();
        for (r, sc) in self.row_scales().into_iter().enumerate() {
            js.row_mut(r).scale_mut(sc);
        }
        for i in 0..self.eq.links.len() {
            js.column_mut(3 * i + 2).scale_mut(1.0 / self.scale[i]);
        }
        for c in 0..js.ncols() {
            let n = js.column(c).norm();
            if n > 0.0 {
                js.column_mut(c).scale_mut(1.0 / n);
            }
        }
        let sv = js.singular_values();
        let max = sv.max();
        if max == 0.0 { 0.0 } else { sv.min() / max }
    }

    /// The largest correction relative to the rounding of its unknown: a
    /// coordinate against its link's size and its own magnitude, an angle
    /// against one radian.
    pub(super) fn correction(&self, q: &DVector<f64>, dq: &DVector<f64>) -> f64 {
        let mut big = 0.0f64;
        for i in 0..self.eq.links.len() {
            let l = self.scale[i];
            big = big
                .max(dq[3 * i].abs() / (l + q[3 * i].abs()))
                .max(dq[3 * i + 1].abs() / (l + q[3 * i + 1].abs()))
                .max(dq[3 * i + 2].abs() / (1.0 + q[3 * i + 2].abs()));
        }
        big
    }

    /// Newton's method at input `x` from the current state. Converged when
    /// every correction is at the rounding of its unknown (or `tol`); it
    /// fails when the corrections stop contracting (`strict`: each at most
    /// half the one before, as the path follower demands of its corrector)
    /// or after `max_iter`.
    pub(super) fn newton(&mut self, x: &[f64], strict: bool) -> std::result::Result<usize, String> {
        let s = self.settings;
        let floor = s.tol.max(4.0 * f64::EPSILON);
        let mut last = f64::INFINITY;
        for it in 0..s.max_iter {
            let r = self.residual(&self.q, x);
            // At the rounding of the equations a nearly singular Jacobian
            // turns the rounding into corrections that need not contract:
            // the equations hold as well as they can, and κ bounds the rest.
            let at_rounding = self.at_rounding(&r);
            let j = self.jacobian(&self.q);
            let Some(dq) = j.lu().solve(&r) else {
                return Err("the constraint Jacobian is singular".into());
            };
            let big = self.correction(&self.q, &dq);
            if !big.is_finite() {
                return Err("Newton's method diverged".into());
            }
            self.q -= &dq;
            if big <= floor || (at_rounding && it > 0) {
                return Ok(it + 1);
            }
            if strict && !at_rounding && big > 0.5 * last && last > 16.0 * floor {
                return Err(format!(
                    "Newton's method contracts too slowly ({big:.1e} after {last:.1e})"
                ));
            }
            last = big;
        }
        let r = self.residual(&self.q, x).amax();
        let reach = self.scale.iter().copied().fold(0.0, f64::max);
        if !strict && r <= 1e-12 * reach {
            Ok(s.max_iter)
        } else {
            Err(format!(
                "Newton's method did not converge (residual {})",
                crate::format::format_quantity(r, "")
            ))
        }
    }

    /// Whether every residual is within 64 ε of the numbers its equation is
    /// made of: the lengths and the coordinates ([`Self::magnitude`]), and
    /// for a row of angles (a prismatic pair's relative angle, a crank's
    /// angle) the angles too: a crank followed through many turns carries
    /// an angle of many radians, rounded as coarsely.
    pub(super) fn at_rounding(&self, r: &DVector<f64>) -> bool {
        let size = self.magnitude();
        let angles = (0..self.eq.links.len())
            .map(|i| self.q[3 * i + 2].abs())
            .fold(size, f64::max);
        let sc = &self.m.scene;
        let angle_rows = self.eq.cons.iter().flat_map(|c| match c {
            Constraint::Revolute { .. } => [Some(false), Some(false)],
            Constraint::Prismatic(_) => [Some(true), Some(false)],
            Constraint::Driver(i) => [Some(sc.input_at(*i).is_crank()), None],
        });
        r.iter()
            .zip(angle_rows.flatten())
            .all(|(r, angle)| r.abs() <= 64.0 * f64::EPSILON * if angle { angles } else { size })
    }

    /// The size of the numbers in the equations: the largest link and the
    /// largest coordinate of a solved link.
    pub(super) fn magnitude(&self) -> f64 {
        let mut x = 0.0f64;
        for i in 0..self.eq.links.len() {
            x = x.max(self.scale[i] + self.q[3 * i].abs().max(self.q[3 * i + 1].abs()));
        }
        x
    }

    /// Positions at input coordinate `x` (a single input), reached by
    /// continuation from the previous solve (from the sketch at first),
    /// the short way round.
    pub fn solve_positions(&mut self, x: f64) -> Result<()> {
        self.solve_positions_at(Coords::one(x))
    }

    /// Positions at input coordinates `x`, reached by continuation from
    /// the previous solve (from the sketch at first), each crank the short
    /// way round.
    pub fn solve_positions_at(&mut self, x: Coords) -> Result<()> {
        let span = input_span(self.m, &self.last_inputs(), &x);
        self.solve_positions_along(x, span)
    }

    /// Positions at input coordinates `x`, reached from the previous solve
    /// by moving the inputs through `span` (straight in the inputs).
    pub fn solve_positions_along(&mut self, x: Coords, span: Coords) -> Result<()> {
        let err = |why: String| {
            Error::assembly(
                "the mechanism (constraint solver)",
                describe_input(self.m, &x),
                why,
            )
        };
        if self.last_input.is_none() {
            let x0 = sketch_input(self.m);
            self.newton(&x0, false).map_err(err)?;
            self.last_input = Some(x0);
        }
        self.walk(&span).map_err(err)?;
        self.last_input = Some(x);
        self.turn_back();
        Ok(())
    }

    /// Turn back by whole turns a link that has turned more than a turn
    /// beyond (−π, π]: the equations and the motion see its angle modulo a
    /// turn, but an angle of many radians is rounded as coarsely (a crank
    /// followed through hundreds of turns would lose the digits Newton's
    /// method needs to converge).
    pub(super) fn turn_back(&mut self) {
        use std::f64::consts::{PI, TAU};
        for i in 0..self.eq.links.len() {
            let a = self.q[3 * i + 2];
            if a.abs() > 3.0 * PI {
                self.q[3 * i + 2] = a - TAU * (a / TAU).round();
            }
        }
    }

    /// The input coordinates of the last solved position (the sketch's
    /// before the first).
    pub fn last_inputs(&self) -> Coords {
        self.last_input.unwrap_or_else(|| sketch_input(self.m))
    }

    /// Velocities and (if asked) accelerations at the last solved
    /// position, a single input's rate and rate of rate given.
    pub fn solve_rates(
        &mut self,
        rate: f64,
        rate2: f64,
        order: Order,
    ) -> Result<Vec<Option<Motion>>> {
        self.solve_rates_of(&[(rate, rate2)], order)
    }

    /// Velocities and (if asked) accelerations at the last solved
    /// position, each input's (rate, rate of rate) given in the scene's
    /// order.
    pub fn solve_rates_of(
        &mut self,
        rates: &[(f64, f64)],
        order: Order,
    ) -> Result<Vec<Option<Motion>>> {
        let j = self.jacobian(&self.q);
        self.conditioning = self.scaled_conditioning(&j);
        if self.conditioning < self.settings.min_conditioning {
            return Err(Error::singular(
                describe_input(self.m, &self.last_inputs()),
                format!(
                    "the constraint Jacobian is ill-conditioned (σ_min/σ_max = {:.2e})",
                    self.conditioning
                ),
            ));
        }
        let lu = j.lu();
        let mut b = DVector::zeros(self.rows());
        for &(i, row) in &self.driver_rows {
            b[row] = rates[i].0;
        }
        let qd = lu.solve(&b).expect("conditioning checked");
        let qdd = if order == Order::Acceleration {
            let acc: Vec<f64> = rates.iter().map(|r| r.1).collect();
            Some(
                lu.solve(&self.gamma(&self.q, &qd, &acc))
                    .expect("conditioning checked"),
            )
        } else {
            None
        };
        Ok(self.motions(self.q.as_slice(), Some(qd.as_slice()), qdd.as_ref().map(|x| x.as_slice())))
    }

    /// Every solved link's motion from the unknowns: poses `q`, rates `qd`
    /// and `qdd` (zero where not given); the frame at rest.
    pub(super) fn motions(
        &self,
        q: &[f64],
        qd: Option<&[f64]>,
        qdd: Option<&[f64]>,
    ) -> Vec<Option<Motion>> {
        self.motions_at(&self.eq.poses(q), qd, qdd)
    }

    /// [`Self::motions`] at the links' poses `at` (the equations' poses
    /// of the same q, their sines and cosines computed once).
    pub(super) fn motions_at(
        &self,
        at: &[PoseOf<f64>],
        qd: Option<&[f64]>,
        qdd: Option<&[f64]>,
    ) -> Vec<Option<Motion>> {
        let mut out = vec![None; self.m.links.len()];
        out[self.m.frame()] = Some(Motion::from_point(
            Pose::IDENTITY,
            Point::ORIGIN,
            Vec2::ZERO,
            Vec2::ZERO,
            0.0,
            0.0,
        ));
        let three = |x: Option<&[f64]>, i: usize| {
            x.map_or((Vec2::ZERO, 0.0), |x| {
                (Vec2::new(x[3 * i], x[3 * i + 1]), x[3 * i + 2])
            })
        };
        for (i, &l) in self.eq.links.iter().enumerate() {
            let p = &at[l];
            let origin = Point::new(p.origin.x, p.origin.y);
            let pose = Pose::with_sin_cos(origin, p.angle, (p.sin, p.cos));
            let ((v, omega), (a, eps)) = (three(qd, i), three(qdd, i));
            out[l] = Some(Motion::from_point(pose, pose.origin, v, a, omega, eps));
        }
        out
    }

    /// The moving links solved, in the order of the unknowns.
    pub fn links(&self) -> &[usize] {
        &self.eq.links
    }

    /// The orientation of the assembly the sketch shows, the sign of
    /// det Φ_q at the sketch's poses (which route (b)'s path following
    /// keeps from there on); `None` when the sketch is within 1e-6 of a
    /// singular position (conditioning), where the sign may be the
    /// drawing's rounding.
    pub fn sketch_orientation(&self) -> Option<f64> {
        let j = self.jacobian(&self.q);
        (self.scaled_conditioning(&j) >= 1e-6).then(|| j.lu().determinant().signum())
    }
}
