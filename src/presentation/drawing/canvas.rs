//! A drawing sheet in millimetres: primitives collected in drawing
//! coordinates (y up, as the plans are computed), labels placed so that they
//! overlap neither each other nor the drawn lines, then written as SVG with
//! one number formatter so the output is byte-stable.

use crate::presentation::notation::{Pos, Run, runs};
use kurbo::{Point, Rect, Vec2};
use std::fmt::Write as _;

/// Line weights after ГОСТ 2.303: main lines S, thin lines S/2.
pub const MAIN: f64 = 0.5;
pub const THIN: f64 = 0.25;
/// A result read off a plan: 1.6 S (ГОСТ 2.303 allows S up to 1.4 mm).
pub const BOLD: f64 = 0.8;
/// Font sizes after ГОСТ 2.304 (mm).
pub const FONT: f64 = 3.5;
pub const SMALL: f64 = 2.5;

/// Numbers as 0.01 mm, no trailing zeros, no "-0": byte-stable output.
pub fn fmt(x: f64) -> String {
    let r = (x * 100.0).round() / 100.0;
    let s = format!("{r:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Advance width of a glyph of DejaVu Sans in em, a little generous.
fn char_width(c: char) -> f64 {
    match c {
        'm' | 'w' | 'M' | 'W' | 'ω' | 'Ω' | '—' => 1.0,
        'i' | 'l' | 'j' | '.' | ',' | ':' | ';' | '\'' | '|' => 0.36,
        'f' | 't' | 'r' | ' ' | '(' | ')' | '/' => 0.46,
        c if c.is_uppercase() => 0.8,
        _ => 0.66,
    }
}

/// Estimated width in mm of runs of text at font size `size`: a
/// superscript and the subscript right after it stand one above the
/// other, so the wider of the two counts.
pub fn runs_width(rs: &[Run], size: f64) -> f64 {
    let w = |s: &str| s.chars().map(char_width).sum::<f64>();
    let mut total = 0.0;
    let mut i = 0;
    while i < rs.len() {
        let (p, t) = &rs[i];
        match p {
            Pos::Base => total += size * w(t),
            Pos::Sub => total += 0.7 * size * w(t),
            Pos::Sup => {
                let mut x = 0.7 * size * w(t);
                if let Some((Pos::Sub, u)) = rs.get(i + 1) {
                    x = x.max(0.7 * size * w(u));
                    i += 1;
                }
                total += x;
            }
        }
        i += 1;
    }
    total
}

/// How far a subscript sinks and a superscript rises, in font sizes:
/// apart enough that a superscript stands clear above the subscript under
/// it (a^k over B3B2).
const SUB_SHIFT: f64 = 0.24;
const SUP_SHIFT: f64 = 0.48;

/// Runs of text as SVG tspans: a subscript right after a superscript
/// moves back under it, and what follows starts after the wider of them.
fn runs_svg(rs: &[Run], size: f64) -> String {
    let small = 0.7 * size;
    let w = |s: &str| small * s.chars().map(char_width).sum::<f64>();
    let mut out = String::new();
    let mut pending_dx = 0.0;
    let mut i = 0;
    while i < rs.len() {
        let (p, t) = &rs[i];
        let dx = if pending_dx > 0.0 {
            format!(r#" dx="{}""#, fmt(pending_dx))
        } else {
            String::new()
        };
        pending_dx = 0.0;
        match p {
            Pos::Base => {
                let _ = write!(out, "<tspan{dx}>{}</tspan>", xml(t));
            }
            Pos::Sub => {
                let _ = write!(
                    out,
                    r#"<tspan{dx} baseline-shift="{}" font-size="{}">{}</tspan>"#,
                    fmt(-SUB_SHIFT * size),
                    fmt(small),
                    xml(t)
                );
            }
            Pos::Sup => {
                let _ = write!(
                    out,
                    r#"<tspan{dx} baseline-shift="{}" font-size="{}">{}</tspan>"#,
                    fmt(SUP_SHIFT * size),
                    fmt(small),
                    xml(t)
                );
                if let Some((Pos::Sub, u)) = rs.get(i + 1) {
                    let (ws, wu) = (w(t), w(u));
                    let _ = write!(
                        out,
                        r#"<tspan dx="{}" baseline-shift="{}" font-size="{}">{}</tspan>"#,
                        fmt(-ws),
                        fmt(-SUB_SHIFT * size),
                        fmt(small),
                        xml(u)
                    );
                    pending_dx = (ws - wu).max(0.0);
                    i += 1;
                }
            }
        }
        i += 1;
    }
    out
}

/// The length of an arrowhead (mm), ГОСТ-like 3 mm on a plan.
pub const HEAD: f64 = 3.0;
/// Half the width of an arrowhead as a share of its length.
const ARROW_WIDTH: f64 = 0.7 / 3.0;

/// What a drawn segment is, for its weight and for the checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// A link, a guide, an absolute vector: main line.
    Main,
    /// A relative vector or a laid-off component: main line too.
    Vector,
    /// A result read off a plan (a reaction on a force polygon): a line
    /// thicker than the main one, as the course marks what was found.
    Bold,
    /// A construction line, a dimension: thin line.
    Thin,
    /// The hatching of a fixed base or guide: thin line, told apart so
    /// that the layout checks can keep symbols off it.
    Hatch,
}

/// Line types after ГОСТ 2.303, for the lines drawn as paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Line {
    /// Solid main line (S): links in the main position.
    Main,
    /// Solid thin line (S/2): the mechanism in its other positions.
    Thin,
    /// Dashed thin line (штриховая): construction lines of the plans.
    Dashed,
    /// Thin dash-dot line (штрихпунктирная тонкая): axes, centre lines,
    /// trajectories of points.
    DashDot,
    /// Thin dash-dot-dot line (штрихпунктирная с двумя точками): extreme
    /// positions of moving links.
    DashDotDot,
}

impl Line {
    fn width(self) -> f64 {
        if self == Line::Main { MAIN } else { THIN }
    }
    /// The CSS class of the SVG element, for the checks.
    fn class(self) -> &'static str {
        match self {
            Line::Main => "main",
            Line::Thin => "thin",
            Line::Dashed => "dashed",
            Line::DashDot => "dash-dot",
            Line::DashDotDot => "dash-dot-dot",
        }
    }
    /// The pattern (mm): a dash first, then gaps and dots, within the
    /// ranges ГОСТ 2.303 gives (dash 2–8 and gap 1–2 for a dashed line,
    /// dash 5–30 and gap 3–5 (4–6) for dash-dot (dash-dot-dot) lines).
    fn pattern(self) -> &'static [f64] {
        match self {
            Line::Main | Line::Thin => &[],
            Line::Dashed => &[4.0, 1.5],
            Line::DashDot => &[12.0, 1.5, 0.6, 1.5],
            Line::DashDotDot => &[12.0, 1.5, 0.6, 1.2, 0.6, 1.5],
        }
    }
    /// The dash array for a line of length `len`, stretched or shrunk (by
    /// at most a third of a period) so that the line begins and ends with
    /// a dash, as ГОСТ 2.303 asks; empty for a solid line. A line shorter
    /// than one dash and period is drawn solid (a short centre line is
    /// drawn solid thin).
    pub fn dash_array(self, len: f64) -> Vec<f64> {
        let pat = self.pattern();
        if pat.is_empty() {
            return Vec::new();
        }
        let period: f64 = pat.iter().sum();
        let n = ((len - pat[0]) / period).round();
        if n < 1.0 {
            return Vec::new();
        }
        let k = len / (n * period + pat[0]);
        pat.iter().map(|x| x * k).collect()
    }
}

