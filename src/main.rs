//! The `mechplan` command: parses arguments and calls the library.

use clap::{Parser, Subcommand, ValueEnum};
use mechplan::construction::text::Lang;
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
    let result = match cli.command {
        None => run(
            mechplan::DEFAULT_SCENE,
            "the embedded default scene",
            Options {
                format: Format::Table,
                output: None,
                steps: false,
                lang: None,
            },
        ),
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
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("mechplan: {}", e.to_string().replace('\n', "\nmechplan: "));
            ExitCode::from(2)
        }
    }
}

fn run(text: &str, name: &str, opt: Options) -> Result<(), Error> {
    let prefix = |e: Error| match e {
        Error::Scene(mut v) => {
            for i in &mut v {
                i.message = format!("{} (in {name})", i.message);
            }
            Error::Scene(v)
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
    let solved = analysis.run()?;
    let text = if opt.steps {
        report::to_steps(&analysis, &solved, lang)
    } else {
        match opt.format {
            Format::Table => report::to_table(&analysis, &solved),
            Format::Json => {
                serde_json::to_string_pretty(&report::to_json(&analysis, &solved))
                    .expect("JSON of finite numbers")
                    + "\n"
            }
        }
    };
    let output = opt.output.as_deref();
    match output {
        None => {
            let _ = std::io::stdout().write_all(text.as_bytes());
            Ok(())
        }
        Some(path) => write_atomically(path, text.as_bytes()),
    }
}

/// Write to a temporary file beside `path`, then rename: never half a file.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let io = |source| Error::Io {
        path: path.display().to_string(),
        source,
    };
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        path.file_name()
            .map(|f| f.to_string_lossy())
            .unwrap_or_default(),
        std::process::id()
    ));
    std::fs::write(&tmp, bytes).map_err(io)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}
