//! The force plans in words, step by step (`solve --steps` with a
//! `dynamics` scene): each group cut out with its loads, the moment
//! equations and projections that give the components found first, the
//! vectors laid off at μ_F, the two lines that close the polygon, the
//! reactions read off it, the couples of the guides and the balancing
//! moment. Each language is one [`Catalogue`] of phrases with named
//! blanks, filled by one path.

use super::catalogue::{ForcePlanPhrases as Phrases, fill};
use super::forces::force_name;
use crate::format::num;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep};
use crate::kinetostatics::loads::Load;
use crate::lang::Lang;
use crate::model::structure::AssurGroup;
use kurbo::Vec2;
use std::fmt::Write as _;


/// The phrases of `lang`.
pub fn words(lang: Lang) -> &'static Phrases {
    &super::catalogue::catalogue(lang).force_plans
}

/// A direction as an angle, degrees in [0, 360).
fn angle(v: Vec2) -> String {
    let a = num(v.y.atan2(v.x).to_degrees().rem_euclid(360.0));
    // A direction a hair below 0° rounds to 360°: it is 0°.
    if a == "360" {
        "0°".into()
    } else {
        format!("{a}°")
    }
}

/// "links 4, 5" in the language.
fn links_words(an: &Analysis, links: &[usize], w: &Phrases) -> String {
    let ids: Vec<&str> = links.iter().map(|&l| an.mech.link_id(l)).collect();
    let word = &w.links[usize::from(ids.len() != 1)];
    format!("{word} {}", ids.join(", "))
}

/// The point a moment is taken about: its name, else (a class III
/// group's Assur point, where two leashes' axes meet) Σ and its
/// coordinates, separated by "; " where the decimal mark is a comma.
fn about_words(an: &Analysis, step_about: (kurbo::Point, Option<usize>), lang: Lang) -> String {
    match step_about.1 {
        Some(p) => an.mech.point_name(p).to_string(),
        None => {
            let comma = super::catalogue::catalogue(lang).units.decimal == ",";
            let sep = if comma { "; " } else { ", " };
            let (x, y) = (num(step_about.0.x), num(step_about.0.y));
            format!("Σ({x}{sep}{y})")
        }
    }
}

/// A force plan (of a group, or of the input link) in words, its steps
/// numbered, appended to `t`.
pub fn plan_words(an: &Analysis, loads: &[Load], plan: &ForcePlan, lang: Lang, t: &mut String) {
    let _ = writeln!(t, "  {}", plan_head(an, plan, lang));
    for (i, s) in plan_sentences(an, loads, plan, lang).iter().enumerate() {
        let _ = writeln!(t, "{:>5}. {s}", i + 1);
    }
    if let Some(worst) = plan_worst(plan, lang) {
        let _ = writeln!(t, "       {worst}");
    }
}

/// A force plan's heading: what is cut out, and its μ_F ("Group RRP of
/// links 4, 5, …; μ_F = 2 N/mm.").
pub fn plan_head(an: &Analysis, plan: &ForcePlan, lang: Lang) -> String {
    let w = words(lang);
    let head = match plan.group {
        Some(g) => {
            let formula = match &an.structure.groups[g] {
                AssurGroup::Dyad(d) => d.kind.name(),
                AssurGroup::Triad(_) => "III",
            };
            let links = links_words(an, &plan.links, w);
            fill(&w.group, &[("formula", formula), ("links", &links)])
        }
        None => {
            let ids: Vec<&str> = plan.links.iter().map(|&l| an.mech.link_id(l)).collect();
            fill(&w.input_link, &[("ids", &ids.join(", "))])
        }
    };
    format!("{head}; μ_F = {} {}.", num(plan.mu), w.per_mm)
}

/// A force plan's steps, one sentence each, in order.
pub fn plan_sentences(
    an: &Analysis,
    loads: &[Load],
    plan: &ForcePlan,
    lang: Lang,
) -> Vec<String> {
    let step = Step {
        an,
        loads,
        plan,
        lang,
        w: words(lang),
    };
    plan.steps.iter().map(|s| step.words(s)).collect()
}

/// The worst intersection angle of a plan and its drafting bound δ, where
/// two lines met at less than a right angle.
pub fn plan_worst(plan: &ForcePlan, lang: Lang) -> Option<String> {
    let w = words(lang);
    let deg = || num(plan.worst_sin.asin().to_degrees());
    (plan.worst_sin < 1.0).then(|| format!("{}: {}°; δ = {} {}", w.worst, deg(), num(plan.delta), w.mm))
}

/// What a plan's steps share in words.
struct Step<'a> {
    an: &'a Analysis,
    loads: &'a [Load],
    plan: &'a ForcePlan,
    lang: Lang,
    w: &'static Phrases,
}

