//! The languages of mechplan's words: the steps, the sheets' annotations
//! and the handout are written in English, Ukrainian or Russian (the
//! scene's `want.lang`, or the command's `--lang`).
//!
//! A language is one line of `languages!` below and its catalogue file
//! `src/words/<code>.json` (every phrase, the way it writes numbers, the
//! words `check` reads in a drawing's titles): nothing else names one.

/// The languages, each as its variant of [`Lang`], its code and its
/// catalogue file (`src/words/<code>.json`, compiled in), in the order of
/// [`Lang::ALL`].
macro_rules! languages {
    ($($(#[$doc:meta])* $name:ident = $code:literal),* $(,)?) => {
        /// A language of the words (the mathematics, names and numbers, is
        /// the same in all).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Lang {
            $($(#[$doc])* $name,)*
        }

        impl Lang {
            /// Every language, in the order of their codes' listing.
            pub const ALL: [Lang; [$($code),*].len()] = [$(Lang::$name),*];

            /// The language of a code (`en`, `uk`, `ru` …).
            pub fn parse(s: &str) -> Option<Lang> {
                match s {
                    $($code => Some(Lang::$name),)*
                    _ => None,
                }
            }

            /// The language's code, as `parse` reads it.
            pub fn code(self) -> &'static str {
                match self {
                    $(Lang::$name => $code,)*
                }
            }

            /// The text of the language's catalogue file
            /// (`src/words/<code>.json`).
            pub(crate) fn catalogue_text(self) -> &'static str {
                match self {
                    $(Lang::$name => include_str!(concat!("words/", $code, ".json")),)*
                }
            }

            /// Its place in [`Lang::ALL`].
            pub(crate) fn index(self) -> usize {
                self as usize
            }
        }
    };
}

languages! {
    /// English (`en`).
    En = "en",
    /// Ukrainian (`uk`).
    Uk = "uk",
    /// Russian (`ru`).
    Ru = "ru",
}

impl Lang {
    /// The codes of every language, for messages: "en, uk, ru".
    pub fn codes() -> String {
        Lang::ALL.map(Lang::code).join(", ")
    }
}
