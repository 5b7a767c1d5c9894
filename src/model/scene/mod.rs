//! The scene file (described completely in `docs/scene-format.md`):
//! reading and validating it completely, every
//! problem reported with its JSON pointer. All numbers are converted to SI
//! (m, rad) here, so nothing downstream knows about units.
//!
//! The types are here; the reader, by section of the file: `reader` (the
//! top level, the units and the getters every section uses), `numbers`
//! (numbers, angles and their rounding),
//! `links` (points and links), `sliders` (prismatic pairs and their
//! guide lines), `lengths`, `input`, `positions`, `want`, `dynamics`.

mod dynamics;
mod input;
mod lengths;
mod links;
mod numbers;
mod positions;
mod reader;
mod sheet;
mod sliders;
mod spec;
mod want;

use crate::error::{Error, Result};
use crate::json::{locate_bad_numbers, parse_strict};
use reader::Reader;
pub use spec::*;


impl Scene {
    /// Every input, in the order `input` lists them.
    pub fn inputs(&self) -> impl Iterator<Item = &InputSpec> {
        std::iter::once(&self.input).chain(&self.more_inputs)
    }
    /// Input `i` (0: the first).
    pub fn input_at(&self, i: usize) -> &InputSpec {
        if i == 0 {
            &self.input
        } else {
            &self.more_inputs[i - 1]
        }
    }
    /// How many inputs the scene has.
    pub fn input_count(&self) -> usize {
        1 + self.more_inputs.len()
    }
    /// Does the scene have several inputs?
    pub fn several_inputs(&self) -> bool {
        !self.more_inputs.is_empty()
    }
    pub fn point_index(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p.name == name)
    }
    pub fn link_index(&self, id: &str) -> Option<usize> {
        self.links.iter().position(|l| l.id == id)
    }
    /// Links (indices) that list point `p`, in scene order.
    pub fn links_of_point(&self, p: usize) -> Vec<usize> {
        (0..self.links.len())
            .filter(|&l| self.links[l].points.contains(&p))
            .collect()
    }

    /// Read a scene from JSON text.
    pub fn from_json(text: &str) -> Result<Scene> {
        if text.len() > MAX_FILE_BYTES {
            return Err(Error::scene(
                "",
                format!(
                    "the file has {} bytes; a scene may have at most {MAX_FILE_BYTES}",
                    text.len()
                ),
            ));
        }
        let value = parse_strict(text.strip_prefix('\u{feff}').unwrap_or(text))
            .map_err(|e| Error::json(locate_bad_numbers(text).unwrap_or(e)))?;
        let mut r = Reader::default();
        let scene = r.scene(&value);
        match scene {
            Some(s) if r.issues.is_empty() => Ok(s),
            _ => Err(Error::fields(r.issues)),
        }
    }
}
