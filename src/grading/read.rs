//! An answer's text read, JSON or a drawing (SVG, DXF), with what the
//! command line says over it ([`Reading`]).

use super::answer::{Answer, check_size, delta_issue, from_json};
use crate::error::{Error, Result};
use super::photo::{PhotoFile, PhotoReading};
use super::position::StatedPosition;
use crate::kinematics::construction::PlanKind;
use crate::model::scene::Numbering;

/// What the command line may say about an answer: an SVG's scale and plan
/// where the drawing does not state them, the pencil's δ, the position
/// (each overrides the answer's own), and the numbering of the position
/// it says and of an answer's that states none (`--positions-from`).
#[derive(Clone, Debug, Default)]
pub struct Reading {
    pub mu: Option<f64>,
    pub plan: Option<PlanKind>,
    pub delta: Option<f64>,
    pub position: Option<usize>,
    pub positions_from: Option<Numbering>,
}

impl Reading {
    /// The position an answer states, with the command line's over it:
    /// `--position` (in the numbering of `--positions-from`, else the
    /// study's) over the answer's own; `--positions-from` the numbering of
    /// an answer's position that states none.
    pub fn over(&self, own: StatedPosition) -> StatedPosition {
        match self.position {
            Some(p) => StatedPosition {
                number: Some(p),
                from: self.positions_from,
            },
            None => StatedPosition {
                number: own.number,
                from: own.from.or(self.positions_from),
            },
        }
    }
}

/// Read an answer's text — JSON, or a drawing: an SVG drawn in a vector
/// editor or a DXF drawn in a CAD (`svg`: by its file's extension, or when
/// its first character is `<`, or it starts as a DXF does) —
/// refusing one larger than [`super::answer::MAX_ANSWER_BYTES`]; its problems name the
/// answer (`name`, its file). Reading the file is the front door's
/// (`crate::study`). With the answer, the notes on what of a drawing was left out (its
/// texts that are no plan letter, letters beside no end of the plan:
/// [`super::drawing::answer_and_notes`]; a JSON answer has none) and, for
/// a marks file (a JSON answer with `photo`, [`super::photo`]), what the
/// report says of its photo, read by `photo_file` (the front door's:
/// reading files is not the grading's).
pub fn from_text_full(
    text: &str,
    name: &str,
    svg: bool,
    r: &Reading,
    photo_file: Option<PhotoFile>,
) -> Result<(Answer, Vec<String>, Option<PhotoReading>)> {
    let in_answer = crate::error::in_file(name);
    check_size(text.len() as u64).map_err(&in_answer)?;
    if let Some(i) = r.delta.and_then(|d| delta_issue(d, "delta")) {
        return Err(Error::fields(vec![i]));
    }
    let svg = svg || text.trim_start().starts_with('<') || super::dxf::looks_like_dxf(text);
    let mut photo = None;
    let (mut ans, notes) = if svg {
        drawing(text).and_then(|d| {
            super::drawing::answer_and_notes(
                d,
                r.mu,
                r.plan,
                r.delta.unwrap_or(0.5),
                StatedPosition::default(),
            )
        })
    } else if is_marks_text(text) {
        super::photo::from_marks(text, photo_file).map(|(a, p)| {
            photo = Some(p);
            (a, Vec::new())
        })
    } else {
        from_json(text).map(|a| (a, Vec::new()))
    }
    .map_err(&in_answer)?;
    if let Some(d) = r.delta {
        ans.delta = d;
    }
    ans.position = r.over(ans.position);
    Ok((ans, notes, photo))
}

/// Whether a JSON answer's text is a marks file (an object with
/// `photo`); a text that is no JSON object is left to [`from_json`]'s
/// messages.
fn is_marks_text(text: &str) -> bool {
    serde_json::from_str::<serde_json::Value>(text)
        .ok()
        .and_then(|v| v.as_object().map(super::photo::is_marks))
        .unwrap_or(false)
}

/// A drawing's text, read by its format: DXF when it looks like one
/// ([`super::dxf::looks_like_dxf`]), else SVG.
pub(crate) fn drawing(text: &str) -> Result<super::drawing::Drawing> {
    if super::dxf::looks_like_dxf(text) {
        super::dxf::parse(text)
    } else {
        super::svg::parse(text)
    }
}
