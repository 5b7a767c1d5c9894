//! Rigid shapes from arbitrary data (`src/shape.rs`): a link of 3 to 8
//! points with arbitrary sketch coordinates (from tiny to huge, needles,
//! points nearly on a line) and arbitrary given lengths between them.
//! Building the mechanism must never panic, and a shape that is built must
//! hold its data: every coordinate finite, every given length of the link
//! to the rounding slack the reader promises, every point placed by a
//! triangle on the side of its references' line where the sketch draws it.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use mechplan::Scene;
use mechplan::mechanism::Mechanism;
use mechplan::shape::{Placement, length_slack};

#[derive(Arbitrary, Debug)]
struct Link {
    /// Sketch coordinates as mantissa and decimal exponent: spans from
    /// 1e-12 to 1e9, so needles and tiny parts far from the origin occur.
    points: Vec<(i32, i32, i8)>,
    /// (i, j, value scale, exponent): a given length between points i and
    /// j, near their sketch distance or anything.
    lengths: Vec<(u8, u8, i16, i8)>,
}

fn num(m: i32, e: i8) -> f64 {
    m as f64 * 10f64.powi((e % 22) as i32 - 12)
}

fuzz_target!(|link: Link| {
    let n = link.points.len().clamp(0, 8);
    if n < 3 {
        return;
    }
    let pts: Vec<(f64, f64)> = link.points[..n]
        .iter()
        .map(|&(x, y, e)| (num(x, e), num(y, e)))
        .collect();
    let mut points = serde_json::Map::new();
    points.insert("O".into(), serde_json::json!([pts[0].0 - 1.0, pts[0].1]));
    for (k, p) in pts.iter().enumerate() {
        points.insert(format!("P{k}"), serde_json::json!([p.0, p.1]));
    }
    let names: Vec<String> = (0..n).map(|k| format!("P{k}")).collect();
    let mut lengths = serde_json::Map::new();
    for &(i, j, scale, e) in link.lengths.iter().take(12) {
        let (i, j) = (i as usize % n, j as usize % n);
        if i == j {
            continue;
        }
        let sketch = ((pts[i].0 - pts[j].0).powi(2) + (pts[i].1 - pts[j].1).powi(2)).sqrt();
        // Half of them near the sketch's distance, half anything.
        let v = if e % 2 == 0 {
            sketch * (1.0 + scale as f64 * 1e-6)
        } else {
            num(scale as i32, e).abs()
        };
        if v.is_finite() && v > 0.0 {
            lengths.insert(format!("{}-{}", names[i], names[j]), serde_json::json!(v));
        }
    }
    let scene = serde_json::json!({
        "mechplan": 1,
        "points": points,
        "links": {
            "0": { "points": ["O", "P0"] },
            "1": { "points": ["P0", "P1"] },
            "2": { "points": names[1..].to_vec() },
        },
        "lengths": lengths,
        "input": { "link": "1", "pivot": "P0", "angle": 0, "omega": 1 },
    });
    // P0 is on the frame and the crank; the link under test is P1…Pn−1.
    let Ok(scene) = Scene::from_json(&scene.to_string()) else {
        return;
    };
    let Ok(m) = Mechanism::new(scene) else {
        return;
    };
    let l = m.scene.link_index("2").unwrap();
    let link = &m.links[l];
    for v in &link.local {
        assert!(v.x.is_finite() && v.y.is_finite(), "{:?}", link.local);
    }
    for len in &m.scene.lengths {
        let (Some(a), Some(b)) = (link.local_of(len.a), link.local_of(len.b)) else {
            continue;
        };
        let got = (a - b).hypot();
        let slack = length_slack(&m.scene, &link.points, len.value, a, b);
        assert!(
            (got - len.value).abs() <= slack,
            "{}: {got} vs {} (slack {slack})",
            len.key,
            len.value
        );
    }
    for (k, p) in m.placements[l].iter().enumerate() {
        if let Placement::Triangle { refs, side } = *p {
            let (a, b, x) = (link.local[refs.0], link.local[refs.1], link.local[k]);
            let cross = (b - a).cross(x - a);
            // A flat triangle (to rounding) may land a rounding either side.
            let noise = 64.0
                * f64::EPSILON
                * (b - a).hypot()
                * ((x - a).hypot() + a.hypot() + b.hypot());
            assert!(
                cross * side >= -noise,
                "point {k} on the wrong side: {cross} vs {side}"
            );
        }
    }
});
