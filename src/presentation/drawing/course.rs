//! The course sheet: the kinematic analysis sheet of a TMM course project
//! (A1, or A2), composed of the mechanism in all its positions with the
//! trajectories, the plans of velocities of the positions (one scale for
//! all), the plans of accelerations of the chosen positions, the kinematic
//! diagrams of the output, the tables of results and the main title block.
//!
//! The layout is found, not fixed: every figure is drawn at the scale that
//! fills a target box (its share of the field, in its own proportions),
//! and the figures are packed into the field by a skyline packer (each
//! placed where its bottom stays highest, then leftmost) around the title
//! block. The shares are grown together while everything still packs
//! (a bisection on one zoom factor), so the sheet is as full as standard
//! scales allow.

use super::canvas::{Canvas, SMALL};
use super::pack::{Figure, GAP, caption_line, field_of, pack, place, round3, size};
use super::sheet::{self, Page};
use super::table::{self, Ruled, number, unit};
use super::{DrawOptions, Sheet, SheetSize, lower_scale, positions, scale_text, words};
use crate::error::Result;
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::scale::Series;
use crate::kinematics::construction::{Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::model::scene::PositionsSpec;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use crate::studies::sheet_data::SheetData;
use kurbo::{Point, Rect};
use std::collections::HashMap;
use std::rc::Rc;

/// What each figure draws at a scale (or at its only size).
enum Source<'a> {
    Positions(positions::Drawn<'a>),
    /// The velocity plans of these positions (the k-th, from 1: not their
    /// numbers, which `position_number` gives) at one μ_v, in a
    /// grid of this many columns.
    Velocities(Vec<usize>, usize),
    /// The acceleration plan of a position.
    Acceleration(usize),
    /// Drawn once, at its own size (the diagrams, a table).
    Fixed(Rc<Figure>),
}

/// The factor on the lettering of the course sheets: the labels drawn
/// at 2.5 mm elsewhere are 3.5 mm (ГОСТ 2.304's smallest size for an A1
/// drawing read at arm's length), their indices 2.5 mm.
pub const COURSE_LETTERING: f64 = 2.5 / (0.7 * 2.5) * 1.0001;

/// The course sheet of `solved` (every position of the scene), with what
/// it draws beyond them solved in `data` (trajectories, chosen positions,
/// diagrams: [`crate::studies::sheet_data`]), its lettering
/// [`COURSE_LETTERING`] times the other sheets'.
pub fn sheet(an: &Analysis, solved: &[Solved], data: &SheetData, opt: &DrawOptions) -> Result<Sheet> {
    super::canvas::with_lettering(COURSE_LETTERING, || course_sheet(an, solved, data, opt))
}

/// The sheet's figures placed on its field, and the positions whose plans
/// they show (velocity, acceleration).
type Layout = (Vec<(Figure, Point)>, (Vec<usize>, Vec<usize>));

fn layout(an: &Analysis, solved: &[Solved], data: &SheetData, opt: &DrawOptions) -> Result<Layout> {
    let size = size(opt);
    let lang = opt.lang;
    let t = positions::given(data, solved.len())?;
    let chosen = (data.chosen.velocity.clone(), data.chosen.acceleration.clone());
    // The velocity plans' grid and the diagrams' length: of the column
    // counts and lengths tried, the layout that draws the figures largest
    // by [`score`]. A grid of 5 × 3 cells, each as wide as its column's
    // widest plan, leaves the plans 25–40 mm long on A1; 6 × 2 or 4 × 3
    // may hold them at the next scale, and shorter diagrams leave room
    // for larger plans.
    let n = chosen.0.len();
    let default = grid(n).0;
    let mut columns: Vec<usize> = [default, n.div_ceil(2), n.div_ceil(3), n.div_ceil(4), default + 1]
        .into_iter()
        .filter(|&c| c >= 1 && c <= n)
        .collect();
    columns.dedup();
    let lengths: &[f64] = match size {
        SheetSize::A1 => &[DIAGRAMS_A1, 0.85 * DIAGRAMS_A1, 0.7 * DIAGRAMS_A1],
        _ => &[120.0],
    };
    let mut best: Option<(f64, Placed)> = None;
    let mut first_err = None;
    let mut base: Option<Vec<(String, f64)>> = None;
    let mut cache = Drawn::new();
    // Sheet 1's data (the structure and given data, the comparison) go
    // with the drawings; where they cannot all pack (an A2 sheet), the
    // comparison is left out first, then the given data.
    let sheet_one: Vec<Rc<Figure>> = std::iter::once(super::course_data::given(an, solved, data, lang))
        .chain(super::course_data::compare(an, solved, data, lang))
        .map(Rc::new)
        .collect();
    for kept in (0..=sheet_one.len()).rev() {
        for &len in lengths {
            let fixed: Vec<Rc<Figure>> = sheet_one[..kept]
                .iter()
                .cloned()
                .chain(fixed_figures(an, solved, data, (lang, len), &chosen).into_iter().map(Rc::new))
                .collect();
            for &cols in &columns {
                let sources = sources((solved, t), &chosen, &fixed, cols);
                let l = match layout_with(an, solved, lang, size, sources, &mut cache) {
                    Ok(l) => l,
                    Err(e) => {
                        first_err.get_or_insert(e);
                        continue;
                    }
                };
                let sc: Vec<(String, f64)> = l
                    .iter()
                    .flat_map(|(f, _)| f.scales.iter().map(|&(k, mu)| (format!("{}/{k}", f.id), mu)))
                    .collect();
                let base = base.get_or_insert_with(|| sc.clone());
                let s = score(base, &sc) + 0.5 * (len / DIAGRAMS_A1).ln();
                if best.as_ref().is_none_or(|b| s > b.0 + 1e-9) {
                    best = Some((s, l));
                }
            }
        }
        if best.is_some() {
            break;
        }
    }
    match best {
        Some((_, l)) => Ok((
            l.into_iter()
                .map(|(f, at)| (Rc::unwrap_or_clone(f), at))
                .collect(),
            chosen,
        )),
        None => Err(first_err.expect("a layout tried")),
    }
}

/// Which drawing a figure is, whatever else the sheet holds: the
/// positions, the grid of velocity plans in so many columns, an
/// acceleration plan.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Positions,
    Velocities(usize),
    Acceleration(usize),
}

