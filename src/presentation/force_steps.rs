//! The force plans in words (`solve --steps` with a `dynamics` scene): each
//! group cut out with its loads, the moment equations and projections that
//! give the components found first, the vectors laid off at μ_F, the two
//! lines that close the polygon, the reactions read off it, the couples of
//! the guides and the balancing moment, in English, Ukrainian or Russian.

use crate::words::construction::Lang;

use crate::format::num;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{Force, ForcePlan, ForceStep};
use crate::kinetostatics::loads::Load;
use crate::model::structure::AssurGroup;
use crate::pipeline::Solved;
use crate::words::forces::force_name;
use kurbo::Vec2;
use std::fmt::Write as _;

/// M_b / F_b in the language's notation (uk: зр, ru: ур).
fn balancing_letter(lang: Lang, moment: bool) -> &'static str {
    match (lang, moment) {
        (Lang::En, true) => "M_b",
        (Lang::En, false) => "F_b",
        (Lang::Uk, true) => "M_зр",
        (Lang::Uk, false) => "F_зр",
        (Lang::Ru, true) => "M_ур",
        (Lang::Ru, false) => "F_ур",
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
fn links_words(an: &Analysis, links: &[usize], lang: Lang) -> String {
    let ids: Vec<&str> = links.iter().map(|&l| an.mech.link_id(l)).collect();
    let word = match (lang, ids.len()) {
        (Lang::En, 1) => "link",
        (Lang::En, _) => "links",
        (Lang::Uk, 1) => "ланки",
        (Lang::Uk, _) => "ланок",
        (Lang::Ru, 1) => "звена",
        (Lang::Ru, _) => "звеньев",
    };
    format!("{word} {}", ids.join(", "))
}

/// The point a moment is taken about: its name, else its coordinates.
fn about_words(an: &Analysis, step_about: (kurbo::Point, Option<usize>)) -> String {
    match step_about.1 {
        Some(p) => an.mech.point_name(p).to_string(),
        None => format!("({}, {})", num(step_about.0.x), num(step_about.0.y)),
    }
}

/// The force analysis of solved position `s` (the `k`-th) in words; empty
/// without force plans.
pub fn force_steps(an: &Analysis, s: &Solved, k: usize, input: &str, lang: Lang) -> String {
    let Some(fp) = s.dynamics.as_ref().and_then(|d| d.force_plans.as_ref()) else {
        return String::new();
    };
    let loads = s.dynamics.as_ref().map_or(&[][..], |d| &d.loads[..]);
    let mut t = String::new();
    let title = match lang {
        Lang::En => "Force plans",
        Lang::Uk => "Плани сил",
        Lang::Ru => "Планы сил",
    };
    let position = match lang {
        Lang::En => "position",
        Lang::Uk => "положення",
        Lang::Ru => "положение",
    };
    let _ = writeln!(t, "\n{title}, {position} {}, {input}", k + 1);
    for plan in &fp.plans {
        plan_words(an, &loads, plan, lang, &mut t);
    }
    lever_words(an, s, &loads, lang, &mut t);
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
    use crate::kinematics::construction::Naming;
    use crate::presentation::drawing::lever as sheet;
    let Ok(levers) = crate::kinetostatics::lever::levers(an, s, loads, Naming::Full) else {
        return;
    };
    let (head, arm) = match lang {
        Lang::En => ("Zhukovsky's lever", "arm"),
        Lang::Uk => ("Важіль Жуковського", "плече"),
        Lang::Ru => ("Рычаг Жуковского", "плечо"),
    };
    for l in &levers {
        let mu_f = sheet::force_scale(l);
        let caption = sheet::caption(an, l, mu_f, lang);
        let _ = writeln!(t, "  {head}: {}.", points(&caption[0]));
        let table = sheet::table(an, l, lang);
        let mut n = 0;
        for row in &table.rows {
            n += 1;
            let row: Vec<String> = row.iter().map(|c| points(c)).collect();
            let _ = writeln!(
                t,
                "{n:>5}. {} = {} {}, {arm} h = {} {}: {}·h = {} {}.",
                row[0],
                row[1],
                if lang == Lang::En { "N" } else { "Н" },
                row[2],
                if lang == Lang::En { "mm" } else { "мм" },
                row[0].split(' ').next().unwrap_or(""),
                row[3],
                if lang == Lang::En {
                    "N·mm"
                } else {
                    "Н·мм"
                },
            );
        }
        for line in &caption[1..] {
            n += 1;
            let _ = writeln!(t, "{n:>5}. {}.", points(line));
        }
    }
}

fn plan_words(an: &Analysis, loads: &[Load], plan: &ForcePlan, lang: Lang, t: &mut String) {
    let m = &an.mech;
    let name = |f: Force| force_name(&an.mech, loads, f, lang);
    let unit = if lang == Lang::En { "N/mm" } else { "Н/мм" };
    let (n_, mm, nm) = match lang {
        Lang::En => ("N", "mm", "N·m"),
        _ => ("Н", "мм", "Н·м"),
    };
    let head = match plan.group {
        Some(g) => {
            let formula = match &an.structure.groups[g] {
                AssurGroup::Dyad(d) => d.kind.name(),
                AssurGroup::Triad(_) => "III",
            };
            match lang {
                Lang::En => format!(
                    "Group {formula} of {}, cut out with its loads and the reactions of the groups solved",
                    links_words(an, &plan.links, lang)
                ),
                Lang::Uk => format!(
                    "Група {formula} {}, відокремлена разом з її навантаженнями та реакціями вже розрахованих груп",
                    links_words(an, &plan.links, lang)
                ),
                Lang::Ru => format!(
                    "Группа {formula} {}, выделенная вместе с её нагрузками и реакциями уже рассчитанных групп",
                    links_words(an, &plan.links, lang)
                ),
            }
        }
        None => {
            let ids: Vec<&str> = plan.links.iter().map(|&l| m.link_id(l)).collect();
            let ids = ids.join(", ");
            match lang {
                Lang::En => format!("The input link {ids}"),
                Lang::Uk => format!("Вхідна ланка {ids}"),
                Lang::Ru => format!("Входное звено {ids}"),
            }
        }
    };
    let _ = writeln!(t, "  {head}; μ_F = {} {unit}.", num(plan.mu));
    for (i, step) in plan.steps.iter().enumerate() {
        let line = match step {
            ForceStep::Moment {
                links,
                about,
                about_name,
                force,
                value,
            } => {
                let at = about_words(an, (*about, *about_name));
                let what = links_words(an, links, lang);
                match lang {
                    Lang::En => format!(
                        "ΣM_{at}({what}) = 0 gives {} = {} {n_} (signed along its assumed direction).",
                        name(*force),
                        num(*value)
                    ),
                    Lang::Uk => format!(
                        "З ΣM_{at}({what}) = 0: {} = {} {n_} (зі знаком щодо прийнятого напрямку).",
                        name(*force),
                        num(*value)
                    ),
                    Lang::Ru => format!(
                        "Из ΣM_{at}({what}) = 0: {} = {} {n_} (со знаком относительно принятого направления).",
                        name(*force),
                        num(*value)
                    ),
                }
            }
            ForceStep::Projection {
                links,
                force,
                value,
            } => {
                let what = links_words(an, links, lang);
                match lang {
                    Lang::En => format!(
                        "Projecting the equilibrium of {what} on the guide: {} = {} {n_}.",
                        name(*force),
                        num(*value)
                    ),
                    Lang::Uk => format!(
                        "Проєкція рівноваги {what} на напрямну: {} = {} {n_}.",
                        name(*force),
                        num(*value)
                    ),
                    Lang::Ru => format!(
                        "Проекция равновесия {what} на направляющую: {} = {} {n_}.",
                        name(*force),
                        num(*value)
                    ),
                }
            }
            ForceStep::LayOff(v) => {
                let d = plan.vectors[*v];
                let len = (plan.points[d.to] - plan.points[d.from]).hypot();
                let f = name(d.force);
                let (val, dir) = (num(d.value.hypot()), angle(d.value));
                match lang {
                    Lang::En => format!(
                        "From point {} lay off {f} = {val} {n_} as {} {mm} at {dir}: point {}.",
                        d.from,
                        num(len),
                        d.to
                    ),
                    Lang::Uk => format!(
                        "Від точки {} відкладаємо {f} = {val} {n_} відрізком {} {mm} під кутом {dir}: точка {}.",
                        d.from,
                        num(len),
                        d.to
                    ),
                    Lang::Ru => format!(
                        "От точки {} откладываем {f} = {val} {n_} отрезком {} {mm} под углом {dir}: точка {}.",
                        d.from,
                        num(len),
                        d.to
                    ),
                }
            }
            ForceStep::Line(l) => {
                let l = plan.lines[*l];
                let f = name(l.force);
                let dir = angle(l.dir);
                match lang {
                    Lang::En => format!(
                        "Through point {} draw the line of {f} (at {dir}).",
                        l.through
                    ),
                    Lang::Uk => format!(
                        "Через точку {} проводимо лінію дії {f} (під кутом {dir}).",
                        l.through
                    ),
                    Lang::Ru => format!(
                        "Через точку {} проводим линию действия {f} (под углом {dir}).",
                        l.through
                    ),
                }
            }
            ForceStep::Intersect { out, sin, .. } => {
                let deg = num(sin.clamp(-1.0, 1.0).asin().to_degrees());
                match lang {
                    Lang::En => format!("The two lines meet at point {out} (at {deg}°)."),
                    Lang::Uk => format!("Лінії перетинаються в точці {out} (під кутом {deg}°)."),
                    Lang::Ru => format!("Линии пересекаются в точке {out} (под углом {deg}°)."),
                }
            }
            ForceStep::Measure(v) => {
                let d = plan.vectors[*v];
                let len = (plan.points[d.to] - plan.points[d.from]).hypot();
                let f = name(d.force);
                let bound = (plan.err[d.from] + plan.err[d.to] + plan.delta) * plan.mu;
                let (val, dir) = (num(d.value.hypot()), angle(d.value));
                let (a, b, l) = (d.from, d.to, num(len));
                let mu = num(plan.mu);
                match lang {
                    Lang::En => format!(
                        "Measure {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {} {n_}, at {dir}.",
                        num(bound)
                    ),
                    Lang::Uk => format!(
                        "Вимірюємо {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {} {n_}, під кутом {dir}.",
                        num(bound)
                    ),
                    Lang::Ru => format!(
                        "Измеряем {a}→{b} = {l} {mm}: {f} = {l}·{mu} = {val} ± {} {n_}, под углом {dir}.",
                        num(bound)
                    ),
                }
            }
            ForceStep::Couple {
                links,
                force,
                value,
                at,
            } => {
                let what = links_words(an, links, lang);
                let f = name(*force);
                let place = at.map(|p| format!("({}, {})", num(p.x), num(p.y)));
                match (lang, place) {
                    (Lang::En, Some(p)) => format!(
                        "ΣM({what}) = 0: the couple of the guide is {} {nm}, so {f} acts at {p} m.",
                        num(*value)
                    ),
                    (Lang::En, None) => format!(
                        "ΣM({what}) = 0: the couple of the guide is {} {nm} ({f} is zero: a couple alone).",
                        num(*value)
                    ),
                    (Lang::Uk, Some(p)) => format!(
                        "ΣM({what}) = 0: момент у поступальній парі {} {nm}, отже {f} прикладена в точці {p} м.",
                        num(*value)
                    ),
                    (Lang::Uk, None) => format!(
                        "ΣM({what}) = 0: момент у поступальній парі {} {nm} ({f} дорівнює нулю).",
                        num(*value)
                    ),
                    (Lang::Ru, Some(p)) => format!(
                        "ΣM({what}) = 0: момент в поступательной паре {} {nm}, значит {f} приложена в точке {p} м.",
                        num(*value)
                    ),
                    (Lang::Ru, None) => format!(
                        "ΣM({what}) = 0: момент в поступательной паре {} {nm} ({f} равна нулю).",
                        num(*value)
                    ),
                }
            }
            ForceStep::Balancing { input, value } => {
                let spec = m.scene.input_at(*input);
                let crank = spec.is_crank();
                let id = m.link_id(spec.link());
                let b = balancing_letter(lang, crank);
                let (unit, sense) = if crank {
                    let ccw = *value >= 0.0;
                    let sense = match (lang, ccw) {
                        (Lang::En, true) => "counter-clockwise",
                        (Lang::En, false) => "clockwise",
                        (Lang::Uk, true) => "проти годинникової стрілки",
                        (Lang::Uk, false) => "за годинниковою стрілкою",
                        (Lang::Ru, true) => "против часовой стрелки",
                        (Lang::Ru, false) => "по часовой стрелке",
                    };
                    (nm, sense)
                } else {
                    (n_, "")
                };
                let sense = if sense.is_empty() {
                    String::new()
                } else {
                    format!(", {sense}")
                };
                match lang {
                    Lang::En => format!(
                        "The equilibrium of link {id} gives the balancing {} {b} = {} {unit}{sense}.",
                        if crank { "moment" } else { "force" },
                        num(*value)
                    ),
                    Lang::Uk => format!(
                        "З рівноваги ланки {id}: {} {b} = {} {unit}{sense}.",
                        if crank {
                            "зрівноважувальний момент"
                        } else {
                            "зрівноважувальна сила"
                        },
                        num(*value)
                    ),
                    Lang::Ru => format!(
                        "Из равновесия звена {id}: {} {b} = {} {unit}{sense}.",
                        if crank {
                            "уравновешивающий момент"
                        } else {
                            "уравновешивающая сила"
                        },
                        num(*value)
                    ),
                }
            }
        };
        let _ = writeln!(t, "{:>5}. {line}", i + 1);
    }
    if plan.worst_sin < 1.0 {
        let deg = num(plan.worst_sin.asin().to_degrees());
        let words = match lang {
            Lang::En => "worst intersection angle",
            Lang::Uk => "найменший кут перетину",
            Lang::Ru => "наименьший угол пересечения",
        };
        let _ = writeln!(t, "       {words}: {deg}°; δ = {} {mm}", num(plan.delta));
    }
}
