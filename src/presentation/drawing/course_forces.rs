//! The course's second sheet: the force analysis of one position (A1, or
//! A2) — every group cut out with its forces and its force polygon, the
//! input link with the balancing moment, Zhukovsky's lever with its table,
//! the reactions and the balancing moment by each route in one table, and
//! the main title block (sheet 2 of 2, the kinematic sheet being 1).
//!
//! The position is the one a course project analyses: the first of
//! `want.plans_at.acceleration` after the start of the working stroke (by
//! default the middle of the working stroke, where the working resistance
//! acts), else position 1. The figures are drawn to fill target boxes (the
//! force panels most of the field, the lever a third) and packed around
//! the title block as on the kinematic sheet; the boxes shrink together
//! until everything packs.

use crate::kinematics::construction::scale::Series;
use super::canvas::Canvas;
use crate::studies::sheet_data::SheetData;
use super::pack::{self, Figure};
use super::sheet::{self, Page};
use super::table::{Ruled, number};
use super::{DrawOptions, Sheet, fill, forces, lever, lower_scale};
use crate::error::Result;
use crate::kinematics::construction::Naming;
use crate::kinematics::solve::Analysis;
use crate::kinetostatics::Balancing;
use crate::kinetostatics::lever::lever_at;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use kurbo::Point;

/// The caption's line height, mm.
const CAPTION: f64 = 6.0;

/// The sheet's name in the title block.
pub fn title(lang: Lang) -> &'static str {
    &crate::words::catalogue(lang).sheets.force_analysis
}

/// The reactions and the balancing moment (force) of position `s` by each
/// route: the links' equilibrium, the force plans, the lever.
fn results(an: &Analysis, s: &Solved, lang: Lang) -> Option<Ruled> {
    let d = s.dynamics.as_ref()?;
    let m = &an.mech;
    let [pair, value, angle, plans, lever] = crate::words::catalogue(lang)
        .sheets
        .reactions_table
        .each_ref()
        .map(|s| s.as_str());
    let head = vec![
        pair.into(),
        value.into(),
        angle.into(),
        plans.into(),
        lever.into(),
    ];
    let deg = |v: kurbo::Vec2| number((v.y.atan2(v.x).to_degrees() * 10.0).round() / 10.0, lang);
    let n3 = |x: f64| number(round3(x), lang);
    let fp = d.force_plans.as_ref();
    let newton = &crate::words::catalogue(lang).force_plans.newton;
    let mut rows = Vec::new();
    for (i, r) in d.revolutes.iter().enumerate() {
        let name = format!(
            "R{}, {}",
            crate::words::forces::pair_sub(m.link_id(r.first), m.link_id(r.second)),
            m.point_name(r.point)
        );
        let by_plan = fp
            .and_then(|f| f.revolute[i])
            .map_or("—".into(), |v| n3(v.hypot()));
        rows.push(vec![
            format!("{name}, {newton}"),
            n3(r.r.hypot()),
            deg(r.r),
            by_plan,
            "—".into(),
        ]);
    }
    for (i, p) in d.prismatics.iter().enumerate() {
        let name = format!(
            "R{} ⊥",
            crate::words::forces::pair_sub(m.link_id(p.guide), m.link_id(p.slider))
        );
        let by_plan = fp
            .and_then(|f| f.prismatic[i])
            .map_or("—".into(), |v| n3(v.0.abs()));
        rows.push(vec![
            format!("{name}, {newton}"),
            n3(p.n.hypot()),
            deg(p.n),
            by_plan,
            "—".into(),
        ]);
    }
    for (i, b) in d.balancing.iter().enumerate() {
        let sub = crate::words::forces::balancing_sub(lang);
        let units = &crate::words::catalogue(lang).force_plans;
        let (name, unit) = match b {
            Balancing::Moment(_) => (format!("M_{sub}"), &units.newton_metre),
            Balancing::Force(_) => (format!("F_{sub}"), &units.newton),
        };
        let by_plan = fp.and_then(|f| f.drives[i]).map_or("—".into(), n3);
        let lever = d.lever.get(i).map_or("—".into(), |v| n3(*v));
        rows.push(vec![
            format!("{name}, {unit}"),
            n3(b.value()),
            "—".into(),
            by_plan,
            lever,
        ]);
    }
    Some(Ruled { head, rows })
}

/// Three significant digits, as a course project's table gives them.
fn round3(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}