/// Every drawing made while the layouts are tried, by what it is and its
/// scale (its bits): each is made once.
type Drawn = HashMap<(Key, u64), Option<Sized>>;

/// A figure drawn, with its size (mm, its caption included).
type Sized = (Rc<Figure>, (f64, f64));

/// Figures placed on the field: each and its top left corner.
type Placed = Vec<(Rc<Figure>, Point)>;

/// The diagrams' length on an A1 course sheet, mm, when nothing else
/// wants the room.
const DIAGRAMS_A1: f64 = 340.0;

/// How much larger a layout's scales `sc` draw the figures than `base`'s:
/// the sum of the logarithms of the ratios, the plans of velocities
/// (the smallest drawings, read on every position) weighing twice, the
/// acceleration plans shared as one.
fn score(base: &[(String, f64)], sc: &[(String, f64)]) -> f64 {
    let acc = sc.iter().filter(|(k, _)| k.ends_with("/mu_a")).count().max(1) as f64;
    sc.iter()
        .filter_map(|(k, mu)| {
            let b = base.iter().find(|b| &b.0 == k)?.1;
            let w = if k.ends_with("/mu_v") {
                2.0
            } else if k.ends_with("/mu_a") {
                1.0 / acc
            } else {
                1.0
            };
            Some(w * (b / mu).ln())
        })
        .sum()
}

