//! The `mechplan` command: parses arguments and calls the library.

use clap::{Parser, Subcommand, ValueEnum};
use mechplan::construction::text::Lang;
use mechplan::drawing::{self, DrawOptions, SheetSize};
use mechplan::output::stdout;
use mechplan::{Analysis, Error, Scene, report};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "mechplan",
    version,
    about = "Kinematic analysis of planar linkages by the graphoanalytic method of a TMM course"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Solve positions, velocities and accelerations of a scene (two analytic routes, cross-checked).
    Solve {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        #[arg(long, value_enum, default_value_t = Format::Table)]
        format: Format,
        /// Write to this file (atomically) instead of standard output.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Print the construction of the plans as numbered lecture-style steps.
        #[arg(long)]
        steps: bool,
        /// Language of the steps: en, uk or ru (default: the scene's want.lang).
        #[arg(long)]
        lang: Option<String>,
    },
    /// Check a hand-drawn plan (ANSWER: JSON or SVG) against the construction; exit 0 right, 1 wrong, 2 bad input, 3 output not written.
    Check {
        /// The scene file.
        scene: PathBuf,
        /// The student's answer: JSON (docs/check.md) or an SVG drawn in a vector editor.
        answer: PathBuf,
        #[arg(long, value_enum, default_value_t = CheckFormat::Text)]
        format: CheckFormat,
        /// Write an SVG overlaying the student's points on the correct plan.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// Pencil precision δ in mm (default: the answer's, else 0.5).
        #[arg(long)]
        delta: Option<f64>,
        /// For an SVG answer: the scale μ, if the drawing does not state it.
        #[arg(long)]
        mu: Option<f64>,
        /// For an SVG answer: velocity or acceleration, if the pole's label does not say.
        #[arg(long)]
        plan: Option<String>,
        /// Which of the scene's positions, from 1 (default: the answer file's, else 1).
        #[arg(long)]
        position: Option<usize>,
    },
    /// Draw the plan of the mechanism, the plans of velocities and accelerations (and positions) as sheets.
    Draw {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// Folder to write the sheets into.
        #[arg(short, long, default_value = "mechplan-out")]
        output: PathBuf,
        #[arg(long, value_enum, default_value_t = DrawFormat::Svg)]
        format: DrawFormat,
        /// Sheet size: A4, A3 or A1, landscape (default: the smallest whose field holds
        /// the mechanism's drawings at the scene's μ_l, A4 when it does).
        #[arg(long)]
        sheet: Option<String>,
        /// Add a title block to every sheet.
        #[arg(long)]
        title_block: bool,
        /// Add the table of measured segments to the plans.
        #[arg(long)]
        table: bool,
        /// Resolution of PNG sheets, dots per inch.
        #[arg(long, default_value_t = 150.0)]
        dpi: f64,
        /// Language of the annotations: en, uk or ru (default: the scene's want.lang).
        #[arg(long)]
        lang: Option<String>,
        /// Write DIR/handout.html instead of the sheets: one offline page with every
        /// position's drawings, the plans drawn step by step (Next/Previous, ← →) with
        /// their lecture-style sentences, and the result tables.
        #[arg(long, conflicts_with_all = ["format", "dpi", "sheet", "title_block", "table"])]
        html: bool,
        /// Mark the instant centres (Kennedy's theorem) on the plans of the mechanism.
        #[arg(long, conflicts_with = "html")]
        centres: bool,
    },
    /// Work-precision report: each method's error against an extended-precision reference, and its run time.
    Precision {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// Folder to write NAME.md, NAME.svg and NAME.png into (default: print the table).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Monte Carlo seeds of the emulated hand drafting.
        #[arg(long, default_value_t = 200)]
        seeds: u64,
        /// Compare at this many positions of a revolution (default: the scene's, or 36).
        #[arg(long)]
        positions: Option<usize>,
        /// Least wall time of one timing batch, seconds.
        #[arg(long, default_value_t = 0.1)]
        min_time: f64,
    },
    /// Instant centres of velocity of every two links (Kennedy's theorem), per position.
    Centres {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// Only this position (from 1).
        #[arg(long)]
        position: Option<usize>,
        #[arg(long, value_enum, default_value_t = Format::Table)]
        format: Format,
    },
    /// Motion-law invariants of an output (paper 003): phases, and the peak constants B, C, D.
    Invariants {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// The output link (id): a slider on a frame guide, or a rocking link (default: the last group's last link).
        #[arg(long)]
        output: Option<String>,
        /// Dwell tolerance E, relative to the whole stroke.
        #[arg(long, default_value_t = 1e-3)]
        tolerance: f64,
        /// Shortest dwell reported, degrees of the crank.
        #[arg(long, default_value_t = 10.0)]
        min_dwell: f64,
        /// Grid steps over a revolution.
        #[arg(long, default_value_t = 1440)]
        n: usize,
        #[arg(long, value_enum, default_value_t = Format::Table)]
        format: Format,
    },
    /// Kinematic diagrams of an output by the chord method of the lecture, with their errors.
    Diagram {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// The output link (id): a slider on a frame guide, or a rocking link (default: the last group's last link).
        #[arg(long, conflicts_with = "point")]
        output: Option<String>,
        /// A point instead: its displacement along its path (arc length), speed and tangential acceleration.
        #[arg(long)]
        point: Option<String>,
        /// Intervals per revolution.
        #[arg(short, default_value_t = 12)]
        n: usize,
        /// Write the sheet into this folder instead of printing the table.
        #[arg(short, long)]
        output_dir: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = DrawFormat::Svg)]
        format: DrawFormat,
    },
    /// Families of link positions in the Frenet trihedron (paper 001, Figs 2, 3, 5) as sheets.
    Frenet {
        /// Folder to write the sheets into.
        #[arg(short, long, default_value = "mechplan-out")]
        output: PathBuf,
        #[arg(long, value_enum, default_value_t = DrawFormat::Svg)]
        format: DrawFormat,
        /// Segments per revolution of the guide circle.
        #[arg(long, default_value_t = 36)]
        count: usize,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum DrawFormat {
    Svg,
    Png,
    Pdf,
}

#[derive(Clone, Copy, ValueEnum)]
enum CheckFormat {
    Text,
    Json,
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Table,
    Json,
}

/// What to print, and where.
struct Options {
    format: Format,
    output: Option<PathBuf>,
    steps: bool,
    lang: Option<String>,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(Command::Check {
        scene,
        answer,
        format,
        svg,
        delta,
        mu,
        plan,
        position,
    }) = cli.command
    {
        return finish(check(CheckArgs {
            scene,
            answer,
            format,
            svg,
            delta,
            mu,
            plan,
            position,
        }));
    }
    let result = match cli.command {
        Some(Command::Check { .. }) => unreachable!("handled above"),
        Some(Command::Precision {
            scene,
            output,
            seeds,
            positions,
            min_time,
        }) => precision(&scene, output.as_deref(), seeds, positions, min_time),
        Some(Command::Centres {
            scene,
            position,
            format,
        }) => centres(&scene, position, format),
        Some(Command::Invariants {
            scene,
            output,
            tolerance,
            min_dwell,
            n,
            format,
        }) => invariants(&scene, output, tolerance, min_dwell, n, format),
        Some(Command::Diagram {
            scene,
            output,
            point,
            n,
            output_dir,
            format,
        }) => diagram(&scene, (output, point), n, output_dir.as_deref(), format),
        Some(Command::Frenet {
            output,
            format,
            count,
        }) => frenet(&output, format, count),
        None => run(
            mechplan::DEFAULT_SCENE,
            "the embedded default scene",
            Options {
                format: Format::Table,
                output: None,
                steps: false,
                lang: None,
            },
        )
        .and_then(|()| {
            draw(
                mechplan::DEFAULT_SCENE,
                "the embedded default scene",
                DrawArgs {
                    dpi: 150.0,
                    dir: PathBuf::from("mechplan-out"),
                    format: DrawFormat::Svg,
                    sheet: None,
                    title_block: false,
                    table: false,
                    lang: None,
                    html: false,
                    centres: false,
                },
            )
        }),
        Some(Command::Draw {
            scene,
            output,
            format,
            sheet,
            title_block,
            table,
            dpi,
            lang,
            html,
            centres,
        }) => match std::fs::read_to_string(&scene) {
            Ok(text) => draw(
                &text,
                &scene.display().to_string(),
                DrawArgs {
                    dpi,
                    dir: output,
                    format,
                    sheet,
                    title_block,
                    table,
                    lang,
                    html,
                    centres,
                },
            ),
            Err(source) => Err(Error::Io {
                path: scene.display().to_string(),
                source,
            }),
        },
        Some(Command::Solve {
            scene,
            format,
            output,
            steps,
            lang,
        }) => match std::fs::read_to_string(&scene) {
            Ok(text) => run(
                &text,
                &scene.display().to_string(),
                Options {
                    format,
                    output,
                    steps,
                    lang,
                },
            ),
            Err(source) => Err(Error::Io {
                path: scene.display().to_string(),
                source,
            }),
        },
    };
    let result = match result {
        Ok(()) => Ok(true),
        Err(e) => Err(e),
    };
    finish(result.map(|ok| if ok { 0 } else { 1 }))
}

/// Exit status: 0 done (or all right), 1 a checked answer has wrong items,
/// 2 bad input, 3 a result could not be written.
/// The exit status: the command's own (0 success; `check`: 1 an item
/// wrong, 4 an item that cannot be judged), 2 bad input, 3 a failed write.
fn finish(result: Result<u8, Error>) -> ExitCode {
    match result {
        Ok(status) => ExitCode::from(status),
        Err(mut e) => {
            // The library names its parameters; here they are options.
            if let Some(issues) = e.issues_mut() {
                for i in issues {
                    if ["output", "point", "sheet", "position", "tolerance"]
                        .contains(&i.pointer.as_str())
                    {
                        i.pointer = format!("--{}", i.pointer);
                    }
                }
            }
            // Standard error may fail too; the status still tells.
            let _ = writeln!(
                std::io::stderr(),
                "mechplan: {}",
                e.to_string().replace('\n', "\nmechplan: ")
            );
            ExitCode::from(match e {
                Error::Write { .. } => 3,
                Error::Internal(_) => 5,
                _ => 2,
            })
        }
    }
}

struct CheckArgs {
    scene: PathBuf,
    answer: PathBuf,
    format: CheckFormat,
    svg: Option<PathBuf>,
    delta: Option<f64>,
    mu: Option<f64>,
    plan: Option<String>,
    position: Option<usize>,
}

/// `mechplan check`: Ok(true) when every item is right.
fn check(a: CheckArgs) -> Result<u8, Error> {
    use mechplan::check;
    let read = |p: &Path| {
        std::fs::read_to_string(p).map_err(|source| Error::Io {
            path: p.display().to_string(),
            source,
        })
    };
    let scene_text = read(&a.scene)?;
    let in_answer = |e: Error| match e {
        Error::Input(mechplan::error::Input::Fields(mut v)) => {
            for i in &mut v {
                i.message = format!("{} (in {})", i.message, a.answer.display());
            }
            Error::fields(v)
        }
        e => e,
    };
    let answer_text = read_answer(&a.answer).map_err(in_answer)?;
    if let Some(d) = a.delta
        && !(d.is_finite() && d > 0.0)
    {
        return Err(Error::scene(
            "--delta",
            "the pencil precision must be a positive number of mm",
        ));
    }
    let is_svg = a
        .answer
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
        || answer_text.trim_start().starts_with('<');
    let mut ans = if is_svg {
        let plan = match a.plan.as_deref() {
            None => None,
            Some("velocity") => Some(mechplan::construction::PlanKind::Velocity),
            Some("acceleration") => Some(mechplan::construction::PlanKind::Acceleration),
            Some(p) => {
                return Err(Error::scene(
                    "--plan",
                    format!("unknown plan \"{p}\": velocity or acceleration"),
                ));
            }
        };
        check::svg::from_svg(
            &answer_text,
            a.mu,
            plan,
            a.delta.unwrap_or(0.5),
            a.position.unwrap_or(1),
        )
        .map_err(in_answer)?
    } else {
        check::answer::from_json(&answer_text).map_err(in_answer)?
    };
    if let Some(d) = a.delta {
        ans.delta = d;
    }
    if let Some(p) = a.position {
        ans.position = p;
    }
    let scene =
        Scene::from_json(&scene_text).map_err(with_file_name(&a.scene.display().to_string()))?;
    let analysis = Analysis::new(scene).map_err(with_file_name(&a.scene.display().to_string()))?;
    let count = analysis.input_values()?.len();
    match a.position {
        Some(p) => position_in_range("--position", p, count)?,
        None => position_in_range("/position", ans.position, count).map_err(in_answer)?,
    }
    let solved = analysis.run()?;
    let report = check::check(&analysis, &solved, &ans).map_err(in_answer)?;
    let text = match a.format {
        CheckFormat::Text => check::to_text(&report),
        CheckFormat::Json => {
            serde_json::to_string_pretty(&check::to_json(&report)).expect("finite numbers") + "\n"
        }
    };
    if let Some(out) = &a.svg {
        mechplan::write_atomically(out, check::overlay(&analysis, &ans, &report).as_bytes())?;
    }
    stdout(&text)?;
    Ok(report.status())
}

/// Positions are numbered from 1: `p` must be one of the scene's `count`.
fn position_in_range(option: &str, p: usize, count: usize) -> Result<(), Error> {
    if (1..=count).contains(&p) {
        return Ok(());
    }
    Err(Error::scene(
        option,
        format!(
            "position {p} is not one of the scene's positions: they are numbered from 1 to {count}"
        ),
    ))
}

/// Read an answer file, refusing one larger than
/// [`mechplan::check::answer::MAX_ANSWER_BYTES`] before reading it.
fn read_answer(p: &Path) -> Result<String, Error> {
    use mechplan::check::answer::{MAX_ANSWER_BYTES, check_size};
    use std::io::Read;
    let io = |source| Error::Io {
        path: p.display().to_string(),
        source,
    };
    let f = std::fs::File::open(p).map_err(io)?;
    if let Ok(md) = f.metadata() {
        check_size(md.len())?;
    }
    let mut text = String::new();
    f.take(MAX_ANSWER_BYTES as u64 + 1)
        .read_to_string(&mut text)
        .map_err(io)?;
    check_size(text.len() as u64)?;
    Ok(text)
}

struct DrawArgs {
    dpi: f64,
    dir: PathBuf,
    format: DrawFormat,
    sheet: Option<String>,
    title_block: bool,
    table: bool,
    lang: Option<String>,
    /// The step-by-step handout instead of the sheets.
    html: bool,
    /// Instant centres on the plans of the mechanism.
    centres: bool,
}

fn parse_lang(l: &Option<String>) -> Result<Option<Lang>, Error> {
    match l {
        None => Ok(None),
        Some(l) => Lang::parse(l).map(Some).ok_or_else(|| {
            Error::scene(
                "--lang",
                format!("unknown language \"{l}\": use en, uk or ru"),
            )
        }),
    }
}

fn with_file_name(name: &str) -> impl Fn(Error) -> Error + '_ {
    move |e| match e {
        Error::Input(mechplan::error::Input::Fields(mut v)) => {
            for i in &mut v {
                i.message = format!("{} (in {name})", i.message);
            }
            Error::fields(v)
        }
        e => e,
    }
}

