//! `check SCENE ANSWER` as one call: the answer file read (JSON or SVG; a
//! force plan when its `plan` is `"force"` or the drawing states μ_F),
//! the command line's overrides applied, the answer checked against the
//! scene, the overlay written when asked, and the report as text or JSON
//! with its exit status. The binary only parses its arguments.

use super::answer::{self, Reading};
use super::forces;
use crate::error::{Error, Result};
use crate::kinematics::construction::PlanKind;
use crate::study::{Study, in_file, read};
use std::path::{Path, PathBuf};

/// What the command line says besides the two files.
#[derive(Clone, Debug, Default)]
pub struct CheckRequest {
    /// The report as JSON (else text).
    pub json: bool,
    /// Where to write the overlay of a kinematic plan (`--svg`).
    pub overlay: Option<PathBuf>,
    pub delta: Option<f64>,
    pub mu: Option<f64>,
    pub plan: Option<PlanKind>,
    pub position: Option<usize>,
}

/// Check `answer` against `scene`: the report, and the exit status (0
/// right, 1 wrong, 4 some items cannot be judged).
pub fn check_file(scene: &Path, answer: &Path, req: &CheckRequest) -> Result<(String, u8)> {
    if let Some(done) = check_force_file(scene, answer, req)? {
        return Ok(done);
    }
    let r = Reading {
        mu: req.mu,
        plan: req.plan,
        delta: req.delta,
        position: req.position,
    };
    let ans = answer::read(answer, &r)?;
    let study = Study::from_path(scene)?;
    match req.position {
        Some(p) => study.position_in_range("position", p)?,
        None => study
            .position_in_range("/position", ans.position)
            .map_err(in_file(&answer.display().to_string()))?,
    }
    let report = study.check(&ans)?;
    if let Some(out) = &req.overlay {
        let overlay = super::overlay(study.analysis(), &ans, &report);
        crate::output::write_atomically(out, overlay.as_bytes())?;
    }
    let text = if req.json {
        serde_json::to_string_pretty(&super::to_json(&report)).expect("finite numbers") + "\n"
    } else {
        super::to_text(&report)
    };
    Ok((text, report.status()))
}

/// A force plan's check (a JSON answer whose `plan` is `"force"`, or an
/// SVG drawing that states μ_F); `None` for a kinematic answer, which its
/// own reader reads (and refuses, when it cannot be read).
fn check_force_file(
    scene: &Path,
    answer: &Path,
    req: &CheckRequest,
) -> Result<Option<(String, u8)>> {
    let name = answer.display().to_string();
    let drawn = answer
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let too_large = std::fs::metadata(answer).is_ok_and(|md| answer::check_size(md.len()).is_err());
    if too_large {
        return Ok(None);
    }
    let Ok(text) = read(answer) else {
        return Ok(None);
    };
    let mut ans = if drawn {
        if !forces::is_force_svg(&text) {
            return Ok(None);
        }
        let (delta, position) = (req.delta.unwrap_or(0.5), req.position.unwrap_or(1));
        forces::from_svg(&text, req.mu, delta, position)
    } else {
        if !forces::is_force_answer(&text) {
            return Ok(None);
        }
        forces::from_json(&text)
    }
    .map_err(in_file(&name))?;
    if let Some(d) = req.delta {
        if !(d.is_finite() && d > 0.0) {
            return Err(Error::scene(
                "delta",
                "the pencil precision must be a positive number of mm",
            ));
        }
        ans.delta = d;
    }
    if req.plan.is_some() {
        return Err(Error::scene(
            "plan",
            "the answer is a force plan (\"plan\": \"force\"): --plan names a plan of velocities or accelerations",
        ));
    }
    if let Some(m) = req.mu {
        if !(m.is_finite() && (1e-6..=1e9).contains(&m)) {
            return Err(Error::scene(
                "mu",
                "μ_F must be a number of N/mm between 1e-6 and 1e9",
            ));
        }
        ans.mu = m;
    }
    if req.overlay.is_some() {
        return Err(Error::scene(
            "svg",
            "the overlay (--svg) is drawn for plans of velocities and accelerations only",
        ));
    }
    let study = Study::from_path(scene)?;
    match req.position {
        Some(p) => {
            study.position_in_range("position", p)?;
            ans.position = p;
        }
        None => study
            .position_in_range("/position", ans.position)
            .map_err(in_file(&name))?,
    }
    let report = study.check_forces(&ans)?;
    let text = if req.json {
        serde_json::to_string_pretty(&forces::to_json(&report)).expect("finite numbers") + "\n"
    } else {
        forces::to_text(&report)
    };
    Ok(Some((text, report.status())))
}