/// The figures of `sources` at the largest zooms that pack on the field.
fn layout_with(
    an: &Analysis,
    solved: &[Solved],
    lang: Lang,
    size: SheetSize,
    sources: Vec<(Source<'_>, f64)>,
    cache: &mut Drawn,
) -> Result<Placed> {
    let field = field_of(size);
    let block = sheet::block(size);
    let cx = Ctx {
        an,
        solved,
        lang,
        field,
    };
    // The figures at zooms `z` (one per figure; a figure's target area is
    // its share of the field times z²), and where they go if they pack.
    let attempt = |z: &[f64]| -> Option<Placed> {
        let mut figs: Vec<Sized> = Vec::new();
        for (i, (src, share)) in sources.iter().enumerate() {
            let area = *share * z[i] * z[i] * field.area();
            figs.push(figure(&cx, src, area, cache)?);
        }
        let rects: Vec<(f64, f64)> = figs.iter().map(|f| f.1).collect();
        let at = pack(&rects, field, block)?;
        Some(figs.into_iter().map(|f| f.0).zip(at).collect())
    };
    let shares: Vec<f64> = sources.iter().map(|s| s.1).collect();
    let placed = grow(&shares, attempt).ok_or_else(|| {
        crate::error::Error::Internal(format!(
            "the course sheet's figures do not pack on {size:?}: too many positions or plans for one sheet; choose fewer with want.plans_at"
        ))
    })?;
    Ok(placed)
}

/// The scales the course sheet draws its plans at, by position (from 0:
/// μ_v, μ_a): one μ_v for every velocity plan it shows, each acceleration
/// plan's μ_a. Built at them, the plans state them everywhere. `data`:
/// what the sheet draws beyond `solved`, solved.
pub fn plan_scales(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
) -> Result<crate::kinematics::solve::ScalesAt> {
    let (placed, (vel_at, _)) = super::canvas::with_lettering(COURSE_LETTERING, || {
        layout(an, solved, data, opt)
    })?;
    let mut out = crate::kinematics::solve::ScalesAt::new();
    for (f, _) in &placed {
        for &(key, mu) in &f.scales {
            let at: Vec<usize> = match (key, f.id.strip_prefix("acceleration-")) {
                ("mu_v", _) => vel_at.clone(),
                ("mu_a", Some(k)) => k.parse().into_iter().collect(),
                _ => Vec::new(),
            };
            for k in at {
                let e: &mut (Option<f64>, Option<f64>) = out.entry(k - 1).or_default();
                match key {
                    "mu_v" => e.0 = Some(mu),
                    _ => e.1 = Some(mu),
                }
            }
        }
    }
    Ok(out)
}

fn course_sheet(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
) -> Result<Sheet> {
    let size = size(opt);
    let w = words(opt.lang);
    let (placed, _) = layout(an, solved, data, opt)?;
    let mut page = Page::new(size);
    place(&mut page, &placed);
    let title = w.course.to_string();
    // Sheet 1 of 2 when the force analysis sheet follows.
    let sheets = if position_has_forces(solved, data) {
        2
    } else {
        1
    };
    page.title_block(&super::main_title_block(an, opt, &title, (1, sheets)));
    let scales = placed.iter().flat_map(|(f, _)| f.scales.clone()).collect();
    Ok(Sheet {
        name: super::SheetKind::Course.stem(),
        title,
        position: None,
        size,
        scales,
        svg: page.finish(),
    })
}

/// Whether the positions have plans of velocities, and of accelerations.
fn has_plans(solved: &[Solved]) -> (bool, bool) {
    let has_plans = solved.first().is_some_and(|s| s.plans.is_some());
    let has_acc = solved
        .first()
        .and_then(|s| s.plans.as_ref())
        .is_some_and(|p| p.acceleration.is_some());
    (has_plans, has_acc)
}

/// The figures at their own size: the diagrams (when the crank turns
/// fully, or over the stroke of a hydraulic cylinder, the one input) and
/// the tables of the `chosen` positions' plans.
fn fixed_figures(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    (lang, length): (Lang, f64),
    (vel_at, acc_at): &(Vec<usize>, Vec<usize>),
) -> Vec<Figure> {
    let w = words(lang);
    let (has_plans, has_acc) = has_plans(solved);
    let mut fixed: Vec<Figure> = Vec::new();
    let cylinder = !an.mech.scene.several_inputs() && !super::cylinder::pairs(an).is_empty();
    if (matches!(an.mech.scene.positions, PositionsSpec::Count { .. }) || cylinder)
        && let Some(d) = data.diagrams.as_ref().map(|d| {
            d.at_length(length)
        })
    {
        fixed.push(Figure {
            id: "diagrams".into(),
            caption: vec![super::diagram::title(an, &d, lang)],
            canvas: super::diagram::figure(an, &d, lang),
            scales: Vec::new(),
        });
    }
    let table = |id: &str, at: &[usize], kind: PlanKind, what: &str| Figure {
        id: id.into(),
        caption: vec![format!("{}: {}", w.table, what.to_lowercase())],
        canvas: results(an, solved, at, kind, lang).draw(),
        scales: Vec::new(),
    };
    if has_plans {
        fixed.push(table(
            "table-velocity",
            vel_at,
            PlanKind::Velocity,
            &w.velocities,
        ));
    }
    if has_acc && !acc_at.is_empty() {
        fixed.push(table(
            "table-acceleration",
            acc_at,
            PlanKind::Acceleration,
            &w.accelerations,
        ));
    }
    fixed
}

/// The sheet's figures, each with its share of the field: the positions,
/// the `chosen` positions' plans (drawn at a scale), then the `fixed`
/// ones (share 0).
fn sources<'a>(
    (solved, t): (&[Solved], positions::Drawn<'a>),
    (vel_at, acc_at): &(Vec<usize>, Vec<usize>),
    fixed: &[Rc<Figure>],
    cols: usize,
) -> Vec<(Source<'a>, f64)> {
    let (has_plans, has_acc) = has_plans(solved);
    let mut sources: Vec<(Source, f64)> = vec![(Source::Positions(t), 0.34)];
    if has_plans {
        sources.push((Source::Velocities(vel_at.clone(), cols), 0.22));
    }
    if has_acc {
        for &k in acc_at {
            sources.push((Source::Acceleration(k), 0.2 / acc_at.len() as f64));
        }
    }
    for f in fixed {
        sources.push((Source::Fixed(f.clone()), 0.0));
    }
    sources
}

/// The placed figures of the largest zooms that pack, `attempt` placing
/// them at one zoom a figure: the shares grown together while everything
/// packs (a bisection), then each figure with a share by itself, the
/// largest share first, by the largest step that still packs (a standard
/// scale's next value is ×1.25 to ×2 away), in rounds until none grows.
fn grow<T>(shares: &[f64], mut attempt: impl FnMut(&[f64]) -> Option<T>) -> Option<T> {
    let n = shares.len();
    let (mut lo, mut hi) = (0.2, 1.8);
    let mut best = None;
    for _ in 0..12 {
        let z = 0.5 * (lo + hi);
        match attempt(&vec![z; n]) {
            Some(p) => {
                best = Some(p);
                lo = z;
            }
            None => hi = z,
        }
    }
    let mut zs = vec![lo; n];
    let mut order: Vec<usize> = (0..n).filter(|&i| shares[i] > 0.0).collect();
    order.sort_by(|&a, &b| shares[b].total_cmp(&shares[a]));
    for _round in 0..4 {
        let mut grew = false;
        for &i in &order {
            for _ in 0..6 {
                let step = [2.0, 1.6, 1.25].into_iter().find_map(|k| {
                    let mut z = zs.clone();
                    z[i] *= k;
                    attempt(&z).map(|p| (z, p))
                });
                match step {
                    Some((z, p)) => {
                        best = Some(p);
                        zs = z;
                        grew = true;
                    }
                    None => break,
                }
            }
        }
        if !grew {
            break;
        }
    }
    best
}

/// What the figures need to be drawn.
struct Ctx<'a> {
    an: &'a Analysis,
    solved: &'a [Solved],
    lang: Lang,
    field: Rect,
}

