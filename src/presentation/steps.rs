//! The constructions as numbered lecture-style steps (`solve --steps`):
//! per position the plan of velocities and of accelerations, their
//! measured values with their drafting bounds, and with `dynamics` the
//! force plans and the lever ([`super::force_steps`]).

use crate::words::inputs::input_words;
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use std::fmt::Write as _;

/// The constructions as numbered lecture-style steps (`solve --steps`).
#[cfg(feature = "internals")]
pub fn to_steps(an: &Analysis, solved: &[Solved], lang: Lang) -> String {
    let mut t = steps_head(an, lang);
    for (i, s) in solved.iter().enumerate() {
        t += &steps_position(an, i, s, lang);
    }
    t
}

/// The steps' title line.
pub(super) fn steps_head(an: &Analysis, lang: Lang) -> String {
    let m = &an.mech;
    let mut t = String::new();
    let title = m.scene.title_in(lang);
    if !title.is_empty() {
        let _ = writeln!(t, "{title}");
    }
    t
}

/// The steps of position `i` (from 0).
pub(super) fn steps_position(an: &Analysis, i: usize, s: &Solved, lang: Lang) -> String {
    use crate::format::num;
    use crate::words::construction::sentence;
    let mut t = String::new();
    let c = crate::words::catalogue(lang);
    let (title_v, title_a) = (&c.sheets.velocities, &c.sheets.accelerations);
    let (worst, bound_word) = (&c.force_plans.worst, &c.sheets.drafting_bound);
    let Some(plans) = &s.plans else { return t };
    let input = input_words(an, s);
    for (title, plan) in [
        (title_v, Some(&plans.velocity)),
        (title_a, plans.acceleration.as_ref()),
    ] {
        let Some(plan) = plan else { continue };
        let position = &c.sheets.position;
        let _ = writeln!(t, "\n{title}, {position} {}, {input}", super::position_number(an, i));
        for k in 0..plan.steps.len() {
            let _ = writeln!(t, "{:>3}. {}", k + 1, sentence(plan, k, lang));
        }
        let mm = &c.force_plans.mm;
        let _ = writeln!(
            t,
            "     {worst}: {}°; δ = {} {mm}",
            num(plan.worst_angle_deg()),
            num(plan.delta)
        );
        for q in &plan.measured {
            let _ = writeln!(
                t,
                "     {} = {} ± {} ({bound_word})",
                q.quantity,
                num(q.value),
                num(q.bound)
            );
        }
    }
    t += &super::force_steps::force_steps(an, s, i, &input, lang);
    // Every number in the language's decimal mark (a comma in uk and ru).
    crate::words::numbers::decimals(&t, lang)
}
