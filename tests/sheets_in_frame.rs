//! Every sheet fits its paper in every mode (issue 40): every sheet `draw`
//! writes for the dynamics fixtures, in English, Ukrainian and Russian,
//! plain, with `--course`, `--title-block`, `--title-block --table` and
//! `--sheet A4 --title-block`, has every text, line and path inside its
//! drawing frame (ГОСТ 2.104's format word under it aside), as the
//! renderer lays them out; `--sheet A4` gives A4 sheets only.
//!
//! The frame is read from the sheet itself (its `class="frame"`
//! rectangle), the extents from usvg's layout of each element: nothing of
//! the engine's own layout is trusted.

mod common;
use common::{fresh, run};
use kurbo::Rect;
use mechplan::drawing::tree;

const FIXTURES: [&str; 5] = [
    "arm_two_cylinders",
    "compressor_fig2_12",
    "shaper_fig2_11",
    "six_link_fig2_10",
    "worked_slider_crank",
];

const MODES: [&[&str]; 5] = [
    &[],
    &["--course"],
    &["--title-block"],
    &["--title-block", "--table"],
    &["--sheet", "A4", "--title-block"],
];

/// How far past the frame's line a stroke may reach, mm (half the frame's
/// own line and rounding).
const SLACK: f64 = 0.4;

/// A number attribute of the first element carrying `marker` in `svg`.
fn attr(svg: &str, marker: &str, name: &str) -> Option<f64> {
    let at = svg.find(marker)?;
    let start = if marker.starts_with('<') {
        at
    } else {
        svg[..at].rfind('<')?
    };
    let tag = &svg[start..at + svg[at..].find('>')?];
    let i = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    tag[i..]
        .split('"')
        .next()?
        .trim_end_matches("mm")
        .parse()
        .ok()
}

/// The page (mm) and the drawing frame of a sheet, read from it.
fn page_and_frame(svg: &str) -> (f64, f64, Rect) {
    let w = attr(svg, "<svg", "width").expect("a page width");
    let h = attr(svg, "<svg", "height").expect("a page height");
    let f = |n| attr(svg, "class=\"frame\"", n).expect("a frame");
    let (x, y) = (f("x"), f("y"));
    (w, h, Rect::new(x, y, x + f("width"), y + f("height")))
}

/// What leaves the frame of one sheet: each element's kind and box (mm).
fn outside(svg: &str) -> Vec<String> {
    let (w, h, frame) = page_and_frame(svg);
    let t = tree(svg).unwrap();
    let k = 25.4 / 96.0;
    let mut out = Vec::new();
    let mut stack: Vec<&usvg::Group> = vec![t.root()];
    while let Some(g) = stack.pop() {
        for n in g.children() {
            let (kind, b) = match n {
                usvg::Node::Group(g) => {
                    stack.push(g);
                    continue;
                }
                usvg::Node::Path(_) => ("path", n.abs_stroke_bounding_box()),
                usvg::Node::Text(_) => ("text", n.abs_bounding_box()),
                usvg::Node::Image(_) => ("image", n.abs_bounding_box()),
            };
            let r = Rect::new(
                b.left() as f64 * k,
                b.top() as f64 * k,
                b.right() as f64 * k,
                b.bottom() as f64 * k,
            );
            let near = |a: f64, b: f64| (a - b).abs() <= 1.0;
            // The page's white ground and the frame itself.
            if near(r.x0, 0.0) && near(r.y0, 0.0) && near(r.x1, w) && near(r.y1, h) {
                continue;
            }
            if near(r.x0, frame.x0)
                && near(r.y0, frame.y0)
                && near(r.x1, frame.x1)
                && near(r.y1, frame.y1)
            {
                continue;
            }
            let words = match n {
                usvg::Node::Text(t) => t.chunks().iter().map(|c| c.text()).collect::<String>(),
                _ => String::new(),
            };
            // ГОСТ 2.104's format word, under the frame's right end.
            if kind == "text" && r.y0 >= frame.y1 && words.contains(" A") {
                continue;
            }
            if r.x0 < frame.x0 - SLACK
                || r.y0 < frame.y0 - SLACK
                || r.x1 > frame.x1 + SLACK
                || r.y1 > frame.y1 + SLACK
            {
                out.push(format!(
                    "{kind} {words:?} at ({:.1}, {:.1})–({:.1}, {:.1}) mm, frame ({:.1}, {:.1})–({:.1}, {:.1})",
                    r.x0, r.y0, r.x1, r.y1, frame.x0, frame.y0, frame.x1, frame.y1
                ));
            }
        }
    }
    out
}

/// The sheets of one run of `draw`, by file name.
fn drawn(fixture: &str, lang: &str, mode: &[&str]) -> Vec<(String, String)> {
    let tag = format!("{fixture}-{lang}-{}", mode.join("").replace("--", "-"));
    let dir = fresh("in-frame", &tag);
    let scene = format!(
        "{}/fixtures/dynamics/{fixture}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let d = dir.display().to_string();
    let mut args = vec!["draw", scene.as_str(), "-o", d.as_str(), "--lang", lang];
    args.extend_from_slice(mode);
    let (code, _, err) = run(&args);
    assert_eq!(code, 0, "{args:?}: {err}");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    out.sort();
    let _ = std::fs::remove_dir_all(&dir);
    out
}

#[test]
fn every_sheet_inside_its_frame_in_every_mode() {
    let mut bad = Vec::new();
    let mut count = 0;
    for fixture in FIXTURES {
        for lang in ["en", "uk", "ru"] {
            for mode in MODES {
                let sheets = drawn(fixture, lang, mode);
                assert!(!sheets.is_empty());
                for (name, svg) in &sheets {
                    count += 1;
                    let (w, h, _) = page_and_frame(svg);
                    if mode.contains(&"A4")
                        && !((w, h) == (210.0, 297.0) || (w, h) == (297.0, 210.0))
                    {
                        bad.push(format!(
                            "{fixture} {lang} {mode:?} {name}: {w} × {h} mm, not A4"
                        ));
                    }
                    let o = outside(svg);
                    if let Some(first) = o.first() {
                        bad.push(format!(
                            "{fixture} {lang} {mode:?} {name}: {} elements outside, e.g. {first}",
                            o.len()
                        ));
                    }
                }
            }
        }
    }
    eprintln!("{count} sheets, {} with a fault", bad.len());
    assert!(
        bad.is_empty(),
        "{} of {count} sheets:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// The check sees a sheet that overflows: a label moved past the frame.
#[test]
fn an_element_past_the_frame_is_seen() {
    let sheets = drawn("worked_slider_crank", "en", &[]);
    let (name, svg) = sheets
        .iter()
        .find(|(n, _)| n.starts_with("velocity"))
        .unwrap();
    assert!(outside(svg).is_empty(), "{name}: {:?}", outside(svg));
    let (w, _, _) = page_and_frame(svg);
    let moved = svg.replacen(
        "</svg>",
        &format!(
            "<text x=\"{}\" y=\"100\" font-size=\"3.5\">b</text></svg>",
            w - 2.0
        ),
        1,
    );
    assert_eq!(outside(&moved).len(), 1, "{:?}", outside(&moved));
    let line = svg.replacen(
        "</svg>",
        "<line x1=\"30\" y1=\"50\" x2=\"30\" y2=\"1\" stroke=\"black\" stroke-width=\"0.5\"/></svg>",
        1,
    );
    assert_eq!(outside(&line).len(), 1);
}
