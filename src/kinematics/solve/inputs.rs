//! The input values of the positions asked for, and the extreme position
//! that begins the working stroke (`positions.count`).

use super::Analysis;
use crate::error::{Error, Result};
use crate::geom::{Pose, wrap_pi};
use crate::kinematics::analytic::{Coords, Motion, Order, contour};
use crate::kinematics::positions::{Configuration, PositionSolver, crank_frame, slide_pose};
use crate::model::scene::{InputSpec, PositionsSpec};
use crate::model::structure::{AssurGroup, DyadKind, Joint};
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

impl Analysis {
    /// The first input's coordinates of the positions asked for (rad or
    /// m): with one input, the positions' input values.
    pub fn input_values(&self) -> Result<Vec<f64>> {
        let sc = &self.mech.scene;
        if let PositionsSpec::Count { count, output } = sc.positions {
            // The steps themselves, not a list of every input's slots.
            let out = output.unwrap_or_else(|| self.default_output());
            let (start, sense) = (self.stroke_start(out)?.angle, sc.input.sense());
            return Ok((0..count).map(|k| count_step(start, sense, k, count)).collect());
        }
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
                self.count_values(self.stroke_start(out)?.angle, *count)
            }
        })
    }

    /// The input values of `count` equal steps of a revolution from the
    /// crank angle `start`, in the sense of ω, each in [0, 2π).
    pub(crate) fn count_values(&self, start: f64, count: usize) -> Vec<Coords> {
        let sense = self.mech.scene.input.sense();
        (0..count)
            .map(|k| Coords::one(count_step(start, sense, k, count)))
            .collect()
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
        Ok(self.stroke_start(out)?.angle)
    }

    /// The crank angle at which the working stroke of `out` begins (as
    /// [`Analysis::working_stroke_start`]) and the crank angle it takes
    /// (a full turn for an output without extreme positions).
    pub fn working_stroke(&self, out: usize) -> Result<(f64, f64)> {
        let s = self.stroke_start(out)?;
        Ok((s.angle, s.stroke))
    }

    /// The extreme position of `out` that begins the working stroke, and
    /// how it was found ([`StrokeStart`]): bracketed on the transfer
    /// function's samples; where the crank and the coupler it drives lie
    /// in line there (and the output stands still with them), solved
    /// directly as that collinearity, which the data determine to their
    /// own precision even where the transfer function is stiff (near a
    /// toggle, a change point); elsewhere the root by bisection.
    pub fn stroke_start(&self, out: usize) -> Result<StrokeStart> {
        let (root, bracket, stroke, swing) = match self.stroke_root(out)? {
            Some(found) => found,
            None => {
                let InputSpec::Crank { angle, .. } = self.mech.scene.input else {
                    unreachable!("stroke_root refuses other inputs")
                };
                return Ok(StrokeStart {
                    angle,
                    stroke: TAU,
                    swing: None,
                    found: Found::Input,
                });
            }
        };
        let in_line = in_line_extremes(self, out)
            .into_iter()
            .map(|q| (q, wrap_pi(q - root).abs()))
            .filter(|&(_, d)| d <= bracket)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        Ok(match in_line {
            Some((q, _)) => StrokeStart {
                angle: q.rem_euclid(TAU),
                stroke,
                swing: Some(swing),
                found: Found::InLine,
            },
            None => StrokeStart {
                angle: root,
                stroke,
                swing: Some(swing),
                found: Found::Root,
            },
        })
    }

    /// The root of the output's transfer function that begins the
    /// working stroke, the width of its bracket, the stroke's crank
    /// angle and the output's swing between its extremes; `None` for an
    /// output that turns fully.
    fn stroke_root(&self, out: usize) -> Result<Option<(f64, f64, f64, f64)>> {
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
            return Ok(None);
        }
        let (start, stroke) = working_stroke_of(&extremes, sc.input.sense());
        let (lo, hi) = extremes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
                (lo.min(e.1), hi.max(e.1))
            });
        Ok(Some((start, TAU / n as f64, stroke, hi - lo)))
    }
}

/// Step `k` of `count` equal steps of a revolution from the crank angle
/// `start` in the sense `sense` (±1), in [0, 2π).
pub(crate) fn count_step(start: f64, sense: f64, k: usize, count: usize) -> f64 {
    (start + sense * TAU * k as f64 / count as f64).rem_euclid(TAU)
}

/// The extreme position that begins the working stroke of an output
/// ([`Analysis::stroke_start`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrokeStart {
    /// Its crank angle, rad, in [0, 2π).
    pub angle: f64,
    /// The crank angle the working stroke takes (2π for an output that
    /// turns fully).
    pub stroke: f64,
    /// The output's stroke between its extreme positions: the slide H
    /// along a frame guide (m), else the rocker's swing (rad); `None`
    /// for an output that turns fully. Read at the extremes, where the
    /// output stands still, so an error δφ of their crank angles moves
    /// it by O(δφ²) only.
    pub swing: Option<f64>,
    pub found: Found,
}

/// How the start of the working stroke was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Found {
    /// The output turns fully: the steps start at the input's angle.
    Input,
    /// The crank and the coupler it drives in line, solved directly.
    InLine,
    /// A root of the output's transfer function, by bisection.
    Root,
}

