//! The force analysis of one position on paper (`forces_<k>`): for every
//! step of the graphical route, in the order solved (the last Assur group
//! first, the input link last), the group's free-body drawing at μ_l
//! ([`free_body`]) and its force polygon at its own μ_F beside it
//! ([`force_polygon`]), captioned. All free bodies share one μ_l; each
//! polygon has the largest standard scale at which it fills its box, as
//! the course draws a polygon per group at a scale of its own.

use super::canvas::{Canvas, FONT, Label, Prim};
use super::free_body::{self, Scene};
use super::{DrawOptions, fill, force_polygon, lower_scale, table};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{Force, ForcePlan};
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::catalogue::fill as phrase;
use crate::words::forces as names;
use kurbo::{Point, Rect, Vec2};

/// The gap between panels and between a free body and its polygon, mm.
const GAP: f64 = 8.0;
/// The band at a panel's top holding its caption, mm.
const CAPTION: f64 = 7.0;
/// The band under a polygon holding its μ_F, mm.
const SCALE_LINE: f64 = 7.0;

/// The sheet's figure: the panels, the free bodies' μ_l and each plan's
/// μ_F (in the order of the plans).
pub struct Figure {
    pub canvas: Canvas,
    pub mu_l: f64,
    pub mu_f: Vec<f64>,
}

/// The heading's words: "Force analysis".
pub fn title(lang: Lang) -> &'static str {
    &crate::words::catalogue(lang).sheets.force_sheets
}

/// A panel's caption as the course names a group, by its class and kind:
/// "Група II класу 2-го виду (4, 5), RRP"; "Input link 1".
fn caption(an: &Analysis, plan: &ForcePlan, lang: Lang) -> String {
    let m = &an.mech;
    let ids: Vec<&str> = plan.links.iter().map(|&l| m.link_id(l)).collect();
    match plan.group {
        Some(g) => {
            let w = &crate::words::catalogue(lang).sheets;
            let links = ids.join(", ");
            match an.structure.groups.get(g) {
                Some(crate::model::structure::AssurGroup::Dyad(d)) => phrase(
                    &w.group,
                    &[
                        ("class", "II"),
                        ("kind", &d.kind.number().to_string()),
                        ("links", &links),
                        ("letters", d.kind.name()),
                    ],
                ),
                _ => phrase(&w.group_triad, &[("links", &links)]),
            }
        }
        None => {
            let word = &crate::words::catalogue(lang).sheets.input_link;
            format!("{word} {}", ids.join(", "))
        }
    }
}

/// "μ_F = 20 N/mm" (uk, ru: "Н/мм", the decimal comma).
pub fn scale_label(mu: f64, lang: Lang) -> Label {
    let newton = &crate::words::catalogue(lang).force_plans.newton;
    Label::new("μ", "F").with_tail(format!(
        " = {} {newton}/{}",
        table::number(mu, lang),
        table::unit("mm", lang)
    ))
}

/// Panels in columns on a field: a free body on the left of each, at
/// most a share ([`SHARES`]) of the column wide, its polygon on the right in
/// the rest; each row as high as its tallest free body needs (a polygon
/// at least [`MIN_POLYGON`] high).
#[derive(Clone, Copy)]
struct Columns {
    cols: usize,
    field: (f64, f64),
    /// The share of a column's width its free bodies may take.
    share: f64,
}

/// The shares of a column's width its free bodies may take.
const SHARES: [f64; 3] = [0.5, 0.6, 0.7];
/// The least height of a polygon's box, mm.
const MIN_POLYGON: f64 = 30.0;

