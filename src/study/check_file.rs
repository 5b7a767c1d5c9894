//! `check SCENE ANSWER` as one call: the answer file read (JSON or SVG; a
//! force plan when its `plan` is `"force"` or the drawing states μ_F),
//! the command line's overrides applied, the answer checked against the
//! scene, the overlay written when asked, and the report as text or JSON
//! with its exit status. The binary only parses its arguments.

use super::Study;
use crate::error::{Error, Result, in_file};
use crate::grading::answer::{self, MAX_ANSWER_BYTES, Reading};
use crate::grading::forces;
use crate::kinematics::construction::PlanKind;
use crate::presentation::verdict;
use std::path::{Path, PathBuf};

/// What the command line says besides the two files.
#[derive(Clone, Debug, Default)]
pub struct CheckRequest {
    /// The report as JSON (else text).
    pub json: bool,
    /// Where to write the overlay of a kinematic plan (`--svg`).
    pub overlay: Option<PathBuf>,
    /// The pencil's precision δ, mm (`--delta`), over the answer's own.
    pub delta: Option<f64>,
    /// The plan's scale μ (`--mu`), over the answer's own.
    pub mu: Option<f64>,
    /// Which plan the answer is (`--plan`), over the answer's own.
    pub plan: Option<PlanKind>,
    /// The position (`--position`, from 1), over the answer's own.
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
    let ans = answer::from_text(&read_answer(answer)?, &name_of(answer), is_svg(answer), &r)?;
    let study = Study::from_path(scene)?;
    match req.position {
        Some(p) => study.position_in_range("position", p)?,
        None => study
            .position_in_range("/position", ans.position)
            .map_err(in_file(&answer.display().to_string()))?,
    }
    let report = study.check(&ans)?;
    if let Some(out) = &req.overlay {
        let overlay = verdict::overlay(study.analysis(), &ans, &report);
        super::files::write_atomically(out, overlay.as_bytes())?;
    }
    let text = if req.json {
        serde_json::to_string_pretty(&verdict::to_json(&report)).expect("finite numbers") + "\n"
    } else {
        verdict::to_text(&report)
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
    let name = name_of(answer);
    let drawn = is_svg(answer);
    let Ok(text) = read_answer(answer) else {
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

/// How an answer file is named in messages.
fn name_of(answer: &Path) -> String {
    answer.display().to_string()
}

/// An answer drawn in a vector editor, by its extension.
fn is_svg(answer: &Path) -> bool {
    answer
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
}

/// An answer file's text, refusing one larger than [`MAX_ANSWER_BYTES`]
/// before it is read whole; its problems name the file.
fn read_answer(path: &Path) -> Result<String> {
    use std::io::Read;
    let name = name_of(path);
    let io = |source| Error::Io {
        path: name.clone(),
        source,
    };
    let f = std::fs::File::open(path).map_err(io)?;
    if let Ok(md) = f.metadata() {
        answer::check_size(md.len()).map_err(in_file(&name))?;
    }
    let mut text = String::new();
    f.take(MAX_ANSWER_BYTES as u64 + 1)
        .read_to_string(&mut text)
        .map_err(io)?;
    Ok(text)
}
