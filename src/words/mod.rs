//! The words: every phrase mechplan writes, by language ([`Lang`]). The
//! mathematics (names of points, vectors, numbers) is the same in every
//! language; only the words change, each language one catalogue of
//! phrases with named blanks ([`fill`]). [`construction`] the steps of the
//! plans, [`force_plans`] the steps of the force plans, [`forces`] the
//! names of forces, [`notation`] the lecture's notation as runs of text
//! and labels, [`inputs`] a position's inputs in short.

pub mod construction;
pub mod force_plans;
pub mod forces;
pub mod inputs;
pub mod notation;

pub use crate::lang::Lang;

use std::sync::OnceLock;
pub use notation::Label;

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
    pub construction: construction::Phrases,
    /// The force plans' steps.
    pub force_plans: force_plans::Phrases,
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
