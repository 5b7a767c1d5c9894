//! Reading a plan drawn in a vector editor (Inkscape): text labels placed
//! next to points (p_v, a, b …) and line segments between them. Each label
//! names the segment end nearest to it; coordinates are taken relative to
//! the pole's point, y up, in millimetres (transforms resolved by usvg).

use super::answer::{Answer, Given, Item};
use crate::construction::PlanKind;
use crate::error::{Error, Issue, Result};
use kurbo::Point;

/// Read an SVG answer. `mu`, `plan` come from the command line or the
/// answer JSON when the drawing does not state them ("μ = 0.01" text, and
/// the pole's label p_v / p_a).
pub fn from_svg(
    text: &str,
    mu: Option<f64>,
    plan: Option<PlanKind>,
    delta: f64,
    position: usize,
) -> Result<Answer> {
    let bad = |m: String| {
        Error::Scene(vec![Issue {
            pointer: "svg".into(),
            message: m,
        }])
    };
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| bad(format!("not a readable SVG file: {e}")))?;
    let root = doc.root_element();
    // Root user units → mm: the width (in its unit) over the viewBox width;
    // without a viewBox, user units are CSS pixels.
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
    // The transform from an element's coordinates to the root's.
    let affine = |n: roxmltree::Node| -> kurbo::Affine {
        let mut t = kurbo::Affine::IDENTITY;
        for a in n.ancestors() {
            if let Some(tr) = a
                .attribute("transform")
                .and_then(|s| s.parse::<svgtypes::Transform>().ok())
            {
                t = kurbo::Affine::new([tr.a, tr.b, tr.c, tr.d, tr.e, tr.f]) * t;
            }
        }
        t
    };
    let mm = |p: Point| ((p - origin).to_vec2() * unit).to_point();
    let num = |n: roxmltree::Node, a: &str| {
        n.attribute(a)
            .and_then(|v| v.split_whitespace().next()?.parse::<f64>().ok())
    };
    let mut labels: Vec<(String, Point)> = Vec::new();
    let mut ends: Vec<Point> = Vec::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        match n.tag_name().name() {
            "text" => {
                let content: String = n
                    .descendants()
                    .filter(|d| d.is_text())
                    .filter_map(|d| d.text())
                    .collect();
                // The anchor: the text's x, y (or its first tspan's).
                let pos = n
                    .descendants()
                    .filter(|d| d.is_element())
                    .find_map(|d| Some((num(d, "x")?, num(d, "y")?)));
                if let Some((x, y)) = pos {
                    let size = num(n, "font-size").unwrap_or(4.0);
                    // Middle of the text's first letter, above its baseline.
                    let at = affine(n) * Point::new(x + 0.3 * size, y - 0.35 * size);
                    labels.push((content.trim().to_string(), mm(at)));
                }
            }
            "path" => {
                let t = affine(n);
                for seg in
                    svgtypes::SimplifyingPathParser::from(n.attribute("d").unwrap_or("")).flatten()
                {
                    let p = match seg {
                        svgtypes::SimplePathSegment::MoveTo { x, y }
                        | svgtypes::SimplePathSegment::LineTo { x, y } => Some((x, y)),
                        svgtypes::SimplePathSegment::CurveTo { x, y, .. }
                        | svgtypes::SimplePathSegment::Quadratic { x, y, .. } => Some((x, y)),
                        svgtypes::SimplePathSegment::ClosePath => None,
                    };
                    if let Some((x, y)) = p {
                        ends.push(mm(t * Point::new(x, y)));
                    }
                }
            }
            "line" => {
                let t = affine(n);
                for (x, y) in [("x1", "y1"), ("x2", "y2")] {
                    if let (Some(x), Some(y)) = (num(n, x), num(n, y)) {
                        ends.push(mm(t * Point::new(x, y)));
                    }
                }
            }
            _ => {}
        }
    }
    // μ from a text such as "μ_v = 0.01 (m/s)/mm" when not given.
    let mu = mu.or_else(|| {
        labels.iter().find_map(|(s, _)| {
            let s = s.replace(' ', "");
            let rest = s.strip_prefix('μ').or_else(|| s.strip_prefix("mu"))?;
            let num: String = rest
                .split('=')
                .nth(1)?
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e' || *c == '-')
                .collect();
            num.parse().ok()
        })
    });
    let Some(mu) = mu else {
        return Err(bad(
            "no scale: give --mu or write \"μ = …\" on the drawing".into()
        ));
    };
    let pole_names = ["p_v", "pv", "p", "p_a", "pa"];
    let pole_label = labels
        .iter()
        .find(|(s, _)| pole_names.contains(&s.to_lowercase().as_str()))
        .cloned();
    let Some((pole_name, pole_at)) = pole_label else {
        return Err(bad("no pole: label the pole p_v (or p_a)".into()));
    };
    let plan = plan.or(match pole_name.to_lowercase().as_str() {
        "p_v" | "pv" => Some(PlanKind::Velocity),
        "p_a" | "pa" => Some(PlanKind::Acceleration),
        _ => None,
    });
    let Some(plan) = plan else {
        return Err(bad(
            "which plan is it? label the pole p_v or p_a, or give --plan".into(),
        ));
    };
    let nearest = |at: Point| {
        ends.iter()
            .copied()
            .min_by(|a, b| (*a - at).hypot().total_cmp(&(*b - at).hypot()))
    };
    let snap = |at: Point| nearest(at).filter(|e| (*e - at).hypot() <= 8.0);
    let Some(pole) = snap(pole_at) else {
        return Err(bad("the pole's label is not next to any line's end".into()));
    };
    let mut items = Vec::new();
    for (name, at) in &labels {
        if name.is_empty()
            || pole_names.contains(&name.to_lowercase().as_str())
            || name.contains('=')
        {
            continue;
        }
        let Some(e) = snap(*at) else { continue };
        let rel = e - pole;
        items.push(Item {
            pointer: format!("svg: label {name}"),
            key: name.clone(),
            given: Given::Point {
                name: name.clone(),
                at: [rel.x, -rel.y],
            },
        });
    }
    if items.is_empty() {
        return Err(bad("no labelled points next to line ends were found".into()));
    }
    Ok(Answer {
        plan,
        position,
        mu,
        delta,
        items,
    })
}