fn draw(text: &str, name: &str, a: DrawArgs) -> Result<(), Error> {
    let lang = parse_lang(&a.lang)?;
    // A sheet asked for is the only one tried; else the smallest that
    // holds the drawings at the scene's μ_l.
    let sizes = match &a.sheet {
        Some(s) => vec![SheetSize::parse(s).ok_or_else(|| {
            Error::scene(
                "--sheet",
                format!("unknown sheet \"{s}\": use A4, A3 or A1"),
            )
        })?],
        None => vec![SheetSize::A4, SheetSize::A3, SheetSize::A1],
    };
    let scene = Scene::from_json(text).map_err(with_file_name(name))?;
    let lang = lang.unwrap_or_else(|| Lang::parse(&scene.want.lang).unwrap_or(Lang::En));
    let analysis = Analysis::new(scene).map_err(with_file_name(name))?;
    let solved = analysis.run()?;
    if a.html {
        let path = drawing::html::write_handout(&analysis, &solved, lang, &a.dir)?;
        return stdout(&format!("wrote {}\n", path.display()));
    }
    let opt = DrawOptions {
        sheet: sizes[0],
        lang,
        title_block: a.title_block,
        table: a.table,
        centres: a.centres,
    };
    // μ_l is the scene's, as `solve` reports it: never changed to fit.
    let (mut sheets, sheet) = drawing::sheets_at_scene_scale(&analysis, &solved, &opt, &sizes)?;
    if sheet != sizes[0] {
        let _ = writeln!(
            std::io::stderr(),
            "mechplan: note: the drawing of the mechanism at μ_l = {} m/mm does not fit sheet {:?}: drawn on {sheet:?}",
            analysis.mu_l,
            sizes[0]
        );
    }
    let opt = DrawOptions { sheet, ..opt };
    sheets.extend(drawing::diagram::wanted(&analysis, &opt)?);
    let format = match a.format {
        DrawFormat::Svg => drawing::Format::Svg,
        DrawFormat::Png => drawing::Format::Png,
        DrawFormat::Pdf => drawing::Format::Pdf,
    };
    if !(a.dpi.is_finite() && (10.0..=1200.0).contains(&a.dpi)) {
        return Err(Error::scene(
            "--dpi",
            format!("{} is not a resolution from 10 to 1200 dpi", a.dpi),
        ));
    }
    let written = drawing::write_sheets(&sheets, &a.dir, format, a.dpi)?;
    stdout(&wrote(&written))
}

