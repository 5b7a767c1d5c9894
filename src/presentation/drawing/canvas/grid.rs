//! Segments (or label boxes) kept in the cells of a grid, so that asking
//! what meets a label's box looks at a few cells and label placement
//! stays linear in the size of the drawing.

use kurbo::{Point, Rect};

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

pub(super) fn seg_hits_rect(a: Point, b: Point, r: &Rect) -> bool {
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

