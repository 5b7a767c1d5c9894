//! The check's report in the language asked (docs/check.md, "The
//! report's language"): `check --lang uk|ru`, or the scene's `want.lang`,
//! writes the grade, the mistake, the items and the steps it quotes in
//! Ukrainian or Russian, its numbers with a decimal comma; `--format json`
//! keeps its keys, its judgements and its numbers machine-readable, only
//! its sentences follow the language. The same wrong answer throughout:
//! the six-link's velocity plan at position 0 turned through the pole
//! (the crank's velocity laid off against ω1, so that the report notes
//! that the points fit position 0 with ω1 reversed), its points taken
//! from `solve --format json`, as tests/check_group.rs builds it.

mod common;

use mechplan::{CheckRequest, Lang, Study};
use serde_json::{Value, json};
use std::path::Path;

const SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/fixtures/six_link_fig2_10.json"
);

fn path(p: &Path) -> String {
    p.display().to_string()
}

/// The velocity plan at position 0 (the first: the scene counts from 0, as
/// its sheets do) with a, b, c, d turned through the pole: the crank's
/// velocity reversed, a mistake named at step 3.
fn reversed() -> Value {
    let (code, out, err) = common::run(&["solve", SCENE, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let doc: Value = serde_json::from_str(&out).unwrap();
    let plan = &doc["positions"][0]["plans"]["velocity"];
    let mut points = serde_json::Map::new();
    for n in ["a", "b", "c", "d"] {
        let p = &plan["points"][n];
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        points.insert(n.into(), json!([-x, -y]));
    }
    assert_eq!(doc["positions"][0]["position"], 0);
    json!({ "plan": "velocity", "position": 0, "mu": plan["mu"], "points": points })
}

/// The scene with `want.lang` set to `lang` (`None`: as it is).
fn scene_text(lang: Option<&str>) -> String {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(SCENE).unwrap()).unwrap();
    if let Some(l) = lang {
        v["want"] = json!({ "lang": l });
    }
    v.to_string()
}

/// Numbers written with a decimal point ("0.01"): a digit, a point, a
/// digit.
fn decimal_points(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    (1..c.len().saturating_sub(1))
        .filter(|&i| c[i] == '.' && c[i - 1].is_ascii_digit() && c[i + 1].is_ascii_digit())
        .map(|i| {
            c[i.saturating_sub(4)..(i + 4).min(c.len())]
                .iter()
                .collect()
        })
        .collect()
}

/// What the report must say in each language: the grade line's start,
/// the mistake, the note under it (the points fit with ω1 reversed), the
/// quoted step's start, a word of the table, English words that must not
/// appear.
struct Words {
    lang: &'static str,
    grade: &'static str,
    mistake: &'static str,
    note: &'static str,
    step: &'static str,
    table: &'static [&'static str],
}

const UK: Words = Words {
    lang: "uk",
    grade: "Оцінка: НЕВІРНО на кроці 3.",
    mistake: "Швидкість кривошипа відкладено проти напрямку ω1.",
    note: "Примітка: ваші точки відповідають положенню 0 з кривошипом, що обертається в інший бік (ω1 навпаки)",
    step: "Від p_v відкладаємо p_va = ω1·l_O1A/μ_v = 1 / 0,004 = 250 мм",
    table: &[
        "Перевірка плану швидкостей, положення 0",
        "δ = 0,5000 мм",
        "Крок за кроком",
        "Помилки:",
        "1. Крок 3:",
        "точка a (від ваших попередніх точок)",
        "500,0",
        "НЕВІРНО (помилка 1)",
        "разом: вірних 3 з 4, невірних 1",
        "Друга думка",
    ],
};

const RU: Words = Words {
    lang: "ru",
    grade: "Оценка: НЕВЕРНО на шаге 3.",
    mistake: "Скорость кривошипа отложена против направления ω1.",
    note: "Примечание: ваши точки соответствуют положению 0 при кривошипе, вращающемся в другую сторону (ω1 наоборот)",
    step: "От p_v откладываем p_va = ω1·l_O1A/μ_v = 1 / 0,004 = 250 мм",
    table: &[
        "Проверка плана скоростей, положение 0",
        "δ = 0,5000 мм",
        "Шаг за шагом",
        "Ошибки:",
        "1. Шаг 3:",
        "точка a (от ваших предыдущих точек)",
        "500,0",
        "НЕВЕРНО (ошибка 1)",
        "итого: верных 3 из 4, неверных 1",
        "Второе мнение",
    ],
};

