//! Reading a plan drawn in a CAD (AutoCAD, KOMPAS, LibreCAD) and saved as
//! an ASCII DXF (R12 to R2018) into a [`Drawing`]: its texts (TEXT, MTEXT,
//! their formatting stripped) and its lines (LINE, LWPOLYLINE,
//! POLYLINE/VERTEX), those of inserted blocks (INSERT) placed by their
//! insertion point, scale and rotation, in millimetres (`$INSUNITS`
//! unitless or a length converted), y turned over to the drawing's y down.
//! How a drawing is read as an answer is shared with SVG
//! ([`super::drawing`]).
//!
//! Texts of files before R2007 are in the file's code page
//! (`$DWGCODEPAGE`, e.g. ANSI_1251) unless the file is valid UTF-8;
//! `\U+XXXX` escapes are read in every version. Reading is linear in the
//! file's size but for blocks, which are inserted at most [`MAX_DEPTH`]
//! deep and into at most [`MAX_ENTITIES`] entities in all.

use super::answer::check_size;
use super::drawing::{Drawing, whole};
use crate::error::Result;
use crate::kinematics::construction::PlanKind;
use kurbo::{Affine, Point, Vec2};
use super::dxf_text::{code_page, encoding, mtext_codes, text_codes};
use std::collections::HashMap;

/// The layer of a teacher's overlay written into a copy of the student's
/// file (`check --dxf`): skipped when the file is read as an answer, so
/// that a marked copy read again is the student's drawing alone.
pub const OVERLAY_LAYER: &str = "MECHPLAN-CHECK";

/// The deepest nesting of inserted blocks read (a CAD nests a few).
pub const MAX_DEPTH: usize = 16;

/// The most entities a drawing may expand to with its blocks inserted.
pub const MAX_ENTITIES: usize = 1_000_000;

/// The first bytes of a binary DXF.
const BINARY: &[u8] = b"AutoCAD Binary DXF";

/// Whether an answer's text is a DXF file: it starts (past blank lines)
/// with a group code 0 and SECTION, or a comment (999), or it is a
/// binary DXF.
pub fn looks_like_dxf(text: &str) -> bool {
    looks_like_dxf_bytes(text.as_bytes())
}

/// [`looks_like_dxf`] of a file's bytes (before they are decoded).
pub fn looks_like_dxf_bytes(bytes: &[u8]) -> bool {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if bytes.starts_with(BINARY) {
        return true;
    }
    let mut lines = bytes
        .split(|&b| b == b'\n')
        .map(|l| l.trim_ascii())
        .skip_while(|l| l.is_empty());
    match (lines.next(), lines.next()) {
        (Some(b"999"), _) => true,
        (Some(b"0"), Some(s)) => s.eq_ignore_ascii_case(b"SECTION"),
        _ => false,
    }
}

/// A DXF file's bytes as text: refused when binary, larger than an
/// answer may be or not a DXF; UTF-8 when it is valid UTF-8 (R2007 and
/// later always are), else in the code page its header names
/// (`$DWGCODEPAGE`, ANSI_1252 when it names none).
pub fn decode(bytes: &[u8]) -> Result<String> {
    check_size(bytes.len() as u64)?;
    if bytes.starts_with(BINARY) {
        return Err(whole(
            "a binary DXF file: save the drawing as an ASCII DXF (R12 to R2018) to have it checked",
        ));
    }
    if !looks_like_dxf_bytes(bytes) {
        let what = if bytes.trim_ascii().is_empty() {
            "an empty file"
        } else {
            "its first lines are not a DXF section (0, SECTION)"
        };
        return Err(whole(&format!(
            "not an ASCII DXF file: {what}; save the drawing as an ASCII DXF (R12 to R2018)"
        )));
    }
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if let Ok(s) = std::str::from_utf8(bytes) {
        return Ok(s.to_string());
    }
    let enc = code_page_encoding(bytes);
    Ok(enc.decode_without_bom_handling(bytes).0.into_owned())
}

/// The encoding of a DXF file's code page (`$DWGCODEPAGE`, ANSI_1252
/// when it names none or one mechplan does not know): how the texts of a
/// file before R2007 are written.
pub fn code_page_encoding(bytes: &[u8]) -> &'static encoding_rs::Encoding {
    encoding(&code_page(bytes)).unwrap_or(encoding_rs::WINDOWS_1252)
}

