//! Verification of the analysis: the cross-check at every position
//! ([`crosscheck`], naming what differed most by [`worst`]), the
//! extended-precision reference
//! ([`reference`](mod@reference)) and the work-precision report built on
//! it ([`precision`]). Checking a student's hand-drawn plan is grading
//! (`crate::grading`), above the pipeline.

pub mod crosscheck;
pub mod precision;
pub mod reference;
mod compare;
mod sensitivity;
pub mod worst;
