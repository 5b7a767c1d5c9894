//! The library's front door: a [`Study`] is a scene read and made ready;
//! it solves, reports, draws and checks. Everything the `mechplan` command
//! does is one call here, so another program does it the same way.
//!
//! ```
//! use mechplan::Study;
//!
//! // The lecture's six-link mechanism, embedded in the crate.
//! let study = Study::from_json(mechplan::DEFAULT_SCENE)?;
//! let solution = study.solve()?;
//! // The slider D's velocity at the first position, by route (a) …
//! let d = study.analysis().mech.scene.point_index("D").unwrap();
//! let (v, _a) = solution.positions[0].point(study.analysis(), d).rates.unwrap();
//! // … and as measured on the velocity plan: the same, within its bound.
//! let plan = &solution.positions[0].plans.as_ref().unwrap().velocity;
//! let measured = plan.value_of(d).unwrap();
//! assert!((v - measured).hypot() < 1e-9);
//! // The result file of the contract.
//! let json = solution.to_json();
//! assert_eq!(json["mechplan"], 1);
//! # Ok::<(), mechplan::Error>(())
//! ```
//!
//! Parameters that the command line shows as options are named here by
//! their bare names (`output`, `position`, `sheet` …) in [`crate::Issue`]s.

use crate::error::{Error, Input, Result};
use crate::kinematics::construction::text::Lang;
use crate::kinematics::solve::{Analysis, Solved};
use crate::model::scene::Scene;
use crate::presentation::drawing::{self, DrawOptions, SheetSize};
use crate::presentation::report;
use crate::verification::check;
use std::path::{Path, PathBuf};

/// A scene read and made ready to solve.
#[derive(Clone, Debug)]
pub struct Study {
    analysis: Analysis,
}

/// The positions of a study, solved: both routes, the plans and their
/// cross-check at every one.
#[derive(Clone, Debug)]
pub struct Solution<'a> {
    study: &'a Study,
    /// Every position asked for, in order.
    pub positions: Vec<Solved>,
}

/// How `solve` writes its result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Results {
    /// The fixed-width table.
    Table,
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
    pub format: drawing::Format,
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
}

impl Default for DrawRequest {
    fn default() -> Self {
        DrawRequest {
            dir: PathBuf::from("mechplan-out"),
            format: drawing::Format::Svg,
            dpi: 150.0,
            sheet: None,
            lang: None,
            title_block: false,
            table: false,
            centres: false,
            html: false,
            course: false,
        }
    }
}

/// Name `name` in the messages of an input's problems ("… (in NAME)").
pub fn in_file(name: &str) -> impl Fn(Error) -> Error + '_ {
    move |e| match e {
        Error::Input(Input::Fields(mut v)) => {
            for i in &mut v {
                i.message = format!("{} (in {name})", i.message);
            }
            Error::fields(v)
        }
        e => e,
    }
}

/// Read a file whole, an error naming it if it cannot be read.
pub fn read(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })
}

impl Study {
    /// A scene from its JSON text.
    pub fn from_json(text: &str) -> Result<Study> {
        Ok(Study {
            analysis: Analysis::new(Scene::from_json(text)?)?,
        })
    }

    /// A scene from its JSON text, its problems saying `name` (a file).
    pub fn named(text: &str, name: &str) -> Result<Study> {
        Study::from_json(text).map_err(in_file(name))
    }

    /// A scene file.
    pub fn from_path(path: &Path) -> Result<Study> {
        Study::named(&read(path)?, &path.display().to_string())
    }

    /// The embedded default scene: the lecture's six-link mechanism.
    pub fn default_scene() -> Study {
        Study::named(crate::DEFAULT_SCENE, "the embedded default scene")
            .expect("the embedded scene is valid")
    }

    /// The analysis: mechanism, structure, what is wanted.
    pub fn analysis(&self) -> &Analysis {
        &self.analysis
    }

    /// The scene's language for annotations (`want.lang`).
    pub fn lang(&self) -> Lang {
        Lang::parse(&self.analysis.mech.scene.want.lang).unwrap_or(Lang::En)
    }

    /// How many positions the scene asks for.
    pub fn position_count(&self) -> Result<usize> {
        Ok(self.analysis.input_values()?.len())
    }

    /// Is `position` (from 1) one of the scene's? An error naming
    /// `parameter` and the range if not.
    pub fn position_in_range(&self, parameter: &str, position: usize) -> Result<()> {
        let count = self.position_count()?;
        if (1..=count).contains(&position) {
            return Ok(());
        }
        Err(Error::scene(
            parameter,
            format!(
                "position {position} is not one of the scene's positions: they are numbered from 1 to {count}"
            ),
        ))
    }

