//! The inputs placed: a crank about its pivot, a slider on a guide of the
//! frame, the link a driving pair places on its known link; the input
//! coordinates the sketch shows.

use super::configuration::sketch;
use crate::kinematics::analytic::Coords;
use crate::geom::Pose;
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use kurbo::{Point, Vec2};

/// A crank's constants: where its pivot is on the frame (as the frame's
/// sketch has it), the pivot on the crank, and the angle on the crank of
/// its line from the pivot to its other point (the input angle's zero).
pub(crate) struct CrankFrame {
    pub at: Point,
    pub local: Vec2,
    pub offset: f64,
}

/// The constants of crank `link` about `pivot`.
pub(crate) fn crank_frame(m: &Mechanism, link: usize, pivot: usize) -> CrankFrame {
    let pts = &m.links[link].points;
    let other = if pts[0] == pivot { pts[1] } else { pts[0] };
    let w = m.local(link, other) - m.local(link, pivot);
    let at = m.links[m.frame()]
        .sketch_pose
        .apply(m.local(m.frame(), pivot));
    CrankFrame {
        at,
        local: m.local(link, pivot),
        offset: w.atan2(),
    }
}

/// Place input `i`'s link exactly at its coordinate `q` (rad or m): a
/// crank about its pivot, a slider on a guide of the frame.
pub fn place_input(m: &Mechanism, i: usize, q: f64) -> Pose {
    match *m.scene.input_at(i) {
        InputSpec::Crank { link, pivot, .. } => {
            let cr = crank_frame(m, link, pivot);
            Pose::through(cr.at, cr.local, q - cr.offset)
        }
        InputSpec::Slider { pair, .. } => {
            let pr = &m.prismatics[pair];
            let line = pr.line(&Pose::IDENTITY);
            let q0 = sketch_slider_ref(m, pair);
            Pose::through(q0 + line.dir * q, pr.slider_local, pr.delta)
        }
    }
}

/// The reference of a driving slider's displacement: its point in the
/// sketch, projected onto the guide.
pub fn sketch_slider_ref(m: &Mechanism, pair: usize) -> Point {
    let pr = &m.prismatics[pair];
    let line = pr.line(&Pose::IDENTITY);
    let p = sketch(m, pr.point);
    line.point + line.dir * (p - line.point).dot(line.dir)
}

/// Where the sketch has the slider's point of pair `k` along its guide
/// line, from the line's point, in the guide's frame: the zero of the
/// pair's slide.
pub fn slide_ref(m: &Mechanism, k: usize) -> f64 {
    let pr = &m.prismatics[k];
    let q0 = m.links[pr.guide].sketch_pose.local(sketch(m, pr.point));
    pr.line_dir.dot(q0 - pr.line_point)
}

/// The slider's pose in its guide's frame when the slider's point of pair
/// `k` has slid by `x` along the guide from where the sketch has it.
pub fn slide_pose(m: &Mechanism, k: usize, x: f64) -> Pose {
    let pr = &m.prismatics[k];
    let at = pr.line_point + pr.line_dir * (slide_ref(m, k) + x);
    Pose::through(at.to_point(), pr.slider_local, pr.delta)
}

/// The pose of the link a driving pair `k` places, its other link
/// (`known`) at `known_pose` and the slide `x`.
pub fn place_across(m: &Mechanism, k: usize, known: usize, known_pose: &Pose, x: f64) -> Pose {
    let rel = slide_pose(m, k, x);
    if m.prismatics[k].guide == known {
        known_pose.then(&rel)
    } else {
        known_pose.then(&rel.inverse())
    }
}

/// The input coordinates the sketch itself shows.
pub fn sketch_input(m: &Mechanism) -> Coords {
    let q: Vec<f64> = m
        .scene
        .inputs()
        .map(|spec| match *spec {
            InputSpec::Crank { link, pivot, .. } => {
                let pts = &m.links[link].points;
                let other = if pts[0] == pivot { pts[1] } else { pts[0] };
                (sketch(m, other) - sketch(m, pivot)).atan2()
            }
            InputSpec::Slider { .. } => 0.0,
        })
        .collect();
    Coords::new(&q)
}
