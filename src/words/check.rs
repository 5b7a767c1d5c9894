//! The check's words: the report's phrases, the typical mistakes in one
//! sentence each and the construction's steps as the report quotes them,
//! in the language asked.

use super::catalogue::{CheckPhrases, catalogue};
use super::numbers::decimals;
use crate::kinematics::construction::{Mistake, Plan};
use crate::lang::Lang;

pub use super::catalogue::fill;

/// The check's phrases in `lang`.
pub fn phrases(lang: Lang) -> &'static CheckPhrases {
    &catalogue(lang).check
}

/// Step `k` (from 0) of `plan` as the report quotes it: the
/// construction's sentence in `lang` ([`super::construction::sentence`]),
/// its numbers with the language's decimal mark, as the report's own.
pub fn step(plan: &Plan, k: usize, lang: Lang) -> String {
    decimals(&super::construction::sentence(plan, k, lang), lang)
}

/// Mistake `m` in one sentence: made at one decision (`one`) or at every
/// one.
pub fn mistake(lang: Lang, m: Mistake, one: bool) -> &'static str {
    let w = &phrases(lang).mistakes;
    let pair = match m {
        Mistake::CoriolisReversed => &w.coriolis_reversed,
        Mistake::CoriolisForgotten => &w.coriolis_forgotten,
        Mistake::CoriolisFactorOne => &w.coriolis_factor_one,
        Mistake::NormalFromCentre => &w.normal_from_centre,
        Mistake::NormalForgotten => &w.normal_forgotten,
        Mistake::MirroredFigure => &w.mirrored_figure,
        Mistake::WrongPerpendicular => &w.wrong_perpendicular,
        Mistake::TangentialParallel => &w.tangential_parallel,
        Mistake::WrongLink => &w.wrong_link,
        Mistake::Epsilon1Forgotten => &w.epsilon1_forgotten,
        Mistake::Epsilon1Added => &w.epsilon1_added,
        Mistake::OmegaWrongLink => &w.omega_wrong_link,
        Mistake::OmegaWrongSense => &w.omega_wrong_sense,
        Mistake::Slip => &w.slip,
        Mistake::NeighbourLink => &w.neighbour_link,
        Mistake::SlideAcross => &w.slide_across,
        Mistake::PointAtNeighbour => &w.point_at_neighbour,
    };
    if one { &pair[0] } else { &pair[1] }
}

/// Mistake `m` made at the one decision that step `k` of the right
/// construction `plan` takes, in the scene's own letters (the lines, the
/// points and the figure of that step), where the mistake has such a
/// sentence and the step is of its kind; `None` otherwise.
pub fn mistake_here(lang: Lang, m: Mistake, plan: &Plan, k: usize) -> Option<String> {
    use crate::kinematics::construction::{Dir, Op};
    let w = &phrases(lang).lettered;
    let cw = super::construction::words(lang);
    let p = |i: usize| plan.points.get(i).map(|x| x.name()).unwrap_or_default();
    let text = match (m, &plan.steps.get(k)?.op) {
        (Mistake::WrongPerpendicular, Op::Intersect { lines, .. }) => fill(
            &w.wrong_perpendicular,
            &[
                ("a", &p(lines[0].through)),
                ("dir_a", &super::construction::dir(cw, &lines[0].dir)),
                ("b", &p(lines[1].through)),
                ("dir_b", &super::construction::dir(cw, &lines[1].dir)),
            ],
        ),
        (Mistake::WrongLink | Mistake::SlideAcross, Op::Intersect { lines, out, .. }) => {
            let guide = lines.iter().find(|l| matches!(l.dir, Dir::Guide(_)))?;
            let phrase = if m == Mistake::WrongLink {
                &w.wrong_link
            } else {
                &w.slide_across
            };
            fill(
                phrase,
                &[
                    ("out", &p(*out)),
                    ("at", &p(guide.through)),
                    ("dir", &super::construction::dir(cw, &guide.dir)),
                ],
            )
        }
        (
            Mistake::PointAtNeighbour,
            Op::Similar { out, figure, .. } | Op::Divide { out, figure, .. },
        ) => fill(
            &w.point_at_neighbour,
            &[("out", &p(*out)), ("fig", &figure.concat())],
        ),
        _ => return None,
    };
    Some(decimals(&text, lang))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;
    use std::collections::BTreeSet;

    /// The `check` section of a language's catalogue file, as JSON.
    fn section(lang: Lang) -> Value {
        let text = lang.catalogue_text();
        let mut v: Value = serde_json::from_str(text).expect("a valid catalogue");
        v["check"].take()
    }

    /// Every phrase of `v` by its path (`mistakes/slip/0`).
    fn phrases_of(v: &Value, path: &str, out: &mut Vec<(String, String)>) {
        match v {
            Value::String(s) => out.push((path.to_string(), s.clone())),
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    phrases_of(x, &format!("{path}/{i}"), out);
                }
            }
            Value::Object(o) => {
                for (k, x) in o {
                    phrases_of(x, &format!("{path}/{k}"), out);
                }
            }
            other => panic!("{path}: not a phrase: {other}"),
        }
    }

    /// A phrase's blanks, by name.
    fn blanks(phrase: &str) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        let mut rest = phrase;
        while let Some(open) = rest.find('{') {
            let close = open + rest[open..].find('}').expect("a closed blank");
            out.insert(rest[open + 1..close].to_string());
            rest = &rest[close + 1..];
        }
        out
    }

    /// Every phrase of the check's report in every language has the
    /// English phrase's blanks, no more and no fewer (a blank left out
    /// would drop a number or a sentence from the report, one added would
    /// panic when filled), and is translated (none is the English copy).
    #[test]
    fn every_phrase_has_the_english_blanks() {
        let mut english = Vec::new();
        phrases_of(&section(Lang::En), "", &mut english);
        assert!(english.len() > 60, "{} phrases", english.len());
        for lang in [Lang::Uk, Lang::Ru] {
            let mut own = Vec::new();
            phrases_of(&section(lang), "", &mut own);
            let paths = |v: &[(String, String)]| v.iter().map(|x| x.0.clone()).collect::<Vec<_>>();
            assert_eq!(paths(&own), paths(&english), "{}: the phrases", lang.code());
            for ((path, en), (_, theirs)) in english.iter().zip(&own) {
                assert_eq!(
                    blanks(theirs),
                    blanks(en),
                    "{}: check{path}: \"{theirs}\" against \"{en}\"",
                    lang.code()
                );
                assert_ne!(theirs, en, "{}: check{path} is not translated", lang.code());
            }
        }
    }

    /// Each language's phrases are read as its own.
    #[test]
    fn a_phrase_of_each_language_is_its_own() {
        assert!(phrases(Lang::Uk).grade_right.contains("ВІРНО"));
        assert!(phrases(Lang::Ru).grade_right.contains("ВЕРНО"));
        assert!(mistake(Lang::Ru, Mistake::OmegaWrongSense, true).contains("ω1"));
    }
}
