//! The writing of a [`Canvas`] as SVG: each primitive as its element (the
//! lines with their ГОСТ 2.303 weights and dash arrays, the labels and the
//! lecture's notation as tspans), every number through one formatter
//! ([`fmt`]: 0.01 mm, no trailing zeros, no "-0") and every text through
//! [`xml`], so the output is byte-stable.

use super::label::{Label, char_width};
use super::primitives::{ARROW_WIDTH, BOLD, Canvas, Class, Line, MAIN, Prim, THIN};
use crate::words::notation::{Pos, Run};
use kurbo::{Point, Vec2};
use std::fmt::Write as _;

/// Numbers as 0.01 mm, no trailing zeros, no "-0": byte-stable output.
pub fn fmt(x: f64) -> String {
    crate::format::fixed((x * 100.0).round() / 100.0, 2)
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

impl Canvas {
    /// Write the primitives as SVG elements, drawing coordinates mapped to
    /// the page by x ↦ ox + x, y ↦ oy − y; within a [`Prim::Group`] what
    /// is black is written in the group's ink.
    pub fn write(&self, out: &mut String, ox: f64, oy: f64) {
        let o = Origin { ox, oy };
        // The ink of each open symbol or group, innermost last.
        let mut inks: Vec<&'static str> = Vec::new();
        for p in &self.prims {
            let ink = inks.last().copied().unwrap_or("black");
            match p {
                Prim::Seg { a, b, class, id } => seg_svg(out, (o, ink), (*a, *b), *class, id),
                Prim::Poly {
                    pts,
                    fill,
                    stroke,
                    id,
                } => {
                    let d: Vec<String> = pts.iter().map(|q| o.xy(*q)).collect();
                    let stroke = stroke_attr(*stroke, ink);
                    let id = id_attr(id);
                    let fill = inked(fill, ink);
                    let _ = writeln!(
                        out,
                        r#"<polygon{id} points="{}" fill="{fill}"{stroke}/>"#,
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
                    let stroke = stroke_attr(*stroke, ink);
                    let fill = inked(fill, ink);
                    let _ = writeln!(
                        out,
                        r#"<circle{id} cx="{}" cy="{}" r="{}" fill="{fill}"{stroke}/>"#,
                        o.x(*c),
                        o.y(*c),
                        fmt(*r)
                    );
                }
                Prim::Path { pts, line } => path_svg(out, (o, ink), pts, *line),
                Prim::Arrow { tip, dir } => {
                    let back = *tip - *dir;
                    let n = Vec2::new(-dir.y, dir.x) * ARROW_WIDTH;
                    let _ = writeln!(
                        out,
                        r#"<polygon class="arrow" points="{} {} {}" fill="{ink}"/>"#,
                        o.xy(*tip),
                        o.xy(back + n),
                        o.xy(back - n)
                    );
                }
                Prim::Arc { c, r, a0, sweep } => arc_svg(out, (o, ink), *c, *r, (*a0, *sweep)),
                Prim::Symbol { kind, at, angle } => {
                    inks.push(ink);
                    symbol_svg(out, o, kind, *at, *angle)
                }
                Prim::Group {
                    class,
                    opacity,
                    ink,
                    id,
                } => {
                    inks.push(inked(ink, inks.last().copied().unwrap_or("black")));
                    let opacity = if *opacity < 1.0 {
                        format!(r#" opacity="{}""#, fmt(*opacity))
                    } else {
                        String::new()
                    };
                    let id = id_attr(id);
                    let _ = writeln!(out, r#"<g{id} class="{class}"{opacity}>"#);
                }
                Prim::End => {
                    inks.pop();
                    out.push_str("</g>\n")
                }
                Prim::Region { rect, id } => region_svg(out, o, *rect, id),
                Prim::Rich {
                    at,
                    runs,
                    size,
                    class,
                    anchor,
                    id,
                } => {
                    let id = id_attr(id);
                    let anchor = if *anchor == "start" {
                        String::new()
                    } else {
                        format!(r#" text-anchor="{anchor}""#)
                    };
                    let _ = writeln!(
                        out,
                        r#"<text class="{class}"{id} x="{}" y="{}" font-size="{}"{anchor}{}>{}</text>"#,
                        o.x(*at),
                        o.y(*at),
                        fmt(*size),
                        text_fill(ink),
                        runs_svg(runs, *size)
                    );
                }
                Prim::Text {
                    at,
                    label,
                    size,
                    id,
                    class,
                } => text_svg(out, (o, ink), (*at, label, *size), id, class),
            }
        }
    }
}

/// A label's text (a link's number in a circle).
fn text_svg(
    out: &mut String,
    (o, ink): (Origin, &str),
    (at, label, size): (Point, &Label, f64),
    id: &Option<String>,
    class: &str,
) {
    // A link's number in a circle, as the course writes it: never read
    // as a position's number beside it.
    if id.as_deref().is_some_and(|i| i.starts_with("link-")) {
        let w = label.width(size);
        let c = Point::new(at.x + w / 2.0, at.y + 0.36 * size);
        let _ = writeln!(
            out,
            r#"<circle class="link-number" cx="{}" cy="{}" r="{}" fill="none" stroke="{ink}" stroke-width="{}"/>"#,
            o.x(c),
            o.y(c),
            fmt(0.5 * w.max(0.6 * size) + 0.45 * size),
            fmt(THIN)
        );
    }
    let id = id_attr(id);
    let _ = writeln!(
        out,
        r#"<text class="{class}"{id} x="{}" y="{}" font-size="{}"{}>{}</text>"#,
        o.x(at),
        o.y(at),
        fmt(size),
        text_fill(ink),
        label_svg(label, size)
    );
}

/// A colour as drawn in `ink`: black becomes the ink, others stay.
fn inked(colour: &'static str, ink: &'static str) -> &'static str {
    if colour == "black" { ink } else { colour }
}

/// ` fill="…"` of a text in `ink` (nothing for black, the default).
fn text_fill(ink: &str) -> String {
    if ink == "black" {
        String::new()
    } else {
        format!(r#" fill="{ink}""#)
    }
}

/// Where the drawing's origin is on the page: a drawing point (x, y) is
/// written at (ox + x, oy − y).
#[derive(Clone, Copy)]
struct Origin {
    ox: f64,
    oy: f64,
}

impl Origin {
    fn x(self, p: Point) -> String {
        fmt(self.ox + p.x)
    }
    fn y(self, p: Point) -> String {
        fmt(self.oy - p.y)
    }
    /// "x y" on the page.
    fn xy(self, p: Point) -> String {
        format!("{} {}", self.x(p), self.y(p))
    }
}

/// A segment `ab` as a line of its class's weight, in `ink`.
fn seg_svg(
    out: &mut String,
    (o, color): (Origin, &str),
    (a, b): (Point, Point),
    class: Class,
    id: &Option<String>,
) {
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
    let id = id_attr(id);
    let _ = writeln!(
        out,
        r#"<line class="{cls}"{id} x1="{}" y1="{}" x2="{}" y2="{}" stroke="{color}" stroke-width="{}" stroke-linecap="round"/>"#,
        o.x(a),
        o.y(a),
        o.x(b),
        o.y(b),
        fmt(w)
    );
}

/// The start of a symbol's group: its kind, its base point on the page and
/// its turn (degrees, counter-clockwise on the sheet, in [0, 360); left
/// out when none), which the DXF writer reads to make it a block.
fn symbol_svg(out: &mut String, o: Origin, kind: &str, at: Point, angle: f64) {
    let deg = crate::format::fixed(angle.to_degrees().rem_euclid(360.0), 4);
    let turn = if deg == "0" || deg == "360" {
        String::new()
    } else {
        format!(r#" data-angle="{deg}""#)
    };
    let _ = writeln!(
        out,
        r#"<g data-symbol="{kind}" data-x="{}" data-y="{}"{turn}>"#,
        o.x(at),
        o.y(at)
    );
}

/// A polyline of one line type, its dashes fitted to its length.
fn path_svg(out: &mut String, (o, ink): (Origin, &str), pts: &[Point], line: Line) {
    let mut d = String::new();
    for (i, q) in pts.iter().enumerate() {
        d += if i == 0 { "M" } else { " L" };
        d += &o.xy(*q);
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
        r#"<path class="{}" d="{d}" fill="none" stroke="{ink}" stroke-width="{}"{dash} stroke-linejoin="round"/>"#,
        line.class(),
        fmt(line.width())
    );
}

/// A thin circular arc about `c` of radius `r` from angle `a0` swept by
/// `sweep` (rad, CCW positive).
fn arc_svg(out: &mut String, (o, ink): (Origin, &str), c: Point, r: f64, (a0, sweep): (f64, f64)) {
    let p0 = c + Vec2::from_angle(a0) * r;
    let p1 = c + Vec2::from_angle(a0 + sweep) * r;
    // In page coordinates y is flipped: a CCW sweep is sweep-flag 0.
    let large = if sweep.abs() > std::f64::consts::PI {
        1
    } else {
        0
    };
    let flag = if sweep > 0.0 { 0 } else { 1 };
    let _ = writeln!(
        out,
        r#"<path class="arc" d="M{} A{} {} 0 {large} {flag} {}" fill="none" stroke="{ink}" stroke-width="{}"/>"#,
        o.xy(p0),
        fmt(r),
        fmt(r),
        o.xy(p1),
        fmt(THIN)
    );
}

/// A label's content as tspans: the base with its subscript (a
/// superscript stacked over the subscript, as the lecture's runs do:
/// R^τ_12), more names after commas, the tail.
fn label_svg(label: &Label, size: f64) -> String {
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
    let (base, sub) = if label.sup.is_empty() {
        (xml(&label.base), sub(&label.sub))
    } else {
        let rs = vec![
            (Pos::Base, label.base.clone()),
            (Pos::Sup, label.sup.clone()),
            (Pos::Sub, label.sub.clone()),
        ];
        (runs_svg(&rs, size), String::new())
    };
    let tail = if label.tail.is_empty() {
        String::new()
    } else {
        format!("<tspan>{}</tspan>", xml(&label.tail))
    };
    format!("{base}{sub}{more}{tail}")
}

/// A region not drawn ([`Prim::Region`]): an empty group with its id and
/// its box on the page, top left and bottom right, `display="none"` so
/// that a renderer gives it no place (no box at the page's origin).
fn region_svg(out: &mut String, o: Origin, rect: kurbo::Rect, id: &str) {
    let (a, b) = (Point::new(rect.x0, rect.y1), Point::new(rect.x1, rect.y0));
    let _ = writeln!(
        out,
        r#"<g id="{}" class="region" display="none" data-box="{} {} {} {}"/>"#,
        xml(id),
        o.x(a),
        o.y(a),
        o.x(b),
        o.y(b)
    );
}

/// ` id="…"` of an element that has an id, else nothing.
fn id_attr(id: &Option<String>) -> String {
    id.as_ref()
        .map(|i| format!(r#" id="{i}""#))
        .unwrap_or_default()
}

/// ` stroke="…" stroke-width="…"` of an outlined shape (in `ink`), else
/// nothing.
fn stroke_attr(stroke: f64, ink: &str) -> String {
    if stroke > 0.0 {
        format!(r#" stroke="{ink}" stroke-width="{}""#, fmt(stroke))
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
