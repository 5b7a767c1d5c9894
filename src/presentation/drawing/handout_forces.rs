//! The force analysis of a position in the handout (a scene with
//! `dynamics`): as the course does it, group by group in the order solved
//! (the last Assur group first, the input link last), each step's free
//! body ([`free_body`], at the μ_l that fills its box) beside its force
//! polygon ([`force_polygon`], at its plan's own μ_F, the one `solve
//! --steps` and the result file state), with the plan's heading and its
//! steps in the words of `solve --steps`; then Zhukovsky's lever of every
//! input ([`lever`]) with its forces' arms and moments and the balancing
//! value. Every number in the language's decimal mark.
//!
//! The figures are static (the page's script steps through the
//! kinematic plans only); their style is [`CSS`], written into the page
//! only when a position has a force analysis, so that a handout without
//! `dynamics` stays as it was.

use crate::kinematics::construction::scale::Series;
use super::canvas::{Canvas, xml};
use super::free_body::{self, Scene};
use super::html_parts::{Fit, label_html, prefixed, rich};
use super::{fill, force_polygon, forces, lever, lower_scale, scale_label};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::Dynamics;
use crate::kinetostatics::force_plan::ForcePlan;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::force_plans::{plan_head, plan_sentences, plan_worst};
use crate::words::numbers::decimals;
use std::fmt::Write as _;

/// The box a free body is drawn to fill, w × h (mm).
const BODY_BOX: (f64, f64) = (80.0, 70.0);

/// The style of the force figures (added to the page's own).
pub(super) const CSS: &str = include_str!("handout-forces.css");

/// Whether any position of `solved` has a force analysis (the page then
/// carries [`CSS`]).
pub(super) fn any(solved: &[Solved]) -> bool {
    solved.iter().any(|s| s.dynamics.is_some())
}

/// A sentence in the language's decimal mark, as HTML in the notation.
fn said(s: &str, lang: Lang) -> String {
    rich(&decimals(s, lang))
}

/// The force analysis of position `k` (from 0) `s`, appended to `h`;
/// nothing without `dynamics`.
pub(super) fn section(h: &mut String, an: &Analysis, (k, s): (usize, &Solved), lang: Lang) {
    let Some(d) = s.dynamics.as_ref() else {
        return;
    };
    let w = &crate::words::catalogue(lang).handout;
    let pos = crate::presentation::position_number(an, k);
    let _ = writeln!(
        h,
        "<div class=\"forces\" id=\"pos-{pos}-forces\">\n<h3>{}</h3>",
        xml(&w.forces)
    );
    if let Some(fp) = &d.force_plans {
        let _ = writeln!(h, "<p class=\"note\">{}</p>", said(&w.not_to_scale, lang));
        for (i, plan) in fp.plans.iter().enumerate() {
            plan_figure(h, an, (s, d), (pos, i, plan), lang);
        }
    }
    for (j, (l, head, items)) in lever::lines(an, s, &d.loads, lang).iter().enumerate() {
        lever_figure(h, an, l, (pos, j), (head, items), lang);
    }
    h.push_str("</div>\n");
}

