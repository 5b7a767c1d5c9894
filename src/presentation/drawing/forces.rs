//! The force analysis of one position on paper (`forces_<k>`): for every
//! step of the graphical route, in the order solved (the last Assur group
//! first, the input link last), the group's free-body drawing at μ_l
//! ([`free_body`]) and its force polygon at its own μ_F beside it
//! ([`force_polygon`]), captioned. Each free body and each polygon has the
//! largest standard scale at which it fills its box (its μ_l and μ_F
//! written in its panel), as the course draws each group apart.

use crate::kinematics::construction::scale::Series;
use super::canvas::{Canvas, FONT, Label, Prim};
use super::free_body::{self, Scene};
use super::layout::field_size;
use super::{DrawOptions, SheetSize, fill, force_polygon, lower_scale, table};
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::force_plan::{self, ForcePlan, Which};
use crate::kinematics::construction::scale::standard_above;
use crate::kinetostatics::loads::Load;
use crate::model::structure::Stage;
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

/// How much larger the main group's panel is than the others (its row's
/// height, its width in its row), as a weight against their 1.
const MAIN_WEIGHT: f64 = 1.5;

/// How many times a polygon may be built at the next standard μ_F up
/// from its plan's where no grid holds the polygons.
const ROUNDS: usize = 8;

/// The least share of its box's width or height a polygon's vectors span
/// for it to be drawn there (where a box holds it only smaller, its names
/// and details crowd it out: a larger box is wanted).
const LEAST_SPAN: f64 = 0.4;

/// The shares of a panel's width (less the gap) its polygon's box may
/// take: the smallest that holds the polygons leaves the free bodies the
/// most.
const POLYGON_SHARES: [f64; 3] = [0.4, 0.5, 0.62];

/// Panels in a grid on a field: each its caption and scale on top, its
/// free body on the left, its polygon on the right in a box of its own.
/// The main group's panel (the first group attached to the input) is the
/// largest: its row taller, and it wider than the others in its row. Each
/// free body is drawn at its own μ_l and each polygon built at its own
/// μ_F, the largest standard scales that fill their boxes, as the course
/// draws each group apart: one μ_l for all would shrink the input link to
/// a blob beside a large group.
#[derive(Clone, Copy)]
struct Grid {
    cols: usize,
    rows: usize,
    field: (f64, f64),
    /// The main group's panel (its place among the plans).
    main: Option<usize>,
    /// The share of a panel's width its polygon's box takes.
    share: f64,
}

