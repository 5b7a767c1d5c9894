//! Lecture-style drawings: the plan of the mechanism, the plans of
//! velocities and accelerations, the positions sheet and the course sheet,
//! as SVG sheets with the ГОСТ 2.104 frame (and title block), exported to
//! PNG (resvg) and PDF (svg2pdf). The drawing code only reads the
//! analysis: the kernel knows nothing of SVG.
//!
//! Every figure is drawn at the scale that fills its field: the smallest
//! standard μ (1, 2, 2.5, 4, 5 × 10^k, ГОСТ 2.302) at which the drawing,
//! labels and symbols included, fits; a scale the scene fixes
//! (`want.scales`) is kept. The plans are built again at their sheet's
//! scale: a new construction, not the solver's plan enlarged.

pub mod canvas;
mod captions;
pub mod centres;
pub mod course;
mod course_forces;
pub mod cylinder;
pub mod diagram;
pub mod export;
pub mod force_polygon;
pub mod forces;
pub mod free_body;
pub mod frenet;
pub mod html;
pub mod lever;
pub mod mechanism;
pub mod plan;
pub mod positions;
pub mod sheet;
pub mod table;

#[cfg(feature = "render")]
pub use export::tree;
pub use export::{pdf, pdf_book, png};

use crate::error::{Error, Result};
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::scale::{standard_above, standard_scale};
use crate::kinematics::construction::{Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::words::construction::Lang;
use canvas::Canvas;
use kurbo::{Point, Rect};
use sheet::{Page, TitleBlock};
use table::number;

pub(crate) use captions::{position_text, scale_label, scale_text, words};
/// Sheet formats, landscape (ГОСТ 2.301).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SheetSize {
    /// 297 × 210 mm.
    A4,
    /// 420 × 297 mm.
    A3,
    /// 594 × 420 mm.
    A2,
    /// 841 × 594 mm (the course project's sheet).
    A1,
}

impl SheetSize {
    /// Width and height, mm, landscape.
    pub fn mm(&self) -> (f64, f64) {
        match self {
            SheetSize::A4 => (297.0, 210.0),
            SheetSize::A3 => (420.0, 297.0),
            SheetSize::A2 => (594.0, 420.0),
            SheetSize::A1 => (841.0, 594.0),
        }
    }
    /// The size of a name, `A4` … `A1` (either case).
    pub fn parse(s: &str) -> Option<SheetSize> {
        match s.to_ascii_uppercase().as_str() {
            "A4" => Some(SheetSize::A4),
            "A3" => Some(SheetSize::A3),
            "A2" => Some(SheetSize::A2),
            "A1" => Some(SheetSize::A1),
            _ => None,
        }
    }
    /// Every size, smallest first.
    pub const ALL: [SheetSize; 4] = [SheetSize::A4, SheetSize::A3, SheetSize::A2, SheetSize::A1];
}

#[derive(Clone, Copy, Debug)]
pub struct DrawOptions {
    pub sheet: SheetSize,
    pub lang: Lang,
    /// The main title block (ГОСТ 2.104 form 1) on every sheet; always on
    /// the course sheet.
    pub title_block: bool,
    /// Add the table of measured quantities to plan sheets.
    pub table: bool,
    /// Mark the instant centres on the plans of the mechanism.
    pub centres: bool,
    /// Compose the course sheet (besides what `want.drawings` asks).
    pub course: bool,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            sheet: SheetSize::A4,
            lang: Lang::En,
            title_block: false,
            table: false,
            centres: false,
            course: false,
        }
    }
}

