//! The force plans in words, step by step (`solve --steps` with a
//! `dynamics` scene): each group cut out with its loads, the moment
//! equations and projections that give the components found first, the
//! vectors laid off at μ_F, the two lines that close the polygon, the
//! reactions read off it, the couples of the guides and the balancing
//! moment. Each language is one [`Catalogue`] of phrases with named
//! blanks, filled by one path.

use super::fill;
use super::forces::force_name;
use crate::format::num;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep};
use crate::kinetostatics::loads::Load;
use crate::lang::Lang;
use crate::model::structure::AssurGroup;
use kurbo::Vec2;
use std::fmt::Write as _;

/// The phrases of one language.
pub struct Catalogue {
    /// The steps' heading and the position's word.
    pub title: &'static str,
    /// "position".
    pub position: &'static str,
    /// "link", "links" (one, several).
    links: [&'static str; 2],
    /// Units: N, mm, N·m, N/mm.
    newton: &'static str,
    mm: &'static str,
    newton_metre: &'static str,
    per_mm: &'static str,
    /// `{formula}`, `{links}`.
    group: &'static str,
    /// `{ids}`.
    input_link: &'static str,
    /// `{at}`, `{what}`, `{f}`, `{value}`, `{n}`.
    moment: &'static str,
    /// `{what}`, `{f}`, `{value}`, `{n}`.
    projection: &'static str,
    /// `{from}`, `{f}`, `{val}`, `{n}`, `{len}`, `{mm}`, `{dir}`, `{to}`.
    lay_off: &'static str,
    /// `{through}`, `{f}`, `{dir}`.
    line: &'static str,
    /// `{out}`, `{deg}`.
    intersect: &'static str,
    /// `{a}`, `{b}`, `{l}`, `{mm}`, `{f}`, `{mu}`, `{val}`, `{bound}`, `{n}`, `{dir}`.
    measure: &'static str,
    /// `{what}`, `{value}`, `{nm}`, `{f}`, `{p}`: the couple of a guide
    /// with its force placed, and alone.
    couple_at: &'static str,
    couple_alone: &'static str,
    /// `{id}`, `{kind}`, `{b}`, `{value}`, `{unit}`, `{sense}`.
    balancing: &'static str,
    /// The balancing moment and force, as `{kind}` says them.
    kind: [&'static str; 2],
    /// A moment's senses: counter-clockwise, clockwise.
    sense: [&'static str; 2],
    /// The subscript of M_b, F_b.
    balancing_sub: &'static str,
    /// "worst intersection angle".
    worst: &'static str,
}

static EN: Catalogue = Catalogue {
    title: "Force plans",
    position: "position",
    links: ["link", "links"],
    newton: "N",
    mm: "mm",
    newton_metre: "N·m",
    per_mm: "N/mm",
    group: "Group {formula} of {links}, cut out with its loads and the reactions of the groups solved",
    input_link: "The input link {ids}",
    moment: "ΣM_{at}({what}) = 0 gives {f} = {value} {n} (signed along its assumed direction).",
    projection: "Projecting the equilibrium of {what} on the guide: {f} = {value} {n}.",
    lay_off: "From point {from} lay off {f} = {val} {n} as {len} {mm} at {dir}: point {to}.",
    line: "Through point {through} draw the line of {f} (at {dir}).",
    intersect: "The two lines meet at point {out} (at {deg}°).",
    measure: "Measure {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {bound} {n}, at {dir}.",
    couple_at: "ΣM({what}) = 0: the couple of the guide is {value} {nm}, so {f} acts at {p} m.",
    couple_alone: "ΣM({what}) = 0: the couple of the guide is {value} {nm} ({f} is zero: a couple alone).",
    balancing: "The equilibrium of link {id} gives the balancing {kind} {b} = {value} {unit}{sense}.",
    kind: ["moment", "force"],
    sense: ["counter-clockwise", "clockwise"],
    balancing_sub: "b",
    worst: "worst intersection angle",
};

static UK: Catalogue = Catalogue {
    title: "Плани сил",
    position: "положення",
    links: ["ланки", "ланок"],
    newton: "Н",
    mm: "мм",
    newton_metre: "Н·м",
    per_mm: "Н/мм",
    group: "Група {formula} {links}, відокремлена разом з її навантаженнями та реакціями вже розрахованих груп",
    input_link: "Вхідна ланка {ids}",
    moment: "З ΣM_{at}({what}) = 0: {f} = {value} {n} (зі знаком щодо прийнятого напрямку).",
    projection: "Проєкція рівноваги {what} на напрямну: {f} = {value} {n}.",
    lay_off: "Від точки {from} відкладаємо {f} = {val} {n} відрізком {len} {mm} під кутом {dir}: точка {to}.",
    line: "Через точку {through} проводимо лінію дії {f} (під кутом {dir}).",
    intersect: "Лінії перетинаються в точці {out} (під кутом {deg}°).",
    measure: "Вимірюємо {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {bound} {n}, під кутом {dir}.",
    couple_at: "ΣM({what}) = 0: момент у поступальній парі {value} {nm}, отже {f} прикладена в точці {p} м.",
    couple_alone: "ΣM({what}) = 0: момент у поступальній парі {value} {nm} ({f} дорівнює нулю).",
    balancing: "З рівноваги ланки {id}: {kind} {b} = {value} {unit}{sense}.",
    kind: ["зрівноважувальний момент", "зрівноважувальна сила"],
    sense: ["проти годинникової стрілки", "за годинниковою стрілкою"],
    balancing_sub: "зр",
    worst: "найменший кут перетину",
};

static RU: Catalogue = Catalogue {
    title: "Планы сил",
    position: "положение",
    links: ["звена", "звеньев"],
    newton: "Н",
    mm: "мм",
    newton_metre: "Н·м",
    per_mm: "Н/мм",
    group: "Группа {formula} {links}, выделенная вместе с её нагрузками и реакциями уже рассчитанных групп",
    input_link: "Входное звено {ids}",
    moment: "Из ΣM_{at}({what}) = 0: {f} = {value} {n} (со знаком относительно принятого направления).",
    projection: "Проекция равновесия {what} на направляющую: {f} = {value} {n}.",
    lay_off: "От точки {from} откладываем {f} = {val} {n} отрезком {len} {mm} под углом {dir}: точка {to}.",
    line: "Через точку {through} проводим линию действия {f} (под углом {dir}).",
    intersect: "Линии пересекаются в точке {out} (под углом {deg}°).",
    measure: "Измеряем {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {bound} {n}, под углом {dir}.",
    couple_at: "ΣM({what}) = 0: момент в поступательной паре {value} {nm}, значит {f} приложена в точке {p} м.",
    couple_alone: "ΣM({what}) = 0: момент в поступательной паре {value} {nm} ({f} равна нулю).",
    balancing: "Из равновесия звена {id}: {kind} {b} = {value} {unit}{sense}.",
    kind: ["уравновешивающий момент", "уравновешивающая сила"],
    sense: ["против часовой стрелки", "по часовой стрелке"],
    balancing_sub: "ур",
    worst: "наименьший угол пересечения",
};

/// The phrases of `lang`.
pub fn words(lang: Lang) -> &'static Catalogue {
    match lang {
        Lang::En => &EN,
        Lang::Uk => &UK,
        Lang::Ru => &RU,
    }
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
fn links_words(an: &Analysis, links: &[usize], w: &Catalogue) -> String {
    let ids: Vec<&str> = links.iter().map(|&l| an.mech.link_id(l)).collect();
    let word = w.links[usize::from(ids.len() != 1)];
    format!("{word} {}", ids.join(", "))
}

/// The point a moment is taken about: its name, else its coordinates.
fn about_words(an: &Analysis, step_about: (kurbo::Point, Option<usize>)) -> String {
    match step_about.1 {
        Some(p) => an.mech.point_name(p).to_string(),
        None => format!("({}, {})", num(step_about.0.x), num(step_about.0.y)),
    }
}

/// A force plan (of a group, or of the input link) in words, its steps
/// numbered, appended to `t`.
pub fn plan_words(an: &Analysis, loads: &[Load], plan: &ForcePlan, lang: Lang, t: &mut String) {
    let w = words(lang);
    let head = match plan.group {
        Some(g) => {
            let formula = match &an.structure.groups[g] {
                AssurGroup::Dyad(d) => d.kind.name(),
                AssurGroup::Triad(_) => "III",
            };
            let links = links_words(an, &plan.links, w);
            fill(w.group, &[("formula", formula), ("links", &links)])
        }
        None => {
            let ids: Vec<&str> = plan.links.iter().map(|&l| an.mech.link_id(l)).collect();
            fill(w.input_link, &[("ids", &ids.join(", "))])
        }
    };
    let _ = writeln!(t, "  {head}; μ_F = {} {}.", num(plan.mu), w.per_mm);
    let step = Step {
        an,
        loads,
        plan,
        lang,
        w,
    };
    for (i, s) in plan.steps.iter().enumerate() {
        let _ = writeln!(t, "{:>5}. {}", i + 1, step.words(s));
    }
    if plan.worst_sin < 1.0 {
        let deg = num(plan.worst_sin.asin().to_degrees());
        let _ = writeln!(
            t,
            "       {}: {deg}°; δ = {} {}",
            w.worst,
            num(plan.delta),
            w.mm
        );
    }
}

/// What a plan's steps share in words.
struct Step<'a> {
    an: &'a Analysis,
    loads: &'a [Load],
    plan: &'a ForcePlan,
    lang: Lang,
    w: &'static Catalogue,
}

impl Step<'_> {
    fn name(&self, f: Force) -> String {
        force_name(&self.an.mech, self.loads, f, self.lang)
    }

    /// One step of the plan in words.
    fn words(&self, step: &ForceStep) -> String {
        let (w, plan) = (self.w, self.plan);
        let n = w.newton;
        match step {
            ForceStep::Moment {
                links,
                about,
                about_name,
                force,
                value,
            } => {
                let at = about_words(self.an, (*about, *about_name));
                let what = links_words(self.an, links, w);
                let (f, value) = (self.name(*force), num(*value));
                let args = [("at", &*at), ("what", &what), ("f", &f), ("value", &value)];
                fill(w.moment, &[args[0], args[1], args[2], args[3], ("n", n)])
            }
            ForceStep::Projection {
                links,
                force,
                value,
            } => {
                let what = links_words(self.an, links, w);
                let (f, value) = (self.name(*force), num(*value));
                fill(
                    w.projection,
                    &[("what", &what), ("f", &f), ("value", &value), ("n", n)],
                )
            }
            ForceStep::LayOff(v) => {
                let d = plan.vectors[*v];
                let len = num((plan.points[d.to] - plan.points[d.from]).hypot());
                let (f, val, dir) = (self.name(d.force), num(d.value.hypot()), angle(d.value));
                let (from, to) = (d.from.to_string(), d.to.to_string());
                fill(
                    w.lay_off,
                    &[
                        ("from", &from),
                        ("f", &f),
                        ("val", &val),
                        ("n", n),
                        ("len", &len),
                        ("mm", w.mm),
                        ("dir", &dir),
                        ("to", &to),
                    ],
                )
            }
            ForceStep::Line(l) => {
                let l = plan.lines[*l];
                let (f, dir, through) = (self.name(l.force), angle(l.dir), l.through.to_string());
                fill(w.line, &[("through", &through), ("f", &f), ("dir", &dir)])
            }
            ForceStep::Intersect { out, sin, .. } => {
                let deg = num(sin.clamp(-1.0, 1.0).asin().to_degrees());
                fill(w.intersect, &[("out", &out.to_string()), ("deg", &deg)])
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
                let args = [("what", &*what), ("value", &value), ("nm", w.newton_metre), ("f", &f)];
                match at {
                    Some(p) => {
                        let p = format!("({}, {})", num(p.x), num(p.y));
                        fill(w.couple_at, &[args[0], args[1], args[2], args[3], ("p", &p)])
                    }
                    None => fill(w.couple_alone, &args),
                }
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
            w.measure,
            &[
                ("a", &a),
                ("b", &b),
                ("l", &l),
                ("mm", w.mm),
                ("f", &f),
                ("mu", &mu),
                ("val", &val),
                ("bound", &bound),
                ("n", w.newton),
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
            let sense = w.sense[if value >= 0.0 { 0 } else { 1 }];
            (w.newton_metre, format!(", {sense}"))
        } else {
            (w.newton, String::new())
        };
        fill(
            w.balancing,
            &[
                ("id", id),
                ("kind", w.kind[usize::from(!crank)]),
                ("b", &b),
                ("value", &num(value)),
                ("unit", unit),
                ("sense", &sense),
            ],
        )
    }
}
