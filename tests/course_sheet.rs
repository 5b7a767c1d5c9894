//! The course sheet (lecture Figs 2.10, 2.11 and the compressor): every
//! figure inside the frame, no two figures (nor a figure and the title
//! block) overlapping as rendered, each figure captioned with its scale,
//! the title block of ГОСТ 2.104 form 1 where and as the standard draws
//! it, and the plans on it built at the scales their captions state.

mod common;
use common::sheets;
use common::*;
use mechplan::drawing::{DrawOptions, SheetSize, tree};

const FIGS: [&str; 3] = ["six_link_fig2_10", "shaper_fig2_11", "compressor_fig2_12"];

fn course(name: &str, size: SheetSize) -> mechplan::drawing::Sheet {
    course_in(name, size, mechplan::Lang::En)
}

fn course_in(name: &str, size: SheetSize, lang: mechplan::Lang) -> mechplan::drawing::Sheet {
    let v = fixture(name);
    let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
    let opt = DrawOptions {
        sheet: size,
        course: true,
        lang,
        ..DrawOptions::default()
    };
    let data = sheet_data(&an, &s, &opt);
    let (sh, _) = mechplan::drawing::sheets_on(&an, &s, &data, &opt, &[size]).unwrap();
    sh.into_iter()
        .find(|s| s.name == "course")
        .expect("a course sheet")
}

/// The rendered box of every figure (mm, page coordinates).
fn figures(svg: &str) -> Vec<(String, kurbo::Rect)> {
    let t = tree(svg).unwrap();
    let k = 25.4 / 96.0;
    let mut out = Vec::new();
    fn walk(g: &usvg::Group, k: f64, out: &mut Vec<(String, kurbo::Rect)>) {
        for n in g.children() {
            if let usvg::Node::Group(g) = n {
                if g.id().starts_with("fig-") {
                    let b = n.abs_stroke_bounding_box();
                    out.push((
                        g.id().to_string(),
                        kurbo::Rect::new(
                            b.left() as f64 * k,
                            b.top() as f64 * k,
                            b.right() as f64 * k,
                            b.bottom() as f64 * k,
                        ),
                    ));
                } else {
                    walk(g, k, out);
                }
            }
        }
    }
    walk(t.root(), k, &mut out);
    out
}

