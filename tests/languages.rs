//! The terminal's tables in the scene's language: with `want.lang` "uk"
//! or "ru" (or `solve --lang`), `solve`'s table, `mechplan diagram` and
//! `mechplan centres` write their headings, units and words from the
//! language's catalogue and every number with its decimal comma; English
//! stays as it was (tests/golden), and the machine-readable outputs (JSON,
//! CSV) keep their decimal points whatever the language.

use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

const FIXTURES: [&str; 2] = ["six_link_fig2_10", "offset_slider_crank"];

/// The binary on `args`: its standard output, the command having
/// succeeded with nothing on standard error.
fn run(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: {err}");
    String::from_utf8(out.stdout).unwrap()
}

/// Numbers written with a decimal point ("0.01"): a digit, a point, a
/// digit; each with the text around it.
fn decimal_points(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    (1..c.len().saturating_sub(1))
        .filter(|&i| c[i] == '.' && c[i - 1].is_ascii_digit() && c[i + 1].is_ascii_digit())
        .map(|i| {
            c[i.saturating_sub(12)..(i + 12).min(c.len())]
                .iter()
                .collect()
        })
        .collect()
}

/// How many numbers are written with a decimal comma and three digits
/// after it or more ("0,000000"; not a pair's "(0,1)").
fn decimal_commas(text: &str) -> usize {
    let c: Vec<char> = text.chars().collect();
    (1..c.len().saturating_sub(3))
        .filter(|&i| {
            c[i] == ','
                && c[i - 1].is_ascii_digit()
                && c[i + 1..i + 4].iter().all(char::is_ascii_digit)
        })
        .count()
}

/// The fixture `name` with `want.lang` set to `lang` (its other wants
/// kept) and a title in that language (a fixture's own says "Fig. 2.10":
/// the user's text, printed as written), in a folder of its own.
fn scene(name: &str, lang: &str, title: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("fixtures").join(format!("{name}.json")));
    let mut v: Value = serde_json::from_str(&text.unwrap()).unwrap();
    if !v["want"].is_object() {
        v["want"] = json!({});
    }
    v["want"]["lang"] = json!(lang);
    v["title"] = json!(title);
    let dir = std::env::temp_dir().join(format!("mechplan-languages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}_{lang}.json"));
    std::fs::write(&path, v.to_string()).unwrap();
    path
}

/// What each command's output must say in a language, and what English
/// it must not.
struct Words {
    lang: &'static str,
    title: &'static str,
    solve: &'static [&'static str],
    diagram: &'static [&'static str],
    centres: &'static [&'static str],
}

const UK: Words = Words {
    lang: "uk",
    title: "Механізм",
    solve: &[
        "будова: W = 1",
        "положення 1: φ1 = ",
        "  точка        x [м]       y [м]    |v| [м/с]",
        "  ланка      кут [°]    ω [рад/с]",
        "рад/с²",
        "перевірка: найбільша відносна різниця",
        "мкс",
        "рух ",
    ],
    diagram: &[
        "кінематичні діаграми ланки ",
        "масштаби: μ_s = ",
        "  вузол  φ1 [°]   s            s′ точно",
        "  інтервал   s′ точно в середині",
        "найбільша похибка",
    ],
    centres: &[
        "положення 1: φ = ",
        "  центр    місце",
        "як знайдено",
        "обертальна пара",
        "Кеннеді: прямі через ланки",
        "поступальна пара: ⊥ напрямній",
    ],
};

const RU: Words = Words {
    lang: "ru",
    title: "Механизм",
    solve: &[
        "строение: W = 1",
        "положение 1: φ1 = ",
        "  точка        x [м]       y [м]    |v| [м/с]",
        "  звено     угол [°]    ω [рад/с]",
        "рад/с²",
        "проверка: наибольшая относительная разность",
        "мкс",
        "движение ",
    ],
    diagram: &[
        "кинематические диаграммы звена ",
        "масштабы: μ_s = ",
        "  узел   φ1 [°]   s            s′ точно",
        "  интервал   s′ точно в середине",
        "наибольшая погрешность",
    ],
    centres: &[
        "положение 1: φ = ",
        "  центр    место",
        "как найден",
        "вращательная пара",
        "Кеннеди: прямые через звенья",
        "поступательная пара: ⊥ направляющей",
    ],
};

/// English words none of the outputs may keep in another language.
const ENGLISH: &[&str] = &[
    "structure:",
    "position ",
    "point ",
    "link ",
    "angle [°]",
    "[m]",
    "m/s",
    "rad/s",
    " ccw",
    " cw",
    "slide of",
    "cross-check",
    "route",
    "µs",
    "kinematic diagrams",
    "scales:",
    "node",
    "exact",
    "central",
    "chords",
    "interval",
    "largest error",
    "centre ",
    "found by",
    "revolute pair",
    "prismatic pair",
    "Kennedy",
    "at infinity",
];

