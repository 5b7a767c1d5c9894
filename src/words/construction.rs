//! Lecture-style sentences for the construction steps, in English,
//! Ukrainian and Russian. The mathematics (names of points, vectors,
//! numbers) is the same in every language; only the words change: each
//! language is one `Catalogue` of phrases with named blanks (`{pole}`),
//! filled by one rendering path.

use super::catalogue::{ConstructionPhrases as Phrases, fill};
use crate::format::num;
use crate::kinematics::construction::{Dir, Op, Plan, PlanKind, PlanLine, Why};

pub use crate::lang::Lang;

/// The construction's phrases in `lang`.
pub(super) fn words(lang: Lang) -> &'static Phrases {
    &super::catalogue::catalogue(lang).construction
}


/// A direction in words: `⊥ AB`, `∥ the guide of link 3` …
pub(super) fn dir(w: &Phrases, d: &Dir) -> String {
    match d {
        Dir::Perp(seg) => format!("⊥ {seg}"),
        Dir::Along(seg) => format!("∥ {seg}"),
        Dir::Toward(p, q) => fill(&w.toward, &[("p", p), ("q", q)]),
        Dir::Guide(link) => fill(&w.guide, &[("link", link)]),
        Dir::Turned(v, r) => fill(&w.turned, &[("v", v), ("w", r)]),
        Dir::PerpSense(seg, r) => fill(&w.perp_sense, &[("seg", seg), ("w", r)]),
    }
}

fn sense(w: &Phrases, x: f64) -> &str {
    if x > 0.0 {
        &w.sense[0]
    } else if x < 0.0 {
        &w.sense[1]
    } else {
        &w.sense[2]
    }
}

/// The sentence of step `i` of `plan`.
pub fn sentence(plan: &Plan, i: usize, l: Lang) -> String {
    let w = words(l);
    let (unit, rate_unit, mu) = match plan.kind {
        PlanKind::Velocity => (&w.unit[0], &w.rate_unit[0], "μ_v"),
        PlanKind::Acceleration => (&w.unit[1], &w.rate_unit[1], "μ_a"),
    };
    let s = Speaker {
        w,
        plan,
        unit,
        rate_unit,
        mu,
        scale: num(plan.mu),
    };
    // In the language's decimal mark (a comma in uk and ru).
    let text = match &plan.steps[i].op {
        Op::Pole { fixed } => s.pole(fixed),
        Op::LayOff {
            from,
            to,
            what,
            value,
            dir: d,
        } => s.lay_off((*from, *to), what, *value, d),
        Op::Intersect {
            lines,
            out,
            sin_angle,
        } => s.intersect(lines, *out, *sin_angle),
        Op::Similar {
            a,
            b,
            out,
            figure,
            link,
        } => fill(
            &w.similar,
            &[
                ("a", &s.p(*a)),
                ("b", &s.p(*b)),
                ("out", &s.p(*out)),
                ("plan_fig", &format!("{}{}{}", s.p(*a), s.p(*b), s.p(*out))),
                ("fig", &figure.concat()),
                ("link", link),
            ],
        ),
        Op::Divide {
            a,
            b,
            out,
            figure,
            ratio,
        } => fill(
            &w.divide,
            &[
                ("a", &s.p(*a)),
                ("b", &s.p(*b)),
                ("out", &s.p(*out)),
                ("x", &figure[2]),
                ("f0", &figure[0]),
                ("f1", &figure[1]),
                ("ratio", &num(*ratio)),
            ],
        ),
        Op::Coincide { out, with, why } => {
            let why = match why {
                Why::Fixed => w.fixed.to_string(),
                Why::Translates(k) => fill(&w.translates, &[("link", k)]),
            };
            fill(
                &w.coincide,
                &[("out", &s.p(*out)), ("with", &s.p(*with)), ("why", &why)],
            )
        }
        Op::Measure {
            from,
            to,
            quantity,
            value,
            length,
            rate,
        } => s.measure((*from, *to), quantity, *value, *length, rate.as_ref()),
        Op::Same {
            link,
            from_link,
            what,
        } => fill(
            &w.same,
            &[("what", what), ("link", link), ("from", from_link)],
        ),
        Op::Equation { text } => fill(&w.equations, &[("text", text)]),
    };
    super::numbers::decimals(&text, l)
}

/// What a plan's sentences share: the language's phrases, the plan, its
/// units and its scale as written.
struct Speaker<'a> {
    w: &'static Phrases,
    plan: &'a Plan,
    unit: &'static str,
    rate_unit: &'static str,
    mu: &'static str,
    scale: String,
}

