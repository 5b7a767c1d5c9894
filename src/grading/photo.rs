//! Plans drawn in pencil on paper, photographed, and graded from a marks
//! file (docs/check.md, "Plans on paper: photos and marks"): the pixels
//! of a rectangle of known size and of the plan's points, mapped to the
//! sheet's millimetres by the rectangle's homography and made relative to
//! the pole, then read as the JSON answer with those points would be.
//! With `"snap": true` each clicked point first moves to the crossing of
//! pencil lines nearest it ([`snap`], feature `photo`).

use crate::error::{Error, Issue, Result};
use crate::json::escape;
use super::answer::{Answer, Given};
pub use super::homography::Homography;
use super::numbers::{issue, number};
use serde_json::{Map, Value};

/// How a marks file's photo is read: its bytes by the name `photo.file`
/// gives, or why not. Reading files is the front door's (`crate::study`
/// finds the name against the marks file's folder).
pub type PhotoFile<'a> = &'a dyn Fn(&str) -> std::result::Result<Vec<u8>, String>;

/// The pole's names in an answer's points (docs/check.md) but `p`, which
/// is the pole only where none of these is marked (in a scene with a
/// point P, `p` is that point and the pole is `p_v` or `p_a`, as the
/// grader reads it).
const POLE_NAMES: [&str; 5] = ["p_v", "pv", "p_a", "pa", "π"];

/// The marks file's own fields beside the answer's.
const MARKS_FIELDS: [&str; 2] = ["photo", "snap"];

/// How far a click may be moved to a crossing of pencil lines, mm on the
/// sheet: a careless click is 1–1.5 mm off, and a wider radius reaches
/// the crossings of other lines more often than it saves a click further
/// off (tests/check_photo.rs: 2.5 mm got 208 of 234 plans as their twin,
/// 2.0 mm 212, 1.8 mm 216). Only with `photo` (snapping decodes the photo).
#[cfg(feature = "photo")]
pub const SNAP_RADIUS_MM: f64 = 1.8;

/// The fields of an answer a marks file may have too (as `from_json`
/// allows them).
const ANSWER_FIELDS: [&str; 11] = [
    "plan", "position", "positions_from", "mu", "delta", "segments", "angles", "points",
    "values", "title", "velocity",
];

/// The smallest and largest rectangle, mm: smaller than a centimetre
/// square it magnifies every click; larger than A0 it is no sheet.
const RECTANGLE_MM: (f64, f64) = (5.0, 1200.0);

/// The shortest side of the rectangle in the photo, px: below this a
/// click's pixel is a large part of it.
const MIN_SIDE_PX: f64 = 20.0;

/// The coordinates a pixel may have: no camera's photo is a million
/// pixels across; a larger number is a slip of the file.
const MAX_PX: f64 = 1e6;

/// A corner clicked a pixel off may move a point by this many of the
/// photo's pixels (at its scale) before the rectangle is called badly
/// conditioned for the plan: inside the rectangle it moves by at most
/// one; far outside a small one, by many.
const AMPLIFICATION_LIMIT: f64 = 3.0;

/// Where the photo's scale across the rectangle varies by more than this
/// factor, it was taken too obliquely to read its far side as well as
/// its near one.
const FORESHORTENING_LIMIT: f64 = 1.5;

/// What the report says of the photo a marks file was read from.
#[derive(Clone, Debug, PartialEq)]
pub struct PhotoReading {
    /// The photo's file as the marks file names it.
    pub file: Option<String>,
    /// The photo's mean scale over the rectangle, px per mm.
    pub px_per_mm: f64,
    /// The least and the most px per mm over the rectangle (they differ
    /// where the photo was taken at an angle).
    pub px_per_mm_range: (f64, f64),
    /// How far, in mm on the plan, a corner clicked one pixel off moves
    /// the farthest point relative to the pole.
    pub corner_pixel_mm: f64,
    /// Why the rectangle is badly conditioned for this plan, if it is.
    pub badly_conditioned: Vec<String>,
    /// Where the points were snapped: each point's move.
    pub snapped: Option<Snapped>,
    /// The rectangle's corners in the photo (px) and its size (mm): the
    /// map back from the sheet to the photo, for the overlay drawn in the
    /// photo's own perspective.
    pub corners_px: [[f64; 2]; 4],
    /// The rectangle's size on the sheet, mm.
    pub size_mm: [f64; 2],
    /// The pole on the sheet, mm from the rectangle's bottom-left corner.
    pub pole_mm: [f64; 2],
}

