//! Sheets as DXF (`draw --format dxf`): the sheet's own SVG, as the
//! renderer writes it, read back (roxmltree) and written as an ASCII DXF
//! R2007 (AC1021, UTF-8) drawing at true paper size in millimetres
//! (`$INSUNITS` = 4), y up (the page's y flipped), so that every μ holds
//! when the sheet is printed 1:1 from the CAD.
//!
//! What maps to what (docs/sheets.md, "DXF sheets"):
//! - `line` → LINE; `path` (M/L/Z, and A arcs as bulges) and `rect` →
//!   LWPOLYLINE; `circle` → CIRCLE; an outlined `polygon` → a closed
//!   LWPOLYLINE;
//! - an arrowhead (`polygon class="arrow"`) → SOLID; any other fill (the
//!   grey triangles, the black half-discs of the hinges, the white of a
//!   joint's circle or a slider's block) → a solid HATCH;
//! - `text` → TEXT at its baseline (plain text) or MTEXT (text with sub- or
//!   superscripts: `\S^sub;`, `\Ssup^sub;`), each SVG text one entity, its
//!   height the font size in mm, in the style `MECHPLAN` (DejaVu Sans, which
//!   carries Cyrillic and Greek), in UTF-8 (R2007 and later: no code
//!   page, no `\U+XXXX` escapes for a reader to decode);
//! - layers by the element's `class`, each with its ГОСТ 2.303 linetype
//!   and lineweight; each entity also carries its own lineweight (370), the
//!   stroke width of the SVG.
//!
//! The writer is this module's own (no DXF crate): the `dxf` crate (0.6.2)
//! has no HATCH entity and would bring a dozen crates (chrono, image,
//! uuid, …) for the fourteen kinds of record written here.

use crate::error::{Error, Result};
use std::fmt::Write as _;

/// The text style of every text.
pub const STYLE: &str = "MECHPLAN";
/// Its font file (TrueType, Latin, Cyrillic and Greek).
pub const FONT_FILE: &str = "DejaVuSans.ttf";

/// DXF's lineweights (1/100 mm) a CAD accepts.
const WEIGHTS: [i32; 24] = [
    0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200,
    211,
];

/// The linetypes, after ГОСТ 2.303 (mm; a dash positive, a gap negative,
/// a dot 0), the same periods as the SVG's dash arrays.
const LTYPES: [(&str, &str, &[f64]); 3] = [
    ("GOST_DASHED", "Dashed (GOST 2.303) __ __ __", &[4.0, -1.5]),
    (
        "GOST_DASHDOT",
        "Dash-dot thin (GOST 2.303) ____ . ____ .",
        &[12.0, -1.8, 0.0, -1.8],
    ),
    (
        "GOST_DASHDOTDOT",
        "Dash-dot-dot (GOST 2.303) ____ . . ____ . .",
        &[12.0, -1.8, 0.0, -1.8, 0.0, -1.8],
    ),
];

/// A layer's linetype and lineweight (1/100 mm) by its name.
pub fn layer_style(name: &str) -> (&'static str, i32) {
    match name {
        "main" | "vector" => ("Continuous", 50),
        "bold" => ("Continuous", 80),
        "frame" => ("Continuous", 70),
        "dashed" => ("GOST_DASHED", 25),
        "dash-dot" => ("GOST_DASHDOT", 25),
        "dash-dot-dot" => ("GOST_DASHDOTDOT", 25),
        "0" => ("Continuous", -3),
        _ => ("Continuous", 25),
    }
}

/// The layer of a text of SVG class `class`.
pub fn text_layer(class: &str) -> String {
    if class.is_empty() {
        "text".into()
    } else {
        format!("text-{class}")
    }
}

/// The nearest DXF lineweight to a stroke width in mm.
fn weight(mm: f64) -> i32 {
    let w = mm * 100.0;
    *WEIGHTS
        .iter()
        .min_by(|a, b| {
            ((**a as f64) - w)
                .abs()
                .partial_cmp(&((**b as f64) - w).abs())
                .unwrap_or(std::cmp::Ordering::Equal)
        })
        .unwrap_or(&25)
}

/// A number as DXF writes it here: to 0.0001 mm, no trailing zeros.
fn num(x: f64) -> String {
    crate::format::fixed(x, 4)
}

