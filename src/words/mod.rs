//! The words: every phrase mechplan writes, by language ([`Lang`]). The
//! mathematics (names of points, vectors, numbers) is the same in every
//! language; only the words change, each language one catalogue of
//! phrases with named blanks ([`catalogue::fill`]). [`construction`] the steps of the
//! plans, [`force_plans`] the steps of the force plans, [`forces`] the
//! names of forces, [`notation`] the lecture's notation as runs of text
//! and labels, [`inputs`] a position's inputs in short, [`numbers`] the
//! language's decimal mark and units' letters, [`terminal`] what the
//! terminal's tables name as data (the cross-check's worst quantity, how
//! an instant centre was found).

pub mod catalogue;
pub mod check;
pub mod construction;
pub mod force_plans;
pub mod forces;
pub mod inputs;
pub mod notation;
pub mod numbers;
pub mod overlay_phrases;
pub mod terminal;

pub use catalogue::catalogue;
pub use notation::Label;
