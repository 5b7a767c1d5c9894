//! Presentation: the result file and tables ([`report`]), the sheets and
//! the handout ([`drawing`]), quantities in messages ([`quantity`]).

pub mod drawing;
pub mod quantity;
pub mod report;