/// The points moved to their crossings (`"snap": true`).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapped {
    /// How far a point may move, mm on the sheet.
    pub radius_mm: f64,
    /// Each point by its key: how far it moved (mm), `None` where no
    /// crossing of two pencil lines lies within the radius (left where
    /// it was clicked).
    pub moves: Vec<(String, Option<f64>)>,
}

impl PhotoReading {
    /// Where a point of the plan (mm from the pole, y up) is in the
    /// photo (px); `None` beyond the sheet's horizon.
    pub fn to_photo(&self, p: [f64; 2]) -> Option<[f64; 2]> {
        let [w, h] = self.size_mm;
        let sheet = [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]];
        Homography::from_corners(&sheet, &self.corners_px)?
            .map([self.pole_mm[0] + p[0], self.pole_mm[1] + p[1]])
    }

    /// The report's lines on the photo.
    pub fn to_text(&self) -> String {
        use std::fmt::Write as _;
        let mut t = String::new();
        let file = self.file.as_deref().unwrap_or("the photo");
        let (lo, hi) = self.px_per_mm_range;
        let _ = writeln!(
            t,
            "Photo {file}: {:.2} px per mm over the rectangle ({lo:.2} to {hi:.2}); a corner clicked 1 px off moves a point by up to {:.3} mm.",
            self.px_per_mm, self.corner_pixel_mm
        );
        for why in &self.badly_conditioned {
            let _ = writeln!(t, "The rectangle is badly conditioned: {why}.");
        }
        if let Some(s) = &self.snapped {
            let _ = writeln!(
                t,
                "Snapped to the pencil lines' crossings within {:.1} mm:",
                s.radius_mm
            );
            for (k, m) in &s.moves {
                let _ = match m {
                    Some(d) => writeln!(t, "  {k}: moved {d:.2} mm"),
                    None => writeln!(
                        t,
                        "  {k}: no crossing of two lines within {:.1} mm, kept where clicked",
                        s.radius_mm
                    ),
                };
            }
        }
        t
    }

    /// The report's JSON on the photo.
    pub fn to_json(&self) -> Value {
        serde_json::json!({
            "file": self.file,
            "px_per_mm": self.px_per_mm,
            "px_per_mm_range": [self.px_per_mm_range.0, self.px_per_mm_range.1],
            "corner_pixel_mm": self.corner_pixel_mm,
            "badly_conditioned": self.badly_conditioned,
            "snapped": self.snapped.as_ref().map(|s| serde_json::json!({
                "radius_mm": s.radius_mm,
                "moves": s.moves.iter().map(|(k, m)| serde_json::json!({"point": k, "moved_mm": m})).collect::<Vec<_>>(),
            })),
        })
    }
}

/// The photo's size as displayed (px): its file's header, its EXIF
/// orientation applied (a photo turned a quarter shows its height as its
/// width).
#[cfg(feature = "photo")]
pub fn displayed_size(bytes: &[u8]) -> Result<(u32, u32)> {
    use image::ImageDecoder;
    use image::metadata::Orientation;
    let bad = |why: String| {
        Error::scene(
            "/photo/file",
            format!("the photo cannot be decoded: {why}"),
        )
    };
    let mut decoder = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| bad(e.to_string()))?
        .into_decoder()
        .map_err(|e| bad(e.to_string()))?;
    let (w, h) = decoder.dimensions();
    Ok(
        match decoder.orientation().unwrap_or(Orientation::NoTransforms) {
            Orientation::Rotate90
            | Orientation::Rotate270
            | Orientation::Rotate90FlipH
            | Orientation::Rotate270FlipH => (h, w),
            _ => (w, h),
        },
    )
}

/// Whether an answer's JSON object is a marks file (it has `photo`).
pub fn is_marks(o: &Map<String, Value>) -> bool {
    o.contains_key("photo")
}

