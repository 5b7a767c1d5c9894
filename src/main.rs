//! The `mechplan` command: parses the arguments and calls the library's
//! [`Study`] (the front door every command goes through).

mod cli;
mod serve;
mod signals;
mod terminal;

use clap::Parser;
use cli::{CheckFormat, Cli, Command, Format, SolveFormat};
use mechplan::Spool;
use mechplan::{CheckRequest, DrawRequest, Error, Numbering, Results, Study};
use std::path::Path;
use std::process::ExitCode;
use std::sync::Arc;
use terminal::{stdout, wrote};

/// mimalloc: per-thread heaps that take back what another thread frees
/// cheaply (a sweep's positions are finished on the pool and freed where
/// they are written).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// A scene file read, long sweeps drawing a bar on a terminal, its
/// positions numbered as `--positions-from` says (else as the scene does).
fn study(path: &Path, numbering: Option<Numbering>) -> Result<Study, Error> {
    let study = Study::from_path(path)?.watched_by(Arc::new(terminal::Bar::default()));
    if let Some(n) = study.units_note() {
        terminal::note(&n);
    }
    Ok(match numbering {
        Some(n) => study.numbered(n),
        None => study,
    })
}

/// The results in `style`: into the file `output`, or held back and
/// printed when every position is solved.
fn results(study: &Study, style: Results, output: Option<&Path>) -> Result<(), Error> {
    match output {
        Some(path) => study.write_results_to_file(style, path),
        None => {
            let mut spool = Spool::new();
            study.write_results_to_spool(style, &mut spool)?;
            terminal::print_spool(spool)
        }
    }
}

/// mimalloc's option `arena_eager_commit` (`mi_option_e` in its
/// mimalloc.h, v3): 0 commits an arena's memory as it is used, so that
/// a process whose data are limited (`ulimit -d`) is not refused the
/// whole arena it reserves (1 GiB) at its first allocation.
const MI_OPTION_ARENA_EAGER_COMMIT: libmimalloc_sys::mi_option_t = 4;

fn main() -> ExitCode {
    // SAFETY: sets an integer option of the allocator, on the one thread
    // running; mimalloc reads it when it next reserves an arena.
    unsafe { libmimalloc_sys::mi_option_set(MI_OPTION_ARENA_EAGER_COMMIT, 0) };
    signals::handle();
    mechplan::study::files::on_waiting(terminal::note);
    let cli = Cli::parse();
    if let Some(Command::Solve { output: None, .. }) = &cli.command {
        signals::stop_when_stdout_closes();
    }
    terminal::finish(match cli.command {
        Some(c) => command(c),
        // No arguments: the embedded default scene, solved and drawn.
        None => {
            let study = Study::default_scene().watched_by(Arc::new(terminal::Bar::default()));
            results(&study, Results::Table(None), None)
                .and_then(|()| study.draw(&DrawRequest::default()))
                .and_then(|w| wrote(&w))
                .map(|()| 0)
        }
    })
}

/// One command: its exit status, or the error to report.
fn command(c: Command) -> Result<u8, Error> {
    match c {
        Command::Solve {
            scene,
            format,
            output,
            steps,
            lang,
            positions_from,
        } => {
            let style = match (steps, format) {
                (true, _) => Results::Steps(lang),
                (false, SolveFormat::Table) => Results::Table(lang),
                (false, SolveFormat::Json) => Results::Json,
                (false, SolveFormat::Csv) => Results::Csv,
                (false, SolveFormat::Jsonl) => Results::Jsonl,
            };
            results(&study(&scene, positions_from)?, style, output.as_deref())?;
        }
        Command::Draw {
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
            course,
            position,
            positions_from,
        } => {
            let req = DrawRequest {
                dir: output,
                format: format.sheet(),
                dpi,
                sheet,
                lang,
                title_block,
                table,
                centres,
                html,
                course,
                positions: position,
            };
            wrote(&study(&scene, positions_from)?.draw(&req)?)?;
        }
        Command::Check {
            scene,
            answers,
            output,
            format,
            svg,
            dxf,
            photo_overlay,
            delta,
            mu,
            plan,
            position,
            positions_from,
            lang,
        } => {
            let req = CheckRequest {
                json: matches!(format, CheckFormat::Json),
                overlay: svg,
                overlay_dxf: dxf,
                overlay_photo: photo_overlay,
                delta,
                mu,
                plan,
                position,
                positions_from,
                lang,
            };
            if mechplan::study::is_group(&answers, output.is_some()) {
                let out = output.unwrap_or_else(|| "mechplan-check".into());
                let bar = terminal::Bar::shown_from(1);
                let graded = mechplan::check_group(&scene, &answers, &req, &out, &bar)?;
                stdout(&match req.json {
                    true => terminal::pretty(&graded.to_json()),
                    false => graded.to_text(),
                })?;
                return Ok(graded.status());
            }
            let (report, status) = mechplan::check_file(&scene, &answers[0], &req)?;
            stdout(&report)?;
            return Ok(status);
        }
        Command::Frenet {
            output,
            format,
            count,
        } => wrote(&mechplan::frenet(&output, format.sheet(), count)?)?,
        Command::Serve {
            listen,
            scene,
            teacher,
            max_upload_mb,
            workers,
        } => serve::run(serve::Options {
            listen,
            scenes: scene,
            teacher,
            max_upload_mb,
            workers,
        })?,
        study_command => studies(study_command)?,
    }
    Ok(0)
}

/// The studies of a scene: the precision report, the instant centres,
/// the motion-law invariants, the kinematic diagrams (the other commands
/// are `command`'s).
fn studies(c: Command) -> Result<(), Error> {
    match c {
        Command::Precision {
            scene,
            output,
            seeds,
            positions,
            min_time,
        } => {
            let settings = mechplan::PrecisionSettings {
                seeds,
                positions,
                min_time,
                ..Default::default()
            };
            let stem = scene
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| "scene".into());
            let report = study(&scene, None)?.precision(&settings)?;
            match output {
                Some(dir) => wrote(&report.write_into(&dir, &stem)?),
                None => stdout(&report.to_markdown()),
            }
        }
        Command::Centres {
            scene,
            position,
            positions_from,
            format,
        } => {
            let study = study(&scene, positions_from)?;
            let centres = study.centres(position)?;
            stdout(&match format {
                Format::Json => terminal::pretty(&centres.to_json()),
                Format::Table => centres.to_table(),
            })
        }
        Command::Invariants {
            scene,
            output,
            tolerance,
            min_dwell,
            n,
            format,
        } => {
            let study = study(&scene, None)?;
            let inv = study.invariants(output.as_deref(), tolerance, min_dwell, n)?;
            stdout(&match format {
                Format::Json => terminal::pretty(&inv.to_json()),
                Format::Table => inv.to_table(),
            })
        }
        Command::Diagram {
            scene,
            output,
            point,
            n,
            output_dir,
            format,
            lang,
        } => {
            let study = study(&scene, None)?;
            let d = study
                .diagram(output.as_deref(), point.as_deref(), n)?
                .in_lang(lang);
            match output_dir {
                Some(dir) => wrote(&d.write_into(&dir, format.sheet())?),
                None => stdout(&d.to_table()),
            }
        }
        // `command` runs the others itself.
        Command::Solve { .. }
        | Command::Draw { .. }
        | Command::Check { .. }
        | Command::Serve { .. }
        | Command::Frenet { .. } => Ok(()),
    }
}
