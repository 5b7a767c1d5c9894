//! The force analysis of one position on paper (`forces_<k>`): for every
//! step of the graphical route, in the order solved (the last Assur group
//! first, the input link last), the group's free-body drawing at μ_l
//! ([`free_body`]) and its force polygon at its own μ_F beside it
//! ([`force_polygon`]), captioned. Each free body and each polygon has the
//! largest standard scale at which it fills its box (its μ_l and μ_F
//! written in its panel), as the course draws each group apart.

use super::canvas::{Canvas, FONT, Label, Prim};
use super::free_body::{self, Scene};
use super::layout::field_size;
use super::{DrawOptions, SheetSize, fill, force_polygon, lower_scale, table};
use crate::kinematics::solve::Analysis;
use crate::kinematics::construction::scale::standard_above;
use crate::kinetostatics::force_plan::{self, ForcePlan, Which};
use crate::kinetostatics::loads::Load;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::words::catalogue::fill as phrase;
use crate::words::forces as names;
use kurbo::{Point, Rect};

/// The gap between panels and between a free body and its polygon, mm.
const GAP: f64 = 8.0;
/// The band at a panel's top holding its caption, mm.
const CAPTION: f64 = 7.0;
/// The band under a polygon holding its μ_F, mm.
const SCALE_LINE: f64 = 7.0;

/// The sheet's figure: the panels, each free body's μ_l and each plan's
/// μ_F (in the order of the plans).
pub struct Figure {
    pub canvas: Canvas,
    pub mu_l: Vec<f64>,
    pub mu_f: Vec<f64>,
    /// The smallest free body's size (its joints' extent across or down
    /// at its μ_l), mm.
    pub smallest: f64,
}

/// The least size of a free body a student can read its forces on, mm:
/// a force sheet too small for it goes on a larger format.
pub const LEAST_BODY: f64 = 40.0;

/// The heading's words: "Force analysis".
pub fn title(lang: Lang) -> &'static str {
    &crate::words::catalogue(lang).sheets.force_sheets
}

