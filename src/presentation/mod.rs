//! Presentation: the result file and the terminal's table ([`report`]),
//! the tables of results as data, for the terminal and the handout alike
//! ([`tables`]), the sheets and the handout ([`drawing`]), quantities in
//! messages ([`quantity`]), the force analysis in the result ([`dynamics`]).

pub mod drawing;
pub mod dynamics;
pub mod force_steps;
pub mod report;
mod steps;
pub mod studies;
pub mod tables;
mod text_table;
