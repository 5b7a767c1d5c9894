//! The studies a solution serves besides its result file, each as a typed
//! result that renders itself as a table or JSON: a checked answer
//! ([`Checked`]), the instant centres ([`Centres`]), the motion-law
//! invariants ([`Invariants`]), the kinematic diagrams ([`Diagram`]), the
//! work-precision report ([`PrecisionReport`]).

use super::{Solution, Study, Written, files, write_sheets};
use crate::error::{Error, Result, in_file};
use crate::grading::answer::{Answer, StatedPosition};
use crate::grading::forces::{self, ForceAnswer, ForceReport};
use crate::grading::photo::PhotoReading;
use crate::grading::read::{self, Reading};
use crate::grading::{self, Report};
use crate::kinematics::construction::PlanKind;
use crate::kinematics::solve::Analysis;
use crate::lang::Lang;
use crate::model::scene::Numbering;
use crate::presentation::drawing::{self, DrawOptions, Format, Sheet};
use crate::presentation::{precision as precision_text, studies as tables, verdict};
use crate::studies::diagrams::Diagrams;
use crate::studies::invariants::{self, Phase, Settings};
use crate::verification::precision;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What the command line says besides the two files: each override
/// replaces what the answer says.
#[derive(Clone, Debug, Default)]
pub struct CheckRequest {
    /// The report as JSON (else text).
    pub json: bool,
    /// Where to write the overlay of a kinematic plan (`--svg`).
    pub overlay: Option<PathBuf>,
    /// Where to write the overlay into a copy of a DXF answer (`--dxf`).
    pub overlay_dxf: Option<PathBuf>,
    /// Where to write the overlay of a photographed plan in the photo's
    /// own perspective (`--photo-overlay`, a marks file only).
    pub overlay_photo: Option<PathBuf>,
    /// The pencil's precision δ, mm (`--delta`), over the answer's own.
    pub delta: Option<f64>,
    /// The plan's scale μ (`--mu`), over the answer's own.
    pub mu: Option<f64>,
    /// Which plan the answer is (`--plan`), over the answer's own.
    pub plan: Option<PlanKind>,
    /// The position (`--position`), over the answer's own: its number in
    /// the numbering `positions_from`, else the study's
    /// ([`Study::numbering`]: a `count` sweep from 0, given input values
    /// from 1), as the sheets show it.
    pub position: Option<usize>,
    /// The numbering of `position` and of an answer's `position` that
    /// states no `positions_from` (`--positions-from`); `None`: the
    /// study's. ([`crate::check_file`] and [`crate::check_group`] number
    /// the report and the gradebook by it too.)
    pub positions_from: Option<Numbering>,
    /// The language of a kinematic plan's report (`--lang`): its
    /// sentences, and its numbers' decimal mark in the text; default: the
    /// scene's `want.lang`. The JSON's keys and judgements stay English.
    pub lang: Option<Lang>,
}

/// An answer read, before it is checked.
impl Study {
    /// Check a student's answer, JSON or a drawing, SVG or DXF (`svg`: a
    /// drawing by its file's extension; a text starting with `<` is an SVG
    /// one too, a text starting as a DXF does a DXF one, its code page
    /// already decoded as `check` decodes a file's), its
    /// problems naming `name` (the answer's file). A plan of velocities or
    /// accelerations, or a force plan (`"plan": "force"`, or a drawing
    /// stating μ_F). The report is in the scene's `want.lang`; another
    /// language is asked by [`CheckRequest::lang`] (through
    /// [`Solution::check_answer`]).
    ///
    /// # Errors
    ///
    /// [`Error::Input`] for an answer that cannot be read (broken JSON, an
    /// unknown point, a drawing without a pole or scale), each problem at
    /// its place and naming `name`; the errors of [`Study::solve`]. A wrong
    /// answer is no error: it is the verdict.
    ///
    /// # Examples
    ///
    /// ```
    /// let study = mechplan::Study::default_scene();
    /// // A student read v_B = 0.3 m/s off a velocity plan drawn at
    /// // μ_v = 0.01 (m/s)/mm, at position 1 (the scene counts its twelve
    /// // positions from 0, as its sheets do).
    /// let answer = r#"{ "plan": "velocity", "position": 1, "mu": 0.01,
    ///                   "values": { "v_B": 0.3 } }"#;
    /// let checked = study.check_answer(answer, "answer.json", false)?;
    /// assert_eq!(checked.wrong(), 1); // v_B is 0.345 m/s there
    /// assert!(checked.to_text().contains("WRONG"));
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn check_answer(&self, text: &str, name: &str, svg: bool) -> Result<Checked> {
        self.solve()?
            .check_answer(text, name, svg, &CheckRequest::default())
    }

