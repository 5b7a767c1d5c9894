//! Reading a plan drawn in a vector editor (Inkscape): text labels placed
//! next to points (p_v, a, b …) and line segments between them. Each label
//! names the segment end nearest to it; coordinates are taken relative to
//! the pole's point, y up, in millimetres (group and element transforms
//! resolved here, each element's from its parent's).
//!
//! Reading is linear in the file's size: the file is at most
//! [`super::answer::MAX_ANSWER_BYTES`] long, its elements nested at most [`MAX_DEPTH`]
//! deep (the XML parser, roxmltree, recurses once per level; deeper files
//! are refused before parsing, by a linear scan), each element's transform
//! is composed once from its parent's, and the line end nearest to a label
//! is found in a grid of cells of the snapping distance.

use super::answer::{Answer, Given, Item, check_size};
use crate::error::{Error, Issue, Result};
use crate::kinematics::construction::PlanKind;
use kurbo::Point;
use std::collections::{HashMap, HashSet};

/// The deepest nesting of elements read (an editor's layers and groups
/// nest a few levels; 20 000 nested groups overflowed the parser's stack).
pub const MAX_DEPTH: usize = 256;

/// How far from a line's end its label may be, mm.
const SNAP_MM: f64 = 8.0;

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

/// The line ends in cells of [`SNAP_MM`]: the nearest end within that
/// distance of a label is in the label's cell or one of its eight
/// neighbours.
struct Ends {
    ends: Vec<Point>,
    cells: HashMap<(i64, i64), Vec<usize>>,
}

impl Ends {
    fn cell(p: Point) -> (i64, i64) {
        // `as` saturates: far-off coordinates share the outermost cells.
        (
            (p.x / SNAP_MM).floor() as i64,
            (p.y / SNAP_MM).floor() as i64,
        )
    }

    fn new(ends: Vec<Point>) -> Ends {
        let mut cells: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
        for (k, p) in ends.iter().enumerate() {
            if p.x.is_finite() && p.y.is_finite() {
                cells.entry(Ends::cell(*p)).or_default().push(k);
            }
        }
        Ends { ends, cells }
    }

    /// The end nearest to `at` if it is within [`SNAP_MM`] (of equally
    /// near ends, the first drawn).
    fn snap(&self, at: Point) -> Option<Point> {
        if !(at.x.is_finite() && at.y.is_finite()) {
            return None;
        }
        let (cx, cy) = Ends::cell(at);
        let mut best: Option<(f64, usize)> = None;
        for dx in -1..=1i64 {
            for dy in -1..=1i64 {
                let key = (cx.saturating_add(dx), cy.saturating_add(dy));
                for &k in self.cells.get(&key).into_iter().flatten() {
                    let d = (self.ends[k] - at).hypot();
                    if d <= SNAP_MM && best.is_none_or(|(bd, bk)| d < bd || (d == bd && k < bk)) {
                        best = Some((d, k));
                    }
                }
            }
        }
        best.map(|(_, k)| self.ends[k])
    }
}

/// What a drawing holds: its text labels (their text and where they are,
/// mm, y down as drawn) and its lines (each path or line element's
/// points in order, mm). Every problem names `svg`.
pub(super) struct Drawing {
    pub labels: Vec<(String, Point)>,
    pub lines: Vec<Vec<Point>>,
}

