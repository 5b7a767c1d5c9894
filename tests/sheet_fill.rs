//! How much of its field a sheet's drawing spans, measured on the
//! rendered page as a reader sees it: for every fixture, on A4, A3 and A1,
//! every position's plan of the mechanism, plan of velocities and plan of
//! accelerations spans at least half its field's width or height, and 65 %
//! at the median, each plan at its own scale (the one its steps state),
//! chosen for the field of the sheet asked for. `UPDATE_GOLDEN=1` writes the table into
//! docs/gallery/README.md.

mod common;

use common::sheets;
use mechplan::drawing::{DrawOptions, SheetSize, sheet, tree};

/// Rendering resolution: 1 px = 0.85 mm, finer than a label's height.
const DPI: f32 = 30.0;

/// The share of `field` (page mm) that the rendered drawing inside it spans
/// across and down, and how many dark pixels lie in the clearance between
/// the field and the frame on the left, right and below (a drawing or a
/// letter spilled out of its field: none may).
fn span(svg: &str, field: kurbo::Rect) -> ((f64, f64), usize) {
    let t = tree(svg).unwrap();
    let k = DPI / 25.4; // px per mm
    let (w, h) = (
        t.size().width() * 25.4 / 96.0,
        t.size().height() * 25.4 / 96.0,
    );
    let (pw, ph) = ((w * k).ceil() as u32, (h * k).ceil() as u32);
    let mut pix = tiny_skia::Pixmap::new(pw, ph).unwrap();
    // usvg sizes in CSS px (96/in): to our px.
    let s = DPI / 96.0;
    resvg::render(
        &t,
        tiny_skia::Transform::from_scale(s, s),
        &mut pix.as_mut(),
    );
    let k = k as f64;
    let (x0, x1) = ((field.x0 * k).ceil() as u32, (field.x1 * k).floor() as u32);
    let (y0, y1) = ((field.y0 * k).ceil() as u32, (field.y1 * k).floor() as u32);
    let (mut lo, mut hi) = ((u32::MAX, u32::MAX), (0u32, 0u32));
    for y in y0..y1.min(ph) {
        for x in x0..x1.min(pw) {
            let p = pix.pixel(x, y).unwrap();
            if p.red() < 200 || p.green() < 200 || p.blue() < 200 {
                lo = (lo.0.min(x), lo.1.min(y));
                hi = (hi.0.max(x), hi.1.max(y));
            }
        }
    }
    // The clearance, clear of the frame's line and of the field's edge.
    let pad = sheet::PAD * k;
    let (near, far) = ((pad - 1.5 * k) as u32, (0.5 * k).ceil() as u32);
    let dark = |x: u32, y: u32| {
        let p = pix.pixel(x, y).unwrap();
        p.red() < 200 || p.green() < 200 || p.blue() < 200
    };
    let mut spilled = 0;
    for y in y0..(y1 + near).min(ph) {
        for x in (x0 - near..x0 - far).chain(x1 + far..(x1 + near).min(pw)) {
            spilled += usize::from(dark(x, y));
        }
    }
    for y in (y1 + far..(y1 + near).min(ph)).filter(|_| y1 + near < ph) {
        for x in x0..x1.min(pw) {
            spilled += usize::from(dark(x, y));
        }
    }
    if hi.0 < lo.0 {
        return ((0.0, 0.0), spilled);
    }
    (
        (
            (hi.0 - lo.0 + 1) as f64 / (x1 - x0) as f64,
            (hi.1 - lo.1 + 1) as f64 / (y1 - y0) as f64,
        ),
        spilled,
    )
}

#[test]
fn drawings_fill_their_field_on_every_sheet_size() {
    let dir = format!("{}/fixtures", env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.ok()?.path();
            (p.extension()? == "json").then(|| p.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    names.sort();
    let sizes = [SheetSize::A4, SheetSize::A3, SheetSize::A1];
    let mut rows = Vec::new();
    let mut all: Vec<(f64, String)> = Vec::new();
    for name in &names {
        let text = std::fs::read_to_string(format!("{dir}/{name}.json")).unwrap();
        let scene = mechplan::Study::from_json(&text).unwrap();
        let mut cells = Vec::new();
        for size in sizes {
            // The plans at the scales of this sheet's field, as `draw
            // --sheet` solves them.
            let study = scene
                .for_sheets(&mechplan::DrawRequest {
                    sheet: Some(size),
                    ..mechplan::DrawRequest::default()
                })
                .unwrap();
            let solution = study.solve().unwrap();
            let opt = DrawOptions {
                sheet: size,
                ..DrawOptions::default()
            };
            let field = sheet::field(size, false, 0.0);
            let mut spans = Vec::new();
            for s in sheets(study.analysis(), solution.solved(), &opt) {
                let kind = ["mechanism_", "velocity_", "acceleration_"]
                    .into_iter()
                    .find(|k| s.name.starts_with(k));
                let Some(_) = kind else { continue };
                let ((sx, sy), spilled) = span(&s.svg, field);
                assert_eq!(
                    spilled, 0,
                    "{name} {size:?} {}: the drawing leaves its field",
                    s.name
                );
                let v = sx.max(sy);
                spans.push(v);
                all.push((v, format!("{name} {size:?} {}", s.name)));
            }
            spans.sort_by(f64::total_cmp);
            let min = spans.first().copied().unwrap_or(0.0);
            let med = spans.get(spans.len() / 2).copied().unwrap_or(0.0);
            cells.push(format!(
                "{:.0} % / {:.0} % ({})",
                100.0 * min,
                100.0 * med,
                spans.len()
            ));
        }
        rows.push(format!("| {name} | {} |", cells.join(" | ")));
    }
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    let median = all[all.len() / 2].0;
    let table = format!(
        "| fixture | A4 least / median (sheets) | A3 | A1 |\n|---|---|---|---|\n{}\n\nOver all {} sheets: least {:.0} % ({}), median {:.0} %.\n",
        rows.join("\n"),
        all.len(),
        100.0 * all[0].0,
        all[0].1,
        100.0 * median
    );
    eprintln!("{table}");
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        let path = format!("{}/docs/gallery/README.md", env!("CARGO_MANIFEST_DIR"));
        let doc = std::fs::read_to_string(&path).unwrap();
        let (a, b) = ("<!-- fill -->", "<!-- /fill -->");
        let (i, j) = (doc.find(a).expect("fill markers"), doc.find(b).unwrap());
        let doc = format!("{}{a}\n{table}{}", &doc[..i], &doc[j..]);
        std::fs::write(&path, doc).unwrap();
    }
    for (v, what) in &all {
        assert!(*v >= 0.5, "{what} spans {:.0} % of its field", 100.0 * v);
    }
    assert!(median >= 0.65, "median span {:.0} %", 100.0 * median);
}