/// One sheet: its file stem (`velocity_1`), title, size, the scales its
/// figures are drawn at (`mu_l`, `mu_v`, `mu_a`) and SVG text.
#[derive(Clone, Debug)]
pub struct Sheet {
    /// The file stem: `mechanism_1`, `velocity_1`, `positions`, `course` …
    pub name: String,
    /// The sheet's title, as its heading says it.
    pub title: String,
    /// The sheet format it is drawn on.
    pub size: SheetSize,
    /// The scales of its figures by name (`mu_l` m/mm, `mu_v` (m/s)/mm,
    /// `mu_a` (m/s²)/mm, `mu_F` N/mm).
    pub scales: Vec<(&'static str, f64)>,
    /// The sheet as SVG text, true size in mm.
    pub svg: String,
}

/// Output formats of `mechplan draw`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// SVG text, true size.
    Svg,
    /// A picture at the request's resolution (the `render` feature).
    Png,
    /// A page per sheet, true size, and one book of all (the `render`
    /// feature).
    Pdf,
}

/// Whether the scene asks for drawing `d` (`want.drawings`; by default the
/// plan of the mechanism and the plans wanted, plus the positions sheet
/// when there are several positions).
fn asked(an: &Analysis, solved: &[Solved], d: &str) -> bool {
    let want = &an.mech.scene.want.drawings;
    if want.is_empty() {
        let has_vel = solved.first().is_some_and(|s| s.plans.is_some());
        let has_acc = solved
            .first()
            .and_then(|s| s.plans.as_ref())
            .is_some_and(|p| p.acceleration.is_some());
        match d {
            "mechanism" => true,
            "velocity" => has_vel,
            "acceleration" => has_acc,
            "positions" => solved.len() > 1,
            "lever" => solved.first().is_some_and(|s| s.dynamics.is_some()),
            "forces" => solved
                .first()
                .and_then(|s| s.dynamics.as_ref())
                .is_some_and(|d| d.force_plans.is_some()),
            _ => false,
        }
    } else {
        want.iter().any(|w| w == d)
    }
}

/// The smallest standard μ, not below `lower`, at which `draw(μ)` fits
/// `field` (w × h, mm), with its drawing; `None` when nothing up to a
/// million times `lower` fits. A drawing at a smaller μ is larger (a
/// drawing's size never shrinks with its scale but for its labels, which
/// keep their size), so the first that fits fills its field best: at the
/// one before it, the drawing overflowed, and standard values are at most
/// ×2 apart, so it spans at least half the field one way.
pub fn fill<T>(
    lower: f64,
    field: (f64, f64),
    mut draw: impl FnMut(f64) -> Option<T>,
    extent: impl Fn(&T) -> Rect,
) -> Option<(f64, T)> {
    let mut mu = standard_scale(lower.max(1e-12), 1.0);
    let top = mu * 1e6;
    while mu <= top {
        if let Some(t) = draw(mu)
            && fits(extent(&t), field)
        {
            return Some((mu, t));
        }
        mu = standard_above(mu);
    }
    None
}

/// The scale `lower` to start [`fill`] from: the smallest at which a real
/// extent `w` × `h` (m, or m/s …) is drawn within the field; the drawing,
/// with its labels, is never smaller.
pub fn lower_scale(w: f64, h: f64, field: (f64, f64)) -> f64 {
    (w / field.0).max(h / field.1).max(1e-12)
}

/// Whether an extent fits a field (mm).
fn fits(u: Rect, (aw, ah): (f64, f64)) -> bool {
    u.width() <= aw && u.height() <= ah
}

/// The real extent of the mechanism's shown points over `solved` (m).
fn mechanism_extent(an: &Analysis, solved: &[Solved]) -> Rect {
    let m = &an.mech;
    let mut r: Option<Rect> = None;
    // The points drawn: those of moving links, and the frame's pivots (a
    // frame point that only names an axis, as the compressor's Y, is not).
    let drawn = |p: usize| {
        let ls = m.links_of_point(p);
        ls.iter().any(|&l| l != m.frame() && an.link(l)) || ls.len() >= 2
    };
    for s in solved {
        for p in (0..m.scene.points.len()).filter(|&p| drawn(p)) {
            if let Some(&l) = m.links_of_point(p).iter().find(|&&l| an.link(l)) {
                let q = s.config.point(m, l, p);
                let b = Rect::from_points(q, q);
                r = Some(r.map_or(b, |x| x.union(b)));
            }
        }
    }
    r.unwrap_or(Rect::ZERO)
}

