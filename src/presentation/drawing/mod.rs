//! Lecture-style drawings: the plan of the mechanism, the plans of
//! velocities and accelerations, and the positions sheet, as SVG sheets
//! (A4 landscape by default) with a ГОСТ 2.301 frame, exported to PNG
//! (resvg) and PDF (svg2pdf). The drawing code only reads the analysis:
//! the kernel knows nothing of SVG.

pub mod canvas;
pub mod centres;
pub mod cylinder;
pub mod diagram;
pub mod frenet;
pub mod html;
pub mod mechanism;
pub mod plan;
pub mod positions;

use crate::error::{Error, Result};
use crate::kinematics::construction::text::{Lang, num};
use crate::kinematics::construction::{Plan, PlanKind};
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::scene::InputSpec;
use canvas::{Canvas, FONT, Label, SMALL, fmt, xml};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Sheet formats, landscape (ГОСТ 2.301).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SheetSize {
    A4,
    A3,
    A1,
}

impl SheetSize {
    pub fn mm(&self) -> (f64, f64) {
        match self {
            SheetSize::A4 => (297.0, 210.0),
            SheetSize::A3 => (420.0, 297.0),
            SheetSize::A1 => (841.0, 594.0),
        }
    }
    pub fn parse(s: &str) -> Option<SheetSize> {
        match s.to_ascii_uppercase().as_str() {
            "A4" => Some(SheetSize::A4),
            "A3" => Some(SheetSize::A3),
            "A1" => Some(SheetSize::A1),
            _ => None,
        }
    }
}

#[derive(Clone, Copy, Debug)]
pub struct DrawOptions {
    pub sheet: SheetSize,
    pub lang: Lang,
    pub title_block: bool,
    /// Add the table of measured segments to plan sheets.
    pub table: bool,
    /// Mark the instant centres on the plans of the mechanism.
    pub centres: bool,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            sheet: SheetSize::A4,
            lang: Lang::En,
            title_block: false,
            table: false,
            centres: false,
        }
    }
}

/// One sheet: its file stem (`velocity_1`) and SVG text.
#[derive(Clone, Debug)]
pub struct Sheet {
    pub name: String,
    pub title: String,
    pub svg: String,
}

/// Output formats of `mechplan draw`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
    Pdf,
}

fn words(lang: Lang) -> [&'static str; 6] {
    match lang {
        Lang::En => [
            "Plan of the mechanism",
            "Plan of velocities",
            "Plan of accelerations",
            "Positions of the mechanism",
            "position",
            "mm",
        ],
        Lang::Uk => [
            "План механізму",
            "План швидкостей",
            "План прискорень",
            "Положення механізму",
            "положення",
            "мм",
        ],
        Lang::Ru => [
            "План механизма",
            "План скоростей",
            "План ускорений",
            "Положения механизма",
            "положение",
            "мм",
        ],
    }
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
            _ => false,
        }
    } else {
        want.iter().any(|w| w == d)
    }
}

/// The drawings of the mechanism at one scale: one per position (the plan
/// of the mechanism) and the positions sheet, those asked for.
struct MechanismDrawings {
    mu_l: f64,
    mech: Vec<Canvas>,
    positions: Option<Canvas>,
}

impl MechanismDrawings {
    fn new(an: &Analysis, solved: &[Solved], opt: &DrawOptions, mu_l: f64) -> MechanismDrawings {
        let mech = if asked(an, solved, "mechanism") {
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
        } else {
            Vec::new()
        };
        let positions = asked(an, solved, "positions").then(|| {
            let mut c = Canvas::default();
            positions::draw(an, solved, &mut c, mu_l);
            c
        });
        MechanismDrawings {
            mu_l,
            mech,
            positions,
        }
    }

    /// The union of every drawing's extent, mm (None: nothing drawn).
    fn extent(&self) -> Option<kurbo::Rect> {
        self.mech
            .iter()
            .chain(self.positions.iter())
            .map(|c| c.bounds())
            .reduce(|a, b| a.union(b))
    }
}