/// "wrote PATH" lines for the files written.
fn wrote(paths: &[PathBuf]) -> String {
    paths
        .iter()
        .map(|p| format!("wrote {}\n", p.display()))
        .collect()
}

fn run(text: &str, name: &str, opt: Options) -> Result<(), Error> {
    let prefix = |e: Error| match e {
        Error::Input(mechplan::error::Input::Fields(mut v)) => {
            for i in &mut v {
                i.message = format!("{} (in {name})", i.message);
            }
            Error::fields(v)
        }
        e => e,
    };
    let lang = match &opt.lang {
        None => None,
        Some(l) => Some(Lang::parse(l).ok_or_else(|| {
            Error::scene(
                "--lang",
                format!("unknown language \"{l}\": use en, uk or ru"),
            )
        })?),
    };
    let scene = Scene::from_json(text).map_err(prefix)?;
    let lang = lang.unwrap_or_else(|| Lang::parse(&scene.want.lang).unwrap_or(Lang::En));
    let analysis = Analysis::new(scene).map_err(prefix)?;
    let style = match (opt.steps, opt.format) {
        (true, _) => report::Style::Steps(lang),
        (false, Format::Table) => report::Style::Table,
        (false, Format::Json) => report::Style::Json,
    };
    // Each position's text is written as soon as the position is solved,
    // and the position dropped: a long sweep costs no more memory than a
    // short one. The text goes to a temporary file (-o) or is held back
    // (standard output), so a run refused at a late position writes nothing.
    let write = |out: &mut dyn FnMut(&str) -> Result<(), Error>| -> Result<(), Error> {
        out(&report::text_head(&analysis, style))?;
        let mut count = 0;
        analysis.run_each(|s| {
            out(&report::text_position(&analysis, style, count, &s))?;
            count += 1;
            Ok(())
        })?;
        out(&report::text_tail(&analysis, style, count))
    };
    match opt.output.as_deref() {
        None => {
            let mut spool = mechplan::output::Spool::new();
            write(&mut |t| spool.write(t))?;
            spool.finish()
        }
        Some(path) => mechplan::output::write_atomically_with(path, |o| write(&mut |t| o.write(t))),
    }
}

