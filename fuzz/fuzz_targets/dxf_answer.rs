//! Arbitrary bytes as a student's DXF answer (`mechplan check SCENE
//! ANSWER.dxf`, a plan drawn in a CAD): reading it must never panic,
//! abort or take long (group codes out of order, a section never ended,
//! blocks inserting blocks, polylines without vertices, huge or NaN
//! coordinates, MTEXT with broken font codes), and an answer that is read
//! is checked against the default scene's plans without panicking. It
//! goes in by the front door, as the command's answers do.
#![no_main]

use libfuzzer_sys::fuzz_target;
use mechplan::{CheckRequest, DEFAULT_SCENE, PlanKind, Solution, Study};
use std::sync::OnceLock;

fn solution() -> &'static Solution<'static> {
    static STUDY: OnceLock<Study> = OnceLock::new();
    static SOLUTION: OnceLock<Solution<'static>> = OnceLock::new();
    SOLUTION.get_or_init(|| {
        let study = STUDY.get_or_init(|| Study::from_json(DEFAULT_SCENE).unwrap());
        study.solve().unwrap()
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let solution = solution();
    for (mu, plan) in [
        (None, None),
        (Some(0.01), Some(PlanKind::Velocity)),
        (Some(0.1), Some(PlanKind::Acceleration)),
    ] {
        let req = CheckRequest {
            mu,
            plan,
            ..CheckRequest::default()
        };
        let _ = solution.check_answer(text, "answer.dxf", true, &req);
    }
});