/// Text for a DXF string value: UTF-8 as R2007 writes it, no line ends.
fn escape(s: &str) -> String {
    s.replace(['\n', '\r'], " ")
}

/// Text as MTEXT content: its own control characters escaped.
fn mtext_escape(s: &str) -> String {
    escape(&s.replace('\\', "\\\\").replace('{', "\\{").replace('}', "\\}"))
}

/// An ACI colour for an SVG colour: black (and anything unknown) by layer,
/// the student's red as red, white and greys as the nearest ACI grey.
fn aci(color: &str) -> Option<i32> {
    let c = color.trim().to_ascii_lowercase();
    let rgb = match c.as_str() {
        "black" | "#000" | "#000000" | "" => return None,
        "white" | "#fff" | "#ffffff" => return Some(255),
        "red" | "#c00000" => return Some(1),
        _ => c.strip_prefix('#').filter(|h| h.len() == 6).and_then(|h| {
            let p = |i: usize| u8::from_str_radix(&h[i..i + 2], 16).ok();
            Some((p(0)?, p(2)?, p(4)?))
        }),
    };
    let (r, g, b) = rgb?;
    if r == g && g == b {
        // ACI 250–255: greys 51, 91, 132, 173, 214, 255.
        let greys = [(250, 51), (251, 91), (252, 132), (253, 173), (254, 214), (255, 255)];
        let v = r as i32;
        return greys.iter().min_by_key(|(_, x)| (x - v).abs()).map(|g| g.0);
    }
    Some(if r > g && r > b { 1 } else { 7 })
}

/// The writer: code pairs, handles counted from 0x20.
struct W {
    out: String,
    next: u32,
}

impl W {
    fn new() -> W {
        W {
            out: String::new(),
            next: 0x20,
        }
    }
    fn p(&mut self, code: i32, v: impl std::fmt::Display) {
        let _ = write!(self.out, "{code:>3}\n{v}\n");
    }
    fn h(&mut self) -> String {
        let h = format!("{:X}", self.next);
        self.next += 1;
        h
    }
    /// A point's 10/20/30 (or 11/21/31 …).
    fn pt(&mut self, code: i32, (x, y): (f64, f64)) {
        self.p(code, num(x));
        self.p(code + 10, num(y));
        self.p(code + 20, 0);
    }
}

/// What an entity shares: its layer, colour and lineweight.
struct Common {
    layer: String,
    color: Option<i32>,
    weight: Option<i32>,
}

/// The entities of the model space, written as they come.
struct Entities {
    w: W,
    owner: String,
    layers: Vec<String>,
}

impl Entities {
    fn head(&mut self, kind: &str, c: &Common, sub: &str) {
        if !self.layers.contains(&c.layer) {
            self.layers.push(c.layer.clone());
        }
        let h = self.w.h();
        self.w.p(0, kind);
        self.w.p(5, h);
        let owner = self.owner.clone();
        self.w.p(330, owner);
        self.w.p(100, "AcDbEntity");
        self.w.p(8, &c.layer);
        if let Some(col) = c.color {
            self.w.p(62, col);
        }
        if let Some(wt) = c.weight {
            self.w.p(370, wt);
        }
        self.w.p(100, sub);
    }

    fn line(&mut self, c: &Common, a: (f64, f64), b: (f64, f64)) {
        self.head("LINE", c, "AcDbLine");
        self.w.pt(10, a);
        self.w.pt(11, b);
    }

