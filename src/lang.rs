//! The languages of mechplan's words: the steps, the sheets' annotations
//! and the handout are written in English, Ukrainian or Russian (the
//! scene's `want.lang`, or the command's `--lang`).

/// A language of the words (the mathematics, names and numbers, is the
/// same in all).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lang {
    /// English (`en`).
    En,
    /// Ukrainian (`uk`).
    Uk,
    /// Russian (`ru`).
    Ru,
}

impl Lang {
    /// Every language, in the order of their codes' listing.
    pub const ALL: [Lang; 3] = [Lang::En, Lang::Uk, Lang::Ru];

    /// The language of a code: `en`, `uk` or `ru`.
    pub fn parse(s: &str) -> Option<Lang> {
        match s {
            "en" => Some(Lang::En),
            "uk" => Some(Lang::Uk),
            "ru" => Some(Lang::Ru),
            _ => None,
        }
    }

    /// The language's code, as `parse` reads it.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Uk => "uk",
            Lang::Ru => "ru",
        }
    }
}
