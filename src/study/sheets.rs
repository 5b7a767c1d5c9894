//! Sheets into a folder, all or nothing, with the manifest that lets the
//! next run remove the sheets of its own it no longer draws
//! ([`write_sheets`]).

use super::files::{FolderLock, committing, discard, remove_stale, track, write_error};
use crate::error::{Error, Result};
use crate::presentation::drawing::dxf::dxf;
use crate::presentation::drawing::export::{
    BOOK, MANIFEST, MANIFEST_HEAD, manifest_entry, manifest_tail,
};
use crate::presentation::drawing::{Format, Sheet, SheetKind, pdf, pdf_book, png};
use std::collections::HashSet;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Files written, and what the user should be told of the folder.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Written {
    /// Every file written, in order.
    pub files: Vec<PathBuf>,
    /// Notes for the user: sheets of an earlier run removed, files that
    /// look like sheets left alone.
    pub notes: Vec<String>,
}

/// The files an earlier run listed in `dir`'s manifest.
fn listed(dir: &Path) -> Vec<String> {
    let Ok(text) = std::fs::read_to_string(dir.join(MANIFEST)) else {
        return Vec::new();
    };
    let Ok(v) = serde_json::from_str::<serde_json::Value>(&text) else {
        return Vec::new();
    };
    let mut out: Vec<String> = v["sheets"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|s| s["file"].as_str().map(str::to_string))
        .collect();
    if let Some(b) = v["book"].as_str() {
        out.push(b.to_string());
    }
    out.retain(|f| plain_name(f));
    out
}

/// Whether `f` names a file in the folder itself: a manifest or a journal
/// is no licence to move or remove anything elsewhere (a drive letter,
/// `C:x`, names another folder on Windows; mechplan's names have no `:`).
fn plain_name(f: &str) -> bool {
    !f.is_empty() && !f.contains(['/', '\\', ':', '\0']) && f != ".." && f != "."
}

/// Write every sheet into `dir` in `format` (with the PDF book of them
/// all for PDF) and the manifest, all or nothing ([`SheetWriter`]).
pub fn write_sheets(sheets: &[Sheet], dir: &Path, format: Format, dpi: f64) -> Result<Written> {
    let mut w = SheetWriter::new(dir, format, dpi)?;
    for s in sheets {
        w.put(s.clone())?;
    }
    w.finish()
}

/// Sheets written into a folder as they come, all or nothing: each is
/// rendered and written at once into this run's staging folder inside it
/// (`.mechplan-staging-PID`: a run of thousands of sheets holds none of
/// them), and only [`SheetWriter::finish`] writes the PDF book and the
/// manifest and moves everything into place; a failure, or a writer
/// dropped unfinished, removes the staging folder. A run killed before
/// either leaves its staging folder behind: the next run into the folder
/// (holding its lock, so that no staging folder there is a live run's)
/// removes it, or finishes its renames from its journal, and says so. Nothing touches
/// the folder before the first sheet (a refused scene creates nothing).
/// Then the sheets an earlier run listed in the manifest and this one did
/// not write are removed, each named in a note.
pub struct SheetWriter {
    dir: PathBuf,
    format: Format,
    dpi: f64,
    before: Vec<String>,
    /// This run's staging folder, once made, and the names of the files
    /// in it, in order (each for the file of that name in the folder).
    staging: Option<PathBuf>,
    staged: Vec<String>,
    /// Notes of the staging (an interrupted run's files removed).
    notes: Vec<String>,
    /// The manifest in the staging folder, each sheet's entry written as
    /// the sheet comes (a run of thousands of sheets holds none of them),
    /// and how many.
    manifest: Option<BufWriter<File>>,
    listed: usize,
    /// The sheets written, with their SVG, for a PDF book only.
    sheets: Vec<Sheet>,
    /// Some sheets of a set (`draw --position`): the folder's others are
    /// kept, and so are their entries in the manifest.
    partial: bool,
    /// The folder locked for this run (from the start when it exists,
    /// else from its making at the first sheet) until the writer is
    /// dropped; dropped after the staging folder is removed.
    lock: Option<FolderLock>,
}

impl SheetWriter {
    /// A writer into `dir` (made at the first sheet if missing), reading
    /// the manifest an earlier run left there.
    pub fn new(dir: &Path, format: Format, dpi: f64) -> Result<SheetWriter> {
        // Another run writing into the folder is waited for before its
        // manifest is read.
        let lock = match dir.is_dir() {
            true => Some(FolderLock::acquire(dir)?),
            false => None,
        };
        Ok(SheetWriter {
            dir: dir.to_path_buf(),
            format,
            dpi,
            before: listed(dir),
            lock,
            staging: None,
            staged: Vec::new(),
            notes: Vec::new(),
            manifest: None,
            listed: 0,
            sheets: Vec::new(),
            partial: false,
        })
    }