impl Columns {
    fn col_width(&self) -> f64 {
        (self.field.0 - GAP * (self.cols - 1) as f64) / self.cols as f64
    }
    /// The field of the free bodies as [`fill`] sees it: the widest body
    /// against the column's share, the rows' heights against the field's.
    fn body_field(&self) -> (f64, f64) {
        (self.share * self.col_width(), self.field.1)
    }
    /// Per row, its height (caption included).
    fn rows(&self, bodies: &[Rect]) -> Vec<f64> {
        bodies
            .chunks(self.cols)
            .map(|row| {
                let h = row.iter().map(|b| b.height()).fold(0.0, f64::max);
                h.max(MIN_POLYGON + SCALE_LINE) + CAPTION
            })
            .collect()
    }
    /// The extent [`fill`] compares with [`Columns::body_field`].
    fn extent(&self, bodies: &[Rect]) -> Rect {
        let w = bodies.iter().map(|b| b.width()).fold(0.0, f64::max);
        let rows = self.rows(bodies);
        let h = rows.iter().sum::<f64>() + GAP * rows.len().saturating_sub(1) as f64;
        Rect::new(0.0, 0.0, w, h)
    }
    /// The rows' heights with the field's height left over shared among
    /// them: the free bodies' μ_l is a standard value (up to ×2 apart), so
    /// there is room the polygons take.
    fn rows_spread(&self, bodies: &[Rect]) -> Vec<f64> {
        let rows = self.rows(bodies);
        let n = rows.len().max(1) as f64;
        let used = rows.iter().sum::<f64>() + GAP * (n - 1.0);
        let extra = ((self.field.1 - used) / n).max(0.0);
        rows.into_iter().map(|h| h + extra).collect()
    }
    /// Panel `i`'s top left corner (drawing coordinates, y up), its free
    /// body's box and its polygon's box (w × h).
    fn panel(&self, i: usize, bodies: &[Rect]) -> (Point, (f64, f64), (f64, f64)) {
        let rows = self.rows_spread(bodies);
        let (col, row) = (i % self.cols, i / self.cols);
        let top: f64 = rows.iter().take(row).map(|h| h + GAP).sum();
        let h = rows.get(row).copied().unwrap_or(0.0) - CAPTION;
        let bw = bodies.iter().map(|b| b.width()).fold(0.0, f64::max);
        let x = col as f64 * (self.col_width() + GAP);
        (
            Point::new(x, -top),
            (bw, h),
            (self.col_width() - bw - GAP, h - SCALE_LINE),
        )
    }
}

/// The figure of position `s` on a field of `field` mm; `None` without
/// force plans.
pub fn figure(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    field: (f64, f64),
) -> Option<Figure> {
    let d = s.dynamics.as_ref()?;
    let fp = d.force_plans.as_ref()?;
    let plans = &fp.plans;
    if plans.is_empty() {
        return None;
    }
    let loads = &d.loads;
    let tags: Vec<String> = (1..=plans.len()).map(|i| format!("f{i}")).collect();
    let scene = |i: usize| Scene {
        an,
        s,
        d,
        loads,
        lang: opt.lang,
        tag: &tags[i],
    };
    let bodies = |mu: f64| -> Vec<Canvas> {
        plans
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let mut c = Canvas::default();
                free_body::draw(&scene(i), p, &mut c, mu);
                c
            })
            .collect()
    };
    let real = plans
        .iter()
        .enumerate()
        .map(|(i, p)| free_body::extent(&scene(i), p))
        .fold((0.0f64, 0.0f64), |a, r| {
            (a.0.max(r.width()), a.1.max(r.height()))
        });
    let (layout, mu_l, cs) = best_layout(plans.len(), field, real, bodies)?;
    let boxes = bounds(&cs);
    let name = |f| names::force(&an.mech, loads, f, opt.lang);
    let mut out = Canvas::default();
    let mut mu_f = Vec::new();
    for (i, (plan, body)) in plans.iter().zip(&cs).enumerate() {
        let panel = layout.panel(i, &boxes);
        let caption = caption(an, plan, opt.lang);
        if let Some(mu) = draw_panel(
            &mut out,
            (plan, &tags[i]),
            &name,
            body,
            panel,
            caption,
            opt.lang,
        ) {
            mu_f.push(mu);
        }
    }
    Some(Figure {
        canvas: out,
        mu_l,
        mu_f,
    })
}

/// The drawings' boxes.
fn bounds(cs: &[Canvas]) -> Vec<Rect> {
    cs.iter().map(|c| c.bounds()).collect()
}