    /// The instant centres of every position (or of `position`, its
    /// number in the study's numbering, [`Study::numbering`]).
    pub fn centres(&self, position: Option<usize>) -> Result<Centres<'_>> {
        self.solve()?.into_centres(position)
    }

    /// The phases and motion-law invariants of link `output` (its id;
    /// default: the last group's last link): `tolerance` the dwell
    /// tolerance E (a fraction of the stroke, 0 to 0.5), `min_dwell_deg`
    /// the shortest dwell reported, `n` the grid's steps per revolution.
    pub fn invariants(
        &self,
        output: Option<&str>,
        tolerance: f64,
        min_dwell_deg: f64,
        n: usize,
    ) -> Result<Invariants<'_>> {
        invariants(self, output, tolerance, min_dwell_deg, n)
    }

    /// The kinematic diagrams of link `output` (or of point `point` along
    /// its path) by the chord method over `n` intervals.
    pub fn diagram(
        &self,
        output: Option<&str>,
        point: Option<&str>,
        n: usize,
    ) -> Result<Diagram<'_>> {
        diagram(self, output, point, n)
    }

    /// The work-precision report: every method's error against an
    /// extended-precision reference, and its run time.
    pub fn precision(
        &self,
        settings: &crate::verification::precision::Settings,
    ) -> Result<PrecisionReport> {
        precision(self, settings)
    }
}

pub(super) enum Parsed {
    /// A plan of velocities or accelerations, the notes on what of its
    /// drawing was left out, and (read from a marks file) what the report
    /// says of its photo.
    Kinematic(Answer, Vec<String>, Option<PhotoReading>),
    /// A force plan.
    Force(ForceAnswer),
}

impl Parsed {
    /// The position the answer is of, as stated (the command line's over
    /// the answer's own).
    fn position(&self) -> StatedPosition {
        match self {
            Parsed::Kinematic(a, ..) => a.position,
            Parsed::Force(a) => a.position,
        }
    }
}

/// What the command line says of an answer (`req`) as read over it.
fn reading(req: &CheckRequest) -> Reading {
    Reading {
        mu: req.mu,
        plan: req.plan,
        delta: req.delta,
        position: req.position,
        positions_from: req.positions_from,
    }
}

/// Read an answer's text (see [`Study::check_answer`]) with the
/// command line's overrides `req`.
pub(super) fn parse_answer(
    text: &str,
    name: &str,
    svg: bool,
    req: &CheckRequest,
) -> Result<Parsed> {
    if let Some(f) = parse_force_answer(text, name, svg, req)? {
        return Ok(Parsed::Force(f));
    }
    // A marks file's photo, found against the marks file's folder.
    let folder = std::path::Path::new(name)
        .parent()
        .map(std::path::Path::to_path_buf);
    let photo_file = move |f: &str| {
        let p = folder.as_ref().map_or_else(|| f.into(), |b| b.join(f));
        super::reads::read_bounded(&p, super::reads::MAX_PHOTO_BYTES, "a photo")
            .map_err(|e| e.to_string())
    };
    let (ans, notes, photo) =
        read::from_text_full(text, name, svg, &reading(req), Some(&photo_file))?;
    Ok(Parsed::Kinematic(ans, notes, photo))
}

