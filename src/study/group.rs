//! `check SCENE DIR` (or `check SCENE A.json B.svg …`) as one call: a
//! group of answers graded against one solution of the scene. Every answer
//! is read and checked on its own (in parallel, told to a [`Progress`]
//! watcher); one that cannot be read or refuses becomes an `unreadable`
//! row with its message while the others are graded. Into the output
//! folder go the gradebook (`gradebook.csv`), the summary page
//! (`summary.html`) and every kinematic answer's overlay
//! (`overlays/STEM.svg`, and a DXF answer's marked copy `STEM.dxf`), all
//! written atomically and together
//! (docs/check.md, "A group at once").

use super::check_file::{is_drawing, read_answer};
use super::files::{write_error, write_files_atomically};
use super::{CheckRequest, Checked, Solution, Study};
use crate::error::{Error, Result, in_file};
use crate::presentation::gradebook::{self, GradeRow, Outcome, Totals};
use crate::progress::Progress;
use rayon::prelude::*;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The gradebook's file in the output folder.
pub const GRADEBOOK: &str = "gradebook.csv";
/// The summary page's file in the output folder.
pub const SUMMARY: &str = "summary.html";
/// The overlays' folder in the output folder.
pub const OVERLAYS: &str = "overlays";

/// A group graded: a row per answer, in the group's order (a folder's
/// answers sorted by name, files as given), each answer's check (or why
/// it could not be checked), and the files written.
#[derive(Debug)]
pub struct Graded {
    /// The gradebook's rows.
    pub rows: Vec<GradeRow>,
    /// Each answer's check, or the error that made it unreadable.
    pub checked: Vec<std::result::Result<Checked, Error>>,
    /// The gradebook written (`OUT/gradebook.csv`).
    pub gradebook: PathBuf,
    /// The summary page written (`OUT/summary.html`).
    pub summary: PathBuf,
    /// The overlays written (`OUT/overlays/STEM.svg`), one per kinematic
    /// answer checked, and each DXF answer's marked copy (`STEM.dxf`).
    pub overlays: Vec<PathBuf>,
}

impl Graded {
    /// How many answers have each grade.
    pub fn totals(&self) -> Totals {
        Totals::of(&self.rows)
    }

    /// The exit status of `mechplan check` on the group: 2 an answer
    /// unreadable, else 1 one wrong, else 4 one that cannot be judged,
    /// else 0.
    pub fn status(&self) -> u8 {
        self.totals().status()
    }

    /// The totals and the files written, as the command prints them.
    pub fn to_text(&self) -> String {
        let mut t = format!(
            "{}\nwrote {}\nwrote {}\n",
            self.totals().to_text(),
            self.gradebook.display(),
            self.summary.display()
        );
        if let Some(dir) = self.overlays.first().and_then(|o| o.parent()) {
            let copies = self
                .overlays
                .iter()
                .filter(|o| o.extension().is_some_and(|e| e == "dxf"))
                .count();
            let svgs = self.overlays.len() - copies;
            let marked = match copies {
                0 => String::new(),
                1 => " and 1 marked copy of a DXF answer".into(),
                n => format!(" and {n} marked copies of DXF answers"),
            };
            t.push_str(&format!(
                "wrote {svgs} overla{}{marked} into {}\n",
                if svgs == 1 { "y" } else { "ys" },
                dir.display()
            ));
        }
        t
    }

    /// Every answer's report as one JSON array (`check --format json` of a
    /// group): `{ "file", "grade", "report" }` for an answer checked (the
    /// report as `check --format json` writes one), `{ "file", "grade":
    /// "unreadable", "message" }` for the others.
    pub fn to_json(&self) -> serde_json::Value {
        let each = self.rows.iter().zip(&self.checked).map(|(row, c)| {
            let mut o = serde_json::json!({ "file": row.file, "grade": row.grade.as_str() });
            match c {
                Ok(c) => o["report"] = c.to_json(),
                Err(e) => o["message"] = e.to_string().into(),
            }
            o
        });
        serde_json::Value::Array(each.collect())
    }
}