/// One group: its code, its value (trimmed) and the line its code is on
/// (from 1).
#[derive(Clone, Copy)]
struct Group<'a> {
    code: i32,
    value: &'a str,
    line: usize,
}

/// The groups of a DXF's text: pairs of lines, a code and a value (CRLF
/// or LF); a code that is not a number is refused where it is.
fn groups(text: &str) -> Result<Vec<Group<'_>>> {
    let mut out = Vec::new();
    let mut lines = text.lines().enumerate();
    // Blank lines before the first group.
    let mut first = true;
    while let Some((k, code)) = lines.next() {
        let code = code.trim();
        if first && code.is_empty() {
            continue;
        }
        first = false;
        let Ok(c) = code.parse::<i32>() else {
            if code.is_empty() && out.last().is_some_and(|g: &Group| g.value == "EOF") {
                break;
            }
            return Err(whole(&format!(
                "line {}: a DXF group code (a number) expected, found \"{}\"",
                k + 1,
                short(code)
            )));
        };
        let value = lines.next().map_or("", |(_, v)| v.trim());
        out.push(Group {
            code: c,
            value,
            line: k + 1,
        });
        if c == 0 && value == "EOF" {
            break;
        }
    }
    Ok(out)
}

/// A value quoted in a message: its first 40 characters.
fn short(s: &str) -> String {
    let mut t: String = s.chars().take(40).collect();
    if t.len() < s.len() {
        t.push('…');
    }
    t
}

/// An entity: its type, its groups (past the type's), the line it starts
/// on, and (POLYLINE) its vertices' entities.
struct Entity<'a> {
    kind: &'a str,
    groups: Vec<Group<'a>>,
    line: usize,
    vertices: Vec<Entity<'a>>,
}

impl<'a> Entity<'a> {
    /// Where the entity is, for a message: its type, line and handle.
    fn place(&self) -> String {
        let handle = self
            .groups
            .iter()
            .find(|g| g.code == 5)
            .map(|g| format!(", handle {}", g.value))
            .unwrap_or_default();
        format!("{} at line {}{handle}", self.kind, self.line)
    }

    fn value(&self, code: i32) -> Option<&'a str> {
        self.groups.iter().find(|g| g.code == code).map(|g| g.value)
    }

    /// Group `code`'s number (`default` without it); not a finite
    /// number is refused, naming the entity.
    fn num(&self, code: i32, default: Option<f64>) -> Result<f64> {
        match self.groups.iter().find(|g| g.code == code) {
            Some(g) => g
                .value
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    whole(&format!(
                        "{}: group {code} \"{}\" (line {}) is not a number",
                        self.place(),
                        short(g.value),
                        g.line + 1
                    ))
                }),
            None => default.ok_or_else(|| {
                whole(&format!(
                    "{}: no group {code} (a coordinate); the entity cannot be read",
                    self.place()
                ))
            }),
        }
    }

    fn point(&self, x: i32) -> Result<Point> {
        Ok(Point::new(self.num(x, None)?, self.num(x + 10, None)?))
    }

    /// Every (x, y) of repeated groups 10, 20 (an LWPOLYLINE's).
    fn points(&self) -> Result<Vec<Point>> {
        let mut out = Vec::new();
        let mut x = None;
        for g in &self.groups {
            let n = || {
                g.value.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                    whole(&format!(
                        "{}: group {} \"{}\" (line {}) is not a number",
                        self.place(),
                        g.code,
                        short(g.value),
                        g.line + 1
                    ))
                })
            };
            match g.code {
                10 => x = Some(n()?),
                20 => {
                    if let Some(x) = x.take() {
                        out.push(Point::new(x, n()?));
                    }
                }
                _ => {}
            }
        }
        Ok(out)
    }

    /// An LWPOLYLINE's vertices, each with its bulge (group 42 after
    /// its x, y; 0 when it has none): the arc to the next vertex.
    fn points_bulged(&self) -> Result<Vec<(Point, f64)>> {
        let ps = self.points()?;
        let mut bulges = vec![0.0; ps.len()];
        let mut k: Option<usize> = None;
        for g in &self.groups {
            match g.code {
                10 => k = Some(k.map_or(0, |k| k + 1)),
                42 => {
                    if let Some(b) = k.and_then(|k| bulges.get_mut(k)) {
                        *b = g.value.parse::<f64>().ok().filter(|x| x.is_finite()).unwrap_or(0.0);
                    }
                }
                _ => {}
            }
        }
        Ok(ps.into_iter().zip(bulges).collect())
    }

    fn flags(&self, code: i32) -> i64 {
        self.value(code)
            .and_then(|v| v.parse::<i64>().ok())
            .unwrap_or(0)
    }
}

