//! The force analysis in words (`solve --steps` with a `dynamics` scene):
//! the force plans group by group (their sentences are
//! `crate::words::force_plans`'), then Zhukovsky's lever of every input as
//! its sheet's table and caption say it.

use crate::kinematics::solve::Analysis;
use crate::kinetostatics::lever::Lever;
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
    let _ = writeln!(t, "\n{}, {} {}, {input}", w.title, w.position, k + 1);
    for plan in &fp.plans {
        force_plans::plan_words(an, loads, plan, lang, &mut t);
    }
    lever_words(an, s, loads, lang, &mut t);
    t
}

/// A decimal comma between digits (the sheets' Ukrainian and Russian
/// numbers) as the steps' decimal point, so that one text writes one way.
fn points(s: &str) -> String {
    let c: Vec<char> = s.chars().collect();
    (0..c.len())
        .map(|i| {
            let digit = |j: Option<&char>| j.is_some_and(|c| c.is_ascii_digit());
            if c[i] == ',' && i > 0 && digit(c.get(i - 1)) && digit(c.get(i + 1)) {
                '.'
            } else {
                c[i]
            }
        })
        .collect()
}

/// Zhukovsky's lever of every input: each force's arm on the turned plan
/// and its moment about the pole, then ΣM_p = 0 solved for the balancing
/// force and moment (the lever sheet's table and caption, in words).
fn lever_words(an: &Analysis, s: &Solved, loads: &[Load], lang: Lang, t: &mut String) {
    let head = &crate::words::catalogue(lang).lever.title;
    for (_, caption, items) in lever_lines(an, s, loads, lang) {
        let _ = writeln!(t, "  {head}: {caption}.");
        for (n, item) in items.iter().enumerate() {
            let _ = writeln!(t, "{:>5}. {item}.", n + 1);
        }
    }
}

/// The levers of position `s` (one per input) as `solve --steps` says
/// them: each lever, its caption's first line (the scales) and its items
/// (every force's arm and moment, ΣM_p = 0 solved, the balancing value),
/// without their full stops; numbers with the decimal point (the caller
/// writes them in the language's mark). Empty where no lever is built.
pub fn lever_lines(
    an: &Analysis,
    s: &Solved,
    loads: &[Load],
    lang: Lang,
) -> Vec<(Lever, String, Vec<String>)> {
    use crate::kinematics::construction::Naming;
    use crate::presentation::drawing::lever as sheet;
    let Ok(levers) = crate::kinetostatics::lever::levers(an, s, loads, Naming::Full) else {
        return Vec::new();
    };
    let w = &crate::words::catalogue(lang).lever;
    let units = &crate::words::catalogue(lang).force_plans;
    let arm = &w.arm;
    let mut out = Vec::new();
    for l in levers {
        let mu_f = sheet::force_scale(&l);
        let caption = sheet::caption(an, &l, mu_f, lang);
        let mut items = Vec::new();
        for row in &sheet::table(an, &l, lang).rows {
            let row: Vec<String> = row.iter().map(|c| points(c)).collect();
            items.push(format!(
                "{} = {} {}, {arm} h = {} {}: {}·h = {} {}",
                row[0],
                row[1],
                units.newton,
                row[2],
                units.mm,
                row[0].split(' ').next().unwrap_or(""),
                row[3],
                units.newton_millimetre,
            ));
        }
        items.extend(caption[1..].iter().map(|line| points(line)));
        let head = points(&caption[0]);
        out.push((l, head, items));
    }
    out
}
