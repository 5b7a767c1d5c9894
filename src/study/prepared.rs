//! A scene read and made ready ([`Study`]): what it asks for, the
//! watcher of its long sweeps, and its results streamed as text. Solving
//! into typed results is `solution`'s, the studies `studies`'.

use super::files;
use crate::error::{Error, Result, in_file};
use crate::kinematics::solve::Analysis;
use crate::lang::Lang;
use crate::model::scene::{MAX_COUNT, MAX_POSITIONS, Numbering, Scene};
use crate::pipeline::Solved;
use crate::presentation::drawing::{self, DrawOptions, Format, SheetSize};
use crate::presentation::report;
use crate::progress::{Progress, Silent};
use crate::studies::chosen::Chosen;
use crate::studies::sheet_data::{SheetData, SheetNeeds};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A scene read and made ready to solve.
#[derive(Clone, Debug)]
pub struct Study {
    pub(super) analysis: Arc<Analysis>,
    pub(super) watcher: Watcher,
}

/// Who is told how far a long sweep has come (none by default).
#[derive(Clone, Default)]
pub(super) struct Watcher(Option<Arc<dyn Progress + Send>>);

impl Watcher {
    pub(super) fn get(&self) -> &dyn Progress {
        match &self.0 {
            Some(w) => &**w,
            None => &Silent,
        }
    }
}

impl std::fmt::Debug for Watcher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "Watcher(..)"
        } else {
            "Watcher(none)"
        })
    }
}

/// How `solve` writes its result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Results {
    /// The fixed-width table, in a language (default: the scene's
    /// `want.lang`).
    Table(Option<Lang>),
    /// The result file of the contract.
    Json,
    /// A row per position: the input values, the wanted points' places
    /// and rates, the solved links' angles and rates (docs/scene-format.md,
    /// "CSV and JSONL results").
    Csv,
    /// A line per position: the position's object of the JSON result.
    Jsonl,
    /// The construction as numbered lecture-style steps.
    Steps(Option<Lang>),
}

/// What `draw` makes.
#[derive(Clone, Debug)]
pub struct DrawRequest {
    /// The folder written into.
    pub dir: PathBuf,
    /// The sheets' file format.
    pub format: Format,
    /// Resolution of PNG sheets, dots per inch (10 to 1200).
    pub dpi: f64,
    /// The sheet size asked for; `None`: A4 (for a μ_l the scene fixes,
    /// the smallest of A4, A3, A2, A1 that holds the mechanism at it).
    pub sheet: Option<SheetSize>,
    /// The language of the annotations (default: the scene's).
    pub lang: Option<Lang>,
    /// A title block on every sheet.
    pub title_block: bool,
    /// The table of measured segments on the plans.
    pub table: bool,
    /// The instant centres on the plans of the mechanism.
    pub centres: bool,
    /// The step-by-step HTML handout instead of the sheets.
    pub html: bool,
    /// The course sheet (A1, or A2 with `sheet`), besides the sheets the
    /// scene asks for.
    pub course: bool,
    /// Only these positions' sheets (empty: every sheet), by their
    /// numbers in the study's numbering ([`Study::numbering`]: a `count`
    /// sweep from 0, given input values from 1), the numbers the sheets
    /// and their files show; drawn at the scales of the whole set; the
    /// folder's other sheets are left as they are.
    pub positions: Vec<usize>,
}

impl DrawRequest {
    /// The drawing's options: the sheet asked for (else A4), the language
    /// asked for (else `scene_lang`, the scene's).
    pub(super) fn options(&self, scene_lang: Lang) -> DrawOptions {
        DrawOptions {
            sheet: self.sheet.unwrap_or(SheetSize::A4),
            lang: self.lang.unwrap_or(scene_lang),
            title_block: self.title_block,
            table: self.table,
            centres: self.centres,
            course: self.course,
            fixed_sheet: self.sheet.is_some(),
        }
    }
}

impl Default for DrawRequest {
    fn default() -> Self {
        DrawRequest {
            dir: PathBuf::from("mechplan-out"),
            format: Format::Svg,
            dpi: 150.0,
            sheet: None,
            lang: None,
            title_block: false,
            table: false,
            centres: false,
            html: false,
            course: false,
            positions: Vec::new(),
        }
    }
}

impl DrawRequest {
    /// Refused before anything is solved: a resolution out of range.
    pub(super) fn validate(&self) -> Result<()> {
        if !(self.dpi.is_finite() && (10.0..=1200.0).contains(&self.dpi)) {
            return Err(Error::scene(
                "dpi",
                format!("{} is not a resolution from 10 to 1200 dpi", self.dpi),
            ));
        }
        Ok(())
    }
}

