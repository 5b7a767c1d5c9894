//! How much of the A1 field the course sheets use, measured on the sheet
//! as the renderer lays it out: the share of the field inside the frame,
//! less the title block, that lies in the box of a figure (the positions,
//! the plans, the diagrams, a table, a force panel, the lever: each box as
//! far as it draws, its caption included); the rest is empty paper. The kinematic and force sheets of the six-link, the shaper
//! (uk), the compressor (ru) and the boom use at least 65 % each.
//! `UPDATE_GOLDEN=1` writes the table into docs/gallery/README.md.

mod common;

use common::sheets;
use mechplan::drawing::{DrawOptions, Sheet, sheet, tree};
use mechplan::words::construction::Lang;

/// The share of the sheet's field (less its title block) inside the box
/// of a figure (`<g class="figure">`, its box as the renderer lays out
/// what it draws, caption included), counted on a 1 mm grid.
fn used(s: &Sheet) -> f64 {
    let t = tree(&s.svg).unwrap();
    let k = 25.4 / 96.0; // mm per CSS px
    let mut boxes = Vec::new();
    fn walk(g: &usvg::Group, k: f64, out: &mut Vec<kurbo::Rect>) {
        for n in g.children() {
            if let usvg::Node::Group(g) = n {
                if g.id().starts_with("fig-") {
                    let b = g.abs_bounding_box();
                    out.push(kurbo::Rect::new(
                        b.left() as f64 * k,
                        b.top() as f64 * k,
                        b.right() as f64 * k,
                        b.bottom() as f64 * k,
                    ));
                } else {
                    walk(g, k, out);
                }
            }
        }
    }
    walk(t.root(), k, &mut boxes);
    assert!(boxes.len() >= 3, "{}: {} figures", s.name, boxes.len());
    let field = sheet::field(s.size, false, 0.0);
    let block = sheet::block(s.size);
    let (mut cells, mut inside) = (0usize, 0usize);
    let mut y = field.y0 + 0.5;
    while y < field.y1 {
        let mut x = field.x0 + 0.5;
        while x < field.x1 {
            let p = kurbo::Point::new(x, y);
            if !block.contains(p) {
                cells += 1;
                inside += usize::from(boxes.iter().any(|b| b.contains(p)));
            }
            x += 1.0;
        }
        y += 1.0;
    }
    inside as f64 / cells as f64
}

fn course_sheets(path: &str, lang: Lang) -> Vec<Sheet> {
    let text =
        std::fs::read_to_string(format!("{}/fixtures/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let req = mechplan::DrawRequest {
        course: true,
        ..mechplan::DrawRequest::default()
    };
    let study = mechplan::Study::from_json(&text)
        .unwrap()
        .for_sheets(&req)
        .unwrap();
    let solution = study.solve().unwrap();
    let opt = DrawOptions {
        lang,
        course: true,
        ..DrawOptions::default()
    };
    sheets(study.analysis(), solution.solved(), &opt)
        .into_iter()
        .filter(|s| s.name.starts_with("course"))
        .collect()
}

#[test]
fn course_sheets_use_their_field() {
    let cases = [
        ("dynamics/six_link_fig2_10.json", Lang::En),
        ("dynamics/shaper_fig2_11.json", Lang::Uk),
        ("dynamics/compressor_fig2_12.json", Lang::Ru),
        ("boom_cylinder.json", Lang::En),
    ];
    let mut rows = Vec::new();
    let mut low = Vec::new();
    for (path, lang) in cases {
        for s in course_sheets(path, lang) {
            let u = used(&s);
            rows.push(format!(
                "| {path} ({lang:?}) | {} | {:.0} % |",
                s.name,
                100.0 * u
            ));
            if u < 0.65 {
                low.push(format!("{path} {}: {:.0} %", s.name, 100.0 * u));
            }
        }
    }
    let table = format!(
        "| scene | sheet | field used |\n|---|---|---|\n{}\n",
        rows.join("\n")
    );
    eprintln!("{table}");
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        let path = format!("{}/docs/gallery/README.md", env!("CARGO_MANIFEST_DIR"));
        let doc = std::fs::read_to_string(&path).unwrap();
        let (a, b) = ("<!-- course-fill -->", "<!-- /course-fill -->");
        let (i, j) = (
            doc.find(a).expect("course-fill markers"),
            doc.find(b).unwrap(),
        );
        let doc = format!("{}{a}\n{table}{}", &doc[..i], &doc[j..]);
        std::fs::write(&path, doc).unwrap();
    }
    assert!(rows.len() >= 7, "{table}");
    assert!(low.is_empty(), "below 65 %: {low:?}\n{table}");
}

/// The velocity plans on the course sheet are drawn to be read: the grid
/// takes the column count that draws them largest without drawing any
/// other figure smaller, so the six-link's twelve plans are at μ_v =
/// 0.02 (m/s)/mm (5 × 3 cells held them at 0.04, 25–40 mm long) and the
/// median plan's longest vector — the fastest point's velocity from the
/// result file, at the μ_v the manifest gives the sheet — is at least
/// 45 mm.
#[test]
fn course_velocity_plans_are_large_enough_to_read() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = root.join("fixtures/six_link_fig2_10.json");
    let dir = std::env::temp_dir().join(format!("mechplan-course-v-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(exe)
        .arg("draw")
        .arg(&scene)
        .args(["--course", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success());
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sheets.json")).unwrap()).unwrap();
    let course = manifest["sheets"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["file"] == "course.svg")
        .unwrap();
    let mu_v = course["scales"]["mu_v"].as_f64().unwrap();
    let out = std::process::Command::new(exe)
        .arg("solve")
        .arg(&scene)
        .args(["--format", "json"])
        .output()
        .unwrap();
    let result: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut longest: Vec<f64> = result["positions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            p["points"]
                .as_object()
                .unwrap()
                .values()
                .map(|q| {
                    let v = &q["v"];
                    v[0].as_f64().unwrap().hypot(v[1].as_f64().unwrap()) / mu_v
                })
                .fold(0.0, f64::max)
        })
        .collect();
    longest.sort_by(f64::total_cmp);
    let median = longest[longest.len() / 2];
    assert!(mu_v <= 0.02 + 1e-12, "μ_v = {mu_v}");
    assert!(
        median >= 45.0,
        "median longest vector {median:.1} mm at μ_v = {mu_v}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
