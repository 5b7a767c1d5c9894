//! The catalogues of phrases, one file per language
//! (`src/words/en.json`, `uk.json`, `ru.json`, compiled in), and the one
//! way their named blanks are filled ([`fill`]).

use crate::lang::Lang;
use std::sync::OnceLock;

/// A phrase with its blanks filled: each `{name}` by the value named so
/// in `args` (one pass: a value is never filled again).
pub(crate) fn fill(phrase: &str, args: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(phrase.len() + 16 * args.len());
    let mut rest = phrase;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let close = open + rest[open..].find('}').expect("a closed blank");
        let name = &rest[open + 1..close];
        let value = args
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("no value for the blank {{{name}}}"));
        out.push_str(value.1);
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    out
}

/// Every phrase of one language, read from its catalogue file
/// (`src/words/en.json`, `uk.json`, `ru.json`, compiled in): a new
/// language is one more file and its [`Lang`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Catalogue {
    /// The language's code, as the file's name.
    pub language: String,
    /// The construction's steps.
    pub construction: ConstructionPhrases,
    /// The force plans' steps.
    pub force_plans: ForcePlanPhrases,
}

/// The catalogue of `lang`, read once.
pub fn catalogue(lang: Lang) -> &'static Catalogue {
    static ALL: OnceLock<[Catalogue; 3]> = OnceLock::new();
    let all = ALL.get_or_init(|| {
        [
            include_str!("en.json"),
            include_str!("uk.json"),
            include_str!("ru.json"),
        ]
        .map(|text| serde_json::from_str(text).expect("the words' catalogues are valid (tested)"))
    });
    let k = Lang::ALL.iter().position(|&l| l == lang).expect("every language has a catalogue");
    &all[k]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each catalogue file reads whole (every phrase there, none unknown)
    /// and says its own language.
    #[test]
    fn every_language_has_its_catalogue() {
        for lang in Lang::ALL {
            assert_eq!(catalogue(lang).language, lang.code());
        }
    }
}

/// The phrases of one language. Blanks in braces are filled by [`fill`].
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConstructionPhrases {
    /// Units of the velocity and the acceleration plan: values, rates.
    pub(super) unit: [String; 2],
    pub(super) rate_unit: [String; 2],
    /// Senses of a rate: positive, negative, zero.
    pub(super) sense: [String; 3],
    /// Directions: `{p}`, `{q}`; `{link}`; `{v}`, `{w}`; `{seg}`, `{w}`.
    pub(super) toward: String,
    pub(super) guide: String,
    pub(super) turned: String,
    pub(super) perp_sense: String,
    /// Steps.
    pub(super) pole: String,
    pub(super) lay_off: String,
    pub(super) intersect: String,
    pub(super) similar: String,
    pub(super) divide: String,
    pub(super) coincide: String,
    /// Why a point coincides: at the pole; `{link}` translates.
    pub(super) fixed: String,
    pub(super) translates: String,
    pub(super) measure: String,
    /// How a relative segment turns its link.
    pub(super) turns: String,
    pub(super) same: String,
    pub(super) equations: String,
}

/// The phrases of one language.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForcePlanPhrases {
    /// The steps' heading and the position's word.
    pub title: String,
    /// "position".
    pub position: String,
    /// "link", "links" (one, several).
    pub(super) links: [String; 2],
    /// Units: N, mm, N·m, N/mm.
    pub(super) newton: String,
    pub(super) mm: String,
    pub(super) newton_metre: String,
    pub(super) per_mm: String,
    /// `{formula}`, `{links}`.
    pub(super) group: String,
    /// `{ids}`.
    pub(super) input_link: String,
    /// `{at}`, `{what}`, `{f}`, `{value}`, `{n}`.
    pub(super) moment: String,
    /// `{what}`, `{f}`, `{value}`, `{n}`.
    pub(super) projection: String,
    /// `{from}`, `{f}`, `{val}`, `{n}`, `{len}`, `{mm}`, `{dir}`, `{to}`.
    pub(super) lay_off: String,
    /// `{through}`, `{f}`, `{dir}`.
    pub(super) line: String,
    /// `{out}`, `{deg}`.
    pub(super) intersect: String,
    /// `{a}`, `{b}`, `{l}`, `{mm}`, `{f}`, `{mu}`, `{val}`, `{bound}`, `{n}`, `{dir}`.
    pub(super) measure: String,
    /// `{what}`, `{value}`, `{nm}`, `{f}`, `{p}`: the couple of a guide
    /// with its force placed, and alone.
    pub(super) couple_at: String,
    pub(super) couple_alone: String,
    /// `{id}`, `{kind}`, `{b}`, `{value}`, `{unit}`, `{sense}`.
    pub(super) balancing: String,
    /// The balancing moment and force, as `{kind}` says them.
    pub(super) kind: [String; 2],
    /// A moment's senses: counter-clockwise, clockwise.
    pub(super) sense: [String; 2],
    /// The subscript of M_b, F_b.
    pub(super) balancing_sub: String,
    /// "worst intersection angle".
    pub(super) worst: String,
}