/// Whether an extent fits a field (mm).
fn fits(u: kurbo::Rect, (aw, ah): (f64, f64)) -> bool {
    !(u.width() > aw || u.height() > ah)
}

/// The drawings a scene asks for (`want.drawings`; by default the plan of
/// the mechanism and the plans wanted, plus the positions sheet when there
/// are several positions), one sheet per drawing and position.
///
/// The mechanism's sheets share one scale and one place on the page, so
/// that flipping through them the mechanism does not jump. Here the scale
/// is the scene's μ_l (`want.scales.mu_l`, else the default that `solve`
/// reports) when the drawings fit the sheet, else it grows to the next
/// standard value until they do (the sheets say which). `mechplan draw`
/// uses [`sheets_at_scene_scale`] instead, which never changes μ_l.
pub fn sheets(an: &Analysis, solved: &[Solved], opt: &DrawOptions) -> Vec<Sheet> {
    let area = free_area(opt, false);
    let mut d = MechanismDrawings::new(an, solved, opt, an.mu_l);
    loop {
        match d.extent() {
            Some(u) if !fits(u, area) && d.mu_l < 1e6 => {
                let f = (u.width() / area.0).max(u.height() / area.1);
                let mu_l = crate::kinematics::construction::scale::standard_scale(
                    d.mu_l * f * 1.0001,
                    1.0,
                );
                d = MechanismDrawings::new(an, solved, opt, mu_l);
            }
            _ => break,
        }
    }
    compose(an, solved, opt, d)
}

/// The sheets at the scene's μ_l (`an.mu_l`: `want.scales.mu_l`, else the
/// default, the value `solve` reports), on the first of `sizes` whose
/// field holds the drawings of the mechanism; with it, the size used.
/// When none does: a refusal with the reason (the drawing's size at that
/// μ_l, the field's size, the smallest standard μ_l that fits the first
/// of `sizes`, and the smallest sheet that would hold it).
pub fn sheets_at_scene_scale(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    sizes: &[SheetSize],
) -> Result<(Vec<Sheet>, SheetSize)> {
    let d = MechanismDrawings::new(an, solved, opt, an.mu_l);
    let Some(u) = d.extent() else {
        let size = sizes.first().copied().unwrap_or(opt.sheet);
        let opt = DrawOptions {
            sheet: size,
            ..*opt
        };
        return Ok((compose(an, solved, &opt, d), size));
    };
    for &size in sizes {
        let opt = DrawOptions {
            sheet: size,
            ..*opt
        };
        if fits(u, free_area(&opt, false)) {
            return Ok((compose(an, solved, &opt, d), size));
        }
    }
    Err(misfit(an, solved, opt, sizes, u))
}