/// A label: letters and a subscript.
#[derive(Clone, Debug)]
pub struct Label {
    pub base: String,
    pub sub: String,
    /// A superscript over the subscript (R^τ_12: the component of a
    /// reaction); empty on most labels.
    pub sup: String,
    /// Plain text after the subscript.
    pub tail: String,
    /// Further names sharing the label, each with its subscript
    /// (", o₁, o₂").
    pub more: Vec<(String, String)>,
}

impl Label {
    /// A bare number: a link's or a position's.
    fn is_number(&self) -> bool {
        !self.base.is_empty()
            && self.base.chars().all(|c| c.is_ascii_digit())
            && self.sub.is_empty()
            && self.sup.is_empty()
            && self.tail.is_empty()
            && self.more.is_empty()
    }

    pub fn new(base: impl Into<String>, sub: impl Into<String>) -> Label {
        Label {
            base: base.into(),
            sub: sub.into(),
            sup: String::new(),
            tail: String::new(),
            more: Vec::new(),
        }
    }
    /// Another name at the same place: "p_v, o₁".
    pub fn and(mut self, base: impl Into<String>, sub: impl Into<String>) -> Label {
        self.more.push((base.into(), sub.into()));
        self
    }
    /// The superscript stacked over the subscript: R^τ_12.
    pub fn with_sup(mut self, sup: impl Into<String>) -> Label {
        self.sup = sup.into();
        self
    }
    pub fn with_tail(mut self, tail: impl Into<String>) -> Label {
        self.tail = tail.into();
        self
    }
    /// How much higher than a plain label's its box reaches (mm): a
    /// superscript stands above the capitals.
    pub fn rise(&self, size: f64) -> f64 {
        if self.sup.is_empty() {
            0.0
        } else {
            0.55 * size
        }
    }
    /// Estimated width in mm at font size `size` (DejaVu Sans: ~0.6 em).
    pub fn width(&self, size: f64) -> f64 {
        let w = |s: &str| s.chars().map(char_width).sum::<f64>();
        let more: f64 = self
            .more
            .iter()
            .map(|(b, s)| size * (w(", ") + w(b)) + 0.7 * size * w(s))
            .sum();
        size * (w(&self.base) + w(&self.tail)) + 0.7 * size * w(&self.sub).max(w(&self.sup)) + more
    }
}

