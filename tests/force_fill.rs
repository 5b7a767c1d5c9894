//! Each force polygon fills its box (issue 40), read back from the
//! written sheets: for every dynamics fixture drawn plainly (`forces_K`),
//! with the course sheets (`course_forces`) and on A4 with the title block
//! (`forces_K`, `forces_K_M`), every polygon's vectors span at least half
//! its box's width or height (the box the sheet marks as
//! `f<i>-polygon-box`, beside its free body in its panel `f<i>-panel`),
//! its μ_F is a standard value, and the forces read off the drawing at
//! that μ_F are the result file's (`solve --format json`): every reaction
//! R_ab and inertia force Φ_k drawn, to the drawing's precision (the page
//! is written to 0.01 mm). Nothing here knows how the sheet is laid out.

use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;
use std::process::Command;

const DYNAMICS: &[&str] = &[
    "six_link_fig2_10",
    "shaper_fig2_11",
    "compressor_fig2_12",
    "arm_two_cylinders",
    "worked_slider_crank",
    "class3_004",
];

/// The least share of its box's width or height a polygon spans.
const LEAST_FILL: f64 = 0.5;

fn mechplan(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A scratch folder, removed when done.
struct Dir(std::path::PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let i = line.find(&format!(" {name}=\""))? + name.len() + 3;
    line[i..].split('"').next()
}

fn num(line: &str, name: &str) -> f64 {
    attr(line, name).unwrap().parse().unwrap()
}

/// Every element with an id, by id (the renderer writes one a line).
fn by_id(svg: &str) -> HashMap<String, String> {
    svg.lines()
        .filter_map(|l| Some((attr(l, "id")?.to_string(), l.to_string())))
        .collect()
}

/// A text element's words, its tags left out.
fn text_of(line: &str) -> String {
    let body = &line[line.find('>').map_or(0, |i| i + 1)..];
    let mut out = String::new();
    let mut inside = false;
    for c in body.chars() {
        match c {
            '<' => inside = true,
            '>' => inside = false,
            _ if !inside => out.push(c),
            _ => {}
        }
    }
    out
}

/// A number as an en or uk/ru text writes it.
fn number(t: &str) -> f64 {
    t.replace(',', ".").parse().unwrap()
}

/// Whether `mu` is a standard scale: 1, 2, 2.5, 4 or 5 × 10^k.
fn standard(mu: f64) -> bool {
    let k = mu.log10().floor();
    let m = mu / 10f64.powf(k);
    [1.0, 2.0, 2.5, 4.0, 5.0, 10.0]
        .iter()
        .any(|s| (m - s).abs() < 1e-9)
}

/// A box written `data-box="x0 y0 x1 y1"` (page mm).
fn data_box(line: &str) -> kurbo::Rect {
    let v: Vec<f64> = attr(line, "data-box")
        .unwrap()
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    kurbo::Rect::new(v[0], v[1], v[2], v[3])
}

/// What one polygon filled: the span of its drawing (its vectors, their
/// names, its details and its equation) over its box's and its panel's
/// width and height (the larger share of each), and its vectors' alone.
struct Fill {
    of_box: f64,
    of_panel: f64,
    vectors_of_box: f64,
    vectors_of_panel: f64,
}

/// The box (page mm) of the element `id` as the renderer draws it, its
/// text laid out.
fn drawn_box(t: &usvg::Tree, id: &str) -> Option<kurbo::Rect> {
    let b = t.node_by_id(id)?.abs_bounding_box();
    let k = 25.4 / 96.0;
    Some(kurbo::Rect::new(
        b.left() as f64 * k,
        b.top() as f64 * k,
        b.right() as f64 * k,
        b.bottom() as f64 * k,
    ))
}

/// The forces a position's result states: each pair's reaction by its
/// links (R of the first on the second), each link's inertia force.
struct Result {
    pairs: HashMap<(String, String), kurbo::Vec2>,
    inertia: HashMap<String, kurbo::Vec2>,
}

fn vec2(v: &Value) -> kurbo::Vec2 {
    kurbo::Vec2::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

fn results(json: &Value) -> HashMap<i64, Result> {
    let mut out = HashMap::new();
    for pos in json["positions"].as_array().unwrap() {
        let d = &pos["dynamics"];
        let mut pairs = HashMap::new();
        for p in d["pairs"].as_array().unwrap() {
            let (a, b, r) = match p.get("links") {
                Some(l) => (&l[0], &l[1], vec2(&p["R"])),
                None => (&p["guide"], &p["slider"], vec2(&p["N"])),
            };
            let (a, b) = (a.as_str().unwrap(), b.as_str().unwrap());
            pairs.insert((a.to_string(), b.to_string()), r);
            pairs.insert((b.to_string(), a.to_string()), -r);
        }
        let inertia = d["inertia"]
            .as_object()
            .unwrap()
            .iter()
            .map(|(k, v)| (k.clone(), vec2(&v["F"])))
            .collect();
        out.insert(pos["position"].as_i64().unwrap(), Result { pairs, inertia });
    }
    out
}

/// The force a vector's name stands for in the result, where it is a
/// reaction R_ab (a, b one character each) or an inertia force Φ_k.
fn stated(name: &str, r: &Result) -> Option<kurbo::Vec2> {
    let mut c = name.chars();
    match c.next()? {
        'R' => {
            let rest: Vec<char> = c.collect();
            if rest.len() != 2 || !rest.iter().all(|x| x.is_ascii_alphanumeric()) {
                return None; // a component (R^n_34, R^τ_34)
            }
            r.pairs
                .get(&(rest[0].to_string(), rest[1].to_string()))
                .copied()
        }
        'Φ' => r.inertia.get(c.as_str()).copied(),
        _ => None,
    }
}

/// Check the polygons of one force sheet; their fills, and how many
/// forces were compared with the result.
fn sheet(where_: &str, svg: &str, r: &Result) -> (Vec<Fill>, usize) {
    let ids = by_id(svg);
    let tree = mechplan::drawing::tree(svg).unwrap();
    let mut fills = Vec::new();
    let mut compared = 0;
    for i in 1.. {
        let tag = format!("f{i}");
        let Some(bx) = ids.get(&format!("{tag}-polygon-box")) else {
            break;
        };
        let (bx, panel) = (data_box(bx), data_box(&ids[&format!("{tag}-panel")]));
        let mu_text = text_of(&ids[&format!("{tag}-mu")]);
        let mu = number(
            mu_text
                .split(" = ")
                .nth(1)
                .and_then(|t| t.split(' ').next())
                .unwrap_or_else(|| panic!("{where_}: no μ_F in {mu_text}")),
        );
        assert!(
            standard(mu),
            "{where_} {tag}: μ_F = {mu} is no standard value"
        );
        let prefix = format!("{tag}-vec-");
        let mut extent: Option<kurbo::Rect> = None;
        for (id, line) in &ids {
            let Some(ends) = id.strip_prefix(&prefix) else {
                continue;
            };
            if ends.ends_with("-label") {
                continue;
            }
            let a = kurbo::Point::new(num(line, "x1"), num(line, "y1"));
            let b = kurbo::Point::new(num(line, "x2"), num(line, "y2"));
            let seg = kurbo::Rect::from_points(a, b);
            extent = Some(extent.map_or(seg, |e| e.union(seg)));
            // Its name: on the polygon, or on a detail's copy of it.
            let label = ids.get(&format!("{id}-label")).cloned().or_else(|| {
                (1..=4).find_map(|n| ids.get(&format!("{tag}-d{n}-vec-{ends}-label")).cloned())
            });
            let Some(want) = label.and_then(|l| stated(&text_of(&l), r)) else {
                continue;
            };
            // Read off at μ_F (the page's y down); each end written to
            // 0.01 mm.
            let got = kurbo::Vec2::new(b.x - a.x, a.y - b.y) * mu;
            let tol = 0.0101 * mu + 1e-9 * want.hypot();
            assert!(
                (got.x - want.x).abs() <= tol && (got.y - want.y).abs() <= tol,
                "{where_} {id}: read {got:?} at μ_F = {mu}, the result {want:?}"
            );
            compared += 1;
        }
        let v = extent.unwrap_or_else(|| panic!("{where_} {tag}: no vectors"));
        let e = drawn_box(&tree, &format!("{tag}-polygon"))
            .unwrap_or_else(|| panic!("{where_} {tag}: no polygon group"));
        let share = |e: kurbo::Rect, of: kurbo::Rect| {
            (e.width() / of.width()).max(e.height() / of.height())
        };
        let f = Fill {
            of_box: share(e, bx),
            of_panel: share(e, panel),
            vectors_of_box: share(v, bx),
            vectors_of_panel: share(v, panel),
        };
        assert!(
            f.of_box >= LEAST_FILL,
            "{where_} {tag}: the polygon ({:.1} × {:.1} mm at μ_F = {mu}) spans {:.0} % of its box ({:.1} × {:.1} mm)",
            e.width(),
            e.height(),
            100.0 * f.of_box,
            bx.width(),
            bx.height()
        );
        // Within its box.
        assert!(
            e.x0 >= bx.x0 - 0.5
                && e.x1 <= bx.x1 + 0.5
                && e.y0 >= bx.y0 - 0.5
                && e.y1 <= bx.y1 + 0.5,
            "{where_} {tag}: the polygon {e:?} leaves its box {bx:?}"
        );
        fills.push(f);
    }
    (fills, compared)
}

/// Every force sheet of `name` drawn with `args`, checked; the fills.
fn mode(name: &str, args: &[&str], label: &str) -> Vec<Fill> {
    let scene = format!(
        "{}/fixtures/dynamics/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let json: Value =
        serde_json::from_str(&mechplan(&["solve", &scene, "--format", "json"])).unwrap();
    let results = results(&json);
    let dir = Dir(std::env::temp_dir().join(format!(
        "mechplan-force-fill-{name}-{label}-{}",
        std::process::id()
    )));
    let out = dir.0.to_str().unwrap().to_string();
    let mut all = vec!["draw", scene.as_str(), "-o", out.as_str()];
    all.extend_from_slice(args);
    mechplan(&all);
    let sheets: Value = serde_json::from_str(
        &std::fs::read_to_string(Path::new(&out).join("sheets.json")).unwrap(),
    )
    .unwrap();
    let mut fills = Vec::new();
    let mut seen = 0;
    for s in sheets["sheets"].as_array().unwrap() {
        let file = s["file"].as_str().unwrap();
        if !(file.starts_with("forces_") || file == "course_forces.svg") {
            continue;
        }
        let where_ = format!("{name} {label} {file}");
        let svg = std::fs::read_to_string(Path::new(&out).join(file)).unwrap();
        let k = s["position"].as_i64().unwrap();
        let (f, compared) = sheet(&where_, &svg, &results[&k]);
        assert!(!f.is_empty(), "{where_}: no polygon");
        assert!(compared > 0, "{where_}: no force compared with the result");
        // The μ_F the manifest lists for the sheet are its panels'.
        let listed = &s["scales"]["mu_F"];
        assert!(!listed.is_null(), "{where_}: no μ_F in sheets.json");
        fills.extend(f);
        seen += 1;
    }
    assert!(seen > 0, "{name} {label}: no force sheet");
    fills
}

fn report(label: &str, fills: &[Fill]) {
    let stat = |v: Vec<f64>| {
        let min = v.iter().copied().fold(f64::INFINITY, f64::min);
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        format!("min {:.0} %, mean {:.0} %", 100.0 * min, 100.0 * mean)
    };
    println!(
        "{label}: {} polygons; drawn, of their box {}, of their panel {}; vectors alone, of their box {}, of their panel {}",
        fills.len(),
        stat(fills.iter().map(|f| f.of_box).collect()),
        stat(fills.iter().map(|f| f.of_panel).collect()),
        stat(fills.iter().map(|f| f.vectors_of_box).collect()),
        stat(fills.iter().map(|f| f.vectors_of_panel).collect())
    );
}

fn check(args: &[&str], label: &str) {
    let mut all = Vec::new();
    for name in DYNAMICS {
        all.extend(mode(name, args, label));
    }
    report(label, &all);
}

#[test]
fn force_sheets_fill_their_polygon_boxes() {
    check(&[], "plain");
}

#[test]
fn the_course_force_sheet_fills_its_polygon_boxes() {
    check(&["--course"], "course");
}

#[test]
fn a4_force_sheets_fill_their_polygon_boxes() {
    check(&["--sheet", "A4", "--title-block"], "a4");
}
