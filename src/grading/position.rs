//! The position an answer states, and the numbering it states it in.
//!
//! One numbering serves every position number a person reads or types: the
//! study's ([`crate::kinematics::solve::Analysis::numbering`]; by default
//! the scene's, a `count` sweep from 0 as the sheets number it, given input
//! values from 1). An answer written in the older numbering of a `count`
//! sweep (the K-th position is position K) says so with `"positions_from":
//! 1` (or the command line with `--positions-from 1`), and its `position`
//! is read so. An answer without a `position` is of the first position,
//! whatever the numbering.

use crate::error::Issue;
use crate::model::scene::Numbering;
use serde_json::{Map, Value};

/// The position an answer states.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StatedPosition {
    /// Its number (`"position"`, `--position`); `None`: not stated, the
    /// first position.
    pub number: Option<usize>,
    /// The numbering it is written in (`"positions_from"`,
    /// `--positions-from`); `None`: the study's.
    pub from: Option<Numbering>,
}

impl StatedPosition {
    /// Position `number` in the study's numbering.
    pub fn new(number: usize) -> StatedPosition {
        StatedPosition {
            number: Some(number),
            from: None,
        }
    }

    /// Position `number` in the numbering `from`.
    #[cfg(feature = "internals")]
    pub fn numbered(number: usize, from: Numbering) -> StatedPosition {
        StatedPosition {
            number: Some(number),
            from: Some(from),
        }
    }

    /// The index (from 0, in the sweep's order) of the position among
    /// `count` positions of a study numbered by `study`; else the message
    /// naming the range in the numbering in force.
    pub fn index(&self, study: Numbering, count: usize) -> Result<usize, String> {
        let Some(number) = self.number else {
            return Ok(0);
        };
        let numbering = self.from.unwrap_or(study);
        numbering.index(number, count).ok_or_else(|| {
            format!(
                "position {number} is not one of the scene's positions: they are numbered {}",
                numbering.range_text(count)
            )
        })
    }
}

/// The answer's `position` and `positions_from` (JSON); `None` (with the
/// issues) when either is not as allowed: a whole number for the
/// position, 0 or 1 for the numbering.
pub(super) fn read(o: &Map<String, Value>, issues: &mut Vec<Issue>) -> Option<StatedPosition> {
    let bad = |at: &str, message: String| Issue {
        pointer: at.into(),
        message,
    };
    let number = match o.get("position") {
        None => Some(None),
        Some(p) => match p.as_u64() {
            Some(n) => Some(Some(usize::try_from(n).unwrap_or(usize::MAX))),
            None => {
                issues.push(bad(
                    "/position",
                    format!("expected a whole position number, found {p}"),
                ));
                None
            }
        },
    };
    let from = match o.get("positions_from") {
        None => Some(None),
        Some(f) => match f.as_u64().and_then(Numbering::from_first) {
            Some(n) => Some(Some(n)),
            None => {
                issues.push(bad(
                    "/positions_from",
                    format!(
                        "expected 0 or 1, the number of the scene's first position in this answer, found {f}"
                    ),
                ));
                None
            }
        },
    };
    Some(StatedPosition {
        number: number?,
        from: from?,
    })
}