/// The index (from 0) of position `number` of `count` positions numbered
/// by `numbering`; else the message naming the range.
pub(super) fn position_index(
    numbering: Numbering,
    number: usize,
    count: usize,
) -> std::result::Result<usize, String> {
    crate::grading::position::StatedPosition::new(number).index(numbering, count)
}

/// The embedded default scene: the lecture's six-link mechanism (Fig. 2.10).
pub const DEFAULT_SCENE: &str = include_str!("../../fixtures/six_link_fig2_10.json");

/// Read a scene file whole, an error naming it if it cannot be read; one
/// of more than 4 MiB (the scene reader's bound: a device, an endless
/// pipe) is refused once that many bytes are read.
pub fn read(path: &Path) -> Result<String> {
    super::reads::read_text_bounded(path, crate::model::scene::MAX_FILE_BYTES as u64, "a scene")
}

impl Study {
    /// A scene from its JSON text (the scene file's format:
    /// docs/scene-format.md). Every problem of the scene is reported at
    /// once, each with its JSON pointer.
    ///
    /// # Errors
    ///
    /// [`Error::Input`]: broken JSON ([`Input::Json`](crate::error::Input::Json)), every problem of
    /// the fields at once, each at its JSON pointer (unknown names, a
    /// missing or non-finite number: [`Input::Fields`](crate::error::Input::Fields)), a structure with
    /// a mobility other than the number of inputs ([`Input::Structure`](crate::error::Input::Structure));
    /// [`Error::Unsolvable`] where the sketch cannot be assembled.
    ///
    /// # Examples
    ///
    /// ```
    /// // A four-bar: link 0 the frame (the first link), crank 1 turned
    /// // at 10 rad/s from 45°, coupler 2, rocker 3; lengths in m.
    /// let study = mechplan::Study::from_json(r#"{
    ///   "mechplan": 1,
    ///   "units": { "length": "m", "angle": "deg" },
    ///   "points": { "O1": [0, 0], "A": [0.0707, 0.0707],
    ///               "B": [0.3402, 0.2940], "O3": [0.4, 0] },
    ///   "links": { "0": { "points": ["O1", "O3"] },
    ///              "1": { "points": ["O1", "A"] },
    ///              "2": { "points": ["A", "B"] },
    ///              "3": { "points": ["O3", "B"] } },
    ///   "lengths": { "O1-A": 0.1, "A-B": 0.35, "O3-B": 0.3 },
    ///   "input": { "link": "1", "pivot": "O1", "angle": 45, "omega": 10 }
    /// }"#)?;
    /// assert_eq!(study.position_count()?, 1);
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn from_json(text: &str) -> Result<Study> {
        let analysis = Analysis::new(Scene::from_json(text)?)?;
        let study = Study {
            analysis: Arc::new(analysis),
            watcher: Watcher::default(),
        };
        // No sheet is composed here: the course sheet's scales are chosen
        // where it is drawn ([`Study::draw`]), or where a result file
        // states them (`solve --format json`, `jsonl`, `--steps`).
        Ok(study.fitted(&DrawRequest::default()))
    }

    /// Whether the sheets `opt` draws include the course sheet (`--course`,
    /// or `"course"` in the scene's `want.drawings`) with plans on it.
    pub(super) fn course_drawn(&self, opt: &DrawOptions) -> bool {
        let an = &self.analysis;
        an.plans && (opt.course || an.mech.scene.want.drawings.iter().any(|d| d == "course"))
    }

    /// The same study with its plans left to mechplan fitting the field
    /// of a single sheet of `req` (its size, title block, table): nothing
    /// solved, no sheet composed.
    pub(super) fn fitted(&self, req: &DrawRequest) -> Study {
        let opt = req.options(self.lang());
        let field = drawing::plan_field(&opt);
        if field == self.analysis.drafting.field {
            return self.clone();
        }
        let mut an = (*self.analysis).clone();
        an.drafting.field = field;
        Study {
            analysis: Arc::new(an),
            watcher: self.watcher.clone(),
        }
    }