impl Step<'_> {
    fn name(&self, f: Force) -> String {
        force_name(&self.an.mech, self.loads, f, self.lang)
    }

    /// One step of the plan in words.
    fn words(&self, step: &ForceStep) -> String {
        let (w, plan) = (self.w, self.plan);
        let n = &w.newton[..];
        match step {
            ForceStep::Moment {
                links,
                about,
                about_name,
                force,
                value,
            } => {
                let at = about_words(self.an, (*about, *about_name), self.lang);
                let what = links_words(self.an, links, w);
                let (f, value) = (self.name(*force), num(*value));
                let args = [("at", &*at), ("what", &what), ("f", &f), ("value", &value), ("n", n)];
                fill(&w.moment, &args)
            }
            ForceStep::Projection {
                links,
                force,
                value,
            } => {
                let what = links_words(self.an, links, w);
                let (f, value) = (self.name(*force), num(*value));
                fill(
                    &w.projection,
                    &[("what", &what), ("f", &f), ("value", &value), ("n", n)],
                )
            }
            ForceStep::LayOff(v) => {
                let d = plan.vectors[*v];
                let len = num((plan.points[d.to] - plan.points[d.from]).hypot());
                let (f, val, dir) = (self.name(d.force), num(d.value.hypot()), angle(d.value));
                let (from, to) = (d.from.to_string(), d.to.to_string());
                fill(
                    &w.lay_off,
                    &[
                        ("from", &from),
                        ("f", &f),
                        ("val", &val),
                        ("n", n),
                        ("len", &len),
                        ("mm", &w.mm),
                        ("dir", &dir),
                        ("to", &to),
                    ],
                )
            }
            ForceStep::Line(l) => {
                let l = plan.lines[*l];
                let (f, dir, through) = (self.name(l.force), angle(l.dir), l.through.to_string());
                fill(&w.line, &[("through", &through), ("f", &f), ("dir", &dir)])
            }
            ForceStep::Intersect { out, sin, .. } => {
                let deg = num(sin.clamp(-1.0, 1.0).asin().to_degrees());
                fill(&w.intersect, &[("out", &out.to_string()), ("deg", &deg)])
            }
            ForceStep::Measure(v) => self.measure(*v),
            ForceStep::Couple {
                links,
                force,
                value,
                at,
            } => {
                let what = links_words(self.an, links, w);
                let (f, value) = (self.name(*force), num(*value));
                // Where the guide's force acts, when it is not zero.
                let p = at.map_or(String::new(), |p| format!("({}, {})", num(p.x), num(p.y)));
                let phrase = if at.is_some() { &w.couple_at } else { &w.couple_alone };
                let nm = &w.newton_metre;
                fill(
                    phrase,
                    &[("what", &what), ("value", &value), ("nm", nm), ("f", &f), ("p", &p)],
                )
            }
            ForceStep::Balancing { input, value } => self.balancing(*input, *value),
        }
    }

    /// A reaction measured off the plan, with its bound.
    fn measure(&self, v: usize) -> String {
        let (w, plan) = (self.w, self.plan);
        let d = plan.vectors[v];
        let len = (plan.points[d.to] - plan.points[d.from]).hypot();
        let bound = (plan.err[d.from] + plan.err[d.to] + plan.delta) * plan.mu;
        let (f, val, dir) = (self.name(d.force), num(d.value.hypot()), angle(d.value));
        let (a, b, l) = (d.from.to_string(), d.to.to_string(), num(len));
        let (mu, bound) = (num(plan.mu), num(bound));
        fill(
            &w.measure,
            &[
                ("a", &a),
                ("b", &b),
                ("l", &l),
                ("mm", &w.mm),
                ("f", &f),
                ("mu", &mu),
                ("val", &val),
                ("bound", &bound),
                ("n", &w.newton),
                ("dir", &dir),
            ],
        )
    }

    /// The balancing moment (force) of input `input` from its link's
    /// equilibrium.
    fn balancing(&self, input: usize, value: f64) -> String {
        let (w, m) = (self.w, &self.an.mech);
        let spec = m.scene.input_at(input);
        let crank = spec.is_crank();
        let id = m.link_id(spec.link());
        let b = format!("{}_{}", if crank { "M" } else { "F" }, w.balancing_sub);
        let (unit, sense) = if crank {
            let sense = &w.sense[if value >= 0.0 { 0 } else { 1 }];
            (&w.newton_metre[..], format!(", {sense}"))
        } else {
            (&w.newton[..], String::new())
        };
        fill(
            &w.balancing,
            &[
                ("id", id),
                ("kind", &w.kind[usize::from(!crank)]),
                ("b", &b),
                ("value", &num(value)),
                ("unit", unit),
                ("sense", &sense),
            ],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every blank of every language's phrases is one the rendering fills.
    #[test]
    fn catalogues_fill() {
        let names = [
            "formula", "links", "ids", "at", "what", "f", "value", "n", "from", "val", "len", "mm",
            "dir", "to", "through", "out", "deg", "a", "b", "l", "mu", "bound", "nm", "p", "id",
            "kind", "unit", "sense",
        ];
        let args: Vec<(&str, &str)> = names.iter().map(|n| (*n, "·")).collect();
        for lang in Lang::ALL {
            let c = words(lang);
            for phrase in [
                &c.group,
                &c.input_link,
                &c.moment,
                &c.projection,
                &c.lay_off,
                &c.line,
                &c.intersect,
                &c.measure,
                &c.couple_at,
                &c.couple_alone,
                &c.balancing,
            ] {
                let filled = fill(phrase, &args);
                assert!(!filled.contains(['{', '}']), "{lang:?}: {phrase}");
            }
        }
    }
}
