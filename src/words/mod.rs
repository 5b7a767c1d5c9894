//! The words: every phrase mechplan writes, by language ([`Lang`]). The
//! mathematics (names of points, vectors, numbers) is the same in every
//! language; only the words change. [`construction`] the steps of the
//! plans, [`forces`] the names of forces, [`notation`] the lecture's
//! notation as runs of text and labels.

pub mod construction;
pub mod forces;
pub mod inputs;
pub mod notation;

pub use crate::lang::Lang;
pub use notation::Label;