/// Why the mechanism's drawings at the scene's μ_l do not fit any of
/// `sizes`, and what would.
fn misfit(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    sizes: &[SheetSize],
    u: kurbo::Rect,
) -> Error {
    use crate::kinematics::construction::scale::standard_scale;
    use crate::presentation::quantity::format_quantity as q;
    let first = sizes.first().copied().unwrap_or(opt.sheet);
    let last = sizes.last().copied().unwrap_or(opt.sheet);
    let area_of = |sheet| free_area(&DrawOptions { sheet, ..*opt }, false);
    let (aw, ah) = area_of(first);
    // The smallest standard μ_l that fits the first sheet: from the one
    // that would if the drawing's size were all geometry (labels and
    // symbols keep their size), up one standard value at a time.
    let f = (u.width() / aw).max(u.height() / ah);
    let mut mu = standard_scale(an.mu_l * f, 1.0);
    while mu < 1e6 {
        let e = MechanismDrawings::new(an, solved, opt, mu).extent();
        if e.is_none_or(|e| fits(e, (aw, ah))) {
            break;
        }
        mu = standard_scale(mu * 1.0001, 1.0);
    }
    // The smallest sheet holding it at this μ_l, beyond those tried.
    let bigger = [SheetSize::A4, SheetSize::A3, SheetSize::A1]
        .into_iter()
        .filter(|s| !sizes.contains(s))
        .find(|&s| s.mm().0 > last.mm().0 && fits(u, area_of(s)));
    let given = an.mech.scene.want.scales.mu_l.is_some();
    let whose = if given {
        "want.scales.mu_l"
    } else {
        "the scene's default, as solve reports it; want.scales.mu_l sets another"
    };
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
        "the drawing of the mechanism at μ_l = {} m/mm ({whose}) is {} × {}, {field}; the smallest standard μ_l that fits sheet {first:?} is {mu} m/mm",
        an.mu_l,
        q(u.width(), "mm"),
        q(u.height(), "mm"),
    );
    if let Some(s) = bigger {
        msg += &format!(", or draw on --sheet {s:?}");
    }
    let pointer = if given || sizes.len() > 1 {
        "/want/scales/mu_l"
    } else {
        "sheet"
    };
    Error::scene(pointer, msg)
}

/// Compose the sheets from the mechanism's drawings and the plans.
fn compose(
    an: &Analysis,
    solved: &[Solved],
    opt: &DrawOptions,
    d: MechanismDrawings,
) -> Vec<Sheet> {
    let w = words(opt.lang);
    let mut out = Vec::new();
    let MechanismDrawings {
        mu_l,
        mech,
        positions: pos_canvas,
    } = d;
    let union = mech.iter().map(|c| c.bounds()).reduce(|a, b| a.union(b));
    if let Some(c) = &pos_canvas {
        let scale = scale_label("l", mu_l, "m", opt.lang);
        out.push(page(
            "positions".into(),
            w[3].into(),
            c,
            Some(scale),
            opt,
            None,
            None,
        ));
    }
    for (k, s) in solved.iter().enumerate() {
        let pos = position_text(an, s, k, opt.lang);
        if let Some(c) = mech.get(k) {
            out.push(page(
                format!("mechanism_{}", k + 1),
                format!("{}, {pos}", w[0]),
                c,
                Some(scale_label("l", mu_l, "m", opt.lang)),
                opt,
                None,
                union,
            ));
        }
        let Some(plans) = &s.plans else { continue };
        for (name, title, plan) in [
            ("velocity", w[1], Some(&plans.velocity)),
            ("acceleration", w[2], plans.acceleration.as_ref()),
        ] {
            let Some(plan) = plan else { continue };
            if !asked(an, solved, name) {
                continue;
            }
            let mut c = Canvas::default();
            plan::draw(plan, &mut c, &an.points);
            let (sym, unit) = match plan.kind {
                PlanKind::Velocity => ("v", "m/s"),
                PlanKind::Acceleration => ("a", "m/s²"),
            };
            let table = if opt.table { Some(plan) } else { None };
            out.push(page(
                format!("{name}_{}", k + 1),
                format!("{title}, {pos}"),
                &c,
                Some(scale_label(sym, plan.mu, unit, opt.lang)),
                opt,
                table,
                None,
            ));
        }
    }
    out
}

fn position_text(an: &Analysis, s: &Solved, k: usize, lang: Lang) -> String {
    let w = words(lang);
    if an.mech.scene.several_inputs() {
        let inputs = crate::presentation::report::input_words(an, s);
        return format!("{} {}, {inputs}", w[4], k + 1);
    }
    match an.mech.scene.input {
        InputSpec::Crank { .. } => format!(
            "{} {}, φ1 = {}°",
            w[4],
            k + 1,
            num(s.q.to_degrees().rem_euclid(360.0))
        ),
        InputSpec::Slider { .. } => format!("{} {}, s = {} m", w[4], k + 1, num(s.q)),
    }
}