/// A force plan's answer (a JSON answer whose `plan` is `"force"`, or an
/// SVG drawing that states μ_F) with the overrides that apply to it;
/// `None` for a kinematic answer.
fn parse_force_answer(
    text: &str,
    name: &str,
    drawn: bool,
    req: &CheckRequest,
) -> Result<Option<ForceAnswer>> {
    let mut ans = if drawn {
        if !forces::is_force_svg(text) {
            return Ok(None);
        }
        forces::from_svg(
            text,
            req.mu,
            req.delta.unwrap_or(0.5),
            StatedPosition::default(),
        )
    } else {
        if !forces::is_force_answer(text) {
            return Ok(None);
        }
        forces::from_json(text)
    }
    .map_err(in_file(name))?;
    if let Some(d) = req.delta {
        if let Some(i) = crate::grading::answer::delta_issue(d, "delta") {
            return Err(Error::fields(vec![i]));
        }
        ans.delta = d;
    }
    if req.plan.is_some() {
        return Err(Error::scene(
            "plan",
            "the answer is a force plan (\"plan\": \"force\"): --plan names a plan of velocities or accelerations",
        ));
    }
    if let Some(m) = req.mu {
        if !(m.is_finite() && (1e-6..=1e9).contains(&m)) {
            return Err(Error::scene(
                "mu",
                "μ_F must be a number of N/mm between 1e-6 and 1e9",
            ));
        }
        ans.mu = m;
    }
    // (`--svg` draws a force plan's overlay too; a DXF answer's marked
    // copy and a photo's overlay are of kinematic plans only.)
    for (set, option) in [
        (req.overlay_dxf.is_some(), "dxf"),
        (req.overlay_photo.is_some(), "photo-overlay"),
    ] {
        if set {
            return Err(Error::scene(
                option,
                format!(
                    "--{option} is drawn for plans of velocities and accelerations only (give --svg for a force plan's overlay)"
                ),
            ));
        }
    }
    ans.position = reading(req).over(ans.position);
    Ok(Some(ans))
}

/// The answer's position is one of the scene's: an error naming the
/// option, or the answer's field in its file (`name`), with the range in
/// the numbering in force.
pub(super) fn position_of(
    study: &Study,
    parsed: &Parsed,
    name: &str,
    req: &CheckRequest,
) -> Result<()> {
    let count = study.position_count()?;
    match parsed.position().index(study.numbering(), count) {
        Ok(_) => Ok(()),
        Err(m) if req.position.is_some() => Err(Error::scene("position", m)),
        Err(m) => Err(in_file(name)(Error::scene("/position", m))),
    }
}

/// Check an answer read against the solved positions, its report in
/// `lang` (default: the scene's `want.lang`).
pub(super) fn check_parsed(sol: &Solution, parsed: Parsed, lang: Option<Lang>) -> Result<Checked> {
    Ok(match parsed {
        Parsed::Kinematic(ans, notes, photo) => {
            let lang = lang.unwrap_or_else(|| sol.study().lang());
            let report = grading::check_in(sol.an(), sol.all(), &ans, lang)?;
            Checked::Kinematic(Box::new(KinematicCheck {
                analysis: Arc::clone(&sol.study().analysis),
                answer: ans,
                report,
                notes,
                photo,
            }))
        }
        Parsed::Force(ans) => {
            let lang = lang.unwrap_or_else(|| sol.study().lang());
            Checked::Force(Box::new(forces::check_in(sol.an(), sol.all(), &ans, lang)?))
        }
    })
}

/// A student's answer checked, item by item (see
/// [`Study::check_answer`]).
#[derive(Clone, Debug)]
pub enum Checked {
    /// A plan of velocities or accelerations.
    Kinematic(Box<KinematicCheck>),
    /// A force plan (boxed: it carries its right plan for the overlay).
    Force(Box<ForceReport>),
}

/// A plan of velocities or accelerations checked: the verdicts, and what
/// the overlay is drawn from.
#[derive(Clone, Debug)]
pub struct KinematicCheck {
    analysis: Arc<Analysis>,
    answer: Answer,
    /// The verdicts, item by item, and the diagnosis.
    pub report: Report,
    /// What of a drawn answer was left out when it was read (texts that
    /// are no plan letter, letters beside no end of the plan): told in
    /// the report, so that a teacher sees what was not graded.
    pub notes: Vec<String>,
    /// A photographed plan's photo: its scale, conditioning and snapping.
    pub photo: Option<PhotoReading>,
}

