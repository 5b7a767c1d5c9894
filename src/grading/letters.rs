//! A drawing's texts as a teacher reads them: which are a plan's letters
//! (`b`, `s2`, `a 3`, `a₃`, the pole `p_v`, `π` …) and which are
//! something else on the sheet — a title block, a sheet number, a
//! caption — that names no point. Students write an index in every way a
//! CAD or a keyboard allows (an underscore, a space, a Unicode subscript,
//! MTEXT's stacked text, braces from LaTeX habits), and type a letter in
//! the Cyrillic layout that looks like the Latin one (`р`, `а`, `с`);
//! each of these is the same letter on paper, so each is read as it.

/// The letters a plan's points and pole are written with, read as one
/// name: a Latin letter (or `π`, the acceleration pole in Russian and
/// Ukrainian books), primes (`′`, `'`), and an index — digits, or `v` /
/// `a` after the pole's letter — written plainly (`s2`), after an
/// underscore or a space (`s_2`, `s 2`, `s_{2}`) or as Unicode subscripts
/// (`s₂`, `pᵥ`). `None`: the text is no plan letter (a word, a number, a
/// sentence), and names no point.
///
/// The name is the letter, its primes and its index run together (`a3`,
/// `b′`, `pv`), as a JSON answer writes it; the letter's case is kept
/// (names are compared in lower case).
pub(crate) fn plan_letter(text: &str) -> Option<String> {
    let mut chars: Vec<char> = text
        .trim()
        .chars()
        .filter(|c| !matches!(c, '{' | '}'))
        .map(latin)
        .collect();
    // A dot or colon after a label ("b.", "a:") is punctuation, not part
    // of it.
    while chars.last().is_some_and(|c| matches!(c, '.' | ':')) {
        chars.pop();
    }
    let mut it = chars.into_iter().peekable();
    let letter = it.next().filter(|c| c.is_ascii_alphabetic() || *c == 'π')?;
    let mut name = String::from(letter);
    let primes = |it: &mut std::iter::Peekable<std::vec::IntoIter<char>>, name: &mut String| {
        while let Some(&c) = it.peek() {
            if !is_prime(c) {
                break;
            }
            name.push('′');
            it.next();
        }
    };
    primes(&mut it, &mut name);
    // A separator may stand only before an index.
    let mut separated = false;
    while it.peek().is_some_and(|c| matches!(c, '_' | ' ' | '\u{a0}')) {
        separated = true;
        it.next();
    }
    let mut index = String::new();
    while let Some(&c) = it.peek() {
        let Some(d) = index_char(c) else { break };
        index.push(d);
        it.next();
    }
    let pole = matches!(letter, 'p' | 'P' | 'π');
    let index_ok = match index.as_str() {
        "" => !separated,
        i if i.chars().all(|c| c.is_ascii_digit()) => i.len() <= 2,
        // The pole's subscript: which plan it is the pole of.
        i => pole && matches!(i.to_ascii_lowercase().as_str(), "v" | "a"),
    };
    if !index_ok {
        return None;
    }
    name.push_str(&index);
    primes(&mut it, &mut name);
    it.next().is_none().then_some(name)
}

/// Whether a plan letter (as [`plan_letter`] gives it) is the pole's:
/// `p`, `π`, with `v` or `a` after them.
pub(crate) fn is_pole(name: &str) -> bool {
    matches!(
        name.to_lowercase().as_str(),
        "p" | "pv" | "pa" | "π" | "πv" | "πa"
    )
}

/// A prime as students type it: the prime, an apostrophe, a right
/// single quote, an acute accent or a backtick.
fn is_prime(c: char) -> bool {
    matches!(c, '′' | '\'' | '’' | '‘' | '´' | '`')
}

/// A character of an index: a digit or a letter, the Unicode subscripts
/// read as their digits and letters.
fn index_char(c: char) -> Option<char> {
    match c {
        '₀'..='₉' => char::from_u32(c as u32 - '₀' as u32 + '0' as u32),
        'ₐ' => Some('a'),
        'ᵥ' => Some('v'),
        c if c.is_ascii_alphanumeric() => Some(c),
        _ => None,
    }
}

