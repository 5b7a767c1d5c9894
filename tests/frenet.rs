//! Paper 001: the slider-crank's rod point in the Frenet trihedron of the
//! crank circle (eq. 8, and the general eqs. 3, 5, 7) equals mechplan's
//! positions over a revolution to 1e-12.

use mechplan::frenet;
use mechplan::positions::PositionSolver;
use mechplan::{Analysis, Scene};

#[test]
fn frenet_trajectory_equals_mechplan_over_a_revolution() {
    // The paper's Fig. 5: k = 0.2 (crank r = 5), rod AB = 8; a rod point
    // 3 from A. Slider B on the vertical through O, above A.
    let (k, l, rho) = (0.2, 8.0, 3.0);
    let s0 = 1.0; // the sketch's arc length
    let a = frenet::rod_point(k, l, 0.0, s0);
    let b = frenet::rod_point(k, l, l, s0);
    let p = frenet::rod_point(k, l, rho, s0);
    let phi0 = (k * s0 - std::f64::consts::FRAC_PI_2).to_degrees();
    let scene = serde_json::json!({
        "mechplan": 1,
        "title": "Central slider-crank of paper 001, Fig. 5 (k = 0.2, AB = 8)",
        "units": { "length": "m", "angle": "deg" },
        "points": { "O": [0, 0], "A": [a.x, a.y], "B": [b.x, b.y], "P": [p.x, p.y] },
        "links": {
            "0": { "points": ["O"] },
            "1": { "points": ["O", "A"] },
            "2": { "points": ["A", "B", "P"] },
            "3": { "points": ["B"] }
        },
        "sliders": [
            { "slider": "3", "guide": "0", "point": "B", "line": { "through": [0, 0], "angle": 90 } }
        ],
        "lengths": { "O-A": 1.0 / k, "A-B": l, "A-P": rho, "B-P": l - rho },
        "input": { "link": "1", "pivot": "O", "angle": phi0, "omega": 1 }
    });
    let an = Analysis::new(Scene::from_json(&scene.to_string()).unwrap()).unwrap();
    let m = &an.mech;
    let (ip, ib) = (
        m.scene.point_index("P").unwrap(),
        m.scene.point_index("B").unwrap(),
    );
    let mut ps = PositionSolver::new(m, &an.structure, an.need.clone()).unwrap();
    let turn = 2.0 * std::f64::consts::PI / k;
    let mut worst = 0.0f64;
    for j in 0..=3600 {
        let s = s0 + turn * j as f64 / 3600.0;
        let c = ps.solve(k * s - std::f64::consts::FRAC_PI_2).unwrap();
        let got_p = c.point(m, 2, ip);
        let got_b = c.point(m, 2, ib);
        for (got, want) in [
            (got_p, frenet::rod_point(k, l, rho, s)),
            (got_p, frenet::rod_point_general(k, l, rho, s)),
            (got_b, frenet::rod_point(k, l, l, s)),
        ] {
            worst = worst.max((got - want).hypot() / l);
        }
    }
    eprintln!(
        "Frenet (eq. 8 and eqs. 3, 5, 7) against mechplan over a revolution: {worst:.1e} of AB"
    );
    assert!(worst <= 1e-12, "{worst:e}");
}

/// Eq. 8's special cases the paper names: ρ = L gives the slider's
/// straight line (x = 0), ρ = 0 the crank circle of radius 1/k.
#[test]
fn eq_8_special_cases() {
    let (k, l) = (0.2, 8.0);
    for j in 0..100 {
        let s = j as f64 * 0.37;
        assert!(frenet::rod_point(k, l, l, s).x.abs() < 1e-12);
        let a = frenet::rod_point(k, l, 0.0, s);
        assert!((a.to_vec2().hypot() - 1.0 / k).abs() < 1e-12);
    }
}

/// `mechplan frenet` writes the nine families of Figs 2, 3 and 5.
#[test]
fn frenet_command_writes_the_families() {
    let dir = std::env::temp_dir().join(format!("mechplan-frenet-{}", std::process::id()));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["frenet", "-o", dir.to_str().unwrap(), "--count", "24"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for f in [
        "fig2a", "fig2b", "fig2c", "fig3a", "fig3b", "fig3c", "fig5a", "fig5b", "fig5c",
    ] {
        let svg = std::fs::read_to_string(dir.join(format!("{f}.svg"))).unwrap();
        // The segments and the trajectories are there: many lines.
        assert!(
            svg.matches("<line").count() + svg.matches("<path").count() > 100,
            "{f}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
    let bad = std::process::Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(["frenet", "--count", "1"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}