/// Whether `check`'s answers are a group: several, or a folder, or one
/// file with an output folder asked for (`output`); else one answer,
/// checked as [`check_file`](fn@super::check_file) does.
pub fn is_group(answers: &[PathBuf], output: bool) -> bool {
    answers.len() != 1 || output || answers[0].is_dir()
}

/// Check the group of `answers` (folders: their `*.json`, `*.svg` and `*.dxf`
/// files, not recursively, sorted by name; files: as they are) against
/// `scene`, solved once, with the overrides of `req` for every answer;
/// write the gradebook, the summary page and the overlays into `out`.
/// Each answer checked is told to `progress`. A scene that cannot be
/// read or solved, a bad option, a folder that cannot be listed or holds
/// no answer are errors (nothing written); so is an output that cannot
/// be written. An answer that cannot be read or refuses is a row.
pub fn check_group(
    scene: &Path,
    answers: &[PathBuf],
    req: &CheckRequest,
    out: &Path,
    progress: &dyn Progress,
) -> Result<Graded> {
    let files = answer_files(answers)?;
    let study = super::check_file::study_for(scene, req)?;
    validate(&study, req)?;
    let solution = study.solve()?;
    let title = scene_name(&study, scene);
    check_files(&solution, &files, req, out, &title, progress)
}

/// The options that apply to every answer, refused once for the group:
/// the single answer's overlay, a pencil precision that is no number of
/// mm, a position the scene has not.
fn validate(study: &Study, req: &CheckRequest) -> Result<()> {
    for (set, option) in [
        (req.overlay.is_some(), "svg"),
        (req.overlay_dxf.is_some(), "dxf"),
    ] {
        if set {
            return Err(Error::scene(
                option,
                format!(
                    "a group writes every answer's overlay into OUT/overlays (--output OUT), a DXF answer's marked copy beside it: --{option} is for a single answer"
                ),
            ));
        }
    }
    if let Some(d) = req.delta
        && !(d.is_finite() && d > 0.0)
    {
        return Err(Error::scene(
            "delta",
            "the pencil precision must be a positive number of mm",
        ));
    }
    if let Some(p) = req.position {
        study.position_index("position", p)?;
    }
    Ok(())
}

/// The scene as the summary names it: its file, and its title if it has
/// one.
fn scene_name(study: &Study, scene: &Path) -> String {
    let file = scene
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_else(|| scene.display().to_string());
    match study.analysis.mech.scene.title.trim() {
        "" => file,
        t => format!("{t} ({file})"),
    }
}

/// The answers of the group: (its name in the gradebook, its path).
fn answer_files(answers: &[PathBuf]) -> Result<Vec<(String, PathBuf)>> {
    let mut out = Vec::new();
    for a in answers {
        if !a.is_dir() {
            out.push((a.display().to_string(), a.clone()));
            continue;
        }
        let io = |source| Error::Io {
            path: a.display().to_string(),
            source,
        };
        let mut found = Vec::new();
        for e in std::fs::read_dir(a).map_err(io)? {
            let p = e.map_err(io)?.path();
            let answer = p.extension().is_some_and(|x| {
                ["json", "svg", "dxf"]
                    .iter()
                    .any(|e| x.eq_ignore_ascii_case(e))
            });
            if answer && p.is_file() {
                let name = p
                    .file_name()
                    .map(|f| f.to_string_lossy().into_owned())
                    .unwrap_or_default();
                found.push((name, p));
            }
        }
        found.sort();
        out.extend(found);
    }
    if out.is_empty() {
        let where_ = answers
            .iter()
            .map(|a| a.display().to_string())
            .collect::<Vec<_>>()
            .join(", ");
        return Err(Error::scene(
            "",
            format!("no answers to check: {where_} holds no *.json, *.svg or *.dxf file"),
        ));
    }
    Ok(out)
}

