//! (drawings: below)