/// A pair of finite numbers at `ptr`, each within ±`max`.
fn pair(v: &Value, ptr: &str, max: f64, what: &str, issues: &mut Vec<Issue>) -> Option<[f64; 2]> {
    let Some(a) = v.as_array().filter(|a| a.len() == 2) else {
        issues.push(issue(ptr, format!("expected [x, y], {what}")));
        return None;
    };
    let mut at = |k: usize| {
        let p = format!("{ptr}/{k}");
        number(&a[k], &p, issues).filter(|x| {
            let ok = x.abs() <= max;
            if !ok {
                issues.push(issue(&p, format!("{x} is out of range: at most {max} in size")));
            }
            ok
        })
    };
    Some([at(0)?, at(1)?])
}

/// The photo's description: its file, the rectangle's corners in px and
/// its size in mm.
struct PhotoSpec {
    file: Option<String>,
    corners: [[f64; 2]; 4],
    size: [f64; 2],
}

/// Read `/photo`, each problem at its field.
fn photo_spec(v: &Value, issues: &mut Vec<Issue>) -> Option<PhotoSpec> {
    let Some(o) = v.as_object() else {
        issues.push(issue(
            "/photo",
            "expected an object: { \"file\", \"rectangle_px\", \"rectangle_mm\" }",
        ));
        return None;
    };
    for k in o.keys() {
        if !["file", "rectangle_px", "rectangle_mm"].contains(&k.as_str()) {
            issues.push(issue(
                format!("/photo/{}", escape(k)),
                format!("unknown field \"{k}\" (allowed: file, rectangle_px, rectangle_mm)"),
            ));
        }
    }
    let before = issues.len();
    let file = match o.get("file") {
        None => None,
        Some(Value::String(s)) if !s.trim().is_empty() => Some(s.clone()),
        Some(_) => {
            issues.push(issue("/photo/file", "expected the photo's file name (relative to the marks file)"));
            None
        }
    };
    let corners = match o.get("rectangle_px") {
        Some(Value::Array(a)) if a.len() == 4 => {
            let c: Vec<Option<[f64; 2]>> = a
                .iter()
                .enumerate()
                .map(|(i, p)| pair(p, &format!("/photo/rectangle_px/{i}"), MAX_PX, "a corner's pixel", issues))
                .collect();
            c.iter().all(Option::is_some).then(|| [c[0].unwrap(), c[1].unwrap(), c[2].unwrap(), c[3].unwrap()])
        }
        _ => {
            issues.push(issue(
                "/photo/rectangle_px",
                "expected the rectangle's four corners in pixels: [[x, y] bottom-left, bottom-right, top-right, top-left]",
            ));
            None
        }
    };
    let size = match o.get("rectangle_mm") {
        Some(v) => pair(v, "/photo/rectangle_mm", f64::MAX, "the rectangle's width and height in mm", issues)
            .filter(|s| {
                let (lo, hi) = RECTANGLE_MM;
                let ok = s.iter().all(|x| (lo..=hi).contains(x));
                if !ok {
                    issues.push(issue(
                        "/photo/rectangle_mm",
                        format!("a rectangle of {} × {} mm is degenerate or no sheet's: each side is from {lo} to {hi} mm", s[0], s[1]),
                    ));
                }
                ok
            }),
        None => {
            issues.push(issue("/photo/rectangle_mm", "missing: the rectangle's [width, height] in mm"));
            None
        }
    };
    if issues.len() > before {
        return None;
    }
    let corners = corners?;
    if let Some(why) = quadrilateral_issue(&corners) {
        issues.push(issue("/photo/rectangle_px", why));
        return None;
    }
    Some(PhotoSpec { file, corners, size: size? })
}

/// Why four corners (bottom-left, bottom-right, top-right, top-left, in
/// pixels with y down) are no photographed rectangle, if they are not.
fn quadrilateral_issue(c: &[[f64; 2]; 4]) -> Option<String> {
    let edge = |i: usize| {
        let (a, b) = (c[i], c[(i + 1) % 4]);
        [b[0] - a[0], b[1] - a[1]]
    };
    for i in 0..4 {
        let e = edge(i);
        if e[0].hypot(e[1]) < MIN_SIDE_PX {
            return Some(format!(
                "corners {i} and {} are {:.1} px apart: a side of the rectangle must be at least {MIN_SIDE_PX} px in the photo",
                (i + 1) % 4,
                e[0].hypot(e[1])
            ));
        }
    }
    // Turning from each edge to the next: with y down, an upright sheet's
    // bottom-left, bottom-right, top-right, top-left turn the same way
    // (negative), by at least a few degrees at every corner.
    let sines: Vec<f64> = (0..4)
        .map(|i| {
            let (a, b) = (edge(i), edge((i + 1) % 4));
            (a[0] * b[1] - a[1] * b[0]) / (a[0].hypot(a[1]) * b[0].hypot(b[1]))
        })
        .collect();
    let min_sin = (5f64).to_radians().sin();
    if sines.iter().all(|&s| s >= min_sin) {
        return Some("the corners go round the wrong way (a mirrored sheet): give them bottom-left, bottom-right, top-right, top-left of the upright sheet".into());
    }
    if !sines.iter().all(|&s| s <= -min_sin) {
        return Some("the four corners are not a convex quadrilateral (a corner crossed, repeated or on a line with two others): give them bottom-left, bottom-right, top-right, top-left of the upright sheet".into());
    }
    None
}

