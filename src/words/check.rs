//! The check's words: the report's phrases and the typical mistakes in
//! one sentence each, in the language asked.

use super::catalogue::{CheckPhrases, catalogue};
use crate::kinematics::construction::Mistake;
use crate::lang::Lang;

pub use super::catalogue::fill;

/// The check's phrases in `lang`.
pub fn phrases(lang: Lang) -> &'static CheckPhrases {
    &catalogue(lang).check
}

/// Mistake `m` in one sentence: made at one decision (`one`) or at every
/// one.
pub fn mistake(lang: Lang, m: Mistake, one: bool) -> &'static str {
    let w = &phrases(lang).mistakes;
    let pair = match m {
        Mistake::CoriolisReversed => &w.coriolis_reversed,
        Mistake::CoriolisForgotten => &w.coriolis_forgotten,
        Mistake::CoriolisFactorOne => &w.coriolis_factor_one,
        Mistake::NormalFromCentre => &w.normal_from_centre,
        Mistake::NormalForgotten => &w.normal_forgotten,
        Mistake::MirroredFigure => &w.mirrored_figure,
        Mistake::WrongPerpendicular => &w.wrong_perpendicular,
        Mistake::TangentialParallel => &w.tangential_parallel,
        Mistake::WrongLink => &w.wrong_link,
        Mistake::Epsilon1Forgotten => &w.epsilon1_forgotten,
        Mistake::Epsilon1Added => &w.epsilon1_added,
        Mistake::OmegaWrongLink => &w.omega_wrong_link,
        Mistake::OmegaWrongSense => &w.omega_wrong_sense,
        Mistake::Slip => &w.slip,
        Mistake::NeighbourLink => &w.neighbour_link,
    };
    if one { &pair[0] } else { &pair[1] }
}
