//! The DXF writer's code pairs ([`W`]) and the entities of the model
//! space ([`Entities`]), each with its layer, colour and lineweight.

use super::style::{STYLE, escape, num};
use std::fmt::Write as _;

/// The writer: code pairs, handles counted from 0x20.
pub(super) struct W {
    pub(super) out: String,
    pub(super) next: u32,
}

impl W {
    pub(super) fn new() -> W {
        W {
            out: String::new(),
            next: 0x20,
        }
    }
    pub(super) fn p(&mut self, code: i32, v: impl std::fmt::Display) {
        let _ = write!(self.out, "{code:>3}\n{v}\n");
    }
    pub(super) fn h(&mut self) -> String {
        let h = format!("{:X}", self.next);
        self.next += 1;
        h
    }
    /// A point's 10/20/30 (or 11/21/31 …).
    pub(super) fn pt(&mut self, code: i32, (x, y): (f64, f64)) {
        self.p(code, num(x));
        self.p(code + 10, num(y));
        self.p(code + 20, 0);
    }
}

/// What an entity shares: its layer, colour and lineweight.
pub(super) struct Common {
    pub(super) layer: String,
    pub(super) color: Option<i32>,
    pub(super) weight: Option<i32>,
}

/// What the entities are written for: a sheet of our own (R2007, mm,
/// layers by class), or a copy of another file (`check --dxf`: the
/// student's version, units and code page, every entity on one layer).
pub(super) struct Target {
    /// R12 and older: no handles, owners or subclass markers; POLYLINE
    /// for LWPOLYLINE, TEXT for MTEXT, a fill's outline for a HATCH.
    pub(super) legacy: bool,
    /// Handles and owners (R13 and later): left out for a file whose own
    /// entities have none, whose reader numbers them all (a handle of
    /// ours would take the number it gives one of the student's).
    pub(super) handles: bool,
    /// Texts in ASCII, other letters as `\U+XXXX` (readable whatever the
    /// file's code page).
    pub(super) ascii: bool,
    /// The texts' style.
    pub(super) style: String,
    /// Drawing units per mm of the sheet (heights, radii).
    pub(super) scale: f64,
    /// Every entity on this layer (else the one its class gives).
    pub(super) layer: Option<String>,
    /// Grey shading (a plan's similar figures) filled; else left out.
    pub(super) shading: bool,
    /// The colour of an entity that names none (else by layer): for a
    /// file without a LAYER table, whose CAD gives an unknown layer the
    /// colour of the student's lines.
    pub(super) color: Option<i32>,
}

impl Target {
    /// A sheet of mechplan's own.
    pub(super) fn sheet() -> Target {
        Target {
            legacy: false,
            handles: true,
            ascii: false,
            style: STYLE.into(),
            scale: 1.0,
            layer: None,
            shading: true,
            color: None,
        }
    }
}

/// The entities of the model space, written as they come.
pub(super) struct Entities {
    pub(super) w: W,
    pub(super) owner: String,
    pub(super) layers: Vec<String>,
    pub(super) target: Target,
}

impl Entities {
    fn head(&mut self, kind: &str, c: &Common, sub: &str) {
        let layer = self.target.layer.clone().unwrap_or_else(|| c.layer.clone());
        if !self.layers.contains(&layer) {
            self.layers.push(layer.clone());
        }
        self.w.p(0, kind);
        if !self.target.legacy {
            if self.target.handles {
                let h = self.w.h();
                self.w.p(5, h);
                if !self.owner.is_empty() {
                    let owner = self.owner.clone();
                    self.w.p(330, owner);
                }
            }
            self.w.p(100, "AcDbEntity");
        }
        self.w.p(8, &layer);
        if let Some(col) = c.color.or(self.target.color) {
            self.w.p(62, col);
        }
        if self.target.legacy {
            return;
        }
        if let Some(wt) = c.weight {
            self.w.p(370, wt);
        }
        // White as a true colour a shade off: a CAD that prints ACI 255
        // black on paper (LibreCAD) prints this white.
        if c.color == Some(255) {
            self.w.p(420, 0xFE_FE_FE);
        }
        self.w.p(100, sub);
    }

    /// A string value as the target reads it.
    fn string(&self, s: &str) -> String {
        let s = escape(s);
        if !self.target.ascii {
            return s;
        }
        s.chars()
            .map(|c| match c {
                ' '..='~' => c.to_string(),
                c if (c as u32) <= 0xFFFF => format!("\\U+{:04X}", c as u32),
                _ => "?".into(),
            })
            .collect()
    }

    pub(super) fn line(&mut self, c: &Common, a: (f64, f64), b: (f64, f64)) {
        self.head("LINE", c, "AcDbLine");
        self.w.pt(10, a);
        self.w.pt(11, b);
    }

    /// A polyline of vertices with the bulge of the segment after each.
    pub(super) fn lwpolyline(&mut self, c: &Common, pts: &[((f64, f64), f64)], closed: bool) {
        if self.target.legacy {
            return self.polyline(c, pts, closed);
        }
        self.head("LWPOLYLINE", c, "AcDbPolyline");
        self.w.p(90, pts.len());
        // Closed, and the linetype's pattern run over the whole polyline.
        self.w.p(70, if closed { 129 } else { 128 });
        for ((x, y), bulge) in pts {
            self.w.p(10, num(*x));
            self.w.p(20, num(*y));
            if *bulge != 0.0 {
                self.w.p(42, num_fine(*bulge));
            }
        }
    }

