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