/// Figure `i` from its source at target area `area` (mm²): drawn at the
/// smallest standard scale at which it fits a box of that area in its own
/// proportions; every drawing made is kept in `cache` by figure and scale.
fn figure(
    cx: &Ctx,
    src: &Source,
    area: f64,
    cache: &mut Drawn,
) -> Option<Sized> {
    let key = match src {
        Source::Fixed(f) => return Some((f.clone(), f.size())),
        Source::Positions(_) => Key::Positions,
        Source::Velocities(_, cols) => Key::Velocities(*cols),
        Source::Acceleration(k) => Key::Acceleration(*k),
    };
    let (aspect, lower_w, lower_h) = natural(cx, src)?;
    let bw = (area * aspect).sqrt().min(cx.field.width());
    let bh = (area / aspect).sqrt().min(cx.field.height());
    // The positions are a drawing of the mechanism (ГОСТ 2.302's scales),
    // the rest plans.
    let series = match key {
        Key::Positions => Series::Drawing,
        _ => Series::Plans,
    };
    let mut mu = series.at_least(lower_scale(lower_w, lower_h, (bw, bh)));
    // A box smaller than the figure's lettering allows: the smallest
    // drawing there is (the packer then judges it).
    let mut smallest: Option<(f64, Sized)> = None;
    for _ in 0..16 {
        let f = cache
            .entry((key, mu.to_bits()))
            .or_insert_with(|| {
                draw(cx, src, mu).map(|f| {
                    let size = f.size();
                    (Rc::new(f), size)
                })
            })
            .as_ref()?;
        let (w, h) = f.1;
        if w <= bw && h <= bh {
            return Some(f.clone());
        }
        if smallest.as_ref().is_none_or(|(a, _)| w * h < *a) {
            smallest = Some((w * h, f.clone()));
        }
        mu = series.above(mu);
    }
    smallest.map(|(_, f)| f)
}

