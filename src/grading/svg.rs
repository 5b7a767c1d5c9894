//! Reading a plan drawn in a vector editor (Inkscape) into a [`Drawing`]:
//! its text labels and its lines in millimetres (group and element
//! transforms resolved here, each element's from its parent's); how a
//! drawing is read as an answer is shared with DXF ([`super::drawing`]).
//!
//! Reading is linear in the file's size: the file is at most
//! [`super::answer::MAX_ANSWER_BYTES`] long, its elements nested at most [`MAX_DEPTH`]
//! deep (the XML parser, roxmltree, recurses once per level; deeper files
//! are refused before parsing, by a linear scan), each element's transform
//! is composed once from its parent's.

use super::answer::check_size;
use super::arrows::{self, Head};
use super::drawing::{Drawing, whole};
use crate::error::Result;
use kurbo::Point;

/// The deepest nesting of elements read (an editor's layers and groups
/// nest a few levels; 20 000 nested groups overflowed the parser's stack).
pub const MAX_DEPTH: usize = 256;

/// The first place where elements nest deeper than `limit`: (byte offset,
/// line), by a linear scan of the text that skips comments, CDATA,
/// processing instructions, the DOCTYPE and quoted attribute values. The
/// parser checks the XML itself; this only bounds its recursion.
fn too_deep(text: &str, limit: usize) -> Option<(usize, usize)> {
    let b = text.as_bytes();
    let skip_to = |from: usize, end: &str| {
        text[from..]
            .find(end)
            .map_or(text.len(), |k| from + k + end.len())
    };
    let (mut i, mut depth) = (0usize, 0usize);
    while let Some(k) = text[i..].find('<') {
        let at = i + k;
        let rest = &text[at..];
        i = if rest.starts_with("<!--") {
            skip_to(at + 4, "-->")
        } else if rest.starts_with("<![CDATA[") {
            skip_to(at + 9, "]]>")
        } else if rest.starts_with("<?") {
            skip_to(at + 2, "?>")
        } else if rest.starts_with("<!") {
            // A DOCTYPE, with its internal subset in brackets.
            let mut j = at + 2;
            let mut brackets = 0usize;
            while j < b.len() {
                match b[j] {
                    b'[' => brackets += 1,
                    b']' => brackets = brackets.saturating_sub(1),
                    b'>' if brackets == 0 => break,
                    _ => {}
                }
                j += 1;
            }
            j + 1
        } else if rest.starts_with("</") {
            depth = depth.saturating_sub(1);
            skip_to(at + 2, ">")
        } else {
            // A start tag: to its '>' outside quoted values.
            let mut j = at + 1;
            let mut quote = None;
            while j < b.len() {
                let c = b[j];
                match quote {
                    Some(q) if c == q => quote = None,
                    Some(_) => {}
                    None if c == b'"' || c == b'\'' => quote = Some(c),
                    None if c == b'>' => break,
                    None => {}
                }
                j += 1;
            }
            if j < b.len() && b[j - 1] != b'/' {
                depth += 1;
                if depth > limit {
                    let line = 1 + b[..at].iter().filter(|&&c| c == b'\n').count();
                    return Some((at, line));
                }
            }
            j + 1
        };
        if i >= text.len() {
            break;
        }
    }
    None
}

