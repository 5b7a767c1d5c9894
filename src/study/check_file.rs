//! `check SCENE ANSWER` as one call: the two files read (the answer JSON,
//! SVG or DXF, refused when larger than the grading reads), the answer
//! checked ([`super::Solution::check_answer`]), the overlay written when
//! asked, and the report as text or JSON with its exit status. The binary
//! only parses its arguments.

use super::Study;
use super::studies::{self, CheckRequest};
use crate::error::{Error, Result, in_file};
use crate::grading::answer::MAX_ANSWER_BYTES;
use crate::grading::dxf;
use std::path::Path;

/// Check `answer` against `scene`: the report, and the exit status (0
/// right, 1 wrong, 4 some items cannot be judged).
pub fn check_file(scene: &Path, answer: &Path, req: &CheckRequest) -> Result<(String, u8)> {
    let name = answer.display().to_string();
    let svg = is_drawing(answer);
    let (text, dxf_bytes) = read_answer(answer)?;
    if req.overlay_dxf.is_some() && dxf_bytes.is_none() {
        return Err(Error::scene(
            "dxf",
            "--dxf writes the overlay into a copy of a DXF answer: this answer is no DXF file (give --svg for an overlay of its own)",
        ));
    }
    let parsed = studies::parse_answer(&text, &name, svg, req)?;
    let study = study_for(scene, req)?;
    studies::position_of(&study, &parsed, &name, req)?;
    let checked = studies::check_parsed(&study.solve()?, parsed, req.lang)?;
    if let Some(out) = &req.overlay
        && let Some(overlay) = checked.overlay()
    {
        super::files::write_atomically(out, overlay.as_bytes())?;
    }
    if let Some(out) = &req.overlay_photo {
        photo_overlay(&checked, answer, out)?;
    }
    if let (Some(out), Some(bytes)) = (&req.overlay_dxf, &dxf_bytes)
        && let Some(copy) = checked.overlay_dxf(bytes)
    {
        super::files::write_atomically(out, &copy.map_err(in_file(&name))?)?;
    }
    let text = if req.json {
        pretty(&checked.to_json())
    } else {
        checked.to_text()
    };
    Ok((text, checked.status()))
}

/// Write the overlay of a photographed plan (`--photo-overlay`) to
/// `out`: the photo is found against the marks file `answer`'s folder and
/// linked from the SVG by its name where both are in one folder, else by
/// its absolute path.
#[cfg(feature = "photo")]
fn photo_overlay(checked: &super::Checked, answer: &Path, out: &Path) -> Result<()> {
    let not_marks = || {
        Error::scene(
            "photo-overlay",
            "--photo-overlay draws over the photo of a marks file (a JSON answer with \"photo\" and its \"file\"): this answer has none",
        )
    };
    let file = checked.photo_file().ok_or_else(not_marks)?;
    let photo = answer.parent().unwrap_or(Path::new("")).join(file);
    let bytes = super::reads::read_bounded(&photo, super::reads::MAX_PHOTO_BYTES, "a photo")?;
    let size = crate::grading::photo::displayed_size(&bytes)?;
    let folder = |p: &Path| {
        p.parent()
            .map(|d| {
                if d.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    d
                }
            })
            .and_then(|d| d.canonicalize().ok())
    };
    let href = match (folder(&photo), folder(out)) {
        (Some(a), Some(b)) if a == b => file.rsplit('/').next().unwrap_or(file).to_string(),
        _ => photo.canonicalize().map_or_else(
            |_| photo.display().to_string(),
            |p| format!("file://{}", p.display()),
        ),
    };
    let svg = checked.photo_overlay(&href, size).ok_or_else(not_marks)?;
    super::files::write_atomically(out, svg.as_bytes())
}

#[cfg(not(feature = "photo"))]
fn photo_overlay(_: &super::Checked, _: &Path, _: &Path) -> Result<()> {
    Err(Error::scene(
        "photo-overlay",
        "this build of mechplan has no photo feature: build it with its default features",
    ))
}

/// The scene file read for a check: numbered as `req.positions_from`
/// says (`--positions-from`: the report and the gradebook number the
/// positions so), else as the scene does.
pub(super) fn study_for(scene: &Path, req: &CheckRequest) -> Result<Study> {
    let study = Study::from_path(scene)?;
    Ok(match req.positions_from {
        Some(n) => study.numbered(n),
        None => study,
    })
}

/// Whether an answer file is a drawing by its extension (.svg, .dxf).
pub(super) fn is_drawing(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg") || e.eq_ignore_ascii_case("dxf"))
}

/// An answer file's text, refusing one larger than [`MAX_ANSWER_BYTES`]
/// before it is read whole; its problems name the file. A DXF (by its
/// extension or its first lines) is decoded from its code page
/// ([`crate::grading::dxf::decode`]), its bytes kept for the copy with the
/// overlay (`--dxf`).
pub(super) fn read_answer(path: &Path) -> Result<(String, Option<Vec<u8>>)> {
    let name = path.display().to_string();
    let bytes = super::reads::read_bounded(path, MAX_ANSWER_BYTES as u64, "an answer")?;
    let dxf = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dxf"));
    if dxf || dxf::looks_like_dxf_bytes(&bytes) {
        let text = dxf::decode(&bytes).map_err(in_file(&name))?;
        return Ok((text, Some(bytes)));
    }
    let text = String::from_utf8(bytes).map_err(|e| Error::Io {
        path: name,
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e.utf8_error()),
    })?;
    Ok((text, None))
}

/// Pretty JSON with a final newline.
fn pretty(v: &serde_json::Value) -> String {
    let mut t = serde_json::to_string_pretty(v).expect("JSON of numbers and strings");
    t.push('\n');
    t
}
