//! Sheets printed at 100 % are their format at true size: every PDF page
//! (each sheet's own file and every page of the book `sheets.pdf`) is the
//! ISO format it was drawn on, to 1 pt, so that every μ written on it
//! holds on paper.

use std::path::Path;
use std::process::Command;

/// The page sizes (points) of every page of a PDF file, from its MediaBox.
fn pages(pdf: &Path) -> Vec<(f64, f64)> {
    let bytes = std::fs::read(pdf).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    text.match_indices("/MediaBox")
        .map(|(i, _)| {
            let rest = &text[i..];
            let open = rest.find('[').unwrap();
            let close = rest.find(']').unwrap();
            let v: Vec<f64> = rest[open + 1..close]
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            (v[2] - v[0], v[3] - v[1])
        })
        .collect()
}

/// Every page of every PDF file in `dir`: (file name, page size in pt).
fn pdf_pages(dir: &Path) -> Vec<(String, (f64, f64))> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "pdf") {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            out.extend(pages(&p).into_iter().map(|pg| (name.clone(), pg)));
        }
    }
    out
}

/// ISO 216 sizes, mm (portrait).
fn iso(name: &str) -> (f64, f64) {
    match name {
        "A4" => (210.0, 297.0),
        "A3" => (297.0, 420.0),
        "A2" => (420.0, 594.0),
        "A1" => (594.0, 841.0),
        _ => unreachable!(),
    }
}

fn points(mm: f64) -> f64 {
    mm * 72.0 / 25.4
}

/// Is the page (pt) the format `name` at true size, either way round?
fn is_format(page: (f64, f64), name: &str) -> bool {
    let (w, h) = iso(name);
    let (w, h) = (points(w), points(h));
    let near = |a: f64, b: f64| (a - b).abs() <= 1.0;
    (near(page.0, w) && near(page.1, h)) || (near(page.0, h) && near(page.1, w))
}

#[test]
fn every_pdf_page_is_its_format_at_true_size() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (sheet, course) in [("A4", "A1"), ("A3", "A1"), ("A2", "A2")] {
        let dir =
            std::env::temp_dir().join(format!("mechplan-true-size-{sheet}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = Command::new(exe)
            .arg("draw")
            .arg(root.join("fixtures/four_bar.json"))
            .args(["--format", "pdf", "--sheet", sheet, "--course", "-o"])
            .arg(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let mut seen = 0;
        for (name, page) in pdf_pages(&dir) {
            let want = if name == "course.pdf" { course } else { sheet };
            // The book holds the course sheet too.
            let ok = is_format(page, want) || (name == "sheets.pdf" && is_format(page, course));
            assert!(
                ok,
                "{name} with --sheet {sheet}: a page of {:.1} × {:.1} pt, not {want} ({:.1} × {:.1} pt)",
                page.0,
                page.1,
                points(iso(want).1),
                points(iso(want).0)
            );
            seen += 1;
        }
        assert!(seen > 20, "{seen} pages");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// ГОСТ 2.304 lettering on the A1 course sheets (kinematic and force):
/// every text at least 3.5 mm, every index (sub- or superscript) at
/// least 2.5 mm, read back from the SVG.
#[test]
fn course_sheets_lettered_at_least_3_5_mm() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for scene in [
        "fixtures/dynamics/six_link_fig2_10.json",
        "fixtures/dynamics/shaper_fig2_11.json",
        "fixtures/compressor_fig2_12.json",
    ] {
        let dir = std::env::temp_dir().join(format!(
            "mechplan-lettering-{}-{}",
            scene.replace('/', "-"),
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        let out = Command::new(exe)
            .arg("draw")
            .arg(root.join(scene))
            .args(["--course", "--title-block", "-o"])
            .arg(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let mut sheets = 0;
        for name in ["course.svg", "course_forces.svg"] {
            let Ok(svg) = std::fs::read_to_string(dir.join(name)) else {
                continue;
            };
            sheets += 1;
            let mut texts = 0;
            for (i, _) in svg.match_indices("font-size=\"") {
                let rest = &svg[i + 11..];
                let size: f64 = rest[..rest.find('"').unwrap()].parse().unwrap();
                // An index: a tspan shifted off the baseline.
                let tag_start = svg[..i].rfind('<').unwrap();
                let tag = &svg[tag_start..i];
                let index = tag.starts_with("<tspan") && tag.contains("baseline-shift");
                let least = if index { 2.5 } else { 3.5 };
                assert!(
                    size >= least,
                    "{scene} {name}: a {} at {size} mm: {}",
                    if index { "index" } else { "text" },
                    &svg[tag_start..(i + 120).min(svg.len())]
                );
                texts += 1;
            }
            assert!(texts > 100, "{scene} {name}: {texts} texts");
        }
        assert!(sheets >= 1, "{scene}: no course sheet");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// A4 with a title block stands upright (ГОСТ 2.301, 2.104: the block
/// across the foot of the frame); without one, and every larger format,
/// landscape.
#[test]
fn a4_with_a_title_block_is_upright() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (sheet, block, upright) in [
        ("A4", true, true),
        ("A4", false, false),
        ("A3", true, false),
    ] {
        let dir = std::env::temp_dir().join(format!(
            "mechplan-upright-{sheet}-{block}-{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        let mut cmd = Command::new(exe);
        cmd.arg("draw")
            .arg(root.join("fixtures/six_link_fig2_10.json"))
            .args(["--format", "pdf", "--sheet", sheet, "-o"])
            .arg(&dir);
        if block {
            cmd.arg("--title-block");
        }
        let out = cmd.output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let mut seen = 0;
        for (name, page) in pdf_pages(&dir)
            .into_iter()
            .filter(|(n, _)| n != "sheets.pdf")
        {
            assert!(is_format(page, sheet), "{name}: {page:?}");
            assert_eq!(
                page.0 < page.1,
                upright,
                "{name} ({sheet}, title block {block}): {:.1} × {:.1} pt",
                page.0,
                page.1
            );
            seen += 1;
        }
        assert!(seen > 10, "{seen}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