impl Checked {
    /// The exit status of `mechplan check`: 0 every item right, 1 an
    /// item wrong, 4 none wrong but some cannot be judged here.
    pub fn status(&self) -> u8 {
        match self {
            Checked::Kinematic(k) => k.report.status(),
            Checked::Force(r) => r.status(),
        }
    }
    /// How many items are wrong.
    pub fn wrong(&self) -> usize {
        match self {
            Checked::Kinematic(k) => k.report.wrong(),
            Checked::Force(r) => r.wrong(),
        }
    }
    /// The report in words, as `mechplan check` prints it.
    pub fn to_text(&self) -> String {
        match self {
            Checked::Kinematic(k) => {
                let photo = k.photo.as_ref().map(PhotoReading::to_text);
                let mut text = photo.unwrap_or_default() + &verdict::to_text(&k.report);
                for n in &k.notes {
                    text.push_str(&format!("note: {n}\n"));
                }
                text
            }
            Checked::Force(r) => verdict::force_to_text(r),
        }
    }
    /// The report as JSON (`mechplan check --format json`).
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            Checked::Kinematic(k) => {
                let mut v = verdict::to_json(&k.report);
                if let Some(o) = v.as_object_mut() {
                    if !k.notes.is_empty() {
                        o.insert("notes".into(), serde_json::json!(k.notes));
                    }
                    if let Some(p) = &k.photo {
                        o.insert("photo".into(), p.to_json());
                    }
                }
                v
            }
            Checked::Force(r) => verdict::force_to_json(r),
        }
    }
    /// The overlay as an SVG sheet: a kinematic plan's answer, the
    /// student's points over the right plan; a force plan's, the
    /// student's vectors over the right polygon at their μ_F.
    pub fn overlay(&self) -> Option<String> {
        match self {
            Checked::Kinematic(k) => Some(verdict::overlay(&k.analysis, &k.answer, &k.report)),
            Checked::Force(r) => Some(verdict::force_overlay(r)),
        }
    }
    /// The overlay of a photographed plan (an answer read from a marks
    /// file): an SVG of the photo's `size` (px, as displayed) showing the
    /// photo at `href` and over it, in its perspective, the plan from the
    /// student's points, their points and the wrong steps; `None` for
    /// any other answer.
    pub fn photo_overlay(&self, href: &str, size: (u32, u32)) -> Option<String> {
        match self {
            Checked::Kinematic(k) => k.photo.as_ref().map(|p| {
                crate::presentation::photo_overlay::photo_overlay(&k.report, p, href, size)
            }),
            Checked::Force(_) => None,
        }
    }
    /// The photo's file a marks file names, if this answer is one.
    pub fn photo_file(&self) -> Option<&str> {
        match self {
            Checked::Kinematic(k) => k.photo.as_ref().and_then(|p| p.file.as_deref()),
            Checked::Force(_) => None,
        }
    }
    /// The overlay written into a copy of the student's DXF file
    /// `original` (its bytes as read): the file unchanged but for a layer
    /// `MECHPLAN-CHECK` holding the right plan at the student's pole and
    /// scale, the student's points marked and the verdict; `None` for a
    /// force plan.
    pub fn overlay_dxf(&self, original: &[u8]) -> Option<Result<Vec<u8>>> {
        match self {
            Checked::Kinematic(k) => Some(verdict::overlay_dxf(
                &k.analysis,
                &k.answer,
                &k.report,
                original,
            )),
            Checked::Force(_) => None,
        }
    }
}

/// The instant centres of every two links, at every position or one.
#[derive(Clone, Debug)]
pub struct Centres<'a> {
    solution: Solution<'a>,
    position: Option<usize>,
}

impl<'a> Solution<'a> {
    /// Check a student's answer against these positions (see
    /// [`Study::check_answer`]); `req` overrides what the answer says.
    pub fn check_answer(
        &self,
        text: &str,
        name: &str,
        svg: bool,
        req: &CheckRequest,
    ) -> Result<Checked> {
        let parsed = parse_answer(text, name, svg, req)?;
        position_of(self.study(), &parsed, name, req)?;
        check_parsed(self, parsed, req.lang)
    }