    /// Solve every position.
    pub fn solve(&self) -> Result<Solution<'_>> {
        Ok(Solution {
            study: self,
            positions: self.solved()?,
        })
    }

    /// Every position solved, a progress bar on a terminal for a long
    /// sweep (the solver only advances the bar it is given).
    fn solved(&self) -> Result<Vec<Solved>> {
        let mut out = Vec::new();
        self.each(|s| {
            out.push(s);
            Ok(())
        })?;
        Ok(out)
    }

    /// Each position as it is solved, in order, with the bar.
    fn each(&self, f: impl FnMut(Solved) -> Result<()>) -> Result<()> {
        let bar = crate::progress::bar(self.position_count()?, "positions");
        let done = self.analysis.run_each_with(&bar, f);
        bar.finish_and_clear();
        done
    }

    /// Write the results of every position in `style` to `out` (a file,
    /// atomically) or to standard output. Each position's text is written
    /// as soon as it is solved and the position dropped, so a long sweep
    /// costs no more memory than a short one; nothing is written if a
    /// position is refused.
    pub fn write_results(&self, style: Results, out: Option<&Path>) -> Result<()> {
        // A table or CSV prints no plan: the plans are checked only, built
        // by the sweep's kernel (`Analysis::keep_plans`).
        let lean;
        let study = match style {
            Results::Table | Results::Csv if self.analysis.keep_plans => {
                let mut analysis = self.analysis.clone();
                analysis.keep_plans = false;
                lean = Study { analysis };
                &lean
            }
            _ => self,
        };
        let an = &study.analysis;
        let style = match style {
            Results::Table => report::Style::Table,
            Results::Json => report::Style::Json,
            Results::Csv => report::Style::Csv,
            Results::Jsonl => report::Style::Jsonl,
            Results::Steps(lang) => report::Style::Steps(lang.unwrap_or_else(|| self.lang())),
        };
        let write = |out: &mut dyn FnMut(&str) -> Result<()>| -> Result<()> {
            out(&report::text_head(an, style))?;
            let mut count = 0;
            study.each(|s| {
                out(&report::text_position(an, style, count, &s))?;
                count += 1;
                Ok(())
            })?;
            out(&report::text_tail(an, style, count))
        };
        match out {
            None => {
                let mut spool = crate::output::Spool::new();
                write(&mut |t| spool.write(t))?;
                spool.finish()
            }
            Some(path) => {
                crate::output::write_atomically_with(path, |o| write(&mut |t| o.write(t)))
            }
        }
    }

    /// Draw the sheets (or the handout) into `req.dir`: the files written.
    pub fn draw(&self, req: &DrawRequest) -> Result<Vec<PathBuf>> {
        if !(req.dpi.is_finite() && (10.0..=1200.0).contains(&req.dpi)) {
            return Err(Error::scene(
                "dpi",
                format!("{} is not a resolution from 10 to 1200 dpi", req.dpi),
            ));
        }
        let an = &self.analysis;
        let lang = req.lang.unwrap_or_else(|| self.lang());
        let solved = self.solved()?;
        if req.html {
            return Ok(vec![drawing::html::write_handout(
                an, &solved, lang, &req.dir,
            )?]);
        }
        // A sheet asked for is the only one tried; else A4, the scales
        // filling it, or (for a μ_l the scene fixes) the smallest sheet
        // that holds the mechanism's drawings at it.
        let sizes = match req.sheet {
            Some(s) => vec![s],
            None => SheetSize::ALL.to_vec(),
        };
        let opt = DrawOptions {
            sheet: sizes[0],
            lang,
            title_block: req.title_block,
            table: req.table,
            centres: req.centres,
            course: req.course,
        };
        let (sheets, sheet) = drawing::sheets_on(an, &solved, &opt, &sizes)?;
        if sheet != sizes[0] {
            crate::output::note(&format!(
                "the drawing of the mechanism at μ_l = {} m/mm (want.scales.mu_l) does not fit sheet {:?}: drawn on {sheet:?}",
                an.mech.scene.want.scales.mu_l.unwrap_or(an.mu_l),
                sizes[0]
            ));
        }
        drawing::write_sheets(&sheets, &req.dir, req.format, req.dpi)
    }

    /// Check a student's force plan ([`check::forces::from_json`]).
    pub fn check_forces(
        &self,
        answer: &check::forces::ForceAnswer,
    ) -> Result<check::forces::ForceReport> {
        let solved = self.solved()?;
        check::forces::check(&self.analysis, &solved, answer)
    }

    /// Check a student's answer (read by [`check::answer::read`]).
    pub fn check(&self, answer: &check::answer::Answer) -> Result<check::Report> {
        let solved = self.solved()?;
        check::check(&self.analysis, &solved, answer)
    }

    /// The instant centres of every position (or of `position`, from 1),
    /// as a table or JSON.
    pub fn centres(&self, position: Option<usize>, json: bool) -> Result<String> {
        if let Some(p) = position {
            self.position_in_range("position", p)?;
        }
        let an = &self.analysis;
        let solved = self.solved()?;
        Ok(if json {
            pretty(&crate::presentation::studies::centres_json(
                an, &solved, position,
            ))
        } else {
            crate::presentation::studies::centres_table(an, &solved, position)
        })
    }

    /// The phases and motion-law invariants of link `output` (its id;
    /// default: the last group's last link), as a table or JSON.
    pub fn invariants(
        &self,
        output: Option<&str>,
        tolerance: f64,
        min_dwell_deg: f64,
        n: usize,
        json: bool,
    ) -> Result<String> {
        use crate::studies::invariants;
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
        let an = &self.analysis;
        let set = invariants::Settings {
            output: self.link("output", output)?,
            tolerance,
            min_dwell: min_dwell_deg.to_radians(),
            n,
        };
        let list = invariants::phases(an, &set)?;
        Ok(if json {
            pretty(&crate::presentation::studies::invariants_json(
                an, &set, &list,
            ))
        } else {
            crate::presentation::studies::invariants_table(an, &set, &list)
        })
    }

    /// The kinematic diagrams of link `output` (or of point `point` along
    /// its path) by the chord method over `n` intervals: the table, or the
    /// sheet written into `dir`.
    pub fn diagram(
        &self,
        output: Option<&str>,
        point: Option<&str>,
        n: usize,
        dir: Option<(&Path, drawing::Format)>,
    ) -> Result<Diagram> {
        use crate::studies::diagrams::Diagrams;
        if !(4..=3600).contains(&n) {
            return Err(Error::scene("n", "must be from 4 to 3600 intervals"));
        }
        let an = &self.analysis;
        let out = self.link("output", output)?;
        let d = match point {
            Some(name) => {
                let p = an.mech.scene.point_index(name).ok_or_else(|| {
                    Error::scene("point", format!("the scene has no point \"{name}\""))
                })?;
                Diagrams::build_point(an, p, n, drawing::diagram::LENGTH)?
            }
            None => Diagrams::build(an, out, n, drawing::diagram::LENGTH)?,
        };
        let Some((dir, format)) = dir else {
            return Ok(Diagram::Table(
                crate::presentation::studies::diagrams_table(an, &d),
            ));
        };
        let sheet = drawing::diagram::sheet(an, &d, &DrawOptions::default());
        Ok(Diagram::Written(drawing::write_sheets(
            &[sheet],
            dir,
            format,
            150.0,
        )?))
    }

    /// A link by its id, or the default output (the last group's last link).
    fn link(&self, parameter: &str, id: Option<&str>) -> Result<usize> {
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

    /// The work-precision report: its table, and with `dir` the table,
    /// the plot (SVG, PNG) written there as `stem.md`, `.svg`, `.png`.
    pub fn precision(
        &self,
        settings: &crate::verification::precision::Settings,
        dir: Option<(&Path, &str)>,
    ) -> Result<Precision> {
        use crate::verification::precision;
        if !(settings.min_time.is_finite() && settings.min_time > 0.0) {
            return Err(Error::scene(
                "min-time",
                "must be a positive number of seconds",
            ));
        }
        let report = precision::run(&self.analysis, settings)?;
        let table = precision::to_markdown(&report);
        let Some((dir, stem)) = dir else {
            return Ok(Precision::Table(table));
        };
        std::fs::create_dir_all(dir)
            .map_err(|e| crate::output::write_error(&dir.display().to_string(), e))?;
        let svg = precision::to_svg(&report, &format!("{stem}: error against run time"));
        let png = drawing::png(&svg, 150.0)?;
        let files: Vec<(PathBuf, &[u8])> = [
            ("md", table.as_bytes()),
            ("svg", svg.as_bytes()),
            ("png", png.as_slice()),
        ]
        .into_iter()
        .map(|(ext, bytes)| (dir.join(format!("{stem}.{ext}")), bytes))
        .collect();
        crate::output::write_files_atomically(&files)?;
        Ok(Precision::Written(
            files.into_iter().map(|(p, _)| p).collect(),
        ))
    }
}

/// A diagram's result: its table, or the sheet's files.
#[derive(Clone, Debug)]
pub enum Diagram {
    /// The table of the diagrams and their errors.
    Table(String),
    /// The sheet's files.
    Written(Vec<PathBuf>),
}

/// The precision report's result: its table, or the files written.
#[derive(Clone, Debug)]
pub enum Precision {
    /// The report's table (Markdown).
    Table(String),
    /// The table and the plot's files.
    Written(Vec<PathBuf>),
}

impl Solution<'_> {
    /// The result file of the contract (`solve --format json`).
    pub fn to_json(&self) -> serde_json::Value {
        report::to_json(&self.study.analysis, &self.positions)
    }

    /// The sheets of the drawings, on A4 (see [`Study::draw`] for files).
    pub fn sheets(&self, opt: &DrawOptions) -> Vec<drawing::Sheet> {
        drawing::sheets(&self.study.analysis, &self.positions, opt)
    }
}

/// Pretty JSON with a final newline.
fn pretty(v: &serde_json::Value) -> String {
    let mut t = serde_json::to_string_pretty(v).expect("JSON of numbers and strings");
    t.push('\n');
    t
}
