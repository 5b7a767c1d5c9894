//! Verification: the cross-check of the analysis at every position
//! ([`crosscheck`]), checking hand-drawn plans ([`check`]), the
//! extended-precision reference ([`reference`](mod@reference)) and the work-precision
//! report built on it ([`precision`]).

pub mod check;
pub mod crosscheck;
pub mod precision;
pub mod reference;