    /// The instant centres (of `position`, its number in the study's
    /// numbering, or of every position).
    pub fn into_centres(self, position: Option<usize>) -> Result<Centres<'a>> {
        if let Some(p) = position {
            self.study().position_index("position", p)?;
        }
        Ok(Centres {
            solution: self,
            position,
        })
    }
}

impl Centres<'_> {
    /// As `mechplan centres` prints them: in the scene's `want.lang`.
    pub fn to_table(&self) -> String {
        let lang = self.solution.study().lang();
        tables::centres_table(self.solution.an(), self.solution.all(), self.position, lang)
    }
    /// As `mechplan centres --format json` writes them.
    pub fn to_json(&self) -> serde_json::Value {
        tables::centres_json(self.solution.an(), self.solution.all(), self.position)
    }
    /// The same, typed: per position its centres (name, place in m or
    /// direction at infinity, links, how, the reliability `sin_angle`) and
    /// the ones that cannot be placed.
    ///
    /// # Examples
    ///
    /// ```
    /// let study = mechplan::Study::from_json(mechplan::DEFAULT_SCENE)?;
    /// let solution = study.solve()?;
    /// let centres = solution.into_centres(Some(0))?;
    /// let at = &centres.positions()[0];
    /// // The crank's centre relative to the frame is its pivot, P12 (a pair).
    /// let p12 = at.centres.iter().find(|c| c.name == "P12").unwrap();
    /// assert_eq!(p12.sin_angle, 1.0);
    /// assert!(p12.at.is_some());
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn positions(&self) -> Vec<tables::CentresAt> {
        tables::centres_records(self.solution.an(), self.solution.all(), self.position)
    }
}

/// The phases of an output (recess, dwell, approach) and their motion-law
/// invariants.
#[derive(Clone, Debug)]
pub struct Invariants<'a> {
    study: &'a Study,
    settings: Settings,
    phases: Vec<Phase>,
}

pub(super) fn invariants<'a>(
    study: &'a Study,
    output: Option<&str>,
    tolerance: f64,
    min_dwell_deg: f64,
    n: usize,
) -> Result<Invariants<'a>> {
    if !(tolerance.is_finite() && (0.0..0.5).contains(&tolerance)) {
        return Err(Error::scene(
            "tolerance",
            "must be a fraction of the stroke from 0 to 0.5",
        ));
    }
    if !(min_dwell_deg.is_finite() && (0.0..360.0).contains(&min_dwell_deg)) {
        return Err(Error::scene("min-dwell", "must be from 0 to 360 degrees"));
    }
    if !(36..=1_000_000).contains(&n) {
        return Err(Error::scene("n", "must be from 36 to 1000000 steps"));
    }
    let settings = Settings {
        output: study.link("output", output)?,
        tolerance,
        min_dwell: min_dwell_deg.to_radians(),
        n,
    };
    let phases = invariants::phases(&study.analysis, &settings)?;
    Ok(Invariants {
        study,
        settings,
        phases,
    })
}

impl Invariants<'_> {
    /// How many phases.
    pub fn len(&self) -> usize {
        self.phases.len()
    }
    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.phases.is_empty()
    }
    /// As `mechplan invariants` prints them.
    pub fn to_table(&self) -> String {
        tables::invariants_table(&self.study.analysis, &self.settings, &self.phases)
    }
    /// As `mechplan invariants --format json` writes them.
    pub fn to_json(&self) -> serde_json::Value {
        tables::invariants_json(&self.study.analysis, &self.settings, &self.phases)
    }
    /// The same phases, typed, angles in degrees as the file writes them.
    pub fn phases(&self) -> Vec<tables::PhaseRecord> {
        tables::phase_records(&self.phases)
    }
}

/// The kinematic diagrams of an output by the chord method.
#[derive(Clone, Debug)]
pub struct Diagram<'a> {
    study: &'a Study,
    diagrams: Diagrams,
    /// The language of the table and the sheet: the scene's `want.lang`
    /// unless [`Diagram::in_lang`] asks another (`mechplan diagram --lang`).
    lang: Lang,
}

