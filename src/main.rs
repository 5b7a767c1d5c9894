//! The `mechplan` command: parses the arguments and calls the library's
//! [`Study`] (the front door every command goes through).

mod cli;

use clap::Parser;
use cli::{CheckFormat, Cli, Command, Format, SolveFormat};
use mechplan::check::answer::Reading;
use mechplan::drawing;
use mechplan::output::{stdout, wrote};
use mechplan::study::{Diagram, Precision};
use mechplan::{DrawRequest, Error, Results, Study};
use std::process::ExitCode;

fn main() -> ExitCode {
    finish(match Cli::parse().command {
        Some(c) => command(c),
        // No arguments: the embedded default scene, solved and drawn.
        None => {
            let study = Study::default_scene();
            study
                .write_results(Results::Table, None)
                .and_then(|()| study.draw(&DrawRequest::default()))
                .and_then(|w| stdout(&wrote(&w)))
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
        } => {
            let style = match (steps, format) {
                (true, _) => Results::Steps(lang),
                (false, SolveFormat::Table) => Results::Table,
                (false, SolveFormat::Json) => Results::Json,
                (false, SolveFormat::Csv) => Results::Csv,
                (false, SolveFormat::Jsonl) => Results::Jsonl,
            };
            Study::from_path(&scene)?.write_results(style, output.as_deref())?;
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
        } => {
            let req = DrawRequest {
                dir: output,
                format: format.into(),
                dpi,
                sheet,
                lang,
                title_block,
                table,
                centres,
                html,
                course,
            };
            stdout(&wrote(&Study::from_path(&scene)?.draw(&req)?))?;
        }
        Command::Check {
            scene,
            answer,
            format,
            svg,
            delta,
            mu,
            plan,
            position,
        } => {
            if let Some(status) =
                check_forces(&scene, &answer, (format, &svg, delta, position), (mu, plan))?
            {
                return Ok(status);
            }
            let r = Reading {
                mu,
                plan,
                delta,
                position,
            };
            let ans = mechplan::check::answer::read(&answer, &r)?;
            let study = Study::from_path(&scene)?;
            match position {
                Some(p) => study.position_in_range("position", p)?,
                None => study
                    .position_in_range("/position", ans.position)
                    .map_err(mechplan::study::in_file(&answer.display().to_string()))?,
            }
            let report = study.check(&ans)?;
            if let Some(out) = &svg {
                let overlay = mechplan::check::overlay(study.analysis(), &ans, &report);
                mechplan::write_atomically(out, overlay.as_bytes())?;
            }
            stdout(&match format {
                CheckFormat::Text => mechplan::check::to_text(&report),
                CheckFormat::Json => {
                    let json = mechplan::check::to_json(&report);
                    serde_json::to_string_pretty(&json).expect("finite numbers") + "\n"
                }
            })?;
            return Ok(report.status());
        }
        Command::Precision {
            scene,
            output,
            seeds,
            positions,
            min_time,
        } => {
            let settings = mechplan::precision::Settings {
                seeds,
                positions,
                min_time,
                ..Default::default()
            };
            let stem = scene
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| "scene".into());
            let dir = output.as_deref().map(|d| (d, stem.as_str()));
            match Study::from_path(&scene)?.precision(&settings, dir)? {
                Precision::Table(t) => stdout(&t)?,
                Precision::Written(w) => stdout(&wrote(&w))?,
            }
        }
        Command::Centres {
            scene,
            position,
            format,
        } => stdout(&Study::from_path(&scene)?.centres(position, format == Format::Json)?)?,
        Command::Invariants {
            scene,
            output,
            tolerance,
            min_dwell,
            n,
            format,
        } => {
            let study = Study::from_path(&scene)?;
            let json = format == Format::Json;
            stdout(&study.invariants(output.as_deref(), tolerance, min_dwell, n, json)?)?;
        }
        Command::Diagram {
            scene,
            output,
            point,
            n,
            output_dir,
            format,
        } => {
            let dir = output_dir.as_deref().map(|d| (d, format.into()));
            let study = Study::from_path(&scene)?;
            match study.diagram(output.as_deref(), point.as_deref(), n, dir)? {
                Diagram::Table(t) => stdout(&t)?,
                Diagram::Written(w) => stdout(&wrote(&w))?,
            }
        }
        Command::Frenet {
            output,
            format,
            count,
        } => stdout(&wrote(&drawing::frenet::write(
            &output,
            format.into(),
            count,
        )?))?,
    }
    Ok(0)
}

