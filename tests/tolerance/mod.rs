//! A student's honest construction on paper, simulated from the method
//! (`hand`: the pencil, the compass, the ruler, reading and typing;
//! `scenes`, `mechanisms`: the plans drawn scene by scene), for the Monte
//! Carlo of each step's tolerance (`tests/tolerance_models.rs`).
#![allow(dead_code)]

pub mod hand;
pub mod mechanisms;
pub mod scenes;

/// The pencil's precision δ, mm.
pub const DELTA: f64 = 0.5;