/// `mechplan precision`: the work-precision table (and plot with -o).
fn precision(
    scene: &Path,
    dir: Option<&Path>,
    seeds: u64,
    positions: Option<usize>,
    min_time: f64,
) -> Result<(), Error> {
    use mechplan::precision;
    let name = scene.display().to_string();
    let text = std::fs::read_to_string(scene).map_err(|source| Error::Io {
        path: name.clone(),
        source,
    })?;
    if !(min_time.is_finite() && min_time > 0.0) {
        return Err(Error::scene(
            "--min-time",
            "must be a positive number of seconds",
        ));
    }
    let sc = Scene::from_json(&text).map_err(with_file_name(&name))?;
    let analysis = Analysis::new(sc).map_err(with_file_name(&name))?;
    let settings = precision::Settings {
        seeds,
        positions,
        min_time,
        ..precision::Settings::default()
    };
    let report = precision::run(&analysis, &settings)?;
    let table = precision::to_markdown(&report);
    let Some(dir) = dir else {
        return stdout(&table);
    };
    std::fs::create_dir_all(dir)
        .map_err(|e| mechplan::output::write_error(&dir.display().to_string(), e))?;
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    let svg = precision::to_svg(&report, &format!("{stem}: error against run time"));
    let png = mechplan::drawing::png(&svg, 150.0)?;
    let files: Vec<(PathBuf, &[u8])> = [
        ("md", table.as_bytes()),
        ("svg", svg.as_bytes()),
        ("png", png.as_slice()),
    ]
    .into_iter()
    .map(|(ext, bytes)| (dir.join(format!("{stem}.{ext}")), bytes))
    .collect();
    mechplan::output::write_files_atomically(&files)?;
    let paths: Vec<PathBuf> = files.into_iter().map(|(p, _)| p).collect();
    stdout(&wrote(&paths))
}