/// "μ_v = 0.01 (m/s)/mm", localised.
pub(crate) fn scale_label(sym: &str, mu: f64, unit: &str, lang: Lang) -> Label {
    let (unit, mm) = match lang {
        Lang::En => (unit.to_string(), "mm"),
        _ => (unit.replace('m', "м").replace('s', "с"), "мм"),
    };
    let unit = if unit.contains('/') {
        format!("({unit})")
    } else {
        unit
    };
    Label::new("μ", sym).with_tail(format!(" = {} {unit}/{mm}", num(mu)))
}

/// A single sheet from a canvas (used by `check --svg`).
pub fn page_svg(
    name: String,
    title: String,
    c: &Canvas,
    scale: Option<Label>,
    opt: &DrawOptions,
) -> Sheet {
    page(name, title, c, scale, opt, None, None)
}

/// The free area of a sheet for the drawing (mm): inside the frame, below
/// the heading, beside the table and above the title block.
fn free_area(opt: &DrawOptions, table: bool) -> (f64, f64) {
    let (w, h) = opt.sheet.mm();
    let title_h = if opt.title_block { 20.0 } else { 0.0 };
    let table_w = if table { 70.0 } else { 0.0 };
    (
        w - 20.0 - 5.0 - 12.0 - table_w,
        h - 10.0 - 16.0 - 6.0 - title_h,
    )
}

/// Compose a sheet: frame, heading, the drawing centred in the free area,
/// optional title block and table of measured segments.
fn page(
    name: String,
    title: String,
    c: &Canvas,
    scale: Option<Label>,
    opt: &DrawOptions,
    table: Option<&Plan>,
    centre_on: Option<kurbo::Rect>,
) -> Sheet {
    let (w, h) = opt.sheet.mm();
    let (left, margin) = (20.0, 5.0);
    let title_h = if opt.title_block { 20.0 } else { 0.0 };
    let table_w = if table.is_some() { 70.0 } else { 0.0 };
    // Free area for the drawing: inside the frame, below the heading.
    let (ax0, ax1) = (left + 6.0, w - margin - 6.0 - table_w);
    let (ay0, ay1) = (margin + 16.0, h - margin - 6.0 - title_h);
    let b = centre_on.unwrap_or_else(|| c.bounds());
    let ox = (ax0 + ax1) / 2.0 - (b.x0 + b.x1) / 2.0;
    let oy = (ay0 + ay1) / 2.0 + (b.y0 + b.y1) / 2.0;
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}mm" height="{h}mm" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, sans-serif">"#
    );
    let _ = writeln!(svg, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<rect class="frame" x="{left}" y="{margin}" width="{}" height="{}" fill="none" stroke="black" stroke-width="0.7"/>"#,
        fmt(w - left - margin),
        fmt(h - 2.0 * margin)
    );
    let mut head = Canvas::default();
    head.text(
        kurbo::Point::new(0.0, 0.0),
        Label::new(title.clone(), ""),
        5.0,
        "heading",
    );
    if let Some(s) = scale {
        head.text(kurbo::Point::new(0.0, -7.0), s, FONT, "scale");
    }
    head.write(&mut svg, left + 6.0, margin + 9.0);
    c.write(&mut svg, ox, oy);
    if let Some(plan) = table {
        let mut t = Canvas::default();
        let x0 = w - margin - table_w + 2.0;
        let mut y = 0.0;
        let head = match opt.lang {
            Lang::En => "segment, mm → value",
            Lang::Uk => "відрізок, мм → величина",
            Lang::Ru => "отрезок, мм → величина",
        };
        t.text(
            kurbo::Point::new(0.0, y),
            Label::new(head, ""),
            SMALL,
            "table",
        );
        for q in &plan.measured {
            y -= 4.0;
            let row = format!(
                "{} = {} → {} = {}",
                crate::presentation::tables::segment(plan, q),
                num(q.mm),
                q.quantity,
                num(q.value)
            );
            t.text(
                kurbo::Point::new(0.0, y),
                Label::new(row, ""),
                SMALL,
                "table",
            );
        }
        t.write(&mut svg, x0, margin + 24.0);
    }
    if opt.title_block {
        let (bw, bx, by) = (130.0, w - margin - 130.0, h - margin - title_h);
        let _ = writeln!(
            svg,
            r#"<rect class="title-block" x="{}" y="{}" width="{bw}" height="{title_h}" fill="none" stroke="black" stroke-width="0.7"/>"#,
            fmt(bx),
            fmt(by)
        );
        let _ = writeln!(
            svg,
            r#"<text class="title-block" x="{}" y="{}" font-size="3.5">{}</text>"#,
            fmt(bx + 3.0),
            fmt(by + 8.0),
            xml(&truncate(&an_title(&title), 60))
        );
        let _ = writeln!(
            svg,
            r#"<text class="title-block" x="{}" y="{}" font-size="2.5">mechplan</text>"#,
            fmt(bx + 3.0),
            fmt(by + 15.0)
        );
    }
    svg.push_str("</svg>\n");
    Sheet { name, title, svg }
}

