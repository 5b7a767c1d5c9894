//! Route (b): a general constraint solver, independent of the group
//! decomposition's formulas. Each moving link is a pose (x, y, θ); each
//! revolute pair gives two equations (its point coincides on both links),
//! each prismatic pair two (no relative rotation; the slider's point on the
//! guide line), the input one. Positions by Newton's method from the
//! previous solution, velocities and accelerations by linear solves with
//! the constraint Jacobian, whose conditioning is checked by SVD.

use super::{Motion, Order};
use crate::error::{Error, Result};
use crate::geom::{Pose, perp, rotate, wrap_pi};
use crate::mechanism::Mechanism;
use crate::positions::{describe_input, sketch_input, sketch_slider_ref};
use crate::scene::InputSpec;
use kurbo::{Point, Vec2};
use nalgebra::{DMatrix, DVector};

#[derive(Clone, Debug)]
enum Constraint {
    /// Point `point` of links a and b coincide (2 rows).
    Revolute { point: usize, a: usize, b: usize },
    /// Prismatic pair k (2 rows).
    Prismatic { k: usize },
    /// The input coordinate (1 row).
    Driver,
}

/// Newton's stopping rule and the limit of conditioning accepted.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Stop when the largest correction is below `tol` × the sketch size.
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
            min_conditioning: 1e-13,
        }
    }
}

/// The solver over a subset of links (those the wanted output needs).
#[derive(Clone, Debug)]
pub struct ConstraintSolver<'a> {
    m: &'a Mechanism,
    /// Moving links solved, in order; their unknowns are 3·i .. 3·i+3.
    links: Vec<usize>,
    slot: Vec<Option<usize>>,
    cons: Vec<Constraint>,
    q: DVector<f64>,
    last_input: f64,
    settings: Settings,
    /// σ_min/σ_max of the scaled Jacobian at the last solve.
    pub conditioning: f64,
}