/// A source's proportions (w/h) and its real extent (w, h: m, m/s, m/s²;
/// the extent of one cell for a grid of plans, times its columns and rows).
fn natural(cx: &Ctx, src: &Source) -> Option<(f64, f64, f64)> {
    match src {
        Source::Fixed(_) => None,
        Source::Positions(_) => {
            let e = super::mechanism_extent(cx.an, cx.solved.iter().map(|s| &s.config));
            let aspect = (e.width() / e.height().max(1e-12)).clamp(0.5, 3.0);
            Some((aspect, e.width(), e.height()))
        }
        Source::Velocities(at, cols) => {
            let (cols, rows) = (*cols, at.len().div_ceil(*cols));
            let (mut ew, mut eh) = (0.0f64, 0.0f64);
            for &k in at {
                let p = &cx.solved.get(k - 1)?.plans.as_ref()?.velocity;
                let e = extent(p);
                ew = ew.max(e.width() * p.mu);
                eh = eh.max(e.height() * p.mu);
            }
            let (w, h) = (ew * cols as f64, eh * rows as f64);
            Some(((w / h.max(1e-12)).clamp(0.5, 3.0), w, h))
        }
        Source::Acceleration(k) => {
            let p = cx
                .solved
                .get(k - 1)?
                .plans
                .as_ref()?
                .acceleration
                .as_ref()?;
            let e = extent(p);
            let aspect = (e.width() / e.height().max(1e-9)).clamp(0.4, 2.5);
            Some((aspect, e.width() * p.mu, e.height() * p.mu))
        }
    }
}

/// Columns and rows of a grid of `n` plans, wider than high.
fn grid(n: usize) -> (usize, usize) {
    let n = n.max(1);
    let cols = ((n as f64 * 1.6).sqrt().ceil() as usize).clamp(1, n);
    (cols, n.div_ceil(cols))
}

/// A source drawn at scale `mu`.
fn draw(cx: &Ctx, src: &Source, mu: f64) -> Option<Figure> {
    let (an, solved, lang) = (cx.an, cx.solved, cx.lang);
    let w = words(lang);
    match src {
        Source::Fixed(f) => Some((**f).clone()),
        Source::Positions(t) => {
            let mut c = Canvas::default();
            let configs: Vec<_> = solved.iter().map(|s| &s.config).collect();
            let bold = solved.get(t.bold)?;
            positions::draw(an, (bold, &configs), *t, &mut c, mu);
            Some(Figure {
                id: "positions".into(),
                caption: vec![format!(
                    "{}, {}",
                    w.positions,
                    scale_text("l", mu, "m", lang)
                )],
                canvas: c,
                scales: vec![("mu_l", mu)],
            })
        }
        Source::Velocities(at, cols) => {
            let cols = *cols;
            let cs: Vec<Canvas> = at
                .iter()
                .map(|&k| {
                    let s = solved.get(k - 1)?;
                    let p = an
                        .plans_at_scales(s, Order::Velocity, Some(mu), None)
                        .ok()?;
                    let mut c = Canvas::default();
                    super::plan::draw(&p.velocity, &mut c, &an.points);
                    Some(c)
                })
                .collect::<Option<_>>()?;
            // Columns as wide as their widest plan, rows as high as their
            // highest; each plan centred in its cell under its number.
            let rows = cs.len().div_ceil(cols);
            let mut cw = vec![0.0f64; cols];
            let mut ch = vec![0.0f64; rows];
            for (j, c) in cs.iter().enumerate() {
                let b = c.bounds();
                cw[j % cols] = cw[j % cols].max(b.width() + GAP);
                ch[j / cols] = ch[j / cols].max(b.height() + caption_line() + GAP);
            }
            let xs: Vec<f64> = (0..cols).map(|i| cw[..i].iter().sum()).collect();
            let ys: Vec<f64> = (0..rows).map(|i| -ch[..i].iter().sum::<f64>()).collect();
            let mut g = Canvas::default();
            for (j, (c, &k)) in cs.iter().zip(at).enumerate() {
                let (col, row) = (j % cols, j / cols);
                let (x0, y0, w_, h_) = (xs[col], ys[row], cw[col], ch[row]);
                let b = c.bounds();
                let ox = x0 + (w_ - b.width()) / 2.0 - b.x0;
                let oy = y0 - caption_line() - (h_ - caption_line() - b.height()) / 2.0 - b.y1;
                g.append(c, ox, oy);
                g.rich(
                    Point::new(x0 + w_ / 2.0, y0 - caption_line() + 1.5),
                    &format!("{} {}", w.position, crate::presentation::position_number(an, k - 1)),
                    SMALL,
                    "caption",
                    "middle",
                );
            }
            Some(Figure {
                id: "velocity".into(),
                caption: vec![format!(
                    "{}, {}",
                    plural_velocities(lang),
                    scale_text("v", mu, "m/s", lang)
                )],
                canvas: g,
                scales: vec![("mu_v", mu)],
            })
        }
        Source::Acceleration(k) => {
            let s = solved.get(k - 1)?;
            let p = an
                .plans_at_scales(s, Order::Acceleration, None, Some(mu))
                .ok()?;
            let mut c = Canvas::default();
            super::plan::draw(p.acceleration.as_ref()?, &mut c, &an.points);
            Some(Figure {
                id: format!("acceleration-{k}"),
                caption: vec![
                    format!(
                        "{}, {} {}",
                        w.accelerations,
                        w.position,
                        crate::presentation::position_number(an, k - 1)
                    ),
                    scale_text("a", mu, "m/s²", lang),
                ],
                canvas: c,
                scales: vec![("mu_a", mu)],
            })
        }
    }
}

