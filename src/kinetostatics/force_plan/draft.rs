//! A force plan being drawn at its scale: vectors laid off head to tail,
//! lines of known direction, their intersection, segments measured; every
//! point with its drafting error radius.

use super::plan::{Drawn, DrawnLine, Force, ForcePlan, ForceStep};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::{Line, LineCut, intersect_lines};
use kurbo::Vec2;

/// A plan being drawn at scale `mu`.
pub(super) struct Draft {
    pub plan: ForcePlan,
}

impl Draft {
    pub(super) fn new(mu: f64, delta: f64) -> Draft {
        Draft {
            plan: ForcePlan {
                group: None,
                input: None,
                links: Vec::new(),
                mu,
                delta,
                points: vec![Vec2::ZERO],
                err: vec![0.0],
                vectors: Vec::new(),
                lines: Vec::new(),
                steps: Vec::new(),
                worst_sin: 1.0,
                arms: Vec::new(),
            },
        }
    }
    pub(super) fn last(&self) -> usize {
        self.plan.points.len() - 1
    }
    /// Lay off `f` from the last point (a zero force is not drawn).
    pub(super) fn lay_off(&mut self, f: Vec2, force: Force) {
        if f == Vec2::ZERO {
            return;
        }
        let p = &mut self.plan;
        let from = p.points.len() - 1;
        p.points.push(p.points[from] + f / p.mu);
        p.err.push(p.err[from] + p.delta);
        p.vectors.push(Drawn {
            from,
            to: from + 1,
            force,
            value: f,
        });
        p.steps.push(ForceStep::LayOff(p.vectors.len() - 1));
    }
    pub(super) fn line(&mut self, through: usize, dir: Vec2, force: Force) -> usize {
        let p = &mut self.plan;
        p.lines.push(DrawnLine {
            through,
            dir: dir.normalize(),
            force,
        });
        p.steps.push(ForceStep::Line(p.lines.len() - 1));
        p.lines.len() - 1
    }
    /// Where lines `a` and `b` meet: a new plan point.
    pub(super) fn meet(&mut self, a: usize, b: usize, at: &dyn Fn() -> String) -> Result<usize> {
        let p = &mut self.plan;
        let line = |i: usize| Line {
            point: p.points[p.lines[i].through].to_point(),
            dir: p.lines[i].dir,
        };
        let LineCut::Point { at: x, sin_angle } =
            intersect_lines(&line(a), &line(b), ACCURACY.min_line_sine)
        else {
            return Err(Error::singular(
                at(),
                "on the force plan the lines of the two unknown reactions are parallel: the group's reactions are not determined",
            ));
        };
        let err = (p.err[p.lines[a].through] + p.delta).hypot(p.err[p.lines[b].through] + p.delta)
            / sin_angle;
        p.points.push(x.to_vec2());
        p.err.push(err);
        p.worst_sin = p.worst_sin.min(sin_angle);
        let out = p.points.len() - 1;
        p.steps.push(ForceStep::Intersect {
            lines: [a, b],
            out,
            sin: sin_angle,
        });
        Ok(out)
    }
    /// The vector from plan point `from` to `to`, measured: `force`.
    pub(super) fn measure(&mut self, from: usize, to: usize, force: Force) -> Vec2 {
        let p = &mut self.plan;
        let value = (p.points[to] - p.points[from]) * p.mu;
        p.vectors.push(Drawn {
            from,
            to,
            force,
            value,
        });
        p.steps.push(ForceStep::Measure(p.vectors.len() - 1));
        value
    }
}