    /// R12's polyline: a POLYLINE, its VERTEXes (with bulges) and SEQEND.
    fn polyline(&mut self, c: &Common, pts: &[((f64, f64), f64)], closed: bool) {
        self.head("POLYLINE", c, "");
        self.w.p(66, 1);
        self.w.pt(10, (0.0, 0.0));
        self.w.p(70, i32::from(closed));
        for (at, bulge) in pts {
            self.head("VERTEX", c, "");
            self.w.pt(10, *at);
            if *bulge != 0.0 {
                self.w.p(42, num_fine(*bulge));
            }
        }
        self.head("SEQEND", c, "");
    }

    pub(super) fn circle(&mut self, c: &Common, o: (f64, f64), r: f64) {
        self.head("CIRCLE", c, "AcDbCircle");
        self.w.pt(10, o);
        self.w.p(40, num(r * self.target.scale));
    }

    pub(super) fn solid(&mut self, c: &Common, p: [(f64, f64); 3]) {
        self.head("SOLID", c, "AcDbTrace");
        self.w.pt(10, p[0]);
        self.w.pt(11, p[1]);
        self.w.pt(12, p[2]);
        self.w.pt(13, p[2]);
    }

    /// A solid fill bounded by one closed polyline (with bulges).
    pub(super) fn hatch(&mut self, c: &Common, pts: &[((f64, f64), f64)]) {
        if !self.target.shading && c.color.is_some_and(|k| (250..=254).contains(&k)) {
            return;
        }
        if self.target.legacy {
            return self.polyline(c, pts, true);
        }
        self.head("HATCH", c, "AcDbHatch");
        self.w.pt(10, (0.0, 0.0));
        self.w.p(210, 0);
        self.w.p(220, 0);
        self.w.p(230, 1);
        self.w.p(2, "SOLID");
        self.w.p(70, 1);
        self.w.p(71, 0);
        self.w.p(91, 1);
        // An external polyline path.
        self.w.p(92, 3);
        let bulged = pts.iter().any(|p| p.1 != 0.0);
        self.w.p(72, i32::from(bulged));
        self.w.p(73, 1);
        self.w.p(93, pts.len());
        for ((x, y), b) in pts {
            self.w.p(10, num(*x));
            self.w.p(20, num(*y));
            if bulged {
                self.w.p(42, num_fine(*b));
            }
        }
        self.w.p(97, 0);
        self.w.p(75, 1);
        self.w.p(76, 1);
        self.w.p(98, 0);
    }

    /// A block `name` inserted at `at`, turned by `deg` (counter-clockwise).
    pub(super) fn insert(&mut self, c: &Common, name: &str, at: (f64, f64), deg: f64) {
        self.head("INSERT", c, "AcDbBlockReference");
        self.w.p(2, name);
        self.w.pt(10, at);
        if deg != 0.0 {
            self.w.p(50, num(deg));
        }
    }

    /// A one-line text at its baseline, of `height` and width `factor`
    /// (1: the font's own); `anchor` start, middle or end.
    pub(super) fn text(
        &mut self,
        c: &Common,
        at: (f64, f64),
        (height, factor): (f64, f64),
        s: &str,
        anchor: &str,
    ) {
        self.head("TEXT", c, "AcDbText");
        self.w.pt(10, at);
        self.w.p(40, num(height * self.target.scale));
        let s = self.string(s);
        self.w.p(1, s);
        if factor != 1.0 {
            self.w.p(41, num(factor));
        }
        let style = self.target.style.clone();
        self.w.p(7, style);
        let h = match anchor {
            "middle" => 1,
            "end" => 2,
            _ => 0,
        };
        if h != 0 {
            self.w.p(72, h);
            self.w.pt(11, at);
        }
        if !self.target.legacy {
            self.w.p(100, "AcDbText");
        }
    }

    /// A text with sub- and superscripts: MTEXT attached at the bottom
    /// (the baseline of its one line) left, centre or right.
    pub(super) fn mtext(
        &mut self,
        c: &Common,
        at: (f64, f64),
        (height, width): (f64, f64),
        content: &str,
        anchor: &str,
    ) {
        self.head("MTEXT", c, "AcDbMText");
        self.w.pt(10, at);
        self.w.p(40, num(height * self.target.scale));
        // The column a little wider than the text: one line, never wrapped
        // (a width of 0, "no wrapping", some readers take as a narrow
        // column).
        self.w.p(41, num(width * self.target.scale));
        let attach = match anchor {
            "middle" => 8,
            "end" => 9,
            _ => 7,
        };
        self.w.p(71, attach);
        self.w.p(72, 1);
        // Content past 250 characters in chunks of code 3, the last as 1.
        let content = self.string(content);
        let chars: Vec<char> = content.chars().collect();
        let chunks: Vec<String> = chars.chunks(250).map(|c| c.iter().collect()).collect();
        for (i, ch) in chunks.iter().enumerate() {
            self.w.p(if i + 1 == chunks.len() { 1 } else { 3 }, ch);
        }
        if chunks.is_empty() {
            self.w.p(1, "");
        }
        let style = self.target.style.clone();
        self.w.p(7, style);
    }
}

/// A bulge to 1e-8.
pub(super) fn num_fine(x: f64) -> String {
    crate::format::fixed(x, 8)
}