/// The crank angles (rad) at which the crank and the coupler of the
/// class II group it drives lie in line (stretched or folded), where
/// that group's other link, and so the output `out`, stands still: the
/// rocker of an RRR group about its frame pivot, the slider of an RRP
/// group on a frame guide. Solved as the triangle (or the circle and
/// line) the in-line crank and coupler make with the group's frame
/// joint: a closed form the data determine to their own precision, also
/// where the transfer function's root is stiff. Empty where the output
/// does not stand still with that group (it hangs on the coupler or the
/// crank, or on a class III group) or the group is of another kind.
pub(crate) fn in_line_extremes(an: &Analysis, out: usize) -> Vec<f64> {
    let m = &an.mech;
    let InputSpec::Crank {
        link: crank, pivot, ..
    } = m.scene.input
    else {
        return Vec::new();
    };
    if m.scene.several_inputs() {
        return Vec::new();
    }
    let frame = m.frame();
    let groups = &an.structure.groups;
    let Some((gi, d)) = groups.iter().enumerate().find_map(|(i, g)| match g {
        AssurGroup::Dyad(d)
            if d.cylinder.is_none() && (d.ext1.from == crank || d.ext2.to == crank) =>
        {
            Some((i, d))
        }
        _ => None,
    }) else {
        return Vec::new();
    };
    // pin: the crank's joint with the coupler; far: the other link's
    // joint with the frame.
    let (pin, coupler, other, far, far_link) = if d.ext1.from == crank {
        (d.ext1.joint, d.links[0], d.links[1], d.ext2.joint, d.ext2.to)
    } else {
        (d.ext2.joint, d.links[1], d.links[0], d.ext1.joint, d.ext1.from)
    };
    let (Joint::R(a), Joint::R(b)) = (pin, d.mid.joint) else {
        return Vec::new();
    };
    if far_link != frame {
        return Vec::new();
    }
    // The output stands still with `other`: every group it needs, but
    // this one, hangs on links standing still.
    let need = an.structure.needed_for(&[out]);
    let mut still: Vec<usize> = vec![frame, other];
    for (i, g) in groups.iter().enumerate() {
        if i == gi || !need[i] {
            continue;
        }
        let known: Vec<usize> = match g {
            AssurGroup::Dyad(d) => vec![d.ext1.from, d.ext2.to],
            AssurGroup::Triad(_) => return Vec::new(),
        };
        if !known.iter().all(|k| still.contains(k)) {
            return Vec::new();
        }
        still.extend(g.links().iter().copied());
    }
    if !still.contains(&out) {
        return Vec::new();
    }
    let cr = crank_frame(m, crank, pivot);
    let o = cr.at;
    let arm = m.local(crank, a) - m.local(crank, pivot);
    let r = arm.hypot();
    let l = (m.local(coupler, b) - m.local(coupler, a)).hypot();
    // The crank's input angle when its pin points along `u`.
    let angle_of = |u: Vec2| u.atan2() - arm.atan2() + cr.offset;
    let frame_pose = m.links[frame].sketch_pose;
    let mut found = Vec::new();
    for (reach, stretched) in [(r + l, true), ((l - r).abs(), false)] {
        if reach == 0.0 {
            continue;
        }
        let places: Vec<Point> = match (d.kind, far) {
            (DyadKind::Rrr, Joint::R(c)) => {
                let c_at = frame_pose.apply(m.local(frame, c));
                let rc = (m.local(other, c) - m.local(other, b)).hypot();
                triangle_apexes(o, reach, c_at, rc)
            }
            (DyadKind::Rrp, Joint::P(k)) => {
                let pr = &m.prismatics[k];
                if pr.slider != other || pr.guide != frame {
                    return Vec::new();
                }
                // B slides with the slider along a line parallel to the guide.
                let at = |x: f64| {
                    frame_pose.apply(slide_pose(m, k, x).apply(m.local(other, b)).to_vec2())
                };
                let (b0, b1) = (at(0.0), at(1.0));
                circle_line_points(o, reach, b0.to_vec2(), b1 - b0)
            }
            _ => return Vec::new(),
        };
        for p in places {
            let ob = p - o;
            // Folded with the coupler longer: the pin opposite B.
            let u = if stretched || r > l { ob } else { -ob };
            found.push(angle_of(u));
        }
    }
    found
}

/// The apexes P of the triangle with |P − a| = ra, |P − b| = rb, both
/// sides of ab: the height by Kahan's formula for the area, accurate to
/// a few roundings also for a triangle within rounding of flat (its
/// sides exact); none where the sides do not close, one where flat.
fn triangle_apexes(a: Point, ra: f64, b: Point, rb: f64) -> Vec<Point> {
    let d = (b - a).hypot();
    if d == 0.0 {
        return Vec::new();
    }
    let mut s = [ra, rb, d];
    s.sort_by(|x, y| y.total_cmp(x));
    let [x, y, z] = s;
    let q = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
    if q < 0.0 {
        return Vec::new();
    }
    let h = 0.5 * q.sqrt() / d;
    let u = (b - a) / d;
    let along = (d * d + ra * ra - rb * rb) / (2.0 * d);
    let n = Vec2::new(-u.y, u.x);
    let foot = a + u * along;
    if h == 0.0 {
        vec![foot]
    } else {
        vec![foot + n * h, foot - n * h]
    }
}

/// The points at distance `r` from `c` on the line through `p` along
/// `dir`: the half chord from (r − h)(r + h), accurate where the line
/// nearly touches the circle.
fn circle_line_points(c: Point, r: f64, p: Vec2, dir: Vec2) -> Vec<Point> {
    let u = dir / dir.hypot();
    let foot = p + u * (c.to_vec2() - p).dot(u);
    let h = (c.to_vec2() - foot).hypot();
    let q = (r - h) * (r + h);
    if q < 0.0 {
        return Vec::new();
    }
    let t = q.sqrt();
    if t == 0.0 {
        vec![foot.to_point()]
    } else {
        vec![(foot + u * t).to_point(), (foot - u * t).to_point()]
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
