//! The force analysis in words (`solve --steps` with a `dynamics` scene):
//! the force plans group by group (their sentences are
//! `crate::words::force_plans`'), then Zhukovsky's lever of every input as
//! its sheet's table and caption say it.

use crate::kinematics::solve::Analysis;
use crate::kinetostatics::loads::Load;
use crate::lang::Lang;
use crate::pipeline::Solved;
use crate::words::force_plans;
use std::fmt::Write as _;

/// The force analysis of solved position `s` (the `k`-th) in words; empty
/// without force plans.
pub fn force_steps(an: &Analysis, s: &Solved, k: usize, input: &str, lang: Lang) -> String {
    let Some(fp) = s.dynamics.as_ref().and_then(|d| d.force_plans.as_ref()) else {
        return String::new();
    };
    let loads = s.dynamics.as_ref().map_or(&[][..], |d| &d.loads[..]);
    let mut t = String::new();
    let w = force_plans::words(lang);
    let _ = writeln!(t, "\n{}, {} {}, {input}", w.title, w.position, super::position_number(an, k));
    for plan in &fp.plans {
        force_plans::plan_words(an, loads, plan, lang, &mut t);
    }
    lever_words(an, s, loads, lang, &mut t);
    t
}

/// Zhukovsky's lever of every input: each force's arm on the turned plan
/// and its moment about the pole, then ΣM_p = 0 solved for the balancing
/// force and moment (the lever sheet's table and caption, in words).
fn lever_words(an: &Analysis, s: &Solved, loads: &[Load], lang: Lang, t: &mut String) {
    let head = &crate::words::catalogue(lang).lever.title;
    for (_, caption, items) in crate::presentation::drawing::lever::lines(an, s, loads, lang) {
        let _ = writeln!(t, "  {head}: {caption}.");
        for (n, item) in items.iter().enumerate() {
            let _ = writeln!(t, "{:>5}. {item}.", n + 1);
        }
    }
}
