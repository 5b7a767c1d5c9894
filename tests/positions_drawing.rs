//! The positions drawing as the lecture draws it (Fig. 2.1), read back
//! from the written SVG: every rigid link a closed figure in every thin
//! position (its body's corners, centres of mass left out), and the
//! output's second extreme position (the end of the working stroke, A′₀)
//! in dash-dot-dot lines with its crank end named.

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