/// A panel's caption as the course names a group, by its class and kind:
/// "Група II класу 2-го виду (4, 5), RRP"; "Input link 1".
pub(super) fn caption(an: &Analysis, plan: &ForcePlan, lang: Lang) -> String {
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

/// The height of a line of the sheet's note, mm.
const NOTE_LINE: f64 = 6.0;

/// The note that the arrows on the free bodies are not to scale (only
/// the polygons are, at μ_F), in the language's words, broken into lines
/// no wider than `width` mm.
fn note_lines(lang: Lang, width: f64) -> Vec<String> {
    let words = &crate::words::catalogue(lang).sheets.not_to_scale;
    let size = FONT * super::canvas::lettering();
    let wide = |s: &str| super::canvas::runs_width(&crate::words::notation::runs(s), size);
    let mut lines: Vec<String> = vec![String::new()];
    for w in words.split(' ') {
        let last = lines.last_mut().expect("a line");
        let joined = if last.is_empty() {
            w.to_string()
        } else {
            format!("{last} {w}")
        };
        if last.is_empty() || wide(&joined) <= width {
            *last = joined;
        } else {
            lines.push(w.to_string());
        }
    }
    lines
}

/// The least width and height of a free body's box, mm.
const MIN_BODY: f64 = 30.0;

/// Panels in a grid on a field, each of the same size: its caption and
/// scale on top, its free body on the left, its polygon on the right in a
/// box that holds the largest of the polygons (each drawn at its plan's
/// own μ_F, the one its steps and the result file state). Each free body
/// is drawn at its own μ_l, the largest standard scale that fills the rest
/// of the panel, as the course draws each group apart: one μ_l for all
/// would shrink the input link to a blob beside a large group.
#[derive(Clone, Copy)]
struct Grid {
    cols: usize,
    rows: usize,
    field: (f64, f64),
    /// The polygons' box, w × h (mm).
    polygon: (f64, f64),
}

impl Grid {
    fn col_width(&self) -> f64 {
        (self.field.0 - GAP * (self.cols - 1) as f64) / self.cols as f64
    }
    fn row_height(&self) -> f64 {
        (self.field.1 - GAP * (self.rows - 1) as f64) / self.rows as f64
    }
    /// The band at a panel's top: its caption and its μ_l.
    fn head() -> f64 {
        2.0 * CAPTION * super::canvas::lettering()
    }
    /// Panel `i`'s top left corner (drawing coordinates, y up), its free
    /// body's box and its polygon's box (w × h).
    fn panel(&self, i: usize) -> (Point, (f64, f64), (f64, f64)) {
        let (col, row) = (i % self.cols, i / self.cols);
        let (cw, rh) = (self.col_width(), self.row_height());
        let h = rh - Grid::head();
        let pw = self.polygon.0;
        (
            Point::new(col as f64 * (cw + GAP), -(row as f64) * (rh + GAP)),
            (cw - pw - GAP, h),
            (pw, h - SCALE_LINE),
        )
    }
}

/// The figure of position `s` on a field of `field` mm; `None` without
/// force plans. With `may_drop`, the equations under the polygons are
/// left off where no grid holds the polygons with them.
pub fn figure(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    (field, may_drop): ((f64, f64), bool),
) -> Option<Figure> {
    let fp = s.dynamics.as_ref()?.force_plans.as_ref()?;
    figure_of(an, s, opt, (field, may_drop), &fp.plans)
}

/// The figure of position `s`'s force plans `plans` (all, or one group's
/// where a sheet holds them one by one) on a field of `field` mm; `None`
/// where none, or where no grid holds them. Where no grid holds the
/// polygons as built, each is built again at the next standard μ_F up,
/// round by round, until the panels hold them: a construction at that
/// scale, stated in its panel.
pub fn figure_of(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    (field, may_drop): ((f64, f64), bool),
    plans: &[ForcePlan],
) -> Option<Figure> {
    let d = s.dynamics.as_ref()?;
    if plans.is_empty() {
        return None;
    }
    let first = try_figure(an, s, opt, (field, may_drop), plans);
    if first.is_some() {
        return first;
    }
    let mut plans = plans.to_vec();
    for _ in 0..8 {
        plans = plans
            .iter()
            .map(|p| at_scale(an, s, &d.loads, p, standard_above(p.mu)))
            .collect::<Option<Vec<_>>>()?;
        if let Some(f) = try_figure(an, s, opt, (field, may_drop), &plans) {
            return Some(f);
        }
    }
    None
}

/// `plan` built again at the scale `mu` N/mm (the force construction of
/// its group or input at that μ_F).
fn at_scale(an: &Analysis, s: &Solved, loads: &[Load], plan: &ForcePlan, mu: f64) -> Option<ForcePlan> {
    let which = match (plan.group, plan.input) {
        (Some(g), _) => Which::Group(g),
        (None, Some(i)) => Which::Input(i),
        (None, None) => return None,
    };
    let all = force_plan::solve_at(an, s, loads, plan.delta, Some((which, mu))).ok()?;
    all.plans
        .into_iter()
        .find(|p| p.group == plan.group && p.input == plan.input)
}

/// [`figure`] of the force plans `plans` as they are built.
fn try_figure(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    (field, may_drop): ((f64, f64), bool),
    plans: &[ForcePlan],
) -> Option<Figure> {
    let d = s.dynamics.as_ref()?;
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
    let body = |i: usize, mu: f64| -> Canvas {
        let mut c = Canvas::default();
        free_body::draw(&scene(i), &plans[i], &mut c, mu);
        c
    };
    let real: Vec<Rect> = plans
        .iter()
        .enumerate()
        .map(|(i, p)| free_body::extent(&scene(i), p))
        .collect();
    let name = |f| names::force(&an.mech, loads, f, opt.lang);
    // The polygons with their equations under them; where no grid holds
    // those and `may_drop` (a small field with no larger format to go to:
    // the A2 course sheet), the polygons alone.
    let draw_polygons = |equations: bool| -> Vec<Canvas> {
        plans
            .iter()
            .enumerate()
            .map(|(i, plan)| {
                let mut c = Canvas::default();
                force_polygon::draw(plan, &name, &mut c, 1.0, &tags[i]);
                if equations {
                    force_polygon::equation(plan, &name, &mut c, &tags[i]);
                }
                c
            })
            .collect()
    };
    let box_of = |polygons: &[Canvas]| {
        polygons.iter().fold((0.0f64, 0.0f64), |a, c| {
            let b = c.bounds();
            (a.0.max(b.width()), a.1.max(b.height()))
        })
    };
    // The note's lines under the panels.
    let note = note_lines(opt.lang, field.0);
    let note_band = NOTE_LINE * super::canvas::lettering() * note.len() as f64;
    let panels = (field.0, field.1 - note_band);
    let mut polygons = draw_polygons(true);
    let mut polygon = box_of(&polygons);
    let mut found = best_grid(plans.len(), (panels, polygon), &real, &body);
    if found.is_none() && may_drop {
        polygons = draw_polygons(false);
        polygon = box_of(&polygons);
        found = best_grid(plans.len(), (panels, polygon), &real, &body);
    }
    let (grid, bodies) = found?;
    let smallest = bodies
        .iter()
        .zip(&real)
        .map(|((mu, _), r)| r.width().max(r.height()) / mu)
        .fold(f64::INFINITY, f64::min);
    let mut out = Canvas::default();
    let (mut mu_l, mut mu_f) = (Vec::new(), Vec::new());
    for (i, (plan, (mu, body))) in plans.iter().zip(&bodies).enumerate() {
        let caption = [
            Label::new(caption(an, plan, opt.lang), ""),
            super::captions::scale_label("l", *mu, "m", opt.lang),
        ];
        draw_panel(
            &mut out,
            (plan, &tags[i]),
            (body, &polygons[i]),
            grid.panel(i),
            caption,
            opt.lang,
        );
        mu_l.push(*mu);
        mu_f.push(plan.mu);
    }
    // The note at the foot of the field: the arrows are not to scale.
    let line = NOTE_LINE * super::canvas::lettering();
    for (j, text) in note.iter().enumerate() {
        out.rich_id(
            Point::new(0.0, -field.1 + (note.len() - 1 - j) as f64 * line + 1.5),
            text,
            FONT,
            ("note", "start"),
            format!("forces-note-{j}"),
        );
    }
    Some(Figure {
        canvas: out,
        mu_l,
        mu_f,
        smallest,
    })
}

/// The grid of `count` panels on `field` whose smallest free body is
/// drawn largest (each at its own μ_l from its real extent in `real`;
/// `body` draws body i at a μ_l), its polygons' box `polygon` (mm) beside
/// each: one to three columns; with each body's μ_l and drawing; `None`
/// where no grid holds the polygons.
fn best_grid(
    count: usize,
    (field, polygon): ((f64, f64), (f64, f64)),
    real: &[Rect],
    body: &impl Fn(usize, f64) -> Canvas,
) -> Option<(Grid, Vec<(f64, Canvas)>)> {
    // (smallest body, the grid, the bodies drawn)
    type Candidate = (f64, Grid, Vec<(f64, Canvas)>);
    let mut best: Option<Candidate> = None;
    for cols in (1..=3usize).filter(|&c| c <= count) {
        let grid = Grid {
            cols,
            rows: count.div_ceil(cols),
            field,
            polygon,
        };
        let (_, (bw, bh), (_, ph)) = grid.panel(0);
        if bw < MIN_BODY || bh < MIN_BODY || ph < polygon.1 {
            continue;
        }
        let drawn: Option<Vec<(f64, Canvas)>> = real
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let lower = lower_scale(r.width(), r.height(), (bw, bh));
                fill(lower, (bw, bh), |mu| Some(body(i, mu)), |c| c.bounds())
            })
            .collect();
        let Some(drawn) = drawn else { continue };
        // The bodies themselves (their joints), not their arrows and letters.
        let smallest = drawn
            .iter()
            .zip(real)
            .map(|((mu, _), r)| r.width().max(r.height()) / mu)
            .fold(f64::INFINITY, f64::min);
        if best.as_ref().is_none_or(|b| smallest > b.0) {
            best = Some((smallest, grid, drawn));
        }
    }
    best.map(|(_, g, d)| (g, d))
}