/// The layout of `count` panels on `field` that draws the free bodies
/// largest (their real extent `real`, m; `bodies` draws them at a μ_l):
/// one column or two, the free bodies taking half to 70 % of a column
/// (standard μ_l are up to ×2 apart, so a little more room can halve
/// μ_l); with its μ_l and the free bodies drawn.
fn best_layout(
    count: usize,
    field: (f64, f64),
    real: (f64, f64),
    bodies: impl Fn(f64) -> Vec<Canvas>,
) -> Option<(Columns, f64, Vec<Canvas>)> {
    let mut best: Option<(Columns, f64, Vec<Canvas>)> = None;
    let layouts = [1, 2]
        .into_iter()
        .filter(|&c| c <= count)
        .flat_map(|cols| SHARES.map(|share| (cols, share)));
    for (cols, share) in layouts {
        let layout = Columns { cols, field, share };
        let f = layout.body_field();
        if f.0 <= GAP || f.1 <= CAPTION + GAP {
            continue;
        }
        let lower = lower_scale(real.0, real.1, f);
        let fit = fill(
            lower,
            f,
            |mu| Some(bodies(mu)),
            |cs| layout.extent(&bounds(cs)),
        );
        // At the same μ_l (standard values are up to ×2 apart, so two
        // layouts often share one), the one whose smallest polygon box is
        // largest: the polygons then take the room the bodies leave.
        let room = |layout: &Columns, cs: &Vec<Canvas>| {
            let boxes = bounds(cs);
            (0..cs.len())
                .map(|i| {
                    let (_, _, (pw, ph)) = layout.panel(i, &boxes);
                    pw.min(ph)
                })
                .fold(f64::INFINITY, f64::min)
        };
        if let Some((mu, cs)) = fit {
            let better = best
                .as_ref()
                .is_none_or(|b| mu < b.1 || (mu == b.1 && room(&layout, &cs) > room(&b.0, &b.2)));
            if better {
                best = Some((layout, mu, cs));
            }
        }
    }
    best
}

/// Draw one panel into `out`: the `caption`, the free body `body` in its
/// box and the polygon of `plan` (ids tagged `tag`) at the largest
/// standard μ_F that fills its box, with μ_F under it; returns that μ_F
/// (`None`, and no panel, when no scale fits).
fn draw_panel(
    out: &mut Canvas,
    (plan, tag): (&ForcePlan, &str),
    name: &dyn Fn(Force) -> Option<Label>,
    body: &Canvas,
    (corner, (bw, bh), (pw, ph)): (Point, (f64, f64), (f64, f64)),
    caption: String,
    lang: Lang,
) -> Option<f64> {
    let top = corner.y - CAPTION;
    // The polygon at the largest standard μ_F that fills its box.
    let (lo, hi) = plan
        .points
        .iter()
        .fold((Vec2::ZERO, Vec2::ZERO), |(lo, hi), p| {
            (
                Vec2::new(lo.x.min(p.x), lo.y.min(p.y)),
                Vec2::new(hi.x.max(p.x), hi.y.max(p.y)),
            )
        });
    let lower = lower_scale((hi.x - lo.x) * plan.mu, (hi.y - lo.y) * plan.mu, (pw, ph));
    let polygon = |mu: f64| {
        let mut c = Canvas::default();
        force_polygon::draw(plan, name, &mut c, plan.mu / mu, tag);
        Some(c)
    };
    let (mu, poly) = fill(lower, (pw, ph), polygon, |c| c.bounds())?;
    out.text(
        Point::new(corner.x, corner.y - FONT),
        Label::new(caption, ""),
        FONT,
        "caption",
    );
    let centre_in = |c: &Canvas, r: Rect| {
        let b = c.bounds();
        r.center() - b.center()
    };
    let d = centre_in(body, Rect::new(corner.x, top - bh, corner.x + bw, top));
    out.append(body, d.x, d.y);
    let px = corner.x + bw + GAP;
    let d = centre_in(&poly, Rect::new(px, top - ph, px + pw, top));
    out.append(&poly, d.x, d.y);
    // μ_F under the polygon, with an id the checks read it by.
    let scale = scale_label(mu, lang);
    let b = poly.bounds();
    out.prims.push(Prim::Text {
        at: Point::new(b.x0 + d.x, b.y0 + d.y - SCALE_LINE + 1.5),
        label: scale,
        size: FONT * super::canvas::lettering(),
        id: Some(format!("{tag}-mu")),
        class: "scale",
    });
    Some(mu)
}
