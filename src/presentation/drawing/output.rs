//! What a sheet is and how it is asked for: its size, its format, the
//! options of a drawing, and the finished sheet (SVG text with its name,
//! title and scales).

use crate::lang::Lang;

/// Sheet formats, landscape (ГОСТ 2.301).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SheetSize {
    /// 297 × 210 mm.
    A4,
    /// 420 × 297 mm.
    A3,
    /// 594 × 420 mm.
    A2,
    /// 841 × 594 mm (the course project's sheet).
    A1,
}

impl SheetSize {
    /// Width and height, mm, landscape.
    pub fn mm(&self) -> (f64, f64) {
        match self {
            SheetSize::A4 => (297.0, 210.0),
            SheetSize::A3 => (420.0, 297.0),
            SheetSize::A2 => (594.0, 420.0),
            SheetSize::A1 => (841.0, 594.0),
        }
    }
    /// The size of a name, `A4` … `A1` (either case).
    pub fn parse(s: &str) -> Option<SheetSize> {
        match s.to_ascii_uppercase().as_str() {
            "A4" => Some(SheetSize::A4),
            "A3" => Some(SheetSize::A3),
            "A2" => Some(SheetSize::A2),
            "A1" => Some(SheetSize::A1),
            _ => None,
        }
    }
    /// Every size, smallest first.
    pub const ALL: [SheetSize; 4] = [SheetSize::A4, SheetSize::A3, SheetSize::A2, SheetSize::A1];
}

#[derive(Clone, Copy, Debug)]
pub struct DrawOptions {
    pub sheet: SheetSize,
    pub lang: Lang,
    /// The main title block (ГОСТ 2.104 form 1) on every sheet; always on
    /// the course sheet.
    pub title_block: bool,
    /// Add the table of measured quantities to plan sheets.
    pub table: bool,
    /// Mark the instant centres on the plans of the mechanism.
    pub centres: bool,
    /// Compose the course sheet (besides what `want.drawings` asks).
    pub course: bool,
    /// The user asked for `sheet` (`--sheet`): every sheet but the course
    /// sheets is drawn on it, the force sheets too (without it a force
    /// sheet whose free bodies cannot be read on `sheet` goes on A3).
    pub fixed_sheet: bool,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            sheet: SheetSize::A4,
            lang: Lang::En,
            title_block: false,
            table: false,
            centres: false,
            course: false,
            fixed_sheet: false,
        }
    }
}

/// One sheet: its file stem (`velocity_1`), title, size, the scales its
/// figures are drawn at (`mu_l`, `mu_v`, `mu_a`) and SVG text.
#[derive(Clone, Debug)]
pub struct Sheet {
    /// The file stem: `mechanism_1`, `velocity_1`, `positions`, `course` …
    pub name: String,
    /// The sheet's title, as its heading says it.
    pub title: String,
    /// The position a sheet of one position draws (its plan of the
    /// mechanism, plans, forces, lever; the course's force analysis): its
    /// number as the heading and the file's name say it, in the study's
    /// numbering (a `count` sweep from 0, given input values from 1).
    pub position: Option<usize>,
    /// The sheet format it is drawn on.
    pub size: SheetSize,
    /// The scales of its figures by name (`mu_l` m/mm, `mu_v` (m/s)/mm,
    /// `mu_a` (m/s²)/mm, `mu_F` N/mm).
    pub scales: Vec<(&'static str, f64)>,
    /// The sheet as SVG text, true size in mm.
    pub svg: String,
}

/// Output formats of `mechplan draw`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// SVG text, true size.
    Svg,
    /// A picture at the request's resolution (the `render` feature).
    Png,
    /// A page per sheet, true size, and one book of all (the `render`
    /// feature).
    Pdf,
    /// An ASCII DXF (R2007, UTF-8) per sheet, true size in mm (see `dxf`).
    Dxf,
}
