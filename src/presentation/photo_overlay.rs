//! The overlay of a photographed plan, in the photo's own perspective:
//! an SVG the size of the photo that shows the photo itself (linked, not
//! copied) and over it the rectangle clicked, the plan each step's
//! construction puts from the student's own points (green vectors from
//! the student's pole), the student's points (blue) and each wrong step in
//! red, from where the student drew the point to where it belongs, with
//! its number. A straight line on the sheet is a straight line in the
//! photo, so mapping each segment's ends through the rectangle's
//! homography draws it exactly.

use crate::grading::photo::PhotoReading;
use crate::grading::{Judgement, Report};
use svg::Document;
use svg::node::element::{Circle, Image, Line, Polygon, Rectangle, Text};

/// The overlay SVG of `report` over the photo at `href` (its path from
/// the SVG's folder), `size` its pixels as displayed.
pub fn photo_overlay(report: &Report, reading: &PhotoReading, href: &str, size: (u32, u32)) -> String {
    let (w, h) = (f64::from(size.0), f64::from(size.1));
    // Pens in millimetres of the sheet, drawn in the photo's pixels.
    let mm = reading.px_per_mm.max(0.1);
    let mut doc = Document::new()
        .set("width", w)
        .set("height", h)
        .set("viewBox", (0.0, 0.0, w, h))
        .add(
            Image::new()
                .set("href", href)
                .set("x", 0)
                .set("y", 0)
                .set("width", w)
                .set("height", h)
                .set("preserveAspectRatio", "none"),
        );
    let frame: Vec<String> = reading
        .corners_px
        .iter()
        .map(|c| format!("{:.2},{:.2}", c[0], c[1]))
        .collect();
    doc = doc.add(
        Polygon::new()
            .set("points", frame.join(" "))
            .set("fill", "none")
            .set("stroke", "#b06000")
            .set("stroke-width", 0.3 * mm)
            .set("stroke-dasharray", format!("{} {}", 3.0 * mm, 2.0 * mm)),
    );
    let at = |p: kurbo::Vec2| reading.to_photo([p.x, p.y]);
    let pole = at(kurbo::Vec2::ZERO);
    let label = |p: [f64; 2], text: String, colour: &str| {
        Text::new(text)
            .set("x", p[0] + 1.2 * mm)
            .set("y", p[1] - 1.2 * mm)
            .set("font-family", "sans-serif")
            .set("font-size", 3.5 * mm)
            .set("fill", colour)
    };
    let line = |a: [f64; 2], b: [f64; 2], colour: &str, width: f64| {
        Line::new()
            .set("x1", a[0])
            .set("y1", a[1])
            .set("x2", b[0])
            .set("y2", b[1])
            .set("stroke", colour)
            .set("stroke-width", width * mm)
            .set("stroke-linecap", "round")
    };
    let dot = |p: [f64; 2], colour: &str, r: f64| {
        Circle::new()
            .set("cx", p[0])
            .set("cy", p[1])
            .set("r", r * mm)
            .set("fill", "none")
            .set("stroke", colour)
            .set("stroke-width", 0.35 * mm)
    };
    for s in report.steps.iter().flat_map(|st| &st.steps) {
        let (Some(given), Some(right)) = (at(s.given), at(s.predicted)) else {
            continue;
        };
        if let Some(p0) = pole {
            doc = doc.add(line(p0, right, "#1a7f37", 0.3));
        }
        doc = doc
            .add(dot(given, "#1f5fbf", 0.9))
            .add(label(given, s.point.clone(), "#1f5fbf"));
        if s.judgement == Judgement::Wrong {
            doc = doc
                .add(line(given, right, "#c62828", 0.6))
                .add(dot(right, "#c62828", 1.3))
                .add(label(
                    [right[0], right[1] + 5.0 * mm],
                    format!("{} (step {})", s.point, s.step.0),
                    "#c62828",
                ));
        }
    }
    if let Some(p0) = pole {
        doc = doc.add(dot(p0, "#1f5fbf", 1.2));
    }
    // The legend on a white band: readable over the table around the
    // sheet too.
    doc = doc.add(
        Rectangle::new()
            .set("x", 2.0 * mm)
            .set("y", 1.5 * mm)
            .set("width", 112.0 * mm)
            .set("height", 6.5 * mm)
            .set("fill", "#ffffff")
            .set("fill-opacity", 0.85),
    );
    doc = doc.add(
        Text::new("green: the plan from your own points · blue: your points · red: a wrong step")
            .set("x", 4.0 * mm)
            .set("y", 6.0 * mm)
            .set("font-family", "sans-serif")
            .set("font-size", 4.0 * mm)
            .set("fill", "#222"),
    );
    doc.to_string()
}
