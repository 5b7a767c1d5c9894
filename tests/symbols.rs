//! Layout checks of the symbols themselves, read back from the SVG a user
//! gets, on every position of every fixture: the input's ω1/ε1 arcs clear
//! of hatching and of slider blocks; hatching clear of the blocks; two
//! blocks apart unless nested (the two blocks of a PRP group pinned at one
//! point) or placed closer than a block's size by the mechanism itself; an
//! arrowhead never longer than 0.4 of its vector (no blobs).

mod common;

use common::sheets;
use kurbo::{Point, Vec2};
use mechplan::drawing::DrawOptions;

/// What the checks read from one sheet (page mm).
#[derive(Default)]
struct Symbols {
    hatch: Vec<(Point, Point)>,
    /// Lines drawn with a vector's class (main or vector) that end in an
    /// arrowhead.
    lines: Vec<(Point, Point)>,
    /// Arcs sampled as polylines.
    arcs: Vec<Vec<Point>>,
    /// Slider blocks: white quadrilaterals.
    blocks: Vec<[Point; 4]>,
    /// Arrowheads: tip and the middle of the base.
    arrows: Vec<(Point, Point)>,
}

fn num(n: &roxmltree::Node, a: &str) -> f64 {
    n.attribute(a).unwrap().parse().unwrap()
}

fn points(s: &str) -> Vec<Point> {
    let v: Vec<f64> = s
        .split([' ', ','])
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap())
        .collect();
    v.chunks(2).map(|c| Point::new(c[0], c[1])).collect()
}

/// An SVG circular arc `M x0 y0 A r r 0 large sweep x1 y1`, sampled.
fn arc(d: &str) -> Vec<Point> {
    let t: Vec<f64> = d
        .replace(['M', 'A'], " ")
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    let (p0, r, large, sweep, p1) = (
        Point::new(t[0], t[1]),
        t[2],
        t[5] != 0.0,
        t[6] != 0.0,
        Point::new(t[7], t[8]),
    );
    let m = p0.midpoint(p1);
    let half = (p1 - p0).hypot() / 2.0;
    let off = (r * r - half * half).max(0.0).sqrt();
    let n = Vec2::new(-(p1 - p0).y, (p1 - p0).x).normalize();
    for c in [m + n * off, m - n * off] {
        let (a0, a1) = ((p0 - c).atan2(), (p1 - c).atan2());
        // In page coordinates sweep-flag 1 is the increasing angle.
        let tau = std::f64::consts::TAU;
        let delta = if sweep {
            (a1 - a0).rem_euclid(tau)
        } else {
            -(a0 - a1).rem_euclid(tau)
        };
        if (delta.abs() > std::f64::consts::PI) == large {
            return (0..=24)
                .map(|k| c + Vec2::from_angle(a0 + delta * k as f64 / 24.0) * r)
                .collect();
        }
    }
    panic!("no centre for the arc {d}");
}

fn read(svg: &str) -> Symbols {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let mut s = Symbols::default();
    for n in doc.descendants().filter(|n| n.is_element()) {
        let class = n.attribute("class").unwrap_or("");
        match n.tag_name().name() {
            "line" => {
                let seg = (
                    Point::new(num(&n, "x1"), num(&n, "y1")),
                    Point::new(num(&n, "x2"), num(&n, "y2")),
                );
                match class {
                    "hatch" => s.hatch.push(seg),
                    "main" | "vector" => s.lines.push(seg),
                    _ => {}
                }
            }
            "path" if class == "arc" => s.arcs.push(arc(n.attribute("d").unwrap())),
            "polygon" => {
                let pts = points(n.attribute("points").unwrap());
                if class == "arrow" {
                    s.arrows.push((pts[0], pts[1].midpoint(pts[2])));
                } else if n.attribute("fill") == Some("white") && pts.len() == 4 {
                    s.blocks.push([pts[0], pts[1], pts[2], pts[3]]);
                }
            }
            _ => {}
        }
    }
    s
}

fn seg_dist(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.hypot2().max(1e-18)).clamp(0.0, 1.0);
    (p - (a + ab * t)).hypot()
}

/// Strictly inside a convex quadrilateral, by `margin` (mm).
fn inside(q: &[Point; 4], p: Point, margin: f64) -> bool {
    let sign = (q[1] - q[0]).cross(q[2] - q[1]).signum();
    (0..4).all(|i| {
        let (a, b) = (q[i], q[(i + 1) % 4]);
        sign * (b - a).cross(p - a) / (b - a).hypot() > margin
    })
}

fn centre(q: &[Point; 4]) -> Point {
    q[0].midpoint(q[2])
}