/// A Cyrillic letter that looks like a Latin one (typed in the Cyrillic
/// layout: `р` for the pole `p`, `а`, `с`; `В` for `B` in capitals only,
/// as a small `в` looks like no `b`) read as the Latin letter; any other
/// character as itself.
fn latin(c: char) -> char {
    match c {
        'а' => 'a',
        'А' => 'A',
        'В' => 'B',
        'с' => 'c',
        'С' => 'C',
        'е' => 'e',
        'Е' => 'E',
        'к' => 'k',
        'К' => 'K',
        'М' => 'M',
        'Н' => 'H',
        'о' => 'o',
        'О' => 'O',
        'р' => 'p',
        'Р' => 'P',
        'Т' => 'T',
        'х' => 'x',
        'Х' => 'X',
        c => c,
    }
}

/// Where a text states a scale: what follows its μ (the Greek letter,
/// the micro sign a code page gives for it, or `mu` as a word of its
/// own), anywhere in the text ("Масштаб μv = 0,005 (м/с)/мм"), when an
/// `=` follows it after no more than a short subscript (`v`, `_a`,
/// `{v}`, `_F`).
pub(crate) fn scale_statement(text: &str) -> Option<&str> {
    let mut from = 0;
    while from < text.len() {
        let rest = &text[from..];
        let (at, len) = [('μ', 'μ'.len_utf8()), ('µ', 'µ'.len_utf8())]
            .iter()
            .filter_map(|&(c, n)| rest.find(c).map(|k| (k, n)))
            .chain(rest.match_indices("mu").map(|(k, _)| (k, 2)).filter(|&(k, _)| {
                // "mu" as a word's start: not "must", "Kmu".
                !rest[..k].chars().next_back().is_some_and(char::is_alphabetic)
                    && !rest[k + 2..].chars().next().is_some_and(|c| {
                        c.is_alphabetic() && !matches!(c, 'v' | 'a' | 'F')
                    })
            }))
            .min()?;
        let after = &rest[at + len..];
        if let Some(eq) = after.find('=') {
            let sub = &after[..eq];
            let short = sub.trim().chars().count() <= 4
                && sub
                    .chars()
                    .all(|c| c.is_alphabetic() || matches!(c, '_' | '{' | '}' | ' '));
            if short {
                return Some(after);
            }
        }
        from += at + len;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_letters_in_every_form_are_read() {
        for (text, name) in [
            ("b", "b"),
            ("s2", "s2"),
            ("a 3", "a3"),
            ("a_3", "a3"),
            ("a_{3}", "a3"),
            ("a₃", "a3"),
            ("n₁₂", "n12"),
            ("b'", "b′"),
            ("b′", "b′"),
            ("B", "B"),
            ("p_v", "pv"),
            ("P v", "Pv"),
            ("pᵥ", "pv"),
            ("pₐ", "pa"),
            ("π", "π"),
            ("π_a", "πa"),
            ("р", "p"),
            ("с.", "c"),
        ] {
            assert_eq!(plan_letter(text).as_deref(), Some(name), "{text}");
        }
        for text in [
            "Machine Design, gr. 41",
            "Лист 3",
            "TMM 2026",
            "a_",
            "ab",
            "gr",
            "a 123",
            "Velocity plan",
            "μv = 0.01",
            "",
            "3",
            "b_v",
            "a b",
        ] {
            assert_eq!(plan_letter(text), None, "{text}");
        }
        assert!(is_pole("π") && is_pole("Pv") && is_pole("pa") && !is_pole("b"));
    }

    #[test]
    fn a_scale_is_found_anywhere_in_its_text() {
        assert_eq!(scale_statement("μv = 0,01"), Some("v = 0,01"));
        assert_eq!(scale_statement("Масштаб μ_a=0.05"), Some("_a=0.05"));
        assert_eq!(scale_statement("mu_v = 0.01"), Some("_v = 0.01"));
        assert_eq!(scale_statement("must = 3"), None);
        assert_eq!(scale_statement("μ written in words"), None);
        assert_eq!(scale_statement("ω1 = 10 1/s"), None);
    }
}