/// The marked points in px, the pole's key apart.
struct Marked {
    pole: (String, [f64; 2]),
    points: Vec<(String, [f64; 2])>,
}

/// Read `/points` in px; the pole is required once.
fn marked_points(v: Option<&Value>, issues: &mut Vec<Issue>) -> Option<Marked> {
    let Some(Value::Object(m)) = v else {
        issues.push(issue(
            "/points",
            "expected the plan's points in pixels of the photo, the pole (p_v, p_a, p or π) among them",
        ));
        return None;
    };
    let (mut pole, mut points) = (None::<(String, [f64; 2])>, Vec::new());
    let before = issues.len();
    let is_pole = |k: &str| POLE_NAMES.contains(&k.trim().to_lowercase().as_str());
    let strong = m.keys().any(|k| is_pole(k));
    for (k, v) in m {
        let ptr = format!("/points/{}", escape(k));
        let Some(at) = pair(v, &ptr, MAX_PX, "the point's pixel in the photo", issues) else {
            continue;
        };
        if is_pole(k) || (!strong && k.trim().to_lowercase() == "p") {
            if let Some((first, _)) = &pole {
                issues.push(issue(&ptr, format!("the pole is marked twice (also \"{first}\"): mark it once")));
            } else {
                pole = Some((k.clone(), at));
            }
        } else {
            points.push((k.clone(), at));
        }
    }
    if issues.len() > before {
        return None;
    }
    let Some(pole) = pole else {
        issues.push(issue(
            "/points",
            "the pole is not marked: the points are measured from it; mark it as p_v, p_a, π or p",
        ));
        return None;
    };
    Some(Marked { pole, points })
}

/// The answer a marks file gives: its points mapped from the photo to
/// mm from the pole, and the photo's reading for the report. `read`
/// reads `photo.file` (which then must be there); without it the photo
/// is not read, and snapping is refused.
pub fn from_marks(text: &str, read: Option<PhotoFile>) -> Result<(Answer, PhotoReading)> {
    let v = crate::json::parse_strict(text)
        .map_err(|e| Error::json(crate::json::locate_bad_numbers(text).unwrap_or(e)))?;
    let Some(o) = v.as_object() else {
        return Err(Error::fields(vec![issue("", "a marks file is a JSON object")]));
    };
    let mut issues = Vec::new();
    for k in o.keys() {
        if !ANSWER_FIELDS.contains(&k.as_str()) && !MARKS_FIELDS.contains(&k.as_str()) {
            issues.push(issue(
                format!("/{}", escape(k)),
                format!("unknown field \"{k}\" (allowed in a marks file: photo, snap, plan, position, positions_from, mu, delta, segments, angles, points, values, velocity)"),
            ));
        }
    }
    let snap = match o.get("snap") {
        None => false,
        Some(Value::Bool(b)) => *b,
        Some(_) => {
            issues.push(issue("/snap", "expected true or false"));
            false
        }
    };
    let spec = o.get("photo").and_then(|p| photo_spec(p, &mut issues));
    let marked = marked_points(o.get("points"), &mut issues);
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    let (spec, mut marked) = (spec.expect("no issue"), marked.expect("no issue"));
    let bytes = match (&spec.file, read) {
        (Some(f), Some(read)) => Some(read(f).map_err(|why| {
            Error::scene(
                "/photo/file",
                format!("the photo cannot be read: {why} (its path is relative to the marks file)"),
            )
        })?),
        _ => None,
    };
    let [w, h] = spec.size;
    let sheet = [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]];
    let Some(hom) = Homography::from_corners(&spec.corners, &sheet) else {
        return Err(Error::scene(
            "/photo/rectangle_px",
            "the corners give no map to the sheet (three of them on a line?)",
        ));
    };
    let snapped = if snap {
        Some(snap_marks(&spec, &hom, &mut marked, bytes.as_deref())?)
    } else {
        None
    };
    let mut reading = reading(&spec, &hom, &marked, snapped)?;
    let to_mm = |k: &str, p: [f64; 2]| {
        hom.map(p).ok_or_else(|| {
            Error::scene(
                format!("/points/{}", escape(k)),
                "the point is beyond the horizon of the sheet's plane in the photo: not on the sheet",
            )
        })
    };
    let pole = to_mm(&marked.pole.0, marked.pole.1)?;
    reading.pole_mm = pole;
    let mut points = Map::new();
    for (k, p) in &marked.points {
        let q = to_mm(k, *p)?;
        // Written as a typed answer would be, to 0.01 mm.
        let r = |x: f64| (x * 100.0).round() / 100.0;
        points.insert(k.clone(), serde_json::json!([r(q[0] - pole[0]), r(q[1] - pole[1])]));
    }
    let mut twin: Map<String, Value> = o
        .iter()
        .filter(|(k, _)| !MARKS_FIELDS.contains(&k.as_str()))
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    twin.insert("points".into(), Value::Object(points));
    let mut ans = super::answer::from_json(&Value::Object(twin).to_string())?;
    // Every coordinate was written to 0.01 mm: its rounding, whatever
    // digits its value happened to end in.
    for it in &mut ans.items {
        if matches!(it.given, Given::Point { .. }) && it.pointer.starts_with("/points/") {
            it.rounding = 0.005 * std::f64::consts::SQRT_2;
        }
    }
    Ok((ans, reading))
}