/// Parse an answer drawn in a vector editor into its labels and lines.
pub(crate) fn parse(text: &str) -> Result<Drawing> {
    let bad = |m: String| whole(&m);
    check_size(text.len() as u64)?;
    if let Some((_, line)) = too_deep(text, MAX_DEPTH) {
        return Err(bad(format!(
            "elements nested more than {MAX_DEPTH} deep (at line {line}); an answer's elements (groups, layers) may nest at most {MAX_DEPTH} deep"
        )));
    }
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| bad(format!("not a readable SVG file: {e}")))?;
    let page = Page::of(&doc);
    let mut labels: Vec<(String, Point)> = Vec::new();
    let mut lines: Vec<Vec<Point>> = Vec::new();
    let mut heads = Vec::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        // A marker's, a symbol's or a definition's shapes are not drawn
        // where they stand.
        if page.unseen[n.id().get_usize()] {
            continue;
        }
        let from = lines.len();
        match n.tag_name().name() {
            "text" => labels.extend(page.label(n)),
            "path" => {
                page.path(n, &mut lines);
                let closed = n.attribute("d").is_some_and(|d| d.contains(['z', 'Z']));
                if let (true, true, [line]) = (closed, filled(n), &lines[from..]) {
                    heads.extend(arrows::triangle(line).map(|corners| Head::Triangle {
                        corners,
                        line: Some(from),
                    }));
                }
            }
            "polygon" if filled(n) => {
                let t = page.affine(n);
                let nums: Vec<f64> = n
                    .attribute("points")
                    .unwrap_or("")
                    .split(|c: char| c == ',' || c.is_whitespace())
                    .filter_map(|x| x.parse().ok())
                    .collect();
                let ps: Vec<Point> = nums
                    .chunks_exact(2)
                    .map(|c| page.mm(t * Point::new(c[0], c[1])))
                    .collect();
                heads.extend(arrows::triangle(&ps).map(|corners| Head::Triangle {
                    corners,
                    line: None,
                }));
            }
            "line" => {
                let t = page.affine(n);
                let mut line = Vec::new();
                for (x, y) in [("x1", "y1"), ("x2", "y2")] {
                    if let (Some(x), Some(y)) = (num(n, x), num(n, y)) {
                        line.push(page.mm(t * Point::new(x, y)));
                    }
                }
                lines.push(line);
            }
            _ => {}
        }
        // A marker at the start of its first line or the end of its last.
        if lines.len() > from && matches!(n.tag_name().name(), "path" | "line") {
            for (prop, line, at_end) in [
                ("marker-start", from, false),
                ("marker-end", lines.len() - 1, true),
            ] {
                if property(n, prop).is_some_and(|v| v != "none") {
                    heads.push(Head::Marked { line, at_end });
                }
            }
        }
    }
    Ok(Drawing {
        labels,
        lines,
        kind: "svg",
        heads,
    })
}

/// A presentation property of an element, its own or inherited: an
/// attribute or a `style` declaration, the nearest's (of the element and
/// its [`INHERIT_DEPTH`] nearest ancestors: reading stays linear).
fn property(n: roxmltree::Node, name: &str) -> Option<String> {
    let mut near = n.ancestors().filter(|a| a.is_element()).take(INHERIT_DEPTH);
    near.find_map(|a| {
        let styled = a.attribute("style").and_then(|st| {
            st.split(';').find_map(|d| {
                let (k, v) = d.split_once(':')?;
                (k.trim() == name).then(|| v.trim().to_string())
            })
        });
        styled.or_else(|| a.attribute(name).map(|v| v.trim().to_string()))
    })
}

/// How many of an element's ancestors its presentation is looked up in.
const INHERIT_DEPTH: usize = 16;

/// Whether an element is filled (SVG fills black unless told `none`).
fn filled(n: roxmltree::Node) -> bool {
    property(n, "fill").is_none_or(|v| v != "none")
}

/// An attribute's first number.
fn num(n: roxmltree::Node, a: &str) -> Option<f64> {
    n.attribute(a)
        .and_then(|v| v.split_whitespace().next()?.parse::<f64>().ok())
}

/// A drawing's coordinates: each node's transform to the root's, and the
/// root's user units in mm from its viewBox's origin.
struct Page {
    transforms: Vec<kurbo::Affine>,
    /// Whether each node is inside a `defs`, `marker` or `symbol`.
    unseen: Vec<bool>,
    unit: f64,
    origin: kurbo::Vec2,
}

impl Page {
    fn of(doc: &roxmltree::Document) -> Page {
        let root = doc.root_element();
        // Root user units → mm: the width (in its unit) over the viewBox
        // width; without a viewBox, user units are CSS pixels.
        let width_mm = root
            .attribute("width")
            .and_then(|l| l.parse::<svgtypes::Length>().ok())
            .map(|l| match l.unit {
                svgtypes::LengthUnit::Mm => l.number,
                svgtypes::LengthUnit::Cm => l.number * 10.0,
                svgtypes::LengthUnit::In => l.number * 25.4,
                svgtypes::LengthUnit::Pt => l.number * 25.4 / 72.0,
                _ => l.number * 25.4 / 96.0,
            });
        let vb = root
            .attribute("viewBox")
            .and_then(|v| v.parse::<svgtypes::ViewBox>().ok());
        let unit = match (vb, width_mm) {
            (Some(v), Some(w)) if v.w > 0.0 => w / v.w,
            _ => 25.4 / 96.0,
        };
        let origin = vb.map(|v| kurbo::Vec2::new(v.x, v.y)).unwrap_or_default();
        // The transform from each node's coordinates to the root's: its
        // parent's (found first, in document order) times its own.
        let mut transforms: Vec<kurbo::Affine> = Vec::new();
        let mut unseen: Vec<bool> = Vec::new();
        for n in doc.descendants() {
            let hidden = n.parent().is_some_and(|p| unseen[p.id().get_usize()])
                || matches!(n.tag_name().name(), "defs" | "marker" | "symbol");
            let parent = n
                .parent()
                .map_or(kurbo::Affine::IDENTITY, |p| transforms[p.id().get_usize()]);
            let own = n
                .attribute("transform")
                .and_then(|s| s.parse::<svgtypes::Transform>().ok())
                .map_or(kurbo::Affine::IDENTITY, |tr| {
                    kurbo::Affine::new([tr.a, tr.b, tr.c, tr.d, tr.e, tr.f])
                });
            let id = n.id().get_usize();
            if transforms.len() <= id {
                transforms.resize(id + 1, kurbo::Affine::IDENTITY);
                unseen.resize(id + 1, false);
            }
            transforms[id] = parent * own;
            unseen[id] = hidden;
        }
        Page {
            transforms,
            unseen,
            unit,
            origin,
        }
    }