/// Force plan `i` of position `pos`: its caption (the group as the course
/// names it, μ_l, μ_F), the free body beside the polygon, the plan's
/// heading and steps in words.
fn plan_figure(
    h: &mut String,
    an: &Analysis,
    (s, d): (&Solved, &Dynamics),
    (pos, i, plan): (usize, usize, &ForcePlan),
    lang: Lang,
) {
    let w = &crate::words::catalogue(lang).handout;
    let tag = format!("f{}", i + 1);
    let sc = Scene {
        an,
        s,
        d,
        loads: &d.loads,
        lang,
        tag: &tag,
    };
    // The free body at the largest standard μ_l that fills its box.
    let real = free_body::extent(&sc, plan);
    let lower = lower_scale(real.width(), real.height(), BODY_BOX);
    let draw = |mu: f64| {
        let mut c = Canvas::default();
        free_body::draw(&sc, plan, &mut c, mu);
        Some(c)
    };
    let (mu_l, body) = fill(Series::Drawing, lower, BODY_BOX, draw, |c| c.bounds())
        .or_else(|| draw(lower).map(|c| (lower, c)))
        .expect("a free body is drawn");
    // The polygon as the plan was built: at its own μ_F.
    let name = |f| crate::words::forces::force(&an.mech, &d.loads, f, lang);
    let mut poly = Canvas::default();
    force_polygon::draw(plan, &name, &mut poly, (1.0, false), &tag);
    let caption = forces::caption(an, plan, lang);
    let _ = write!(
        h,
        "<figure class=\"fig force\" id=\"pos-{pos}-{tag}\">\n<figcaption><b>{}</b> <span class=\"scale\">{}</span> <span class=\"scale mu-f\">{}</span></figcaption>\n",
        xml(&caption),
        label_html(&scale_label("l", mu_l, "m", lang)),
        label_html(&forces::scale_label(plan.mu, lang)),
    );
    let prefix = format!("p{pos}{tag}-");
    let _ = writeln!(
        h,
        "<div class=\"pair\"><div class=\"paper body\"><p class=\"what\">{}</p>{}</div><div class=\"paper polygon\"><p class=\"what\">{}</p>{}</div></div>",
        xml(&w.free_body),
        svg(&body, &format!("{prefix}b-"), &format!("{}: {caption}", w.free_body)),
        xml(&w.polygon),
        svg(&poly, &format!("{prefix}p-"), &format!("{}: {caption}", w.polygon)),
    );
    let _ = writeln!(
        h,
        "<p class=\"force-head\">{}</p>\n<ol class=\"force-log\">",
        said(&plan_head(an, plan, lang), lang)
    );
    for sentence in plan_sentences(an, &d.loads, plan, lang) {
        let _ = writeln!(h, "<li>{}</li>", said(&sentence, lang));
    }
    h.push_str("</ol>\n");
    if let Some(worst) = plan_worst(plan, lang) {
        let _ = writeln!(h, "<p class=\"worst\">{}</p>", said(&worst, lang));
    }
    h.push_str("</figure>\n");
}

/// Zhukovsky's lever `j` (its input's) of position `pos`: the turned plan
/// with the forces at their μ_F, its scales (`head`), every force's arm
/// and moment and ΣM_p = 0 solved for the balancing value (`items`, the
/// last the balancing value).
fn lever_figure(
    h: &mut String,
    an: &Analysis,
    l: &crate::kinetostatics::lever::Lever,
    (pos, j): (usize, usize),
    (head, items): (&str, &[String]),
    lang: Lang,
) {
    let lw = lever::words(lang);
    let mu_f = lever::force_scale(l);
    let mut c = Canvas::default();
    lever::figure(an, l, &mut c, mu_f, lang);
    let title = if an.mech.scene.several_inputs() {
        format!("{}, {}", lw.title, lever::input_text(l, lang))
    } else {
        lw.title.clone()
    };
    let _ = write!(
        h,
        "<figure class=\"fig lever\" id=\"pos-{pos}-lever-{}\">\n<figcaption><b>{}</b> <span class=\"scale\">{}</span></figcaption>\n<div class=\"paper\">{}</div>\n<ol class=\"force-log\">\n",
        j + 1,
        xml(&title),
        said(head, lang),
        svg(&c, &format!("p{pos}l{}-", j + 1), &title),
    );
    for (n, item) in items.iter().enumerate() {
        let class = if n + 1 == items.len() {
            " class=\"balancing\""
        } else {
            ""
        };
        let _ = writeln!(h, "<li{class}>{}</li>", said(item, lang));
    }
    h.push_str("</ol>\n</figure>\n");
}

/// A canvas in its own SVG, ids prefixed with `prefix`, shown at
/// [`PX_PER_MM`] (narrower where the page is): every figure's letters at
/// one size, a small free body small.
fn svg(c: &Canvas, prefix: &str, aria: &str) -> String {
    let f = Fit::new(c.bounds(), 4.0);
    let mut body = String::new();
    c.write(&mut body, f.ox, f.oy);
    let open = f.open("sheet", aria).replacen(
        "<svg ",
        &format!("<svg style=\"width: {}px\" ", (f.w * PX_PER_MM).round()),
        1,
    );
    open + &prefixed(body, prefix) + "</svg>\n"
}

/// How large the force figures are shown, px per mm of the drawing.
const PX_PER_MM: f64 = 4.5;