/// `mechplan centres`: the instant centres of every position (or one).
fn centres(scene: &Path, position: Option<usize>, format: Format) -> Result<(), Error> {
    let name = scene.display().to_string();
    let text = std::fs::read_to_string(scene).map_err(|source| Error::Io {
        path: name.clone(),
        source,
    })?;
    let sc = Scene::from_json(&text).map_err(with_file_name(&name))?;
    let analysis = Analysis::new(sc).map_err(with_file_name(&name))?;
    if let Some(p) = position {
        position_in_range("--position", p, analysis.input_values()?.len())?;
    }
    let solved = analysis.run()?;
    let out = match format {
        Format::Table => mechplan::centres::to_table(&analysis, &solved, position),
        Format::Json => {
            let mut t = serde_json::to_string_pretty(&mechplan::centres::to_json(
                &analysis, &solved, position,
            ))
            .expect("JSON of numbers and strings");
            t.push('\n');
            t
        }
    };
    stdout(&out)
}

/// `mechplan invariants`: the phases of an output and their peak constants.
fn invariants(
    scene: &Path,
    output: Option<String>,
    tolerance: f64,
    min_dwell: f64,
    n: usize,
    format: Format,
) -> Result<(), Error> {
    use mechplan::invariants;
    let name = scene.display().to_string();
    let text = std::fs::read_to_string(scene).map_err(|source| Error::Io {
        path: name.clone(),
        source,
    })?;
    if !(tolerance.is_finite() && (0.0..0.5).contains(&tolerance)) {
        return Err(Error::scene(
            "--tolerance",
            "must be a fraction of the stroke from 0 to 0.5",
        ));
    }
    if !(min_dwell.is_finite() && (0.0..360.0).contains(&min_dwell)) {
        return Err(Error::scene("--min-dwell", "must be from 0 to 360 degrees"));
    }
    if !(36..=1_000_000).contains(&n) {
        return Err(Error::scene("--n", "must be from 36 to 1000000 steps"));
    }
    let sc = Scene::from_json(&text).map_err(with_file_name(&name))?;
    let analysis = Analysis::new(sc).map_err(with_file_name(&name))?;
    let out =
        match &output {
            Some(id) => analysis.mech.scene.link_index(id).ok_or_else(|| {
                Error::scene("--output", format!("the scene has no link \"{id}\""))
            })?,
            None => invariants::default_output(&analysis),
        };
    let set = invariants::Settings {
        output: out,
        tolerance,
        min_dwell: min_dwell.to_radians(),
        n,
    };
    let list = invariants::phases(&analysis, &set)?;
    let text = match format {
        Format::Table => invariants::to_table(&analysis, &set, &list),
        Format::Json => {
            let mut t = serde_json::to_string_pretty(&invariants::to_json(&analysis, &set, &list))
                .expect("JSON of numbers and strings");
            t.push('\n');
            t
        }
    };
    stdout(&text)
}

