//! What a label is and how wide text is: the [`Label`] (letters, a
//! subscript, a superscript over it, a tail, further names) and the
//! estimated widths of glyphs and of runs of the lecture's notation, which
//! both the placing of labels and the writing of SVG measure text by, so
//! that a label's box and its drawn text agree.

pub use crate::words::Label;
use crate::words::notation::{Pos, Run};

/// Advance width of a glyph of DejaVu Sans in em, a little generous.
pub(super) fn char_width(c: char) -> f64 {
    match c {
        'm' | 'w' | 'M' | 'W' | 'ω' | 'Ω' | '—' => 1.0,
        'i' | 'l' | 'j' | '.' | ',' | ':' | ';' | '\'' | '|' => 0.36,
        'f' | 't' | 'r' | ' ' | '(' | ')' | '/' => 0.46,
        c if c.is_uppercase() => 0.8,
        _ => 0.66,
    }
}

/// `text` (the lecture's notation, [`crate::words::notation::runs`]) in
/// lines no wider than `width` mm at font size `size`, broken after a
/// comma, a colon or a semicolon and its space (an equation's steps stay
/// whole between them); a piece wider than `width` alone keeps its line.
pub fn wrap(text: &str, width: f64, size: f64) -> Vec<String> {
    let wide = |t: &str| runs_width(&crate::words::notation::runs(t), size);
    let mut pieces: Vec<&str> = Vec::new();
    let mut start = 0;
    for (i, _) in text.match_indices([',', ':', ';']) {
        if text[i + 1..].starts_with(' ') {
            pieces.push(&text[start..i + 2]);
            start = i + 2;
        }
    }
    pieces.push(&text[start..]);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for p in pieces {
        let joined = format!("{line}{p}");
        if !line.is_empty() && wide(joined.trim_end()) > width {
            lines.push(line.trim_end().to_string());
            line = p.to_string();
        } else {
            line = joined;
        }
    }
    lines.push(line.trim_end().to_string());
    lines
}

/// Estimated width in mm of runs of text at font size `size`: a
/// superscript and the subscript right after it stand one above the
/// other, so the wider of the two counts.
pub fn runs_width(rs: &[Run], size: f64) -> f64 {
    let w = |s: &str| s.chars().map(char_width).sum::<f64>();
    let mut total = 0.0;
    let mut i = 0;
    while i < rs.len() {
        let (p, t) = &rs[i];
        match p {
            Pos::Base => total += size * w(t),
            Pos::Sub => total += 0.7 * size * w(t),
            Pos::Sup => {
                let mut x = 0.7 * size * w(t);
                if let Some((Pos::Sub, u)) = rs.get(i + 1) {
                    x = x.max(0.7 * size * w(u));
                    i += 1;
                }
                total += x;
            }
        }
        i += 1;
    }
    total
}

impl Label {
    /// A bare number: a link's or a position's.
    pub(super) fn is_number(&self) -> bool {
        !self.base.is_empty()
            && self.base.chars().all(|c| c.is_ascii_digit())
            && self.sub.is_empty()
            && self.sup.is_empty()
            && self.tail.is_empty()
            && self.more.is_empty()
    }

    /// How much higher than a plain label's its box reaches (mm): a
    /// superscript stands above the capitals.
    pub fn rise(&self, size: f64) -> f64 {
        if self.sup.is_empty() {
            0.0
        } else {
            0.55 * size
        }
    }
    /// Estimated width in mm at font size `size` (DejaVu Sans: ~0.6 em).
    pub fn width(&self, size: f64) -> f64 {
        let w = |s: &str| s.chars().map(char_width).sum::<f64>();
        let more: f64 = self
            .more
            .iter()
            .map(|(b, s)| size * (w(", ") + w(b)) + 0.7 * size * w(s))
            .sum();
        size * (w(&self.base) + w(&self.tail)) + 0.7 * size * w(&self.sub).max(w(&self.sup)) + more
    }
}
