//! A configuration (the poses of the links solved), and the geometry every
//! group's closed form shares: a point of a link, a pair's point, the
//! angle across a pair, a slider's line, a link placed by two of its points.

use crate::format::read_back;
use crate::geom::{Pose, rotate};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::Joint;
use kurbo::{Point, Vec2};

/// The poses of the links solved so far (None: not needed, not computed).
#[derive(Clone, Debug)]
pub struct Configuration {
    pub poses: Vec<Option<Pose>>,
}

impl Configuration {
    #[inline]
    pub fn pose(&self, link: usize) -> Pose {
        self.poses[link].expect("link solved before use")
    }
    /// World position of `point` as carried by `link`.
    #[inline]
    pub fn point(&self, m: &Mechanism, link: usize, point: usize) -> Point {
        self.pose(link).apply(m.local(link, point))
    }
}

/// Describe the input values for messages: "φ = 123.4°" or "s = 0.05 m",
/// in the shortest decimal that is the value as the file's units give it
/// ([`read_back`]: 60° written in degrees is "φ = 60°", not the
/// 59.99999999999999° it comes back as through radians; near a limit,
/// positions a nano-degree apart still read apart); several inputs each
/// with its link's id: "φ1 = 30°, φ4 = 120°".
pub fn describe_input(m: &Mechanism, q: &[f64]) -> String {
    let unit = m.scene.length_unit;
    describe_input_with(
        m,
        q,
        &|q| {
            let deg = |d: f64| (d % 360.0) * (std::f64::consts::PI / 180.0);
            format!("{}°", read_back(q.to_degrees(), q, &deg))
        },
        &|q| {
            // The shortest decimal in the file's unit, in metres (a slide
            // of 70 mm is 0.07 m, not 0.07000000000000001 m).
            let written = read_back(q / unit, q, &|x| x * unit);
            let m = format!("{written}e{}", unit.log10().round() as i32)
                .parse::<f64>()
                .map_or(written, |m| m.to_string());
            format!("{m} m")
        },
    )
}

/// The input values `q` as [`describe_input`] names them, each angle (rad)
/// written by `angle` ("40.804°"), each slide (m) by `length` ("0.05 m").
pub fn describe_input_with(
    m: &Mechanism,
    q: &[f64],
    angle: &dyn Fn(f64) -> String,
    length: &dyn Fn(f64) -> String,
) -> String {
    let several = m.scene.several_inputs();
    q.iter()
        .zip(m.scene.inputs())
        .map(|(&q, spec)| {
            let id = if several { m.link_id(spec.link()) } else { "" };
            match spec {
                InputSpec::Crank { .. } => format!("φ{id} = {}", angle(q)),
                InputSpec::Slider { .. } => format!("s{id} = {}", length(q)),
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn sketch(m: &Mechanism, p: usize) -> Point {
    m.scene.points[p].sketch
}

pub(crate) fn point_of(j: Joint) -> usize {
    match j {
        Joint::R(p) => p,
        Joint::P(_) => unreachable!("a revolute pair was expected"),
    }
}

pub(crate) fn pair_of(j: Joint) -> usize {
    match j {
        Joint::P(k) => k,
        Joint::R(_) => unreachable!("a prismatic pair was expected"),
    }
}

/// Angle of `moving` given the angle of `known` across prismatic pair `k`.
pub(crate) fn angle_across(m: &Mechanism, k: usize, known: usize, known_angle: f64) -> f64 {
    let pr = &m.prismatics[k];
    if pr.guide == known {
        known_angle + pr.delta
    } else {
        known_angle - pr.delta
    }
}

/// The world line on which the local point `x` of link `moving` (at angle
/// `theta`) must lie, because of prismatic pair `k` with the posed link `known`.
pub fn slide_line(
    m: &Mechanism,
    k: usize,
    known: usize,
    known_pose: &Pose,
    theta: f64,
    x: Vec2,
) -> crate::geom::Line {
    let pr = &m.prismatics[k];
    if pr.guide == known {
        crate::geom::Line {
            point: known_pose.apply(pr.line_point) + rotate(x - pr.slider_local, theta),
            dir: known_pose.dir(pr.line_dir),
        }
    } else {
        crate::geom::Line {
            point: known_pose.apply(pr.slider_local) + rotate(x - pr.line_point, theta),
            dir: rotate(pr.line_dir, theta),
        }
    }
}

/// The guide direction of pair `k` in the sketch.
pub(super) fn sketch_guide_dir(m: &Mechanism, k: usize) -> Vec2 {
    let pr = &m.prismatics[k];
    m.links[pr.guide].sketch_pose.dir(pr.line_dir)
}

/// Pose a link by two points at local places `lp`, `lq` at known world
/// places.
pub(super) fn set_by_two_local(
    c: &mut Configuration,
    link: usize,
    lp: Vec2,
    at_p: Point,
    lq: Vec2,
    at_q: Point,
) {
    let (w, l) = (at_q - at_p, lq - lp);
    let angle = w.atan2() - l.atan2();
    // The turn from l to w: its cosine and sine straight from the vectors.
    let norm = w.hypot() * l.hypot();
    let turn = (l.dot(w) / norm, l.cross(w) / norm);
    c.poses[link] = Some(Pose::through_turned(at_p, lp, angle, turn));
}
