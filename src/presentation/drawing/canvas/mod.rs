//! A drawing sheet in millimetres: primitives collected in drawing
//! coordinates (y up, as the plans are computed), labels placed so that they
//! overlap neither each other nor the drawn lines, then written as SVG with
//! one number formatter so the output is byte-stable.
//!
//! `primitives` holds the sheet ([`Canvas`]), its primitives ([`Prim`]), the
//! classes and line types of ГОСТ 2.303 and the drawing calls; `label`
//! holds the [`Label`] and the widths of text, `placement` the grids of
//! segments and boxes and the placing of labels and text, `render` the
//! writing as SVG and the number formatter.

mod grid;
// Named by the tests that read a canvas's boxes (`internals`).
#[cfg(feature = "internals")]
pub use grid::Grid;
mod label;
mod placement;
mod primitives;
mod render;

pub use label::{Label, runs_width, wrap};
pub use placement::{lettering, with_lettering};
pub use render::{fmt, xml};
pub use primitives::*;