/// Check each of `files` against `sol`, then write the group's files.
fn check_files(
    sol: &Solution,
    files: &[(String, PathBuf)],
    req: &CheckRequest,
    out: &Path,
    title: &str,
    progress: &dyn Progress,
) -> Result<Graded> {
    progress.start(files.len(), "answers");
    let checked: Vec<Result<Checked>> = files
        .par_iter()
        .map(|(_, path)| {
            let c = check_one(sol, path, req);
            progress.advance(1);
            c
        })
        .collect();
    progress.finish();
    let rows: Vec<GradeRow> = files
        .iter()
        .zip(&checked)
        .map(|((name, _), c)| match c {
            Ok(Checked::Kinematic(k)) => {
                let mut row = gradebook::row_of(name, Outcome::Kinematic(&k.report));
                // What the drawing's reading left out, after the report's
                // own note.
                if !k.notes.is_empty() {
                    let notes = k.notes.join("; ");
                    row.message = Some(match row.message.take() {
                        Some(m) => format!("{m}; {notes}"),
                        None => notes,
                    });
                }
                row
            }
            Ok(Checked::Force(r)) => gradebook::row_of(name, Outcome::Force(r)),
            Err(e) => gradebook::row_of(name, Outcome::Unreadable(&e.to_string())),
        })
        .collect();
    // The overlays, each named after its answer's file (a second answer
    // of the same stem gets "-2", …).
    let mut stems = BTreeSet::new();
    let mut overlays: Vec<Option<(String, String)>> = Vec::new();
    // A DXF answer's marked copy beside its overlay (STEM.dxf).
    let mut copies: Vec<(String, Vec<u8>)> = Vec::new();
    for ((_, path), c) in files.iter().zip(&checked) {
        let Some((svg, c)) = c.as_ref().ok().and_then(|c| c.overlay().map(|s| (s, c))) else {
            overlays.push(None);
            continue;
        };
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "answer".into());
        let mut name = stem.clone();
        let mut k = 1;
        while !stems.insert(name.clone()) {
            k += 1;
            name = format!("{stem}-{k}");
        }
        if is_drawing(path)
            && let (_, Some(bytes)) = read_answer(path)?
            && let Some(copy) = c.overlay_dxf(&bytes)
        {
            let copy = copy.map_err(in_file(&path.display().to_string()))?;
            copies.push((format!("{OVERLAYS}/{name}.dxf"), copy));
        }
        overlays.push(Some((format!("{OVERLAYS}/{name}.svg"), svg)));
    }
    let linked: Vec<(GradeRow, Option<String>)> = rows
        .iter()
        .cloned()
        .zip(
            overlays
                .iter()
                .map(|o| o.as_ref().map(|(rel, _)| rel.clone())),
        )
        .collect();
    let csv = gradebook::gradebook_csv(&rows);
    let html = gradebook::summary_html(title, &linked);
    let mut writes: Vec<(PathBuf, &[u8])> = vec![
        (out.join(GRADEBOOK), csv.as_bytes()),
        (out.join(SUMMARY), html.as_bytes()),
    ];
    for (rel, svg) in overlays.iter().flatten() {
        writes.push((out.join(rel), svg.as_bytes()));
    }
    for (rel, copy) in &copies {
        writes.push((out.join(rel), copy));
    }
    let dir = if stems.is_empty() {
        out.to_path_buf()
    } else {
        out.join(OVERLAYS)
    };
    std::fs::create_dir_all(&dir).map_err(|e| write_error(&dir.display().to_string(), e))?;
    write_files_atomically(&writes)?;
    Ok(Graded {
        rows,
        checked,
        gradebook: out.join(GRADEBOOK),
        summary: out.join(SUMMARY),
        overlays: writes.into_iter().skip(2).map(|(p, _)| p).collect(),
    })
}

/// One answer's file read and checked against `sol`.
fn check_one(sol: &Solution, path: &Path, req: &CheckRequest) -> Result<Checked> {
    let svg = is_drawing(path);
    let (text, _) = read_answer(path)?;
    sol.check_answer(&text, &path.display().to_string(), svg, req)
}