/// The plans of the mechanism, one canvas per position, at `mu_l`.
fn mechanism_canvases(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    mu_l: f64,
) -> Vec<Canvas> {
    solved
        .iter()
        .map(|s| {
            let mut c = Canvas::default();
            mechanism::draw(an, s, &mut c, mu_l, true);
            if opt.centres {
                centres::draw(an, s, &mut c, mu_l);
            }
            c.place_pending();
            c
        })
        .collect()
}

fn union(cs: &[Canvas]) -> Rect {
    cs.iter()
        .map(|c| c.bounds())
        .reduce(|a, b| a.union(b))
        .unwrap_or(Rect::ZERO)
}

/// The field (w × h) of a single-figure sheet.
fn field_size(opt: &DrawOptions, right: f64) -> (f64, f64) {
    let f = sheet::field(opt.sheet, opt.title_block, right);
    (f.width(), f.height())
}

/// A figure waiting for its page: the drawing, the box to centre (the
/// union of a series, so that flipping through the series the mechanism
/// does not jump), the heading, the scale, a table beside it.
struct Pending {
    name: String,
    title: String,
    scale: Option<String>,
    scales: Vec<(&'static str, f64)>,
    canvas: Canvas,
    centre_on: Option<Rect>,
    table: Option<table::Ruled>,
}

/// The drawings a scene asks for (`want.drawings`; by default the plan
/// of the mechanism and the plans wanted, plus the positions sheet when
/// there are several positions), one sheet per drawing and position, on
/// `opt.sheet`, each figure at the scale that fills its field; a μ_l the
/// scene fixes that does not fit is replaced by the one that fills (the
/// sheets say which). `mechplan draw` uses [`sheets_on`], which refuses
/// instead.
pub fn sheets(an: &Analysis, solved: &[Solved], opt: &DrawOptions) -> Vec<Sheet> {
    match sheets_on(an, solved, opt, &[opt.sheet]) {
        Ok((s, _)) => s,
        Err(_) => compose(an, solved, opt, Scale::Fill).unwrap_or_default(),
    }
}

/// How the mechanism's scale is chosen.
#[derive(Clone, Copy, PartialEq)]
enum Scale {
    /// The scene's μ_l (`want.scales.mu_l`) when it gives one.
    Scene,
    /// Chosen to fill, whatever the scene says.
    Fill,
}

/// The sheets, on the first of `sizes` whose field holds the mechanism's
/// drawings at the μ_l the scene fixes (without one, the first size: the
/// scale then fills it); with it, the size used. When a fixed μ_l fits
/// none: a refusal with the reason (the drawing's size at that μ_l, the
/// field's size, the smallest standard μ_l that fits the first of
/// `sizes`, and the smallest sheet that would hold it).
pub fn sheets_on(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    sizes: &[SheetSize],
) -> Result<(Vec<Sheet>, SheetSize)> {
    let first = sizes.first().copied().unwrap_or(opt.sheet);
    let Some(mu_l) = an.mech.scene.want.scales.mu_l else {
        let opt = DrawOptions {
            sheet: first,
            ..*opt
        };
        return Ok((compose(an, solved, &opt, Scale::Scene)?, first));
    };
    let t = asked(an, solved, "positions").then(|| positions::trajectories(an, solved));
    let u = mechanism_union(an, solved, opt, mu_l, t.as_ref());
    for &size in sizes {
        let opt = DrawOptions {
            sheet: size,
            ..*opt
        };
        if solved.is_empty() || fits(u, field_size(&opt, 0.0)) {
            return Ok((compose(an, solved, &opt, Scale::Scene)?, size));
        }
    }
    Err(misfit(an, solved, opt, sizes, u, mu_l, t.as_ref()))
}

/// The extent of the mechanism's drawings at `mu_l`: every position's
/// plan of the mechanism and, with trajectories `t`, the positions sheet.
fn mechanism_union(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    mu_l: f64,
    t: Option<&positions::Trajectories>,
) -> Rect {
    let mut u = union(&mechanism_canvases(an, solved, opt, mu_l));
    if let Some(t) = t {
        let mut c = Canvas::default();
        positions::draw(an, solved, t, &mut c, mu_l);
        u = u.union(c.bounds());
    }
    u
}

/// Why the mechanism's drawings at the scene's μ_l do not fit any of
/// `sizes`, and what would.
fn misfit(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    sizes: &[SheetSize],
    u: Rect,
    mu_l: f64,
    t: Option<&positions::Trajectories>,
) -> Error {
    use crate::format::format_quantity as q;
    let first = sizes.first().copied().unwrap_or(opt.sheet);
    let last = sizes.last().copied().unwrap_or(opt.sheet);
    let area_of = |sheet| field_size(&DrawOptions { sheet, ..*opt }, 0.0);
    let (aw, ah) = area_of(first);
    let e = mechanism_extent(an, solved);
    let mu = fill(
        lower_scale(e.width(), e.height(), (aw, ah)),
        (aw, ah),
        |mu| Some(mechanism_union(an, solved, opt, mu, t)),
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
    let mut msg = format!(
        "the drawing of the mechanism at μ_l = {mu_l} m/mm (want.scales.mu_l) is {} × {}, {field}; the smallest standard μ_l that fits sheet {first:?} is {mu} m/mm",
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
fn compose(an: &Analysis, solved: &[Solved], opt: &DrawOptions, how: Scale) -> Result<Vec<Sheet>> {
    let w = words(opt.lang);
    let fixed_l = match how {
        Scale::Scene => an.mech.scene.want.scales.mu_l,
        Scale::Fill => None,
    };
    let mut out: Vec<Pending> = Vec::new();
    let field = field_size(opt, 0.0);
    let extent = mechanism_extent(an, solved);
    let lower = lower_scale(extent.width(), extent.height(), field);
    if asked(an, solved, "positions") && !solved.is_empty() {
        let t = positions::trajectories(an, solved);
        let draw = |mu: f64| {
            let mut c = Canvas::default();
            positions::draw(an, solved, &t, &mut c, mu);
            Some(c)
        };
        let (mu, c) = match fixed_l {
            Some(mu) => (mu, draw(mu).unwrap_or_default()),
            None => fill(lower, field, draw, |c| c.bounds()).ok_or_else(too_large)?,
        };
        out.push(pending(
            "positions".into(),
            w.positions.into(),
            scale_text("l", mu, "m", opt.lang),
            ("mu_l", mu),
            c,
        ));
    }
    let mech = if asked(an, solved, "mechanism") && !solved.is_empty() {
        let draw = |mu: f64| Some(mechanism_canvases(an, solved, opt, mu));
        Some(match fixed_l {
            Some(mu) => (mu, mechanism_canvases(an, solved, opt, mu)),
            None => fill(lower, field, draw, |cs| union(cs)).ok_or_else(too_large)?,
        })
    } else {
        None
    };
    let (mu_l, mut mech) = mech.map_or((0.0, Vec::new()), |(mu, cs)| (mu, cs));
    let centre_on = (!mech.is_empty()).then(|| union(&mech));
    for (k, s) in solved.iter().enumerate() {
        let pos = position_text(an, s, k, opt.lang);
        if k < mech.len() {
            out.push(Pending {
                centre_on,
                ..pending(
                    format!("mechanism_{}", k + 1),
                    format!("{}, {pos}", w.mechanism),
                    scale_text("l", mu_l, "m", opt.lang),
                    ("mu_l", mu_l),
                    std::mem::take(&mut mech[k]),
                )
            });
        }
        out.extend(position_sheets(an, solved, (k, s), opt, field)?);
    }
    let mut sheets = Vec::new();
    if opt.course || asked(an, solved, "course") {
        sheets.push(course::sheet(an, solved, opt)?);
        if let Some(f) = course_forces::sheet(an, solved, opt)? {
            sheets.push(f);
        }
    }
    let n = out.len();
    let lead = sheets.len();
    for (i, p) in out.into_iter().enumerate() {
        sheets.push(render(an, opt, p, (lead + i + 1, lead + n)));
    }
    if let Some(d) = diagram::wanted(an, opt)? {
        sheets.push(d);
    }
    Ok(sheets)
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
    solved: &[Solved],
    (k, s): (usize, &Solved),
    opt: &DrawOptions,
    field: (f64, f64),
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
            PlanKind::Velocity => ("velocity", w.velocities),
            PlanKind::Acceleration => ("acceleration", w.accelerations),
        };
        if !asked(an, solved, name)
            || (kind == PlanKind::Acceleration && plans.acceleration.is_none())
        {
            continue;
        }
        let (plan, c, t) = plan_figure(an, s, kind, opt, |plan| {
            let t = opt.table.then(|| table::plan_table(plan, opt.lang));
            let right = t.as_ref().map_or(0.0, |t| t.size().0 + sheet::PAD);
            field_size(opt, right)
        });
        let (sym, unit, key) = match kind {
            PlanKind::Velocity => ("v", "m/s", "mu_v"),
            PlanKind::Acceleration => ("a", "m/s²", "mu_a"),
        };
        out.push(Pending {
            table: t,
            ..pending(
                format!("{name}_{}", k + 1),
                format!("{title}, {pos}"),
                scale_text(sym, plan.mu, unit, opt.lang),
                (key, plan.mu),
                c,
            )
        });
    }
    if asked(an, solved, "forces")
        && let Some(f) = forces::figure(an, s, opt, field)
    {
        out.push(pending(
            format!("forces_{}", k + 1),
            format!("{}, {pos}", forces::title(opt.lang)),
            scale_text("l", f.mu_l, "m", opt.lang),
            ("mu_l", f.mu_l),
            f.canvas,
        ));
    }
    out.extend(levers);
    Ok(out)
}

fn too_large() -> Error {
    Error::Internal("no standard scale up to a million times the first fits the sheet".into())
}

/// A plan of position `s` at the scale that fills the field `field(plan)`
/// gives for it (the scene's scale where it fixes one): the plan, its
/// drawing and the table for it.
fn plan_figure(
    an: &Analysis,
    s: &Solved,
    kind: PlanKind,
    opt: &DrawOptions,
    field: impl Fn(&Plan) -> (f64, f64),
) -> (Plan, Canvas, Option<table::Ruled>) {
    let solved_plan = || {
        let p = s.plans.as_ref().expect("a plan asked for");
        match kind {
            PlanKind::Velocity => p.velocity.clone(),
            PlanKind::Acceleration => p.acceleration.clone().expect("an acceleration plan"),
        }
    };
    let draw = |plan: &Plan| {
        let mut c = Canvas::default();
        plan::draw(plan, &mut c, &an.points);
        c
    };
    let table = |plan: &Plan| opt.table.then(|| table::plan_table(plan, opt.lang));
    let fixed = match kind {
        PlanKind::Velocity => an.drafting.mu_v,
        PlanKind::Acceleration => an.drafting.mu_a,
    };
    let p0 = solved_plan();
    if fixed.is_some() {
        let c = draw(&p0);
        let t = table(&p0);
        return (p0, c, t);
    }
    let f = field(&p0);
    let (lo, hi) = p0.points.iter().fold(
        (Point::new(0.0, 0.0), Point::new(0.0, 0.0)),
        |(lo, hi), q| {
            let a = q.at.to_point();
            (
                Point::new(lo.x.min(a.x), lo.y.min(a.y)),
                Point::new(hi.x.max(a.x), hi.y.max(a.y)),
            )
        },
    );
    let lower = lower_scale((hi.x - lo.x) * p0.mu, (hi.y - lo.y) * p0.mu, f);
    let rebuild = |mu: f64| -> Option<(Plan, Canvas)> {
        let (order, mv, ma) = match kind {
            PlanKind::Velocity => (Order::Velocity, Some(mu), None),
            PlanKind::Acceleration => (Order::Acceleration, None, Some(mu)),
        };
        let p = an.plans_at_scales(s, order, mv, ma).ok()?;
        let plan = match kind {
            PlanKind::Velocity => p.velocity,
            PlanKind::Acceleration => p.acceleration?,
        };
        let c = draw(&plan);
        Some((plan, c))
    };
    match fill(lower, f, rebuild, |(_, c)| c.bounds()) {
        Some((_, (plan, c))) => {
            let t = table(&plan);
            (plan, c, t)
        }
        // A plan all at the pole (everything at rest) or one that cannot
        // be built again: the solver's own.
        None => {
            let c = draw(&p0);
            let t = table(&p0);
            (p0, c, t)
        }
    }
}

/// A single-figure sheet from its pending figure: frame, heading, the
/// figure centred in its field, the table beside it, the title block.
fn render(an: &Analysis, opt: &DrawOptions, p: Pending, number: (usize, usize)) -> Sheet {
    let right = p.table.as_ref().map_or(0.0, |t| t.size().0 + sheet::PAD);
    let mut page = Page::new(opt.sheet);
    page.heading(&p.title, p.scale.as_deref());
    let f = sheet::field(opt.sheet, opt.title_block, right);
    page.place(&p.canvas, f, p.centre_on);
    if let Some(t) = &p.table {
        let (tw, _) = t.size();
        let fr = sheet::frame(opt.sheet);
        page.place_at(
            &t.draw(),
            Point::new(fr.x1 - sheet::PAD - tw, fr.y0 + sheet::HEADING),
        );
    }
    if opt.title_block {
        page.title_block(&title_block(an, opt, &p.title, number));
    }
    Sheet {
        name: p.name,
        title: p.title,
        size: opt.sheet,
        scales: p.scales,
        svg: page.finish(),
    }
}

/// The title block of a sheet of this scene.
pub(crate) fn title_block(
    an: &Analysis,
    opt: &DrawOptions,
    title: &str,
    number: (usize, usize),
) -> TitleBlock {
    TitleBlock::new(&an.mech.scene.sheet, title, opt.lang, number)
}

/// A single sheet from a canvas (the diagrams, the Frenet families, the
/// `check --svg` overlay): on the first of `opt.sheet` and the larger
/// sizes whose field holds it; a drawing larger than A1's field is drawn
/// reduced (its heading says by how much).
pub fn page_svg(
    name: String,
    title: String,
    c: &Canvas,
    scale: Option<String>,
    opt: &DrawOptions,
) -> Sheet {
    let b = c.bounds();
    let size = SheetSize::ALL
        .into_iter()
        .filter(|s| s.mm().0 >= opt.sheet.mm().0)
        .find(|&s| fits(b, field_size(&DrawOptions { sheet: s, ..*opt }, 0.0)))
        .unwrap_or(SheetSize::A1);
    let opt = DrawOptions {
        sheet: size,
        ..*opt
    };
    let f = sheet::field(size, opt.title_block, 0.0);
    let k = (f.width() / b.width())
        .min(f.height() / b.height())
        .min(1.0);
    let mut page = Page::new(size);
    let title = if k < 1.0 {
        // The largest "1:n" reduction with n from the standard values.
        let n = standard_scale(1.0 / k, 1.0);
        let c2 = c.scaled(1.0 / n);
        let t = format!("{title} (1:{})", number(n, opt.lang));
        page.heading(&t, scale.as_deref());
        page.place(&c2, f, None);
        t
    } else {
        page.heading(&title, scale.as_deref());
        page.place(c, f, None);
        title
    };
    Sheet {
        name,
        title,
        size,
        scales: Vec::new(),
        svg: page.finish(),
    }
}