    /// A writer of some sheets of a set: the folder's other sheets are
    /// left as they are and stay in the manifest.
    pub fn partial(mut self) -> SheetWriter {
        self.partial = true;
        self
    }

    /// Render sheet `s`, write it to its temporary and its entry to the
    /// manifest's.
    pub fn put(&mut self, mut s: Sheet) -> Result<()> {
        let (ext, bytes) = match self.format {
            Format::Svg => ("svg", std::mem::take(&mut s.svg).into_bytes()),
            Format::Png => ("png", png(&s.svg, self.dpi)?),
            Format::Pdf => ("pdf", pdf(&s.svg)?),
            Format::Dxf => ("dxf", dxf(&s.svg)?.into_bytes()),
        };
        let file = format!("{}.{ext}", s.name);
        self.stage(&file, &bytes)?;
        self.list(&s, &file)?;
        if self.format == Format::Pdf {
            self.sheets.push(s);
        }
        Ok(())
    }

    /// Sheet `s`'s entry, in `file`, written to the manifest in the
    /// staging folder (begun at the first).
    fn list(&mut self, s: &Sheet, file: &str) -> Result<()> {
        let m = self.dir.join(MANIFEST);
        let fail = |e| write_error(&m.display().to_string(), e);
        let w = match (&mut self.manifest, &self.staging) {
            (Some(w), _) => w,
            (None, Some(staging)) => {
                let mut w = BufWriter::new(File::create(staging.join(MANIFEST)).map_err(fail)?);
                w.write_all(MANIFEST_HEAD.as_bytes()).map_err(fail)?;
                self.manifest.insert(w)
            }
            (None, None) => {
                return Err(Error::Internal("a sheet listed before it is staged".into()));
            }
        };
        w.write_all(manifest_entry(s, file, self.listed).as_bytes())
            .map_err(fail)?;
        self.listed += 1;
        Ok(())
    }

    /// Write `bytes` for the folder's file `name` into the staging folder
    /// (made, with the output folder, at the first file).
    fn stage(&mut self, name: &str, bytes: &[u8]) -> Result<()> {
        let staging = match &self.staging {
            Some(s) => s.clone(),
            None => {
                let dir = &self.dir;
                std::fs::create_dir_all(dir)
                    .map_err(|e| write_error(&dir.display().to_string(), e))?;
                if self.lock.is_none() {
                    self.lock = Some(FolderLock::acquire(dir)?);
                    self.before = listed(dir);
                }
                let (note, finished) = remove_interrupted(dir);
                self.notes.extend(note);
                if finished {
                    // The folder as the interrupted run's manifest lists it.
                    self.before = listed(dir);
                }
                let stale = remove_stale(dir);
                if stale > 0 {
                    self.notes.push(format!(
                        "removed {stale} temporary file(s) of interrupted run(s) in {}",
                        dir.display()
                    ));
                }
                let s = dir.join(format!("{STAGING}{}", std::process::id()));
                track(&s);
                std::fs::create_dir_all(&s)
                    .map_err(|e| write_error(&s.display().to_string(), e))?;
                self.staging = Some(s.clone());
                s
            }
        };
        let path = self.dir.join(name);
        std::fs::write(staging.join(name), bytes)
            .map_err(|e| write_error(&path.display().to_string(), e))?;
        self.staged.push(name.to_string());
        Ok(())
    }

    /// The manifest's end written after its entries (the whole of it when
    /// no sheet came), merged into the folder's for some sheets of a set.
    fn end_manifest(&mut self) -> Result<()> {
        let m = self.dir.join(MANIFEST);
        let fail = |e| write_error(&m.display().to_string(), e);
        let tail = manifest_tail(self.listed, self.format);
        let (Some(mut w), Some(staging)) = (self.manifest.take(), self.staging.clone()) else {
            let mut text = format!("{MANIFEST_HEAD}{tail}");
            if self.partial {
                text = merged(&m, &text);
            }
            return self.stage(MANIFEST, text.as_bytes());
        };
        w.write_all(tail.as_bytes())
            .and_then(|_| w.flush())
            .map_err(fail)?;
        drop(w);
        if self.partial {
            let tmp = staging.join(MANIFEST);
            let text = std::fs::read_to_string(&tmp).map_err(fail)?;
            std::fs::write(&tmp, merged(&m, &text)).map_err(fail)?;
        }
        self.staged.push(MANIFEST.to_string());
        Ok(())
    }