/// Draw one panel into `out`: the `caption` (the group, its μ_l), the free
/// body `body` in its box and the polygon of `plan` drawn at its own μ_F
/// (`poly`, ids tagged `tag`) in its box, with μ_F under it.
fn draw_panel(
    out: &mut Canvas,
    (plan, tag): (&ForcePlan, &str),
    (body, poly): (&Canvas, &Canvas),
    (corner, (bw, bh), (pw, ph)): (Point, (f64, f64), (f64, f64)),
    caption: [Label; 2],
    lang: Lang,
) {
    let top = corner.y - Grid::head();
    let mu = plan.mu;
    let line = CAPTION * super::canvas::lettering();
    for (j, label) in caption.into_iter().enumerate() {
        out.text(
            Point::new(corner.x, corner.y - FONT - j as f64 * line),
            label,
            FONT,
            "caption",
        );
    }
    let centre_in = |c: &Canvas, r: Rect| {
        let b = c.bounds();
        r.center() - b.center()
    };
    let d = centre_in(body, Rect::new(corner.x, top - bh, corner.x + bw, top));
    out.append(body, d.x, d.y);
    let px = corner.x + bw + GAP;
    let d = centre_in(poly, Rect::new(px, top - ph, px + pw, top));
    out.append(poly, d.x, d.y);
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
}

