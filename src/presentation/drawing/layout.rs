//! Figures on their sheets: the standard scale that fills a field
//! ([`fill`]), the fields of single-figure sheets, a figure waiting for
//! its page and the page made of it, the title block, a sheet from one
//! canvas.

use super::canvas::Canvas;
use super::output::{DrawOptions, Sheet, SheetSize};
use super::sheet::{self, Page, TitleBlock};
use super::table::{self, number};
use super::{centres, mechanism};
use crate::kinematics::construction::Field;
use crate::kinematics::construction::scale::{Series, drawing_reduction};
use crate::kinematics::positions::Configuration;
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use kurbo::{Point, Rect};

/// The smallest μ of `series`, not below `lower`, at which `draw(μ)` fits
/// `field` (w × h, mm), with its drawing; `None` when nothing up to a
/// million times `lower` fits. A drawing at a smaller μ is larger (a
/// drawing's size never shrinks with its scale but for its labels, which
/// keep their size), so the first that fits fills its field best: at the
/// one before it, the drawing overflowed, and standard values are at most
/// ×2 apart, so it spans at least half the field one way.
pub fn fill<T>(
    series: Series,
    lower: f64,
    field: (f64, f64),
    mut draw: impl FnMut(f64) -> Option<T>,
    extent: impl Fn(&T) -> Rect,
) -> Option<(f64, T)> {
    let mut mu = series.at_least(lower.max(1e-12));
    let top = mu * 1e6;
    while mu <= top {
        if let Some(t) = draw(mu)
            && fits(extent(&t), field)
        {
            return Some((mu, t));
        }
        mu = series.above(mu);
    }
    None
}

/// The scale `lower` to start [`fill`] from: the smallest at which a real
/// extent `w` × `h` (m, or m/s …) is drawn within the field; the drawing,
/// with its labels, is never smaller.
pub fn lower_scale(w: f64, h: f64, field: (f64, f64)) -> f64 {
    (w / field.0).max(h / field.1).max(1e-12)
}

/// Whether an extent fits a field (mm).
pub(super) fn fits(u: Rect, (aw, ah): (f64, f64)) -> bool {
    u.width() <= aw && u.height() <= ah
}

/// The real extent of the mechanism's shown points over the positions of
/// `configs` (m).
pub(crate) fn mechanism_extent<'c>(
    an: &Analysis,
    configs: impl IntoIterator<Item = &'c Configuration>,
) -> Rect {
    let m = &an.mech;
    let mut r: Option<Rect> = None;
    // The points drawn: those of moving links, and the frame's pivots (a
    // frame point that only names an axis, as the compressor's Y, is not).
    let drawn = |p: usize| {
        let ls = m.links_of_point(p);
        ls.iter().any(|&l| l != m.frame() && an.link(l)) || ls.len() >= 2
    };
    for config in configs {
        for p in (0..m.scene.points.len()).filter(|&p| drawn(p)) {
            if let Some(&l) = m.links_of_point(p).iter().find(|&&l| an.link(l)) {
                let q = config.point(m, l, p);
                let b = Rect::from_points(q, q);
                r = Some(r.map_or(b, |x| x.union(b)));
            }
        }
    }
    r.unwrap_or(Rect::ZERO)
}

/// The plan of the mechanism at position `s`, at `mu_l`.
pub(super) fn mechanism_canvas(an: &Analysis, s: &Solved, opt: &DrawOptions, mu_l: f64) -> Canvas {
    let mut c = Canvas::default();
    mechanism::draw(an, s, &mut c, mu_l, true);
    if opt.centres {
        centres::draw(an, s, &mut c, mu_l);
    }
    c.place_pending();
    c
}

/// How far a plan's letters reach beyond its points, mm: the margin its
/// field keeps on either side across (where a list of the letters of
/// points that fall together runs on, "p_v, b, c, d₅, s₄") and above and
/// below (one line of letters).
const LETTERS: (f64, f64) = (20.0, 8.0);
/// The width kept beside a plan for its table of measured segments
/// (`--table`), mm: the widest table of the fixtures' plans, rounded up.
pub(crate) const TABLE_WIDTH: f64 = 80.0;

/// Where a plan whose scale the scene leaves open must fit on a sheet of
/// `opt`: the single-figure sheet's field (beside the table when one is
/// asked for), less the letters' margin. The construction picks the
/// smallest standard μ at which its points fall there, and that μ is the
/// plan's everywhere: the sheet draws it as built.
pub fn plan_field(opt: &DrawOptions) -> Field {
    let right = if opt.table { TABLE_WIDTH + sheet::PAD } else { 0.0 };
    let (w, h) = field_size(opt, right);
    let (width, height) = (w - 2.0 * LETTERS.0, h - 2.0 * LETTERS.1);
    Field {
        longest: width.hypot(height),
        width,
        height,
    }
}

/// The field (w × h) of a single-figure sheet.
pub(crate) fn field_size(opt: &DrawOptions, right: f64) -> (f64, f64) {
    let f = sheet::field(opt.sheet, opt.title_block, right);
    (f.width(), f.height())
}