/// A block: its base point and entities.
struct Block<'a> {
    base: Point,
    entities: Vec<Entity<'a>>,
}

/// A DXF's parts read: its header's units, its blocks and its entities.
struct File<'a> {
    units: Option<i64>,
    blocks: HashMap<String, Block<'a>>,
    entities: Vec<Entity<'a>>,
}

/// The entities of a run of groups (a section's or a block's), a
/// POLYLINE's VERTEX entities gathered into it.
fn entities<'a>(gs: &[Group<'a>]) -> Vec<Entity<'a>> {
    let mut out: Vec<Entity<'a>> = Vec::new();
    let mut in_polyline = false;
    let mut k = 0;
    while k < gs.len() {
        let g = gs[k];
        let mut j = k + 1;
        while j < gs.len() && gs[j].code != 0 {
            j += 1;
        }
        let e = Entity {
            kind: g.value,
            groups: gs[k + 1..j].to_vec(),
            line: g.line,
            vertices: Vec::new(),
        };
        k = j;
        match e.kind {
            "VERTEX" if in_polyline => {
                if let Some(p) = out.last_mut() {
                    p.vertices.push(e);
                }
            }
            "SEQEND" => in_polyline = false,
            _ => {
                in_polyline = e.kind == "POLYLINE";
                out.push(e);
            }
        }
    }
    out
}

fn read_file<'a>(gs: &[Group<'a>]) -> Result<File<'a>> {
    let mut file = File {
        units: None,
        blocks: HashMap::new(),
        entities: Vec::new(),
    };
    let mut k = 0;
    while k < gs.len() {
        if !(gs[k].code == 0 && gs[k].value == "SECTION") {
            k += 1;
            continue;
        }
        let name = gs.get(k + 1).filter(|g| g.code == 2).map_or("", |g| g.value);
        // A SECTION at the very end (no name, no body) has an empty body.
        let start = (k + 2).min(gs.len());
        let mut end = start;
        while end < gs.len() && !(gs[end].code == 0 && gs[end].value == "ENDSEC") {
            end += 1;
        }
        let body = &gs[start.min(end)..end];
        match name {
            "HEADER" => {
                for (i, g) in body.iter().enumerate() {
                    if g.code == 9
                        && g.value == "$INSUNITS"
                        && let Some(v) = body.get(i + 1)
                    {
                        file.units = v.value.parse().ok();
                    }
                }
            }
            "ENTITIES" => file.entities = entities(body),
            "BLOCKS" => {
                let mut i = 0;
                while i < body.len() {
                    if !(body[i].code == 0 && body[i].value == "BLOCK") {
                        i += 1;
                        continue;
                    }
                    let mut j = i + 1;
                    while j < body.len() && body[j].code != 0 {
                        j += 1;
                    }
                    let head = Entity {
                        kind: "BLOCK",
                        groups: body[i + 1..j].to_vec(),
                        line: body[i].line,
                        vertices: Vec::new(),
                    };
                    let mut e = j;
                    while e < body.len() && !(body[e].code == 0 && body[e].value == "ENDBLK") {
                        e += 1;
                    }
                    let name = head.value(2).unwrap_or("").to_string();
                    let base = Point::new(head.num(10, Some(0.0))?, head.num(20, Some(0.0))?);
                    file.blocks.insert(
                        name,
                        Block {
                            base,
                            entities: entities(&body[j..e]),
                        },
                    );
                    i = e + 1;
                }
            }
            _ => {}
        }
        k = end + 1;
    }
    Ok(file)
}