/// The text report `out` is the wrong answer's, in `w`'s language.
fn speaks(w: &Words, out: &str) {
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[1].starts_with(w.grade), "{}: {out}", w.lang);
    assert!(lines[1].contains(w.mistake), "{}: {out}", w.lang);
    assert!(lines[2].starts_with(w.note), "{}: {out}", w.lang);
    let quoted = lines.iter().filter(|l| l.contains(w.step)).count();
    // The mistake's step, and the wrong item's step.
    assert_eq!(quoted, 2, "{}: {out}", w.lang);
    for t in w.table {
        assert!(out.contains(t), "{}: no \"{t}\" in\n{out}", w.lang);
    }
    for english in [
        "Grade", "WRONG", "RIGHT", "Step", "step", "point a", "total", "lay off",
    ] {
        assert!(
            !out.contains(english),
            "{}: \"{english}\" in\n{out}",
            w.lang
        );
    }
    assert_eq!(
        decimal_points(out),
        Vec::<String>::new(),
        "{}: {out}",
        w.lang
    );
}

/// `check --lang uk` and `--lang ru`: the grade, the mistake, the quoted
/// steps and the tables in that language, numbers with a decimal comma,
/// exit status 1; `--lang en` is the English report.
#[test]
fn the_report_is_in_the_language_asked() {
    let dir = common::fresh("lang", "asked");
    let answer = dir.join("answer.json");
    std::fs::write(&answer, reversed().to_string()).unwrap();
    for w in [&UK, &RU] {
        let (code, out, err) = common::run(&["check", SCENE, &path(&answer), "--lang", w.lang]);
        assert_eq!(code, 1, "{}: {err}{out}", w.lang);
        speaks(w, &out);
    }
    let (code, out, _) = common::run(&["check", SCENE, &path(&answer), "--lang", "en"]);
    assert_eq!(code, 1);
    assert!(
        out.contains(
            "Grade: WRONG at step 3. The crank's velocity is laid off against the sense of ω1."
        ),
        "{out}"
    );
    assert!(out.contains("1 / 0.004 = 250 mm"), "{out}");
    let (code, _, err) = common::run(&["check", SCENE, &path(&answer), "--lang", "de"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("unknown language \"de\""), "{err}");
}

/// A scene whose `want.lang` is uk or ru: the same report without
/// `--lang`; `--lang` still decides over it.
#[test]
fn the_scene_language_is_the_default() {
    let dir = common::fresh("lang", "scene");
    let answer = dir.join("answer.json");
    std::fs::write(&answer, reversed().to_string()).unwrap();
    for w in [&UK, &RU] {
        let scene = dir.join(format!("scene-{}.json", w.lang));
        std::fs::write(&scene, scene_text(Some(w.lang))).unwrap();
        let (code, out, err) = common::run(&["check", &path(&scene), &path(&answer)]);
        assert_eq!(code, 1, "{}: {err}{out}", w.lang);
        speaks(w, &out);
        let (_, asked, _) = common::run(&["check", SCENE, &path(&answer), "--lang", w.lang]);
        assert_eq!(out, asked, "{}", w.lang);
        let (code, out, _) = common::run(&["check", &path(&scene), &path(&answer), "--lang", "en"]);
        assert_eq!(code, 1);
        assert!(out.contains("Grade: WRONG at step 3."), "{out}");
    }
}

/// `--format json` in Ukrainian: the keys, the grade and the judgements
/// in English, the numbers JSON numbers; the sentences (the mistake, the
/// quoted step, the item's name) in Ukrainian.
#[test]
fn json_stays_machine_readable() {
    let dir = common::fresh("lang", "json");
    let answer = dir.join("answer.json");
    std::fs::write(&answer, reversed().to_string()).unwrap();
    let (code, out, err) = common::run(&[
        "check",
        SCENE,
        &path(&answer),
        "--format",
        "json",
        "--lang",
        "uk",
    ]);
    assert_eq!(code, 1, "{err}");
    let r: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["grade"], "wrong");
    assert_eq!(r["plan"], "velocity");
    assert_eq!(r["mu"], json!(0.004));
    assert_eq!(r["delta"], json!(0.5));
    assert_eq!(r["wrong"], 1);
    assert_eq!(r["status"], 1);
    assert_eq!(r["items"][0]["judgement"], "wrong");
    assert_eq!(r["items"][0]["unit"], "mm");
    assert!(r["items"][0]["given"].is_f64());
    assert_eq!(
        r["items"][0]["what"],
        "точка a (від ваших попередніх точок)"
    );
    assert_eq!(r["steps"][0]["judgement"], "wrong");
    assert_eq!(r["steps"][1]["judgement"], "right");
    let m = &r["mistakes"][0];
    assert_eq!(m["step"], 3);
    assert_eq!(m["recognised"], true);
    assert_eq!(m["explanation"]["kind"], "OmegaWrongSense");
    assert_eq!(m["mistake"], UK.mistake);
    assert!(m["step_text"].as_str().unwrap().starts_with(UK.step), "{m}");
    assert_eq!(r["second_opinion"]["agrees"], true);
}