/// An output in language `w`: its decimal commas, no decimal point, its
/// words and none of the English.
fn speaks(what: &str, out: &str, w: &Words, words: &[&str]) {
    let points = decimal_points(out);
    assert!(points.is_empty(), "{}: {what}: {points:?}\n{out}", w.lang);
    assert!(
        decimal_commas(out) > 10,
        "{}: {what}: few decimal commas\n{out}",
        w.lang
    );
    for word in words {
        assert!(
            out.contains(word),
            "{}: {what}: no \"{word}\"\n{out}",
            w.lang
        );
    }
    for word in ENGLISH {
        assert!(
            !out.contains(word),
            "{}: {what}: English \"{word}\"\n{out}",
            w.lang
        );
    }
}

#[test]
fn the_terminal_tables_speak_the_scenes_language() {
    for w in [&UK, &RU] {
        for name in FIXTURES {
            let path = scene(name, w.lang, w.title);
            let p = path.to_str().unwrap();
            let table = run(&["solve", p]);
            assert!(table.starts_with(&format!("{}\n", w.title)), "{table}");
            speaks(&format!("{name}: solve"), &table, w, w.solve);
            speaks(
                &format!("{name}: diagram"),
                &run(&["diagram", p]),
                w,
                w.diagram,
            );
            speaks(
                &format!("{name}: centres"),
                &run(&["centres", p]),
                w,
                w.centres,
            );
        }
    }
}

/// `solve --lang` over the scene's language: Russian from a Ukrainian
/// scene, English (with its decimal points) too.
#[test]
fn solve_lang_overrides_the_scenes() {
    let path = scene("six_link_fig2_10", "uk", UK.title);
    let p = path.to_str().unwrap();
    speaks(
        "--lang ru",
        &run(&["solve", p, "--lang", "ru"]),
        &RU,
        RU.solve,
    );
    let english = run(&["solve", p, "--lang", "en"]);
    assert!(english.contains("\nstructure: W = 1"), "{english}");
    assert!(english.contains("\nposition 1: φ1 = "), "{english}");
    assert!(
        english.contains("  link     angle [°]    ω [rad/s]"),
        "{english}"
    );
    assert!(!decimal_points(&english).is_empty());
    assert_eq!(decimal_commas(&english), 0, "{english}");
}

/// The machine-readable outputs do not follow the language: the same
/// CSV to the byte, JSON with decimal points.
#[test]
fn machine_readable_outputs_keep_their_points() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let english = root.join("fixtures/offset_slider_crank.json");
    let csv = |p: &Path| run(&["solve", p.to_str().unwrap(), "--format", "csv"]);
    for w in [&UK, &RU] {
        let path = scene("offset_slider_crank", w.lang, w.title);
        assert_eq!(csv(&path), csv(&english), "{}", w.lang);
        let p = path.to_str().unwrap();
        let json = run(&["solve", p, "--format", "json", "--lang", w.lang]);
        let doc: Value = serde_json::from_str(&json).unwrap();
        assert!(doc["positions"][0]["crosscheck"]["worst"].is_string());
        assert_eq!(decimal_commas(&json), 0);
        assert!(!decimal_points(&json).is_empty());
        let centres = run(&["centres", p, "--format", "json"]);
        let doc: Value = serde_json::from_str(&centres).unwrap();
        assert_eq!(
            doc["positions"][0]["centres"]["P12"]["how"],
            "revolute pair A"
        );
    }
}

/// A title given in several languages (`"title": { "en": …, "uk": … }`)
/// is printed in the output's language, the English one (else the first
/// of uk, ru) where the language has none and in the result file; a
/// language code the scene does not know is refused by its pointer.
#[test]
fn titles_in_the_outputs_language() {
    let path = scene("six_link_fig2_10", "uk", "x");
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    v["title"] =
        json!({ "en": "Six-link lever mechanism", "uk": "Шестиланковий важільний механізм" });
    let path = path.with_file_name("six_link_titles.json");
    std::fs::write(&path, v.to_string()).unwrap();
    let p = path.to_str().unwrap();
    let uk = run(&["solve", p]);
    assert!(uk.starts_with("Шестиланковий важільний механізм\n"), "{uk}");
    let steps = run(&["solve", p, "--steps"]);
    assert!(
        steps.starts_with("Шестиланковий важільний механізм\n"),
        "{steps}"
    );
    let en = run(&["solve", p, "--lang", "en"]);
    assert!(en.starts_with("Six-link lever mechanism\n"), "{en}");
    // No Russian text: the English one.
    let ru = run(&["solve", p, "--lang", "ru"]);
    assert!(ru.starts_with("Six-link lever mechanism\n"), "{ru}");
    let json: Value = serde_json::from_str(&run(&["solve", p, "--format", "json"])).unwrap();
    assert_eq!(json["title"], "Six-link lever mechanism");

    for (title, pointer) in [
        (json!({ "de": "Sechsgliedriges Getriebe" }), "/title/de"),
        (json!({}), "/title"),
        (json!({ "uk": 5 }), "/title/uk"),
    ] {
        v["title"] = title;
        std::fs::write(&path, v.to_string()).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(["solve", p])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(pointer), "{err}");
    }
}
