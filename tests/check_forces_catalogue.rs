//! `check` of force plans graded on answers built independently of the
//! engine (docs/check.md, "Force plans", "The catalogue of force-plan
//! answers"): tests/forces_catalogue/ holds, for every one-input dynamics
//! fixture (the class III class3_004's plans too), honest answers (vectors,
//! segments only, values only, with pencil noise), answers with one
//! seeded mistake each and bad answers, all computed by
//! tests/reference/forceref.py at 60 digits (tests/forces_catalogue/make.py
//! writes them; `labels.json` says what each is). Asserted, never to
//! regress: no honest answer rejected, no mistake judged right, every bad
//! answer refused naming its field. The stricter targets (at most 3 % of
//! the honest answers undecided, at least 90 % of the mistakes named, none
//! named wrongly) are `force_catalogue_targets`.

use mechplan::check::forces::{ForceMistake, check, from_json};
use mechplan::scene::Scene;
use mechplan::{Analysis, Solved};
use serde_json::Value;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// At most this share of the honest answers may be undecided (status 4).
const TARGET_MAX_HONEST_UNDECIDED: f64 = 0.03;
/// At least this share of the mistaken answers must be named rightly.
const TARGET_MIN_MISTAKES_NAMED: f64 = 0.90;

fn root() -> String {
    env!("CARGO_MANIFEST_DIR").to_string()
}

/// What check made of one answer.
#[derive(Debug)]
enum Outcome {
    /// Its status (0, 1, 4), diagnosis and the report's text.
    Judged(u8, Option<String>, String),
    /// Refused: the error's text.
    Refused(String),
}

struct Graded {
    file: String,
    scene: String,
    expected: String,
    pointer: String,
    outcome: Outcome,
}

fn load(scene: &str) -> (Analysis, Vec<Solved>) {
    let text = std::fs::read_to_string(format!("{}/{scene}", root())).unwrap();
    let an = Analysis::new(Scene::from_json(&text).unwrap()).unwrap();
    let s = an.run().unwrap();
    (an, s)
}

fn grade_all() -> Vec<Graded> {
    let dir = format!("{}/tests/forces_catalogue", root());
    let labels: Value =
        serde_json::from_str(&std::fs::read_to_string(format!("{dir}/labels.json")).unwrap())
            .unwrap();
    let mut scenes: BTreeMap<String, (Analysis, Vec<Solved>)> = BTreeMap::new();
    let mut out = Vec::new();
    for a in labels["answers"].as_array().unwrap() {
        let s = |k: &str| a[k].as_str().unwrap_or_default().to_string();
        let (file, scene) = (s("file"), s("scene"));
        let (an, solved) = scenes.entry(scene.clone()).or_insert_with(|| load(&scene));
        let text = std::fs::read_to_string(format!("{dir}/{file}")).unwrap();
        let outcome = match from_json(&text).and_then(|ans| check(an, solved, &ans)) {
            Ok(r) => Outcome::Judged(
                r.status(),
                r.mistake.map(label_of),
                mechplan::presentation::verdict::force_to_text(&r),
            ),
            Err(e) => Outcome::Refused(e.to_string()),
        };
        out.push(Graded {
            file,
            scene,
            expected: s("expected"),
            pointer: s("pointer"),
            outcome,
        });
    }
    assert!(
        out.len() > 300,
        "the catalogue is there: {} answers",
        out.len()
    );
    out
}

/// The catalogue's label of a mistake `check` names (labels.json).
fn label_of(m: ForceMistake) -> String {
    match m {
        ForceMistake::NotReversed => "not_reversed",
        ForceMistake::WeightsLeftOut => "weights_left_out",
        // Segments twice what the stated μ_F gives: drawn at half of it.
        ForceMistake::Scale { drawn } if drawn < 1.0 => "scale_twice",
        ForceMistake::Scale { .. } => "scale_half",
        ForceMistake::TangentialSign => "tau_wrong_sign",
        ForceMistake::TangentialAlong => "tau_along_link",
        ForceMistake::NeighbourSign => "neighbour_wrong_sign",
        ForceMistake::BalancingArm => "mb_arms_wrong_point",
        ForceMistake::ActionForReaction => "reaction_as_action",
        ForceMistake::BalancingSign => "mb_wrong_sign",
    }
    .to_string()
}

#[derive(Default, Clone, Copy)]
struct Row {
    answers: usize,
    right: usize,
    wrong: usize,
    undecided: usize,
    refused: usize,
    named: usize,
    named_wrongly: usize,
    unnamed: usize,
}

impl Row {
    fn add(&mut self, g: &Graded) {
        self.answers += 1;
        match &g.outcome {
            Outcome::Refused(_) => self.refused += 1,
            Outcome::Judged(st, d, _) => {
                match st {
                    0 => self.right += 1,
                    1 => self.wrong += 1,
                    _ => self.undecided += 1,
                }
                if g.expected != "honest" && g.expected != "bad" && *st == 1 {
                    match d {
                        Some(d) if *d == g.expected => self.named += 1,
                        Some(_) => self.named_wrongly += 1,
                        None => self.unnamed += 1,
                    }
                }
            }
        }
    }
}

struct Tally {
    by_kind: BTreeMap<String, Row>,
    by_scene: BTreeMap<String, BTreeMap<&'static str, Row>>,
    misses: Vec<String>,
    honest_undecided: Vec<String>,
    markdown: String,
}

