//! Verification of the analysis: the cross-check at every position
//! ([`crosscheck`]), the extended-precision reference
//! ([`reference`](mod@reference)) and the work-precision report built on
//! it ([`precision`]). Checking a student's hand-drawn plan is grading
//! (`crate::grading`), above the pipeline.

pub mod crosscheck;
pub mod precision;
pub mod reference;