#[derive(Clone, Debug)]
pub enum Prim {
    Seg {
        a: Point,
        b: Point,
        class: Class,
        id: Option<String>,
    },
    Poly {
        pts: Vec<Point>,
        fill: &'static str,
        stroke: f64,
    },
    Circle {
        c: Point,
        r: f64,
        fill: &'static str,
        stroke: f64,
        id: Option<String>,
    },
    /// An open polyline of one line type: a trajectory, a position of
    /// the mechanism, an axis (one element however many its vertices).
    Path { pts: Vec<Point>, line: Line },
    /// A filled arrowhead with its tip at `tip`, pointing along `dir`, as
    /// long as `dir` (shorter than [`HEAD`] on a short vector).
    Arrow { tip: Point, dir: Vec2 },
    /// A circular arc about `c` of radius `r` from angle `a0` swept by `sweep` (rad, CCW positive).
    Arc {
        c: Point,
        r: f64,
        a0: f64,
        sweep: f64,
    },
    /// Text in the lecture's notation (subscripts, superscripts) with its
    /// baseline's left end at `at`; `anchor` "start", "middle" or "end".
    Rich {
        at: Point,
        runs: Vec<Run>,
        size: f64,
        class: &'static str,
        anchor: &'static str,
    },
    /// Text whose box's lower-left corner is `at` (drawing coordinates).
    Text {
        at: Point,
        label: Label,
        size: f64,
        id: Option<String>,
        class: &'static str,
    },
}