/// `mechplan frenet`: the families of link positions of paper 001.
fn frenet(dir: &Path, format: DrawFormat, count: usize) -> Result<(), Error> {
    if !(2..=10_000).contains(&count) {
        return Err(Error::scene("--count", "must be from 2 to 10000 segments"));
    }
    let sheets = drawing::frenet::sheets(count, &DrawOptions::default());
    let format = match format {
        DrawFormat::Svg => drawing::Format::Svg,
        DrawFormat::Png => drawing::Format::Png,
        DrawFormat::Pdf => drawing::Format::Pdf,
    };
    stdout(&wrote(&drawing::write_sheets(&sheets, dir, format, 150.0)?))
}

/// `mechplan diagram`: the kinematic diagrams of an output, as a table or a sheet.
fn diagram(
    scene: &Path,
    (output, point): (Option<String>, Option<String>),
    n: usize,
    dir: Option<&Path>,
    format: DrawFormat,
) -> Result<(), Error> {
    use mechplan::diagrams::Diagrams;
    let name = scene.display().to_string();
    let text = std::fs::read_to_string(scene).map_err(|source| Error::Io {
        path: name.clone(),
        source,
    })?;
    if !(4..=3600).contains(&n) {
        return Err(Error::scene("-n", "must be from 4 to 3600 intervals"));
    }
    let sc = Scene::from_json(&text).map_err(with_file_name(&name))?;
    let analysis = Analysis::new(sc).map_err(with_file_name(&name))?;
    let out =
        match &output {
            Some(id) => analysis.mech.scene.link_index(id).ok_or_else(|| {
                Error::scene("--output", format!("the scene has no link \"{id}\""))
            })?,
            None => mechplan::invariants::default_output(&analysis),
        };
    let d = match &point {
        Some(name) => {
            let p = analysis.mech.scene.point_index(name).ok_or_else(|| {
                Error::scene("--point", format!("the scene has no point \"{name}\""))
            })?;
            Diagrams::build_point(&analysis, p, n, drawing::diagram::LENGTH)?
        }
        None => Diagrams::build(&analysis, out, n, drawing::diagram::LENGTH)?,
    };
    let Some(dir) = dir else {
        return stdout(&mechplan::diagrams::to_table(&analysis, &d));
    };
    let sheet = drawing::diagram::sheet(&analysis, &d, &DrawOptions::default());
    let format = match format {
        DrawFormat::Svg => drawing::Format::Svg,
        DrawFormat::Png => drawing::Format::Png,
        DrawFormat::Pdf => drawing::Format::Pdf,
    };
    stdout(&wrote(&drawing::write_sheets(
        &[sheet],
        dir,
        format,
        150.0,
    )?))
}
