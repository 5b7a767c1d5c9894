//! The sheet ([`Canvas`]), its primitives ([`Prim`]), the classes and
//! line types of ГОСТ 2.303 and the drawing calls.

use super::grid::Grid;
use super::label::{Label, runs_width};
use crate::words::notation::Run;
use kurbo::{Point, Rect, Vec2};

/// Line weights after ГОСТ 2.303: main lines S, thin lines S/2.
pub const MAIN: f64 = 0.5;
pub const THIN: f64 = 0.25;
/// A result read off a plan: 1.6 S (ГОСТ 2.303 allows S up to 1.4 mm).
pub const BOLD: f64 = 0.8;
/// Font sizes after ГОСТ 2.304 (mm).
pub const FONT: f64 = 3.5;
pub const SMALL: f64 = 2.5;

/// The length of an arrowhead (mm), ГОСТ-like 3 mm on a plan.
pub const HEAD: f64 = 3.0;
/// Half the width of an arrowhead as a share of its length.
pub(super) const ARROW_WIDTH: f64 = 0.7 / 3.0;

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
    pub(super) fn width(self) -> f64 {
        if self == Line::Main { MAIN } else { THIN }
    }
    /// The CSS class of the SVG element, for the checks.
    pub(super) fn class(self) -> &'static str {
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
        id: Option<String>,
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
        id: Option<String>,
    },
    /// Text whose box's lower-left corner is `at` (drawing coordinates).
    Text {
        at: Point,
        label: Label,
        size: f64,
        id: Option<String>,
        class: &'static str,
    },
    /// The start of a symbol drawn as one object (a joint, a fixed pivot,
    /// a slider block, a centre of mass), whose primitives follow up to
    /// [`Prim::End`]: `kind` names it, `at` is its base point and `angle`
    /// (rad, counter-clockwise) its turn from its upright drawing. The SVG
    /// groups it (`<g data-symbol=…>`), the DXF makes it a block.
    Symbol {
        kind: &'static str,
        at: Point,
        angle: f64,
    },
    /// The start of a group of primitives up to [`Prim::End`] (a check's
    /// overlay: the right plan, the student's marks, the wrong step):
    /// `class` names it, `opacity` pales it (1: as drawn), and what would
    /// be drawn black in it is drawn in `ink`.
    Group {
        class: &'static str,
        opacity: f64,
        ink: &'static str,
        /// Its id, where the checks find it by one.
        id: Option<String>,
    },
    /// The end of a symbol or a group.
    End,
    /// A region of the sheet, not drawn: a box the checks read (a force
    /// polygon's box in its panel), `<g id=… data-box="x0 y0 x1 y1"/>` in
    /// page coordinates.
    Region { rect: Rect, id: String },
}

impl Prim {
    /// The primitive with every place `q` it is drawn at moved to `p(q)`;
    /// its sizes (radii, arrowheads, text) as they are.
    fn placed(mut self, p: impl Fn(Point) -> Point) -> Prim {
        match &mut self {
            Prim::Seg { a, b, .. } => {
                *a = p(*a);
                *b = p(*b);
            }
            Prim::Poly { pts, .. } | Prim::Path { pts, .. } => {
                for q in pts.iter_mut() {
                    *q = p(*q);
                }
            }
            Prim::Circle { c, .. } | Prim::Arc { c, .. } => *c = p(*c),
            Prim::Arrow { tip, .. } => *tip = p(*tip),
            Prim::Rich { at, .. } | Prim::Text { at, .. } | Prim::Symbol { at, .. } => {
                *at = p(*at)
            }
            Prim::Region { rect, .. } => {
                let (a, b) = (p(Point::new(rect.x0, rect.y0)), p(Point::new(rect.x1, rect.y1)));
                *rect = Rect::from_points(a, b);
            }
            Prim::Group { .. } | Prim::End => {}
        }
        self
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
        self.prims.push(Prim::Poly {
            pts,
            fill,
            stroke,
            id: None,
        });
    }

    /// [`Canvas::poly`] with an id the checks can find it by (a slider's
    /// block on a free body).
    pub fn poly_id(&mut self, pts: Vec<Point>, fill: &'static str, stroke: f64, id: String) {
        self.poly(pts, fill, stroke);
        if let Some(Prim::Poly { id: slot, .. }) = self.prims.last_mut() {
            *slot = Some(id);
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

    /// A thin ring (a local enlargement's mark on a polygon), with an id;
    /// unlike [`Self::circle`] it keeps no labels off its inside.
    pub fn ring(&mut self, c: Point, r: f64, id: String) {
        self.prims.push(Prim::Circle {
            c,
            r,
            fill: "none",
            stroke: THIN,
            id: Some(id),
        });
    }

    /// A symbol (a joint, a fixed pivot, a slider block, a centre of mass)
    /// as one object: what `draw` draws, based at `at` and turned by
    /// `angle` (rad, counter-clockwise) from its upright drawing.
    pub fn symbol(
        &mut self,
        kind: &'static str,
        at: Point,
        angle: f64,
        draw: impl FnOnce(&mut Canvas),
    ) {
        self.prims.push(Prim::Symbol { kind, at, angle });
        draw(self);
        self.prims.push(Prim::End);
    }

    /// What `draw` draws, as a group ([`Prim::Group`]): named `class`,
    /// `opacity` times as strong, its black in `ink`.
    pub fn group(
        &mut self,
        (class, opacity, ink): (&'static str, f64, &'static str),
        draw: impl FnOnce(&mut Canvas),
    ) {
        self.prims.push(Prim::Group {
            class,
            opacity,
            ink,
            id: None,
        });
        draw(self);
        self.prims.push(Prim::End);
    }

    /// What `draw` draws, as a group named `class` with the id `id` (a
    /// figure the checks find whole: a force polygon), as drawn.
    pub fn group_id(&mut self, class: &'static str, id: String, draw: impl FnOnce(&mut Canvas)) {
        self.prims.push(Prim::Group {
            class,
            opacity: 1.0,
            ink: "black",
            id: Some(id),
        });
        draw(self);
        self.prims.push(Prim::End);
    }

    /// The last primitive drawn, past the end of a symbol.
    pub fn last_drawn_mut(&mut self) -> Option<&mut Prim> {
        self.prims.iter_mut().rev().find(|p| !matches!(p, Prim::End))
    }

    /// A region not drawn, with an id the checks read its box by
    /// ([`Prim::Region`]).
    pub fn region(&mut self, rect: Rect, id: String) {
        self.prims.push(Prim::Region { rect, id });
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
                Prim::Symbol { .. } | Prim::Group { .. } | Prim::End | Prim::Region { .. } => {}
            }
        }
        r.unwrap_or(Rect::ZERO)
    }
}