impl<'a> ConstraintSolver<'a> {
    /// `include[l]`: link l is solved (the frame is always fixed).
    pub fn new(m: &'a Mechanism, include: &[bool], settings: Settings) -> ConstraintSolver<'a> {
        let frame = m.frame();
        let links: Vec<usize> = (0..m.links.len())
            .filter(|&l| l != frame && include[l])
            .collect();
        let mut slot = vec![None; m.links.len()];
        for (i, &l) in links.iter().enumerate() {
            slot[l] = Some(i);
        }
        let inside = |l: usize| l == frame || include[l];
        let mut cons = Vec::new();
        for p in 0..m.scene.points.len() {
            let ls: Vec<usize> = m
                .links_of_point(p)
                .into_iter()
                .filter(|&l| inside(l))
                .collect();
            for &b in ls.iter().skip(1) {
                cons.push(Constraint::Revolute {
                    point: p,
                    a: ls[0],
                    b,
                });
            }
        }
        for (k, pr) in m.prismatics.iter().enumerate() {
            if inside(pr.slider) && inside(pr.guide) {
                cons.push(Constraint::Prismatic { k });
            }
        }
        cons.push(Constraint::Driver);
        let mut q = DVector::zeros(3 * links.len());
        for (i, &l) in links.iter().enumerate() {
            let p = m.links[l].sketch_pose;
            q[3 * i] = p.origin.x;
            q[3 * i + 1] = p.origin.y;
            q[3 * i + 2] = p.angle;
        }
        ConstraintSolver {
            m,
            links,
            slot,
            cons,
            q,
            last_input: f64::NAN,
            settings,
            conditioning: 1.0,
        }
    }

    fn pose(&self, q: &DVector<f64>, l: usize) -> Pose {
        match self.slot[l] {
            Some(i) => Pose::new(Point::new(q[3 * i], q[3 * i + 1]), q[3 * i + 2]),
            None => Pose::IDENTITY,
        }
    }

    fn rows(&self) -> usize {
        self.cons
            .iter()
            .map(|c| {
                if matches!(c, Constraint::Driver) {
                    1
                } else {
                    2
                }
            })
            .sum()
    }

    /// Constraint residuals Φ(q) at input coordinate `x`.
    fn residual(&self, q: &DVector<f64>, x: f64) -> DVector<f64> {
        let m = self.m;
        let mut r = DVector::zeros(self.rows());
        let mut row = 0;
        for c in &self.cons {
            match *c {
                Constraint::Revolute { point, a, b } => {
                    let d = self.pose(q, a).apply(m.local(a, point))
                        - self.pose(q, b).apply(m.local(b, point));
                    r[row] = d.x;
                    r[row + 1] = d.y;
                    row += 2;
                }
                Constraint::Prismatic { k } => {
                    let pr = &m.prismatics[k];
                    let (ps, pg) = (self.pose(q, pr.slider), self.pose(q, pr.guide));
                    r[row] = wrap_pi(ps.angle - pg.angle - pr.delta);
                    let line = pr.line(&pg);
                    r[row + 1] = line.dir.cross(ps.apply(pr.slider_local) - line.point);
                    row += 2;
                }
                Constraint::Driver => {
                    let d = self.driver_value(q) - x;
                    // A crank angle is defined modulo a turn.
                    r[row] = match m.scene.input {
                        InputSpec::Crank { .. } => wrap_pi(d),
                        InputSpec::Slider { .. } => d,
                    };
                    row += 1;
                }
            }
        }
        r
    }

    fn driver_value(&self, q: &DVector<f64>) -> f64 {
        let m = self.m;
        match m.scene.input {
            InputSpec::Crank { link, pivot, .. } => {
                let pts = &m.links[link].points;
                let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                let w = m.local(link, other) - m.local(link, pivot);
                self.pose(q, link).angle + w.atan2()
            }
            InputSpec::Slider { link, pair, .. } => {
                let pr = &m.prismatics[pair];
                let u = pr.line(&Pose::IDENTITY).dir;
                u.dot(self.pose(q, link).apply(pr.slider_local) - sketch_slider_ref(m, pair))
            }
        }
    }

    /// The Jacobian ∂Φ/∂q (analytic).
    fn jacobian(&self, q: &DVector<f64>) -> DMatrix<f64> {
        let m = self.m;
        let mut j = DMatrix::zeros(self.rows(), q.len());
        // d(world point)/d(pose of l): [I | k×r].
        let put_point =
            |j: &mut DMatrix<f64>, row: usize, l: usize, r: Vec2, sign: f64, w: Vec2| {
                // Row of w·(world point of l) with r = R(θ)·local.
                if let Some(i) = self.slot[l] {
                    j[(row, 3 * i)] += sign * w.x;
                    j[(row, 3 * i + 1)] += sign * w.y;
                    j[(row, 3 * i + 2)] += sign * w.dot(perp(r));
                }
            };
        let mut row = 0;
        for c in &self.cons {
            match *c {
                Constraint::Revolute { point, a, b } => {
                    let ra = self.pose(q, a).dir(m.local(a, point));
                    let rb = self.pose(q, b).dir(m.local(b, point));
                    for (k, w) in [(0, Vec2::new(1.0, 0.0)), (1, Vec2::new(0.0, 1.0))] {
                        put_point(&mut j, row + k, a, ra, 1.0, w);
                        put_point(&mut j, row + k, b, rb, -1.0, w);
                    }
                    row += 2;
                }
                Constraint::Prismatic { k } => {
                    let pr = &m.prismatics[k];
                    let (ps, pg) = (self.pose(q, pr.slider), self.pose(q, pr.guide));
                    if let Some(i) = self.slot[pr.slider] {
                        j[(row, 3 * i + 2)] += 1.0;
                    }
                    if let Some(i) = self.slot[pr.guide] {
                        j[(row, 3 * i + 2)] -= 1.0;
                    }
                    // f = u × (Q − P): u and P turn with the guide.
                    let line = pr.line(&pg);
                    let u = line.dir;
                    let rs = ps.dir(pr.slider_local);
                    let rg = pg.dir(pr.line_point);
                    let d = ps.apply(pr.slider_local) - line.point;
                    // cross(u, X) = (−u.y, u.x)·X
                    let n = Vec2::new(-u.y, u.x);
                    put_point(&mut j, row + 1, pr.slider, rs, 1.0, n);
                    put_point(&mut j, row + 1, pr.guide, rg, -1.0, n);
                    if let Some(i) = self.slot[pr.guide] {
                        j[(row + 1, 3 * i + 2)] += perp(u).cross(d);
                    }
                    row += 2;
                }
                Constraint::Driver => {
                    match m.scene.input {
                        InputSpec::Crank { link, .. } => {
                            let i = self.slot[link].expect("input is solved");
                            j[(row, 3 * i + 2)] = 1.0;
                        }
                        InputSpec::Slider { link, pair, .. } => {
                            let pr = &m.prismatics[pair];
                            let u = pr.line(&Pose::IDENTITY).dir;
                            let r = self.pose(q, link).dir(pr.slider_local);
                            put_point(&mut j, row, link, r, 1.0, u);
                        }
                    }
                    row += 1;
                }
            }
        }
        j
    }

    /// γ of the acceleration equations Φ_q·q̈ = γ (the terms quadratic in q̇).
    fn gamma(&self, q: &DVector<f64>, qd: &DVector<f64>, input_acc: f64) -> DVector<f64> {
        let m = self.m;
        let mut g = DVector::zeros(self.rows());
        let rate = |l: usize| self.slot[l].map_or(0.0, |i| qd[3 * i + 2]);
        let lin =
            |l: usize| self.slot[l].map_or(Vec2::ZERO, |i| Vec2::new(qd[3 * i], qd[3 * i + 1]));
        let mut row = 0;
        for c in &self.cons {
            match *c {
                Constraint::Revolute { point, a, b } => {
                    let ra = self.pose(q, a).dir(m.local(a, point));
                    let rb = self.pose(q, b).dir(m.local(b, point));
                    let t = ra * rate(a).powi(2) - rb * rate(b).powi(2);
                    g[row] = t.x;
                    g[row + 1] = t.y;
                    row += 2;
                }
                Constraint::Prismatic { k } => {
                    let pr = &m.prismatics[k];
                    let (ps, pg) = (self.pose(q, pr.slider), self.pose(q, pr.guide));
                    let line = pr.line(&pg);
                    let u = line.dir;
                    let (ws, wg) = (rate(pr.slider), rate(pr.guide));
                    let rs = ps.dir(pr.slider_local);
                    let rg = pg.dir(pr.line_point);
                    let d = ps.apply(pr.slider_local) - line.point;
                    let dd = (lin(pr.slider) + perp(rs) * ws) - (lin(pr.guide) + perp(rg) * wg);
                    // f̈ = ü×d + 2u̇×ḋ + u×d̈; move the q̈-free part to γ.
                    let quad = (-u * wg * wg).cross(d)
                        + 2.0 * (perp(u) * wg).cross(dd)
                        + u.cross(-rs * ws * ws + rg * wg * wg);
                    g[row + 1] = -quad;
                    row += 2;
                }
                Constraint::Driver => {
                    g[row] = match m.scene.input {
                        InputSpec::Crank { .. } => input_acc,
                        InputSpec::Slider { link, pair, .. } => {
                            let pr = &m.prismatics[pair];
                            let u = pr.line(&Pose::IDENTITY).dir;
                            let r = self.pose(q, link).dir(pr.slider_local);
                            input_acc + rate(link).powi(2) * u.dot(r)
                        }
                    };
                    row += 1;
                }
            }
        }
        g
    }

    /// Column scaling so that θ columns carry a length, as x and y do.
    fn scaled_conditioning(&self, j: &DMatrix<f64>) -> f64 {
        let mut js = j.clone();
        for i in 0..self.links.len() {
            js.column_mut(3 * i + 2).scale_mut(1.0 / self.m.size);
        }
        let sv = js.singular_values();
        let max = sv.max();
        if max == 0.0 { 0.0 } else { sv.min() / max }
    }

    fn newton(&mut self, x: f64) -> std::result::Result<(), String> {
        let s = self.settings;
        for _ in 0..s.max_iter {
            let r = self.residual(&self.q, x);
            let j = self.jacobian(&self.q);
            let Some(dq) = j.lu().solve(&r) else {
                return Err("the constraint Jacobian is singular".into());
            };
            self.q -= &dq;
            let mut big = 0.0f64;
            for i in 0..self.links.len() {
                big = big
                    .max(dq[3 * i].abs())
                    .max(dq[3 * i + 1].abs())
                    .max(dq[3 * i + 2].abs() * self.m.size);
            }
            if !big.is_finite() {
                return Err("Newton's method diverged".into());
            }
            if big <= s.tol * self.m.size {
                return Ok(());
            }
        }
        let r = self.residual(&self.q, x).amax();
        if r <= 1e-9 * self.m.size {
            Ok(())
        } else {
            Err(format!(
                "Newton's method did not converge (residual {r:.3e})"
            ))
        }
    }

    /// Positions at input coordinate `x`, reached by continuation from the
    /// previous solve (from the sketch at first), the short way round.
    pub fn solve_positions(&mut self, x: f64) -> Result<()> {
        let last = self.last_input();
        let span = match self.m.scene.input {
            InputSpec::Crank { .. } => wrap_pi(x - last),
            InputSpec::Slider { .. } => x - last,
        };
        self.solve_positions_by(x, span)
    }

    /// Positions at input coordinate `x`, reached from the previous solve
    /// by turning the input through `span` (which way round a rocking
    /// crank goes is the caller's: the way the mechanism assembles).
    pub fn solve_positions_by(&mut self, x: f64, span: f64) -> Result<()> {
        let err = |why: String| Error::Assembly {
            group: "the mechanism (constraint solver)".into(),
            at: describe_input(self.m, x),
            why,
        };
        if self.last_input.is_nan() {
            let x0 = sketch_input(self.m);
            self.newton(x0).map_err(err)?;
            self.last_input = x0;
        }
        self.walk(span).map_err(err)?;
        self.last_input = x;
        Ok(())
    }

    /// The input coordinate of the last solved position (the sketch's
    /// before the first).
    pub fn last_input(&self) -> f64 {
        if self.last_input.is_nan() {
            sketch_input(self.m)
        } else {
            self.last_input
        }
    }

    /// Newton's method along the input from the last solved coordinate by
    /// `span`, in steps of at most 5° (or 2 % of the size).
    fn walk(&mut self, span: f64) -> std::result::Result<(), String> {
        let crank = matches!(self.m.scene.input, InputSpec::Crank { .. });
        let step = if crank {
            5f64.to_radians()
        } else {
            0.02 * self.m.size
        };
        let n = ((span.abs() / step).ceil() as usize).max(1);
        for i in 1..=n {
            self.newton(self.last_input + span * i as f64 / n as f64)?;
        }
        Ok(())
    }

    /// Velocities and (if asked) accelerations at the last solved position.
    pub fn solve_rates(
        &mut self,
        rate: f64,
        rate2: f64,
        order: Order,
    ) -> Result<Vec<Option<Motion>>> {
        let j = self.jacobian(&self.q);
        self.conditioning = self.scaled_conditioning(&j);
        if self.conditioning < self.settings.min_conditioning {
            return Err(Error::Singular {
                at: describe_input(self.m, self.last_input),
                why: format!(
                    "the constraint Jacobian is ill-conditioned (σ_min/σ_max = {:.2e})",
                    self.conditioning
                ),
            });
        }
        let lu = j.lu();
        let mut b = DVector::zeros(self.rows());
        let last = b.len() - 1;
        b[last] = rate;
        let qd = lu.solve(&b).expect("conditioning checked");
        let qdd = if order == Order::Acceleration {
            Some(
                lu.solve(&self.gamma(&self.q, &qd, rate2))
                    .expect("conditioning checked"),
            )
        } else {
            None
        };
        let mut out = vec![None; self.m.links.len()];
        out[self.m.frame()] = Some(Motion::from_point(
            Pose::IDENTITY,
            Point::ORIGIN,
            Vec2::ZERO,
            Vec2::ZERO,
            0.0,
            0.0,
        ));
        for (i, &l) in self.links.iter().enumerate() {
            let pose = self.pose(&self.q, l);
            let v = Vec2::new(qd[3 * i], qd[3 * i + 1]);
            let (a, eps) = match &qdd {
                Some(a) => (Vec2::new(a[3 * i], a[3 * i + 1]), a[3 * i + 2]),
                None => (Vec2::ZERO, 0.0),
            };
            out[l] = Some(Motion::from_point(
                pose,
                pose.origin,
                v,
                a,
                qd[3 * i + 2],
                eps,
            ));
        }
        let _ = rotate;
        Ok(out)
    }
}
