//! The course's names of forces, as the force sheets print them: Φ₂ the
//! inertia force of link 2 and M_Φ2 its inertia couple, G₂ its weight,
//! F₅ (M₅) an external force (couple) on link 5, R₁₂ the force of link 1
//! on link 2 with R^τ₁₂, R^n₁₂ its components, and the balancing moment
//! (force) M_b, F_b (uk M_зр, ru M_ур: "зрівноважувальний",
//! "уравновешивающий"). Subscripts are the scene's link ids.

use super::notation::Label;
use crate::kinetostatics::force_plan::{Force, Part};
use crate::kinetostatics::{Load, Origin};
use crate::lang::Lang;
use crate::model::mechanism::Mechanism;

/// The subscript of the balancing moment (force) in `lang` (its
/// catalogue's `reading.balancing_subscript`).
pub fn balancing_sub(lang: Lang) -> &'static str {
    &super::catalogue::catalogue(lang).reading.balancing_subscript
}

/// Whether `key` (a force's name as `check` reads it, letters only) is
/// the balancing force ("F") or moment ("M") in any language: Fb, Fзр.
pub fn is_balancing(key: &str, letter: &str) -> bool {
    super::catalogue::every_reading()
        .any(|r| key.strip_prefix(letter) == Some(r.balancing_subscript.as_str()))
}

/// The balancing moment of an input: M_b.
pub fn balancing_moment(lang: Lang) -> Label {
    Label::new("M", balancing_sub(lang))
}

/// Two link ids as one subscript: "12", or "10,2" when an id has more
/// than one character (so that it reads one way only).
pub fn pair_sub(a: &str, b: &str) -> String {
    if a.chars().count() > 1 || b.chars().count() > 1 {
        format!("{a},{b}")
    } else {
        format!("{a}{b}")
    }
}

/// A known load's name: Φ₂, M_Φ2, G₂, F₅, M₅.
pub fn load(m: &Mechanism, l: &Load) -> Label {
    let id = m.link_id(l.link());
    match (l, l.origin()) {
        (Load::Force { .. }, Origin::Inertia) => Label::new("Φ", id),
        (Load::Force { .. }, Origin::Gravity) => Label::new("G", id),
        (Load::Force { .. }, Origin::External) => Label::new("F", id),
        (Load::Couple { .. }, Origin::Inertia) => Label::new("M", format!("Φ{id}")),
        (Load::Couple { .. }, _) => Label::new("M", id),
    }
}

/// The superscript of a reaction's component: τ along the link's normal
/// (or along the middle guide), n along the link (or across the guide).
pub fn part_sup(part: Part) -> &'static str {
    match part {
        Part::Whole => "",
        Part::Tangential | Part::AlongGuide => "τ",
        Part::Normal | Part::AcrossGuide => "n",
    }
}

/// A force of a force plan by name; `None` for a load index out of range.
pub fn force(m: &Mechanism, loads: &[Load], f: Force, lang: Lang) -> Option<Label> {
    Some(match f {
        Force::Load(i) => load(m, loads.get(i)?),
        Force::Reaction { from, to, part, .. } => {
            Label::new("R", pair_sub(m.link_id(from), m.link_id(to))).with_sup(part_sup(part))
        }
        Force::Drive { .. } => Label::new("F", balancing_sub(lang)),
    })
}

/// The name of a force in the course's notation, as the force sheets
/// print it (`presentation::force_notation`) in plain text: Φ_2 (inertia
/// force), M_Φ2 (inertia couple), G_2 (weight), F_5 and M_3 (external),
/// R_12 (the reaction of link 1 on link 2) with ^τ, ^n for a component,
/// F_b (the drive force of a cylinder or slider; uk F_зр, ru F_ур).
pub fn force_name(m: &Mechanism, loads: &[Load], f: Force, lang: Lang) -> String {
    force(m, loads, f, lang).map_or_else(|| "?".into(), |l| plain(&l))
}

/// A label as plain text in the lecture's notation (`R^τ_12`), for
/// messages and tests.
pub fn plain(l: &Label) -> String {
    let mut s = l.base.clone();
    if !l.sup.is_empty() {
        s += &format!("^{}", l.sup);
    }
    if !l.sub.is_empty() {
        s += &format!("_{}", l.sub);
    }
    s + &l.tail
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subscripts_read_one_way() {
        assert_eq!(pair_sub("1", "2"), "12");
        assert_eq!(pair_sub("10", "2"), "10,2");
        let r = Label::new("R", "03").with_sup(part_sup(Part::Tangential));
        assert_eq!(plain(&r), "R^τ_03");
        assert_eq!(plain(&balancing_moment(Lang::Uk)), "M_зр");
        assert_eq!(plain(&balancing_moment(Lang::Ru)), "M_ур");
    }
}
