//! The scenes the generator is run on: every fixture (fixtures/*.json) at
//! three positions, each scene file rewritten with its three positions
//! given explicitly (so that an answer's `position` 1, 2, 3 names the same
//! position in every numbering), and scenes made for one construction.

use mechplan::{Analysis, Scene, Solved};
use serde_json::{Value, json};

/// A scene with its three positions solved.
pub struct Case {
    pub name: String,
    /// The scene file as solved (its positions explicit).
    pub json: Value,
    pub an: Analysis,
    pub solved: Vec<Solved>,
}

fn fixture(name: &str) -> Value {
    let path = format!("{}/fixtures/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap()
}

/// The names of fixtures/*.json, sorted.
pub fn fixture_names() -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(format!("{}/fixtures", env!("CARGO_MANIFEST_DIR")))
            .unwrap()
            .filter_map(|e| {
                let p = e.unwrap().path();
                (p.extension().is_some_and(|x| x == "json"))
                    .then(|| p.file_stem().unwrap().to_string_lossy().into_owned())
            })
            .collect();
    names.sort();
    names
}

fn solve(v: &Value) -> (Analysis, Vec<Solved>) {
    let an = Analysis::new(Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let s = an.run().unwrap();
    (an, s)
}

/// The inputs' values of a solved position in the scene file's units (an
/// angle in its angle unit, a slide in its length unit).
fn file_values(v: &Value, s: &Solved) -> Vec<f64> {
    let deg = v["units"]["angle"].as_str() != Some("rad");
    let unit = if v["units"]["length"].as_str() == Some("mm") {
        0.001
    } else {
        1.0
    };
    let list: Vec<&Value> = match &v["input"] {
        Value::Array(a) => a.iter().collect(),
        i => vec![i],
    };
    s.drives
        .coords()
        .iter()
        .zip(list)
        .map(|(&q, i)| {
            if i["slider"].as_bool() == Some(true) {
                q / unit
            } else if deg {
                q.to_degrees()
            } else {
                q
            }
        })
        .collect()
}

/// The sweep over which a crank fixture assembles (its input values in
/// the file's units), where the scene's own positions are a single one:
/// the scene's own angle turned through a revolution, else the scene's
/// positions.
fn sweep(name: &str, v: &Value) -> Option<Vec<f64>> {
    match name {
        // The slot is parallel to the fixed guide at 0° and 180°.
        "prp_tangent_drive" => Some((0..=140).map(|k| 20.0 + k as f64).collect()),
        // The three-leash group locks near φ = 34.6° and −92°.
        "class3_004" => Some((0..=124).map(|k| -90.0 + k as f64).collect()),
        "slider_driven_rocker" => {
            Some((0..=360).map(|k| -0.06 + 0.36 * k as f64 / 360.0).collect())
        }
        "rrp_rotating_guide_002"
        | "four_bar"
        | "offset_slider_crank"
        | "six_link_fig2_10"
        | "shaper_fig2_11"
        | "compressor_fig2_12" => {
            let a0 = v["input"]["angle"].as_f64().unwrap();
            Some((0..360).map(|k| a0 + k as f64).collect())
        }
        _ => None,
    }
}

/// `v` with its positions given as the list `values` (one row per
/// position, a value per input).
fn with_positions(mut v: Value, values: &[Vec<f64>]) -> Value {
    let several = v["input"].is_array();
    let slider = !several && v["input"]["slider"].as_bool() == Some(true);
    v["positions"] = if several {
        json!({ "values": values })
    } else if slider {
        json!({ "s": values.iter().map(|r| r[0]).collect::<Vec<_>>() })
    } else {
        json!({ "angles": values.iter().map(|r| r[0]).collect::<Vec<_>>() })
    };
    v
}

/// Three positions of scene `v` (a sixth, a half and five sixths of its
/// sweep or of its own positions), the file rewritten with them.
pub fn three_positions(name: &str, v: &Value) -> Case {
    let values: Vec<Vec<f64>> = match sweep(name, v) {
        Some(list) => {
            let n = list.len();
            [n / 6, n / 2, 5 * n / 6]
                .iter()
                .map(|&k| vec![list[k]])
                .collect()
        }
        None => {
            let (_, all) = solve(v);
            let n = all.len();
            let picks: Vec<usize> = if n >= 3 {
                vec![n / 6, n / 2, 5 * n / 6]
            } else {
                (0..n).collect()
            };
            picks.iter().map(|&k| file_values(v, &all[k])).collect()
        }
    };
    let json = with_positions(v.clone(), &values);
    let (an, solved) = solve(&json);
    Case {
        name: name.to_string(),
        json,
        an,
        solved,
    }
}

/// Every fixture at three positions.
pub fn fixtures() -> Vec<Case> {
    fixture_names()
        .iter()
        .map(|n| three_positions(n, &fixture(n)))
        .collect()
}

/// The six-link of lecture Fig. 2.10 with S2 moved off its rod AB, to the
/// side `side` (+1 left of A→B, −1 right), so that the coupler's triangle
/// has the angle `at_s2` (degrees) at S2: its similar figure s2 on a, b is
/// found by two arcs meeting at 180° − `at_s2`.
pub fn six_link_s2_off_the_rod(at_s2: f64, side: f64) -> Case {
    let mut v = fixture("six_link_fig2_10");
    let p = |v: &Value, k: &str| {
        let a = &v["points"][k];
        (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
    };
    let ((ax, ay), (bx, by)) = (p(&v, "A"), p(&v, "B"));
    let ab = v["lengths"]["A-B"].as_f64().unwrap();
    let l = ((bx - ax).powi(2) + (by - ay).powi(2)).sqrt();
    let (nx, ny) = (-(by - ay) / l, (bx - ax) / l);
    let h = 0.5 * ab / (0.5 * at_s2).to_radians().tan();
    let k = side * h * l / ab;
    v["points"]["S2"] = json!([0.5 * (ax + bx) + k * nx, 0.5 * (ay + by) + k * ny]);
    let r = ((0.5 * ab).powi(2) + h * h).sqrt();
    v["lengths"]["A-S2"] = json!(r);
    v["lengths"]["B-S2"] = json!(r);
    let mut case = three_positions("six_link_fig2_10", &v);
    case.name = format!("six_link_S2_at_{at_s2}deg");
    case
}
