//! Figures packed on a course sheet: a figure with its caption and
//! scales, the sheet's size and field, the skyline packer (each figure
//! placed where its bottom stays highest, then leftmost, around the title
//! block) and the placing of the packed figures on the page.

use super::DrawOptions;
use super::canvas::Canvas;
use super::output::SheetSize;
use super::sheet::{self, Page};
use kurbo::{Point, Rect};

/// The space between figures, and between a caption and its figure, mm.
pub(super) const GAP: f64 = 8.0;

/// The caption's line height, mm.
pub(super) const CAPTION: f64 = 6.0;

/// Caption font size, mm.
const CAPTION_FONT: f64 = 3.5;

/// A caption line's height at the lettering in force
/// ([`super::canvas::with_lettering`]).
pub(super) fn caption_line() -> f64 {
    CAPTION * super::canvas::lettering()
}

/// The sheet size of the course sheet: A2 when asked, else A1.
pub fn size(opt: &DrawOptions) -> SheetSize {
    if opt.sheet == SheetSize::A2 {
        SheetSize::A2
    } else {
        SheetSize::A1
    }
}

/// A figure of the sheet: a caption over a drawing, and the scales it is
/// drawn at.
#[derive(Clone)]
pub(super) struct Figure {
    pub id: String,
    pub caption: Vec<String>,
    pub canvas: Canvas,
    pub scales: Vec<(&'static str, f64)>,
}

impl Figure {
    /// Width and height with the caption, mm.
    pub fn size(&self) -> (f64, f64) {
        let b = self.canvas.bounds();
        let cw = self
            .caption
            .iter()
            .map(|c| {
                super::canvas::runs_width(
                    &crate::words::notation::runs(c),
                    CAPTION_FONT * super::canvas::lettering(),
                )
            })
            .fold(0.0, f64::max);
        (
            b.width().max(cw),
            b.height() + caption_line() * self.caption.len() as f64 + 2.0,
        )
    }
}

/// Write the placed figures on `page`, each a group `fig-<id>`: its
/// caption lines centred over it, the drawing under them.
pub(super) fn place(page: &mut Page, placed: &[(Figure, Point)]) {
    for (f, at) in placed {
        let (fw, _) = f.size();
        let b = f.canvas.bounds();
        page.push(&format!("<g class=\"figure\" id=\"fig-{}\">\n", f.id));
        let mut cap = Canvas::default();
        for (i, t) in f.caption.iter().enumerate() {
            cap.rich(
                Point::new(fw / 2.0, -caption_line() * (i as f64 + 1.0) + 1.5),
                t,
                CAPTION_FONT,
                "caption",
                "middle",
            );
        }
        page.write_canvas(&cap, at.x, at.y);
        // The drawing under its caption, centred across the figure's width.
        let top = at.y + caption_line() * f.caption.len() as f64 + 2.0;
        let ox = at.x + (fw - b.width()) / 2.0 - b.x0;
        page.write_canvas(&f.canvas, ox, top + b.y1);
        page.push("</g>\n");
    }
}

/// The field of the course sheet: inside the frame, with no heading band
/// (the sheet's name is in the title block).
pub(super) fn field_of(size: SheetSize) -> Rect {
    let f = sheet::frame(size);
    f.inset(-sheet::PAD)
}

/// Three significant digits, as a table of a course project gives them.
pub(super) fn round3(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}

/// Place rectangles `sizes` (w × h, mm) in `field` (page coordinates,
/// y down) clear of `block`, largest first, each where its bottom stays
/// highest and then leftmost (a skyline packer): their top left corners,
/// or `None` when one does not fit.
pub fn pack(sizes: &[(f64, f64)], field: Rect, block: Rect) -> Option<Vec<Point>> {
    // Largest first, by area, by height, by width: the first order that
    // packs.
    // Of those that pack, the one whose figures end highest: it leaves the
    // most room to grow.
    let keys: [fn((f64, f64)) -> f64; 3] = [|(w, h)| w * h, |(_, h)| h, |(w, _)| w];
    keys.iter()
        .filter_map(|key| {
            let mut order: Vec<usize> = (0..sizes.len()).collect();
            order.sort_by(|&a, &b| key(sizes[b]).total_cmp(&key(sizes[a])));
            let at = pack_in_order(sizes, &order, field, block)?;
            let bottom = at
                .iter()
                .zip(sizes)
                .map(|(p, (_, h))| p.y + h)
                .fold(f64::MIN, f64::max);
            Some((bottom, at))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, at)| at)
}

/// [`pack`] in one order.
fn pack_in_order(
    sizes: &[(f64, f64)],
    order: &[usize],
    field: Rect,
    block: Rect,
) -> Option<Vec<Point>> {
    // The skyline: x-intervals with the depth filled so far.
    let mut sky: Vec<(f64, f64, f64)> = vec![(field.x0, field.x1, field.y0)];
    let mut placed: Vec<Rect> = Vec::new();
    let mut out = vec![Point::ZERO; sizes.len()];
    let block = block.inset(GAP / 2.0);
    for &i in order {
        let (w, h) = (sizes[i].0 + GAP, sizes[i].1 + GAP);
        let mut xs: Vec<f64> = sky.iter().map(|s| s.0).collect();
        xs.extend(sky.iter().map(|s| s.1 - w));
        xs.push(field.x1 - w);
        xs.push(block.x0 - w);
        let mut best: Option<(f64, f64, f64)> = None;
        for x in xs {
            if x < field.x0 - 1e-9 || x + w > field.x1 + 1e-9 {
                continue;
            }
            let y = sky
                .iter()
                .filter(|s| s.1 > x + 1e-9 && s.0 < x + w - 1e-9)
                .map(|s| s.2)
                .fold(field.y0, f64::max);
            let r = Rect::new(x, y, x + w, y + h);
            if r.y1 > field.y1 + 1e-9 || r.intersect(block).area() > 0.0 {
                continue;
            }
            if placed.iter().any(|p| p.intersect(r).area() > 1e-9) {
                continue;
            }
            if best.is_none_or(|(bx, by, _)| (y + h, x) < (by, bx)) {
                best = Some((x, y + h, y));
            }
        }
        let (x, _, y) = best?;
        let r = Rect::new(x, y, x + w, y + h);
        placed.push(r);
        out[i] = Point::new(x + GAP / 2.0, y + GAP / 2.0);
        // Raise the skyline under the new rectangle.
        let mut next = Vec::new();
        for &(a, b, d) in &sky {
            if b <= r.x0 || a >= r.x1 {
                next.push((a, b, d));
                continue;
            }
            if a < r.x0 {
                next.push((a, r.x0, d));
            }
            if b > r.x1 {
                next.push((r.x1, b, d));
            }
        }
        next.push((r.x0, r.x1, r.y1));
        next.sort_by(|p, q| p.0.total_cmp(&q.0));
        sky = next;
    }
    Some(out)
}
