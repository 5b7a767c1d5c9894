//! The `mechplan` command's arguments (a module of the binary, not of the
//! library): the commands and their options, as clap parses them.

use clap::{Parser, Subcommand, ValueEnum};
use mechplan::Lang;
use mechplan::Numbering;
use mechplan::PlanKind;
use mechplan::{Format as SheetFormat, SheetSize};
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "mechplan",
    version,
    about = "Kinematic analysis of planar linkages by the graphoanalytic method of a TMM course"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand)]
pub enum Command {
    /// Solve positions, velocities and accelerations of a scene (two analytic routes, cross-checked); with dynamics, the forces too (three routes).
    Solve {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// table; json (the result file); csv (a row per position: inputs, the wanted
        /// points' x, y, v, a and links' angle, ω, ε); jsonl (a position per line).
        #[arg(long, value_enum, default_value_t = SolveFormat::Table)]
        format: SolveFormat,
        /// Write to this file (atomically) instead of standard output.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Print the construction of the plans as numbered lecture-style steps.
        #[arg(long)]
        steps: bool,
        /// Language of the table and of the steps: en, uk or ru, their words and decimal mark
        /// (default: the scene's want.lang); json, csv and jsonl are written as they are.
        #[arg(long, value_parser = lang)]
        lang: Option<Lang>,
        /// Number the positions from 0 or from 1 in everything the command reads and writes
        /// (default: the scene's, a count sweep from 0 as the sheets show, given input
        /// values from 1); 1 reads the older numbering of a count sweep (the K-th position
        /// is position K).
        #[arg(long, value_parser = numbering)]
        positions_from: Option<Numbering>,
    },
    /// Check a hand-drawn plan of velocities, accelerations or forces (ANSWER: JSON, SVG or DXF) against the construction; exit 0 right, 1 wrong, 4 some items cannot be judged, 2 bad input, 3 output not written. Several ANSWERs or a folder: a group, graded into OUT/gradebook.csv, OUT/summary.html and OUT/overlays/ (exit 2 if an answer is unreadable, else 1 if one is wrong, else 4 if one cannot be judged).
    Check {
        /// The scene file.
        scene: PathBuf,
        /// The student's answer: JSON (docs/check.md), an SVG drawn in a vector editor or a
        /// DXF drawn in a CAD; or several, or a folder of them (its *.json, *.svg and *.dxf
        /// files): a group.
        #[arg(required = true, value_name = "ANSWER")]
        answers: Vec<PathBuf>,
        /// A group's output folder: gradebook.csv, summary.html, overlays/ (default:
        /// mechplan-check; given with a single answer, that answer is a group of one).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// text, or json (a group: one JSON array of the answers' reports).
        #[arg(long, value_enum, default_value_t = CheckFormat::Text)]
        format: CheckFormat,
        /// Write an SVG overlaying the student's points on the correct plan.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// For a DXF answer: write a copy of it with the same overlay on its own layer
        /// (MECHPLAN-CHECK), to open in the CAD it was drawn in.
        #[arg(long)]
        dxf: Option<PathBuf>,
        /// For a marks file (a photographed plan): write an SVG of the photo with the plan
        /// from the student's points, their points and the wrong steps drawn over it in the
        /// photo's own perspective (the photo linked, not copied).
        #[arg(long)]
        photo_overlay: Option<PathBuf>,
        /// Pencil precision δ in mm (default: the answer's, else 0.5).
        #[arg(long)]
        delta: Option<f64>,
        /// For an SVG or DXF answer: the scale μ, if the drawing does not state it; for a force plan
        /// (μ_F, N/mm) it overrides the answer's.
        #[arg(long)]
        mu: Option<f64>,
        /// For an SVG or DXF answer: velocity or acceleration, if the pole's label does not say.
        #[arg(long, value_parser = plan)]
        plan: Option<PlanKind>,
        /// Which of the scene's positions: its number as the sheets show it (a count sweep
        /// from 0, given input values from 1; default: the answer file's, else the first).
        #[arg(long)]
        position: Option<usize>,
        /// Number the positions from 0 or from 1 in --position, in the answers that do not
        /// state their own "positions_from", in the report and the gradebook (default: the
        /// scene's, a count sweep from 0 as the sheets show, given input values from 1); 1
        /// reads the older numbering of a count sweep (the K-th position is position K).
        #[arg(long, value_parser = numbering)]
        positions_from: Option<Numbering>,

        /// Language of the report: en, uk or ru (default: the scene's want.lang); JSON keeps
        /// its keys and judgements in English.
        #[arg(long, value_parser = lang)]
        lang: Option<Lang>,
    },
    /// Draw the plan of the mechanism, the plans of velocities and accelerations (and positions) as sheets; with dynamics, the force sheets and Zhukovsky's lever too.
    Draw {
        /// The scene file (JSON, see docs/scene-format.md).
        scene: PathBuf,
        /// Folder to write the sheets into.
        #[arg(short, long, default_value = "mechplan-out")]
        output: PathBuf,
        #[arg(long, value_enum, default_value_t = DrawFormat::Svg)]
        format: DrawFormat,
        /// Sheet size: A4, A3, A2 or A1, landscape (default A4; the plans are built at the
        /// scale that fills it, the other figures drawn so; with want.scales.mu_l, the
        /// smallest sheet that holds the mechanism).
        #[arg(long, value_parser = sheet)]
        sheet: Option<SheetSize>,
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
        #[arg(long, value_parser = lang)]
        lang: Option<Lang>,
        /// Write DIR/handout.html instead of the sheets: one offline page with every
        /// position's drawings, the plans drawn step by step (Next/Previous, ← →) with
        /// their lecture-style sentences, and the result tables.
        #[arg(long, conflicts_with_all = ["format", "dpi", "sheet", "title_block", "table"])]
        html: bool,
        /// Mark the instant centres (Kennedy's theorem) on the plans of the mechanism.
        #[arg(long, conflicts_with = "html")]
        centres: bool,
        /// Also compose the course sheet (course.svg): the kinematic analysis sheet of a
        /// course project on A1 (A2 with --sheet A2), with the ГОСТ 2.104 title block.
        #[arg(long, conflicts_with = "html")]
        course: bool,
        /// Only the sheets of these positions, by the numbers the sheets show (a count sweep
        /// from 0, given input values from 1; a list: 0,4,7), at the scales of the whole
        /// set; the folder's other sheets are left as they are.
        #[arg(long, value_delimiter = ',', conflicts_with = "html")]
        position: Vec<usize>,
        /// Number the positions from 0 or from 1 in everything the command reads and writes
        /// (default: the scene's, a count sweep from 0 as the sheets show, given input
        /// values from 1); 1 reads the older numbering of a count sweep (the K-th position
        /// is position K).
        #[arg(long, value_parser = numbering)]
        positions_from: Option<Numbering>,
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
        /// Only this position, its number as the sheets show it (a count sweep from 0, given
        /// input values from 1).
        #[arg(long)]
        position: Option<usize>,
        /// Number the positions from 0 or from 1 in everything the command reads and writes
        /// (default: the scene's, a count sweep from 0 as the sheets show, given input
        /// values from 1); 1 reads the older numbering of a count sweep (the K-th position
        /// is position K).
        #[arg(long, value_parser = numbering)]
        positions_from: Option<Numbering>,

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
        /// Language of the table or the sheet (its words and decimal mark): en, uk or ru
        /// (default: the scene's want.lang).
        #[arg(long, value_parser = lang)]
        lang: Option<Lang>,
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
    /// A local web page to grade a plan drawn on paper from its photo: choose a scene, open the photo, click the rectangle's corners and the plan's points, read the verdict (docs/serve.md). Nothing is fetched from outside or sent elsewhere.
    Serve {
        /// Where to listen: 127.0.0.1 (this machine only) by default; an address of the
        /// classroom's network (e.g. 0.0.0.0:8080) lets other machines in.
        #[arg(long, default_value = "127.0.0.1:8080")]
        listen: String,
        /// A scene file to offer beside the bundled examples (repeat for several).
        #[arg(long)]
        scene: Vec<PathBuf>,
        /// The teacher's folder: its subfolders of answers (marks files with their photos,
        /// JSON, SVG, DXF) can be graded from the page into a gradebook.
        #[arg(long)]
        teacher: Option<PathBuf>,
        /// The largest photo accepted, MB.
        #[arg(long, default_value_t = 20)]
        max_upload_mb: usize,
        /// Requests handled at once (students grading at the same time).
        #[arg(long, default_value_t = 8)]
        workers: usize,
    },
}

#[derive(Clone, Copy, ValueEnum)]
pub enum DrawFormat {
    Svg,
    Png,
    Pdf,
    Dxf,
}

impl DrawFormat {
    /// The library's sheet format (an inherent method, not `From`: a
    /// trait impl on the library's public type would make this enum
    /// reachable from outside yet unnameable).
    pub fn sheet(self) -> SheetFormat {
        match self {
            DrawFormat::Svg => SheetFormat::Svg,
            DrawFormat::Png => SheetFormat::Png,
            DrawFormat::Pdf => SheetFormat::Pdf,
            DrawFormat::Dxf => SheetFormat::Dxf,
        }
    }
}

#[derive(Clone, Copy, ValueEnum)]
pub enum CheckFormat {
    Text,
    Json,
}

/// `solve`'s formats: the table, the JSON result, and the streaming ones.
#[derive(Clone, Copy, PartialEq, ValueEnum)]
pub enum SolveFormat {
    Table,
    Json,
    Csv,
    Jsonl,
}

#[derive(Clone, Copy, PartialEq, ValueEnum)]
pub enum Format {
    Table,
    Json,
}

pub fn lang(s: &str) -> Result<Lang, String> {
    Lang::parse(s).ok_or_else(|| format!("unknown language \"{s}\": use en, uk or ru"))
}

pub fn sheet(s: &str) -> Result<SheetSize, String> {
    SheetSize::parse(s).ok_or_else(|| format!("unknown sheet \"{s}\": use A4, A3, A2 or A1"))
}

pub fn numbering(s: &str) -> Result<Numbering, String> {
    s.parse()
        .ok()
        .and_then(Numbering::from_first)
        .ok_or_else(|| format!("positions are numbered from 0 or from 1, not from \"{s}\""))
}

pub fn plan(s: &str) -> Result<PlanKind, String> {
    match s {
        "velocity" => Ok(PlanKind::Velocity),
        "acceleration" => Ok(PlanKind::Acceleration),
        _ => Err(format!("unknown plan \"{s}\": velocity or acceleration")),
    }
}