impl Speaker<'_> {
    /// A plan point's name.
    fn p(&self, k: usize) -> String {
        self.plan.points[k].name()
    }

    /// A segment's length on the plan, mm, as written.
    fn between(&self, from: usize, to: usize) -> String {
        num((self.plan.points[to].at - self.plan.points[from].at).hypot())
    }

    fn pole(&self, fixed: &[String]) -> String {
        let fixed = if fixed.is_empty() {
            String::new()
        } else {
            format!(" ({})", fixed.join(", "))
        };
        fill(
            &self.w.pole,
            &[
                ("pole", &self.p(0)),
                ("fixed", &fixed),
                ("mu", self.mu),
                ("scale", &self.scale),
                ("unit", self.unit),
            ],
        )
    }

    fn lay_off(&self, (from, to): (usize, usize), what: &str, value: f64, d: &Dir) -> String {
        fill(
            &self.w.lay_off,
            &[
                ("from", &self.p(from)),
                ("to", &self.p(to)),
                ("what", what),
                ("mu", self.mu),
                ("value", &num(value)),
                ("scale", &self.scale),
                // The formula's result, the length the vector must have
                // (in a replay the point may be drawn elsewhere: the
                // report puts the student's length beside it).
                ("mm", &num(value / self.plan.mu)),
                ("dir", &dir(self.w, d)),
            ],
        )
    }

    fn intersect(&self, lines: &[PlanLine; 2], out: usize, sin_angle: f64) -> String {
        let ang = sin_angle.clamp(-1.0, 1.0).asin().to_degrees();
        let (a, b) = (&lines[0], &lines[1]);
        fill(
            &self.w.intersect,
            &[
                ("a", &self.p(a.through)),
                ("dir_a", &dir(self.w, &a.dir)),
                ("b", &self.p(b.through)),
                ("dir_b", &dir(self.w, &b.dir)),
                ("out", &self.p(out)),
                ("angle", &num(ang)),
            ],
        )
    }

    /// A measurement: the value, and with a link's `length` and the
    /// `rate` it gives ((name, value, (j, x)): ω or ε of link j by its
    /// point x), the rate and its sense.
    fn measure(
        &self,
        (from, to): (usize, usize),
        quantity: &str,
        value: f64,
        length: Option<f64>,
        rate: Option<&(String, f64, (String, String))>,
    ) -> String {
        let w = self.w;
        let seg = format!("{}{}", self.p(from), self.p(to));
        let base = fill(
            &w.measure,
            &[
                ("seg", &seg),
                ("mm", &self.between(from, to)),
                ("quantity", quantity),
                ("mu", self.mu),
                ("value", &num(value)),
                ("unit", self.unit),
            ],
        );
        let (Some((name, r, (j, x))), Some(len)) = (rate, length) else {
            return format!("{base}.");
        };
        let value = format!(
            "{base}; {name} = {quantity}/l_{j}{x} = {} / {} = {} {}",
            num(value),
            num(len),
            num(r.abs()),
            self.rate_unit
        );
        // A rate that prints as 0 has no sense to tell.
        if *r == 0.0 || num(r.abs()) == "0" {
            return format!("{value}.");
        }
        let args = [("seg", &*seg), ("x", x), ("j", j), ("sense", sense(w, *r))];
        let why = fill(&w.turns, &args);
        format!("{value}, {} ({why}).", sense(w, *r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every blank of every language's phrases is one the rendering fills.
    #[test]
    fn catalogues_fill() {
        for lang in Lang::ALL {
            let c = words(lang);
            let phrases = [
                &c.toward,
                &c.guide,
                &c.turned,
                &c.perp_sense,
                &c.pole,
                &c.lay_off,
                &c.intersect,
                &c.similar,
                &c.divide,
                &c.coincide,
                &c.translates,
                &c.measure,
                &c.turns,
                &c.same,
                &c.equations,
            ];
            let names = [
                "p", "q", "link", "v", "w", "seg", "pole", "fixed", "mu", "scale", "unit", "from",
                "to", "what", "value", "mm", "dir", "a", "b", "dir_a", "dir_b", "out", "angle",
                "plan_fig", "fig", "x", "f0", "f1", "ratio", "with", "why", "quantity", "j",
                "sense", "text",
            ];
            let args: Vec<(&str, &str)> = names.iter().map(|n| (*n, "·")).collect();
            for ph in phrases {
                assert!(!fill(ph, &args).contains(['{', '}']), "{ph}");
            }
        }
        assert_eq!(
            fill("{a}{b} = {a}", &[("a", "{b}"), ("b", "x")]),
            "{b}x = {b}"
        );
    }
}