impl Prim {
    /// The primitive with every place `q` it is drawn at moved to `p(q)`;
    /// its sizes (radii, arrowheads, text) as they are.
    fn placed(self, p: impl Fn(Point) -> Point) -> Prim {
        match self {
            Prim::Seg { a, b, class, id } => Prim::Seg {
                a: p(a),
                b: p(b),
                class,
                id,
            },
            Prim::Poly { pts, fill, stroke } => Prim::Poly {
                pts: pts.into_iter().map(&p).collect(),
                fill,
                stroke,
            },
            Prim::Path { pts, line } => Prim::Path {
                pts: pts.into_iter().map(&p).collect(),
                line,
            },
            Prim::Circle {
                c,
                r,
                fill,
                stroke,
                id,
            } => Prim::Circle {
                c: p(c),
                r,
                fill,
                stroke,
                id,
            },
            Prim::Arrow { tip, dir } => Prim::Arrow { tip: p(tip), dir },
            Prim::Arc { c, r, a0, sweep } => Prim::Arc {
                c: p(c),
                r,
                a0,
                sweep,
            },
            Prim::Rich {
                at,
                runs,
                size,
                class,
                anchor,
            } => Prim::Rich {
                at: p(at),
                runs,
                size,
                class,
                anchor,
            },
            Prim::Text {
                at,
                label,
                size,
                id,
                class,
            } => Prim::Text {
                at: p(at),
                label,
                size,
                id,
                class,
            },
        }
    }
}

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

/// The sheet: what is drawn, the boxes of the placed labels (drawing
/// coordinates) and the segments labels must avoid.
#[derive(Default, Clone)]
pub struct Canvas {
    pub prims: Vec<Prim>,
    /// The placed labels' boxes, as their two corners.
    pub boxes: Grid,
    /// Main lines, outlines of symbols, arrowheads: labels keep off them.
    pub avoid: Grid,
    /// Thin lines (hatching, construction lines): labels keep off them
    /// where they can.
    pub avoid_thin: Grid,
    /// Labels waiting to be placed once everything else is drawn.
    pub pending: Vec<(Point, Label, f64, Option<String>)>,
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
    pub fn seg(&mut self, a: Point, b: Point, class: Class) {
        self.prims.push(Prim::Seg {
            a,
            b,
            class,
            id: None,
        });
        if !matches!(class, Class::Thin | Class::Hatch) {
            self.avoid.push((a, b));
        } else {
            self.avoid_thin.push((a, b));
        }
    }

    /// An open polyline of line type `line`; labels keep off it (off a
    /// thin one where they can).
    pub fn path(&mut self, pts: Vec<Point>, line: Line) {
        if pts.len() < 2 {
            return;
        }
        let grid = if line == Line::Main {
            &mut self.avoid
        } else {
            &mut self.avoid_thin
        };
        for w in pts.windows(2) {
            grid.push((w[0], w[1]));
        }
        self.prims.push(Prim::Path { pts, line });
    }

    /// A filled polygon; its outline is kept clear of labels.
    pub fn poly(&mut self, pts: Vec<Point>, fill: &'static str, stroke: f64) {
        for i in 0..pts.len() {
            self.avoid.push((pts[i], pts[(i + 1) % pts.len()]));
        }
        self.prims.push(Prim::Poly { pts, fill, stroke });
    }

    /// A label to place after everything else is drawn ([`Canvas::place_pending`]).
    pub fn label_later(&mut self, anchor: Point, label: Label, size: f64, id: Option<String>) {
        self.pending.push((anchor, label, size, id));
    }

    pub fn place_pending(&mut self) {
        for (a, l, s, id) in std::mem::take(&mut self.pending) {
            self.label(a, l, s, id);
        }
    }

    /// A vector with its arrowhead at `b`.
    pub fn vector(&mut self, a: Point, b: Point, class: Class, id: Option<String>) {
        if (b - a).hypot() < 1e-6 {
            return;
        }
        self.prims.push(Prim::Seg { a, b, class, id });
        self.avoid.push((a, b));
        // A head no longer than 0.4 of its vector: a short vector keeps its
        // line visible instead of becoming a blob; a very short one (under
        // a millimetre) is a line and its end point's dot.
        let len = (b - a).hypot();
        let head = HEAD.min(0.4 * len);
        if head >= 0.4 {
            self.arrow_of(b, (b - a) / len * head);
        }
    }

