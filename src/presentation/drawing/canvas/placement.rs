//! The placing of labels and text on a [`Canvas`] (its segments and the
//! placed labels' boxes kept in `grid`s), the calls that place a label
//! at the nearest free place about its anchor (at once or once everything
//! else is drawn), free text and text in the lecture's notation.

use super::grid::seg_hits_rect;
use super::label::{Label, runs_width};
use super::primitives::{Canvas, Prim};
use crate::words::notation::runs;
use kurbo::{Point, Rect, Vec2};

impl Canvas {
    /// A label to place after everything else is drawn ([`Canvas::place_pending`]).
    pub fn label_later(&mut self, anchor: Point, label: Label, size: f64, id: Option<String>) {
        self.pending.push((anchor, label, size, id));
    }

    pub fn place_pending(&mut self) {
        for (a, l, s, id) in std::mem::take(&mut self.pending) {
            self.label(a, l, s, id);
        }
    }

    /// Place `label` near `anchor`: the nearest of the candidate places
    /// (16 directions on rings 1–9 mm away) whose box meets no placed label
    /// and no avoided segment; failing that, the one that meets no label
    /// and the fewest segments; and keep its box.
    pub fn label(&mut self, anchor: Point, label: Label, size: f64, id: Option<String>) {
        let size = size * lettering();
        // The box runs from the subscript's bottom (0.35 em below the
        // baseline) to the capitals' top (0.97 em above, as DejaVu renders).
        let (w, h) = (label.width(size), size * 1.32 + label.rise(size));
        // A bare number (a link's, a position's) stands apart from other
        // labels, so that "S₄ 4" does not read as one label, nor "2 7" as
        // a number: 1.2 mm clear, where labels otherwise keep 0.3 mm.
        let gap = if label.is_number() { 1.2 } else { 0.3 };
        let mut best: Option<((usize, usize, usize), Rect)> = None;
        'rings: for ring in [1.0, 2.0, 3.2, 4.6, 6.5, 9.0, 12.0, 16.0] {
            for k in 0..16 {
                let ang =
                    std::f64::consts::FRAC_PI_8 * k as f64 + std::f64::consts::FRAC_PI_8 / 2.0;
                let d = Vec2::from_angle(ang) * ring;
                // The box sits on the side of the anchor the direction points to.
                let x0 = anchor.x + d.x + if d.x < 0.0 { -w } else { 0.0 };
                let y0 = anchor.y + d.y + if d.y < 0.0 { -h } else { 0.0 };
                let r = Rect::new(x0, y0, x0 + w, y0 + h);
                let (r3, r2) = (r.inflate(0.3, 0.3), r.inflate(0.2, 0.2));
                let rl = r.inflate(gap, gap);
                let labels = self.boxes.count(&rl, |(a, b)| {
                    Rect::from_points(*a, *b).intersect(rl).area() > 0.0
                });
                let lines = self.avoid.count(&r3, |(a, b)| seg_hits_rect(*a, *b, &r3));
                let thin = self
                    .avoid_thin
                    .count(&r2, |(a, b)| seg_hits_rect(*a, *b, &r2));
                let score = (labels, lines, thin);
                if best.as_ref().is_none_or(|(s0, _)| score < *s0) {
                    best = Some((score, r));
                }
                if score == (0, 0, 0) {
                    break 'rings;
                }
            }
        }
        let (_, r) = best.expect("candidates exist");
        // A bare number keeps its room for labels placed after it too.
        self.boxes.push_rect(r.inflate(gap - 0.3, gap - 0.3));
        self.prims.push(Prim::Text {
            // The baseline sits 0.35 em above the box's bottom.
            at: Point::new(r.x0, r.y0 + 0.35 * size),
            label,
            size,
            id,
            class: "label",
        });
    }

    /// Free text (titles, scales) with its lower-left corner at `at`.
    pub fn text(&mut self, at: Point, label: Label, size: f64, class: &'static str) {
        let size = size * lettering();
        let r = Rect::new(
            at.x,
            at.y - 0.35 * size,
            at.x + label.width(size),
            at.y + size * 0.8,
        );
        self.boxes.push_rect(r);
        self.prims.push(Prim::Text {
            at,
            label,
            size,
            id: None,
            class,
        });
    }

    /// Text in the lecture's notation ([`runs`]) at `at` (the baseline's
    /// start, middle or end by `anchor`); its box keeps labels off.
    pub fn rich(
        &mut self,
        at: Point,
        text: &str,
        size: f64,
        class: &'static str,
        anchor: &'static str,
    ) {
        let size = size * lettering();
        let rs = runs(text);
        let w = runs_width(&rs, size);
        let x0 = match anchor {
            "middle" => at.x - w / 2.0,
            "end" => at.x - w,
            _ => at.x,
        };
        self.boxes
            .push_rect(Rect::new(x0, at.y - 0.35 * size, x0 + w, at.y + size * 0.8));
        self.prims.push(Prim::Rich {
            at,
            runs: rs,
            size,
            class,
            anchor,
            id: None,
        });
    }

    /// [`Canvas::rich`] with an id the checks read it by.
    pub fn rich_id(
        &mut self,
        at: Point,
        text: &str,
        size: f64,
        (class, anchor): (&'static str, &'static str),
        id: String,
    ) {
        self.rich(at, text, size, class, anchor);
        if let Some(Prim::Rich { id: slot, .. }) = self.prims.last_mut() {
            *slot = Some(id);
        }
    }
}

thread_local! {
    /// The factor on every text size of the canvases drawn now
    /// ([`with_lettering`]).
    static LETTERING: std::cell::Cell<f64> = const { std::cell::Cell::new(1.0) };
}

/// The factor on text sizes in force on this thread (1 but within
/// [`with_lettering`]).
pub fn lettering() -> f64 {
    LETTERING.with(|k| k.get())
}

/// Run `f` with every text drawn on a canvas (labels, text, rich text) `k`
/// times its size: a sheet whose lettering the standard sets larger (the
/// A1 course sheets, ГОСТ 2.304) drawn by the same figure code, its labels
/// placed at their final size. Restored afterwards, also on an error.
pub fn with_lettering<T>(k: f64, f: impl FnOnce() -> T) -> T {
    struct Restore(f64);
    impl Drop for Restore {
        fn drop(&mut self) {
            LETTERING.with(|c| c.set(self.0));
        }
    }
    let _restore = Restore(LETTERING.with(|c| c.replace(k)));
    f()
}

