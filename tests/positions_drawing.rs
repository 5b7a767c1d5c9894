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
        let bold = mechplan::drawing::chosen::position(study.analysis(), solved);
        let speed = |k: usize| {
            solution
                .position(k + 1)
                .unwrap()
                .point(slider)
                .unwrap()
                .velocity()
                .unwrap()
                .hypot()
        };
        let top = (0..solved.len()).map(speed).fold(0.0, f64::max);
        // Position 1 is the start of the working stroke: the slider stands.
        assert!(
            speed(0) < 1e-9 * top,
            "{name}: position 1 is not a dead centre"
        );
        assert!(
            speed(bold) > 0.3 * top,
            "{name}: bold position {} at {} of the top speed",
            bold + 1,
            speed(bold) / top
        );
    }
}