    /// Every position solved for the sheets `req` draws, the pipeline run
    /// once: the plans fit a single sheet of `req` ([`Study::fitted`]);
    /// where the course sheet is drawn, its scales are chosen from the
    /// positions solved (by composing it) and the plans it shows are
    /// finished again at them ([`Analysis::run_rescaled`]), so that the
    /// sheets, tables and handout state the μ of the sheet each plan is
    /// drawn on. The study so prepared (its `scales_at` the course
    /// sheet's) and the positions, held only where a sheet reads them all
    /// at once (the course sheet, the handout, a plan scale the scene
    /// fixes, whose fit is judged over all positions): else none are
    /// solved here, and the sheets solve them again each time they read
    /// the sweep (`again::Again`).
    pub(super) fn solved_for_sheets(
        &self,
        req: &DrawRequest,
    ) -> Result<(Study, Option<Vec<Solved>>)> {
        self.held()?;
        let opt = req.options(self.lang());
        let fitted = self.fitted(req);
        if !fitted.course_drawn(&opt) {
            // No sheet reads every position at once: none held.
            let d = &fitted.analysis.drafting;
            if !req.html && d.mu_v.is_none() && d.mu_a.is_none() {
                return Ok((fitted, None));
            }
            let solved = fitted.solved()?;
            return Ok((fitted, Some(solved)));
        }
        let mut an = (*fitted.analysis).clone();
        an.scales_at = Arc::default();
        let (solved, scales) =
            an.run_rescaled(self.watcher.get(), &|n| Chosen::of(&an, n).shown(), |all| {
                drawing::course::plan_scales(&an, all, &SheetData::solve(&an, all, COURSE)?, &opt)
            })?;
        an.scales_at = scales;
        let study = Study {
            analysis: Arc::new(an),
            watcher: self.watcher.clone(),
        };
        Ok((study, Some(solved)))
    }

    /// The same study with its plans at the scales of the sheets `req`
    /// draws: a plan's μ is chosen once, for the sheet it is drawn on, and
    /// every output of the study states that μ (steps, result file,
    /// sheets, handout). A plan left to mechplan fits the field of a
    /// single sheet of `req` (its size, title block, table); where the
    /// course sheet is drawn (`req.course`, or `"course"` in the scene's
    /// `want.drawings`), the plans it shows are built at its scales (one
    /// μ_v for all its velocity plans), found by composing it from a first
    /// run — a run of its own, for a study to be solved again at them:
    /// [`Study::draw`] does not call this but runs the pipeline once, and
    /// a study read ([`Study::from_json`]) composes no sheet. (A study
    /// prepared for another sheet draws its plans at their own scales.)
    pub fn for_sheets(&self, req: &DrawRequest) -> Result<Study> {
        let opt = req.options(self.lang());
        let mut an = (*self.analysis).clone();
        an.drafting.field = drawing::plan_field(&opt);

        if self.course_drawn(&opt) {
            self.held()?;
            let mut first = Vec::new();
            an.run_each_with(self.watcher.get(), |s| {
                first.push(s);
                Ok(())
            })?;
            let data = SheetData::solve(&an, &first, COURSE)?;
            an.scales_at = Arc::new(drawing::course::plan_scales(&an, &first, &data, &opt)?);
        }
        let same = an.drafting.field == self.analysis.drafting.field
            && an.scales_at == self.analysis.scales_at;
        Ok(Study {
            analysis: if same {
                Arc::clone(&self.analysis)
            } else {
                Arc::new(an)
            },
            watcher: self.watcher.clone(),
        })
    }

    /// A scene from its JSON text, its problems saying `name` (a file).
    pub fn named(text: &str, name: &str) -> Result<Study> {
        Study::from_json(text).map_err(in_file(name))
    }

    /// A scene file.
    ///
    /// # Errors
    ///
    /// [`Error::Io`] where the file cannot be read (naming it), else those
    /// of [`Study::from_json`], each message naming the file.
    ///
    /// # Examples
    ///
    /// ```
    /// let dir = std::env::temp_dir().join("mechplan-doc-from-path");
    /// std::fs::create_dir_all(&dir).unwrap();
    /// let path = dir.join("scene.json");
    /// std::fs::write(&path, mechplan::DEFAULT_SCENE).unwrap();
    /// let study = mechplan::Study::from_path(&path)?;
    /// assert_eq!(study.position_count()?, 12);
    /// let missing = mechplan::Study::from_path(&dir.join("none.json")).unwrap_err();
    /// assert!(missing.to_string().contains("none.json"));
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn from_path(path: &Path) -> Result<Study> {
        Study::named(&read(path)?, &path.display().to_string())
    }

    /// The embedded default scene: the lecture's six-link mechanism.
    pub fn default_scene() -> Study {
        Study::named(DEFAULT_SCENE, "the embedded default scene")
            .expect("the embedded scene is valid")
    }

