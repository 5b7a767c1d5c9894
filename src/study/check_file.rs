//! `check SCENE ANSWER` as one call: the two files read (the answer JSON
//! or SVG, refused when larger than the grading reads), the answer
//! checked ([`super::Solution::check_answer`]), the overlay written when
//! asked, and the report as text or JSON with its exit status. The binary
//! only parses its arguments.

use super::{Study, studies};
use crate::error::{Error, Result, in_file};
use crate::grading::answer::{self, MAX_ANSWER_BYTES};
use crate::kinematics::construction::PlanKind;
use std::path::{Path, PathBuf};

/// What the command line says besides the two files: each override
/// replaces what the answer says.
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
    let name = answer.display().to_string();
    let svg = answer
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let text = read_answer(answer)?;
    let parsed = studies::parse_answer(&text, &name, svg, req)?;
    let study = Study::from_path(scene)?;
    studies::position_of(&study, &parsed, &name, req)?;
    let checked = studies::check_parsed(&study.solve()?, parsed)?;
    if let Some(out) = &req.overlay
        && let Some(overlay) = checked.overlay()
    {
        super::files::write_atomically(out, overlay.as_bytes())?;
    }
    let text = if req.json {
        super::pretty(&checked.to_json())
    } else {
        checked.to_text()
    };
    Ok((text, checked.status()))
}

/// An answer file's text, refusing one larger than [`MAX_ANSWER_BYTES`]
/// before it is read whole; its problems name the file.
fn read_answer(path: &Path) -> Result<String> {
    use std::io::Read;
    let name = path.display().to_string();
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