    /// A thin circular arc (the input's ω1, ε1), kept clear of labels.
    pub fn arc(&mut self, c: Point, r: f64, a0: f64, sweep: f64) {
        let n = 12;
        let at = |k: usize| c + Vec2::from_angle(a0 + sweep * k as f64 / n as f64) * r;
        for k in 0..n {
            self.avoid_thin.push((at(k), at(k + 1)));
        }
        self.prims.push(Prim::Arc { c, r, a0, sweep });
    }

    /// An arrowhead of the usual size; its sides are kept clear of labels.
    pub fn arrow(&mut self, tip: Point, dir: Vec2) {
        self.arrow_of(tip, dir.normalize() * HEAD);
    }

    /// An arrowhead whose length is that of `dir`.
    fn arrow_of(&mut self, tip: Point, dir: Vec2) {
        let back = tip - dir;
        let n = Vec2::new(-dir.y, dir.x) * ARROW_WIDTH;
        self.avoid.push((tip, back + n));
        self.avoid.push((tip, back - n));
        self.prims.push(Prim::Arrow { tip, dir });
    }

    pub fn circle(&mut self, c: Point, r: f64, fill: &'static str, stroke: f64) {
        // Its bounding square keeps labels off the symbol.
        let q = [
            Vec2::new(-r, -r),
            Vec2::new(r, -r),
            Vec2::new(r, r),
            Vec2::new(-r, r),
        ];
        for i in 0..4 {
            self.avoid.push((c + q[i], c + q[(i + 1) % 4]));
        }
        self.prims.push(Prim::Circle {
            c,
            r,
            fill,
            stroke,
            id: None,
        });
    }

