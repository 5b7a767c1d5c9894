//! The words of the terminal's tables (`solve`'s table, `mechplan
//! centres`, `mechplan diagram`) that name what the analysis found as
//! data: which quantity the cross-check found worst, how an instant centre
//! was found or why it was not. Their English is also the JSON result's
//! (its `worst`, `how`, `why`), which keeps it in every language.

use super::catalogue::{CentrePhrases, ResultPhrases, catalogue, fill};
use crate::lang::Lang;
use crate::model::mechanism::Mechanism;
use crate::studies::centres::{How, Why};
use crate::verification::worst::{Route, Worst};

/// The result lines' phrases in `lang`.
pub fn results(lang: Lang) -> &'static ResultPhrases {
    &catalogue(lang).results
}

/// The centres' phrases in `lang`.
pub fn centres(lang: Lang) -> &'static CentrePhrases {
    &catalogue(lang).centres
}

/// What the cross-check found worst, in `lang`: "v of B", "ε of link 3
/// (plan against the contour route)", "none" (in English as
/// [`Worst`]'s `Display`).
pub fn worst(w: &Worst, lang: Lang) -> String {
    let r = results(lang);
    let what = match &w.item {
        None => r.none.clone(),
        Some((q, id)) if q.of_link() => fill(&r.of_link[q.index()], &[("id", id)]),
        Some((q, p)) => fill(&r.of_point[q.index()], &[("p", p)]),
    };
    match w.plan {
        None => what,
        Some(route) => {
            let route = &r.route[match route {
                Route::Contour => 0,
                Route::Constraint => 1,
            }];
            fill(&r.plan, &[("what", &what), ("route", route)])
        }
    }
}

/// How a centre was found, in `lang`: "revolute pair A", "Kennedy: lines
/// through links 1 and 3".
pub fn how(m: &Mechanism, h: &How, lang: Lang) -> String {
    let c = centres(lang);
    match h {
        How::Revolute(p) => fill(&c.revolute, &[("p", p)]),
        How::Prismatic => c.prismatic.clone(),
        How::Kennedy([a, b]) => fill(&c.kennedy, &[("a", m.link_id(*a)), ("b", m.link_id(*b))]),
    }
}

/// Why the centre of links `links` cannot be placed, in `lang`.
pub fn why(m: &Mechanism, links: (usize, usize), w: Why, lang: Lang) -> String {
    let c = centres(lang);
    let (i, j) = (m.link_id(links.0), m.link_id(links.1));
    match w {
        Why::Coincide([a, b]) => fill(
            &c.coincide,
            &[
                ("a", m.link_id(a)),
                ("b", m.link_id(b)),
                ("i", i),
                ("j", j),
            ],
        ),
        Why::FewLines => fill(&c.few_lines, &[("i", i), ("j", j)]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verification::worst::Quantity;
    use serde_json::Value;
    use std::collections::BTreeSet;

    /// The English words are [`Worst`]'s own, as the refusals and the
    /// JSON result write them.
    #[test]
    fn the_english_worst_is_the_results() {
        for q in Quantity::ALL {
            for plan in [None, Some(Route::Contour), Some(Route::Constraint)] {
                let w = Worst {
                    plan,
                    ..Worst::of(q, "B")
                };
                assert_eq!(worst(&w, Lang::En), w.to_string());
            }
        }
        assert_eq!(worst(&Worst::default(), Lang::En), "none");
        let w = Worst {
            plan: Some(Route::Contour),
            ..Worst::of(Quantity::Epsilon, "3")
        };
        assert_eq!(w.to_string(), "ε of link 3 (plan against the contour route)");
        assert_eq!(worst(&w, Lang::Uk), "ε ланки 3 (план порівняно з методом контурів)");
    }

    /// A section of a language's catalogue file, as JSON.
    fn section(lang: Lang, name: &str) -> Value {
        let text = lang.catalogue_text();
        let mut v: Value = serde_json::from_str(text).expect("a valid catalogue");
        v[name].take()
    }

    /// Every phrase of `v` with its blanks, by its path.
    fn blanks(v: &Value, path: &str, out: &mut Vec<(String, BTreeSet<String>)>) {
        match v {
            Value::String(s) => {
                let names = s
                    .split('{')
                    .skip(1)
                    .map(|b| b.split('}').next().unwrap_or_default().to_string())
                    .collect();
                out.push((path.to_string(), names));
            }
            Value::Array(a) => a
                .iter()
                .enumerate()
                .for_each(|(i, x)| blanks(x, &format!("{path}/{i}"), out)),
            Value::Object(o) => o
                .iter()
                .for_each(|(k, x)| blanks(x, &format!("{path}/{k}"), out)),
            other => panic!("{path}: not a phrase: {other}"),
        }
    }

    /// Every phrase of the terminal's tables in every language has the
    /// English phrase's blanks, no more and no fewer (one left out would
    /// drop a number, one added would panic when filled).
    #[test]
    fn every_phrase_has_the_english_blanks() {
        for name in ["results", "centres", "diagrams", "tables"] {
            let mut english = Vec::new();
            blanks(&section(Lang::En, name), name, &mut english);
            for lang in Lang::ALL {
                let mut own = Vec::new();
                blanks(&section(lang, name), name, &mut own);
                assert_eq!(own, english, "{}", lang.code());
            }
        }
    }
}
