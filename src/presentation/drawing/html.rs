//! The step-by-step handout (`mechplan draw --html`): one self-contained
//! HTML file (inline CSS, JS and SVG, nothing fetched) that shows, for each
//! position, the plan of the mechanism and the plans of velocities and
//! accelerations being drawn step by step, with the lecture-style sentence
//! of the current step, the sentences so far, and the result tables.
//!
//! Every SVG element a step draws sits in a `<g data-step="k">` (k from 1;
//! `data-until="m"` when it is replaced at step m, as a shared label that
//! grows when a coinciding point joins it); the page's script shows the
//! elements with `data-step` ≤ the current step. Steps that draw nothing
//! new (measuring a segment already drawn) mark what they use for their
//! own step only. `#step=N` opens the N-th step of the whole handout,
//! `#pos=P` (and `#pos=P&step=K`) position P (its number as the page shows
//! it: a `count` sweep from 0), `#selftest` steps through
//! every step and reports in the page's title.
//!
//! The page's style and script are files beside this one (`handout.css`,
//! `handout.js`, `handout-errors.js`), written into the page as they are;
//! its result tables are those of [`crate::presentation::tables`], as the
//! terminal's.

use super::canvas::{Canvas, Prim, xml};
pub use super::html_parts::rich;
use super::html_parts::{Fit, label_html, prefixed};
use super::handout_forces;
use super::{mechanism, plan, scale_label, words};
use crate::format::num;
use crate::kinematics::construction::{Op, Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use crate::presentation::report::group_kinds;
use crate::presentation::tables::{self, Cell, Kind, Table, unit};
use crate::words::catalogue::HandoutPhrases;
use crate::words::construction::{Lang, sentence};
use std::fmt::Write as _;

/// Words of the page around the drawings (the language's catalogue).
fn ui(l: Lang) -> &'static HandoutPhrases {
    &crate::words::catalogue(l).handout
}

/// The plan of the mechanism at every position.
fn mechanism_canvases(an: &Analysis, solved: &[Solved]) -> Vec<Canvas> {
    solved
        .iter()
        .map(|s| {
            let mut c = Canvas::default();
            mechanism::draw(an, s, &mut c, an.mu_l, true);
            c.place_pending();
            c
        })
        .collect()
}

/// The plan of the mechanism at a position, whole, in the frame `f` that
/// all positions share (the frame stays put from position to position).
fn mechanism_svg(c: &Canvas, f: &Fit, prefix: &str, aria: &str) -> String {
    let mut body = String::new();
    c.write(&mut body, f.ox, f.oy);
    f.open("sheet", aria) + &prefixed(body, prefix) + "</svg>\n"
}

/// A primitive and the steps it is shown for: from `from` (1-based) until
/// before `until`.
struct Tagged {
    prim: Prim,
    from: usize,
    until: Option<usize>,
}

