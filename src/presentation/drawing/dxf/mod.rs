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
//!   height the font size in mm, in the style `lc_opengost-ar` (LibreCAD
//!   takes that name for its ГОСТ font; the font file, for the others, is
//!   DejaVu Sans: both carry Cyrillic and Greek), in UTF-8 (R2007 and later: no code
//!   page, no `\U+XXXX` escapes for a reader to decode);
//! - a symbol the renderer groups (`<g data-symbol=…>`: a joint, a fixed
//!   pivot, a slider block, a centre of mass) → an INSERT, on the layer of
//!   its kind, of a block holding its entities about its base point
//!   (`blocks`: symbols alike share a block, `JOINT`, `PIVOT`, …);
//! - layers by the element's `class`, each with its ГОСТ 2.303 linetype
//!   and lineweight; each entity also carries its own lineweight (370), the
//!   stroke width of the SVG.
//!
//! The writer is this module's own (no DXF crate): the `dxf` crate (0.6.2)
//! has no HATCH entity and would bring a dozen crates (chrono, image,
//! uuid, …) for the fifteen kinds of record written here.

mod blocks;
mod document;
mod entities;
pub mod overlay;
mod style;

use crate::error::{Error, Result};
use blocks::{Block, insert_symbol};
use document::document;
use entities::{Common, Entities, Target, W};
use style::escape;
use std::fmt::Write as _;

/// DXF's lineweights (1/100 mm) a CAD accepts.
const WEIGHTS: [i32; 24] = [
    0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200,
    211,
];

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
/// `\Sx^;`. A stack ends at its `;`: no braces round it, which add
/// nothing and which LibreCAD (2.2) prints as they are.
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
                    "\\S{}^{};",
                    mtext_escape(&stack(t)),
                    mtext_escape(&stack(&sub))
                );
            }
            _ => {
                let _ = write!(out, "\\S^{};", mtext_escape(&stack(t)));
            }
        }
        i += 1;
    }
    out
}

/// A number attribute of an element.
fn f(n: &roxmltree::Node, a: &str) -> Option<f64> {
    n.attribute(a).and_then(|v| v.parse::<f64>().ok())
}

/// A map of the page's points to the DXF's: the sheet's y-up
/// coordinates, or a block's own.
type Place<'a> = &'a dyn Fn(f64, f64) -> (f64, f64);

/// One element of the sheet as its entities, its points mapped by `flip`.
fn element(e: &mut Entities, n: roxmltree::Node, (w, h): (f64, f64), flip: Place) -> Result<()> {
    let class = n.attribute("class").unwrap_or("").to_string();
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
        "text" => text_element(e, n, flip, w, &class),
        _ => {}
    }
    Ok(())
}

/// A text: TEXT when plain, MTEXT with its sub- and superscripts.
fn text_element(
    e: &mut Entities,
    n: roxmltree::Node,
    flip: impl Fn(f64, f64) -> (f64, f64),
    w: f64,
    class: &str,
) {
        let at = flip(f(&n, "x").unwrap_or(0.0), f(&n, "y").unwrap_or(0.0));
        let size = f(&n, "font-size").unwrap_or(3.5);
        let anchor = n.attribute("text-anchor").unwrap_or("start");
        let rs = runs(n);
        let tl = text_layer(class);
        let c = Common {
            layer: tl,
            color: n.attribute("fill").and_then(aci),
            weight: None,
        };
        // R12 has no MTEXT: sub- and superscripts written as a person
        // types them (a^n_KC).
        let plain = |rs: &[(String, i32)]| -> String {
            rs.iter()
                .map(|(t, k)| match k {
                    0 => t.clone(),
                    1 => format!("^{t}"),
                    _ => format!("_{t}"),
                })
                .collect()
        };
        if rs.iter().all(|r| r.1 == 0) || e.target.legacy {
            let s = plain(&rs);
            // A field narrowed to its cell (the title block's, SVG
            // `textLength`) keeps its height and is narrowed by TEXT's
            // width factor, by the renderer's estimate of its width.
            let factor = f(&n, "textLength")
                .map(|len| {
                    let natural = crate::presentation::drawing::canvas::runs_width(
                        &crate::words::notation::runs(&s),
                        size,
                    );
                    (len / natural).clamp(0.1, 1.0)
                })
                .unwrap_or(1.0);
            if !s.trim().is_empty() {
                e.text(&c, at, (size, factor), &s, anchor);
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

/// The elements under `n` in the order drawn: a symbol's group
/// (`data-symbol`) as a block's INSERT, anything else as its entities.
fn walk(e: &mut Entities, defs: &mut Vec<Block>, n: roxmltree::Node, wh: (f64, f64)) -> Result<()> {
    let flip = |x: f64, y: f64| (x, wh.1 - y);
    for ch in n.children().filter(|c| c.is_element()) {
        if ch.has_tag_name("g") && ch.attribute("data-symbol").is_some() {
            symbol(e, defs, ch, wh)?;
        } else {
            element(e, ch, wh, &flip)?;
            walk(e, defs, ch, wh)?;
        }
    }
    Ok(())
}

/// A symbol's group `g` (`data-symbol`, its base point `data-x`,
/// `data-y` and turn `data-angle` on the page) as the INSERT of its block,
/// the block's entities about the base point, turned back by the angle.
fn symbol(
    e: &mut Entities,
    defs: &mut Vec<Block>,
    g: roxmltree::Node,
    (w, h): (f64, f64),
) -> Result<()> {
    let kind = g.attribute("data-symbol").unwrap_or("symbol");
    let (Some(x), Some(y)) = (f(&g, "data-x"), f(&g, "data-y")) else {
        return Err(Error::Internal(format!(
            "the symbol {kind} has no base point (data-x, data-y)"
        )));
    };
    let deg = f(&g, "data-angle").unwrap_or(0.0);
    let base = (x, h - y);
    let (sin, cos) = (-deg.to_radians()).sin_cos();
    let local = move |px: f64, py: f64| {
        let (dx, dy) = (px - base.0, (h - py) - base.1);
        (dx * cos - dy * sin, dx * sin + dy * cos)
    };
    let draw = |into: &mut Entities| -> Result<()> {
        for n in g.descendants().skip(1).filter(|n| n.is_element()) {
            element(into, n, (w, h), &local)?;
        }
        Ok(())
    };
    insert_symbol(e, defs, (kind, base, deg), &draw)
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
    let mut e = Entities {
        w: W::new(),
        // Handles of the tables and blocks first: fixed, below 0x20.
        owner: "1F".into(),
        layers: vec!["0".into()],
        target: Target::sheet(),
    };
    // Handles of the tables and blocks first: fixed, below 0x20.
    e.owner = "1F".into();
    let mut defs: Vec<Block> = Vec::new();
    walk(&mut e, &mut defs, root, (w, h))?;
    let Entities {
        w: ents, layers, ..
    } = e;
    Ok(document((w, h), &layers, &defs, ents))
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
        assert_eq!(escape("0,837 ↺ 0,934 ↻"), "0,837 ⥀ 0,934 ⥁");
        assert_eq!(escape("I(0,1) → II(2,3)"), "I(0,1) -> II(2,3)");
        assert_eq!(
            mtext_content(&[("a".into(), 0), ("n".into(), 1), ("KC".into(), -1)]),
            "a\\Sn^KC;"
        );
    }
}