/// Millimetres per drawing unit of `$INSUNITS` (unitless: mm).
fn mm_per_unit(units: Option<i64>) -> Result<f64> {
    Ok(match units.unwrap_or(0) {
        0 | 4 => 1.0,
        1 => 25.4,
        2 => 304.8,
        5 => 10.0,
        6 => 1000.0,
        14 => 100.0,
        u => {
            return Err(whole(&format!(
                "the drawing's units ($INSUNITS = {u}) are not a length mechplan reads: draw the plan in millimetres ($INSUNITS = 4) or unitless"
            )));
        }
    })
}

/// Where the drawing's parts go: the lines and labels read so far (in
/// drawing units, y up) and the entities placed.
struct Out {
    labels: Vec<(String, Point)>,
    lines: Vec<Vec<Point>>,
    placed: usize,
    /// Arrowheads' outlines (a SOLID's corners, a closed polyline's),
    /// with the line that draws one when one does.
    heads: Vec<(Vec<Point>, Option<usize>)>,
}

fn walk(file: &File, es: &[Entity], t: Affine, depth: usize, out: &mut Out) -> Result<()> {
    for e in es {
        // A teacher's overlay (`check --dxf`) is not the student's drawing.
        if e.value(8).is_some_and(|l| l.eq_ignore_ascii_case(OVERLAY_LAYER)) {
            continue;
        }
        out.placed += 1;
        if out.placed > MAX_ENTITIES {
            return Err(whole(&format!(
                "the drawing expands to more than {MAX_ENTITIES} entities with its blocks inserted (at {}); an answer may have at most {MAX_ENTITIES}",
                e.place()
            )));
        }
        // An entity drawn in its object coordinates with the extrusion
        // turned over (a mirrored one, z = -1): x is -x of the world's.
        let world = t;
        let t = if e.num(230, Some(1.0))? < 0.0 && e.kind != "LINE" && e.kind != "MTEXT" {
            t * Affine::FLIP_X
        } else {
            t
        };
        match e.kind {
            "LINE" => out.lines.push(vec![world * e.point(10)?, world * e.point(11)?]),
            "LWPOLYLINE" => {
                let ps: Vec<(Point, f64)> = e
                    .points_bulged()?
                    .into_iter()
                    .map(|(p, b)| (t * p, b))
                    .collect();
                let codes: Vec<(i32, &str)> = e.groups.iter().map(|g| (g.code, g.value)).collect();
                let ps = super::arrows::taper(&ps, &codes, &mut out.heads);
                push_runs(out, &ps, e.flags(70) & 1 == 1);
            }
            "SOLID" => {
                let cs = [e.point(10)?, e.point(11)?, e.point(12)?];
                let last = e.point(13).unwrap_or(cs[2]);
                let mut ps: Vec<Point> = cs.iter().map(|&p| t * p).collect();
                if !cs.iter().any(|c| (*c - last).hypot() < 1e-9) {
                    ps.push(t * last);
                }
                out.heads.push((ps, None));
            }
            "POLYLINE" => {
                // Meshes and polyface meshes are no plan's vectors.
                if e.flags(70) & (16 | 64) != 0 {
                    continue;
                }
                let mut ps = Vec::new();
                for v in &e.vertices {
                    ps.push((t * v.point(10)?, v.num(42, Some(0.0))?));
                }
                push_runs(out, &ps, e.flags(70) & 1 == 1);
            }
            "TEXT" | "MTEXT" => out.labels.push(label(e, t)?),
            "INSERT" => {
                let name = e.value(2).unwrap_or("");
                if depth >= MAX_DEPTH {
                    return Err(whole(&format!(
                        "blocks inserted more than {MAX_DEPTH} deep ({} inserts block \"{}\"); an answer's blocks may nest at most {MAX_DEPTH} deep",
                        e.place(),
                        short(name)
                    )));
                }
                let Some(b) = file.blocks.get(name) else {
                    return Err(whole(&format!(
                        "{} inserts block \"{}\", which the file does not define",
                        e.place(),
                        short(name)
                    )));
                };
                let at = e.point(10)?;
                let (sx, sy) = (e.num(41, Some(1.0))?, e.num(42, Some(1.0))?);
                let rot = e.num(50, Some(0.0))?.to_radians();
                let own = Affine::translate(at.to_vec2())
                    * Affine::rotate(rot)
                    * Affine::scale_non_uniform(sx, sy)
                    * Affine::translate(-b.base.to_vec2());
                walk(file, &b.entities, t * own, depth + 1, out)?;
            }
            _ => {}
        }
    }
    Ok(())
}

