//! An answer's text read, JSON or a drawing (SVG, DXF), with what the
//! command line says over it ([`Reading`]).

use super::answer::{Answer, check_size, delta_issue, from_json};
use crate::error::{Error, Result};
use crate::kinematics::construction::PlanKind;

/// What the command line may say about an answer: an SVG's scale and plan
/// where the drawing does not state them, the pencil's δ, the position
/// (each overrides the answer's own).
#[derive(Clone, Debug, Default)]
pub struct Reading {
    pub mu: Option<f64>,
    pub plan: Option<PlanKind>,
    pub delta: Option<f64>,
    pub position: Option<usize>,
}

/// Read an answer's text — JSON, or a drawing: an SVG drawn in a vector
/// editor or a DXF drawn in a CAD (`svg`: by its file's extension, or when
/// its first character is `<`, or it starts as a DXF does) —
/// refusing one larger than [`super::answer::MAX_ANSWER_BYTES`]; its problems name the
/// answer (`name`, its file). Reading the file is the front door's
/// (`crate::study`).
pub fn from_text(text: &str, name: &str, svg: bool, r: &Reading) -> Result<Answer> {
    let in_answer = crate::error::in_file(name);
    check_size(text.len() as u64).map_err(&in_answer)?;
    if let Some(i) = r.delta.and_then(|d| delta_issue(d, "delta")) {
        return Err(Error::fields(vec![i]));
    }
    let svg = svg || text.trim_start().starts_with('<') || super::dxf::looks_like_dxf(text);
    let mut ans = if svg {
        drawing(text).and_then(|d| {
            super::drawing::answer_of(
                d,
                r.mu,
                r.plan,
                r.delta.unwrap_or(0.5),
                r.position.unwrap_or(1),
            )
        })
    } else {
        from_json(text)
    }
    .map_err(&in_answer)?;
    if let Some(d) = r.delta {
        ans.delta = d;
    }
    if let Some(p) = r.position {
        ans.position = p;
    }
    Ok(ans)
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