/// The photo's scale and conditioning for the points `marked`.
fn reading(
    spec: &PhotoSpec,
    hom: &Homography,
    marked: &Marked,
    snapped: Option<Snapped>,
) -> Result<PhotoReading> {
    let bad = || Error::scene("/photo/rectangle_px", "the corners give no map to the sheet");
    // px per mm at each corner and the centre.
    let centre = spec
        .corners
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / 4.0, s[1] + p[1] / 4.0]);
    let scales: Vec<f64> = spec
        .corners
        .iter()
        .chain(std::iter::once(&centre))
        .map(|&p| hom.scale_at(p).map(|mm_per_px| 1.0 / mm_per_px))
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    let (lo, hi) = scales
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &s| (l.min(s), h.max(s)));
    let [w, h] = spec.size;
    let (a, b) = (
        spec.corners,
        [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]],
    );
    // Each corner coordinate clicked a pixel off: how far the points move
    // relative to the pole.
    let place = |hm: &Homography| -> Option<Vec<[f64; 2]>> {
        let p0 = hm.map(marked.pole.1)?;
        marked
            .points
            .iter()
            .map(|(_, p)| hm.map(*p).map(|q| [q[0] - p0[0], q[1] - p0[1]]))
            .collect()
    };
    let base = place(hom).ok_or_else(bad)?;
    let mut worst: f64 = 0.0;
    for i in 0..4 {
        for j in 0..2 {
            for d in [-1.0, 1.0] {
                let mut c = a;
                c[i][j] += d;
                let moved = Homography::from_corners(&c, &b)
                    .and_then(|hm| place(&hm))
                    .ok_or_else(bad)?;
                for (p, q) in base.iter().zip(&moved) {
                    worst = worst.max((p[0] - q[0]).hypot(p[1] - q[1]));
                }
            }
        }
    }
    let mean = scales[4];
    let mut badly = Vec::new();
    if worst * mean > AMPLIFICATION_LIMIT {
        badly.push(format!(
            "a corner clicked 1 px off moves a point by up to {worst:.2} mm ({:.1} px at this scale): the points lie far outside the rectangle; mark a larger rectangle around the plan",
            worst * mean
        ));
    }
    if hi / lo > FORESHORTENING_LIMIT {
        badly.push(format!(
            "the scale goes from {lo:.2} to {hi:.2} px per mm across it: the photo was taken at a steep angle; photograph the sheet square on"
        ));
    }
    Ok(PhotoReading {
        file: spec.file.clone(),
        px_per_mm: mean,
        px_per_mm_range: (lo, hi),
        corner_pixel_mm: worst,
        badly_conditioned: badly,
        snapped,
        corners_px: spec.corners,
        size_mm: spec.size,
        pole_mm: [0.0, 0.0],
    })
}