/// A polyline's straight runs into the drawing's lines; a closed one of
/// three straight sides is an arrowhead's outline too.
fn push_runs(out: &mut Out, ps: &[(Point, f64)], closed: bool) {
    let runs = straight_runs(ps, closed);
    if closed && ps.len() == 3 && runs.len() == 1 {
        out.heads.push((runs[0].clone(), Some(out.lines.len())));
    }
    out.lines.extend(runs);
}

/// A polyline's straight runs: its vertices (each with the bulge of the
/// segment to the next; `closed`: the last's back to the first) cut
/// where a segment bulges. A bulge is an arc — a construction arc, a
/// rounded corner — never a plan's vector, and its ends are not where a
/// label may snap: a similar figure built by two arcs ends them beside
/// the point they find.
fn straight_runs(ps: &[(Point, f64)], closed: bool) -> Vec<Vec<Point>> {
    let mut runs = Vec::new();
    let Some(&(first, _)) = ps.first() else {
        return runs;
    };
    let mut run = vec![first];
    let n = ps.len();
    let last = if closed && n > 2 { n } else { n - 1 };
    for k in 0..last {
        let next = ps[(k + 1) % n].0;
        if ps[k].1 != 0.0 {
            if run.len() > 1 {
                runs.push(std::mem::take(&mut run));
            }
            run = vec![next];
        } else {
            run.push(next);
        }
    }
    // A lone vertex is a point drawn, as an unclosed one-vertex polyline
    // was read before.
    if run.len() > 1 || (runs.is_empty() && n == 1) {
        runs.push(run);
    }
    runs
}

/// A text's content (formatting stripped) and where it is: the middle of
/// its first letter (as an SVG text's is taken), y up.
fn label(e: &Entity, t: Affine) -> Result<(String, Point)> {
    let h = e.num(40, Some(2.5))?.abs().max(1e-9);
    let (content, at, rot, dx, base_dy) = if e.kind == "TEXT" {
        let content = text_codes(e.value(1).unwrap_or(""));
        let halign = e.flags(72);
        let valign = e.flags(73);
        let at = if halign != 0 || valign != 0 {
            e.point(11).or_else(|_| e.point(10))?
        } else {
            e.point(10)?
        };
        let rot = e.num(50, Some(0.0))?.to_radians();
        let w = width(&content, h);
        let dx = match halign {
            1 | 4 => -w / 2.0,
            2 => -w,
            _ => 0.0,
        };
        let base_dy = match valign {
            2 => -0.5 * h,
            3 => -h,
            _ => 0.0,
        };
        (content, at, rot, dx, base_dy)
    } else {
        // MTEXT: its chunks (3) then its last (1).
        let raw: String = e
            .groups
            .iter()
            .filter(|g| g.code == 3)
            .chain(e.groups.iter().filter(|g| g.code == 1))
            .map(|g| g.value)
            .collect();
        let content = mtext_codes(&raw);
        let at = e.point(10)?;
        let rot = match (e.num(11, Some(0.0))?, e.num(21, Some(0.0))?) {
            (x, y) if x != 0.0 || y != 0.0 => y.atan2(x),
            _ => e.num(50, Some(0.0))?.to_radians(),
        };
        let w = width(&content, h);
        let attach = e.flags(71).clamp(1, 9);
        let dx = match (attach - 1) % 3 {
            1 => -w / 2.0,
            2 => -w,
            _ => 0.0,
        };
        let base_dy = match (attach - 1) / 3 {
            0 => -h,
            1 => -0.5 * h,
            _ => 0.0,
        };
        (content, at, rot, dx, base_dy)
    };
    // The middle of the first letter, above the baseline, in the text's
    // direction.
    let off = Vec2::new(dx + 0.3 * h, base_dy + 0.35 * h);
    let local = Affine::translate(at.to_vec2()) * Affine::rotate(rot) * off.to_point();
    Ok((content.trim().to_string(), t * local))
}