    fn affine(&self, n: roxmltree::Node) -> kurbo::Affine {
        self.transforms[n.id().get_usize()]
    }

    /// A root point in mm.
    fn mm(&self, p: Point) -> Point {
        ((p - self.origin).to_vec2() * self.unit).to_point()
    }

    /// A text element's content and where it is: the middle of its first
    /// letter, above its baseline (its x, y or its first tspan's).
    fn label(&self, n: roxmltree::Node) -> Option<(String, Point)> {
        let content: String = n
            .descendants()
            .filter(|d| d.is_text())
            .filter_map(|d| d.text())
            .collect();
        // The anchor: the text's x, y (or its first tspan's).
        let (x, y) = n
            .descendants()
            .filter(|d| d.is_element())
            .find_map(|d| Some((num(d, "x")?, num(d, "y")?)))?;
        let size = num(n, "font-size").unwrap_or(4.0);
        // Middle of the text's first letter, above its baseline.
        let at = self.affine(n) * Point::new(x + 0.3 * size, y - 0.35 * size);
        Some((content.trim().to_string(), self.mm(at)))
    }

    /// A path element's lines (a move starts a new one) into `lines`.
    fn path(&self, n: roxmltree::Node, lines: &mut Vec<Vec<Point>>) {
        let t = self.affine(n);
        let mut line = Vec::new();
        for seg in svgtypes::SimplifyingPathParser::from(n.attribute("d").unwrap_or("")).flatten() {
            let p = match seg {
                svgtypes::SimplePathSegment::MoveTo { x, y }
                | svgtypes::SimplePathSegment::LineTo { x, y } => Some((x, y)),
                svgtypes::SimplePathSegment::CurveTo { x, y, .. }
                | svgtypes::SimplePathSegment::Quadratic { x, y, .. } => Some((x, y)),
                svgtypes::SimplePathSegment::ClosePath => None,
            };
            match (seg, p) {
                // A move starts a new line of the path.
                (svgtypes::SimplePathSegment::MoveTo { .. }, Some((x, y))) => {
                    if !line.is_empty() {
                        lines.push(std::mem::take(&mut line));
                    }
                    line.push(self.mm(t * Point::new(x, y)));
                }
                (_, Some((x, y))) => line.push(self.mm(t * Point::new(x, y))),
                _ => {}
            }
        }
        if !line.is_empty() {
            lines.push(line);
        }
    }
}

/// Read an SVG answer. `mu`, `plan` come from the command line when the
/// drawing does not state them (a "μ = 0.01" text, and the pole's label
/// p_v / p_a); a plan asked that the pole's label contradicts is refused.
/// `position` is the number of the position in the study's numbering.
#[cfg(feature = "internals")]
pub fn from_svg(
    text: &str,
    mu: Option<f64>,
    plan: Option<crate::kinematics::construction::PlanKind>,
    delta: f64,
    position: usize,
) -> Result<super::answer::Answer> {
    let position = super::position::StatedPosition::new(position);
    super::drawing::answer_of(parse(text)?, mu, plan, delta, position)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nesting_is_counted_past_comments_quotes_and_empty_elements() {
        let t = r#"<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "<g>">]><svg><!-- <g><g> --><g a=">"><![CDATA[<g>]]><path/><g/></g></svg>"#;
        assert_eq!(too_deep(t, 2), None);
        assert!(too_deep(t, 1).is_some());
        assert!(too_deep("<a><b><c>", 2).is_some());
        assert_eq!(too_deep("<a><b></b><b></b></a>", 2), None);
    }
}