/// The figures of position `k` with the force panels in a box of
/// `panels` mm and the lever in one of `lever_box` mm.
fn figures(
    an: &Analysis,
    s: &Solved,
    k: usize,
    opt: &DrawOptions,
    (panels, lever_box): ((f64, f64), (f64, f64)),
) -> Result<Vec<Figure>> {
    let lang = opt.lang;
    let pos = super::position_text(an, s, k, lang);
    let mut out = Vec::new();
    if let Some(f) = forces::figure(an, s, opt, (panels, true)) {
        out.push(Figure {
            id: "forces".into(),
            caption: vec![format!("{}, {pos}", forces::title(lang))],
            canvas: f.canvas,
            // Each panel's μ_l and its polygon's μ_F, as the panels state
            // them.
            scales: f
                .mu_l
                .iter()
                .map(|&m| ("mu_l", m))
                .chain(f.mu_f.iter().map(|&m| ("mu_F", m)))
                .collect(),
        });
    }
    let loads = s.dynamics.as_ref().map_or(&[][..], |d| &d.loads[..]);
    let w = lever::words(lang);
    for input in 0..an.mech.scene.input_count() {
        let first = lever_at(an, s, loads, input, Naming::Full, None)?;
        let draw = |l: &crate::kinetostatics::lever::Lever| {
            let mu_f = lever::force_scale(l);
            let mut c = Canvas::default();
            lever::draw(an, l, &mut c, (mu_f, lever_box.0), lang);
            c
        };
        let e = first.plan.points.iter().fold(kurbo::Rect::ZERO, |r, p| {
            r.union_pt(Point::new(-p.at.y, p.at.x))
        });
        let lower = lower_scale(e.width() * first.mu_v, e.height() * first.mu_v, lever_box);
        let rebuild = |mu: f64| {
            let l = lever_at(an, s, loads, input, Naming::Full, Some(mu)).ok()?;
            let c = draw(&l);
            Some((l, c))
        };
        let (l, c) = fill(Series::Plans, lower, lever_box, rebuild, |(_, c)| c.bounds())
            .map(|(_, x)| x)
            .unwrap_or_else(|| {
                let c = draw(&first);
                (first, c)
            });
        // Its scales and equations are written under the lever itself
        // ([`lever::draw`]): the caption above is its title alone.
        out.push(Figure {
            id: format!("lever-{}", input + 1),
            caption: vec![w.title.to_string()],
            canvas: c,
            scales: vec![("mu_v", l.mu_v)],
        });
        let forces_on = &crate::words::catalogue(lang).sheets.forces_on_lever;
        out.push(Figure {
            id: format!("lever-table-{}", input + 1),
            caption: vec![forces_on.to_string()],
            canvas: lever::table(an, &l, lang).draw(),
            scales: Vec::new(),
        });
    }
    if let Some(t) = results(an, s, lang) {
        let head = &crate::words::catalogue(lang).sheets.reactions_title;
        out.push(Figure {
            id: "reactions".into(),
            caption: vec![head.into()],
            canvas: t.draw(),
            scales: Vec::new(),
        });
    }
    Ok(out)
}

/// The second course sheet; `None` without force plans. Lettered as the
/// first ([`super::course::COURSE_LETTERING`]).
pub fn sheet(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
) -> Result<Option<Sheet>> {
    super::canvas::with_lettering(super::course::COURSE_LETTERING, || {
        forces_sheet(an, solved, data, opt)
    })
}

fn forces_sheet(
    an: &Analysis,
    solved: &[Solved],
    data: &SheetData,
    opt: &DrawOptions,
) -> Result<Option<Sheet>> {
    if solved.is_empty() {
        return Ok(None);
    }
    let k = data.chosen.analysed(solved.len());
    let s = &solved[k];
    if s.dynamics
        .as_ref()
        .and_then(|d| d.force_plans.as_ref())
        .is_none()
    {
        return Ok(None);
    }
    let size = pack::size(opt);
    let field = pack::field_of(size);
    let block = sheet::block(size);
    let (fw, fh) = (field.width(), field.height());
    // The boxes shrink together until the figures pack.
    let mut placed = None;
    // The panels as wide as still packs (they take the room the lever and
    // the tables leave), then everything smaller together.
    let tries = [1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4]
        .into_iter()
        .flat_map(|zoom| [0.74, 0.67, 0.6].map(|share| (zoom, share)));
    for (zoom, share) in tries {
        let panels = (share * fw * zoom, (fh - 3.0 * CAPTION) * zoom);
        let lever_box = (0.36 * fw * zoom, 0.45 * fh * zoom);
        let figs = figures(an, s, k, opt, (panels, lever_box))?;
        let sizes: Vec<(f64, f64)> = figs.iter().map(|f| f.size()).collect();
        if let Some(at) = pack::pack(&sizes, field, block) {
            placed = Some(figs.into_iter().zip(at).collect::<Vec<_>>());
            break;
        }
    }
    let placed = placed.ok_or_else(|| {
        crate::error::Error::Internal(format!(
            "the force analysis sheet's figures do not pack on {size:?}"
        ))
    })?;
    let mut page = Page::new(size);
    pack::place(&mut page, &placed);
    let name = title(opt.lang);
    page.title_block(&super::title_block(an, opt, name, (2, 2)));
    Ok(Some(Sheet {
        name: super::SheetKind::CourseForces.stem(),
        title: name.into(),
        position: Some(crate::presentation::position_number(an, k)),
        size,
        scales: placed.iter().flat_map(|(f, _)| f.scales.clone()).collect(),
        svg: page.finish(),
    }))
}