    /// A plan or mechanism point: a dot with an id the checks can find.
    pub fn dot(&mut self, c: Point, id: String) {
        self.prims.push(Prim::Circle {
            c,
            r: 0.5,
            fill: "black",
            stroke: 0.0,
            id: Some(id),
        });
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

    /// The drawing reduced (or enlarged) `k` times about the origin: its
    /// geometry only; text, arrowheads and symbols keep their size, as
    /// a reduced drawing keeps its lettering.
    pub fn scaled(&self, k: f64) -> Canvas {
        Canvas {
            prims: self
                .prims
                .iter()
                .map(|prim| prim.clone().placed(|q| Point::new(q.x * k, q.y * k)))
                .collect(),
            ..Canvas::default()
        }
    }

    /// Everything drawn on `other`, moved by (`dx`, `dy`), drawn here too
    /// (a figure of figures: the course sheet's grid of plans).
    pub fn append(&mut self, other: &Canvas, dx: f64, dy: f64) {
        let d = Vec2::new(dx, dy);
        self.prims.extend(
            other
                .prims
                .iter()
                .map(|prim| prim.clone().placed(|q| q + d)),
        );
    }

    /// Bounding box of everything drawn (drawing coordinates).
    pub fn bounds(&self) -> Rect {
        let mut r: Option<Rect> = None;
        let mut add = |p: Point, pad: f64| {
            let b = Rect::new(p.x - pad, p.y - pad, p.x + pad, p.y + pad);
            r = Some(r.map_or(b, |x| x.union(b)));
        };
        for p in &self.prims {
            match p {
                Prim::Seg { a, b, .. } => {
                    add(*a, 0.5);
                    add(*b, 0.5);
                }
                Prim::Poly { pts, .. } => pts.iter().for_each(|q| add(*q, 0.3)),
                Prim::Path { pts, .. } => pts.iter().for_each(|q| add(*q, 0.3)),
                Prim::Circle { c, r, .. } => add(*c, *r + 0.3),
                Prim::Arrow { tip, dir } => add(*tip, dir.hypot()),
                Prim::Arc { c, r, .. } => add(*c, *r + 1.5),
                Prim::Rich {
                    at,
                    runs,
                    size,
                    anchor,
                    ..
                } => {
                    let w = runs_width(runs, *size);
                    let x0 = match *anchor {
                        "middle" => at.x - w / 2.0,
                        "end" => at.x - w,
                        _ => at.x,
                    };
                    add(Point::new(x0, at.y - 0.35 * size), 0.2);
                    add(Point::new(x0 + w, at.y + size), 0.2);
                }
                Prim::Text {
                    at, label, size, ..
                } => {
                    add(*at, 0.2);
                    add(
                        Point::new(at.x + label.width(*size), at.y + size + label.rise(*size)),
                        0.2,
                    );
                }
            }
        }
        r.unwrap_or(Rect::ZERO)
    }

    /// Write the primitives as SVG elements, drawing coordinates mapped to
    /// the page by x ↦ ox + x, y ↦ oy − y.
    pub fn write(&self, out: &mut String, ox: f64, oy: f64) {
        let px = |p: Point| format!("{} {}", fmt(ox + p.x), fmt(oy - p.y));
        for p in &self.prims {
            match p {
                Prim::Seg { a, b, class, id } => {
                    let w = match class {
                        Class::Thin | Class::Hatch => THIN,
                        Class::Bold => BOLD,
                        Class::Main | Class::Vector => MAIN,
                    };
                    let cls = match class {
                        Class::Main => "main",
                        Class::Vector => "vector",
                        Class::Thin => "thin",
                        Class::Hatch => "hatch",
                        Class::Bold => "bold",
                    };
                    // A student's marks (check --svg) in red.
                    let color = if id.as_deref().is_some_and(|i| i.starts_with("student-")) {
                        "#c00000"
                    } else {
                        "black"
                    };
                    let id = id_attr(id);
                    let _ = writeln!(
                        out,
                        r#"<line class="{cls}"{id} x1="{}" y1="{}" x2="{}" y2="{}" stroke="{color}" stroke-width="{}" stroke-linecap="round"/>"#,
                        fmt(ox + a.x),
                        fmt(oy - a.y),
                        fmt(ox + b.x),
                        fmt(oy - b.y),
                        fmt(w)
                    );
                }
                Prim::Poly { pts, fill, stroke } => {
                    let d: Vec<String> = pts.iter().map(|q| px(*q)).collect();
                    let stroke = stroke_attr(*stroke);
                    let _ = writeln!(
                        out,
                        r#"<polygon points="{}" fill="{fill}"{stroke}/>"#,
                        d.join(" ")
                    );
                }
                Prim::Circle {
                    c,
                    r,
                    fill,
                    stroke,
                    id,
                } => {
                    let id = id_attr(id);
                    let stroke = stroke_attr(*stroke);
                    let _ = writeln!(
                        out,
                        r#"<circle{id} cx="{}" cy="{}" r="{}" fill="{fill}"{stroke}/>"#,
                        fmt(ox + c.x),
                        fmt(oy - c.y),
                        fmt(*r)
                    );
                }
                Prim::Path { pts, line } => {
                    let mut d = String::new();
                    for (i, q) in pts.iter().enumerate() {
                        d += if i == 0 { "M" } else { " L" };
                        d += &px(*q);
                    }
                    let len: f64 = pts.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
                    let dash = line.dash_array(len);
                    let dash = if dash.is_empty() {
                        String::new()
                    } else {
                        let v: Vec<String> = dash.iter().map(|x| fmt(*x)).collect();
                        format!(r#" stroke-dasharray="{}""#, v.join(" "))
                    };
                    let _ = writeln!(
                        out,
                        r#"<path class="{}" d="{d}" fill="none" stroke="black" stroke-width="{}"{dash} stroke-linejoin="round"/>"#,
                        line.class(),
                        fmt(line.width())
                    );
                }
                Prim::Arrow { tip, dir } => {
                    let back = *tip - *dir;
                    let n = Vec2::new(-dir.y, dir.x) * ARROW_WIDTH;
                    let _ = writeln!(
                        out,
                        r#"<polygon class="arrow" points="{} {} {}" fill="black"/>"#,
                        px(*tip),
                        px(back + n),
                        px(back - n)
                    );
                }
                Prim::Arc { c, r, a0, sweep } => {
                    let p0 = *c + Vec2::from_angle(*a0) * *r;
                    let p1 = *c + Vec2::from_angle(a0 + sweep) * *r;
                    // In page coordinates y is flipped: a CCW sweep is sweep-flag 0.
                    let large = if sweep.abs() > std::f64::consts::PI {
                        1
                    } else {
                        0
                    };
                    let flag = if *sweep > 0.0 { 0 } else { 1 };
                    let _ = writeln!(
                        out,
                        r#"<path class="arc" d="M{} A{} {} 0 {large} {flag} {}" fill="none" stroke="black" stroke-width="{}"/>"#,
                        px(p0),
                        fmt(*r),
                        fmt(*r),
                        px(p1),
                        fmt(THIN)
                    );
                }
                Prim::Rich {
                    at,
                    runs,
                    size,
                    class,
                    anchor,
                } => {
                    let anchor = if *anchor == "start" {
                        String::new()
                    } else {
                        format!(r#" text-anchor="{anchor}""#)
                    };
                    let _ = writeln!(
                        out,
                        r#"<text class="{class}" x="{}" y="{}" font-size="{}"{anchor}>{}</text>"#,
                        fmt(ox + at.x),
                        fmt(oy - at.y),
                        fmt(*size),
                        runs_svg(runs, *size)
                    );
                }
                Prim::Text {
                    at,
                    label,
                    size,
                    id,
                    class,
                } => {
                    let id = id_attr(id);
                    // A subscript, when there is one.
                    let sub = |s: &str| {
                        if s.is_empty() {
                            String::new()
                        } else {
                            format!(
                                r#"<tspan baseline-shift="sub" font-size="{}">{}</tspan>"#,
                                fmt(size * 0.7),
                                xml(s)
                            )
                        }
                    };
                    let more: String = label
                        .more
                        .iter()
                        .map(|(b, s)| format!("<tspan>, {}</tspan>{}", xml(b), sub(s)))
                        .collect();
                    // A superscript stacks over the subscript, as the
                    // lecture's runs do (R^τ_12); else the base as it is.
                    let (base, sub) = if label.sup.is_empty() {
                        (xml(&label.base), sub(&label.sub))
                    } else {
                        let rs = vec![
                            (Pos::Base, label.base.clone()),
                            (Pos::Sup, label.sup.clone()),
                            (Pos::Sub, label.sub.clone()),
                        ];
                        (runs_svg(&rs, *size), String::new())
                    };
                    let tail = if label.tail.is_empty() {
                        String::new()
                    } else {
                        format!("<tspan>{}</tspan>", xml(&label.tail))
                    };
                    let fill = if *class == "student" {
                        r##" fill="#c00000""##
                    } else {
                        ""
                    };
                    let _ = writeln!(
                        out,
                        r#"<text class="{class}"{id} x="{}" y="{}" font-size="{}"{fill}>{}{sub}{more}{tail}</text>"#,
                        fmt(ox + at.x),
                        fmt(oy - at.y),
                        fmt(*size),
                        base
                    );
                }
            }
        }
    }
}

/// ` id="…"` of an element that has an id, else nothing.
fn id_attr(id: &Option<String>) -> String {
    id.as_ref()
        .map(|i| format!(r#" id="{i}""#))
        .unwrap_or_default()
}

/// ` stroke="black" stroke-width="…"` of an outlined shape, else nothing.
fn stroke_attr(stroke: f64) -> String {
    if stroke > 0.0 {
        format!(r#" stroke="black" stroke-width="{}""#, fmt(stroke))
    } else {
        String::new()
    }
}

pub fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