/// A group checked with `--lang ru`: each report in Russian, the
/// group's grades machine words.
#[test]
fn a_group_is_checked_in_the_language_asked() {
    let dir = common::fresh("lang", "group");
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    std::fs::write(answers.join("reversed.json"), reversed().to_string()).unwrap();
    let out_dir = dir.join("out");
    let (code, out, err) = common::run(&[
        "check",
        SCENE,
        &path(&answers),
        "-o",
        &path(&out_dir),
        "--format",
        "json",
        "--lang",
        "ru",
    ]);
    assert_eq!(code, 1, "{err}");
    let all: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(all[0]["grade"], "wrong");
    assert_eq!(all[0]["report"]["grade"], "wrong");
    assert_eq!(all[0]["report"]["mistakes"][0]["mistake"], RU.mistake);
    let book = std::fs::read_to_string(out_dir.join("gradebook.csv")).unwrap();
    assert!(book.contains(RU.mistake), "{book}");
}

/// The library: a [`CheckRequest`]'s language, else the scene's.
#[test]
fn the_library_takes_the_language_too() {
    let answer = reversed().to_string();
    let study = Study::from_json(&scene_text(Some("uk"))).unwrap();
    let text = study
        .check_answer(&answer, "answer.json", false)
        .unwrap()
        .to_text();
    speaks(&UK, &text);
    let req = CheckRequest {
        lang: Some(Lang::Ru),
        ..CheckRequest::default()
    };
    let checked = study
        .solve()
        .unwrap()
        .check_answer(&answer, "answer.json", false, &req)
        .unwrap();
    assert_eq!(checked.status(), 1);
    speaks(&RU, &checked.to_text());
    let overlay = checked.overlay().unwrap();
    assert!(
        overlay.contains("Проверка плана скоростей, положение 0 — верных 3 из 4"),
        "{overlay}"
    );
    let english = Study::from_json(&scene_text(None)).unwrap();
    let text = english
        .check_answer(&answer, "answer.json", false)
        .unwrap()
        .to_text();
    assert!(text.contains("Grade: WRONG at step 3."), "{text}");
}

/// A force plan's report follows the language too: its heading, its
/// verdicts and its numbers (decimal commas) in Ukrainian and Russian.
#[test]
fn a_force_plans_report_in_every_language() {
    let dir = common::fresh("lang", "force");
    let scene = format!(
        "{}/fixtures/dynamics/six_link_fig2_10.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let (code, out, _) = common::run(&["solve", &scene, "--format", "json"]);
    assert_eq!(code, 0);
    let doc: Value = serde_json::from_str(&out).unwrap();
    let mut values = serde_json::Map::new();
    let norm = |v: &Value| v[0].as_f64().unwrap().hypot(v[1].as_f64().unwrap());
    for pair in doc["positions"][1]["dynamics"]["pairs"].as_array().unwrap() {
        if !pair["R"].is_array() {
            continue;
        }
        if pair["point"] == "C" {
            // R_34 half as long again: wrong.
            values.insert("R_34".into(), json!(1.5 * norm(&pair["R"])));
        } else if pair["point"] == "D" {
            values.insert("R_54".into(), json!(norm(&pair["R"])));
        }
    }
    let answer =
        json!({ "plan": "force", "position": 1, "links": ["4", "5"], "mu": 2.0, "values": values });
    let file = dir.join("force.json");
    std::fs::write(&file, answer.to_string()).unwrap();
    for (lang, heading, wrong) in [
        ("en", "Force plan of links", "WRONG"),
        ("uk", "План сил ланок", "НЕВІРНО"),
        ("ru", "План сил звеньев", "НЕВЕРНО"),
    ] {
        let (code, out, err) = common::run(&["check", &scene, &path(&file), "--lang", lang]);
        assert_eq!(code, 1, "{out}{err}");
        assert!(
            out.contains(heading) && out.contains(wrong),
            "{lang}: {out}"
        );
        if lang != "en" {
            let first = out.lines().nth(1).unwrap();
            assert!(
                first.contains(',') && !first.contains('.') && first.contains(" Н"),
                "{lang}: {out}"
            );
        }
    }
}