    /// The book and the manifest, everything renamed into place, and the
    /// notes on what else the folder holds.
    pub fn finish(mut self) -> Result<Written> {
        if self.format == Format::Pdf && self.listed > 1 && !self.partial {
            let bytes = pdf_book(&self.sheets)?;
            self.stage(BOOK, &bytes)?;
        }
        self.sheets = Vec::new();
        self.end_manifest()?;
        // Into place, when no place is taken by something that is not a
        // file (a folder of that name): then nothing is moved.
        let staged = std::mem::take(&mut self.staged);
        let written: Vec<PathBuf> = staged.iter().map(|n| self.dir.join(n)).collect();
        if let Some(p) = written
            .iter()
            .find(|p| std::fs::metadata(p).is_ok_and(|m| m.is_dir()))
        {
            let e =
                std::io::Error::new(std::io::ErrorKind::IsADirectory, "is a folder, not a file");
            return Err(write_error(&p.display().to_string(), e));
        }
        // The order (a signal meanwhile waits for it, see `committing`):
        // every file of the run is complete in the staging folder before
        // the first rename; the sheets (and the book) are renamed into
        // place, then the manifest last, then the sheets of the earlier
        // manifest this run does not draw are removed. A run killed
        // outright (SIGKILL) during the renames leaves the old manifest
        // with new sheets beside it until the next run into the folder,
        // which finishes the renames from the journal before anything else.
        let dir = &self.dir;
        let is_written: HashSet<&PathBuf> = written.iter().collect();
        // The earlier manifest's sheets this run does not draw (none for
        // some sheets of a set: the others stay).
        let outdated: Vec<String> = match self.partial {
            true => Vec::new(),
            false => std::mem::take(&mut self.before)
                .into_iter()
                .filter(|old| !is_written.contains(&dir.join(old)))
                .collect(),
        };
        let _commit = committing();
        // The journal first: a run killed outright from here on is
        // finished by the next run into the folder ([`remove_interrupted`]).
        if let Some(staging) = &self.staging {
            write_journal(staging, &staged, &outdated)?;
            for (name, path) in staged.iter().zip(&written) {
                std::fs::rename(staging.join(name), path)
                    .map_err(|e| write_error(&path.display().to_string(), e))?;
            }
        }
        let mut notes = std::mem::take(&mut self.notes);
        if self.partial {
            return Ok(Written {
                files: written,
                notes,
            });
        }
        let removed: Vec<String> = outdated
            .into_iter()
            .map(|old| dir.join(old))
            .filter(|p| p.is_file() && std::fs::remove_file(p).is_ok())
            .map(|p| file_name(&p))
            .collect();
        if !removed.is_empty() {
            notes.push(format!(
                "removed {} sheet file(s) of an earlier run in {} that this run does not draw: {}",
                removed.len(),
                dir.display(),
                abbreviate(&removed)
            ));
        }
        // Sheets by the names this program gives, neither written now nor
        // listed by a manifest (an older version's): said, left alone.
        if let Ok(entries) = std::fs::read_dir(dir) {
            let mut stale: Vec<String> = entries
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.is_file() && !is_written.contains(p) && looks_like_a_sheet(p))
                .map(|p| file_name(&p))
                .collect();
            stale.sort();
            if !stale.is_empty() {
                notes.push(format!(
                    "{} sheet file(s) in {} are not from this run (no manifest lists them; left as they are): {}",
                    stale.len(),
                    dir.display(),
                    abbreviate(&stale)
                ));
            }
        }
        Ok(Written {
            files: written,
            notes,
        })
    }
}

impl Drop for SheetWriter {
    /// A writer dropped before it finished (a failure): its staging
    /// folder goes; finished, it is empty and goes too.
    fn drop(&mut self) {
        self.manifest = None;
        if let Some(s) = &self.staging {
            discard(s);
        }
    }
}

/// The name of a run's staging folder, before its process id.
const STAGING: &str = ".mechplan-staging-";

/// The journal in a staging folder, written before the first rename: the
/// files to move into place, in order, and the earlier sheets to remove.
const JOURNAL: &str = ".commit";

