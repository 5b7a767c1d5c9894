//! A DXF's texts: its code page ([`code_page`], [`encoding`]) and the
//! codes of its TEXT and MTEXT values (`%%d`, `\U+XXXX`, MTEXT's
//! formatting) read into plain text ([`text_codes`], [`mtext_codes`]).

/// The code page a DXF's header names ($DWGCODEPAGE), upper case; empty
/// when it names none.
pub(super) fn code_page(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let mut lines = text.lines().map(str::trim);
    while let Some(l) = lines.next() {
        if l.eq_ignore_ascii_case("$DWGCODEPAGE") {
            let _code = lines.next();
            return lines.next().unwrap_or("").to_ascii_uppercase();
        }
        if l.eq_ignore_ascii_case("ENDSEC") {
            break;
        }
    }
    String::new()
}

/// The encoding of a DXF code page (ANSI_1251, DOS866 …).
pub(super) fn encoding(page: &str) -> Option<&'static encoding_rs::Encoding> {
    let label = match page {
        p if p.starts_with("ANSI_125") => format!("windows-{}", &p[5..]),
        "ANSI_874" => "windows-874".into(),
        "ANSI_932" | "DOS932" => "shift_jis".into(),
        "ANSI_936" => "gbk".into(),
        "ANSI_949" => "euc-kr".into(),
        "ANSI_950" => "big5".into(),
        "DOS866" => "ibm866".into(),
        p if p.starts_with("ISO8859-") => format!("iso-8859-{}", &p[8..]),
        _ => return None,
    };
    encoding_rs::Encoding::for_label(label.as_bytes())
}

/// `\U+XXXX` at the start of `s` (past the backslash): the character and
/// the bytes read.
fn unicode_escape(s: &str) -> Option<(char, usize)> {
    let hex = s.strip_prefix("U+")?.get(..4)?;
    let c = char::from_u32(u32::from_str_radix(hex, 16).ok()?)?;
    Some((c, 6))
}

/// A TEXT's value: `%%` codes (°, ±, ⌀, over- and underline toggles) and
/// `\U+XXXX` escapes read.
pub(super) fn text_codes(s: &str) -> String {
    let mut out = String::new();
    let mut i = 0;
    while i < s.len() {
        let rest = &s[i..];
        if let Some(r) = rest.strip_prefix("%%") {
            let c = r.chars().next();
            match c.map(|c| c.to_ascii_lowercase()) {
                Some('d') => out.push('°'),
                Some('p') => out.push('±'),
                Some('c') => out.push('⌀'),
                Some('%') => out.push('%'),
                Some('u' | 'o' | 'k') => {}
                Some(d) if d.is_ascii_digit() => {
                    let n: String = r.chars().take_while(char::is_ascii_digit).take(3).collect();
                    if let Some(ch) = n.parse::<u32>().ok().and_then(char::from_u32) {
                        out.push(ch);
                    }
                    i += 2 + n.len();
                    continue;
                }
                _ => {
                    out.push_str("%%");
                    i += 2;
                    continue;
                }
            }
            i += 2 + c.map_or(0, char::len_utf8);
        } else if let Some((c, n)) = rest.strip_prefix('\\').and_then(unicode_escape) {
            out.push(c);
            i += 1 + n;
        } else {
            let c = rest.chars().next().expect("within the text");
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// An MTEXT's content with its formatting stripped: paragraphs (`\P`) as
/// spaces, braces dropped, `\f…;`, `\H…;` and the other codes with a
/// value removed, stacked text (`\S2^;`, `\Sa/b;`) as its parts in a row,
/// `\U+XXXX` read, `\\`, `\{`, `\}` as themselves.
pub(super) fn mtext_codes(s: &str) -> String {
    let mut out = String::new();
    let mut chars = s.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        match c {
            '{' | '}' => {}
            '\\' => {
                let Some(&(_, code)) = chars.peek() else {
                    break;
                };
                chars.next();
                match code {
                    'P' | 'X' | '~' => out.push(' '),
                    '\\' | '{' | '}' => out.push(code),
                    'L' | 'l' | 'O' | 'o' | 'K' | 'k' | 'N' => {}
                    'U' => {
                        if let Some((ch, n)) = unicode_escape(&s[i + 1..]) {
                            out.push(ch);
                            for _ in 1..n {
                                chars.next();
                            }
                        }
                    }
                    'S' => {
                        for (_, d) in chars.by_ref() {
                            match d {
                                ';' => break,
                                '^' | '/' | '#' => {}
                                d => out.push(d),
                            }
                        }
                    }
                    // \f, \F, \H, \W, \Q, \T, \A, \C, \c, \p …: up to ';'.
                    _ => {
                        for (_, d) in chars.by_ref() {
                            if d == ';' {
                                break;
                            }
                        }
                    }
                }
            }
            c => out.push(c),
        }
    }
    text_codes(&out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mtext_formatting_is_stripped() {
        assert_eq!(mtext_codes(r"{\fArial|b0|i0;n}\S^2;"), "n2");
        assert_eq!(mtext_codes(r"\H3.5;n_2"), "n_2");
        assert_eq!(mtext_codes(r"\U+03BCv = 0,01\P(m/s)/mm"), "μv = 0,01 (m/s)/mm");
        assert_eq!(mtext_codes(r"a\\b\{c\}"), r"a\b{c}");
        assert_eq!(text_codes("45%%d %%ub%%u"), "45° b");
    }

    #[test]
    fn code_pages_are_named() {
        let enc = encoding("ANSI_1251").unwrap();
        assert_eq!(enc.decode(&[0xEC, 0xEC]).0, "мм");
        assert!(encoding("DOS866").is_some());
        assert!(encoding("WHATEVER").is_none());
    }

}