    /// A polyline of vertices with the bulge of the segment after each.
    fn lwpolyline(&mut self, c: &Common, pts: &[((f64, f64), f64)], closed: bool) {
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

    fn circle(&mut self, c: &Common, o: (f64, f64), r: f64) {
        self.head("CIRCLE", c, "AcDbCircle");
        self.w.pt(10, o);
        self.w.p(40, num(r));
    }

    fn solid(&mut self, c: &Common, p: [(f64, f64); 3]) {
        self.head("SOLID", c, "AcDbTrace");
        self.w.pt(10, p[0]);
        self.w.pt(11, p[1]);
        self.w.pt(12, p[2]);
        self.w.pt(13, p[2]);
    }

    /// A solid fill bounded by one closed polyline (with bulges).
    fn hatch(&mut self, c: &Common, pts: &[((f64, f64), f64)]) {
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

    /// A one-line text at its baseline; `anchor` start, middle or end.
    fn text(&mut self, c: &Common, at: (f64, f64), height: f64, s: &str, anchor: &str) {
        self.head("TEXT", c, "AcDbText");
        self.w.pt(10, at);
        self.w.p(40, num(height));
        self.w.p(1, escape(s));
        self.w.p(7, STYLE);
        let h = match anchor {
            "middle" => 1,
            "end" => 2,
            _ => 0,
        };
        if h != 0 {
            self.w.p(72, h);
            self.w.pt(11, at);
        }
        self.w.p(100, "AcDbText");
    }

    /// A text with sub- and superscripts: MTEXT attached at the bottom
    /// (the baseline of its one line) left, centre or right.
    fn mtext(
        &mut self,
        c: &Common,
        at: (f64, f64),
        (height, width): (f64, f64),
        content: &str,
        anchor: &str,
    ) {
        self.head("MTEXT", c, "AcDbMText");
        self.w.pt(10, at);
        self.w.p(40, num(height));
        // The column a little wider than the text: one line, never wrapped
        // (a width of 0, "no wrapping", some readers take as a narrow
        // column).
        self.w.p(41, num(width));
        let attach = match anchor {
            "middle" => 8,
            "end" => 9,
            _ => 7,
        };
        self.w.p(71, attach);
        self.w.p(72, 1);
        // Content past 250 characters in chunks of code 3, the last as 1.
        let chars: Vec<char> = content.chars().collect();
        let chunks: Vec<String> = chars.chunks(250).map(|c| c.iter().collect()).collect();
        for (i, ch) in chunks.iter().enumerate() {
            self.w.p(if i + 1 == chunks.len() { 1 } else { 3 }, ch);
        }
        if chunks.is_empty() {
            self.w.p(1, "");
        }
        self.w.p(7, STYLE);
    }
}

/// A bulge to 1e-8.
fn num_fine(x: f64) -> String {
    crate::format::fixed(x, 8)
}

/// Numbers of an SVG list ("1 2, 3 4").
fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
        .filter_map(|t| t.parse().ok())
        .collect()
}

/// A path's subpaths as vertices with bulges, and whether each is closed:
/// M, L (absolute), A (circular, absolute) and Z, as the renderer writes.
type Sub = (Vec<((f64, f64), f64)>, bool);
fn path_subpaths(d: &str, flip: impl Fn(f64, f64) -> (f64, f64)) -> Result<Vec<Sub>> {
    let mut subs: Vec<Sub> = Vec::new();
    let mut toks: Vec<String> = Vec::new();
    let mut cur = String::new();
    for c in d.chars() {
        if c.is_ascii_alphabetic() && c != 'e' && c != 'E' {
            if !cur.trim().is_empty() {
                toks.push(cur.clone());
            }
            cur.clear();
            toks.push(c.to_string());
        } else {
            cur.push(c);
        }
    }
    if !cur.trim().is_empty() {
        toks.push(cur);
    }
    let bad = || Error::Internal(format!("a path the DXF writer cannot read: {d}"));
    let mut i = 0;
    while i < toks.len() {
        let cmd = toks[i].as_str();
        let args = if i + 1 < toks.len() && !toks[i + 1].chars().all(|c| c.is_ascii_alphabetic())
        {
            i += 1;
            numbers(&toks[i])
        } else {
            Vec::new()
        };
        i += 1;
        match cmd {
            "M" | "L" => {
                if cmd == "M" || subs.is_empty() {
                    subs.push((Vec::new(), false));
                }
                let sub = subs.last_mut().ok_or_else(bad)?;
                for xy in args.chunks(2) {
                    if xy.len() == 2 {
                        sub.0.push((flip(xy[0], xy[1]), 0.0));
                    }
                }
            }
            "A" => {
                let sub = subs.last_mut().ok_or_else(bad)?;
                for a in args.chunks(7) {
                    if a.len() < 7 {
                        return Err(bad());
                    }
                    let Some(last) = sub.0.last_mut() else {
                        return Err(bad());
                    };
                    let (p0, p1) = (last.0, flip(a[5], a[6]));
                    let r = a[0];
                    let chord = ((p1.0 - p0.0).powi(2) + (p1.1 - p0.1).powi(2)).sqrt();
                    let half = (chord / (2.0 * r)).clamp(-1.0, 1.0).asin();
                    let theta = if a[3] != 0.0 {
                        2.0 * std::f64::consts::PI - 2.0 * half
                    } else {
                        2.0 * half
                    };
                    // SVG's sweep 1 turns clockwise on the page, and so
                    // on the y-up sheet: a negative bulge.
                    let sign = if a[4] != 0.0 { -1.0 } else { 1.0 };
                    last.1 = sign * (theta / 4.0).tan();
                    sub.0.push((p1, 0.0));
                }
            }
            "Z" | "z" => {
                if let Some(s) = subs.last_mut() {
                    s.1 = true;
                }
            }
            _ => return Err(bad()),
        }
    }
    Ok(subs)
}

/// A text's runs: (text, shift: 0 base, −1 sub, +1 sup).
fn runs(node: roxmltree::Node) -> Vec<(String, i32)> {
    let mut out = Vec::new();
    for ch in node.children() {
        if ch.is_text() {
            if let Some(t) = ch.text() {
                out.push((t.to_string(), 0));
            }
        } else if ch.has_tag_name("tspan") {
            let shift = match ch.attribute("baseline-shift") {
                Some("sub") => -1,
                Some("super") => 1,
                Some(v) => match v.parse::<f64>() {
                    Ok(x) if x < 0.0 => -1,
                    Ok(x) if x > 0.0 => 1,
                    _ => 0,
                },
                None => 0,
            };
            let t: String = ch
                .descendants()
                .filter(|n| n.is_text())
                .filter_map(|n| n.text())
                .collect();
            out.push((t, shift));
        }
    }
    out
}

/// A text's runs as MTEXT content: a superscript followed by a subscript
/// stacked over it (`\Sn^KC;`), a lone subscript `\S^x;`, a superscript
/// `\Sx^;`.
fn mtext_content(rs: &[(String, i32)]) -> String {
    let stack = |s: &str| s.replace(['^', '/', '#', ';'], " ");
    let mut out = String::new();
    let mut i = 0;
    while i < rs.len() {
        let (t, k) = &rs[i];
        match k {
            0 => out += &mtext_escape(t),
            1 => {
                let sub = match rs.get(i + 1) {
                    Some((u, -1)) => {
                        i += 1;
                        u.clone()
                    }
                    _ => String::new(),
                };
                let _ = write!(
                    out,
                    "{{\\S{}^{};}}",
                    mtext_escape(&stack(t)),
                    mtext_escape(&stack(&sub))
                );
            }
            _ => {
                let _ = write!(out, "{{\\S^{};}}", mtext_escape(&stack(t)));
            }
        }
        i += 1;
    }
    out
}

/// The sheet's SVG (as the renderer writes it) as an ASCII DXF R2007.
pub fn dxf(svg: &str) -> Result<String> {
    let doc = roxmltree::Document::parse(svg)
        .map_err(|e| Error::Internal(format!("the drawing is not valid SVG: {e}")))?;
    let root = doc.root_element();
    let vb = numbers(root.attribute("viewBox").unwrap_or(""));
    let (w, h) = match vb.as_slice() {
        [_, _, w, h] => (*w, *h),
        _ => return Err(Error::Internal("the sheet has no viewBox".into())),
    };
    let flip = |x: f64, y: f64| (x, h - y);

    let mut e = Entities {
        w: W::new(),
        owner: String::new(),
        layers: vec!["0".into()],
    };
    // Handles of the tables and blocks first: fixed, below 0x20.
    e.owner = "1F".into();
    let attr = |n: &roxmltree::Node, a: &str| n.attribute(a).unwrap_or("").to_string();
    let f = |n: &roxmltree::Node, a: &str| n.attribute(a).and_then(|v| v.parse::<f64>().ok());
    for n in root.descendants().filter(|n| n.is_element()) {
        let class = attr(&n, "class");
        let stroke = n.attribute("stroke").filter(|s| *s != "none");
        let sw = f(&n, "stroke-width").unwrap_or(1.0);
        let fill = n.attribute("fill").unwrap_or("black");
        let filled = fill != "none";
        let layer = if class.is_empty() {
            "symbol".to_string()
        } else {
            class.clone()
        };
        let outline = |layer: &str| Common {
            layer: layer.to_string(),
            color: stroke.and_then(aci),
            weight: Some(weight(sw)),
        };
        let fill_layer = if fill == "white" || fill == "#ffffff" {
            "mask"
        } else {
            "fill"
        };
        let filler = Common {
            layer: fill_layer.to_string(),
            color: aci(fill),
            weight: None,
        };
        match n.tag_name().name() {
            "line" => {
                let c = outline(&layer);
                let a = flip(f(&n, "x1").unwrap_or(0.0), f(&n, "y1").unwrap_or(0.0));
                let b = flip(f(&n, "x2").unwrap_or(0.0), f(&n, "y2").unwrap_or(0.0));
                e.line(&c, a, b);
            }
            "path" => {
                let subs = path_subpaths(n.attribute("d").unwrap_or(""), flip)?;
                for (pts, closed) in subs {
                    if filled && closed {
                        e.hatch(&filler, &pts);
                    }
                    if stroke.is_some() && pts.len() > 1 {
                        e.lwpolyline(&outline(&layer), &pts, closed);
                    }
                }
            }
            "polygon" | "polyline" => {
                let v = numbers(n.attribute("points").unwrap_or(""));
                let pts: Vec<((f64, f64), f64)> = v
                    .chunks(2)
                    .filter(|c| c.len() == 2)
                    .map(|c| (flip(c[0], c[1]), 0.0))
                    .collect();
                let closed = n.tag_name().name() == "polygon";
                if class == "arrow" && pts.len() == 3 {
                    let c = Common {
                        layer: "arrow".to_string(),
                        color: aci(fill),
                        weight: None,
                    };
                    e.solid(&c, [pts[0].0, pts[1].0, pts[2].0]);
                } else if filled && closed && pts.len() >= 3 {
                    e.hatch(&filler, &pts);
                }
                if stroke.is_some() && pts.len() > 1 {
                    e.lwpolyline(&outline(&layer), &pts, closed);
                }
            }
            "rect" => {
                let (x, y) = (f(&n, "x").unwrap_or(0.0), f(&n, "y").unwrap_or(0.0));
                let (rw, rh) = (f(&n, "width").unwrap_or(0.0), f(&n, "height").unwrap_or(0.0));
                let pts: Vec<((f64, f64), f64)> = [(x, y), (x + rw, y), (x + rw, y + rh), (x, y + rh)]
                    .iter()
                    .map(|&(a, b)| (flip(a, b), 0.0))
                    .collect();
                // The white paper under the sheet is the CAD's paper.
                let paper = stroke.is_none() && rw >= w && rh >= h;
                if filled && !paper {
                    e.hatch(&filler, &pts);
                }
                if stroke.is_some() {
                    e.lwpolyline(&outline(&layer), &pts, true);
                }
            }
            "circle" => {
                let o = flip(f(&n, "cx").unwrap_or(0.0), f(&n, "cy").unwrap_or(0.0));
                let r = f(&n, "r").unwrap_or(0.0);
                if filled && r > 0.0 {
                    let pts = [((o.0 - r, o.1), 1.0), ((o.0 + r, o.1), 1.0)];
                    e.hatch(&filler, &pts);
                }
                if stroke.is_some() {
                    e.circle(&outline(&layer), o, r);
                }
            }
            "text" => {
                let at = flip(f(&n, "x").unwrap_or(0.0), f(&n, "y").unwrap_or(0.0));
                let size = f(&n, "font-size").unwrap_or(3.5);
                let anchor = n.attribute("text-anchor").unwrap_or("start");
                let rs = runs(n);
                let tl = text_layer(&class);
                let c = Common {
                    layer: tl,
                    color: n.attribute("fill").and_then(aci),
                    weight: None,
                };
                if rs.iter().all(|r| r.1 == 0) {
                    let s: String = rs.iter().map(|r| r.0.as_str()).collect();
                    if !s.trim().is_empty() {
                        e.text(&c, at, size, &s, anchor);
                    }
                } else {
                    let width: f64 = rs
                        .iter()
                        .map(|(t, k)| {
                            let k = if *k == 0 { 1.0 } else { 0.7 };
                            t.chars().count() as f64 * size * k
                        })
                        .sum();
                    // Within the paper: the column a reader may take as
                    // the text's box.
                    let room = match anchor {
                        "middle" => 2.0 * at.0.min(w - at.0),
                        "end" => at.0,
                        _ => w - at.0,
                    };
                    let width = (width + size).min(room.max(size));
                    e.mtext(&c, at, (size, width), &mtext_content(&rs), anchor);
                }
            }
            _ => {}
        }
    }
    let Entities {
        w: ents, layers, ..
    } = e;
    Ok(document((w, h), &layers, ents))
}

/// The whole file around the entities: header, tables, blocks, objects.
fn document((w, h): (f64, f64), layers: &[String], ents: W) -> String {
    let mut d = W::new();
    d.next = ents.next;
    // Fixed handles: tables 1–9, block records 1F (model) and 1E (paper),
    // their blocks, the dictionaries and layouts 10–1D.
    let mut tables = W::new();
    tables.next = 0; // unused: fixed handles and d's below.
    let table = |t: &mut W, name: &str, handle: &str, count: usize| {
        t.p(0, "TABLE");
        t.p(2, name);
        t.p(5, handle);
        t.p(330, 0);
        t.p(100, "AcDbSymbolTable");
        t.p(70, count);
    };
    let record = |t: &mut W, d: &mut W, kind: &str, owner: &str, sub: &str, name: &str| {
        let hh = d.h();
        t.p(0, kind);
        t.p(5, hh);
        t.p(330, owner);
        t.p(100, "AcDbSymbolTableRecord");
        t.p(100, sub);
        t.p(2, name);
        t.p(70, 0);
    };
    // VPORT: the sheet in view.
    table(&mut tables, "VPORT", "8", 1);
    record(&mut tables, &mut d, "VPORT", "8", "AcDbViewportTableRecord", "*Active");
    tables.pt(10, (0.0, 0.0));
    tables.pt(11, (1.0, 1.0));
    tables.p(12, num(w / 2.0));
    tables.p(22, num(h / 2.0));
    tables.p(40, num(h * 1.05));
    tables.p(41, num(w / h));
    tables.p(0, "ENDTAB");
    // LTYPE.
    table(&mut tables, "LTYPE", "5", 3 + LTYPES.len());
    for name in ["ByBlock", "ByLayer", "Continuous"] {
        record(&mut tables, &mut d, "LTYPE", "5", "AcDbLinetypeTableRecord", name);
        tables.p(3, if name == "Continuous" { "Solid line" } else { "" });
        tables.p(72, 65);
        tables.p(73, 0);
        tables.p(40, 0);
    }
    for (name, desc, pat) in LTYPES {
        record(&mut tables, &mut d, "LTYPE", "5", "AcDbLinetypeTableRecord", name);
        tables.p(3, desc);
        tables.p(72, 65);
        tables.p(73, pat.len());
        tables.p(40, num(pat.iter().map(|x| x.abs()).sum()));
        for x in pat {
            tables.p(49, num(*x));
            tables.p(74, 0);
        }
    }
    tables.p(0, "ENDTAB");
    // LAYER.
    table(&mut tables, "LAYER", "2", layers.len());
    for l in layers {
        let (lt, wt) = layer_style(l);
        record(&mut tables, &mut d, "LAYER", "2", "AcDbLayerTableRecord", l);
        tables.p(62, 7);
        tables.p(6, lt);
        tables.p(370, wt);
        tables.p(390, "F");
    }
    tables.p(0, "ENDTAB");
    // STYLE.
    table(&mut tables, "STYLE", "3", 2);
    for (name, font) in [("Standard", "txt"), (STYLE, FONT_FILE)] {
        record(&mut tables, &mut d, "STYLE", "3", "AcDbTextStyleTableRecord", name);
        tables.p(40, 0);
        tables.p(41, 1);
        tables.p(50, 0);
        tables.p(71, 0);
        tables.p(42, 2.5);
        tables.p(3, font);
        tables.p(4, "");
    }
    tables.p(0, "ENDTAB");
    for (name, handle) in [("VIEW", "6"), ("UCS", "7")] {
        table(&mut tables, name, handle, 0);
        tables.p(0, "ENDTAB");
    }
    table(&mut tables, "APPID", "9", 1);
    record(&mut tables, &mut d, "APPID", "9", "AcDbRegAppTableRecord", "ACAD");
    tables.p(0, "ENDTAB");
    // DIMSTYLE: its records' handles are code 105.
    tables.p(0, "TABLE");
    tables.p(2, "DIMSTYLE");
    tables.p(5, "A");
    tables.p(330, 0);
    tables.p(100, "AcDbSymbolTable");
    tables.p(70, 1);
    tables.p(100, "AcDbDimStyleTable");
    tables.p(71, 0);
    let hh = d.h();
    tables.p(0, "DIMSTYLE");
    tables.p(105, hh);
    tables.p(330, "A");
    tables.p(100, "AcDbSymbolTableRecord");
    tables.p(100, "AcDbDimStyleTableRecord");
    tables.p(2, "Standard");
    tables.p(70, 0);
    tables.p(0, "ENDTAB");
    // BLOCK_RECORD.
    table(&mut tables, "BLOCK_RECORD", "1", 2);
    for (name, handle, layout) in [("*Model_Space", "1F", "1A"), ("*Paper_Space", "1E", "1B")] {
        tables.p(0, "BLOCK_RECORD");
        tables.p(5, handle);
        tables.p(330, 1);
        tables.p(100, "AcDbSymbolTableRecord");
        tables.p(100, "AcDbBlockTableRecord");
        tables.p(2, name);
        tables.p(340, layout);
        tables.p(70, 0);
        tables.p(280, 1);
        tables.p(281, 0);
    }
    tables.p(0, "ENDTAB");

    // BLOCKS.
    let mut blocks = W::new();
    for (name, rec, begin, end, paper) in [
        ("*Model_Space", "1F", "1C", "1D", false),
        ("*Paper_Space", "1E", "18", "19", true),
    ] {
        blocks.p(0, "BLOCK");
        blocks.p(5, begin);
        blocks.p(330, rec);
        blocks.p(100, "AcDbEntity");
        if paper {
            blocks.p(67, 1);
        }
        blocks.p(8, 0);
        blocks.p(100, "AcDbBlockBegin");
        blocks.p(2, name);
        blocks.p(70, 0);
        blocks.pt(10, (0.0, 0.0));
        blocks.p(3, name);
        blocks.p(1, "");
        blocks.p(0, "ENDBLK");
        blocks.p(5, end);
        blocks.p(330, rec);
        blocks.p(100, "AcDbEntity");
        if paper {
            blocks.p(67, 1);
        }
        blocks.p(8, 0);
        blocks.p(100, "AcDbBlockEnd");
    }

    // OBJECTS: the root dictionary (C), the groups (D), the layouts (E)
    // with Model (1A) and Layout1 (1B), the plot styles (F, 10).
    let mut objs = W::new();
    let dict = |o: &mut W, handle: &str, owner: &str, items: &[(&str, &str)]| {
        o.p(0, "DICTIONARY");
        o.p(5, handle);
        o.p(330, owner);
        o.p(100, "AcDbDictionary");
        o.p(281, 1);
        for (k, v) in items {
            o.p(3, k);
            o.p(350, v);
        }
    };
    dict(
        &mut objs,
        "C",
        "0",
        &[
            ("ACAD_GROUP", "D"),
            ("ACAD_LAYOUT", "E"),
            ("ACAD_PLOTSTYLENAME", "B"),
        ],
    );
    dict(&mut objs, "D", "C", &[]);
    dict(&mut objs, "E", "C", &[("Layout1", "1B"), ("Model", "1A")]);
    // The plot style names: a dictionary with a default of "Normal".
    objs.p(0, "ACDBDICTIONARYWDFLT");
    objs.p(5, "B");
    objs.p(330, "C");
    objs.p(100, "AcDbDictionary");
    objs.p(281, 1);
    objs.p(3, "Normal");
    objs.p(350, "F");
    objs.p(100, "AcDbDictionaryWithDefault");
    objs.p(340, "F");
    objs.p(0, "ACDBPLACEHOLDER");
    objs.p(5, "F");
    objs.p(330, "B");
    for (name, handle, rec, order) in [("Model", "1A", "1F", 0), ("Layout1", "1B", "1E", 1)] {
        objs.p(0, "LAYOUT");
        objs.p(5, handle);
        objs.p(330, "E");
        objs.p(100, "AcDbPlotSettings");
        objs.p(1, "");
        objs.p(4, if order == 0 { "" } else { "ISO_A4_(297.00_x_210.00_MM)" });
        objs.p(6, "");
        objs.p(40, 0);
        objs.p(41, 0);
        objs.p(42, 0);
        objs.p(43, 0);
        objs.p(44, num(w));
        objs.p(45, num(h));
        objs.p(46, 0);
        objs.p(47, 0);
        objs.p(48, 0);
        objs.p(49, 0);
        objs.p(140, 0);
        objs.p(141, 0);
        objs.p(142, 1);
        objs.p(143, 1);
        objs.p(70, if order == 0 { 1712 } else { 688 });
        objs.p(72, 1);
        objs.p(73, 0);
        objs.p(74, 5);
        objs.p(7, "");
        objs.p(75, 16);
        objs.p(147, 1);
        objs.p(148, 0);
        objs.p(149, 0);
        objs.p(100, "AcDbLayout");
        objs.p(1, name);
        objs.p(70, 1);
        objs.p(71, order);
        objs.pt(10, (0.0, 0.0));
        objs.pt(11, (w, h));
        objs.pt(12, (0.0, 0.0));
        objs.pt(14, (0.0, 0.0));
        objs.pt(15, (w, h));
        objs.p(146, 0);
        objs.pt(13, (0.0, 0.0));
        objs.pt(16, (1.0, 0.0));
        objs.pt(17, (0.0, 1.0));
        objs.p(76, 0);
        objs.p(330, rec);
    }

    // HEADER, now that the handles are counted.
    let mut head = W::new();
    let var = |o: &mut W, name: &str| o.p(9, name);
    var(&mut head, "$ACADVER");
    head.p(1, "AC1021");
    var(&mut head, "$DWGCODEPAGE");
    head.p(3, "ANSI_1252");
    var(&mut head, "$HANDSEED");
    head.p(5, format!("{:X}", d.next + 1));
    var(&mut head, "$INSUNITS");
    head.p(70, 4);
    var(&mut head, "$MEASUREMENT");
    head.p(70, 1);
    var(&mut head, "$LUNITS");
    head.p(70, 2);
    var(&mut head, "$EXTMIN");
    head.pt(10, (0.0, 0.0));
    var(&mut head, "$EXTMAX");
    head.pt(10, (w, h));
    var(&mut head, "$LIMMIN");
    head.p(10, 0);
    head.p(20, 0);
    var(&mut head, "$LIMMAX");
    head.p(10, num(w));
    head.p(20, num(h));
    var(&mut head, "$LTSCALE");
    head.p(40, 1);
    var(&mut head, "$PSLTSCALE");
    head.p(70, 0);
    var(&mut head, "$LWDISPLAY");
    head.p(290, 1);
    var(&mut head, "$TEXTSTYLE");
    head.p(7, STYLE);
    var(&mut head, "$CLAYER");
    head.p(8, 0);

    let mut out = String::new();
    let section = |out: &mut String, name: &str, body: &str| {
        let _ = write!(out, "  0\nSECTION\n  2\n{name}\n{body}  0\nENDSEC\n");
    };
    section(&mut out, "HEADER", &head.out);
    section(&mut out, "CLASSES", "");
    section(&mut out, "TABLES", &tables.out);
    section(&mut out, "BLOCKS", &blocks.out);
    section(&mut out, "ENTITIES", &ents.out);
    section(&mut out, "OBJECTS", &objs.out);
    out += "  0\nEOF\n";
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arcs_become_bulges() {
        // A quarter circle CCW on the sheet (sweep 0 in SVG).
        let subs = path_subpaths("M10 0 A10 10 0 0 0 0 -10", |x, y| (x, -y)).unwrap();
        let (pts, closed) = &subs[0];
        assert!(!closed);
        assert!((pts[0].1 - (std::f64::consts::FRAC_PI_8).tan()).abs() < 1e-12);
    }

    #[test]
    fn texts_escape_past_ascii() {
        assert_eq!(escape("φ\n= 5°"), "φ = 5°");
        assert_eq!(
            mtext_content(&[("a".into(), 0), ("n".into(), 1), ("KC".into(), -1)]),
            "a{\\Sn^KC;}"
        );
    }
}