/// A path's file name as text.
fn file_name(p: &Path) -> String {
    p.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Write the journal of a run's renames into its staging folder (whole or
/// not at all: a temporary renamed).
fn write_journal(staging: &Path, moves: &[String], remove: &[String]) -> Result<()> {
    let text = serde_json::json!({ "moves": moves, "remove": remove }).to_string();
    let (tmp, path) = (staging.join(".commit.tmp"), staging.join(JOURNAL));
    std::fs::write(&tmp, text)
        .and_then(|_| std::fs::rename(&tmp, &path))
        .map_err(|e| write_error(&path.display().to_string(), e))
}

/// Finish the renames of an interrupted run from its journal: every file
/// still in `staging` moved into `dir` in the journal's order (the
/// manifest last), the earlier sheets it lists removed. The number of
/// files moved; `None` when there is no readable journal (the run was
/// killed before its renames: nothing of it is in place).
fn finish_journal(dir: &Path, staging: &Path) -> Option<usize> {
    let text = std::fs::read_to_string(staging.join(JOURNAL)).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    let names = |key: &str| -> Vec<String> {
        v[key]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|x| x.as_str())
            .filter(|f| plain_name(f))
            .map(str::to_string)
            .collect()
    };
    let mut moved = 0;
    for name in names("moves") {
        let from = staging.join(&name);
        if from.is_file() && std::fs::rename(&from, dir.join(&name)).is_ok() {
            moved += 1;
        }
    }
    for name in names("remove") {
        let p = dir.join(&name);
        if p.is_file() {
            let _ = std::fs::remove_file(p);
        }
    }
    Some(moved)
}

/// Deal with the staging folders in `dir` of earlier runs: one killed
/// during its renames (a journal) is finished, one killed before them
/// removed. Called with the folder's lock held, so that no staging folder
/// in it belongs to a live run, whatever its process id (a container's
/// runs are often all process 1, and ids are reused). A note saying so,
/// if any, and whether a run was finished (the folder's manifest is then
/// that run's).
fn remove_interrupted(dir: &Path) -> (Option<String>, bool) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return (None, false);
    };
    let (mut files, mut runs, mut finished, mut moved) = (0, 0, 0, 0);
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(pid) = name.strip_prefix(STAGING) else {
            continue;
        };
        if !pid.bytes().all(|b| b.is_ascii_digit()) || !e.path().is_dir() {
            continue;
        }
        if let Some(n) = finish_journal(dir, &e.path()) {
            finished += 1;
            moved += n;
        } else {
            files += std::fs::read_dir(e.path()).map_or(0, |d| d.count());
            runs += 1;
        }
        let _ = std::fs::remove_dir_all(e.path());
    }
    let mut notes = Vec::new();
    if finished > 0 {
        notes.push(format!(
            "finished the renames of {finished} run(s) killed while putting their sheets into place in {} ({moved} file(s) moved)",
            dir.display()
        ));
    }
    if runs > 0 {
        notes.push(format!(
            "removed {files} unfinished file(s) of {runs} interrupted run(s) in {}",
            dir.display()
        ));
    }
    ((!notes.is_empty()).then(|| notes.join("; ")), finished > 0)
}

/// The manifest `text` of some sheets merged into the one at `path`: its
/// entries for other files kept, in their order, those rewritten now
/// replaced, new ones added.
fn merged(path: &Path, text: &str) -> String {
    let Ok(new) = serde_json::from_str::<serde_json::Value>(text) else {
        return text.to_string();
    };
    let Some(mut old) = std::fs::read_to_string(path)
        .ok()
        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
        .filter(|v| v["sheets"].is_array())
    else {
        return text.to_string();
    };
    let fresh = new["sheets"].as_array().cloned().unwrap_or_default();
    let list = old["sheets"].as_array_mut().expect("an array");
    for s in fresh {
        match list.iter_mut().find(|o| o["file"] == s["file"]) {
            Some(o) => *o = s,
            None => list.push(s),
        }
    }
    serde_json::to_string_pretty(&old).unwrap_or_default() + "\n"
}

/// The first names of a list and how many more.
fn abbreviate(names: &[String]) -> String {
    if names.len() <= 6 {
        names.join(", ")
    } else {
        format!("{} and {} more", names[..5].join(", "), names.len() - 5)
    }
}

/// Whether a file is named as this program names its sheets.
fn looks_like_a_sheet(p: &Path) -> bool {
    let (Some(stem), Some(ext)) = (
        p.file_stem().and_then(|s| s.to_str()),
        p.extension().and_then(|s| s.to_str()),
    ) else {
        return false;
    };
    if !matches!(ext, "svg" | "png" | "pdf" | "dxf") {
        return false;
    }
    // A sheet by its kind, or the document of them all.
    SheetKind::parse(stem).is_some() || stem == "sheets"
}

#[cfg(test)]
mod tests {
    use super::plain_name;

    #[test]
    fn only_names_in_the_folder_itself_are_plain() {
        for good in ["sheet-01.svg", "sheets.json", "a b.pdf", "..x"] {
            assert!(plain_name(good), "{good}");
        }
        for bad in [
            "", ".", "..", "../x", "a/b", "a\\b", "C:x", "C:\\x", "/x", "x\0y",
        ] {
            assert!(!plain_name(bad), "{bad:?}");
        }
    }
}
