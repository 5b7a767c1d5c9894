//! How a language writes the numbers and units mechplan has already
//! formatted ([`crate::format`]): its decimal mark (a comma in Ukrainian
//! and Russian, as the lecture writes 0,001 м/мм) and its letters of the
//! SI units (м/с², рад/с). The digits are [`crate::format`]'s in every
//! language; only the mark and the letters change.

use super::catalogue::catalogue;
use crate::format::format_quantity;
use crate::lang::Lang;

/// `text` with every decimal point between two digits written with the
/// language's decimal mark (`units.decimal` of its catalogue): "0.3500"
/// is "0,3500" in Ukrainian; a full stop after a word or a number ("… 70
/// мм. ", "1. Step") stays.
pub fn decimals(text: &str, lang: Lang) -> String {
    let mark = catalogue(lang).units.decimal.as_str();
    if mark == "." {
        return text.to_string();
    }
    let c: Vec<char> = text.chars().collect();
    let digit = |j: Option<&char>| j.is_some_and(char::is_ascii_digit);
    let mut out = String::with_capacity(text.len());
    for (i, &ch) in c.iter().enumerate() {
        if ch == '.' && i > 0 && digit(c.get(i - 1)) && digit(c.get(i + 1)) {
            out.push_str(mark);
        } else {
            out.push(ch);
        }
    }
    out
}

/// A unit in the language: "м/с²" for "m/s²" (its catalogue's
/// `units.letters`, replaced in order).
pub fn unit(u: &str, lang: Lang) -> String {
    catalogue(lang)
        .units
        .letters
        .iter()
        .fold(u.to_string(), |u, [si, own]| u.replace(si.as_str(), own))
}

/// `x` and its unit as [`format_quantity`] writes them, in the language:
/// "0,5000 мм" for (0.5, "mm") in Ukrainian.
pub fn quantity(x: f64, u: &str, lang: Lang) -> String {
    decimals(&format_quantity(x, &unit(u, lang)), lang)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_marks_and_units() {
        assert_eq!(decimals("0.3500", Lang::En), "0.3500");
        assert_eq!(decimals("0.3500", Lang::Uk), "0,3500");
        assert_eq!(decimals("-1.25e3", Lang::Ru), "-1,25e3");
        assert_eq!(
            decimals("= 1 / 0.01 = 100 мм. 2. Крок", Lang::Uk),
            "= 1 / 0,01 = 100 мм. 2. Крок"
        );
        assert_eq!(quantity(0.5, "mm", Lang::Uk), "0,5000 мм");
        assert_eq!(quantity(2.5, "m/s²", Lang::Ru), "2,500 м/с²");
        assert_eq!(quantity(2.5, "rad/s", Lang::En), "2.500 rad/s");
        assert_eq!(unit("°", Lang::Uk), "°");
    }
}
