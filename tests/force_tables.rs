//! A force given by a table against its point's displacement (a working
//! resistance over the stroke): the same analysis as the per-position
//! list a hand computes from the positions found; a position outside the
//! table refused with its pointer; bad tables named by field.

use mechplan::scene::Scene;
use mechplan::{Analysis, report};
use serde_json::{Value, json};

/// The worked slider-crank turned through 12 positions, the working
/// resistance on slider 3 given as `f` (replacing the fixture's force).
fn scene(f: Value) -> Value {
    let path = format!(
        "{}/fixtures/dynamics/worked_slider_crank.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["positions"] = json!({ "count": 12 });
    v["dynamics"]["forces"][0]["F"] = f;
    v
}

fn run(v: &Value) -> mechplan::Result<Vec<Value>> {
    let an = Analysis::new(Scene::from_json(&v.to_string())?)?;
    Ok(an
        .run()?
        .iter()
        .enumerate()
        .map(|(k, s)| report::position_json(&an, k, s))
        .collect())
}

/// The cutting force of a shaper's kind: −2000 N along x while the slider
/// moves away from its outer dead centre (x = r + l = 0.5 m), growing
/// over the first 0.05 m of travel; nothing on the way back.
fn table() -> Value {
    json!({
        "from": [0.5, 0.0],
        "s": [0.0, 0.05, 0.2],
        "working": [[0.0, 0.0], [-2000.0, 0.0], [-2000.0, 0.0]],
    })
}

#[test]
fn a_table_gives_the_forces_a_hand_reads_off_it() {
    let by_table = run(&scene(table())).unwrap();
    // The same force per position, read off the table here by hand from
    // the slider's place and velocity in the result.
    let mut list = Vec::new();
    let mut working = 0;
    for p in &by_table {
        let b = &p["points"]["B"];
        let (x, vx) = (b["p"][0].as_f64().unwrap(), b["v"][0].as_f64().unwrap());
        let s = 0.5 - x;
        // Moving away from x = 0.5: toward −x.
        let f = if vx <= 0.0 {
            working += 1;
            -2000.0 * (s / 0.05).min(1.0)
        } else {
            0.0
        };
        list.push(json!([f, 0.0]));
    }
    assert!(
        (4..=8).contains(&working),
        "{working} positions on the working stroke"
    );
    let by_list = run(&scene(Value::Array(list))).unwrap();
    for (a, b) in by_table.iter().zip(&by_list) {
        let (a, b) = (&a["dynamics"], &b["dynamics"]);
        let (ma, mb) = (
            a["balancing"]["M"].as_f64().unwrap(),
            b["balancing"]["M"].as_f64().unwrap(),
        );
        assert!((ma - mb).abs() <= 1e-9 * ma.abs().max(1.0), "{ma} vs {mb}");
        assert_eq!(
            a["pairs"].as_array().unwrap().len(),
            b["pairs"].as_array().unwrap().len()
        );
    }
}

#[test]
fn a_position_outside_the_table_is_refused() {
    let mut t = table();
    t["s"] = json!([0.0, 0.05, 0.1]);
    let e = run(&scene(t)).unwrap_err().to_string();
    assert!(
        e.contains("/dynamics/forces/0/F/s") && e.contains("outside its displacements"),
        "{e}"
    );
}

#[test]
fn bad_tables_are_named_by_field() {
    let cases = [
        (
            json!({ "s": [0, 1], "working": [[0, 0], [1, 0]] }),
            "/dynamics/forces/0/F/from",
        ),
        (
            json!({ "from": "Q", "s": [0, 1], "working": [[0, 0], [1, 0]] }),
            "/dynamics/forces/0/F/from",
        ),
        (
            json!({ "from": "O", "s": [0], "working": [[0, 0]] }),
            "/dynamics/forces/0/F/s",
        ),
        (
            json!({ "from": "O", "s": [0, 0.2, 0.1], "working": [[0, 0], [1, 0], [2, 0]] }),
            "/dynamics/forces/0/F/s",
        ),
        (
            json!({ "from": "O", "s": [0, 1], "working": [[0, 0]] }),
            "/dynamics/forces/0/F/working",
        ),
        (
            json!({ "from": "O", "s": [0, 1] }),
            "/dynamics/forces/0/F/working",
        ),
        (
            json!({ "from": "O", "s": [0, 1], "working": [[0, 0], [1, 0]], "back": [[0, "x"], [1, 0]] }),
            "/dynamics/forces/0/F/back/0/1",
        ),
        (
            json!({ "from": "O", "s": [0, 1], "working": [[0, 0], [1, 0]], "colour": 1 }),
            "/dynamics/forces/0/F/colour",
        ),
    ];
    for (t, at) in cases {
        let e = Scene::from_json(&scene(t.clone()).to_string())
            .unwrap_err()
            .to_string();
        assert!(e.contains(at), "{t}: {e}");
    }
}
