//! Sheets into a folder, all or nothing, with the manifest that lets the
//! next run remove the sheets of its own it no longer draws
//! ([`write_sheets`]).

use super::files::{write_error, write_files_atomically};
use crate::error::Result;
use crate::presentation::drawing::export::{BOOK, MANIFEST, manifest};
use crate::presentation::drawing::{Format, Sheet, pdf, pdf_book, png};
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
    // Only plain file names in the folder itself: a manifest is no
    // licence to remove anything elsewhere.
    out.retain(|f| !f.is_empty() && !f.contains(['/', '\\']) && f != ".." && f != ".");
    out
}

/// Write every sheet into `dir` in `format` (with the PDF book of them
/// all for PDF) and the manifest, all or nothing: every file is rendered,
/// then written to a temporary beside its place, and only when all are
/// written are they renamed into place; a failure removes every temporary
/// of this run ([`write_files_atomically`]). Then the
/// sheets an earlier run listed in the manifest and this one did not
/// write are removed, each named in a note.
pub fn write_sheets(sheets: &[Sheet], dir: &Path, format: Format, dpi: f64) -> Result<Written> {
    std::fs::create_dir_all(dir).map_err(|e| write_error(&dir.display().to_string(), e))?;
    let before = listed(dir);
    // Render everything first, so that a failure writes nothing.
    let mut files = Vec::new();
    for s in sheets {
        let (ext, bytes) = match format {
            Format::Svg => ("svg", s.svg.clone().into_bytes()),
            Format::Png => ("png", png(&s.svg, dpi)?),
            Format::Pdf => ("pdf", pdf(&s.svg)?),
        };
        files.push((dir.join(format!("{}.{ext}", s.name)), bytes));
    }
    let paths: Vec<PathBuf> = files.iter().map(|(p, _)| p.clone()).collect();
    if format == Format::Pdf && sheets.len() > 1 {
        files.push((dir.join(BOOK), pdf_book(sheets)?));
    }
    files.push((
        dir.join(MANIFEST),
        manifest(sheets, &paths, format).into_bytes(),
    ));
    let refs: Vec<(PathBuf, &[u8])> = files.iter().map(|(p, b)| (p.clone(), &b[..])).collect();
    write_files_atomically(&refs)?;
    let mut notes = Vec::new();
    let written: Vec<PathBuf> = files.into_iter().map(|(p, _)| p).collect();
    let removed: Vec<String> = before
        .into_iter()
        .map(|old| dir.join(old))
        .filter(|p| !written.contains(p) && p.is_file() && std::fs::remove_file(p).is_ok())
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
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
            .filter(|p| p.is_file() && !written.contains(p) && looks_like_a_sheet(p))
            .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
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
    if !matches!(ext, "svg" | "png" | "pdf") {
        return false;
    }
    let numbered = |prefix: &str| {
        stem.strip_prefix(prefix)
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
    };
    matches!(stem, "positions" | "diagrams" | "course" | "sheets")
        || ["mechanism_", "velocity_", "acceleration_"]
            .iter()
            .any(|p| numbered(p))
}
