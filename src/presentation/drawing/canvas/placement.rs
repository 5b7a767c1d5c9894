//! The placing of labels and text on a [`Canvas`]: the grids that keep the
//! drawn segments and the placed labels' boxes in cells (so that asking
//! what meets a label's box looks at a few cells, and placement stays
//! linear in the size of the drawing), and the calls that place a label
//! at the nearest free place about its anchor (at once or once everything
//! else is drawn), free text and text in the lecture's notation.

use super::{Canvas, Label, Prim, runs_width};
use crate::words::notation::runs;
use kurbo::{Point, Rect, Vec2};

/// Segments (or label boxes) kept in cells of a grid, so that asking which
/// meet a small rectangle looks at a few cells, not at all of them: label
/// placement stays linear in the size of the drawing (a positions sheet
/// of 2 000 positions has some 100 000 segments).
#[derive(Default, Clone)]
pub struct Grid {
    items: Vec<(Point, Point)>,
    cells: std::collections::HashMap<(i64, i64), Vec<u32>>,
    /// Per item, the last query that met it (to count each once).
    stamp: std::cell::RefCell<(u32, Vec<u32>)>,
}

/// The side of a grid's cell, mm.
const CELL: f64 = 8.0;

fn cell_of(p: Point) -> (i64, i64) {
    ((p.x / CELL).floor() as i64, (p.y / CELL).floor() as i64)
}

impl Grid {
    /// Every item, in the order added.
    pub fn iter(&self) -> impl Iterator<Item = &(Point, Point)> {
        self.items.iter()
    }
    pub fn len(&self) -> usize {
        self.items.len()
    }
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }
    pub fn push(&mut self, seg: (Point, Point)) {
        let k = self.items.len() as u32;
        self.items.push(seg);
        let (a, b) = seg;
        // The cells along the segment, a half cell at a time.
        let n = ((b - a).hypot() / (0.5 * CELL)).ceil().max(1.0) as usize;
        let mut last = None;
        for i in 0..=n {
            let c = cell_of(a + (b - a) * (i as f64 / n as f64));
            // Crossing a corner diagonally can skip a cell: add the
            // neighbours along the way too.
            for d in [(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1)] {
                let cc = (c.0 + d.0, c.1 + d.1);
                if last != Some(cc) {
                    let v = self.cells.entry(cc).or_default();
                    if v.last() != Some(&k) {
                        v.push(k);
                    }
                }
            }
            last = Some(c);
        }
    }
    /// A rectangle (a label's box), kept as its two corners in every cell
    /// it covers.
    pub fn push_rect(&mut self, r: Rect) {
        let k = self.items.len() as u32;
        self.items
            .push((Point::new(r.x0, r.y0), Point::new(r.x1, r.y1)));
        let (c0, c1) = (
            cell_of(Point::new(r.x0, r.y0)),
            cell_of(Point::new(r.x1, r.y1)),
        );
        for x in c0.0..=c1.0 {
            for y in c0.1..=c1.1 {
                self.cells.entry((x, y)).or_default().push(k);
            }
        }
    }
    /// How many items meet `test` among those near `r`.
    pub fn count(&self, r: &Rect, test: impl Fn(&(Point, Point)) -> bool) -> usize {
        let mut st = self.stamp.borrow_mut();
        st.0 = st.0.wrapping_add(1);
        let q = st.0;
        if st.1.len() < self.items.len() {
            st.1.resize(self.items.len(), 0);
        }
        let (c0, c1) = (
            cell_of(Point::new(r.x0, r.y0)),
            cell_of(Point::new(r.x1, r.y1)),
        );
        let mut n = 0;
        for x in c0.0..=c1.0 {
            for y in c0.1..=c1.1 {
                let Some(v) = self.cells.get(&(x, y)) else {
                    continue;
                };
                for &k in v {
                    if st.1[k as usize] == q {
                        continue;
                    }
                    st.1[k as usize] = q;
                    if test(&self.items[k as usize]) {
                        n += 1;
                    }
                }
            }
        }
        n
    }
}

fn seg_hits_rect(a: Point, b: Point, r: &Rect) -> bool {
    // Liang–Barsky clipping: does the segment enter the rectangle?
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let d = b - a;
    for (p, q) in [
        (-d.x, a.x - r.x0),
        (d.x, r.x1 - a.x),
        (-d.y, a.y - r.y0),
        (d.y, r.y1 - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

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
        });
    }
}