/// A plan drawn step by step: every primitive in a group tagged with its
/// step; shared labels in versions that grow as their points are made;
/// a mark on what a step uses when it draws nothing new.
fn plan_svg(plan: &Plan, an: &Analysis, prefix: &str, aria: &str) -> String {
    let mut c = Canvas::default();
    let mut steps = plan::draw_steps(plan, &mut c, &an.points);
    c.place_pending();
    let made = plan::made_at(plan);
    // Whatever was drawn after the steps (labels placed last): a point's
    // dot and label by the step that made the point, else the last step.
    let last = plan.steps.len().saturating_sub(1);
    for prim in &c.prims[steps.len()..] {
        let id = match prim {
            Prim::Text { id, .. } | Prim::Circle { id, .. } => id.as_deref(),
            _ => None,
        };
        let key = id.and_then(|i| i.strip_prefix("label-").or_else(|| i.strip_prefix("pt-")));
        let k = key
            .and_then(|key| plan.points.iter().position(|p| p.key == key))
            .and_then(|i| made[i])
            .unwrap_or(last);
        steps.push(k);
    }
    let mut tagged: Vec<Tagged> = Vec::new();
    for (prim, &k) in c.prims.iter().zip(&steps) {
        if let Some(v) = label_versions(plan, &made, prim, k) {
            tagged.extend(v);
            continue;
        }
        tagged.push(Tagged {
            prim: prim.clone(),
            from: k + 1,
            until: None,
        });
    }
    let f = Fit::new(c.bounds(), 4.0);
    let mut body = String::new();
    let mut i = 0;
    while i < tagged.len() {
        let (from, until) = (tagged[i].from, tagged[i].until);
        let mut run = Canvas::default();
        while i < tagged.len() && tagged[i].from == from && tagged[i].until == until {
            run.prims.push(tagged[i].prim.clone());
            i += 1;
        }
        let until = until
            .map(|u| format!(r#" data-until="{u}""#))
            .unwrap_or_default();
        let _ = writeln!(body, r#"<g data-step="{from}"{until}>"#);
        run.write(&mut body, f.ox, f.oy);
        body.push_str("</g>\n");
    }
    // Steps that drew nothing: mark the segment measured, the point met.
    let drew: Vec<bool> = (1..=plan.steps.len())
        .map(|k| tagged.iter().any(|t| t.from == k))
        .collect();
    let at = |i: usize| plan.points[i].at.to_point();
    for (k, step) in plan.steps.iter().enumerate() {
        if drew[k] {
            continue;
        }
        let (a, b) = match &step.op {
            Op::Measure { from, to, .. } => (at(*from), at(*to)),
            Op::LayOff { to, .. }
            | Op::Coincide { out: to, .. }
            | Op::Divide { out: to, .. }
            | Op::Similar { out: to, .. }
            | Op::Intersect { out: to, .. } => (at(*to), at(*to)),
            Op::Pole { .. } => (at(0), at(0)),
            Op::Same { .. } | Op::Equation { .. } => continue,
        };
        let mark = if (b - a).hypot() > 0.05 {
            format!(
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}"/>"#,
                f.x(a),
                f.y(a),
                f.x(b),
                f.y(b)
            )
        } else {
            format!(r#"<circle cx="{}" cy="{}" r="2.2"/>"#, f.x(b), f.y(b))
        };
        let _ = writeln!(
            body,
            r#"<g class="mark" data-step="{}" data-until="{}">{mark}</g>"#,
            k + 1,
            k + 2
        );
    }
    f.open("sheet", aria) + &prefixed(body, prefix) + "</svg>\n"
}

/// A label shared by points made at different steps, in one version per
/// step: from the step its first point is made, each next version with the
/// names made so far. None for other primitives.
fn label_versions(
    plan: &Plan,
    made: &[Option<usize>],
    prim: &Prim,
    k: usize,
) -> Option<Vec<Tagged>> {
    let Prim::Text {
        label,
        id: Some(id),
        ..
    } = prim
    else {
        return None;
    };
    let key = id.strip_prefix("label-")?;
    if label.more.is_empty() {
        return None;
    }
    let first = plan.points.iter().find(|p| p.key == key)?;
    // Each further name: the point of that name at the same place.
    let when: Vec<usize> = label
        .more
        .iter()
        .map(|(b, s)| {
            plan.points
                .iter()
                .enumerate()
                .find(|(_, p)| {
                    p.key != first.key
                        && (&p.label.0, &p.label.1) == (b, s)
                        && (p.at - first.at).hypot() < 0.05
                })
                .map(|(i, _)| made[i].unwrap_or(k).max(k))
        })
        .collect::<Option<_>>()?;
    let mut at: Vec<usize> = when.clone();
    at.push(k);
    at.sort_unstable();
    at.dedup();
    let versions = at
        .iter()
        .enumerate()
        .map(|(n, &s)| {
            let mut prim = prim.clone();
            if let Prim::Text { label, id, .. } = &mut prim {
                // The id stays with the complete label, unique in the page.
                if n + 1 < at.len() {
                    *id = None;
                }
                let more = std::mem::take(&mut label.more);
                label.more = more
                    .into_iter()
                    .zip(&when)
                    .filter(|(_, w)| **w <= s)
                    .map(|(m, _)| m)
                    .collect();
            }
            Tagged {
                prim,
                from: s + 1,
                until: at.get(n + 1).map(|u| u + 1),
            }
        })
        .collect();
    Some(versions)
}

/// "φ1 = 235.8°" or "s = 0.1 m".
fn input_text(an: &Analysis, s: &Solved, l: Lang) -> String {
    if an.mech.scene.several_inputs() {
        return crate::words::inputs::input_words(an, s);
    }
    match an.mech.scene.input {
        InputSpec::Crank { .. } => format!("φ1 = {}°", num(s.q.to_degrees().rem_euclid(360.0))),
        InputSpec::Slider { .. } => format!("s = {} {}", num(s.q), unit("m", l)),
    }
}

/// The drive at a position: "ω1 = −10 rad/s, ε1 = 0 rad/s²".
fn drive_text(an: &Analysis, s: &Solved, l: Lang) -> String {
    if an.mech.scene.several_inputs() {
        return crate::words::inputs::drive_words(an, s);
    }
    match an.mech.scene.input {
        InputSpec::Crank { .. } => format!(
            "ω1 = {} {}, ε1 = {} {}",
            num(s.rate),
            unit("rad/s", l),
            num(s.rate2),
            unit("rad/s²", l)
        ),
        InputSpec::Slider { .. } => format!(
            "v = {} {}, a = {} {}",
            num(s.rate),
            unit("m/s", l),
            num(s.rate2),
            unit("m/s²", l)
        ),
    }
}

/// A signed angular rate with its sense: "0.837 ↺".
fn rate_cell(x: f64, scale: f64) -> String {
    if x.abs() <= 1e-12 * scale || x == 0.0 {
        return "0".into();
    }
    format!(
        "{} <span class=\"sense\">{}</span>",
        num(x.abs()),
        if x > 0.0 { "↺" } else { "↻" }
    )
}

/// The tables of a position: points, links, what was measured on the plans.
fn tables(an: &Analysis, s: &Solved, l: Lang) -> String {
    let mut h = String::from("<div class=\"tables\">\n");
    h += &table_html(&tables::points(an, s, l), l);
    h += &table_html(&tables::links(an, s, l), l);
    if let Some(plans) = &s.plans {
        let titles = words(l);
        h += &table_html(&tables::measured(
            plans,
            [&titles.velocities[..], &titles.accelerations[..]],
            l,
        ), l);
    }
    h + "</div>\n"
}

/// A table of results as HTML: the columns the handout shows (not where
/// the points are, nor which way they move: its drawings show that), the
/// rows complete in them, a group's title on a row of its own; nothing for
/// a table left with names alone.
fn table_html(t: &Table, l: Lang) -> String {
    let shown = |k: Kind| !matches!(k, Kind::Coordinate | Kind::Direction | Kind::Angle);
    let columns: Vec<usize> = (0..t.columns.len())
        .filter(|&i| shown(t.columns[i].kind))
        .collect();
    if columns.iter().all(|&i| t.columns[i].kind == Kind::Name) {
        return String::new();
    }
    let class = t
        .class
        .map(|c| format!(" class=\"{c}\""))
        .unwrap_or_default();
    let mut h = format!("<table{class}><caption>{}</caption><thead><tr>", t.caption);
    for &i in &columns {
        let c = &t.columns[i];
        let _ = match &c.unit {
            Some(u) => write!(h, "<th>{}, {u}</th>", c.head),
            None => write!(h, "<th>{}</th>", c.head),
        };
    }
    h.push_str("</tr></thead>");
    // Titled groups stand on lines of their own.
    let nl = if t.groups.iter().any(|g| g.title.is_some()) {
        "\n"
    } else {
        ""
    };
    h.push_str(nl);
    for g in &t.groups {
        h.push_str("<tbody>");
        if let Some(title) = &g.title {
            let _ = write!(
                h,
                "<tr class=\"group\"><th colspan=\"{}\">{title}</th></tr>",
                columns.len()
            );
        }
        h.push('\n');
        for row in &g.rows {
            if columns.iter().any(|&i| matches!(row[i], Cell::Missing)) {
                continue;
            }
            h.push_str("<tr>");
            for &i in &columns {
                let _ = write!(h, "<td>{}</td>", cell_html(&row[i]));
            }
            h.push_str("</tr>\n");
        }
        h.push_str("</tbody>");
        h.push_str(nl);
    }
    // Numbers with the language's decimal mark (the tables are shared with
    // the terminal, which writes its own).
    crate::words::numbers::decimals(&(h + "</table>\n"), l)
}

/// A cell as HTML: names in the lecture's notation, numbers as the
/// sentences write them, a rate as its magnitude and sense.
fn cell_html(c: &Cell) -> String {
    match c {
        Cell::Notation(s) => rich(s),
        Cell::Plain(s) => xml(s),
        Cell::Number(x) => num(*x),
        Cell::Rate { value, scale } => rate_cell(*value, *scale),
        Cell::Segment { name, mm } => format!("{} = {}", rich(name), num(*mm)),
        Cell::Measured { value, bound, unit } => {
            format!("{} ± {} {unit}", cell_html(value), num(*bound))
        }
        Cell::Missing => String::new(),
    }
}

/// The handout: every position's drawings and tables, the plans drawn step
/// by step with their sentences in `lang`.
pub fn handout(an: &Analysis, solved: &[Solved], lang: Lang) -> String {
    let w = ui(lang);
    let mut h = page_head(an, solved, lang, w);
    let _ = write!(
        h,
        "<div class=\"board\" id=\"board\">\n<div class=\"where\"><span id=\"where\"></span><span id=\"counter\"></span></div>\n<div class=\"sentence\" id=\"sentence\" aria-live=\"polite\"></div>\n<div class=\"controls\"><button type=\"button\" id=\"first\" title=\"Home\">⇤ {}</button><button type=\"button\" id=\"prev\" title=\"←\">◀ {}</button><button type=\"button\" id=\"next\" class=\"primary\" title=\"→\">{} ▶</button><button type=\"button\" id=\"last\" title=\"End\">{} ⇥</button><span class=\"hint\">{}</span></div>\n</div>\n",
        w.start, w.prev, w.next, w.all, w.keys
    );
    if solved.iter().all(|s| s.plans.is_none()) {
        let _ = writeln!(h, "<p class=\"none\">{}</p>", w.no_plans);
    }
    h.push_str("<main>\n");
    let mechs = mechanism_canvases(an, solved);
    let frame = mechs
        .iter()
        .map(|c| c.bounds())
        .reduce(|a, b| a.union(b))
        .unwrap_or_default();
    let frame = Fit::new(frame, 4.0);
    for (k, s) in solved.iter().enumerate() {
        position_section(&mut h, an, (k, s), lang, (&mechs[k], &frame));
    }
    h.push_str("</main>\n<pre id=\"selftest\" hidden></pre>\n");
    let _ = write!(h, "<script>\n{JS}</script>\n</body>\n</html>\n");
    h
}

/// The page up to its board: the head (style, the errors' script), the
/// title, the structure and a tab per position.
fn page_head(an: &Analysis, solved: &[Solved], lang: Lang, w: &HandoutPhrases) -> String {
    let m = &an.mech;
    let title = match m.scene.title_in(lang) {
        "" => "mechplan".to_string(),
        t => t.to_string(),
    };
    let code = lang.code();
    let structure = format!(
        "{}: W = {}, {} [{}]",
        w.structure,
        an.structure.dof,
        an.structure.formula(m).replace("->", "→"),
        group_kinds(an)
    );
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"{code}\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{}</title>\n<style>\n{CSS}{}</style>\n<script>\n{ERRORS_JS}</script>\n</head>\n",
        xml(&title),
        if handout_forces::any(solved) {
            handout_forces::CSS
        } else {
            ""
        }
    );
    let _ = writeln!(
        h,
        "<body data-word-step=\"{}\" data-word-of=\"{}\">",
        xml(&w.step),
        xml(&w.of)
    );
    let _ = writeln!(
        h,
        "<header class=\"top\">\n<h1>{}</h1>\n<p class=\"meta\">{}</p>",
        xml(&title),
        rich(&structure)
    );
    h.push_str("<nav class=\"tabs\">\n");
    for (k, s) in solved.iter().enumerate() {
        let _ = writeln!(
            h,
            "<button type=\"button\" class=\"tab\" data-pos=\"{0}\">{0} {1}</button>",
            crate::presentation::position_number(an, k),
            rich(&crate::words::numbers::decimals(
                &format!("· {}", input_text(an, s, lang)),
                lang
            ))
        );
    }
    h.push_str("</nav>\n</header>\n");
    h
}

/// Position `k` (from 0) `s`: its heading, the plan of the mechanism (its
/// canvas `mech` in the handout's `frame`), the plans step by step, the
/// result tables.
fn position_section(
    h: &mut String,
    an: &Analysis,
    (k, s): (usize, &Solved),
    lang: Lang,
    (mech, frame): (&Canvas, &Fit),
) {
    let w = ui(lang);
    let sheet_words = words(lang);
    let pos = crate::presentation::position_number(an, k);
    let heading = format!(
        "{} {pos}: {}; {}",
        w.position,
        input_text(an, s, lang),
        drive_text(an, s, lang)
    );
    let _ = writeln!(
        h,
        "<section class=\"position\" id=\"pos-{pos}\" data-pos=\"{pos}\">\n<h2>{}</h2>\n<div class=\"figs\">",
        rich(&crate::words::numbers::decimals(&heading, lang))
    );
    let mu_l = scale_label("l", an.mu_l, "m", lang);
    let _ = write!(
        h,
        "<figure class=\"fig mech\"><figcaption><b>{}</b> <span class=\"scale\">{}</span></figcaption>\n<div class=\"paper\">{}</div></figure>\n",
        sheet_words.mechanism,
        label_html(&mu_l),
        mechanism_svg(mech, frame, &format!("p{pos}m-"), &sheet_words.mechanism)
    );
    if let Some(plans) = &s.plans {
        for (kind, title, plan) in [
            ("v", &sheet_words.velocities[..], Some(&plans.velocity)),
            ("a", &sheet_words.accelerations[..], plans.acceleration.as_ref()),
        ] {
            let Some(plan) = plan else { continue };
            plan_figure(h, an, plan, (pos, kind, title), lang);
        }
    }
    h.push_str("</div>\n");
    let _ = writeln!(h, "<h3>{}</h3>", w.results);
    h.push_str(&tables(an, s, lang));
    handout_forces::section(h, an, (k, s), lang);
    h.push_str("</section>\n");
}

/// A plan of position `pos` (`kind` "v" or "a", its `title`) drawn step by
/// step, with the list of its steps' sentences.
fn plan_figure(
    h: &mut String,
    an: &Analysis,
    plan: &Plan,
    (pos, kind, title): (usize, &str, &str),
    lang: Lang,
) {
    let w = ui(lang);
    let (sym, u) = match plan.kind {
        PlanKind::Velocity => ("v", "m/s"),
        PlanKind::Acceleration => ("a", "m/s²"),
    };
    let scale = scale_label(sym, plan.mu, u, lang);
    let _ = write!(
        h,
        "<figure class=\"fig plan\" id=\"pos-{pos}-{kind}\" data-pos=\"{pos}\" data-kind=\"{kind}\" data-steps=\"{}\" data-title=\"{}, {} {pos}\">\n<figcaption><b>{title}</b> <span class=\"scale\">{}</span></figcaption>\n<div class=\"paper\">{}<p class=\"placeholder\">{}</p></div>\n",
        plan.steps.len(),
        xml(title),
        xml(&w.position.to_lowercase()),
        label_html(&scale),
        plan_svg(plan, an, &format!("p{pos}{kind}-"), title),
        w.after
    );
    let _ = writeln!(
        h,
        "<details class=\"steps\" open><summary>{}</summary><ol class=\"log\">",
        w.steps_title
    );
    for i in 0..plan.steps.len() {
        let _ = writeln!(
            h,
            "<li data-step=\"{}\">{}</li>",
            i + 1,
            rich(&sentence(plan, i, lang))
        );
    }
    h.push_str("</ol></details>\n</figure>\n");
}

/// Errors of the page's script, collected for `#selftest` (in the head,
/// before anything else runs).
const ERRORS_JS: &str = include_str!("handout-errors.js");

/// The page's style: the board, the figures, the tables, print.
const CSS: &str = include_str!("handout.css");

/// The page's script: the steps shown one by one, the keys and tabs,
/// `#step=`/`#pos=` and `#selftest`.
const JS: &str = include_str!("handout.js");