/// About how wide a text of height `h` is (its first line).
fn width(s: &str, h: f64) -> f64 {
    let n = s.lines().next().unwrap_or("").trim().chars().count() as f64;
    0.6 * h * n
}

/// Parse a DXF answer's text into its labels and lines (mm, y down).
pub(crate) fn parse(text: &str) -> Result<Drawing> {
    parse_in(text).map(|(d, _)| d)
}

/// Where a DXF answer's pole is in its file (drawing units, y up), and
/// the file's millimetres per unit: where `check --dxf` draws the
/// overlay. `plan`: the plan the answer was read as (of two plans on one
/// sheet, its pole).
pub fn pole_in_file(text: &str, plan: Option<PlanKind>) -> Result<(Point, f64)> {
    let (d, unit) = parse_in(text)?;
    let pole = super::drawing::pole_of(&d, plan)?;
    Ok((Point::new(pole.x / unit, -pole.y / unit), unit))
}

/// [`parse`], and the file's millimetres per drawing unit.
fn parse_in(text: &str) -> Result<(Drawing, f64)> {
    check_size(text.len() as u64)?;
    if text.as_bytes().starts_with(BINARY) {
        return Err(whole(
            "a binary DXF file: save the drawing as an ASCII DXF (R12 to R2018) to have it checked",
        ));
    }
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    // Blank lines at the end of a file that lacks its EOF are no group.
    let gs = groups(text.trim_end())?;
    let file = read_file(&gs)?;
    let unit = mm_per_unit(file.units)?;
    let mut out = Out {
        labels: Vec::new(),
        lines: Vec::new(),
        placed: 0,
        heads: Vec::new(),
    };
    walk(&file, &file.entities, Affine::IDENTITY, 0, &mut out)?;
    if out.labels.is_empty() && out.lines.is_empty() {
        return Err(whole(
            "the DXF file has no lines and no texts (LINE, LWPOLYLINE, POLYLINE, TEXT, MTEXT) in its ENTITIES: no plan",
        ));
    }
    if out.labels.is_empty() {
        return Err(whole(
            "the DXF file has no texts (TEXT, MTEXT): label the pole p_v (or p_a) and the plan's points beside their vectors' ends",
        ));
    }
    // Drawing units to mm, y up to the drawing's y down.
    let mm = |p: Point| Point::new(p.x * unit, -p.y * unit);
    let d = Drawing {
        labels: out.labels.into_iter().map(|(s, p)| (s, mm(p))).collect(),
        lines: out
            .lines
            .into_iter()
            .map(|l| l.into_iter().map(mm).collect())
            .collect(),
        kind: "dxf",
        heads: out
            .heads
            .into_iter()
            .filter_map(|(ps, line)| {
                let ps: Vec<Point> = ps.into_iter().map(mm).collect();
                let corners = super::arrows::triangle(&ps)?;
                Some(super::arrows::Head::Triangle { corners, line })
            })
            .collect(),
    };
    Ok((d, unit))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An LWPOLYLINE and a TEXT with the extrusion turned over are
    /// mirrored in x; a LINE is in world coordinates; blank lines at the
    /// end are no group.
    #[test]
    fn object_coordinates_turned_over_are_mirrored() {
        let t = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n2\n10\n10\n20\n5\n10\n20\n20\n5\n230\n-1\n\
                 0\nLINE\n10\n10\n20\n5\n11\n20\n21\n5\n230\n-1\n\
                 0\nTEXT\n10\n10\n20\n5\n40\n2\n1\nb\n230\n-1\n0\nENDSEC\n\n\n";
        let d = parse(t).unwrap();
        assert_eq!(d.lines[0], vec![Point::new(-10.0, -5.0), Point::new(-20.0, -5.0)]);
        assert_eq!(d.lines[1], vec![Point::new(10.0, -5.0), Point::new(20.0, -5.0)]);
        assert!(d.labels[0].1.x < -10.0, "{:?}", d.labels[0]);
    }

    #[test]
    fn dxf_is_sniffed() {
        assert!(looks_like_dxf("  0\r\nSECTION\r\n"));
        assert!(looks_like_dxf("999\ncomment\n0\nSECTION\n"));
        assert!(!looks_like_dxf("{\"plan\": 1}"));
        assert!(!looks_like_dxf("<svg/>"));
    }
}