/// Parse an answer drawn in a vector editor into its labels and lines.
pub(super) fn parse(text: &str) -> Result<Drawing> {
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
    for n in doc.descendants().filter(|n| n.is_element()) {
        match n.tag_name().name() {
            "text" => labels.extend(page.label(n)),
            "path" => page.path(n, &mut lines),
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
    }
    Ok(Drawing { labels, lines })
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
        for n in doc.descendants() {
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
            }
            transforms[id] = parent * own;
        }
        Page {
            transforms,
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

/// The scale a drawing states in a text such as "μ_v = 0.01 (m/s)/mm",
/// "μ_F = 2 N/mm" (`prefix`: "" for any μ, "_F" for a force plan's).
pub(super) fn stated_mu(labels: &[(String, Point)], prefix: &str) -> Option<f64> {
    labels.iter().find_map(|(s, _)| {
        let s = s.replace(' ', "");
        let rest = s.strip_prefix('μ').or_else(|| s.strip_prefix("mu"))?;
        let rest = rest.strip_prefix(prefix)?;
        let num: String = rest
            .split('=')
            .nth(1)?
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e' || *c == '-')
            .collect();
        num.parse().ok()
    })
}

/// The names of the pole a drawing may have.
const POLE_NAMES: [&str; 5] = ["p_v", "pv", "p", "p_a", "pa"];

fn is_pole(name: &str) -> bool {
    POLE_NAMES.contains(&name.to_lowercase().as_str())
}

/// A problem of the drawing as a whole: no pointer ("svg" would be read as
/// the option --svg); the file is named by the caller.
fn whole(message: &str) -> Error {
    Error::fields(vec![Issue {
        pointer: String::new(),
        message: message.into(),
    }])
}

/// Read an SVG answer. `mu`, `plan` come from the command line when the
/// drawing does not state them (a "μ = 0.01" text, and the pole's label
/// p_v / p_a); a plan asked that the pole's label contradicts is refused.
pub fn from_svg(
    text: &str,
    mu: Option<f64>,
    plan: Option<PlanKind>,
    delta: f64,
    position: usize,
) -> Result<Answer> {
    let Drawing { labels, lines } = parse(text)?;
    let ends: Vec<Point> = lines.into_iter().flatten().collect();
    // μ from a text such as "μ_v = 0.01 (m/s)/mm" when not given: a
    // scale no plan has is refused where it is said (the option, or the
    // drawing).
    let (mu, said) = match mu {
        Some(m) => (Some(m), "mu"),
        None => (stated_mu(&labels, ""), "svg: label μ"),
    };
    let Some(mu) = mu else {
        return Err(whole(
            "no scale: give --mu or write \"μ = …\" on the drawing",
        ));
    };
    if let Some(i) = super::answer::mu_issue(mu, said) {
        return Err(Error::fields(vec![i]));
    }
    let Some((pole_name, pole_at)) = labels.iter().find(|(s, _)| is_pole(s)).cloned() else {
        return Err(whole("no pole: label the pole p_v (or p_a)"));
    };
    let plan = plan_of(&pole_name, plan)?;
    let ends = Ends::new(ends);
    let Some(pole) = ends.snap(pole_at) else {
        return Err(whole("the pole's label is not next to any line's end"));
    };
    // The pole labelled again at another line end: which is the pole?
    let other_pole = labels
        .iter()
        .filter(|(s, _)| is_pole(s))
        .find_map(|(s, at)| ends.snap(*at).filter(|e| *e != pole).map(|e| (s, e)));
    if let Some((s, e)) = other_pole {
        let rel = e - pole;
        return Err(Error::scene(
            format!("svg: label {s}"),
            format!(
                "the pole is given twice, by labels at different line ends: (0, 0) and ({}, {}) mm from the first; label the pole once",
                crate::format::num(rel.x),
                crate::format::num(-rel.y)
            ),
        ));
    }
    Ok(Answer {
        plan,
        position,
        mu,
        delta,
        items: points(&labels, &ends, pole)?,
        mu_v: None,
        omegas: Vec::new(),
    })
}

/// The plan a drawing is of: `asked` (--plan), else the one the pole's
/// label `pole` names; the two must agree (a velocity plan's pole is p_v,
/// an acceleration plan's p_a).
fn plan_of(pole: &str, asked: Option<PlanKind>) -> Result<PlanKind> {
    let labelled = match pole.to_lowercase().as_str() {
        "p_v" | "pv" => Some(PlanKind::Velocity),
        "p_a" | "pa" => Some(PlanKind::Acceleration),
        _ => None,
    };
    let name = |k: PlanKind| {
        if k == PlanKind::Velocity {
            "velocity"
        } else {
            "acceleration"
        }
    };
    match (asked, labelled) {
        (Some(p), Some(l)) if p != l => Err(Error::scene(
            "plan",
            format!(
                "the plan asked is the {} plan, but the drawing's pole is labelled \"{pole}\", the {} plan's pole: give --plan {} or label the pole {}",
                name(p),
                name(l),
                name(l),
                if p == PlanKind::Velocity { "p_v" } else { "p_a" }
            ),
        )),
        (Some(p), _) | (None, Some(p)) => Ok(p),
        (None, None) => Err(whole(
            "which plan is it? label the pole p_v or p_a, or give --plan",
        )),
    }
}

/// The labelled points of a drawing: each label (but the pole's and
/// texts with "=") at the line end nearest to it, mm from the `pole`'s
/// end, y up; a place off any sheet is refused.
fn points(labels: &[(String, Point)], ends: &Ends, pole: Point) -> Result<Vec<Item>> {
    let mut items: Vec<Item> = Vec::new();
    let mut issues = Vec::new();
    // The labels read so far: (name in lower case, place's bits).
    let mut read: HashSet<(String, [u64; 2])> = HashSet::new();
    for (name, at) in labels {
        if name.is_empty() || is_pole(name) || name.contains('=') {
            continue;
        }
        let Some(e) = ends.snap(*at) else { continue };
        let rel = e - pole;
        // One label at the same line end twice (a copied text) is one
        // point labelled twice; at another end it gives a second place,
        // refused when the names are resolved (`items::given_twice`).
        if !read.insert((name.to_lowercase(), [rel.x.to_bits(), (-rel.y).to_bits()])) {
            continue;
        }
        let pointer = format!("svg: label {name}");
        let far = [rel.x, rel.y]
            .iter()
            .find_map(|&x| super::answer::coordinate_issue(x, &pointer));
        issues.extend(far);
        items.push(Item {
            pointer,
            key: name.clone(),
            given: Given::Point {
                name: name.clone(),
                at: [rel.x, -rel.y],
            },
        });
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    if items.is_empty() {
        return Err(whole("no labelled points next to line ends were found"));
    }
    Ok(items)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid finds what a search of every end finds: the nearest end
    /// within the snapping distance, the first drawn of equally near ones.
    #[test]
    fn snapping_in_cells_agrees_with_a_search_of_every_end() {
        let mut r: u64 = 7;
        let mut next = || {
            r = r
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (r >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut ends: Vec<Point> = (0..2000)
            .map(|_| Point::new(300.0 * next() - 50.0, 300.0 * next() - 50.0))
            .collect();
        // Repeated ends, ends on cell borders, far-off and non-finite ones.
        ends.extend_from_slice(&[
            ends[3],
            Point::new(16.0, 24.0),
            Point::new(24.0, 24.0),
            Point::new(1e300, -1e300),
            Point::new(f64::NAN, 0.0),
        ]);
        let grid = Ends::new(ends.clone());
        let brute = |at: Point| {
            ends.iter()
                .copied()
                .min_by(|a, b| (*a - at).hypot().total_cmp(&(*b - at).hypot()))
                .filter(|e| (*e - at).hypot() <= SNAP_MM)
        };
        let mut probes: Vec<Point> = (0..5000)
            .map(|_| Point::new(320.0 * next() - 60.0, 320.0 * next() - 60.0))
            .collect();
        probes.extend_from_slice(&[
            Point::new(20.0, 24.0),
            Point::new(16.0 + SNAP_MM, 24.0),
            Point::new(1e300, -1e300),
        ]);
        for at in probes {
            assert_eq!(grid.snap(at), brute(at), "at {at:?}");
        }
    }

    #[test]
    fn nesting_is_counted_past_comments_quotes_and_empty_elements() {
        let t = r#"<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "<g>">]><svg><!-- <g><g> --><g a=">"><![CDATA[<g>]]><path/><g/></g></svg>"#;
        assert_eq!(too_deep(t, 2), None);
        assert!(too_deep(t, 1).is_some());
        assert!(too_deep("<a><b><c>", 2).is_some());
        assert_eq!(too_deep("<a><b></b><b></b></a>", 2), None);
    }
}