pub(super) fn diagram<'a>(
    study: &'a Study,
    output: Option<&str>,
    point: Option<&str>,
    n: usize,
) -> Result<Diagram<'a>> {
    if !(4..=3600).contains(&n) {
        return Err(Error::scene("n", "must be from 4 to 3600 intervals"));
    }
    let an = &*study.analysis;
    let out = study.link("output", output)?;
    let diagrams = match point {
        Some(name) => {
            let p = an.mech.scene.point_index(name).ok_or_else(|| {
                Error::scene("point", format!("the scene has no point \"{name}\""))
            })?;
            Diagrams::build_point(an, p, n, drawing::diagram::LENGTH)?
        }
        None => Diagrams::build(an, out, n, drawing::diagram::LENGTH)?,
    };
    Ok(Diagram {
        study,
        diagrams,
        lang: study.lang(),
    })
}

impl Diagram<'_> {
    /// The table and the sheet in `lang` (`mechplan diagram --lang`);
    /// None keeps the scene's `want.lang`.
    pub fn in_lang(mut self, lang: Option<Lang>) -> Self {
        if let Some(l) = lang {
            self.lang = l;
        }
        self
    }
    /// The language the table and the sheet are written in.
    pub fn lang(&self) -> Lang {
        self.lang
    }
    /// The table of the diagrams and their errors (`mechplan diagram`),
    /// in the scene's `want.lang` (or [`Diagram::in_lang`]'s): its words
    /// and its decimal mark.
    pub fn to_table(&self) -> String {
        tables::diagrams_table(&self.study.analysis, &self.diagrams, self.lang)
    }
    /// The diagrams' sheet (SVG), in the same language as the table.
    pub fn sheet(&self) -> Sheet {
        drawing::diagram::sheet(
            &self.study.analysis,
            &self.diagrams,
            &DrawOptions {
                lang: self.lang,
                ..DrawOptions::default()
            },
        )
    }
    /// The sheet written into `dir` in `format`.
    pub fn write_into(&self, dir: &Path, format: Format) -> Result<Written> {
        write_sheets(&[self.sheet()], dir, format, 150.0)
    }
}

/// The work-precision report of a scene.
#[derive(Clone, Debug)]
pub struct PrecisionReport(precision::Report);

pub(super) fn precision(study: &Study, settings: &precision::Settings) -> Result<PrecisionReport> {
    // The report holds every position's values and references at once.
    study.held()?;
    if !(settings.min_time.is_finite() && settings.min_time > 0.0) {
        return Err(Error::scene(
            "min-time",
            "must be a positive number of seconds",
        ));
    }
    Ok(PrecisionReport(precision::run_watched(
        &study.analysis,
        settings,
        study.watcher.get(),
    )?))
}

impl PrecisionReport {
    /// The report's table (Markdown).
    pub fn to_markdown(&self) -> String {
        precision_text::to_markdown(&self.0)
    }
    /// The plot of error against run time (SVG) titled `title`.
    pub fn to_svg(&self, title: &str) -> String {
        precision_text::to_svg(&self.0, title)
    }
    /// The table, the plot (SVG) and its picture (PNG) written into `dir`
    /// as `stem.md`, `stem.svg`, `stem.png`.
    pub fn write_into(&self, dir: &Path, stem: &str) -> Result<Written> {
        std::fs::create_dir_all(dir)
            .map_err(|e| files::write_error(&dir.display().to_string(), e))?;
        let table = self.to_markdown();
        let svg = self.to_svg(&format!("{stem}: error against run time"));
        let png = drawing::png(&svg, 150.0)?;
        let files: Vec<(PathBuf, &[u8])> = [
            ("md", table.as_bytes()),
            ("svg", svg.as_bytes()),
            ("png", png.as_slice()),
        ]
        .into_iter()
        .map(|(ext, bytes)| (dir.join(format!("{stem}.{ext}")), bytes))
        .collect();
        files::write_files_atomically(&files)?;
        Ok(Written {
            files: files.into_iter().map(|(p, _)| p).collect(),
            notes: Vec::new(),
        })
    }
    /// The rows of numbers (the internals, for the project's own tests).
    #[cfg(feature = "internals")]
    pub fn report(&self) -> &precision::Report {
        &self.0
    }
}
