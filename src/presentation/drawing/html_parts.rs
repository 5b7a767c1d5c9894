//! What the handout's writers share ([`super::html`] the kinematics,
//! [`super::handout_forces`] the force analysis): the lecture's notation
//! as HTML, a label as HTML, a canvas fitted into its own SVG, ids made
//! unique in the page.

use super::canvas::{fmt, xml};
use kurbo::Point;
use std::fmt::Write as _;

/// A sentence (or a quantity's name) as HTML, in the lecture's notation:
/// `v_B3C` → v<sub>B3C</sub>, `a^n_BA` → a<sup>n</sup><sub>BA</sub>, the
/// pole `p_vb` → p<sub>v</sub>b, digits after a letter as a subscript
/// (`ω1`, `b3`, `O2`) as the drawings write them. Only `_` and `^` are
/// dropped (with a combining underline right after them); the rest of the
/// text is kept, escaped.
pub fn rich(s: &str) -> String {
    use crate::words::notation::{Pos, runs};
    runs(s)
        .into_iter()
        .map(|(p, t)| match p {
            Pos::Base => xml(&t),
            Pos::Sub => format!("<sub>{}</sub>", xml(&t)),
            Pos::Sup => format!("<sup>{}</sup>", xml(&t)),
        })
        .collect()
}

/// A label (letters, subscript, more names, tail) as HTML.
pub(super) fn label_html(l: &super::canvas::Label) -> String {
    let sub = |s: &str| {
        if s.is_empty() {
            String::new()
        } else {
            format!("<sub>{}</sub>", xml(s))
        }
    };
    let mut h = format!("{}{}", xml(&l.base), sub(&l.sub));
    for (b, s) in &l.more {
        let _ = write!(h, ", {}{}", xml(b), sub(s));
    }
    h + &xml(&l.tail)
}

/// Where a canvas goes in its own SVG: page = (ox + x, oy − y).
pub(super) struct Fit {
    pub ox: f64,
    pub oy: f64,
    pub w: f64,
    pub h: f64,
}

impl Fit {
    pub fn new(b: kurbo::Rect, pad: f64) -> Fit {
        Fit {
            ox: pad - b.x0,
            oy: pad + b.y1,
            w: b.width() + 2.0 * pad,
            h: b.height() + 2.0 * pad,
        }
    }
    pub fn x(&self, p: Point) -> String {
        fmt(self.ox + p.x)
    }
    pub fn y(&self, p: Point) -> String {
        fmt(self.oy - p.y)
    }
    pub fn open(&self, class: &str, aria: &str) -> String {
        format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" class="{class}" viewBox="0 0 {} {}" font-family="DejaVu Sans, sans-serif" role="img" aria-label="{}">"#,
            fmt(self.w),
            fmt(self.h),
            xml(aria)
        ) + "\n"
    }
}

/// Ids made unique in the page (every sheet has its `pt-b`).
pub(super) fn prefixed(svg: String, prefix: &str) -> String {
    svg.replace(" id=\"", &format!(" id=\"{prefix}"))
}