    /// The same study, telling `watcher` how far its long sweeps have
    /// come (the command's progress bar; the library itself prints
    /// nothing).
    pub fn watched_by(mut self, watcher: Arc<dyn Progress + Send>) -> Study {
        self.watcher = Watcher(Some(watcher));
        self
    }

    /// The analysis: mechanism, structure, what is wanted (the internals,
    /// for the project's own tests).
    #[cfg(feature = "internals")]
    pub fn analysis(&self) -> &Analysis {
        &self.analysis
    }

    /// A note for the user when the scene's lengths look like
    /// millimetres read as metres: the file states no `units.length` and
    /// its sketch is more than
    /// 20 m (`MILLIMETRES_LIKELY_M`)
    /// across. Nothing is refused: the scene is solved as written.
    pub fn units_note(&self) -> Option<String> {
        let m = &self.analysis.mech;
        let limit = crate::model::scene::MILLIMETRES_LIKELY_M;
        (!m.scene.length_stated && m.size > limit).then(|| {
            format!(
                "the scene states no \"units\": its lengths are read as metres, which makes the mechanism {} across (more than {limit} m); if they are millimetres, add \"units\": {{\"length\": \"mm\"}} to the scene",
                crate::format::format_quantity(m.size, "m")
            )
        })
    }

    /// The scene's language for annotations (`want.lang`).
    pub fn lang(&self) -> Lang {
        Lang::parse(&self.analysis.mech.scene.want.lang).unwrap_or(Lang::En)
    }

    /// Refuses a sweep of more than [`MAX_POSITIONS`] positions where
    /// every position is held at once (the sheets, the checks, the
    /// server, [`Study::solve`]): `solve` writes each position as it is
    /// solved and takes any count the scene may give ([`MAX_COUNT`]).
    pub(super) fn held(&self) -> Result<()> {
        let n = self.analysis.mech.scene.positions.count();
        if n <= MAX_POSITIONS {
            return Ok(());
        }
        Err(Error::scene(
            "/positions/count",
            format!(
                "{n} positions: drawing, checking and serving hold every position at once and take at most {MAX_POSITIONS}; `mechplan solve` writes each position as it is solved (every format) and takes up to {MAX_COUNT}"
            ),
        ))
    }

    /// How many positions the scene asks for.
    pub fn position_count(&self) -> Result<usize> {
        Ok(self.analysis.mech.scene.positions.count())
    }

    /// How this study numbers its positions in everything it writes and
    /// reads (sheets and their files, result files, `--position`, reports,
    /// the gradebook, the handout): the scene's — a `count` sweep from 0
    /// (position 0 the extreme position that starts the working stroke,
    /// as the lecture numbers them), given input values (`angles`, `s`,
    /// `values`) from 1 — unless [`Study::numbered`] says otherwise.
    pub fn numbering(&self) -> Numbering {
        self.analysis.numbering
    }

    /// The same study with its positions numbered by `numbering` in
    /// everything it writes and reads (`--positions-from`):
    /// [`Numbering::FROM_1`] reads and writes a `count` sweep's positions
    /// as mechplan numbered them before the one numbering (the K-th
    /// position is position K).
    ///
    /// ```
    /// use mechplan::{Numbering, Study};
    /// let study = Study::default_scene(); // a count sweep of 12
    /// assert_eq!(study.numbering(), Numbering::FROM_0);
    /// assert_eq!(study.solve()?.position(11)?.number(), 11); // the last
    /// let older = study.numbered(Numbering::FROM_1);
    /// assert_eq!(older.solve()?.position(12)?.number(), 12); // the same
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn numbered(&self, numbering: Numbering) -> Study {
        if numbering == self.analysis.numbering {
            return self.clone();
        }
        let mut an = (*self.analysis).clone();
        an.numbering = numbering;
        Study {
            analysis: Arc::new(an),
            watcher: self.watcher.clone(),
        }
    }

    /// The index (from 0, in the sweep's order) of position `number`, in
    /// the study's numbering ([`Study::numbering`]); an error naming
    /// `parameter` and the range if the scene has no such position.
    pub fn position_index(&self, parameter: &str, number: usize) -> Result<usize> {
        let count = self.position_count()?;
        position_index(self.numbering(), number, count).map_err(|m| Error::scene(parameter, m))
    }

    /// Each position of `an` (this study's analysis, or a variant of it)
    /// as it is solved, in order, told to the watcher.
    pub(super) fn each_of(&self, an: &Analysis, f: impl FnMut(Solved) -> Result<()>) -> Result<()> {
        an.run_each_with(self.watcher.get(), f)
    }