/// A figure waiting for its page: the drawing, the box to centre (the
/// union of a series, so that flipping through the series the mechanism
/// does not jump), the heading, the scale, a table beside it.
pub(crate) struct Pending {
    /// A larger sheet than the run's (a force sheet whose free bodies
    /// need it), or `None`.
    pub(super) sheet: Option<super::SheetSize>,
    pub(super) name: String,
    pub(super) title: String,
    pub(super) scale: Option<String>,
    pub(super) scales: Vec<(&'static str, f64)>,
    pub(super) canvas: Canvas,
    pub(super) centre_on: Option<Rect>,
    pub(super) table: Option<table::Ruled>,
}

/// A single-figure sheet from its pending figure: frame, heading, the
/// figure centred in its field, the table beside it, the title block.
pub(super) fn render(an: &Analysis, opt: &DrawOptions, p: Pending, number: (usize, usize)) -> Sheet {
    let opt = &DrawOptions {
        sheet: p.sheet.unwrap_or(opt.sheet),
        ..*opt
    };
    let right = p.table.as_ref().map_or(0.0, |t| t.size().0 + sheet::PAD);
    let mut page = Page::for_sheet(opt.sheet, opt.title_block);
    page.heading(&p.title, p.scale.as_deref());
    let f = sheet::field(opt.sheet, opt.title_block, right);
    page.place(&p.canvas, f, p.centre_on);
    if let Some(t) = &p.table {
        let (tw, _) = t.size();
        let fr = sheet::frame_of(opt.sheet, sheet::upright(opt.sheet, opt.title_block));
        page.place_at(
            &t.draw(),
            Point::new(fr.x1 - sheet::PAD - tw, fr.y0 + sheet::HEADING),
        );
    }
    if opt.title_block {
        page.title_block(&title_block(an, opt, &p.title, number));
    }
    Sheet {
        name: p.name,
        title: p.title,
        position: None,
        size: opt.sheet,
        scales: p.scales,
        svg: page.finish(),
    }
}

/// The title block of a sheet of this scene.
pub(crate) fn title_block(
    an: &Analysis,
    opt: &DrawOptions,
    title: &str,
    number: (usize, usize),
) -> TitleBlock {
    TitleBlock::new(&an.mech.scene.sheet, title, opt.lang, number)
}

/// The course sheet's title block: the scene's `sheet.title` (in the
/// sheet's language where it gives several) names this drawing, the
/// project's first; every other sheet's block names that sheet.
pub(crate) fn main_title_block(
    an: &Analysis,
    opt: &DrawOptions,
    title: &str,
    number: (usize, usize),
) -> TitleBlock {
    let info = &an.mech.scene.sheet;
    let name = info.title_in(opt.lang).unwrap_or(title);
    TitleBlock::new(info, name, opt.lang, number)
}

/// The sheet a drawing of extent `b` (mm) goes on: the first of
/// `opt.sheet` and the larger sizes whose field holds it, else A1.
fn sheet_for(b: Rect, opt: &DrawOptions) -> SheetSize {
    SheetSize::ALL
        .into_iter()
        .filter(|s| s.mm().0 >= opt.sheet.mm().0)
        .find(|&s| fits(b, field_size(&DrawOptions { sheet: s, ..*opt }, 0.0)))
        .unwrap_or(SheetSize::A1)
}

/// How many times [`page_svg`] reduces a drawing of extent `b` (mm): 1
/// when a sheet holds it, else the standard n of "1:n" that brings it
/// within A1's field. A drawing that places its labels itself (the
/// check's overlay) is drawn reduced by it before its labels are placed,
/// since a reduction keeps the lettering's size.
pub fn reduction(b: Rect, opt: &DrawOptions) -> f64 {
    let size = sheet_for(b, opt);
    let f = sheet::field(size, opt.title_block, 0.0);
    let k = (f.width() / b.width())
        .min(f.height() / b.height())
        .min(1.0);
    if k < 1.0 {
        // The smallest "1:n" reduction of ГОСТ 2.302 that brings it within.
        drawing_reduction(1.0 / k)
    } else {
        1.0
    }
}

/// A single sheet from a canvas (the diagrams, the Frenet families, the
/// `check --svg` overlay): on the first of `opt.sheet` and the larger
/// sizes whose field holds it; a drawing larger than A1's field is drawn
/// reduced (its heading says by how much).
pub fn page_svg(
    name: String,
    title: String,
    c: &Canvas,
    scale: Option<String>,
    opt: &DrawOptions,
) -> Sheet {
    let b = c.bounds();
    let size = sheet_for(b, opt);
    let opt = DrawOptions {
        sheet: size,
        ..*opt
    };
    let f = sheet::field(size, opt.title_block, 0.0);
    let n = reduction(b, &opt);
    let mut page = Page::new(size);
    let title = if n > 1.0 {
        let c2 = c.scaled(1.0 / n);
        let t = format!("{title} (1:{})", number(n, opt.lang));
        page.heading(&t, scale.as_deref());
        page.place(&c2, f, None);
        t
    } else {
        page.heading(&title, scale.as_deref());
        page.place(c, f, None);
        title
    };
    Sheet {
        name,
        title,
        position: None,
        size,
        scales: Vec::new(),
        svg: page.finish(),
    }
}