/// "Plans of velocities", localised.
fn plural_velocities(l: Lang) -> &'static str {
    &super::words(l).velocity_plans
}

/// A plan's extent in its own mm, the pole included.
fn extent(p: &Plan) -> Rect {
    p.points.iter().fold(Rect::ZERO, |r, q| {
        let a = q.at.to_point();
        r.union(Rect::from_points(a, a))
    })
}

/// The table of the results of the positions `at` (the k-th, from 1;
/// headed by their numbers as the sheets show them): a row per
/// quantity the plans give (its unit in the first column), a column per
/// position.
fn results(an: &Analysis, solved: &[Solved], at: &[usize], kind: PlanKind, lang: Lang) -> Ruled {
    let plan_of = |k: usize| -> Option<&Plan> {
        let p = solved.get(k - 1)?.plans.as_ref()?;
        match kind {
            PlanKind::Velocity => Some(&p.velocity),
            PlanKind::Acceleration => p.acceleration.as_ref(),
        }
    };
    // Every quantity of any of the positions, in the order first met.
    let mut names: Vec<(String, &'static str, bool)> = Vec::new();
    let mut values: Vec<HashMap<String, f64>> = Vec::new();
    for &k in at {
        let mut m = HashMap::new();
        if let Some(p) = plan_of(k) {
            for r in table::plan_rows(p) {
                if !names.iter().any(|n| n.0 == r.quantity) {
                    names.push((r.quantity.clone(), r.unit, r.rate));
                }
                m.insert(r.quantity, r.value);
            }
        }
        values.push(m);
    }
    let head_q = &super::words(lang).quantity_unit;
    let mut head = vec![head_q.to_string()];
    // Headed by the numbers the sheet writes (the lecture's, from 0).
    head.extend(
        at.iter()
            .map(|&k| crate::presentation::position_number(an, k - 1).to_string()),
    );
    let rows = names
        .iter()
        .map(|(q, u, rate)| {
            let mut r = vec![format!("{q}, {}", unit(u, lang))];
            for m in &values {
                r.push(match m.get(q) {
                    Some(v) if *rate => table::rate(round3(*v), lang),
                    Some(v) => number(round3(*v), lang),
                    None => "—".into(),
                });
            }
            r
        })
        .collect();
    Ruled { head, rows }
}

/// Whether the second sheet is drawn: the analysed position has force
/// plans.
pub fn position_has_forces(solved: &[Solved], data: &SheetData) -> bool {
    !solved.is_empty()
        && solved[data.chosen.analysed(solved.len())]
            .dynamics
            .as_ref()
            .is_some_and(|d| d.force_plans.is_some())
}
