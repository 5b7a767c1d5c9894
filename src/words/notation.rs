//! The lecture's notation as runs of text: `v_B3C` is v with the
//! subscript B3C, `a^K_B3B2` is a with K above and B3B2 below, the pole
//! `p_vb` is p with the subscript v and then b, digits after a letter are
//! a subscript (`ω1`, `b3`, `O2`). The sheets (SVG) and the handout (HTML)
//! write the same runs each in its own way.

/// Where a run of text sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pos {
    Base,
    Sub,
    Sup,
}

/// A run: its place and its text.
pub type Run = (Pos, String);

/// `s` in the lecture's notation, split into runs. Only `_` and `^` are
/// dropped (with a combining underline right after them); the rest of the
/// text is kept.
pub fn runs(s: &str) -> Vec<Run> {
    let cs: Vec<char> = s.chars().collect();
    let mark = |c: char| ('\u{300}'..='\u{36f}').contains(&c);
    // The last character that is not a combining mark, before `i`.
    let base_before = |i: usize| cs[..i].iter().rev().find(|c| !mark(**c)).copied();
    let mut out: Vec<Run> = Vec::new();
    let mut push = |pos: Pos, t: &[char]| {
        let t: String = t.iter().collect();
        match out.last_mut() {
            Some((p, s)) if *p == pos => s.push_str(&t),
            _ => out.push((pos, t)),
        }
    };
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        let skip_marks = |mut j: usize| {
            while j < cs.len() && mark(cs[j]) {
                j += 1;
            }
            j
        };
        if c == '^' || c == '_' {
            let start = skip_marks(i + 1);
            let mut j = start;
            let pole = c == '_'
                && base_before(i) == Some('p')
                && i >= 1
                && cs[..i - 1]
                    .iter()
                    .rev()
                    .find(|c| !mark(**c))
                    .is_none_or(|c| !c.is_alphanumeric())
                && matches!(cs.get(start), Some('v' | 'a'));
            if pole {
                j = skip_marks(start + 1);
            } else if c == '^' {
                while j < cs.len() && (cs[j].is_alphabetic() || mark(cs[j])) {
                    j += 1;
                }
            } else {
                while j < cs.len() && (cs[j].is_alphanumeric() || mark(cs[j])) {
                    j += 1;
                }
            }
            if j > start {
                push(if c == '^' { Pos::Sup } else { Pos::Sub }, &cs[start..j]);
                i = j;
                continue;
            }
        } else if c.is_ascii_digit() && base_before(i).is_some_and(|b| b.is_alphabetic()) {
            let mut j = i;
            while j < cs.len() && (cs[j].is_ascii_digit() || mark(cs[j])) {
                j += 1;
            }
            push(Pos::Sub, &cs[i..j]);
            i = j;
            continue;
        }
        push(Pos::Base, &cs[i..i + 1]);
        i += 1;
    }
    out
}

/// A label: letters and a subscript.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    pub base: String,
    pub sub: String,
    /// A superscript over the subscript (R^τ_12: the component of a
    /// reaction); empty on most labels.
    pub sup: String,
    /// Plain text after the subscript.
    pub tail: String,
    /// Further names sharing the label, each with its subscript
    /// (", o₁, o₂").
    pub more: Vec<(String, String)>,
}

impl Label {
    /// Letters and a subscript.
    pub fn new(base: impl Into<String>, sub: impl Into<String>) -> Label {
        Label {
            base: base.into(),
            sub: sub.into(),
            sup: String::new(),
            tail: String::new(),
            more: Vec::new(),
        }
    }
    /// Another name at the same place: "p_v, o₁".
    pub fn and(mut self, base: impl Into<String>, sub: impl Into<String>) -> Label {
        self.more.push((base.into(), sub.into()));
        self
    }
    /// The superscript stacked over the subscript: R^τ_12.
    pub fn with_sup(mut self, sup: impl Into<String>) -> Label {
        self.sup = sup.into();
        self
    }
    /// Plain text after the subscript.
    pub fn with_tail(mut self, tail: impl Into<String>) -> Label {
        self.tail = tail.into();
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn show(s: &str) -> String {
        runs(s)
            .into_iter()
            .map(|(p, t)| match p {
                Pos::Base => t,
                Pos::Sub => format!("_{{{t}}}"),
                Pos::Sup => format!("^{{{t}}}"),
            })
            .collect()
    }

    #[test]
    fn the_lecture_notation() {
        assert_eq!(show("v_B3C"), "v_{B3C}");
        assert_eq!(show("a^K_B3B2 = 2·ω3"), "a^{K}_{B3B2} = 2·ω_{3}");
        assert_eq!(show("p_vb = 12.5 mm"), "p_{v}b = 12.5 mm");
        assert_eq!(show("φ1 = 30°, O2"), "φ_{1} = 30°, O_{2}");
        assert_eq!(show("120 mm"), "120 mm");
    }
}
