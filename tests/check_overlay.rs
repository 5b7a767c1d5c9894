//! The check's overlay (`check --svg`; docs/check.md, "The overlay"), on
//! answers right and wrong, of velocities and accelerations, on the
//! six-link, the shaper and the four-bar (and one drawn so far off that
//! the sheet is reduced): every label is the plan's letters with their
//! subscript (the student's starred), never a result file's key; no two
//! labels overlap (their boxes as the renderer lays the text out from the
//! SVG's positions and font sizes), and none sits on a drawn point or a
//! line's end; a legend says what the marks are; and for a wrong answer
//! the step the report names is drawn in red with its number beside it,
//! its lines where the right construction draws them from the student's
//! own points.

mod common;
use serde_json::{Value, json};

const WRONG_INK: &str = "#c00000";
const STUDENT_INK: &str = "#1f5fa8";

fn fixture_path(name: &str) -> String {
    format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"))
}

/// A fixture's result file (`solve --format json`).
fn solved(fixture: &str) -> Value {
    let (code, out, err) = common::run(&["solve", &fixture_path(fixture), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// A pencil's noise, the same every run: uniform in ±0.1 mm.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.2
    }
}

/// Every point of a plan at position `k` (from 1), read off with the
/// pencil's noise; `edit` moves or turns them.
fn answer(doc: &Value, kind: &str, k: usize, edit: impl Fn(&str, [f64; 2]) -> [f64; 2]) -> Value {
    let plan = &doc["positions"][k - 1]["plans"][kind];
    let mut noise = Noise(k as u64 * 7 + kind.len() as u64);
    let mut pts = serde_json::Map::new();
    for (n, p) in plan["points"].as_object().unwrap() {
        let at = [
            p[0].as_f64().unwrap() + noise.next(),
            p[1].as_f64().unwrap() + noise.next(),
        ];
        let [x, y] = edit(n, at);
        pts.insert(n.clone(), json!([x, y]));
    }
    json!({ "plan": kind, "position": k, "positions_from": 1, "mu": plan["mu"], "points": pts })
}

/// The worked example's answer, read from docs/check.md.
fn worked_example() -> Value {
    let page =
        std::fs::read_to_string(format!("{}/docs/check.md", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let example = &page[page.find("### A worked example").unwrap()..];
    let start = example.find("```json\n").unwrap() + 8;
    let end = start + example[start..].find("```").unwrap();
    serde_json::from_str(&example[start..end]).unwrap()
}

/// An answer checked with `--svg` (and `extra` options): its status, its
/// report as JSON and the overlay.
fn overlay_of(
    dir: &std::path::Path,
    tag: &str,
    fixture: &str,
    a: &Value,
    extra: &[&str],
) -> (i32, Value, String) {
    let file = dir.join(format!("{tag}.json"));
    let svg = dir.join(format!("{tag}.svg"));
    std::fs::write(&file, a.to_string()).unwrap();
    let (scene, f, s) = (
        fixture_path(fixture),
        file.to_str().unwrap(),
        svg.to_str().unwrap(),
    );
    let mut args = vec!["check", &scene, f, "--svg", s, "--format", "json"];
    args.extend(extra);
    let (code, out, err) = common::run(&args);
    assert!(code == 0 || code == 1, "{tag}: {err}");
    (
        code,
        serde_json::from_str(&out).unwrap(),
        std::fs::read_to_string(&svg).unwrap(),
    )
}

/// An attribute of an SVG element written on one line.
fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()
}

fn num(line: &str, name: &str) -> f64 {
    attr(line, name).unwrap().parse().unwrap()
}

/// A text element's letters, its tags stripped.
fn content(line: &str) -> String {
    let mut out = String::new();
    let mut tag = false;
    for c in line[line.find('>').unwrap() + 1..].chars() {
        match c {
            '<' => tag = true,
            '>' => tag = false,
            c if !tag => out.push(c),
            _ => {}
        }
    }
    out
}

/// The text elements with an id: (id, the whole line).
fn texts(svg: &str) -> Vec<(String, &str)> {
    svg.lines()
        .filter(|l| l.starts_with("<text"))
        .filter_map(|l| Some((attr(l, "id")?.to_string(), l)))
        .collect()
}

/// Every text's box (mm on the sheet) as the renderer lays it out from
/// the SVG's positions and font sizes: (id or "", box).
fn text_boxes(svg: &str) -> Vec<(String, kurbo::Rect)> {
    let tree = mechplan::drawing::tree(svg).unwrap();
    let k = 25.4 / 96.0;
    let mut out = Vec::new();
    fn walk(g: &usvg::Group, k: f64, out: &mut Vec<(String, kurbo::Rect)>) {
        for n in g.children() {
            match n {
                usvg::Node::Group(g) => walk(g, k, out),
                usvg::Node::Text(t) => {
                    let b = n.abs_bounding_box();
                    let r = kurbo::Rect::new(
                        b.left() as f64 * k,
                        b.top() as f64 * k,
                        b.right() as f64 * k,
                        b.bottom() as f64 * k,
                    );
                    out.push((t.id().to_string(), r));
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), k, &mut out);
    out
}

/// The points drawn (the right plan's dots, the student's crosses) and
/// every line's ends, arrowheads' tips included, on the sheet (mm).
fn drawn_points(svg: &str) -> Vec<(String, kurbo::Point)> {
    let mut out = Vec::new();
    let p = |x: f64, y: f64| kurbo::Point::new(x, y);
    for l in svg.lines() {
        let id = attr(l, "id").unwrap_or("").to_string();
        if l.starts_with("<circle") && id.starts_with("pt-") {
            out.push((id, p(num(l, "cx"), num(l, "cy"))));
        } else if l.starts_with("<line") {
            let (a, b) = (p(num(l, "x1"), num(l, "y1")), p(num(l, "x2"), num(l, "y2")));
            if id.starts_with("student-") {
                out.push((id.clone(), a.midpoint(b)));
            }
            out.push((format!("{id} end"), a));
            out.push((format!("{id} end"), b));
        } else if l.starts_with("<path") {
            let v: Vec<f64> = attr(l, "d")
                .unwrap()
                .split([' ', 'M', 'L'])
                .filter(|t| !t.is_empty())
                .map(|t| t.parse().unwrap())
                .collect();
            if v.len() >= 4 && !l.contains("class=\"arc\"") {
                out.push(("path end".into(), p(v[0], v[1])));
                out.push(("path end".into(), p(v[v.len() - 2], v[v.len() - 1])));
            }
        } else if l.starts_with("<polygon class=\"arrow\"") {
            let v: Vec<f64> = attr(l, "points")
                .unwrap()
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            out.push(("arrow tip".into(), p(v[0], v[1])));
        }
    }
    out
}

/// The checks every overlay passes: labels of plan letters, not keys; no
/// two texts overlapping; no label on a point or a line's end; a legend.
fn labels_and_legend(tag: &str, a: &Value, svg: &str) {
    let ts = texts(svg);
    let keys: Vec<&String> = a["points"]
        .as_object()
        .map(|p| p.keys().collect())
        .unwrap_or_default();
    // Every text: no key's underscore, no key starred.
    for l in svg.lines().filter(|l| l.starts_with("<text")) {
        let c = content(l);
        assert!(!c.contains('_'), "{tag}: a key's underscore in {c:?}");
    }
    // The student's labels: the plan's letters and subscript, starred.
    for key in &keys {
        let (_, line) = ts
            .iter()
            .find(|(id, _)| id == &format!("student-label-{key}"))
            .unwrap_or_else(|| panic!("{tag}: no label of the student's {key}"));
        let c = content(line);
        let letters = key.replace('_', "");
        assert_eq!(c.matches('*').count(), 1, "{tag}: {c}");
        assert_eq!(
            c.trim_end_matches('*').replace('′', ""),
            letters,
            "{tag}: {key} labelled {c}"
        );
        if let Some(d) = key.rfind(|ch: char| !ch.is_ascii_digit())
            && d + 1 < key.len()
        {
            let digits = &key[d + 1..];
            assert!(
                line.contains(&format!(
                    r#"baseline-shift="sub" font-size="1.75">{digits}</tspan>"#
                )),
                "{tag}: the subscript of {key} not written as one: {line}"
            );
        }
        assert!(
            line.contains(&format!(r#"fill="{STUDENT_INK}""#)),
            "{tag}: {line}"
        );
    }
    // No two texts overlap (the heading, the labels, the legend).
    let boxes = text_boxes(svg);
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            let (a, b) = (&boxes[i], &boxes[j]);
            assert!(
                a.1.intersect(b.1).area() <= 0.05,
                "{tag}: texts {:?} and {:?} overlap: {:?} {:?}",
                a.0,
                b.0,
                a.1,
                b.1
            );
        }
    }
    // No label on a drawn point or a line's end.
    let points = drawn_points(svg);
    let labels = boxes.iter().filter(|(id, _)| {
        id.starts_with("label-")
            || id.starts_with("student-label-")
            || id.starts_with("wrong-step-label-")
    });
    let mut n = 0;
    for (id, r) in labels {
        n += 1;
        let inner = r.inset(-0.15);
        for (what, p) in &points {
            assert!(
                !inner.contains(*p),
                "{tag}: label {id} {r:?} sits on {what} at {p:?}"
            );
        }
    }
    assert!(n > keys.len(), "{tag}: the plan's labels and the student's");
    // The legend: the right plan, the student's points, each step's place.
    let legend: Vec<String> = ts
        .iter()
        .filter(|(id, _)| id.starts_with("legend-"))
        .map(|(_, l)| content(l))
        .collect();
    assert!(legend.len() >= 3, "{tag}: {legend:?}");
    assert!(
        legend[0].contains("the right plan at your scale"),
        "{tag}: {legend:?}"
    );
    assert!(
        legend[1].contains("your point, its letter starred"),
        "{tag}: {legend:?}"
    );
    assert!(
        legend[2].contains("where the step puts the point"),
        "{tag}: {legend:?}"
    );
}

/// The wrong steps: each step the report names, its lines red with ids
/// `wrong-step-N-…`, its number beside them in red; none for a right one.
fn wrong_steps_marked(tag: &str, report: &Value, svg: &str) -> Vec<usize> {
    let steps: Vec<usize> = report["mistakes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["step"].as_u64().unwrap() as usize)
        .collect();
    let ts = texts(svg);
    let numbers: Vec<&(String, &str)> = ts
        .iter()
        .filter(|(id, _)| id.starts_with("wrong-step-label-"))
        .collect();
    assert_eq!(
        numbers.len(),
        steps.len(),
        "{tag}: one number per step named"
    );
    for n in &steps {
        let (_, l) = numbers
            .iter()
            .find(|(id, _)| id == &format!("wrong-step-label-{n}"))
            .unwrap_or_else(|| panic!("{tag}: step {n} not marked"));
        assert_eq!(content(l), format!("step {n}"), "{tag}");
        assert!(l.contains(&format!(r#"fill="{WRONG_INK}""#)), "{tag}: {l}");
        let lines: Vec<&str> = svg
            .lines()
            .filter(|l| attr(l, "id").is_some_and(|i| i.starts_with(&format!("wrong-step-{n}-"))))
            .collect();
        assert!(!lines.is_empty(), "{tag}: step {n}'s lines");
        for l in &lines {
            assert!(
                l.contains(&format!(r#"stroke="{WRONG_INK}""#)),
                "{tag}: {l}"
            );
        }
    }
    let legend_says = ts.iter().any(|(id, l)| {
        id.starts_with("legend-") && content(l).contains("the step where the mistake enters")
    });
    assert_eq!(
        legend_says,
        !steps.is_empty(),
        "{tag}: the legend's red line"
    );
    steps
}

/// The line of an SVG element by its id.
fn element<'a>(svg: &'a str, id: &str) -> &'a str {
    svg.lines()
        .find(|l| attr(l, "id") == Some(id))
        .unwrap_or_else(|| panic!("no element {id}"))
}

/// A segment element's ends (mm on the sheet).
fn ends(l: &str) -> (kurbo::Point, kurbo::Point) {
    (
        kurbo::Point::new(num(l, "x1"), num(l, "y1")),
        kurbo::Point::new(num(l, "x2"), num(l, "y2")),
    )
}

/// Right and wrong answers on three fixtures, both plans: the labels, the
/// overlaps, the legend and the wrong steps.
#[test]
fn overlays_label_the_plan_letters_clear_of_each_other_with_a_legend() {
    let dir = common::fresh("overlay", "cases");
    let six = solved("six_link_fig2_10");
    let shaper = solved("shaper_fig2_11");
    let four = solved("four_bar");
    let same = |_: &str, p: [f64; 2]| p;
    let moved = |key: &str, p: [f64; 2]| if key == "d" { [p[0] + 15.0, p[1]] } else { p };
    let cases: Vec<(&str, &str, Value, i32)> = vec![
        (
            "six-v-right",
            "six_link_fig2_10",
            answer(&six, "velocity", 2, same),
            0,
        ),
        (
            "six-a-right",
            "six_link_fig2_10",
            answer(&six, "acceleration", 2, same),
            0,
        ),
        ("six-a-worked", "six_link_fig2_10", worked_example(), 1),
        (
            "six-v-moved",
            "six_link_fig2_10",
            answer(&six, "velocity", 2, moved),
            1,
        ),
        (
            "shaper-a-right",
            "shaper_fig2_11",
            answer(&shaper, "acceleration", 3, same),
            0,
        ),
        (
            "shaper-v-right",
            "shaper_fig2_11",
            answer(&shaper, "velocity", 3, same),
            0,
        ),
        (
            "shaper-a-moved",
            "shaper_fig2_11",
            answer(&shaper, "acceleration", 3, moved),
            1,
        ),
        (
            "four-v-turned",
            "four_bar",
            answer(&four, "velocity", 2, |_, p| [-p[0], -p[1]]),
            1,
        ),
        (
            "four-a-right",
            "four_bar",
            answer(&four, "acceleration", 2, same),
            0,
        ),
    ];
    for (tag, fixture, a, status) in &cases {
        let (code, report, svg) = overlay_of(&dir, tag, fixture, a, &[]);
        assert_eq!(code, *status, "{tag}");
        labels_and_legend(tag, a, &svg);
        let steps = wrong_steps_marked(tag, &report, &svg);
        assert_eq!(steps.is_empty(), *status == 0, "{tag}");
        // A wrong point's way off its place, red; none on a right answer.
        let off = svg
            .lines()
            .filter(|l| attr(l, "id").is_some_and(|i| i.starts_with("off-")))
            .count();
        assert_eq!(off > 0, *status == 1, "{tag}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The worked example of docs/check.md: the normal component a^n_BA laid
/// off the wrong way at step 5. The overlay draws step 5 in red as it
/// should be drawn from the student's own a: a vector from there, as long
/// as the step's sentence says (29.2 mm), "step 5" beside it; the title
/// names the step too.
#[test]
fn the_worked_examples_step_is_drawn_from_the_students_points() {
    let dir = common::fresh("overlay", "worked");
    let a = worked_example();
    let (_, report, svg) = overlay_of(&dir, "worked", "six_link_fig2_10", &a, &[]);
    assert_eq!(report["mistakes"][0]["step"], 5);
    let sentence = report["mistakes"][0]["step_text"].as_str().unwrap();
    let mm: f64 = sentence
        .split(" = ")
        .filter_map(|s| {
            s.strip_suffix(" mm, ∥ BA, from B toward A.")
                .and_then(|n| n.parse().ok())
        })
        .next()
        .unwrap_or_else(|| panic!("{sentence}"));
    let pole = element(&svg, "pt-p_a");
    let pole = kurbo::Point::new(num(pole, "cx"), num(pole, "cy"));
    let at = |x: f64, y: f64| pole + kurbo::Vec2::new(x, -y);
    let student_a = at(
        a["points"]["a"][0].as_f64().unwrap(),
        a["points"]["a"][1].as_f64().unwrap(),
    );
    let (from, to) = ends(element(&svg, "wrong-step-5-0"));
    assert!(
        (from - student_a).hypot() < 0.02,
        "from the student's a: {from:?} {student_a:?}"
    );
    assert!(
        ((to - from).hypot() - mm).abs() < 0.05,
        "{} mm, not {mm}",
        (to - from).hypot()
    );
    // Its arrowhead, red too, at its end.
    let arrows: Vec<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<polygon class=\"arrow\"") && l.contains(WRONG_INK))
        .collect();
    assert!(
        arrows.iter().any(|l| {
            let v: Vec<f64> = attr(l, "points")
                .unwrap()
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            (kurbo::Point::new(v[0], v[1]) - to).hypot() < 0.02
        }),
        "no red arrowhead at step 5's vector's end"
    );
    let title = svg
        .lines()
        .find(|l| l.contains("class=\"heading\""))
        .unwrap();
    assert!(
        content(title).contains("step 5: One normal component"),
        "{title}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A point moved along the guide: the step that draws it (two lines
/// meeting) in red, each line through the point where the step puts it
/// from the student's own points (the circle of its tolerance).
#[test]
fn an_intersections_two_lines_meet_where_the_step_puts_the_point() {
    let dir = common::fresh("overlay", "meet");
    let six = solved("six_link_fig2_10");
    let a = answer(&six, "velocity", 2, |key, p| {
        if key == "d" { [p[0] + 15.0, p[1]] } else { p }
    });
    let (_, report, svg) = overlay_of(&dir, "moved", "six_link_fig2_10", &a, &[]);
    let first = &report["mistakes"][0];
    assert!(
        first["step_text"].as_str().unwrap().contains("meet at d"),
        "{first}"
    );
    let n = first["step"].as_u64().unwrap();
    let circle = element(&svg, &format!("step-{n}-d"));
    let place = kurbo::Point::new(num(circle, "cx"), num(circle, "cy"));
    for i in 0..2 {
        let (p, q) = ends(element(&svg, &format!("wrong-step-{n}-{i}")));
        let u = (q - p).normalize();
        let off = (place - p).cross(u).abs();
        assert!(off < 0.02, "line {i} passes {off} mm from the step's place");
    }
    assert!(
        svg.lines()
            .all(|l| attr(l, "id") != Some(&format!("wrong-step-{n}-2")))
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// An answer whose only mistake is a value: no step marked, the value in
/// red under the legend as written and as it should be; in Ukrainian, the
/// legend and the mark in Ukrainian.
#[test]
fn a_value_written_wrong_is_shown_and_the_legend_follows_the_language() {
    let dir = common::fresh("overlay", "value");
    let six = solved("six_link_fig2_10");
    let mut a = answer(&six, "velocity", 2, |_, p| p);
    let v = &six["positions"][1]["points"]["B"]["v"];
    let vb = v[0].as_f64().unwrap().hypot(v[1].as_f64().unwrap());
    a["values"] = json!({ "v_B": 1.3 * vb });
    let (code, _, svg) = overlay_of(&dir, "value", "six_link_fig2_10", &a, &[]);
    assert_eq!(code, 1);
    labels_and_legend("value", &a, &svg);
    let written = element(&svg, "written-wrong-0");
    assert!(written.contains(WRONG_INK), "{written}");
    let c = content(written);
    assert!(
        c.starts_with("vB: written ") && c.contains(", right "),
        "{c}"
    );
    assert!(!svg.contains("id=\"wrong-step-"), "no step is wrong");
    let b = worked_example();
    let (_, report, svg) = overlay_of(&dir, "uk", "six_link_fig2_10", &b, &["--lang", "uk"]);
    assert_eq!(report["mistakes"][0]["step"], 5);
    assert_eq!(content(element(&svg, "wrong-step-label-5")), "крок 5");
    let legend: Vec<String> = texts(&svg)
        .iter()
        .filter(|(id, _)| id.starts_with("legend-"))
        .map(|(_, l)| content(l))
        .collect();
    assert!(legend[0].starts_with("правильний план"), "{legend:?}");
    assert!(
        legend
            .iter()
            .any(|l| l.starts_with("крок, на якому входить помилка")),
        "{legend:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A point drawn 700 mm off a plan drawn large: the sheet is reduced
/// (its title says 1:n) and its labels, placed at the reduced size, still
/// keep clear of each other.
#[test]
fn a_reduced_overlay_keeps_its_labels_apart() {
    let dir = common::fresh("overlay", "reduced");
    let shaper = solved("shaper_fig2_11");
    let k = 8.0;
    let mut a = answer(&shaper, "acceleration", 1, |key, p| {
        let p = [p[0] * k, p[1] * k];
        if key == "d" { [p[0] + 700.0, p[1]] } else { p }
    });
    a["mu"] = json!(a["mu"].as_f64().unwrap() / k);
    let (code, _, svg) = overlay_of(&dir, "far", "shaper_fig2_11", &a, &[]);
    assert_eq!(code, 1);
    let title = svg
        .lines()
        .find(|l| l.contains("class=\"heading\""))
        .unwrap();
    assert!(content(title).ends_with("(1:2)"), "{title}");
    labels_and_legend("far", &a, &svg);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The gallery's picture of the overlay (docs/gallery/check_overlay.png,
/// docs/check.md): the worked example rendered at 150 dpi (its letters
/// legible on the page); `UPDATE_GOLDEN=1` (docs/gallery/make.sh) writes
/// it. The rendering shows the three inks: the pale right plan, the
/// student's blue crosses and letters, the red step; the picture kept in
/// the docs is the sheet rendered now (its size).
#[test]
fn the_gallerys_picture_of_the_overlay() {
    let dir = common::fresh("overlay", "gallery");
    let (_, _, svg) = overlay_of(&dir, "worked", "six_link_fig2_10", &worked_example(), &[]);
    let png = mechplan::drawing::png(&svg, 150.0).unwrap();
    let pixmap = tiny_skia::Pixmap::decode_png(&png).unwrap();
    let count = |f: &dyn Fn(u8, u8, u8) -> bool| {
        pixmap
            .pixels()
            .iter()
            .filter(|p| p.alpha() == 255 && f(p.red(), p.green(), p.blue()))
            .count()
    };
    let red = count(&|r, g, b| r > 170 && g < 60 && b < 60);
    let blue = count(&|r, g, b| r < 80 && (70..140).contains(&g) && b > 140);
    let grey = count(&|r, g, b| r == g && g == b && (120..200).contains(&r));
    assert!(
        red > 200 && blue > 40 && grey > 1000,
        "red {red}, blue {blue}, grey {grey}"
    );
    let path = format!(
        "{}/docs/gallery/check_overlay.png",
        env!("CARGO_MANIFEST_DIR")
    );
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(&path, &png).unwrap();
    }
    let kept = std::fs::read(&path).unwrap_or_else(|_| panic!("{path} missing: UPDATE_GOLDEN=1"));
    assert_eq!(
        kept[16..24],
        png[16..24],
        "{path}: another size than the sheet's (UPDATE_GOLDEN=1)"
    );
    let page =
        std::fs::read_to_string(format!("{}/docs/check.md", env!("CARGO_MANIFEST_DIR"))).unwrap();
    assert!(
        page.contains("(gallery/check_overlay.png)"),
        "docs/check.md shows it"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
