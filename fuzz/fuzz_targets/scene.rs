//! Arbitrary bytes as a scene: `Scene::from_json` → `Analysis::new` →
//! `run` → `studies::sheet_data` → `drawing::sheets` must never panic
//! (errors are fine).
#![no_main]

use libfuzzer_sys::fuzz_target;
use mechplan::drawing::{DrawOptions, sheet_needs, sheets};
use mechplan::studies::sheet_data::SheetData;
use mechplan::scene::PositionsSpec;
use mechplan::{Analysis, Scene};

/// Positions solved per input: a valid scene may ask for 100 000 (the
/// parser's limit) and each one is solved, cross-checked and drawn; that
/// is slow by design, not a bug, so longer lists are cut to keep the
/// fuzzer's executions fast.
const MAX_FUZZ_POSITIONS: usize = 16;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(mut scene) = Scene::from_json(text) else {
        return;
    };
    match &mut scene.positions {
        PositionsSpec::List(v) => v.truncate(MAX_FUZZ_POSITIONS),
        PositionsSpec::Values(v) => v.truncate(MAX_FUZZ_POSITIONS),
        PositionsSpec::Count { count, .. } => *count = (*count).min(MAX_FUZZ_POSITIONS),
        PositionsSpec::Single => {}
    }
    let Ok(an) = Analysis::new(scene) else {
        return;
    };
    let Ok(solved) = an.run() else {
        return;
    };
    let opt = DrawOptions::default();
    let Ok(data) = SheetData::solve(&an, &solved, sheet_needs(&an, &solved, &opt, true)) else {
        return;
    };
    let _ = sheets(&an, &solved, &data, &opt);
});