    /// The result style of the report module for `style`.
    fn style(&self, style: Results) -> report::Style {
        match style {
            Results::Table(lang) => report::Style::Table(lang.unwrap_or_else(|| self.lang())),
            Results::Json => report::Style::Json,
            Results::Csv => report::Style::Csv,
            Results::Jsonl => report::Style::Jsonl,
            Results::Steps(lang) => report::Style::Steps(lang.unwrap_or_else(|| self.lang())),
        }
    }

    /// Every position's results in `style`, handed to `out` a piece at a
    /// time: each position's text as soon as it is solved, the position
    /// then dropped, so that a long sweep costs no more memory than a
    /// short one.
    fn stream_results(
        &self,
        style: Results,
        out: &mut dyn FnMut(&str) -> Result<()>,
    ) -> Result<()> {
        // A table or CSV prints no plan: its plans are only checked, built
        // numbers only (`Analysis::keep_plans`: the same plans to the bit).
        // A result file that states the plans' μ states, for the plans
        // the course sheet shows (`"course"` in `want.drawings`), the
        // course sheet's, chosen here (by composing it from a run of its
        // own) since it is asked for: reading the scene composes nothing.
        let course;
        let study = match style {
            Results::Json | Results::Jsonl | Results::Steps(_)
                if self.analysis.scales_at.is_empty()
                    && self.course_drawn(&DrawRequest::default().options(self.lang())) =>
            {
                course = self.for_sheets(&DrawRequest::default())?;
                &course
            }
            _ => self,
        };
        let lean;
        let an = match style {
            Results::Table(_) | Results::Csv
                if self.analysis.keep_plans || self.analysis.printed_check =>
            {
                let mut a = (*self.analysis).clone();
                a.keep_plans = false;
                a.printed_check = false;
                lean = a;
                &lean
            }
            _ => &*study.analysis,
        };
        let style = self.style(style);
        out(&report::text_head(an, style))?;
        let mut count = 0;
        self.each_of(an, |s| {
            out(&report::text_position(an, style, count, &s))?;
            count += 1;
            Ok(())
        })?;
        out(&report::text_tail(an, style, count))
    }

    /// Write the results of every position in `style` to `out` as they
    /// are solved (flat memory however many positions). A position that
    /// cannot be solved stops the run with its error, what was written
    /// before it staying written: for all or nothing, write into a file
    /// ([`Study::write_results_to_file`]) or a [`files::Spool`].
    ///
    /// ```
    /// use mechplan::{Results, Study};
    /// let mut csv = Vec::new();
    /// Study::default_scene().write_results(Results::Csv, &mut csv)?;
    /// let text = String::from_utf8(csv).unwrap();
    /// assert!(text.lines().count() > 1);
    /// # Ok::<(), mechplan::Error>(())
    /// ```
    pub fn write_results(&self, style: Results, out: &mut dyn std::io::Write) -> Result<()> {
        let mut o = files::Output::new(out, "the output");
        self.stream_results(style, &mut |t| o.write(t))?;
        out.flush().map_err(|e| files::write_error("the output", e))
    }

    /// Write the results of every position in `style` into the file
    /// `path`, all or nothing (a temporary beside it, renamed into place
    /// when the last position is written).
    pub fn write_results_to_file(&self, style: Results, path: &Path) -> Result<()> {
        files::write_atomically_with(path, |o| self.stream_results(style, &mut |t| o.write(t)))
    }

    /// The results of every position in `style`, held back in `spool`
    /// (memory, then a temporary file) to be printed when all are solved.
    pub fn write_results_to_spool(&self, style: Results, spool: &mut files::Spool) -> Result<()> {
        self.stream_results(style, &mut |t| spool.write(t))
    }

    /// A link by its id, or the default output (the last group's last link).
    pub(super) fn link(&self, parameter: &str, id: Option<&str>) -> Result<usize> {
        let an = &self.analysis;
        match id {
            Some(id) => {
                an.mech.scene.link_index(id).ok_or_else(|| {
                    Error::scene(parameter, format!("the scene has no link \"{id}\""))
                })
            }
            None => Ok(crate::studies::invariants::default_output(an)),
        }
    }
}

/// What the course sheet draws beyond the positions, whose layout fixes
/// the scales of the plans it shows.
const COURSE: SheetNeeds = SheetNeeds {
    trajectories: true,
    diagrams: false,
    course: true,
};