fn tally(all: &[Graded]) -> Tally {
    let mut by_kind: BTreeMap<String, Row> = BTreeMap::new();
    let mut by_scene: BTreeMap<String, BTreeMap<&'static str, Row>> = BTreeMap::new();
    let mut misses = Vec::new();
    let mut honest_undecided = Vec::new();
    for g in all {
        by_kind.entry(g.expected.clone()).or_default().add(g);
        let class = match g.expected.as_str() {
            "honest" => "honest",
            "bad" => "bad",
            _ => "mistake",
        };
        let scene = g.scene.rsplit('/').next().unwrap_or_default().to_string();
        by_scene
            .entry(scene)
            .or_default()
            .entry(class)
            .or_default()
            .add(g);
        match (class, &g.outcome) {
            ("honest", Outcome::Judged(1, _, t)) => {
                misses.push(format!("honest answer rejected: {}\n{t}", g.file))
            }
            ("honest", Outcome::Judged(4, _, t)) => {
                let why: Vec<&str> = t
                    .lines()
                    .filter(|l| l.contains("cannot be judged") || l.contains("too small"))
                    .collect();
                honest_undecided.push(format!("{}: {}", g.file, why.join(" | ")));
            }
            ("honest" | "mistake", Outcome::Refused(e)) => {
                misses.push(format!("{class} answer refused: {}: {e}", g.file));
            }
            ("mistake", Outcome::Judged(0, _, t)) => {
                misses.push(format!("mistake judged right: {}\n{t}", g.file));
            }
            ("mistake", Outcome::Judged(1, Some(d), _)) if *d != g.expected => {
                misses.push(format!("{} named wrongly \"{d}\": {}", g.expected, g.file));
            }
            ("bad", Outcome::Refused(e)) if !e.contains(&g.pointer) => {
                misses.push(format!(
                    "bad answer refused without naming {}: {}: {e}",
                    g.pointer, g.file
                ));
            }
            ("bad", Outcome::Judged(..)) => {
                misses.push(format!("bad answer judged: {}", g.file));
            }
            _ => {}
        }
    }
    let mut md = String::new();
    let head = "| | answers | right (0) | wrong (1) | undecided (4) | refused | named | named wrongly | unnamed |\n|---|---|---|---|---|---|---|---|---|\n";
    let line = |md: &mut String, what: &str, r: &Row| {
        let _ = writeln!(
            md,
            "| {what} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.answers,
            r.right,
            r.wrong,
            r.undecided,
            r.refused,
            r.named,
            r.named_wrongly,
            r.unnamed
        );
    };
    md += "### By answer kind\n\n";
    md += head;
    for (k, r) in &by_kind {
        line(&mut md, k, r);
    }
    md += "\n### By fixture\n\n";
    md += head;
    for (s, rows) in &by_scene {
        for (class, r) in rows {
            line(&mut md, &format!("{s}: {class}"), r);
        }
    }
    Tally {
        by_kind,
        by_scene,
        misses,
        honest_undecided,
        markdown: md,
    }
}

fn report(t: &Tally) {
    println!("{}", t.markdown);
    eprintln!("{}", t.markdown);
    eprintln!("honest answers undecided ({}):", t.honest_undecided.len());
    for u in &t.honest_undecided {
        eprintln!("  {u}");
    }
    eprintln!("misses ({}):", t.misses.len());
    for m in &t.misses {
        eprintln!("  {m}");
    }
}

#[test]
fn force_catalogue_never_regresses() {
    let all = grade_all();
    let t = tally(&all);
    report(&t);
    let honest = t.by_kind["honest"];
    assert_eq!(honest.wrong, 0, "no honest answer rejected");
    assert_eq!(honest.refused, 0, "no honest answer refused");
    let mut bad = 0;
    for g in &all {
        match (g.expected.as_str(), &g.outcome) {
            ("honest", _) => {}
            ("bad", Outcome::Refused(e)) => {
                assert!(e.contains(&g.pointer), "{}: {e}", g.file);
                bad += 1;
            }
            ("bad", o) => panic!("{}: a bad answer judged: {o:?}", g.file),
            (kind, Outcome::Judged(st, _, text)) => {
                assert_ne!(*st, 0, "{kind} judged right: {}\n{text}", g.file);
            }
            (kind, Outcome::Refused(e)) => panic!("{kind} refused: {}: {e}", g.file),
        }
    }
    assert!(bad >= 3 * t.by_scene.len(), "every fixture's bad answers");
}

/// Issue 42's targets: at most 3 % of the honest answers undecided, at
/// least 90 % of the mistakes named (and none named wrongly).
#[test]
fn force_catalogue_targets() {
    let all = grade_all();
    let t = tally(&all);
    report(&t);
    let honest = t.by_kind["honest"];
    let undecided = honest.undecided as f64 / honest.answers as f64;
    assert!(
        undecided <= TARGET_MAX_HONEST_UNDECIDED,
        "honest answers undecided: {:.1} % (target ≤ {:.0} %)",
        100.0 * undecided,
        100.0 * TARGET_MAX_HONEST_UNDECIDED
    );
    let (named, mistakes) = t
        .by_kind
        .iter()
        .filter(|(k, _)| *k != "honest" && *k != "bad")
        .fold((0, 0), |(n, m), (_, r)| (n + r.named, m + r.answers));
    let wrongly: usize = t.by_kind.values().map(|r| r.named_wrongly).sum();
    assert_eq!(wrongly, 0, "mistakes named wrongly");
    let share = named as f64 / mistakes as f64;
    assert!(
        share >= TARGET_MIN_MISTAKES_NAMED,
        "mistakes named: {:.1} % (target ≥ {:.0} %)",
        100.0 * share,
        100.0 * TARGET_MIN_MISTAKES_NAMED
    );
}
