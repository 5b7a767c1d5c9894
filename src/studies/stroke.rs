//! The output's stroke as a course sheet states it: the stroke H between
//! the extreme positions (a slide, or a rocker's swing), the crank angles
//! of the working and the idle stroke, and the coefficient K of the
//! change of the output's mean speed (their ratio, K ≥ 1).

use crate::kinematics::solve::Analysis;
use crate::model::scene::PositionsSpec;

/// The stroke of the output a sweep (`positions.count`) starts from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// The output link.
    pub output: usize,
    /// It slides on a frame guide (H in m), or turns (H in rad).
    pub slide: bool,
    /// The stroke H: the slide between the extreme positions (m), or the
    /// rocker's swing (rad).
    pub h: f64,
    /// The crank angle of the working stroke (the larger), rad.
    pub working: f64,
    /// The crank angle of the idle stroke, rad: 2π − `working`.
    pub idle: f64,
}

impl Stroke {
    /// The stroke of the sweep's output (`positions.count`'s `output`, by
    /// default the last group's last link) for a crank input; `None` when
    /// the output turns fully, the input is no single crank or the
    /// extremes cannot be found.
    pub fn of(an: &Analysis) -> Option<Stroke> {
        let m = &an.mech;
        let output = match m.scene.positions {
            PositionsSpec::Count {
                output: Some(out), ..
            } => out,
            _ => an.default_output(),
        };
        let s = an.stroke_start(output).ok()?;
        let h = s.swing?;
        let slide = m
            .prismatics
            .iter()
            .any(|p| p.slider == output && p.guide == m.frame());
        Some(Stroke {
            output,
            slide,
            h,
            working: s.stroke,
            idle: std::f64::consts::TAU - s.stroke,
        })
    }

    /// The coefficient of the change of the output's mean speed,
    /// K = φ_w / φ_i (the working stroke slower: K ≥ 1).
    pub fn k(&self) -> f64 {
        self.working / self.idle
    }
}