/// Move each of `marked` to the crossing of pencil lines nearest it in
/// the photo (within [`SNAP_RADIUS_MM`]), the photo's file's `bytes`:
/// how far each moved on the sheet.
#[cfg(feature = "photo")]
fn snap_marks(
    spec: &PhotoSpec,
    hom: &Homography,
    marked: &mut Marked,
    bytes: Option<&[u8]>,
) -> Result<Snapped> {
    if spec.file.is_none() {
        return Err(Error::scene(
            "/photo/file",
            "\"snap\": true reads the photo: give its file (relative to the marks file)",
        ));
    }
    let Some(bytes) = bytes else {
        return Err(Error::scene(
            "/snap",
            "the photo is read by the front door (mechplan check, Study::check_answer); an answer's text alone (check::answer::from_json) reads no file and cannot snap",
        ));
    };
    let img = super::snap::load(bytes)?;
    let mut moves = Vec::new();
    let pole = std::iter::once(&mut marked.pole);
    for (k, at) in pole.chain(marked.points.iter_mut()) {
        let outside = || {
            Error::scene(
                format!("/points/{}", escape(k)),
                "the point is beyond the horizon of the sheet's plane in the photo: not on the sheet",
            )
        };
        let mm_per_px = hom.scale_at(*at).ok_or_else(outside)?;
        let px_per_mm = 1.0 / mm_per_px;
        let found = super::snap::crossing(&img, *at, SNAP_RADIUS_MM * px_per_mm, px_per_mm);
        let moved = match found {
            Some(x) => {
                let (a, b) = (hom.map(*at).ok_or_else(outside)?, hom.map(x).ok_or_else(outside)?);
                *at = x;
                Some((a[0] - b[0]).hypot(a[1] - b[1]))
            }
            None => None,
        };
        moves.push((k.clone(), moved));
    }
    Ok(Snapped {
        radius_mm: SNAP_RADIUS_MM,
        moves,
    })
}

/// Without the photo's decoding (feature `photo`), snapping is refused.
#[cfg(not(feature = "photo"))]
fn snap_marks(
    _spec: &PhotoSpec,
    _hom: &Homography,
    _marked: &mut Marked,
    _bytes: Option<&[u8]>,
) -> Result<Snapped> {
    Err(Error::scene(
        "/snap",
        "this build of mechplan reads no photos (it was built without the feature `photo`): mark the points carefully and leave out \"snap\"",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn homography_maps_its_corners() {
        let from = [[100.0, 900.0], [800.0, 950.0], [760.0, 80.0], [130.0, 120.0]];
        let to = [[0.0, 0.0], [185.0, 0.0], [185.0, 287.0], [0.0, 287.0]];
        let h = Homography::from_corners(&from, &to).unwrap();
        for (f, t) in from.iter().zip(&to) {
            let m = h.map(*f).unwrap();
            assert!((m[0] - t[0]).abs() < 1e-9 && (m[1] - t[1]).abs() < 1e-9, "{m:?} {t:?}");
        }
        let back = h.inverse().unwrap();
        let p = back.map(h.map([400.0, 500.0]).unwrap()).unwrap();
        assert!((p[0] - 400.0).abs() < 1e-8 && (p[1] - 500.0).abs() < 1e-8);
    }

    #[test]
    fn corners_that_are_no_rectangle_are_named() {
        let ok = [[0.0, 100.0], [100.0, 100.0], [100.0, 0.0], [0.0, 0.0]];
        assert!(quadrilateral_issue(&ok).is_none());
        let mirrored = [ok[1], ok[0], ok[3], ok[2]];
        assert!(quadrilateral_issue(&mirrored).unwrap().contains("wrong way"));
        let crossed = [ok[0], ok[2], ok[1], ok[3]];
        assert!(quadrilateral_issue(&crossed).unwrap().contains("convex"));
        let flat = [[0.0, 100.0], [50.0, 100.0], [100.0, 100.0], [0.0, 0.0]];
        assert!(quadrilateral_issue(&flat).unwrap().contains("convex"));
    }
}