/// `check` of a force plan (a JSON answer whose `plan` is `"force"`, or
/// an SVG drawing that states μ_F): its status, or `None` for a
/// kinematic answer (read by the caller).
fn check_forces(
    scene: &std::path::Path,
    answer: &std::path::Path,
    (format, svg, delta, position): (
        CheckFormat,
        &Option<std::path::PathBuf>,
        Option<f64>,
        Option<usize>,
    ),
    (mu, plan): (Option<f64>, Option<mechplan::construction::PlanKind>),
) -> Result<Option<u8>, Error> {
    use mechplan::check::forces;
    let name = answer.display().to_string();
    let drawn = answer
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let too_large = std::fs::metadata(answer)
        .is_ok_and(|md| mechplan::check::answer::check_size(md.len()).is_err());
    if too_large {
        // The kinematic reader refuses it with the limit.
        return Ok(None);
    }
    let Ok(text) = mechplan::study::read(answer) else {
        // Unreadable: the kinematic reader reports it.
        return Ok(None);
    };
    // A force plan: JSON whose plan is "force", or a drawing stating μ_F.
    let mut ans = if drawn {
        if !forces::is_force_svg(&text) {
            return Ok(None);
        }
        forces::from_svg(&text, mu, delta.unwrap_or(0.5), position.unwrap_or(1))
    } else {
        if !forces::is_force_answer(&text) {
            return Ok(None);
        }
        forces::from_json(&text)
    }
    .map_err(mechplan::study::in_file(&name))?;
    if let Some(d) = delta {
        if !(d.is_finite() && d > 0.0) {
            return Err(Error::scene(
                "delta",
                "the pencil precision must be a positive number of mm",
            ));
        }
        ans.delta = d;
    }
    if plan.is_some() {
        return Err(Error::scene(
            "plan",
            "the answer is a force plan (\"plan\": \"force\"): --plan names a plan of velocities or accelerations",
        ));
    }
    if let Some(m) = mu {
        if !(m.is_finite() && (1e-6..=1e9).contains(&m)) {
            return Err(Error::scene(
                "mu",
                "μ_F must be a number of N/mm between 1e-6 and 1e9",
            ));
        }
        ans.mu = m;
    }
    if svg.is_some() {
        return Err(Error::scene(
            "svg",
            "the overlay (--svg) is drawn for plans of velocities and accelerations only",
        ));
    }
    let study = Study::from_path(scene)?;
    match position {
        Some(p) => {
            study.position_in_range("position", p)?;
            ans.position = p;
        }
        None => study
            .position_in_range("/position", ans.position)
            .map_err(mechplan::study::in_file(&name))?,
    }
    let report = study.check_forces(&ans)?;
    stdout(&match format {
        CheckFormat::Text => forces::to_text(&report),
        CheckFormat::Json => {
            serde_json::to_string_pretty(&forces::to_json(&report)).expect("finite numbers") + "\n"
        }
    })?;
    Ok(Some(report.status() as u8))
}

/// The exit status: the command's own (0 success; `check`: 1 an item
/// wrong, 4 an item that cannot be judged), 2 bad input or a mechanism
/// that cannot be solved, 3 a failed write, 5 an internal error.
fn finish(result: Result<u8, Error>) -> ExitCode {
    let mut e = match result {
        Ok(status) => return ExitCode::from(status),
        Err(e) => e,
    };
    // The library names its parameters; here they are options.
    if let Some(issues) = e.issues_mut() {
        for i in issues {
            let options = [
                "output",
                "point",
                "sheet",
                "position",
                "tolerance",
                "dpi",
                "min-dwell",
                "n",
                "min-time",
                "count",
                "delta",
                "mu",
                "plan",
                "svg",
            ];
            if options.contains(&i.pointer.as_str()) {
                let dash = if i.pointer == "n" { "-" } else { "--" };
                i.pointer = format!("{dash}{}", i.pointer);
            }
        }
    }
    mechplan::output::error(&e.to_string());
    ExitCode::from(match e {
        Error::Write { .. } => 3,
        Error::Internal(_) => 5,
        _ => 2,
    })
}
