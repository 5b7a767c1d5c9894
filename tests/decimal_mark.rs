//! Numbers in the language's decimal mark: in uk and ru outputs a comma,
//! never a point, in every generated sentence — `solve --steps` (the
//! plans' steps, their measured values, the force plans and the lever of
//! a dynamics scene) and the handout's step sentences. The scene's own
//! title (which may say "Fig. 2.10") is the user's text and left as
//! written.

use std::path::Path;
use std::process::Command;

/// A number written with a decimal point: a digit, '.', a digit.
fn decimal_points(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    for i in 1..c.len().saturating_sub(1) {
        if c[i] == '.' && c[i - 1].is_ascii_digit() && c[i + 1].is_ascii_digit() {
            let from = i.saturating_sub(30);
            let to = (i + 30).min(c.len());
            out.push(c[from..to].iter().collect());
        }
    }
    out
}

fn run(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn uk_and_ru_steps_write_decimal_commas() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for lang in ["uk", "ru"] {
        for scene in [
            "fixtures/four_bar.json",
            "fixtures/six_link_fig2_10.json",
            "fixtures/dynamics/six_link_fig2_10.json",
        ] {
            let path = root.join(scene);
            let text = run(&["solve", path.to_str().unwrap(), "--steps", "--lang", lang]);
            let title: String =
                serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&path).unwrap())
                    .unwrap()["title"]
                    .as_str()
                    .unwrap_or("")
                    .to_string();
            let body: String = text
                .lines()
                .filter(|l| title.is_empty() || *l != title)
                .collect::<Vec<_>>()
                .join("\n");
            assert!(body.contains(','), "{scene} {lang}: no numbers?");
            let bad = decimal_points(&body);
            assert!(bad.is_empty(), "{scene} --lang {lang}: {bad:#?}");
        }
        // The English steps keep their points.
        let en = run(&[
            "solve",
            root.join("fixtures/four_bar.json").to_str().unwrap(),
            "--steps",
        ]);
        assert!(!decimal_points(&en).is_empty());
    }
}

#[test]
fn uk_and_ru_handout_sentences_write_decimal_commas() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for lang in ["uk", "ru"] {
        let dir =
            std::env::temp_dir().join(format!("mechplan-decimal-{lang}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        run(&[
            "draw",
            root.join("fixtures/six_link_fig2_10.json")
                .to_str()
                .unwrap(),
            "--html",
            "--lang",
            lang,
            "-o",
            dir.to_str().unwrap(),
        ]);
        let html = std::fs::read_to_string(dir.join("handout.html")).unwrap();
        let mut sentences = 0;
        for (i, _) in html.match_indices("<li data-step=") {
            let li = &html[i..];
            let li = &li[li.find('>').unwrap() + 1..li.find("</li>").unwrap()];
            sentences += 1;
            let bad = decimal_points(li);
            assert!(bad.is_empty(), "handout --lang {lang}: {bad:#?}");
        }
        assert!(sentences > 50, "{sentences}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// A rate read off a plan as zero is written without a sense of rotation
/// (the four-bar's rocker stands still in position 1).
#[test]
fn a_zero_rate_has_no_sense() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = root.join("fixtures/four_bar.json");
    for (lang, unit) in [("en", "rad/s"), ("uk", "рад/с"), ("ru", "рад/с")] {
        let text = run(&["solve", scene.to_str().unwrap(), "--steps", "--lang", lang]);
        let zero = format!("= 0 {unit}");
        assert!(text.contains(&format!("{zero}.")), "{lang}: no zero rate");
        assert!(
            !text.contains(&format!("{zero},")),
            "{lang}: a zero rate with a sense"
        );
    }
}

/// The force sheets name a group as the course does, by its class and
/// kind (вид), in every language.
#[test]
fn force_panels_name_groups_by_class_and_kind() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (lang, want) in [
        ("uk", "Група II класу 2-го виду (4, 5), RRP"),
        ("ru", "Группа II класса 2-го вида (4, 5), RRP"),
        ("en", "Group (4, 5), class II, kind 2 (RRP)"),
    ] {
        let dir =
            std::env::temp_dir().join(format!("mechplan-groups-{lang}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        run(&[
            "draw",
            root.join("fixtures/dynamics/six_link_fig2_10.json")
                .to_str()
                .unwrap(),
            "--lang",
            lang,
            "-o",
            dir.to_str().unwrap(),
        ]);
        let svg = std::fs::read_to_string(dir.join("forces_1.svg")).unwrap();
        assert!(svg.contains(want), "{lang}: no \"{want}\"");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// `solve --lang uk` without `--steps` writes the table in Ukrainian,
/// its numbers with the decimal comma, and no note on stderr (the table
/// was English once, and said so); tests/languages.rs has the rest.
#[test]
fn the_table_follows_lang_without_a_note() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene = root.join("fixtures/four_bar.json");
    for steps in [false, true] {
        let mut args = vec!["solve", scene.to_str().unwrap(), "--lang", "uk"];
        if steps {
            args.push("--steps");
        }
        let out = Command::new(env!("CARGO_BIN_EXE_mechplan"))
            .args(&args)
            .output()
            .unwrap();
        assert!(out.status.success());
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        if !steps {
            assert!(text.contains("положення 1: φ1 = "), "{text}");
            assert!(text.contains("рад/с"), "{text}");
        }
        let body = text.split_once('\n').map_or("", |x| x.1);
        assert!(
            decimal_points(body).is_empty(),
            "{:?}",
            decimal_points(body)
        );
    }
}
