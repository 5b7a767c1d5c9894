//! Sweeps at scale (issue 16): `solve --format csv` and `--format jsonl`
//! give the JSON result's numbers, a row (a line) per position, the
//! columns `want` asks for; a sweep of 20 000 positions streams to a file
//! in bounded memory and agrees with a short solve of the same positions.

mod common;
use common::*;
use mechplan::report::{self, Style};
use serde_json::{Value, json};
use std::path::PathBuf;
use std::process::{Command, Output};

const EXE: &str = env!("CARGO_BIN_EXE_mechplan");

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mechplan-csv-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A CSV text as its header and rows of fields (no field of the fixtures
/// needs quotes).
fn parse_csv(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines();
    let head: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    for r in &rows {
        assert_eq!(r.len(), head.len(), "a row has every column");
    }
    (head, rows)
}

/// The value of CSV column `col` in a position of the JSON result (the
/// column names of docs/scene-format.md, "CSV and JSONL results").
fn json_value(doc_pos: &Value, input_kinds: &[(String, bool)], col: &str) -> Value {
    if col == "position" {
        // The JSON result's number of the position, as the sheets show it.
        return doc_pos["position"].clone();
    }
    let (kind, id) = col.split_once('_').unwrap();
    let pair = |v: &Value, i: usize| v[i].clone();
    match kind {
        "phi" | "s" => {
            let i = input_kinds.iter().position(|(n, _)| n == id).unwrap();
            let input = if input_kinds.len() > 1 {
                doc_pos["input"][i].clone()
            } else {
                doc_pos["input"].clone()
            };
            input[if input_kinds[i].1 { "angle" } else { "s" }].clone()
        }
        "x" => pair(&doc_pos["points"][id]["p"], 0),
        "y" => pair(&doc_pos["points"][id]["p"], 1),
        "vx" => pair(&doc_pos["points"][id]["v"], 0),
        "vy" => pair(&doc_pos["points"][id]["v"], 1),
        "ax" => pair(&doc_pos["points"][id]["a"], 0),
        "ay" => pair(&doc_pos["points"][id]["a"], 1),
        "angle" | "omega" | "epsilon" => doc_pos["links"][id][kind].clone(),
        _ => panic!("unknown column {col}"),
    }
}

/// Every CSV cell is the JSON result's number (as JSON text: the same
/// digits), every JSON number of `p`, `v`, `a`, `angle`, `omega`,
/// `epsilon` has its column, and the JSONL lines are the JSON positions.
fn check_formats(v: &Value, what: &str) {
    let scene = mechplan::Scene::from_json(&v.to_string()).unwrap();
    let (an, solved) = solve(scene);
    let doc = report::to_json(&an, &solved);
    let positions = doc["positions"].as_array().unwrap();
    let inputs: Vec<(String, bool)> = an
        .mech
        .scene
        .inputs()
        .map(|i| (an.mech.link_id(i.link()).to_string(), i.is_crank()))
        .collect();
    let csv = report::to_text(&an, &solved, Style::Csv);
    let (head, rows) = parse_csv(&csv);
    assert_eq!(rows.len(), solved.len(), "{what}");
    for (k, row) in rows.iter().enumerate() {
        // A count sweep from 0, given values from 1.
        let first = usize::from(!matches!(
            v["positions"].get("count"),
            Some(Value::Number(_))
        ));
        assert_eq!(positions[k]["position"], json!(k + first), "{what}");
        for (col, cell) in head.iter().zip(row) {
            let want = json_value(&positions[k], &inputs, col);
            assert!(!want.is_null(), "{what}: column {col} has no JSON value");
            // The same digits as the JSON text (built from the f64s).
            assert_eq!(
                cell,
                &want.to_string(),
                "{what}: position {} column {col}",
                k + 1
            );
        }
    }
    // Every number of the JSON position that the CSV promises is a column.
    let mut expected = 1 + inputs.len();
    let p0 = &positions[0];
    for (_, pt) in p0["points"].as_object().unwrap() {
        expected += ["p", "v", "a"]
            .iter()
            .filter(|k| pt.get(**k).is_some())
            .count()
            * 2;
    }
    for (_, l) in p0["links"].as_object().unwrap() {
        expected += ["angle", "omega", "epsilon"]
            .iter()
            .filter(|k| l.get(**k).is_some())
            .count();
    }
    assert_eq!(head.len(), expected, "{what}: {head:?}");
    // JSONL: a position a line, the JSON result's objects.
    let jsonl = report::to_text(&an, &solved, Style::Jsonl);
    let lines: Vec<&str> = jsonl.lines().collect();
    assert_eq!(lines.len(), solved.len(), "{what}");
    assert!(jsonl.ends_with('\n'));
    for (k, (line, pos)) in lines.iter().zip(positions).enumerate() {
        // The text of the object (serde_json's reading of a number need
        // not round correctly, so texts are compared, not values).
        let same = *line == serde_json::to_string(pos).unwrap();
        assert!(
            same,
            "{what}: JSONL line {} is not position {}",
            k + 1,
            k + 1
        );
    }
}

#[test]
fn csv_and_jsonl_give_the_json_results_numbers() {
    for name in FIXTURES {
        let v = fixture(name);
        let mut swept = v.clone();
        swept["positions"] = sweep(name, &v);
        check_formats(&swept, name);
    }
    for name in ["arm_two_cylinders", "five_bar_two_cranks", "boom_cylinder"] {
        check_formats(&fixture(name), name);
    }
}

#[test]
fn csv_columns_follow_want() {
    let v = fixture("six_link_fig2_10");
    let with = |want: Value| {
        let mut v = v.clone();
        v["want"] = want;
        check_formats(&v, &v["want"].to_string());
        let an =
            mechplan::Analysis::new(mechplan::Scene::from_json(&v.to_string()).unwrap()).unwrap();
        report::csv_head(&an)
    };
    let all = with(json!({}));
    assert!(all.contains(",ax_D,ay_D,") && all.contains(",epsilon_5"));
    let vel = with(json!({ "plans": ["velocity"] }));
    assert!(
        vel.contains(",vx_D,vy_D,") && vel.contains(",omega_5"),
        "{vel}"
    );
    assert!(!vel.contains("ax_") && !vel.contains("epsilon_"), "{vel}");
    let none = with(json!({ "plans": [] }));
    assert!(!none.contains("vx_") && !none.contains("omega_"), "{none}");
    assert!(
        none.contains(",x_D,y_D") && none.contains(",angle_5"),
        "{none}"
    );
    // Only S2: its point, and the links of the groups it hangs on.
    let s2 = with(json!({ "points": ["S2"] }));
    assert!(s2.starts_with("position,phi_1,x_S2,y_S2,vx_S2,vy_S2,ax_S2,ay_S2,angle_"));
    assert!(!s2.contains("_D,") && !s2.contains("angle_5"), "{s2}");
}

#[test]
fn csv_quotes_names_that_need_it() {
    // Link ids are any string: the coupler "2" renamed `2,"c"`.
    let mut v = fixture("four_bar");
    let coupler = v["links"]["2"].clone();
    let links = v["links"].as_object_mut().unwrap();
    links.remove("2");
    links.insert("2,\"c\"".into(), coupler);
    let an = mechplan::Analysis::new(mechplan::Scene::from_json(&v.to_string()).unwrap()).unwrap();
    let head = report::csv_head(&an);
    let quoted = r#","angle_2,""c""","omega_2,""c""","epsilon_2,""c""""#;
    assert!(head.contains(quoted), "{head}");
}

/// Show 1 of issue 16: 20 000 positions of the six-link mechanism, CSV to
/// a file, with the process's data segment limited to 250 MB; the rows
/// are those positions, and every 1000th row is the JSON result of a
/// short solve of the same positions, number for number.
#[cfg(target_os = "linux")]
#[test]
fn twenty_thousand_positions_stream_to_csv_in_bounded_memory() {
    let dir = temp_dir("long");
    let v = fixture("six_link_fig2_10");
    let n = 20_000;
    let angles: Vec<f64> = (0..n).map(|k| 10.0 + 0.018 * k as f64).collect();
    let mut long = v.clone();
    long["positions"] = json!({ "angles": angles });
    let scene = dir.join("long.json");
    std::fs::write(&scene, long.to_string()).unwrap();
    let out = dir.join("long.csv");
    let o = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "ulimit -d 250000; exec '{EXE}' solve '{}' --format csv -o '{}'",
            scene.display(),
            out.display()
        ))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let (head, rows) = parse_csv(&text);
    assert_eq!(rows.len(), n);
    // The same positions, every 1000th, solved on their own: the JSON
    // result `solve --format json` writes (built here from its f64s, as
    // serde_json's reading of a number need not round correctly).
    let picked: Vec<usize> = (0..n).step_by(1000).chain([n - 1]).collect();
    let short = json!({ "angles": picked.iter().map(|&k| angles[k]).collect::<Vec<_>>() });
    let (an, solved) = solve(scene_with(v.clone(), short));
    let doc = report::to_json(&an, &solved);
    let inputs = vec![("1".to_string(), true)];
    for (j, &k) in picked.iter().enumerate() {
        // Given angles: numbered from 1.
        assert_eq!(rows[k][0], (k + 1).to_string());
        for (col, cell) in head.iter().zip(&rows[k]).skip(1) {
            let want = json_value(&doc["positions"][j], &inputs, col);
            assert_eq!(cell, &want.to_string(), "position {} column {col}", k + 1);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