/// Every defect found on one sheet, described.
fn defects(svg: &str) -> Vec<String> {
    let s = read(svg);
    let mut out = Vec::new();
    // Strokes are 0.25–0.5 mm wide: apart by more than their half-widths.
    let clear = 0.4;
    for a in &s.arcs {
        for &p in a {
            if let Some(h) = s.hatch.iter().find(|h| seg_dist(p, h.0, h.1) < clear) {
                out.push(format!("an arc crosses hatching at {h:?}"));
                break;
            }
            if s.blocks.iter().any(|b| inside(b, p, -clear)) {
                out.push(format!("an arc crosses a block near {p:?}"));
                break;
            }
        }
    }
    for h in &s.hatch {
        let mid = h.0.midpoint(h.1);
        if let Some(b) = s
            .blocks
            .iter()
            .find(|b| inside(b, h.0, 0.1) || inside(b, h.1, 0.1) || inside(b, mid, 0.1))
        {
            out.push(format!("hatching {h:?} inside the block {b:?}"));
        }
    }
    for (i, a) in s.blocks.iter().enumerate() {
        for b in &s.blocks[i + 1..] {
            let nested =
                a.iter().all(|&p| inside(b, p, -0.01)) || b.iter().all(|&p| inside(a, p, -0.01));
            // Two blocks whose pairs the mechanism itself puts within a
            // block's length of each other cannot be drawn apart.
            let close = (centre(a) - centre(b)).hypot() < 10.0;
            let overlap =
                a.iter().any(|&p| inside(b, p, 0.1)) || b.iter().any(|&p| inside(a, p, 0.1));
            if overlap && !nested && !close {
                out.push(format!("blocks {a:?} and {b:?} overlap"));
            }
        }
    }
    for &(tip, base) in &s.arrows {
        let head = (tip - base).hypot();
        // The arrowhead's vector: the line ending at its tip along it.
        let along = s.lines.iter().filter_map(|&(a, b)| {
            let (from, to) = if (b - tip).hypot() < 1e-3 {
                (a, b)
            } else if (a - tip).hypot() < 1e-3 {
                (b, a)
            } else {
                return None;
            };
            let d = to - from;
            // The sheet writes coordinates to 0.01 mm: the head's direction
            // is known to about 0.01 mm over its length.
            let tol = 1e-3 + 0.01 / head.max(0.1);
            ((d.normalize() - (tip - base).normalize()).hypot() < tol).then_some(d.hypot())
        });
        let len = along.fold(None, |m: Option<f64>, l| Some(m.map_or(l, |m| m.max(l))));
        if let Some(len) = len.filter(|&len| head > 0.4 * len + 0.02) {
            out.push(format!(
                "an arrowhead of {head:.2} mm on a vector of {len:.2} mm at {tip:?}"
            ));
        }
    }
    out
}

fn fixtures() -> Vec<(String, String)> {
    let dir = format!("{}/fixtures", env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.ok()?.path();
            (p.extension()? == "json").then(|| {
                (
                    p.file_stem().unwrap().to_str().unwrap().to_string(),
                    std::fs::read_to_string(&p).unwrap(),
                )
            })
        })
        .collect();
    names.sort();
    names
}

#[test]
fn symbols_keep_clear_of_each_other() {
    let mut found = Vec::new();
    let mut checked = (0, 0, 0);
    for (name, text) in fixtures() {
        let study = mechplan::Study::from_json(&text).unwrap();
        let solution = study.solve().unwrap();
        for sheet in sheets(study.analysis(), solution.solved(), &DrawOptions::default()) {
            if sheet.name == "positions" {
                continue;
            }
            let s = read(&sheet.svg);
            checked.0 += s.arcs.len();
            checked.1 += s.blocks.len();
            checked.2 += s.arrows.len();
            for d in defects(&sheet.svg) {
                found.push(format!("{name}/{}: {d}", sheet.name));
            }
        }
    }
    // The checks saw what they judge.
    assert!(
        checked.0 > 50 && checked.1 > 50 && checked.2 > 500,
        "{checked:?}"
    );
    assert!(
        found.is_empty(),
        "{} defects:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The checks catch what they are for: a hand-made sheet with each defect.
#[test]
fn the_checks_catch_each_defect() {
    let page = |body: &str| {
        format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 297 210">{body}</svg>"#)
    };
    let block =
        r#"<polygon points="100 100 110 100 110 106 100 106" fill="white" stroke="black"/>"#;
    let ok = page(&format!(
        r#"{block}<line class="hatch" x1="90" y1="95" x2="120" y2="95"/><line class="main" x1="0" y1="0" x2="20" y2="0"/><polygon class="arrow" points="20 0 17 0.7 17 -0.7"/>"#
    ));
    assert!(defects(&ok).is_empty(), "{:?}", defects(&ok));
    let hatch_in_block = page(&format!(
        r#"{block}<line class="hatch" x1="90" y1="103" x2="120" y2="103"/>"#
    ));
    assert_eq!(defects(&hatch_in_block).len(), 1);
    let arc_on_hatch = page(
        r#"<line class="hatch" x1="40" y1="48" x2="60" y2="48"/><path class="arc" d="M45 46 A6 6 0 0 0 55 46"/>"#,
    );
    assert_eq!(
        defects(&arc_on_hatch).len(),
        1,
        "{:?}",
        defects(&arc_on_hatch)
    );
    let blob = page(
        r#"<line class="vector" x1="0" y1="0" x2="4" y2="0"/><polygon class="arrow" points="4 0 1 0.7 1 -0.7"/>"#,
    );
    assert_eq!(defects(&blob).len(), 1);
    let crossing = page(&format!(
        r#"{block}<polygon points="108 103 128 103 128 109 108 109" fill="white" stroke="black"/>"#
    ));
    assert_eq!(defects(&crossing).len(), 1);
}
