//! The sheets a scene asks for, composed: which drawings, at which
//! scales, on which sheet size; each position's mechanism, velocity and
//! acceleration plans, the positions sheet, the course sheets, the force
//! sheets and the levers.

use crate::kinematics::construction::scale::Series;
use super::canvas::Canvas;
use super::layout::{
    Pending, field_size, fill, fits, lower_scale, mechanism_canvas,
    mechanism_extent, render,
};
use super::kind::SheetKind;
use super::output::{DrawOptions, Sheet, SheetSize};
use super::shared::{Scale, Shared, asked, mechanism_bounds, shared_scales};
use super::sweep::{self, Sweep};
use super::{course, course_forces, diagram, forces, lever, plan, positions, sheet, table};
use super::{position_text, scale_text, words};
use crate::error::{Error, Result};
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::{Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::presentation::position_number;
use crate::pipeline::Solved;
use crate::studies::sheet_data::{SheetData, SheetNeeds};
use kurbo::Rect;
use std::collections::BTreeMap;

/// What the sheets `opt` draws for `solved` need solved beyond the
/// positions (`all`: every position's sheets are drawn, not only some):
/// the positions sheet and the course sheet their trajectories and the
/// chosen positions, the diagrams sheet and the course sheet the
/// diagrams. The caller solves them ([`SheetData::solve`]) and hands them
/// to [`sheets_on_each`], which only reads them.
#[cfg(feature = "internals")]
pub fn sheet_needs(an: &Analysis, solved: &[Solved], opt: &DrawOptions, all: bool) -> SheetNeeds {
    sweep_needs(an, &solved, opt, all)
}

/// [`sheet_needs`] of a sweep ([`Sweep`]).
pub fn sweep_needs(an: &Analysis, solved: &dyn Sweep, opt: &DrawOptions, all: bool) -> SheetNeeds {
    let course = opt.course || asked(an, solved, "course");
    SheetNeeds {
        trajectories: asked(an, solved, "positions") || course,
        diagrams: all && diagram::asked(an),
        course,
    }
}

/// The drawings a scene asks for (`want.drawings`; by default the plan
/// of the mechanism and the plans wanted, plus the positions sheet when
/// there are several positions), one sheet per drawing and position, on
/// `opt.sheet`, each figure at the scale that fills its field; a μ_l the
/// scene fixes that does not fit is replaced by the one that fills (the
/// sheets say which). `mechplan draw` uses [`sheets_on`], which refuses
/// instead. `data`: what [`sheet_needs`] names, solved.
#[cfg(feature = "internals")]
pub fn sheets(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
) -> Vec<Sheet> {
    match sheets_on(an, solved, data, opt, &[opt.sheet]) {
        Ok((s, _)) => s,
        Err(_) => compose(an, solved, data, opt, Scale::Fill).unwrap_or_default(),
    }
}

/// The sheets, on the first of `sizes` whose field holds the mechanism's
/// drawings at the μ_l the scene fixes (without one, the first size: the
/// scale then fills it); with it, the size used. When a fixed μ_l fits
/// none: a refusal with the reason (the drawing's size at that μ_l, the
/// field's size, the smallest standard μ_l that fits the first of
/// `sizes`, and the smallest sheet that would hold it).
#[cfg(feature = "internals")]
pub fn sheets_on(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
    sizes: &[SheetSize],
) -> Result<(Vec<Sheet>, SheetSize)> {
    let mut sheets = Vec::new();
    let size = sheets_on_each(an, &solved, data, opt, (sizes, &[]), &mut |s| {
        sheets.push(s);
        Ok(())
    })?;
    Ok((sheets, size))
}

/// [`sheets_on`], each sheet handed to `sink` as soon as it is drawn (a
/// sheet is dropped there: memory flat in the number of positions); with
/// `only` (positions from 0, none: all), only those positions' sheets,
/// drawn at the scales of the whole set and numbered as in it. `data`:
/// what [`sheet_needs`] names, solved by the caller (presentation never
/// solves); a sheet without its data is an internal error. `solved`:
/// the positions, held or solved again as they are read ([`Sweep`]).
pub fn sheets_on_each(
    an: &Analysis,
    solved: &dyn Sweep,
    data: &SheetData,
    opt: &DrawOptions,
    (sizes, only): (&[SheetSize], &[usize]),
    sink: &mut dyn FnMut(Sheet) -> Result<()>,
) -> Result<SheetSize> {
    let first = sizes.first().copied().unwrap_or(opt.sheet);
    let Some(mu_l) = an.mech.scene.want.scales.mu_l else {
        let opt = DrawOptions {
            sheet: first,
            ..*opt
        };
        compose_each(an, solved, data, &opt, (Scale::Scene, only), sink)?;
        return Ok(first);
    };
    let t = match asked(an, solved, "positions") {
        true => Some(positions::given(data, solved.len())?),
        false => None,
    };
    // Counted before anything is drawn: the joints alone at μ_l. A drawing
    // that no standard sheet could hold is refused at once (drawn at such
    // a scale, its hatching alone would run to millions of strokes).
    let e = mechanism_extent(an, solved.configs());
    let joints = Rect::new(0.0, 0.0, e.width() / mu_l, e.height() / mu_l);
    let largest = DrawOptions {
        sheet: SheetSize::ALL[SheetSize::ALL.len() - 1],
        ..*opt
    };
    if !solved.is_empty() && !fits(joints, field_size(&largest, 0.0)) {
        return Err(misfit(an, solved, opt, sizes, (joints, true), mu_l, t));
    }
    let u = mechanism_union(an, solved, opt, mu_l, t)?;
    for &size in sizes {
        let opt = DrawOptions {
            sheet: size,
            ..*opt
        };
        if solved.is_empty() || fits(u, field_size(&opt, 0.0)) {
            compose_each(an, solved, data, &opt, (Scale::Scene, only), sink)?;
            return Ok(size);
        }
    }
    Err(misfit(an, solved, opt, sizes, (u, false), mu_l, t))
}

/// The extent of the mechanism's drawings at `mu_l`: every position's
/// plan of the mechanism and, with trajectories `t`, the positions sheet.
fn mechanism_union(
    an: &Analysis,
    solved: &dyn Sweep,
    opt: &DrawOptions,
    mu_l: f64,
    t: Option<positions::Drawn>,
) -> Result<Rect> {
    let mut u = mechanism_bounds(an, solved, opt, &[mu_l])?[0];
    if let Some(t) = t {
        let mut c = Canvas::default();
        let configs = solved.configs();
        positions::draw(an, (sweep::at(solved, t.bold)?, &configs), t, &mut c, mu_l);
        u = u.union(c.bounds());
    }
    Ok(u)
}

/// Why the mechanism's drawings at the scene's μ_l do not fit any of
/// `sizes`, and what would; `u` their extent, or with `at_least` a lower
/// bound of it (the joints alone, when they fit no sheet).
fn misfit(
    an: &Analysis,
    solved: &dyn Sweep,
    opt: &DrawOptions,
    sizes: &[SheetSize],
    (u, at_least): (Rect, bool),
    mu_l: f64,
    t: Option<positions::Drawn>,
) -> Error {
    use crate::format::format_quantity as q;
    let first = sizes.first().copied().unwrap_or(opt.sheet);
    let last = sizes.last().copied().unwrap_or(opt.sheet);
    let area_of = |sheet| field_size(&DrawOptions { sheet, ..*opt }, 0.0);
    let (aw, ah) = area_of(first);
    let e = mechanism_extent(an, solved.configs());
    let mu = fill(
        Series::Drawing,
        lower_scale(e.width(), e.height(), (aw, ah)),
        (aw, ah),
        |mu| mechanism_union(an, solved, opt, mu, t).ok(),
        |r| *r,
    )
    .map(|(mu, _)| mu)
    .unwrap_or(f64::NAN);
    // The smallest sheet holding it at this μ_l, beyond those tried.
    let bigger = SheetSize::ALL
        .into_iter()
        .filter(|s| !sizes.contains(s))
        .find(|&s| s.mm().0 > last.mm().0 && fits(u, area_of(s)));
    let field = if sizes.len() > 1 {
        let (w, h) = area_of(last);
        format!(
            "larger than the field of every sheet up to {last:?} ({} × {})",
            q(w, "mm"),
            q(h, "mm")
        )
    } else {
        format!(
            "larger than the field of sheet {first:?} ({} × {})",
            q(aw, "mm"),
            q(ah, "mm")
        )
    };
    let is = if at_least {
        "is at least (its joints alone)"
    } else {
        "is"
    };
    let mut msg = format!(
        "the drawing of the mechanism at μ_l = {mu_l} m/mm (want.scales.mu_l) {is} {} × {}, {field}; the smallest standard μ_l that fits sheet {first:?} is {mu} m/mm",
        q(u.width(), "mm"),
        q(u.height(), "mm"),
    );
    if let Some(s) = bigger {
        msg += &format!(", or draw on --sheet {s:?}");
    }
    msg += ", or leave μ_l to mechplan (it fills the sheet)";
    Error::scene("/want/scales/mu_l", msg)
}

/// Compose the sheets on `opt.sheet`: the positions sheet, and per
/// position the plan of the mechanism and the plans asked for; the course
/// sheet when asked; the diagrams sheet when asked.
#[cfg(feature = "internals")]
fn compose(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
    how: Scale,
) -> Result<Vec<Sheet>> {
    let mut sheets = Vec::new();
    compose_each(an, &solved, data, opt, (how, &[]), &mut |s| {
        sheets.push(s);
        Ok(())
    })?;
    Ok(sheets)
}

/// [`compose`], each sheet handed to `sink` as soon as it is rendered and
/// dropped there: memory stays flat in the number of positions (a
/// position's figures are drawn when its turn comes; with a title block,
/// whose "sheet i of n" needs n, the figures are composed twice, the
/// first time only counted). With `only` (positions from 0), only those
/// positions' sheets: the others, the positions sheet, the course and the
/// diagrams sheets are left out (counted in the numbering all the same).
fn compose_each(
    an: &Analysis,
    solved: &dyn Sweep,
    data: &SheetData,
    opt: &DrawOptions,
    (how, only): (Scale, &[usize]),
    sink: &mut dyn FnMut(Sheet) -> Result<()>,
) -> Result<()> {
    fixed_plan_scales(an, solved, opt)?;
    let shared = shared_scales(an, solved, data, opt, how)?;
    let all = only.is_empty();
    let mut lead = 0;
    if opt.course || asked(an, solved, "course") {
        lead += 1;
        let held = sweep::held(solved)?;
        let course = course::sheet(an, held, data, opt)?;
        let forces = course_forces::sheet(an, held, data, opt)?;
        lead += usize::from(forces.is_some());
        if all {
            sink(course)?;
            if let Some(f) = forces {
                sink(f)?;
            }
        }
    }
    // How many sheets each figure source gives (the positions sheet under
    // `None`), counted when the numbers are needed.
    let mut counts: BTreeMap<Option<usize>, usize> = BTreeMap::new();
    if opt.title_block {
        figures(an, solved, opt, &shared, &|_| true, &mut |at, _| {
            *counts.entry(at).or_default() += 1;
            Ok(())
        })?;
    }
    let n: usize = counts.values().sum();
    let chosen = |at: Option<usize>| all || at.is_some_and(|k| only.contains(&k));
    let (mut last, mut within) = (None, 0);
    figures(an, solved, opt, &shared, &chosen, &mut |at, p| {
        if last != Some(at) {
            (last, within) = (Some(at), 0);
        }
        within += 1;
        // After every sheet of the sources before this one, those left
        // out included.
        let i = counts.range(..at).map(|(_, c)| c).sum::<usize>() + within;
        let mut sheet = render(an, opt, p, (lead + i, lead + n));
        sheet.position = at.map(|k| position_number(an, k));
        sink(sheet)
    })?;
    if all && let Some(d) = diagram::wanted(an, data, opt)? {
        sink(d)?;
    }
    Ok(())
}

/// Every figure to render, in the order of the sheets, to `emit`: the
/// positions sheet, then per position its plan of the mechanism and the
/// rest of its sheets, each position as `finish` gives it.
fn figures(
    an: &Analysis,
    solved: &dyn Sweep,
    opt: &DrawOptions,
    shared: &Shared,
    chosen: &dyn Fn(Option<usize>) -> bool,
    emit: &mut dyn FnMut(Option<usize>, Pending) -> Result<()>,
) -> Result<()> {
    let w = words(opt.lang);
    if let Some((mu, c)) = shared.positions.as_ref().filter(|_| chosen(None)) {
        emit(None, pending(
            SheetKind::Positions.stem(),
            w.positions.clone(),
            scale_text("l", *mu, "m", opt.lang),
            ("mu_l", *mu),
            c.clone(),
        ))?;
    }
    solved.each(&|k| chosen(Some(k)), &mut |k, s| {
        let pos = position_text(an, s, k, opt.lang);
        if let Some((mu_l, centre_on)) = shared.mechanism {
            emit(Some(k), Pending {
                centre_on: Some(centre_on),
                ..pending(
                    SheetKind::Mechanism(position_number(an, k)).stem(),
                    format!("{}, {pos}", w.mechanism),
                    scale_text("l", mu_l, "m", opt.lang),
                    ("mu_l", mu_l),
                    mechanism_canvas(an, s, opt, mu_l),
                )
            })?;
        }
        for p in position_sheets(an, solved, (k, s), opt)? {
            emit(Some(k), p)?;
        }
        Ok(())
    })
}

/// A sheet to render: its name, title, scale text and the scale its
/// figure `canvas` is drawn at; centred on its own bounds, no table.
fn pending(
    name: String,
    title: String,
    scale: String,
    scales: (&'static str, f64),
    canvas: Canvas,
) -> Pending {
    Pending {
        sheet: None,
        name,
        title,
        scale: Some(scale),
        scales: vec![scales],
        canvas,
        centre_on: None,
        table: None,
    }
}

/// The sheets of position `s` (the `k`-th, from 0) after its plan of the
/// mechanism: the plans asked for, the forces, then Zhukovsky's lever.
fn position_sheets(
    an: &Analysis,
    solved: &dyn Sweep,
    (k, s): (usize, &Solved),
    opt: &DrawOptions,
) -> Result<Vec<Pending>> {
    let w = words(opt.lang);
    let pos = position_text(an, s, k, opt.lang);
    let mut out = Vec::new();
    // Zhukovsky's lever after the plans and forces of its position.
    let levers = if asked(an, solved, "lever") && s.dynamics.is_some() {
        lever::pending(an, s, k, opt)?
    } else {
        Vec::new()
    };
    for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
        let Some(plans) = &s.plans else { break };
        let (name, title) = match kind {
            PlanKind::Velocity => ("velocity", &w.velocities[..]),
            PlanKind::Acceleration => ("acceleration", &w.accelerations[..]),
        };
        if !asked(an, solved, name)
            || (kind == PlanKind::Acceleration && plans.acceleration.is_none())
        {
            continue;
        }
        let (plan, c, t) = plan_figure(an, (k, s), kind, opt);
        let n = position_number(an, k);
        let (sym, unit, key, sheet) = match kind {
            PlanKind::Velocity => ("v", "m/s", "mu_v", SheetKind::Velocity(n)),
            PlanKind::Acceleration => ("a", "m/s²", "mu_a", SheetKind::Acceleration(n)),
        };
        out.push(Pending {
            table: t,
            ..pending(
                sheet.stem(),
                format!("{title}, {pos}"),
                scale_text(sym, plan.mu, unit, opt.lang),
                (key, plan.mu),
                c,
            )
        });
    }
    let parts = match asked(an, solved, "forces") {
        true => forces::sheets_of(an, s, opt),
        false => Vec::new(),
    };
    let several = parts.len() > 1;
    for (part, (size, f)) in parts.into_iter().enumerate() {
        // Each panel states its μ_l and μ_F: the heading none.
        let mut scales: Vec<(&'static str, f64)> = f.mu_l.iter().map(|&m| ("mu_l", m)).collect();
        scales.extend(f.mu_f.iter().map(|&m| ("mu_F", m)));
        let position = position_number(an, k);
        let kind = match several {
            true => SheetKind::ForcesPart { position, part },
            false => SheetKind::Forces(position),
        };
        out.push(Pending {
            sheet: (size != opt.sheet).then_some(size),
            scale: None,
            scales,
            ..pending(
                kind.stem(),
                format!("{}, {pos}", forces::title(opt.lang)),
                String::new(),
                ("mu_l", 0.0),
                f.canvas,
            )
        });
    }
    out.extend(levers);
    Ok(out)
}


/// The solved plan of `kind` at position `s`, the extent of its points
/// (mm, the pole included) and the field it is drawn in (beside its table
/// when one is asked for).
fn plan_extent<'a>(s: &'a Solved, kind: PlanKind, opt: &DrawOptions) -> (&'a Plan, Rect, (f64, f64)) {
    let p = s.plans.as_ref().expect("a plan asked for");
    let plan = match kind {
        PlanKind::Velocity => &p.velocity,
        PlanKind::Acceleration => p.acceleration.as_ref().expect("an acceleration plan"),
    };
    let t = opt.table.then(|| table::plan_table(plan, opt.lang));
    let right = t.as_ref().map_or(0.0, |t| t.size().0 + sheet::PAD);
    let points = plan.points.iter().fold(Rect::ZERO, |r, q| {
        r.union(Rect::from_points(q.at.to_point(), q.at.to_point()))
    });
    (plan, points, field_size(opt, right))
}

fn draw_plan(an: &Analysis, plan: &Plan) -> Canvas {
    let mut c = Canvas::default();
    plan::draw(plan, &mut c, &an.points);
    c
}

/// The smallest standard scale at which the plan of `kind` at `s`, built
/// again at it (whatever the scene fixes), is drawn within `field`; the
/// plan and its drawing. `plan`, `points`: the solved plan and its extent.
fn fitting_scale(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    (plan, points): (&Plan, Rect),
    field: (f64, f64),
) -> Option<(f64, (Plan, Canvas))> {
    let lower = lower_scale(points.width() * plan.mu, points.height() * plan.mu, field);
    let rebuild = |mu: f64| -> Option<(Plan, Canvas)> {
        let (order, mv, ma) = match kind {
            PlanKind::Velocity => (Order::Velocity, Some(mu), None),
            PlanKind::Acceleration => (Order::Acceleration, None, Some(mu)),
        };
        let p = an.plans_at_given_scales(s, order, mv, ma).ok()?;
        let plan = match kind {
            PlanKind::Velocity => p.velocity,
            PlanKind::Acceleration => p.acceleration?,
        };
        let c = draw_plan(an, &plan);
        Some((plan, c))
    };
    fill(Series::Plans, lower, field, rebuild, |(_, c)| c.bounds())
}

/// The scales the scene fixes for its plans (`want.scales.mu_v`, `mu_a`),
/// counted before anything is drawn: where a plan's points alone overflow
/// the field at some position, a refusal naming the worst position, with
/// the smallest standard scale that fits every position (drawn at a scale
/// of a millionth of the right one, a plan's dashed lines alone would
/// take gigabytes).
fn fixed_plan_scales(an: &Analysis, solved: &dyn Sweep, opt: &DrawOptions) -> Result<()> {
    for kind in [PlanKind::Velocity, PlanKind::Acceleration] {
        let (fixed, name, sym, unit, key) = match kind {
            PlanKind::Velocity => (an.drafting.mu_v, "velocity", "v", "(m/s)/mm", "mu_v"),
            PlanKind::Acceleration => (an.drafting.mu_a, "acceleration", "a", "(m/s²)/mm", "mu_a"),
        };
        let Some(mu) = fixed else { continue };
        if !asked(an, solved, name) {
            continue;
        }
        let drawn: Vec<(usize, &Solved)> = sweep::held(solved)?
            .iter()
            .enumerate()
            .filter(|(_, s)| {
                s.plans.as_ref().is_some_and(|p| {
                    kind == PlanKind::Velocity || p.acceleration.is_some()
                })
            })
            .collect();
        let over = |points: Rect, f: (f64, f64)| (points.width() / f.0).max(points.height() / f.1);
        let extents: Vec<_> = drawn
            .iter()
            .map(|&(k, s)| (k, s, plan_extent(s, kind, opt)))
            .collect();
        let worst = extents
            .iter()
            .map(|&(k, _, (_, points, f))| (k, points, f, over(points, f)))
            .max_by(|a, b| a.3.total_cmp(&b.3));
        let Some((k, points, f, ratio)) = worst.filter(|w| w.3 > 1.0) else {
            continue;
        };
        let q = |x: f64| crate::format::format_quantity(x, "mm");
        let mut msg = format!(
            "the plan at μ_{sym} = {mu} {unit} (want.scales.{key}) is at least (its points alone) {} × {} at position {} ({} times the field), larger than the field of sheet {:?} ({} × {})",
            q(points.width()),
            q(points.height()),
            position_number(an, k),
            crate::format::format_number(ratio),
            opt.sheet,
            q(f.0),
            q(f.1),
        );
        let fit = extents.iter().try_fold(0.0_f64, |m, &(_, s, (plan, points, f))| {
            fitting_scale(an, s, kind, (plan, points), f).map(|x| m.max(x.0))
        });
        if let Some(fit) = fit {
            msg += &format!("; the smallest standard μ_{sym} that fits every position is {fit} {unit}");
        }
        msg += &format!(", or leave μ_{sym} to mechplan (it fills the sheet)");
        return Err(Error::scene(format!("/want/scales/{key}"), msg));
    }
    Ok(())
}

/// A plan of position `s` at its own scale, the one the steps, the result
/// file and the handout state: the construction chose it for this sheet's
/// field ([`plan_field`](super::layout::plan_field)), or the scene fixed it
/// ([`fixed_plan_scales`] has seen it fit). The plan, its drawing and the
/// table for it.
fn plan_figure(
    an: &Analysis,
    (k, s): (usize, &Solved),
    kind: PlanKind,
    opt: &DrawOptions,
) -> (Plan, Canvas, Option<table::Ruled>) {
    let (plan, _, _) = plan_extent(s, kind, opt);
    // A plan built at the course sheet's scale (`scales_at`) is that
    // sheet's; its own sheet draws it built again at the scale that fills
    // its own field (every sheet at its own scale on its own paper).
    let course = an.scales_at.get(&k).is_some_and(|&(v, a)| match kind {
        PlanKind::Velocity => v.is_some(),
        PlanKind::Acceleration => a.is_some(),
    });
    if course {
        let order = match kind {
            PlanKind::Velocity => Order::Velocity,
            PlanKind::Acceleration => Order::Acceleration,
        };
        // The scales the construction chooses for this sheet's field, as
        // for a position the course sheet does not show.
        let own = an.plans_at_scales(s, order, None, None).ok().and_then(|p| match kind {
            PlanKind::Velocity => Some(p.velocity),
            PlanKind::Acceleration => p.acceleration,
        });
        if let Some(own) = own {
            let table = opt.table.then(|| table::plan_table(&own, opt.lang));
            let c = draw_plan(an, &own);
            return (own, c, table);
        }
    }
    let table = opt.table.then(|| table::plan_table(plan, opt.lang));
    (plan.clone(), draw_plan(an, plan), table)
}
