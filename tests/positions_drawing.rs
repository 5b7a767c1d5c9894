//! The positions drawing as the lecture draws it (Fig. 2.1), read back
//! from the written SVG: every rigid link a closed figure in every thin
//! position (its body's corners, centres of mass left out), and the
//! output's second extreme position (the end of the working stroke, A′₀)
//! in dash-dot-dot lines with its crank end named.

mod common;

use serde_json::Value;
use std::path::Path;
use std::process::Command;

/// The points of each `<path class="CLASS" d="M x y L x y …"/>`.
fn paths(svg: &str, class: &str) -> Vec<Vec<(f64, f64)>> {
    let tag = format!(r#"<path class="{class}" d=""#);
    svg.match_indices(&tag)
        .map(|(i, _)| {
            let d = &svg[i + tag.len()..];
            let d = &d[..d.find('"').unwrap()];
            d.split(['M', 'L'])
                .filter(|s| !s.trim().is_empty())
                .map(|xy| {
                    let v: Vec<f64> = xy
                        .split([' ', ','])
                        .filter(|s| !s.is_empty())
                        .map(|x| x.parse().unwrap())
                        .collect();
                    (v[0], v[1])
                })
                .collect()
        })
        .collect()
}

fn closed(p: &[(f64, f64)]) -> bool {
    p.len() >= 4 && p[0] == p[p.len() - 1]
}

/// The moving links whose body has three corners or more: points shared
/// with another link, or not a centre of mass (S…).
fn rigid_links(scene: &Value) -> usize {
    let links = scene["links"].as_object().unwrap();
    let shared = |p: &str| {
        links
            .values()
            .filter(|l| l["points"].as_array().unwrap().iter().any(|q| q == p))
            .count()
            >= 2
    };
    links
        .iter()
        .filter(|(id, _)| id.as_str() != "0")
        .filter(|(_, l)| {
            l["points"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|p| {
                    let p = p.as_str().unwrap();
                    shared(p) || !p.starts_with('S')
                })
                .count()
                >= 3
        })
        .count()
}

#[test]
fn rigid_links_closed_and_both_extreme_positions_drawn() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut rigid_seen = 0;
    // The compressor's central slider-crank strokes 180°: its second
    // extreme is position 7, drawn already.
    for (name, apart) in [
        ("six_link_fig2_10", true),
        ("shaper_fig2_11", true),
        ("compressor_fig2_12", false),
        ("four_bar", true),
    ] {
        let path = root.join(format!("fixtures/{name}.json"));
        let scene: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let dir =
            std::env::temp_dir().join(format!("mechplan-positions-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = Command::new(exe)
            .arg("draw")
            .arg(&path)
            .arg("-o")
            .arg(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let svg = std::fs::read_to_string(dir.join("positions.svg")).unwrap();
        let n = svg.matches(r#"id="pos-"#).count();
        assert!(n >= 8, "{name}: {n} positions numbered");
        // Link numbers circled, as the course writes them: never read as
        // the positions' numbers beside them.
        let links = svg.matches(r#"id="link-"#).count();
        assert!(links >= 3, "{name}: {links} link numbers");
        assert_eq!(
            svg.matches(r#"<circle class="link-number""#).count(),
            links,
            "{name}: link numbers not circled"
        );
        // A slider on a fixed guide: its places numbered as the crank's.
        if name == "six_link_fig2_10" {
            assert_eq!(
                svg.matches(r#"id="slider-"#).count(),
                n,
                "{name}: slider positions"
            );
        }
        let thin = paths(&svg, "thin");
        for p in &thin {
            assert!(
                p.len() == 2 || closed(p),
                "{name}: a link drawn open in a thin position: {p:?}"
            );
        }
        let rigid = rigid_links(&scene);
        rigid_seen += rigid;
        assert_eq!(
            thin.iter().filter(|p| closed(p)).count(),
            (n - 1) * rigid,
            "{name}: {rigid} rigid links in {} thin positions",
            n - 1
        );
        // The end of the working stroke: every moving link with a body.
        let extreme = paths(&svg, "dash-dot-dot");
        if !apart {
            assert!(extreme.is_empty(), "{name}: an extreme drawn twice");
            std::fs::remove_dir_all(&dir).unwrap();
            continue;
        }
        assert!(!extreme.is_empty(), "{name}: no extreme position drawn");
        assert_eq!(
            extreme.iter().filter(|p| closed(p)).count(),
            rigid,
            "{name}"
        );
        assert!(
            svg.contains(r#"id="extreme-1""#) && svg.contains("′<tspan"),
            "{name}: the second extreme position's crank end is not named"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
    assert!(rigid_seen >= 2, "{rigid_seen}");
}

/// The bold position of the positions drawing is the one the course
/// analyses (the middle of the working stroke), never an extreme position
/// where a slider-crank's links lie on one line and its slider stands.
#[test]
fn the_bold_position_is_not_a_dead_centre() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (name, slider) in [
        ("offset_slider_crank", "B"),
        ("compressor_fig2_12", "D"),
        ("six_link_fig2_10", "D"),
    ] {
        let text = std::fs::read_to_string(root.join(format!("fixtures/{name}.json"))).unwrap();
        let study = mechplan::Study::from_json(&text).unwrap();
        let solution = study.solve().unwrap();
        let solved = solution.solved();
        let bold = mechplan::studies::chosen::Chosen::of(study.analysis(), solved.len())
            .analysed(solved.len());
        let speed = |k: usize| {
            solution
                .position(study.numbering().number(k))
                .unwrap()
                .point(slider)
                .unwrap()
                .velocity()
                .unwrap()
                .hypot()
        };
        let top = (0..solved.len()).map(speed).fold(0.0, f64::max);
        // Position 0 is the start of the working stroke: the slider stands.
        assert!(
            speed(0) < 1e-9 * top,
            "{name}: position 0 is not a dead centre"
        );
        assert!(
            speed(bold) > 0.3 * top,
            "{name}: bold position {} at {} of the top speed",
            bold,
            speed(bold) / top
        );
    }
}

/// The text of every `<text … id="ID" …>TEXT</text>` whose id starts with `prefix`.
fn labelled(svg: &str, prefix: &str) -> Vec<(String, String)> {
    svg.lines()
        .filter_map(|l| {
            let i = l.find(&format!("id=\"{prefix}"))? + 4;
            let id = &l[i..i + l[i..].find('"')?];
            let t = &l[l.find('>')? + 1..l.rfind("</text>")?];
            Some((id.to_string(), t.to_string()))
        })
        .collect()
}

/// The lecture numbers a `count` sweep 0 … 11 from the extreme position
/// (Figs 2.1–2.3), and the diagrams' axis 0 … 12 beside it: the crank's
/// marks (and their ids), the slider's marks, every sheet's title and file
/// name, the course sheet's plan captions and the `solve --steps` text all
/// write the same number for the same position. A sweep of listed angles
/// has no extreme to start from and is numbered from 1.
#[test]
fn positions_are_numbered_as_the_lecture_numbers_them() {
    let exe = env!("CARGO_BIN_EXE_mechplan");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = root.join("fixtures/six_link_fig2_10.json");
    let dir = std::env::temp_dir().join(format!("mechplan-numbers-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(exe)
        .arg("draw")
        .arg(&scene)
        .args(["--course", "-o"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let positions = std::fs::read_to_string(dir.join("positions.svg")).unwrap();
    let crank: Vec<(String, String)> = labelled(&positions, "pos-");
    assert_eq!(crank.len(), 12, "{crank:?}");
    for (id, text) in &crank {
        let k: usize = id["pos-".len()..].parse().unwrap();
        assert_eq!(text, &k.to_string(), "crank mark {id}");
    }
    let slider = labelled(&positions, "slider-");
    assert!(!slider.is_empty(), "the slider's places are numbered");
    for (id, text) in &slider {
        let k: usize = id.rsplit('-').next().unwrap().parse().unwrap();
        assert_eq!(text, &k.to_string(), "slider mark {id}");
    }
    for k in [0, 3, 11] {
        let svg = std::fs::read_to_string(dir.join(format!("velocity_{k}.svg"))).unwrap();
        assert!(
            svg.contains(&format!("position {k}, φ")),
            "velocity_{k}.svg is titled position {k}"
        );
    }
    assert!(!dir.join("velocity_12.svg").exists());
    let course = std::fs::read_to_string(dir.join("course.svg")).unwrap();
    for k in 0..12 {
        assert!(
            course.contains(&format!(">position {k}<")),
            "course caption position {k}"
        );
    }
    assert!(
        !course.contains(">position 12<"),
        "no position 12 on the course sheet"
    );
    let steps = Command::new(exe)
        .arg("solve")
        .arg(&scene)
        .arg("--steps")
        .output()
        .unwrap();
    let steps = String::from_utf8_lossy(&steps.stdout);
    assert!(
        steps.contains("Plan of velocities, position 0, φ1"),
        "{}",
        &steps[..300.min(steps.len())]
    );
    assert!(!steps.contains("position 12,"));
    let _ = std::fs::remove_dir_all(&dir);

    // Listed angles: from 1.
    let listed = root.join("fixtures/prp_tangent_drive.json");
    let steps = Command::new(exe)
        .arg("solve")
        .arg(&listed)
        .arg("--steps")
        .output()
        .unwrap();
    let steps = String::from_utf8_lossy(&steps.stdout);
    assert!(
        steps.contains("position 1,") && !steps.contains("position 0,"),
        "{steps}"
    );
}

/// The value of an attribute `name="…"` of one SVG element's text.
fn attr(element: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let i = element.find(&key)? + key.len();
    Some(element[i..i + element[i..].find('"')?].to_string())
}

/// A straight stroke on a sheet: its two ends (mm) and whether it is drawn
/// in the sheet's main (bold) lines or thin ones (other lines: None).
type Stroke = ((f64, f64), (f64, f64), Option<bool>);

/// Every straight segment the sheet strokes: each `<line>`, each pair of
/// consecutive points of a `<path d="M … L …">` of straight pieces, each
/// side of a `<polygon>` (closed). Bold: class "main", or a stroke width of
/// 0.5 mm (ГОСТ 2.303's main line on these sheets); thin: class "thin".
fn strokes(svg: &str) -> Vec<Stroke> {
    let num = |s: &str| -> f64 { s.trim().parse().unwrap() };
    let pairs = |s: &str| -> Vec<(f64, f64)> {
        let v: Vec<f64> = s
            .split([' ', ',', 'M', 'L'])
            .filter(|x| !x.is_empty())
            .map(num)
            .collect();
        v.chunks(2).map(|c| (c[0], c[1])).collect()
    };
    let mut out = Vec::new();
    for (i, _) in svg.match_indices('<') {
        let element = &svg[i..i + svg[i..].find('>').unwrap() + 1];
        let class = attr(element, "class");
        let width = attr(element, "stroke-width").map(|w| num(&w));
        let style = match (class.as_deref(), width) {
            (Some("main"), _) => Some(true),
            (Some("thin"), _) => Some(false),
            (None, Some(w)) if (w - 0.5).abs() < 1e-9 => Some(true),
            _ => None,
        };
        if element.starts_with("<line ") {
            let a = |n: &str| num(&attr(element, n).unwrap());
            out.push(((a("x1"), a("y1")), (a("x2"), a("y2")), style));
        } else if element.starts_with("<path ") {
            let d = attr(element, "d").unwrap();
            // Arcs and curves are no straight strokes.
            if d.chars()
                .any(|c| c.is_ascii_alphabetic() && c != 'M' && c != 'L')
            {
                continue;
            }
            // Each M starts a new run of straight pieces.
            for run in d.split('M').filter(|r| !r.trim().is_empty()) {
                let p = pairs(run);
                for w in p.windows(2) {
                    out.push((w[0], w[1], style));
                }
            }
        } else if element.starts_with("<polygon ") {
            let p = pairs(&attr(element, "points").unwrap());
            for k in 0..p.len() {
                out.push((p[k], p[(k + 1) % p.len()], style));
            }
        }
    }
    out
}

/// The scale of lengths the sheet states: "μ … = 0.004 m/mm" (a decimal
/// comma read too).
fn stated_mu_l(svg: &str) -> f64 {
    let line = svg
        .lines()
        .find(|l| l.contains("<tspan>μ</tspan>") && l.contains("m/mm"))
        .expect("the sheet states its scale μ_l in m/mm");
    let text: String = {
        // The text of the element without its tags.
        let mut t = String::new();
        let mut inside = false;
        for c in line.chars() {
            match c {
                '<' => inside = true,
                '>' => inside = false,
                c if !inside => t.push(c),
                _ => {}
            }
        }
        t
    };
    let after = &text[text.find('=').unwrap() + 1..text.find("m/mm").unwrap()];
    after.trim().replace(',', ".").parse().unwrap()
}

/// Every position of a `count` sweep, position 0 (the start of the working
/// stroke, A₀) included, has its crank drawn on the positions sheet: a
/// stroke from the crank's pivot to its tip A_k, thin, and the position
/// drawn bold in main lines once, never again in thin ones.
///
/// The crank's figure in each position is found from the scene alone: its
/// points (centres of mass left out) turned rigidly about the pivot from
/// the scene's input angle to the position's (the angles `solve --format
/// json` gives), put on the sheet at the scale the sheet states, the
/// pivot's place being the pivot symbol from which the scene's other fixed
/// pivots lie where the scale puts them (y up in the scene, down on the
/// sheet). A figure of two or three points has a side between each two of
/// them, so the stroke O–A_k is expected as many times, thin and bold, as
/// there are sides on it in the thin positions and in the bold one (the
/// compressor's crank has two opposite throws: A of one position is C of
/// the position half a turn on).
#[test]
fn every_position_has_its_crank_drawn_position_0_included() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for name in ["six_link_fig2_10", "compressor_fig2_12"] {
        let path = root.join(format!("fixtures/{name}.json"));
        let path_s = path.to_str().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let scene: Value = serde_json::from_str(&text).unwrap();
        let dir = common::fresh("positions-crank", name);
        let (code, _, err) = common::run(&["draw", path_s, "-o", dir.to_str().unwrap()]);
        assert_eq!(code, 0, "{name}: {err}");
        let svg = std::fs::read_to_string(dir.join("positions.svg")).unwrap();
        let (code, out, err) = common::run(&["solve", path_s, "--format", "json"]);
        assert_eq!(code, 0, "{name}: {err}");
        let solved: Value = serde_json::from_str(&out).unwrap();
        let angles: Vec<f64> = solved["positions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["input"]["angle"].as_f64().unwrap())
            .collect();
        let count = scene["positions"]["count"].as_u64().unwrap() as usize;
        assert_eq!(angles.len(), count, "{name}: positions solved");

        let mu = stated_mu_l(&svg);
        let point = |n: &str| {
            let v = &scene["points"][n];
            (v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
        };
        let input = &scene["input"];
        let pivot_name = input["pivot"].as_str().unwrap();
        let o = point(pivot_name);
        let near = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1) < 0.05;
        // The pivot symbols on the sheet; the scene's fixed points.
        let pivots: Vec<(f64, f64)> = svg
            .lines()
            .filter(|l| l.starts_with(r#"<g data-symbol="pivot""#))
            .map(|l| {
                let a = |n: &str| attr(l, n).unwrap().parse::<f64>().unwrap();
                (a("data-x"), a("data-y"))
            })
            .collect();
        let fixed: Vec<(f64, f64)> = scene["links"]["0"]["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| point(p.as_str().unwrap()))
            .collect();
        let places: Vec<(f64, f64)> = pivots
            .iter()
            .copied()
            .filter(|&c| {
                pivots.iter().all(|&q| {
                    let at = (o.0 + (q.0 - c.0) * mu, o.1 - (q.1 - c.1) * mu);
                    fixed
                        .iter()
                        .any(|&f| (f.0 - at.0).hypot(f.1 - at.1) < 0.05 * mu)
                })
            })
            .collect();
        assert_eq!(places.len(), 1, "{name}: the crank's pivot on the sheet");
        let origin = places[0];
        let sheet = |p: (f64, f64)| (origin.0 + (p.0 - o.0) / mu, origin.1 - (p.1 - o.1) / mu);

        // The crank's points in position k, on the sheet.
        let crank = &scene["links"][input["link"].as_str().unwrap()];
        let names: Vec<&str> = crank["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p.as_str().unwrap())
            .filter(|p| !p.starts_with('S'))
            .collect();
        let tip = "A";
        assert!(
            names.contains(&tip) && names.contains(&pivot_name),
            "{name}"
        );
        let at = |k: usize, n: &str| {
            let turn = (angles[k] - input["angle"].as_f64().unwrap()).to_radians();
            let p = point(n);
            let (dx, dy) = (p.0 - o.0, p.1 - o.1);
            sheet((
                o.0 + dx * turn.cos() - dy * turn.sin(),
                o.1 + dx * turn.sin() + dy * turn.cos(),
            ))
        };
        // The crank's tip in the scene's own position: a check of the
        // turning and of the scale's reading.
        let r = {
            let a = point(tip);
            (a.0 - o.0).hypot(a.1 - o.1)
        };
        let by_angle = |k: usize| {
            let f = angles[k].to_radians();
            sheet((o.0 + r * f.cos(), o.1 + r * f.sin()))
        };
        for k in 0..count {
            assert!(near(at(k, tip), by_angle(k)), "{name}: A_{k}");
        }

        let same = |s: &Stroke, a: (f64, f64), b: (f64, f64)| {
            (near(s.0, a) && near(s.1, b)) || (near(s.0, b) && near(s.1, a))
        };
        // The sides of position j's crank figure that lie on O–A_k.
        let sides_on = |j: usize, k: usize| {
            let (a, b) = (at(k, pivot_name), at(k, tip));
            let mut n = 0;
            for x in 0..names.len() {
                for y in x + 1..names.len() {
                    let s = (at(j, names[x]), at(j, names[y]), None);
                    n += same(&s, a, b) as usize;
                }
            }
            n
        };
        let bold = {
            let study = mechplan::Study::from_json(&text).unwrap();
            mechplan::studies::chosen::Chosen::of(study.analysis(), count).analysed(count)
        };
        let drawn = strokes(&svg);
        for k in 0..count {
            let (a, b) = (at(k, pivot_name), at(k, tip));
            let thin = drawn
                .iter()
                .filter(|s| s.2 == Some(false) && same(s, a, b))
                .count();
            let main = drawn
                .iter()
                .filter(|s| s.2 == Some(true) && same(s, a, b))
                .count();
            let want_thin: usize = (0..count)
                .filter(|&j| j != bold)
                .map(|j| sides_on(j, k))
                .sum();
            let want_main = sides_on(bold, k);
            assert!(
                k == bold && want_main >= 1 || k != bold && want_thin >= 1,
                "{name}: the crank figure of position {k} is not on O–A_{k}"
            );
            assert_eq!(
                (thin, main),
                (want_thin, want_main),
                "{name}: position {k} (bold {bold}): the crank {pivot_name}–{tip}_{k} from {a:?} \
                 to {b:?}, drawn (thin, main) times"
            );
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