fn an_title(t: &str) -> String {
    t.to_string()
}

fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

/// A font database with the system's fonts (DejaVu on the project's machines).
fn options() -> usvg::Options<'static> {
    let mut o = usvg::Options::default();
    o.fontdb_mut().load_system_fonts();
    o.font_family = "DejaVu Sans".into();
    o
}

/// Parse a sheet's SVG with usvg (for PNG, PDF and the rendered checks).
pub fn tree(svg: &str) -> Result<usvg::Tree> {
    usvg::Tree::from_str(svg, &options())
        .map_err(|e| Error::Internal(format!("the drawing is not valid SVG: {e}")))
}

/// Render a sheet to PNG at `dpi`.
pub fn png(svg: &str, dpi: f64) -> Result<Vec<u8>> {
    let tree = tree(svg)?;
    let size = tree.size();
    // usvg sizes the sheet in CSS pixels (96 per inch).
    let k = (dpi / 96.0) as f32;
    let (pw, ph) = (
        (size.width() * k).ceil() as u32,
        (size.height() * k).ceil() as u32,
    );
    let mut pixmap = tiny_skia::Pixmap::new(pw, ph)
        .ok_or_else(|| Error::structure("the sheet is too large to render"))?;
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(k, k),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| Error::Internal(format!("PNG encoding failed: {e}")))
}

/// Convert a sheet to PDF.
pub fn pdf(svg: &str) -> Result<Vec<u8>> {
    let tree = tree(svg)?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        svg2pdf::PageOptions::default(),
    )
    .map_err(|e| Error::Internal(format!("PDF conversion failed: {e}")))
}

/// Write every sheet into `dir` in `format`, all or nothing: every sheet is
/// rendered, then written to a temporary file beside its place, and only
/// when all are written are they renamed into place; a failure removes
/// every temporary of this run ([`crate::output::write_files_atomically`]).
/// Returns the paths written.
pub fn write_sheets(
    sheets: &[Sheet],
    dir: &Path,
    format: Format,
    dpi: f64,
) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)
        .map_err(|e| crate::output::write_error(&dir.display().to_string(), e))?;
    // Render everything first, so that a failure writes nothing.
    let mut files = Vec::new();
    for s in sheets {
        let (ext, bytes) = match format {
            Format::Svg => ("svg", s.svg.clone().into_bytes()),
            Format::Png => ("png", png(&s.svg, dpi)?),
            Format::Pdf => ("pdf", pdf(&s.svg)?),
        };
        files.push((dir.join(format!("{}.{ext}", s.name)), bytes));
    }
    let refs: Vec<(PathBuf, &[u8])> = files.iter().map(|(p, b)| (p.clone(), &b[..])).collect();
    crate::output::write_files_atomically(&refs)?;
    Ok(files.into_iter().map(|(p, _)| p).collect())
}