impl Grid {
    /// Row `r`'s weight in the field's height.
    fn row_weight(&self, r: usize) -> f64 {
        match self.main {
            Some(m) if self.rows > 1 && m / self.cols == r => MAIN_WEIGHT,
            _ => 1.0,
        }
    }
    /// Column `c`'s weight in row `r`'s width.
    fn col_weight(&self, r: usize, c: usize) -> f64 {
        match self.main {
            Some(m) if self.cols > 1 && m / self.cols == r && m % self.cols == c => MAIN_WEIGHT,
            _ => 1.0,
        }
    }
    /// The band at a panel's top: its caption and its μ_l.
    fn head() -> f64 {
        2.0 * CAPTION * super::canvas::lettering()
    }
    /// Panel `i`'s top left corner (drawing coordinates, y up), its width
    /// and height.
    fn cell(&self, i: usize) -> (Point, f64, f64) {
        let (col, row) = (i % self.cols, i / self.cols);
        let rows: f64 = (0..self.rows).map(|r| self.row_weight(r)).sum();
        let unit_h = (self.field.1 - GAP * (self.rows - 1) as f64) / rows;
        let above: f64 = (0..row).map(|r| self.row_weight(r)).sum();
        let cols: f64 = (0..self.cols).map(|c| self.col_weight(row, c)).sum();
        let unit_w = (self.field.0 - GAP * (self.cols - 1) as f64) / cols;
        let left: f64 = (0..col).map(|c| self.col_weight(row, c)).sum();
        (
            Point::new(
                left * unit_w + col as f64 * GAP,
                -(above * unit_h + row as f64 * GAP),
            ),
            self.col_weight(row, col) * unit_w,
            self.row_weight(row) * unit_h,
        )
    }
    /// Panel `i`'s top left corner (drawing coordinates, y up), its free
    /// body's box and its polygon's box (w × h).
    fn panel(&self, i: usize) -> (Point, (f64, f64), (f64, f64)) {
        let (corner, cw, rh) = self.cell(i);
        let h = rh - Grid::head();
        let pw = (cw - GAP) * self.share;
        (corner, (cw - GAP - pw, h), (pw, h - SCALE_LINE))
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
        .or_else(|| figure_in(an, s, opt, (field, may_drop, false), &fp.plans))
}

/// The place among `plans` of the main group's: the first Assur group
/// attached to the input (the first solved, the last plan of a group).
fn main_plan(an: &Analysis, plans: &[ForcePlan]) -> Option<usize> {
    let first = an.structure.stages.iter().find_map(|st| match st {
        Stage::Group(g) => Some(*g),
        Stage::Input(_) => None,
    })?;
    plans.iter().position(|p| p.group == Some(first))
}

/// `plan` built again at the scale `mu` N/mm (the force construction of
/// its group or input at that μ_F); itself where it is built at `mu`.
fn at_scale(an: &Analysis, s: &Solved, loads: &[Load], plan: &ForcePlan, mu: f64) -> Option<ForcePlan> {
    if (plan.mu - mu).abs() <= 1e-12 * mu {
        return Some(plan.clone());
    }
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

/// The real extent of `plan`'s points, w × h (N).
fn real_extent(plan: &ForcePlan) -> (f64, f64) {
    let r = plan.points.iter().fold(None, |r: Option<Rect>, p| {
        let q = Rect::from_points(p.to_point(), p.to_point());
        Some(r.map_or(q, |r| r.union(q)))
    });
    r.map_or((0.0, 0.0), |r| (r.width() * plan.mu, r.height() * plan.mu))
}

/// A polygon built and drawn: its plan at the μ_F it is drawn at, and
/// its drawing (the polygon, its details, its equation).
type Polygon = (ForcePlan, Canvas);

/// The figure of position `s`'s force plans `plans` (all, or one group's
/// where a sheet holds them one by one) on a field of `field` mm; `None`
/// where none, or where no grid holds them. Each polygon is built again
/// at the smallest standard μ_F at which it fills its box: a
/// construction at that scale, stated in its panel.
pub fn figure_of(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    (field, may_drop): ((f64, f64), bool),
    plans: &[ForcePlan],
) -> Option<Figure> {
    figure_in(an, s, opt, (field, may_drop, true), plans)
}

/// [`figure_of`]; with `legible`, only where each polygon's vectors span
/// at least [`LEAST_SPAN`] of its box one way (else the box is too small
/// for it, its names and details: a larger sheet, or a sheet of its
/// own, holds it); without, at whatever μ_F its box holds it (up to
/// [`ROUNDS`] standard values above its plan's).
fn figure_in(
    an: &Analysis,
    s: &Solved,
    opt: &DrawOptions,
    (field, may_drop, legible): ((f64, f64), bool, bool),
    plans: &[ForcePlan],
) -> Option<Figure> {
    let d = s.dynamics.as_ref()?;
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
    // Each free body drawn once at a scale, whichever grids ask for it
    // (placing its labels is most of a force sheet's time).
    let bodies_drawn = std::cell::RefCell::new(std::collections::HashMap::new());
    let body = |i: usize, mu: f64| -> Canvas {
        bodies_drawn
            .borrow_mut()
            .entry((i, mu.to_bits()))
            .or_insert_with(|| {
                let mut c = Canvas::default();
                free_body::draw(&scene(i), &plans[i], &mut c, mu);
                c
            })
            .clone()
    };
    let real: Vec<Rect> = plans
        .iter()
        .enumerate()
        .map(|(i, p)| free_body::extent(&scene(i), p))
        .collect();
    let name = |f| names::force(&an.mech, loads, f, opt.lang);
    // Polygon i with its equation under it (or without) built at the
    // scale that fills a box, from the scale its real extent fits at (as
    // built where it is all at the pole), at most `cap`.
    let polygon = |i: usize, bx: (f64, f64), (equations, cap): (bool, f64)| -> Option<Polygon> {
        let draw = |plan: ForcePlan| {
            let mut c = Canvas::default();
            c.group_id("force-polygon", format!("{}-polygon", tags[i]), |c| {
                force_polygon::draw(&plan, &name, c, (1.0, bx.1 > bx.0), &tags[i]);
                if equations {
                    force_polygon::equation(&plan, &name, c, (&tags[i], bx.0));
                }
            });
            Some((plan, c))
        };
        let p = &plans[i];
        let (w, h) = real_extent(p);
        let lower = match w.max(h) > 1e-9 {
            true => lower_scale(w, h, bx).min(cap),
            false => p.mu,
        };
        let build = |mu: f64| {
            (mu <= cap * (1.0 + 1e-9))
                .then(|| at_scale(an, s, loads, p, mu).and_then(draw))
                .flatten()
        };
        let (_, (plan, c)) = fill(Series::Plans, lower, bx, build, |(_, c)| c.bounds())?;
        // Its vectors' span in its box (mm: the plan's points are drawn
        // as built); a plan all at the pole spans nothing at any scale.
        let (w, h) = real_extent(p);
        let held = !legible || span(&plan, bx) >= LEAST_SPAN || w.max(h) <= 1e-9;
        held.then_some((plan, c))
    };
    // The note's lines under the panels.
    let note = note_lines(opt.lang, field.0);
    let note_band = NOTE_LINE * super::canvas::lettering() * note.len() as f64;
    let panels = ((field.0, field.1 - note_band), main_plan(an, plans));
    // Each polygon at most as small as built (its longest vector 40–80
    // mm); where no grid holds them so, at most the next standard μ_F up,
    // round by round. The polygons with their equations under them; where
    // no grid holds those and `may_drop` (a small field with no larger
    // format to go to: the A2 course sheet), the polygons alone.
    let grids = grids(plans.len(), panels, &real, &body);
    let mut caps: Vec<f64> = plans.iter().map(|p| p.mu).collect();
    let mut found = None;
    for _ in 0..=ROUNDS {
        let try_with = |equations: bool| {
            let each = |i: usize, b: (f64, f64)| polygon(i, b, (equations, caps[i]));
            holding(&grids, &each, legible)
        };
        found = try_with(true).or_else(|| may_drop.then(|| try_with(false)).flatten());
        if found.is_some() {
            break;
        }
        caps = caps.iter().map(|&m| standard_above(m)).collect();
    }
    let (k, polygons) = found?;
    let (grid, bodies) = &grids[k];
    let smallest = bodies
        .iter()
        .zip(&real)
        .map(|((mu, _), r)| r.width().max(r.height()) / mu)
        .fold(f64::INFINITY, f64::min);
    let (canvas, mu_l, mu_f) = compose(an, opt.lang, (grid, bodies, &polygons), (&note, field.1));
    Some(Figure {
        canvas,
        mu_l,
        mu_f,
        smallest,
    })
}

/// The figure's drawing: the panels of `grid` with their free bodies
/// `bodies` and polygons `polygons`, the note's lines `note` at the foot
/// of a field `height` mm high; with each body's μ_l and each polygon's
/// μ_F.
fn compose(
    an: &Analysis,
    lang: Lang,
    (grid, bodies, polygons): (&Grid, &[(f64, Canvas)], &[Polygon]),
    (note, height): (&[String], f64),
) -> (Canvas, Vec<f64>, Vec<f64>) {
    let mut out = Canvas::default();
    let (mut mu_l, mut mu_f) = (Vec::new(), Vec::new());
    for (i, ((mu, body), (plan, poly))) in bodies.iter().zip(polygons).enumerate() {
        let caption = [
            Label::new(caption(an, plan, lang), ""),
            super::captions::scale_label("l", *mu, "m", lang),
        ];
        draw_panel(
            &mut out,
            (plan, &format!("f{}", i + 1)),
            (body, poly),
            (grid.panel(i), grid.cell(i)),
            caption,
            lang,
        );
        mu_l.push(*mu);
        mu_f.push(plan.mu);
    }
    // The note at the foot of the field: the arrows are not to scale.
    let line = NOTE_LINE * super::canvas::lettering();
    for (j, text) in note.iter().enumerate() {
        out.rich_id(
            Point::new(0.0, -height + (note.len() - 1 - j) as f64 * line + 1.5),
            text,
            FONT,
            ("note", "start"),
            format!("forces-note-{j}"),
        );
    }
    (out, mu_l, mu_f)
}

/// A grid with its free bodies drawn: each body's μ_l and drawing.
type Bodies = (Grid, Vec<(f64, Canvas)>);

/// The grids of `count` panels on `field` (the main group's panel `main`
/// the largest) that hold the free bodies, of one to three columns and
/// each share of a panel for its polygon ([`POLYGON_SHARES`]), the one
/// whose smallest free body is drawn largest first (each at its own μ_l
/// from its real extent in `real`; `body` draws body i at a μ_l).
fn grids(
    count: usize,
    (field, main): ((f64, f64), Option<usize>),
    real: &[Rect],
    body: &impl Fn(usize, f64) -> Canvas,
) -> Vec<Bodies> {
    let mut out: Vec<(f64, Bodies)> = Vec::new();
    let each = (1..=3usize)
        .filter(|&c| c <= count)
        .flat_map(|c| POLYGON_SHARES.map(|share| (c, share)));
    for (cols, share) in each {
        let grid = Grid {
            cols,
            rows: count.div_ceil(cols),
            field,
            main,
            share,
        };
        let boxes: Vec<_> = (0..count).map(|i| grid.panel(i).1).collect();
        if boxes.iter().any(|(bw, bh)| *bw < MIN_BODY || *bh < MIN_BODY) {
            continue;
        }
        let drawn: Option<Vec<(f64, Canvas)>> = real
            .iter()
            .zip(&boxes)
            .enumerate()
            .map(|(i, (r, b))| {
                let lower = lower_scale(r.width(), r.height(), *b);
                fill(Series::Drawing, lower, *b, |mu| Some(body(i, mu)), |c| c.bounds())
            })
            .collect();
        let Some(drawn) = drawn else { continue };
        // The bodies themselves (their joints), not their arrows and letters.
        let smallest = drawn
            .iter()
            .zip(real)
            .map(|((mu, _), r)| r.width().max(r.height()) / mu)
            .fold(f64::INFINITY, f64::min);
        out.push((smallest, (grid, drawn)));
    }
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    out.into_iter().map(|(_, g)| g).collect()
}

/// The grid of `grids` in whose boxes `polygon` builds every polygon,
/// with the polygons: with `first`, the first such (its bodies the
/// largest); else the one whose least filled polygon spans the most of
/// its box.
fn holding(
    grids: &[Bodies],
    polygon: &dyn Fn(usize, (f64, f64)) -> Option<Polygon>,
    first: bool,
) -> Option<(usize, Vec<Polygon>)> {
    let mut best: Option<(f64, (usize, Vec<Polygon>))> = None;
    for (k, (grid, drawn)) in grids.iter().enumerate() {
        let polygons: Option<Vec<Polygon>> = (0..drawn.len())
            .map(|i| polygon(i, grid.panel(i).2))
            .collect();
        let Some(polygons) = polygons else { continue };
        if first {
            return Some((k, polygons));
        }
        let least = polygons
            .iter()
            .enumerate()
            .map(|(i, (plan, _))| span(plan, grid.panel(i).2))
            .fold(f64::INFINITY, f64::min);
        if best.as_ref().is_none_or(|b| least > b.0) {
            best = Some((least, (k, polygons)));
        }
    }
    best.map(|(_, b)| b)
}

/// The larger share of box `bx`'s width or height (mm) `plan`'s vectors
/// span (its points are drawn as built).
fn span(plan: &ForcePlan, bx: (f64, f64)) -> f64 {
    let (w, h) = real_extent(plan);
    (w / bx.0).max(h / bx.1) / plan.mu
}

/// A panel's place: its corner, its free body's and polygon's boxes
/// ([`Grid::panel`]), and its corner, width and height ([`Grid::cell`]).
type Panel = ((Point, (f64, f64), (f64, f64)), (Point, f64, f64));

/// Draw one panel into `out`: the `caption` (the group, its μ_l), the free
/// body `body` in its box and the polygon of `plan` drawn at its own μ_F
/// (`poly`, ids tagged `tag`) in its box, with μ_F under it.
fn draw_panel(
    out: &mut Canvas,
    (plan, tag): (&ForcePlan, &str),
    (body, poly): (&Canvas, &Canvas),
    ((corner, (bw, bh), (pw, ph)), (_, cw, rh)): Panel,
    caption: [Label; 2],
    lang: Lang,
) {
    let top = corner.y - Grid::head();
    // The panel and the polygon's box, not drawn: the checks read them.
    let px = corner.x + bw + GAP;
    out.region(
        Rect::new(corner.x, corner.y - rh, corner.x + cw, corner.y),
        format!("{tag}-panel"),
    );
    out.region(Rect::new(px, top - ph, px + pw, top), format!("{tag}-polygon-box"));
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
/// takes), else each group on a sheet of its own (`forces_N_M`), its
/// polygon smaller where that is what it takes, and only a group no such
/// sheet holds on a larger one. Else one sheet, on the
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
    let on_asked = |plans: &[ForcePlan], legible: bool| {
        figure_in(an, s, opt, (field, false, legible), plans)
            .or_else(|| figure_in(an, s, opt, (field, true, legible), plans))
            .map(|f| (opt.sheet, f))
    };
    if let Some(whole) = on_asked(plans, true) {
        return vec![whole];
    }
    plans
        .chunks(1)
        .filter_map(|one| {
            on_asked(one, true)
                .or_else(|| on_asked(one, false))
                .or_else(|| larger_force_figure(an, s, opt, one))
        })
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
    // None holds the polygons legibly: the largest as it may.
    last.or_else(|| {
        let o = DrawOptions {
            sheet: SheetSize::ALL.into_iter().last()?,
            ..*opt
        };
        let f = figure_in(an, s, &o, (field_size(&o, 0.0), true, false), plans)?;
        Some((o.sheet, f))
    })
}
