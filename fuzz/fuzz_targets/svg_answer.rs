//! Arbitrary bytes as a student's SVG answer (`mechplan check SCENE
//! ANSWER.svg`): reading it must never panic, abort or take long (deep
//! nesting, huge files, broken transforms, labels without lines), and an
//! answer that is read is checked against the default scene's plans
//! without panicking.
#![no_main]

use libfuzzer_sys::fuzz_target;
use mechplan::check::{check, svg::from_svg};
use mechplan::construction::PlanKind;
use mechplan::{Analysis, DEFAULT_SCENE, Scene, Solved};
use std::sync::OnceLock;

fn scene() -> &'static (Analysis, Vec<Solved>) {
    static S: OnceLock<(Analysis, Vec<Solved>)> = OnceLock::new();
    S.get_or_init(|| {
        let an = Analysis::new(Scene::from_json(DEFAULT_SCENE).unwrap()).unwrap();
        let solved = an.run().unwrap();
        (an, solved)
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (an, solved) = scene();
    for (mu, plan) in [
        (None, None),
        (Some(0.01), Some(PlanKind::Velocity)),
        (Some(0.1), Some(PlanKind::Acceleration)),
    ] {
        if let Ok(ans) = from_svg(text, mu, plan, 0.5, 1) {
            let _ = check(an, solved, &ans);
        }
    }
});
