//! Lecture-style sentences for the construction steps, in English,
//! Ukrainian and Russian. The mathematics (names of points, vectors,
//! numbers) is the same in every language; only the words change.

use super::{Dir, Op, Plan, PlanKind, Why};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lang {
    En,
    Uk,
    Ru,
}

impl Lang {
    pub fn parse(s: &str) -> Option<Lang> {
        match s {
            "en" => Some(Lang::En),
            "uk" => Some(Lang::Uk),
            "ru" => Some(Lang::Ru),
            _ => None,
        }
    }
}

fn pick(l: Lang, en: &str, uk: &str, ru: &str) -> String {
    match l {
        Lang::En => en,
        Lang::Uk => uk,
        Lang::Ru => ru,
    }
    .to_string()
}

/// Numbers as a student writes them: up to 4 significant digits.
pub fn num(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 9) as usize;
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" { "0".into() } else { s }
}

fn dir(l: Lang, d: &Dir) -> String {
    match d {
        Dir::Perp(seg) => format!("⊥ {seg}"),
        Dir::Along(seg) => format!("∥ {seg}"),
        Dir::Toward(p, q) => match l {
            Lang::En => format!("∥ {p}{q}, from {p} toward {q}"),
            Lang::Uk => format!("∥ {p}{q}, від {p} до {q}"),
            Lang::Ru => format!("∥ {p}{q}, от {p} к {q}"),
        },
        Dir::Guide(link) => match l {
            Lang::En => format!("∥ the guide of link {link}"),
            Lang::Uk => format!("∥ напрямній ланки {link}"),
            Lang::Ru => format!("∥ направляющей звена {link}"),
        },
        Dir::Turned(v, w) => match l {
            Lang::En => format!("{v} turned by 90° in the sense of {w}"),
            Lang::Uk => format!("{v}, повернутий на 90° у напрямку {w}"),
            Lang::Ru => format!("{v}, повёрнутый на 90° в сторону {w}"),
        },
        Dir::PerpSense(seg, w) => match l {
            Lang::En => format!("⊥ {seg} in the sense of {w}"),
            Lang::Uk => format!("⊥ {seg} у напрямку {w}"),
            Lang::Ru => format!("⊥ {seg} в сторону {w}"),
        },
    }
}

fn sense(l: Lang, x: f64) -> String {
    if x > 0.0 {
        pick(
            l,
            "counter-clockwise",
            "проти годинникової стрілки",
            "против часовой стрелки",
        )
    } else if x < 0.0 {
        pick(
            l,
            "clockwise",
            "за годинниковою стрілкою",
            "по часовой стрелке",
        )
    } else {
        pick(l, "zero", "нуль", "ноль")
    }
}