/// In every language: its words are of other lengths (the tables' heads,
/// the captions, the title block), its numbers written with a comma.
#[test]
fn course_sheets_pass_the_layout_checks() {
    use mechplan::Lang;
    for (name, lang) in FIGS
        .iter()
        .flat_map(|n| [(*n, Lang::En), (*n, Lang::Uk), (*n, Lang::Ru)])
    {
        for size in [SheetSize::A1, SheetSize::A2] {
            let s = course_in(name, size, lang);
            let at = format!("{name} {size:?} {lang:?}");
            let (w, h) = size.mm();
            assert!(
                s.svg.contains(&format!(r#"width="{w}mm" height="{h}mm""#)),
                "{at}: the sheet's format"
            );
            let frame = kurbo::Rect::new(20.0, 5.0, w - 5.0, h - 5.0);
            let block = kurbo::Rect::new(frame.x1 - 185.0, frame.y1 - 55.0, frame.x1, frame.y1);
            let figs = figures(&s.svg);
            let ids: Vec<&str> = figs.iter().map(|f| f.0.as_str()).collect();
            for want in [
                "fig-positions",
                "fig-velocity",
                "fig-diagrams",
                "fig-table-velocity",
                "fig-table-acceleration",
            ] {
                assert!(ids.contains(&want), "{at}: no {want} in {ids:?}");
            }
            // The acceleration plans of the middle of the working and of
            // the idle stroke (not the extreme position the sweep starts
            // at, a dead centre).
            let acc: Vec<&&str> = ids
                .iter()
                .filter(|i| i.starts_with("fig-acceleration-"))
                .collect();
            assert_eq!(acc.len(), 2, "{at}: {ids:?}");
            assert!(!ids.contains(&"fig-acceleration-1"), "{at}: {ids:?}");
            for (i, (a, ra)) in figs.iter().enumerate() {
                assert!(
                    frame.inset(-1.0).contains(ra.origin())
                        && frame.inset(-1.0).contains(kurbo::Point::new(ra.x1, ra.y1)),
                    "{at}: {a} {ra:?} leaves the frame"
                );
                assert!(
                    ra.intersect(block).area() == 0.0,
                    "{at}: {a} overlaps the title block"
                );
                for (b, rb) in &figs[i + 1..] {
                    assert!(ra.intersect(*rb).area() == 0.0, "{at}: {a} and {b} overlap");
                }
            }
            // Every scaled figure states its scale in its caption.
            let scales: Vec<&str> = s.scales.iter().map(|(k, _)| *k).collect();
            for k in ["mu_l", "mu_v", "mu_a"] {
                assert!(scales.contains(&k), "{at}: no {k} among {scales:?}");
            }
            let captions: Vec<String> = texts(&s.svg)
                .into_iter()
                .filter(|(c, _)| c == "caption")
                .map(|(_, t)| t)
                .collect();
            for (k, mu) in &s.scales {
                let mu = if lang == Lang::En {
                    mu.to_string()
                } else {
                    mu.to_string().replace('.', ",")
                };
                let shown = format!("μ{} = {mu} ", &k[3..]);
                assert!(
                    captions.iter().any(|c| c.contains(&shown)),
                    "{at}: no caption with \"{shown}\" in {captions:?}"
                );
            }
            title_block(&s.svg, frame, &at);
        }
    }
}

/// The text elements of a sheet: their class and their text, tags
/// stripped.
fn texts(svg: &str) -> Vec<(String, String)> {
    svg.lines()
        .filter(|l| l.starts_with("<text"))
        .map(|l| {
            let class = l
                .split("class=\"")
                .nth(1)
                .and_then(|r| r.split('"').next())
                .unwrap_or("")
                .to_string();
            let mut t = String::new();
            let mut inside = false;
            for ch in l.chars() {
                match ch {
                    '<' => inside = true,
                    '>' => inside = false,
                    c if !inside => t.push(c),
                    _ => {}
                }
            }
            (class, t)
        })
        .collect()
}

/// The lines of the title block against ГОСТ 2.104 form 1 (185 × 55 mm):
/// the verticals at 7, 17, 40, 55, 65 mm from its left edge across the
/// left part, 135, 150, 167 mm in the right part, the rows of 5 mm, the
/// main horizontals at 15, 20, 35, 40 mm from its bottom, all in the
/// frame's bottom right corner.
fn title_block(svg: &str, frame: kurbo::Rect, at: &str) {
    let attr = |l: &str, n: &str| -> f64 {
        let i = l.find(&format!(" {n}=\"")).unwrap() + n.len() + 3;
        l[i..].split('"').next().unwrap().parse().unwrap()
    };
    let lines: Vec<(f64, f64, f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with(r#"<line class="title-block""#))
        .map(|l| (attr(l, "x1"), attr(l, "y1"), attr(l, "x2"), attr(l, "y2")))
        .collect();
    // In the block's own coordinates: from its left edge, from its bottom.
    let (x0, y0) = (frame.x1 - 185.0, frame.y1);
    let local: Vec<(f64, f64, f64, f64)> = lines
        .iter()
        .map(|&(a, b, c, d)| (a - x0, y0 - b, c - x0, y0 - d))
        .collect();
    let has = |x1: f64, y1: f64, x2: f64, y2: f64| {
        local.iter().any(|&(a, b, c, d)| {
            let same = |p: f64, q: f64| (p - q).abs() < 0.01;
            (same(a, x1) && same(b, y1) && same(c, x2) && same(d, y2))
                || (same(a, x2) && same(b, y2) && same(c, x1) && same(d, y1))
        })
    };
    // The outline: top and left edge (the frame draws the others).
    assert!(has(0.0, 55.0, 185.0, 55.0), "{at}: the block's top");
    assert!(has(0.0, 55.0, 0.0, 0.0), "{at}: the block's left edge");
    // Columns of the left part: Изм. 7, Лист 10, № докум. 23, Подп. 15, Дата 10.
    assert!(has(7.0, 55.0, 7.0, 30.0), "{at}: Изм.");
    for x in [17.0, 40.0, 55.0, 65.0] {
        assert!(has(x, 55.0, x, 0.0), "{at}: column at {x}");
    }
    // The right part: 70 mm for the name, then Лит. 15, Масса 17, Масштаб 18.
    assert!(has(135.0, 40.0, 135.0, 0.0), "{at}: the right part");
    assert!(has(150.0, 40.0, 150.0, 20.0), "{at}: Лит./Масса");
    assert!(has(167.0, 40.0, 167.0, 20.0), "{at}: Масса/Масштаб");
    assert!(has(155.0, 20.0, 155.0, 15.0), "{at}: Лист/Листов");
    for (xa, y, xb) in [
        (65.0, 40.0, 185.0),
        (0.0, 35.0, 65.0),
        (135.0, 35.0, 185.0),
        (0.0, 30.0, 65.0),
        (135.0, 20.0, 185.0),
        (65.0, 15.0, 185.0),
    ] {
        assert!(has(xa, y, xb, y), "{at}: the main line at {y} mm");
    }
    for y in [50.0, 45.0, 40.0, 25.0, 20.0, 15.0, 10.0, 5.0] {
        assert!(has(0.0, y, 65.0, y), "{at}: the row at {y} mm");
    }
    let words: [&str; 6] = if at.ends_with("Uk") {
        ["Зм.", "Розроб.", "Перев.", "Масштаб", "Арк.", "Формат A"]
    } else if at.ends_with("Ru") {
        ["Изм.", "Разраб.", "Пров.", "Масштаб", "Лист", "Формат A"]
    } else {
        ["Rev.", "Drawn", "Checked", "Scale", "Sheet", "Format A"]
    };
    for word in words {
        assert!(svg.contains(word), "{at}: no \"{word}\"");
    }
}

/// In Ukrainian the sheet speaks Ukrainian and writes a decimal comma.
#[test]
fn a_course_sheet_in_ukrainian() {
    let mut v = fixture("six_link_fig2_10");
    v["want"]["lang"] = serde_json::json!("uk");
    v["sheet"] = serde_json::json!({
        "designation": "ТММ.КП.02.10.00",
        "author": "Іваненко",
        "organisation": "Кафедра ТММ"
    });
    let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
    let opt = DrawOptions {
        lang: mechplan::words::construction::Lang::Uk,
        course: true,
        ..DrawOptions::default()
    };
    let sh = sheets(&an, &s, &opt);
    let c = sh.iter().find(|s| s.name == "course").unwrap();
    for word in [
        "ТММ.КП.02.10.00",
        "Іваненко",
        "Кафедра ТММ",
        "Розроб.",
        "Масштаб",
        "Плани швидкостей",
        "0,0",
    ] {
        assert!(c.svg.contains(word), "no \"{word}\"");
    }
    for (_, t) in texts(&c.svg)
        .into_iter()
        .filter(|(c, _)| c != "designation")
    {
        let b = t.as_bytes();
        let point = (1..b.len().saturating_sub(1))
            .any(|i| b[i] == b'.' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit());
        assert!(!point, "a decimal point in a Ukrainian sheet: {t}");
    }
}

/// `sheet.title` names the project's first drawing, the course sheet, in
/// the sheet's language where it gives several; the force sheet (sheet 2
/// of 2) and the single sheets with a block name themselves.
#[test]
fn the_sheet_title_names_the_course_sheet_only() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text =
        std::fs::read_to_string(root.join("fixtures/dynamics/six_link_fig2_10.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["sheet"] = serde_json::json!({
        "title": { "en": "Six-link kinematics", "uk": "Кінематика механізму" }
    });
    let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
    for (lang, mine, other) in [
        (
            mechplan::words::construction::Lang::Uk,
            "Кінематика механізму",
            "Six-link kinematics",
        ),
        (
            mechplan::words::construction::Lang::En,
            "Six-link kinematics",
            "Кінематика механізму",
        ),
    ] {
        let opt = DrawOptions {
            lang,
            course: true,
            title_block: true,
            ..DrawOptions::default()
        };
        let sh = sheets(&an, &s, &opt);
        let course = sh.iter().find(|s| s.name == "course").unwrap();
        assert!(
            course.svg.contains(mine),
            "{lang:?}: the course sheet is named {mine}"
        );
        assert!(
            !course.svg.contains(other),
            "{lang:?}: {other} on the course sheet"
        );
        let rest: Vec<_> = sh.iter().filter(|s| s.name != "course").collect();
        assert!(
            rest.iter().any(|s| s.name == "course_forces"),
            "a force sheet"
        );
        for s in rest {
            assert!(
                !s.svg.contains(mine),
                "{lang:?}: {} carries the course sheet's name",
                s.name
            );
        }
    }
}

/// A slide along the frame's guide is named by the guide's point under
/// the slider (v_DD0, a^r_DD0) at every position, even where the two
/// pistons of the compressor meet and the construction draws D's guide
/// line through b₀: one row per quantity, not a row split in two.
#[test]
fn slides_keep_their_names_in_the_results_table() {
    let sheet = course("compressor_fig2_12", SheetSize::A1);
    let subs: Vec<&str> = sheet
        .svg
        .split('>')
        .filter_map(|t| t.strip_suffix("</tspan"))
        .collect();
    assert!(subs.contains(&"DD0") && subs.contains(&"BB0"), "{subs:?}");
    assert!(
        !subs.contains(&"DB0") && !subs.contains(&"BD0"),
        "a split row"
    );
}

/// The course's second sheet (force analysis) of every dynamics fixture on
/// A1 and A2: its figures inside the frame, apart, off the title block; the
/// force panels, the lever, its table and the table of reactions present;
/// the balancing moment the same by the three routes in that table; none
/// for a scene without `dynamics`.
#[test]
fn force_course_sheets_pass_the_layout_checks() {
    for name in [
        "six_link_fig2_10",
        "shaper_fig2_11",
        "compressor_fig2_12",
        "worked_slider_crank",
        "class3_004",
    ] {
        let path = format!(
            "{}/fixtures/dynamics/{name}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(path).unwrap();
        let (an, solved) = solve(mechplan::Scene::from_json(&text).unwrap());
        for size in [SheetSize::A1, SheetSize::A2] {
            let opt = DrawOptions {
                sheet: size,
                course: true,
                ..DrawOptions::default()
            };
            let data = sheet_data(&an, &solved, &opt);
            let (sh, _) = mechplan::drawing::sheets_on(&an, &solved, &data, &opt, &[size]).unwrap();
            let s = sh
                .iter()
                .find(|s| s.name == "course_forces")
                .unwrap_or_else(|| panic!("{name}: no force analysis sheet"));
            let at = format!("{name} {size:?}");
            let (w, h) = size.mm();
            let frame = kurbo::Rect::new(20.0, 5.0, w - 5.0, h - 5.0);
            let block = kurbo::Rect::new(frame.x1 - 185.0, frame.y1 - 55.0, frame.x1, frame.y1);
            let figs = figures(&s.svg);
            assert!(figs.len() >= 4, "{at}: {} figures", figs.len());
            for (i, (a, ra)) in figs.iter().enumerate() {
                assert!(
                    frame.inset(-1.0).contains(ra.origin())
                        && frame.inset(-1.0).contains(kurbo::Point::new(ra.x1, ra.y1)),
                    "{at}: {a} {ra:?} leaves the frame"
                );
                assert!(
                    ra.intersect(block).area() == 0.0,
                    "{at}: {a} overlaps the title block"
                );
                for (b, rb) in &figs[i + 1..] {
                    assert!(ra.intersect(*rb).area() == 0.0, "{at}: {a} and {b} overlap");
                }
            }
            let all: Vec<String> = texts(&s.svg).into_iter().map(|(_, t)| t).collect();
            for want in [
                "Force analysis, position",
                "Zhukovsky's lever",
                "The forces on the lever",
                "Reactions and the balancing moment",
            ] {
                assert!(all.iter().any(|t| t.contains(want)), "{at}: no \"{want}\"");
            }
            // The balancing moment's row: the same three digits thrice.
            let k = all
                .iter()
                .position(|t| t.starts_with("Mb, ") || t.starts_with("M_b, "))
                .unwrap_or_else(|| panic!("{at}: no M_b row in {all:?}"));
            let row: Vec<&String> = all[k + 1..k + 5].iter().collect();
            assert_eq!(row[0], row[2], "{at}: {row:?}");
            assert_eq!(row[0], row[3], "{at}: {row:?}");
            title_block(&s.svg, frame, &at);
        }
    }
    let (an, solved) =
        solve(mechplan::Scene::from_json(&fixture("six_link_fig2_10").to_string()).unwrap());
    let opt = DrawOptions {
        course: true,
        ..DrawOptions::default()
    };
    let data = sheet_data(&an, &solved, &opt);
    let (sh, _) =
        mechplan::drawing::sheets_on(&an, &solved, &data, &opt, &[SheetSize::A1]).unwrap();
    assert!(sh.iter().all(|s| s.name != "course_forces"));
}

/// The title block's letter cells (ГОСТ 2.104 field 4) are never empty:
/// the scene's `sheet.letter`, one letter a cell, else "У" (a student's
/// document) in uk and ru, a dash in en; more than three letters are
/// refused by the field's pointer.
#[test]
fn the_letter_cells_are_filled() {
    let cell = |svg: &str, ch: &str| {
        svg.lines()
            .any(|l| l.contains("title-block-field") && l.ends_with(&format!(">{ch}</text>")))
    };
    let mut v = fixture("six_link_fig2_10");
    for (lang, ch) in [
        (mechplan::words::construction::Lang::Uk, "У"),
        (mechplan::words::construction::Lang::Ru, "У"),
        (mechplan::words::construction::Lang::En, "—"),
    ] {
        let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
        let opt = DrawOptions {
            lang,
            course: true,
            ..DrawOptions::default()
        };
        let sh = sheets(&an, &s, &opt);
        let c = sh.iter().find(|s| s.name == "course").unwrap();
        assert!(cell(&c.svg, ch), "{lang:?}: the letter {ch}");
    }
    v["sheet"] = serde_json::json!({ "letter": "ДП" });
    let (an, s) = solve(mechplan::Scene::from_json(&v.to_string()).unwrap());
    let opt = DrawOptions {
        course: true,
        ..DrawOptions::default()
    };
    let sh = sheets(&an, &s, &opt);
    let c = sh.iter().find(|s| s.name == "course").unwrap();
    assert!(cell(&c.svg, "Д") && cell(&c.svg, "П"), "one letter a cell");
    v["sheet"] = serde_json::json!({ "letter": "ABCD" });
    let e = mechplan::Scene::from_json(&v.to_string())
        .unwrap_err()
        .to_string();
    assert!(e.contains("/sheet/letter"), "{e}");
}

/// What the sheets `opt` draws need beyond the positions, solved (as
/// `Study::draw` does before drawing).
fn sheet_data(
    an: &mechplan::Analysis,
    solved: &[mechplan::Solved],
    opt: &DrawOptions,
) -> mechplan::studies::sheet_data::SheetData {
    let needs = mechplan::drawing::sheet_needs(an, solved, opt, true);
    mechplan::studies::sheet_data::SheetData::solve(an, solved, needs).unwrap()
}