/// The force sheets of position `s`, each with its size (none without
/// force plans). Where the user asked for the sheet (`--sheet`:
/// `opt.fixed_sheet`), on it: every group on one sheet where a grid
/// holds them (the polygons' equations left off where that is what it
/// takes), else each group on a sheet of its own (`forces_N_M`), and only
/// a group no such sheet holds on a larger one. Else one sheet, on the
/// run's sheet or the first larger one on which each free body is drawn
/// at least [`LEAST_BODY`].
pub(super) fn sheets_of(an: &Analysis, s: &Solved, opt: &DrawOptions) -> Vec<(SheetSize, Figure)> {
    let Some(plans) = s
        .dynamics
        .as_ref()
        .and_then(|d| d.force_plans.as_ref())
        .map(|f| &f.plans[..])
    else {
        return Vec::new();
    };
    if !opt.fixed_sheet {
        return larger_force_figure(an, s, opt, plans).into_iter().collect();
    }
    let field = field_size(opt, 0.0);
    let on_asked = |plans: &[ForcePlan]| {
        figure_of(an, s, opt, (field, false), plans)
            .or_else(|| figure_of(an, s, opt, (field, true), plans))
            .map(|f| (opt.sheet, f))
    };
    if let Some(whole) = on_asked(plans) {
        return vec![whole];
    }
    plans
        .chunks(1)
        .filter_map(|one| on_asked(one).or_else(|| larger_force_figure(an, s, opt, one)))
        .collect()
}

/// The force sheet of `plans` on the run's sheet or the first larger one
/// on which every free body is drawn at least [`LEAST_BODY`],
/// else on the largest that holds them.
fn larger_force_figure(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    plans: &[ForcePlan],
) -> Option<(SheetSize, Figure)> {
    let mut last = None;
    for size in SheetSize::ALL.into_iter().filter(|z| z.mm().0 >= opt.sheet.mm().0) {
        let o = DrawOptions { sheet: size, ..*opt };
        // None: none of the grids holds the polygons.
        let Some(f) = figure_of(an, s, &o, (field_size(&o, 0.0), false), plans) else {
            continue;
        };
        if f.smallest >= LEAST_BODY {
            return Some((size, f));
        }
        last = Some((size, f));
    }
    last
}
