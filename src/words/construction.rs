//! Lecture-style sentences for the construction steps, in English,
//! Ukrainian and Russian. The mathematics (names of points, vectors,
//! numbers) is the same in every language; only the words change: each
//! language is one `Catalogue` of phrases with named blanks (`{pole}`),
//! filled by one rendering path.

use super::fill;
use crate::format::num;
use crate::kinematics::construction::{Dir, Op, Plan, PlanKind, PlanLine, Why};

pub use crate::lang::Lang;

impl Lang {
    fn words(self) -> &'static Catalogue {
        match self {
            Lang::En => &EN,
            Lang::Uk => &UK,
            Lang::Ru => &RU,
        }
    }
}

/// The phrases of one language. Blanks in braces are filled by [`fill`].
struct Catalogue {
    /// Units of the velocity and the acceleration plan: values, rates.
    unit: [&'static str; 2],
    rate_unit: [&'static str; 2],
    /// Senses of a rate: positive, negative, zero.
    sense: [&'static str; 3],
    /// Directions: `{p}`, `{q}`; `{link}`; `{v}`, `{w}`; `{seg}`, `{w}`.
    toward: &'static str,
    guide: &'static str,
    turned: &'static str,
    perp_sense: &'static str,
    /// Steps.
    pole: &'static str,
    lay_off: &'static str,
    intersect: &'static str,
    similar: &'static str,
    divide: &'static str,
    coincide: &'static str,
    /// Why a point coincides: at the pole; `{link}` translates.
    fixed: &'static str,
    translates: &'static str,
    measure: &'static str,
    /// How a relative segment turns its link.
    turns: &'static str,
    same: &'static str,
    equations: &'static str,
}

static EN: Catalogue = Catalogue {
    unit: ["m/s", "m/s²"],
    rate_unit: ["rad/s", "rad/s²"],
    sense: ["counter-clockwise", "clockwise", "zero"],
    toward: "∥ {p}{q}, from {p} toward {q}",
    guide: "∥ the guide of link {link}",
    turned: "{v} turned by 90° in the sense of {w}",
    perp_sense: "⊥ {seg} in the sense of {w}",
    pole: "Choose the pole {pole}: the points of the frame lie there{fixed}; {mu} = {scale} ({unit})/mm.",
    lay_off: "From {from} lay off {from}{to} = {what}/{mu} = {value} / {scale} = {mm} mm, {dir}.",
    intersect: "Through {a} draw a line {dir_a}; through {b} a line {dir_b}; they meet at {out} (at {angle}°).",
    similar: "By the similarity theorem build on {a}{b} the triangle {plan_fig} similar to {fig} of link {link}, the letters in the same order: point {out}.",
    divide: "Divide {a}{b} as {x} divides {f0}{f1} ({a}{out} = {ratio} · {a}{b}): point {out}.",
    coincide: "Point {out} coincides with {with}: {why}.",
    fixed: "a point of the frame lies at the pole",
    translates: "link {link} translates",
    measure: "Measure {seg} = {mm} mm: {quantity} = {seg}·{mu} = {value} {unit}",
    turns: "segment {seg} carried to {x} turns {j}{x} about {j} {sense}",
    same: "{what}{link} = {what}{from}: links {link} and {from} form a prismatic pair and turn together.",
    equations: "Vector equations: {text}.",
};

static UK: Catalogue = Catalogue {
    unit: ["м/с", "м/с²"],
    rate_unit: ["рад/с", "рад/с²"],
    sense: [
        "проти годинникової стрілки",
        "за годинниковою стрілкою",
        "нуль",
    ],
    toward: "∥ {p}{q}, від {p} до {q}",
    guide: "∥ напрямній ланки {link}",
    turned: "{v}, повернутий на 90° у напрямку {w}",
    perp_sense: "⊥ {seg} у напрямку {w}",
    pole: "Обираємо полюс {pole}: у ньому лежать точки стояка{fixed}; {mu} = {scale} ({unit})/мм.",
    lay_off: "Від {from} відкладаємо {from}{to} = {what}/{mu} = {value} / {scale} = {mm} мм, {dir}.",
    intersect: "Через {a} проводимо пряму {dir_a}; через {b} — пряму {dir_b}; вони перетинаються в точці {out} (під кутом {angle}°).",
    similar: "За теоремою подібності будуємо на {a}{b} трикутник {plan_fig}, подібний до {fig} ланки {link}, з тим самим порядком літер: точка {out}.",
    divide: "Ділимо {a}{b} так, як {x} ділить {f0}{f1} ({a}{out} = {ratio} · {a}{b}): точка {out}.",
    coincide: "Точка {out} збігається з {with}: {why}.",
    fixed: "точки стояка лежать у полюсі",
    translates: "ланка {link} рухається поступально",
    measure: "Вимірюємо {seg} = {mm} мм: {quantity} = {seg}·{mu} = {value} {unit}",
    turns: "відрізок {seg}, перенесений у точку {x}, повертає {j}{x} навколо {j} {sense}",
    same: "{what}{link} = {what}{from}: ланки {link} і {from} утворюють поступальну пару й обертаються разом.",
    equations: "Векторні рівняння: {text}.",
};

static RU: Catalogue = Catalogue {
    unit: ["м/с", "м/с²"],
    rate_unit: ["рад/с", "рад/с²"],
    sense: ["против часовой стрелки", "по часовой стрелке", "ноль"],
    toward: "∥ {p}{q}, от {p} к {q}",
    guide: "∥ направляющей звена {link}",
    turned: "{v}, повёрнутый на 90° в сторону {w}",
    perp_sense: "⊥ {seg} в сторону {w}",
    pole: "Выбираем полюс {pole}: в нём лежат точки стойки{fixed}; {mu} = {scale} ({unit})/мм.",
    lay_off: "От {from} откладываем {from}{to} = {what}/{mu} = {value} / {scale} = {mm} мм, {dir}.",
    intersect: "Через {a} проводим прямую {dir_a}; через {b} — прямую {dir_b}; они пересекаются в точке {out} (под углом {angle}°).",
    similar: "По теореме подобия строим на {a}{b} треугольник {plan_fig}, подобный {fig} звена {link}, с тем же порядком букв: точка {out}.",
    divide: "Делим {a}{b} так, как {x} делит {f0}{f1} ({a}{out} = {ratio} · {a}{b}): точка {out}.",
    coincide: "Точка {out} совпадает с {with}: {why}.",
    fixed: "точки стойки лежат в полюсе",
    translates: "звено {link} движется поступательно",
    measure: "Измеряем {seg} = {mm} мм: {quantity} = {seg}·{mu} = {value} {unit}",
    turns: "отрезок {seg}, перенесённый в точку {x}, поворачивает {j}{x} вокруг {j} {sense}",
    same: "{what}{link} = {what}{from}: звенья {link} и {from} образуют поступательную пару и вращаются вместе.",
    equations: "Векторные уравнения: {text}.",
};

fn dir(w: &Catalogue, d: &Dir) -> String {
    match d {
        Dir::Perp(seg) => format!("⊥ {seg}"),
        Dir::Along(seg) => format!("∥ {seg}"),
        Dir::Toward(p, q) => fill(w.toward, &[("p", p), ("q", q)]),
        Dir::Guide(link) => fill(w.guide, &[("link", link)]),
        Dir::Turned(v, r) => fill(w.turned, &[("v", v), ("w", r)]),
        Dir::PerpSense(seg, r) => fill(w.perp_sense, &[("seg", seg), ("w", r)]),
    }
}

fn sense(w: &Catalogue, x: f64) -> &'static str {
    if x > 0.0 {
        w.sense[0]
    } else if x < 0.0 {
        w.sense[1]
    } else {
        w.sense[2]
    }
}

/// The sentence of step `i` of `plan`.
pub fn sentence(plan: &Plan, i: usize, l: Lang) -> String {
    let w = l.words();
    let (unit, rate_unit, mu) = match plan.kind {
        PlanKind::Velocity => (w.unit[0], w.rate_unit[0], "μ_v"),
        PlanKind::Acceleration => (w.unit[1], w.rate_unit[1], "μ_a"),
    };
    let s = Speaker {
        w,
        plan,
        unit,
        rate_unit,
        mu,
        scale: num(plan.mu),
    };
    match &plan.steps[i].op {
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
            w.similar,
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
            w.divide,
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
                Why::Translates(k) => fill(w.translates, &[("link", k)]),
            };
            fill(
                w.coincide,
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
            w.same,
            &[("what", what), ("link", link), ("from", from_link)],
        ),
        Op::Equation { text } => fill(w.equations, &[("text", text)]),
    }
}

/// What a plan's sentences share: the language's phrases, the plan, its
/// units and its scale as written.
struct Speaker<'a> {
    w: &'static Catalogue,
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
            self.w.pole,
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
            self.w.lay_off,
            &[
                ("from", &self.p(from)),
                ("to", &self.p(to)),
                ("what", what),
                ("mu", self.mu),
                ("value", &num(value)),
                ("scale", &self.scale),
                ("mm", &self.between(from, to)),
                ("dir", &dir(self.w, d)),
            ],
        )
    }

    fn intersect(&self, lines: &[PlanLine; 2], out: usize, sin_angle: f64) -> String {
        let ang = sin_angle.clamp(-1.0, 1.0).asin().to_degrees();
        let (a, b) = (&lines[0], &lines[1]);
        fill(
            self.w.intersect,
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
            w.measure,
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
        if *r == 0.0 {
            return format!("{value}.");
        }
        let args = [("seg", &*seg), ("x", x), ("j", j), ("sense", sense(w, *r))];
        let why = fill(w.turns, &args);
        format!("{value}, {} ({why}).", sense(w, *r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every blank of every language's phrases is one the rendering fills.
    #[test]
    fn catalogues_fill() {
        for c in [&EN, &UK, &RU] {
            let phrases = [
                c.toward,
                c.guide,
                c.turned,
                c.perp_sense,
                c.pole,
                c.lay_off,
                c.intersect,
                c.similar,
                c.divide,
                c.coincide,
                c.translates,
                c.measure,
                c.turns,
                c.same,
                c.equations,
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
