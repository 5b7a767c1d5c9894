//! Lecture-style drawings: the plan of the mechanism, the plans of
//! velocities and accelerations, the positions sheet and the course sheet,
//! as SVG sheets with the ГОСТ 2.104 frame (and title block), exported to
//! PNG (resvg) and PDF (svg2pdf). The drawing code only reads the
//! analysis: the kernel knows nothing of SVG. What the sheets draw beyond
//! the solved positions (the trajectories and extreme positions, the
//! positions a course singles out, the kinematic diagrams) is handed in
//! solved ([`crate::studies::sheet_data`]; see [`sheet_needs`]).
//!
//! Every figure is drawn at the scale that fills its field: the smallest
//! standard μ (1, 2, 2.5, 4, 5 × 10^k, ГОСТ 2.302) at which the drawing,
//! labels and symbols included, fits; a scale the scene fixes
//! (`want.scales`) is kept. The plans are built again at their sheet's
//! scale: a new construction, not the solver's plan enlarged.

pub mod canvas;
mod captions;
mod compose;
pub mod centres;
pub mod course;
mod course_data;
mod course_forces;
pub mod cylinder;
pub mod diagram;
pub mod dxf;
pub mod export;
pub mod force_polygon;
pub mod forces;
pub mod free_body;
mod free_body_marks;
pub mod frenet;
pub mod html;
mod kind;
mod handout_forces;
mod html_parts;
mod layout;
pub mod lever;
pub mod mechanism;
mod output;
mod pack;
pub mod plan;
pub mod positions;
mod rate_arc;
pub mod sheet;
mod shared;
mod sweep;
pub mod table;
mod wall;

#[cfg(all(feature = "render", feature = "internals"))]
pub use export::tree;
pub use export::{pdf, pdf_book, png};

pub(crate) use captions::{position_text, scale_label, scale_text, words};
#[cfg(feature = "internals")]
pub use compose::{sheets, sheets_on};
#[cfg(feature = "internals")]
pub use compose::sheet_needs;
pub use compose::{sheets_on_each, sweep_needs};
pub use sweep::Sweep;
pub use layout::plan_field;
pub(crate) use layout::{Pending, field_size, fill, lower_scale, mechanism_extent, page_svg, reduction, main_title_block, title_block};
pub use kind::SheetKind;
pub use output::{DrawOptions, Format, Sheet, SheetSize};