/// The sentence of step `i` of `plan`.
pub fn sentence(plan: &Plan, i: usize, l: Lang) -> String {
    let p = |k: usize| plan.points[k].name();
    let step = &plan.steps[i];
    let unit = match (plan.kind, l) {
        (PlanKind::Velocity, Lang::En) => "m/s",
        (PlanKind::Acceleration, Lang::En) => "m/s²",
        (PlanKind::Velocity, _) => "м/с",
        (PlanKind::Acceleration, _) => "м/с²",
    };
    let mu = match plan.kind {
        PlanKind::Velocity => "μ_v",
        PlanKind::Acceleration => "μ_a",
    };
    match &step.op {
        Op::Pole { fixed } => {
            let pole = p(0);
            let fixed = if fixed.is_empty() {
                String::new()
            } else {
                format!(" ({})", fixed.join(", "))
            };
            match l {
                Lang::En => format!(
                    "Choose the pole {pole}: the points of the frame lie there{fixed}; {mu} = {} ({unit})/mm.",
                    num(plan.mu)
                ),
                Lang::Uk => format!(
                    "Обираємо полюс {pole}: у ньому лежать точки стояка{fixed}; {mu} = {} ({unit})/мм.",
                    num(plan.mu)
                ),
                Lang::Ru => format!(
                    "Выбираем полюс {pole}: в нём лежат точки стойки{fixed}; {mu} = {} ({unit})/мм.",
                    num(plan.mu)
                ),
            }
        }
        Op::LayOff {
            from,
            to,
            what,
            value,
            dir: d,
        } => {
            let mm = (plan.points[*to].at - plan.points[*from].at).hypot();
            match l {
                Lang::En => format!(
                    "From {} lay off {}{} = {what}/{mu} = {} / {} = {} mm, {}.",
                    p(*from),
                    p(*from),
                    p(*to),
                    num(*value),
                    num(plan.mu),
                    num(mm),
                    dir(l, d)
                ),
                Lang::Uk => format!(
                    "Від {} відкладаємо {}{} = {what}/{mu} = {} / {} = {} мм, {}.",
                    p(*from),
                    p(*from),
                    p(*to),
                    num(*value),
                    num(plan.mu),
                    num(mm),
                    dir(l, d)
                ),
                Lang::Ru => format!(
                    "От {} откладываем {}{} = {what}/{mu} = {} / {} = {} мм, {}.",
                    p(*from),
                    p(*from),
                    p(*to),
                    num(*value),
                    num(plan.mu),
                    num(mm),
                    dir(l, d)
                ),
            }
        }
        Op::Intersect {
            lines,
            out,
            sin_angle,
        } => {
            let ang = sin_angle.clamp(-1.0, 1.0).asin().to_degrees();
            let (a, b) = (&lines[0], &lines[1]);
            match l {
                Lang::En => format!(
                    "Through {} draw a line {}; through {} a line {}; they meet at {} (at {}°).",
                    p(a.through),
                    dir(l, &a.dir),
                    p(b.through),
                    dir(l, &b.dir),
                    p(*out),
                    num(ang)
                ),
                Lang::Uk => format!(
                    "Через {} проводимо пряму {}; через {} — пряму {}; вони перетинаються в точці {} (під кутом {}°).",
                    p(a.through),
                    dir(l, &a.dir),
                    p(b.through),
                    dir(l, &b.dir),
                    p(*out),
                    num(ang)
                ),
                Lang::Ru => format!(
                    "Через {} проводим прямую {}; через {} — прямую {}; они пересекаются в точке {} (под углом {}°).",
                    p(a.through),
                    dir(l, &a.dir),
                    p(b.through),
                    dir(l, &b.dir),
                    p(*out),
                    num(ang)
                ),
            }
        }
        Op::Similar {
            a,
            b,
            out,
            figure,
            link,
        } => {
            let fig = format!("{}{}{}", figure[0], figure[1], figure[2]);
            let plan_fig = format!("{}{}{}", p(*a), p(*b), p(*out));
            match l {
                Lang::En => format!(
                    "By the similarity theorem build on {}{} the triangle {plan_fig} similar to {fig} of link {link}, the letters in the same order: point {}.",
                    p(*a),
                    p(*b),
                    p(*out)
                ),
                Lang::Uk => format!(
                    "За теоремою подібності будуємо на {}{} трикутник {plan_fig}, подібний до {fig} ланки {link}, з тим самим порядком літер: точка {}.",
                    p(*a),
                    p(*b),
                    p(*out)
                ),
                Lang::Ru => format!(
                    "По теореме подобия строим на {}{} треугольник {plan_fig}, подобный {fig} звена {link}, с тем же порядком букв: точка {}.",
                    p(*a),
                    p(*b),
                    p(*out)
                ),
            }
        }
        Op::Divide {
            a,
            b,
            out,
            figure,
            ratio,
        } => match l {
            Lang::En => format!(
                "Divide {}{} as {} divides {}{} ({}{} = {} · {}{}): point {}.",
                p(*a),
                p(*b),
                figure[2],
                figure[0],
                figure[1],
                p(*a),
                p(*out),
                num(*ratio),
                p(*a),
                p(*b),
                p(*out)
            ),
            Lang::Uk => format!(
                "Ділимо {}{} так, як {} ділить {}{} ({}{} = {} · {}{}): точка {}.",
                p(*a),
                p(*b),
                figure[2],
                figure[0],
                figure[1],
                p(*a),
                p(*out),
                num(*ratio),
                p(*a),
                p(*b),
                p(*out)
            ),
            Lang::Ru => format!(
                "Делим {}{} так, как {} делит {}{} ({}{} = {} · {}{}): точка {}.",
                p(*a),
                p(*b),
                figure[2],
                figure[0],
                figure[1],
                p(*a),
                p(*out),
                num(*ratio),
                p(*a),
                p(*b),
                p(*out)
            ),
        },
        Op::Coincide { out, with, why } => {
            let why = match (why, l) {
                (Why::Fixed, Lang::En) => "a point of the frame lies at the pole".to_string(),
                (Why::Fixed, Lang::Uk) => "точки стояка лежать у полюсі".to_string(),
                (Why::Fixed, Lang::Ru) => "точки стойки лежат в полюсе".to_string(),
                (Why::Translates(k), Lang::En) => format!("link {k} translates"),
                (Why::Translates(k), Lang::Uk) => format!("ланка {k} рухається поступально"),
                (Why::Translates(k), Lang::Ru) => format!("звено {k} движется поступательно"),
            };
            match l {
                Lang::En => format!("Point {} coincides with {}: {why}.", p(*out), p(*with)),
                Lang::Uk => format!("Точка {} збігається з {}: {why}.", p(*out), p(*with)),
                Lang::Ru => format!("Точка {} совпадает с {}: {why}.", p(*out), p(*with)),
            }
        }
        Op::Measure {
            from,
            to,
            quantity,
            value,
            length,
            rate,
        } => {
            let mm = (plan.points[*to].at - plan.points[*from].at).hypot();
            let seg = format!("{}{}", p(*from), p(*to));
            let base = match l {
                Lang::En => format!(
                    "Measure {seg} = {} mm: {quantity} = {seg}·{mu} = {} {unit}",
                    num(mm),
                    num(*value)
                ),
                Lang::Uk => format!(
                    "Вимірюємо {seg} = {} мм: {quantity} = {seg}·{mu} = {} {unit}",
                    num(mm),
                    num(*value)
                ),
                Lang::Ru => format!(
                    "Измеряем {seg} = {} мм: {quantity} = {seg}·{mu} = {} {unit}",
                    num(mm),
                    num(*value)
                ),
            };
            match (rate, length) {
                (Some((name, w, (j, x))), Some(len)) => {
                    let runit = match (plan.kind, l) {
                        (PlanKind::Velocity, Lang::En) => "rad/s",
                        (PlanKind::Acceleration, Lang::En) => "rad/s²",
                        (PlanKind::Velocity, _) => "рад/с",
                        (PlanKind::Acceleration, _) => "рад/с²",
                    };
                    let value = format!(
                        "{base}; {name} = {quantity}/l_{j}{x} = {} / {} = {} {runit}",
                        num(*value),
                        num(*len),
                        num(w.abs())
                    );
                    if *w == 0.0 {
                        return format!("{value}.");
                    }
                    let why = match l {
                        Lang::En => format!(
                            "segment {seg} carried to {x} turns {j}{x} about {j} {}",
                            sense(l, *w)
                        ),
                        Lang::Uk => format!(
                            "відрізок {seg}, перенесений у точку {x}, повертає {j}{x} навколо {j} {}",
                            sense(l, *w)
                        ),
                        Lang::Ru => format!(
                            "отрезок {seg}, перенесённый в точку {x}, поворачивает {j}{x} вокруг {j} {}",
                            sense(l, *w)
                        ),
                    };
                    format!("{value}, {} ({why}).", sense(l, *w))
                }
                _ => format!("{base}."),
            }
        }
        Op::Same {
            link,
            from_link,
            what,
        } => match l {
            Lang::En => format!(
                "{what}{link} = {what}{from_link}: links {link} and {from_link} form a prismatic pair and turn together."
            ),
            Lang::Uk => format!(
                "{what}{link} = {what}{from_link}: ланки {link} і {from_link} утворюють поступальну пару й обертаються разом."
            ),
            Lang::Ru => format!(
                "{what}{link} = {what}{from_link}: звенья {link} и {from_link} образуют поступательную пару и вращаются вместе."
            ),
        },
        Op::Equation { text } => match l {
            Lang::En => format!("Vector equations: {text}."),
            Lang::Uk => format!("Векторні рівняння: {text}."),
            Lang::Ru => format!("Векторные уравнения: {text}."),
        },
    }
}
