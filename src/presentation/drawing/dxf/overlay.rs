//! `check --dxf`: a checked answer's overlay written into a copy of the
//! student's own DXF file, on a layer of its own ([`OVERLAY_LAYER`]), so
//! that the teacher returns the marked drawing in the CAD it was drawn in.
//! The copy is the student's bytes unchanged (code page, line ends,
//! handles, everything drawn) with three insertions: the layer's record
//! at the end of the LAYER table, the overlay's entities at the end of the
//! ENTITIES section, and `$HANDSEED` moved past the handles they take
//! (a copy marked before has its old overlay's entities replaced).
//! The entities follow the file's version: R12 and older get no handles
//! and no R13 entities (POLYLINE for LWPOLYLINE, TEXT for MTEXT); texts
//! are in the file's encoding (UTF-8 from R2007 on, else its code page),
//! a letter the code page lacks as a `\U+XXXX` escape. The right plan's
//! shading is left out: a fill added last would cover the student's
//! lines.

use super::entities::{Entities, Target, W};
use crate::error::{Error, Result};

use crate::grading::dxf::OVERLAY_LAYER;

/// The overlay layer's colour (ACI 5, blue): the right plan apart from
/// the student's black lines and the red marks of the wrong points.
const OVERLAY_COLOR: i32 = 5;

/// One code pair of the file: its code, its value (trimmed bytes), the
/// byte offset of its code line's start and the value's (trimmed) bytes.
struct Pair<'a> {
    code: i32,
    value: &'a [u8],
    at: usize,
    value_at: usize,
    value_end: usize,
}

/// The file's code pairs.
fn pairs(b: &[u8]) -> Result<Vec<Pair<'_>>> {
    let mut lines: Vec<(usize, usize)> = Vec::new();
    // A UTF-8 byte order mark (a text editor's) before the first code,
    // which the answer's reader skips too.
    let mut start = if b.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
    for (i, &c) in b.iter().enumerate().skip(start) {
        if c == b'\n' {
            lines.push((start, i));
            start = i + 1;
        }
    }
    if start < b.len() {
        lines.push((start, b.len()));
    }
    let trim = |(s, e): (usize, usize)| -> (usize, usize) {
        let (mut s, mut e) = (s, e);
        while s < e && b[s].is_ascii_whitespace() {
            s += 1;
        }
        while e > s && b[e - 1].is_ascii_whitespace() {
            e -= 1;
        }
        (s, e)
    };
    let mut out = Vec::new();
    for ch in lines.chunks(2) {
        let [code, value] = ch else { break };
        let (cs, ce) = trim(*code);
        if cs == ce {
            // Blank lines at the end of a file without its EOF.
            break;
        }
        let code_num = std::str::from_utf8(&b[cs..ce])
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| {
                Error::Internal(format!(
                    "the answer's DXF has a group code that is no number at byte {cs}"
                ))
            })?;
        let (vs, ve) = trim(*value);
        out.push(Pair {
            code: code_num,
            value: &b[vs..ve],
            at: code.0,
            value_at: vs,
            value_end: ve,
        });
    }
    Ok(out)
}

/// What the copy needs to know of the student's file.
#[derive(Default)]
struct Found {
    version: Option<String>,
    /// The value line of `$HANDSEED`.
    handseed: Option<(usize, usize)>,
    /// The largest handle given (5, 105) or the seed.
    max_handle: u64,
    /// Whether the file's tables and entities have handles (a minimal
    /// R2000 file may have none: its reader numbers them).
    handled: bool,
    /// Where the LAYER table ends (its ENDTAB), and the table's handle.
    layer_end: Option<usize>,
    layer_table: Option<String>,
    layer_there: bool,
    /// The model space's block record, the owner of its entities.
    model_space: Option<String>,
    styles: Vec<String>,
    /// Where the ENTITIES section ends (its ENDSEC).
    entities_end: Option<usize>,
    /// The ENTITIES section left open at the end of a file (no ENDSEC):
    /// where its EOF is, if it has one.
    entities_open: Option<Option<usize>>,
    /// The entities of an overlay added before (a marked copy checked
    /// again): their bytes, from their `0` line to the next one's.
    old_overlay: Vec<(usize, usize)>,
}

fn text(v: &[u8]) -> String {
    String::from_utf8_lossy(v).into_owned()
}

fn scan(ps: &[Pair]) -> Found {
    let mut f = Found::default();
    let (mut section, mut table, mut var) = (String::new(), String::new(), String::new());
    // The handle of the table record (or table) being read.
    let mut handle = String::new();
    // The entity being read in the ENTITIES section: where it starts, and
    // whether it is on the overlay's layer.
    let mut entity: Option<(usize, bool)> = None;
    for (i, p) in ps.iter().enumerate() {
        let v = text(p.value);
        match p.code {
            0 => {
                handle.clear();
                if let Some((s, true)) = entity.take() {
                    f.old_overlay.push((s, p.at));
                }
                if section == "ENTITIES" && v != "ENDSEC" && v != "EOF" {
                    entity = Some((p.at, false));
                }
                match v.as_str() {
                    "SECTION" => section = ps.get(i + 1).map(|q| text(q.value)).unwrap_or_default(),
                    "ENDSEC" => {
                        if section == "ENTITIES" && f.entities_end.is_none() {
                            f.entities_end = Some(p.at);
                        }
                        section.clear();
                    }
                    "TABLE" => table = ps.get(i + 1).map(|q| text(q.value)).unwrap_or_default(),
                    "EOF" if section == "ENTITIES" && f.entities_end.is_none() => {
                        f.entities_open = Some(Some(p.at));
                    }
                    "ENDTAB" => {
                        if table == "LAYER" {
                            f.layer_end = Some(p.at);
                        }
                        table.clear();
                    }
                    _ => {}
                }
            }
            5 | 105 => {
                f.max_handle = f.max_handle.max(u64::from_str_radix(&v, 16).unwrap_or(0));
                handle = v.clone();
                f.handled |= section != "HEADER";
                if section == "HEADER" && var == "$HANDSEED" {
                    f.handseed = Some((p.value_at, p.value_end));
                } else if section == "TABLES"
                    && table == "LAYER"
                    && i.checked_sub(1).is_some_and(|j| ps[j].code == 2)
                {
                    f.layer_table = Some(v);
                }
            }
            9 if section == "HEADER" => var = v,
            8 if entity.is_some() && v.eq_ignore_ascii_case(OVERLAY_LAYER) => {
                entity = entity.map(|(s, _)| (s, true));
            }
            1 if section == "HEADER" && var == "$ACADVER" => f.version = Some(v),
            2 if section == "TABLES" => match table.as_str() {
                "LAYER" if v.eq_ignore_ascii_case(OVERLAY_LAYER) => f.layer_there = true,
                "STYLE" if i.checked_sub(1).is_some_and(|j| ps[j].code != 0) || v != "STYLE" => {
                    f.styles.push(v)
                }
                "BLOCK_RECORD" if v.eq_ignore_ascii_case("*Model_Space") => {
                    f.model_space = Some(handle.clone())
                }
                _ => {}
            },
            _ => {}
        }
    }
    if section == "ENTITIES" && f.entities_end.is_none() && f.entities_open.is_none() {
        f.entities_open = Some(None);
    }
    f
}

/// The student's file `original` with the overlay added: the SVG
/// elements `svg` (a page's coordinates, mm, y down) each point placed in
/// the file by `place`, `scale` the file's units per mm.
pub fn into_copy(
    original: &[u8],
    svg: &str,
    place: &dyn Fn(f64, f64) -> (f64, f64),
    scale: f64,
) -> Result<Vec<u8>> {
    let ps = pairs(original)?;
    let f = scan(&ps);
    // Where the entities go: before the ENTITIES section's ENDSEC; in a
    // file cut short after its entities (which the reader takes), before
    // its EOF or at its end, the section then closed.
    let (end, close) = match (f.entities_end, f.entities_open) {
        (Some(at), _) => (at, ""),
        (None, Some(Some(eof))) => (eof, "  0\nENDSEC\n"),
        (None, Some(None)) => (after_last(original, &ps), "  0\nENDSEC\n  0\nEOF\n"),
        (None, None) => {
            return Err(Error::Internal(
                "the answer's DXF has no ENTITIES section to add the overlay to".into(),
            ));
        }
    };
    // R13 (AC1012) and later have handles, owners and subclass markers;
    // handles only if the file's own have them.
    let version = f.version.clone().unwrap_or_default();
    let legacy = version.as_str() < "AC1012";
    let handles = !legacy && f.handled;
    let style = f
        .styles
        .iter()
        .find(|s| s.eq_ignore_ascii_case("STANDARD"))
        .or(f.styles.first())
        .cloned()
        .unwrap_or_else(|| "STANDARD".into());
    let mut w = W::new();
    w.next = u32::try_from(f.max_handle + 1).unwrap_or(u32::MAX / 2);
    // The layer's record, unless a copy marked before has it.
    let mut layer = W::new();
    if !f.layer_there {
        layer.p(0, "LAYER");
        if handles {
            let h = w.h();
            layer.p(5, h);
            layer.p(330, f.layer_table.clone().unwrap_or_else(|| "0".into()));
        }
        if !legacy {
            layer.p(100, "AcDbSymbolTableRecord");
            layer.p(100, "AcDbLayerTableRecord");
        }
        layer.p(2, OVERLAY_LAYER);
        layer.p(70, 0);
        layer.p(62, OVERLAY_COLOR);
        layer.p(6, if legacy { "CONTINUOUS" } else { "Continuous" });
    }
    let mut e = Entities {
        w,
        owner: f.model_space.clone().unwrap_or_default(),
        layers: Vec::new(),
        target: Target {
            legacy,
            handles,
            ascii: true,
            shading: false,
            style,
            scale,
            layer: Some(OVERLAY_LAYER.into()),
            color: (f.layer_end.is_none() && !f.layer_there).then_some(OVERLAY_COLOR),
        },
    };
    let doc = roxmltree::Document::parse(svg)
        .map_err(|er| Error::Internal(format!("the overlay is not valid SVG: {er}")))?;
    for n in doc.root_element().descendants().filter(|n| n.is_element()) {
        super::element(&mut e, n, (f64::INFINITY, f64::INFINITY), place)?;
    }
    let seed = format!("{:X}", e.w.next);
    // R2007 and later are UTF-8; an older file in UTF-8 (some programs
    // write it) keeps it; else its code page.
    let utf8 = version.as_str() >= "AC1021"
        || (!original.is_ascii() && std::str::from_utf8(original).is_ok());
    let enc = if utf8 {
        encoding_rs::UTF_8
    } else {
        crate::grading::dxf::code_page_encoding(original)
    };
    // The student's line ends (CRLF or LF) in what is added.
    let crlf = original.windows(2).any(|w| w == b"\r\n");
    let ends = |s: &str| -> Vec<u8> {
        let s = if crlf {
            s.replace('\n', "\r\n")
        } else {
            s.to_string()
        };
        encoded(&s, enc)
    };
    let mut added = e.w.out.clone();
    if !close.is_empty() && end > 0 && !original[..end].ends_with(b"\n") {
        added.insert(0, '\n');
    }
    added.push_str(close);
    let mut cuts: Vec<(usize, usize, Vec<u8>)> = vec![(end, end, ends(&added))];
    if let (Some(at), false) = (f.layer_end, f.layer_there) {
        cuts.push((at, at, ends(&layer.out)));
    }
    // A marked copy checked again: its old overlay replaced by the new one
    // (the two verdicts' titles would lie one over the other).
    for &(s, t) in &f.old_overlay {
        cuts.push((s, t, Vec::new()));
    }
    if let Some((s, t)) = f.handseed.filter(|_| handles) {
        cuts.push((s, t, seed.into_bytes()));
    }
    Ok(splice(original, cuts))
}

/// `original` with each cut's bytes (from, to) replaced by its own.
fn splice(original: &[u8], mut cuts: Vec<(usize, usize, Vec<u8>)>) -> Vec<u8> {
    cuts.sort_by_key(|c| c.0);
    let mut out = Vec::with_capacity(original.len() + cuts.iter().map(|c| c.2.len()).sum::<usize>());
    let mut from = 0;
    for (s, t, bytes) in cuts {
        out.extend_from_slice(&original[from..s]);
        out.extend_from_slice(&bytes);
        from = t;
    }
    out.extend_from_slice(&original[from..]);
    out
}

/// Where the line after the file's last code pair starts (the file's
/// end when its last line has no line end: then a line end is added).
fn after_last(b: &[u8], ps: &[Pair]) -> usize {
    let from = ps.last().map_or(0, |p| p.value_end);
    b[from..]
        .iter()
        .position(|&c| c == b'\n')
        .map_or(b.len(), |i| from + i + 1)
}

/// The entities' ASCII text (letters past it as `\U+XXXX`) in the file's
/// encoding `enc`: each escaped letter the encoding has as its bytes, the
/// others left escaped (a CAD reads the escape in any version).
fn encoded(s: &str, enc: &'static encoding_rs::Encoding) -> Vec<u8> {
    let mut out = Vec::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find("\\U+") {
        out.extend_from_slice(&rest.as_bytes()[..i]);
        let tail = &rest[i..];
        let letter = tail
            .get(3..7)
            .and_then(|h| u32::from_str_radix(h, 16).ok())
            .and_then(char::from_u32);
        let bytes = letter.and_then(|c| {
            let mut buf = [0; 4];
            let (b, _, bad) = enc.encode(c.encode_utf8(&mut buf));
            (!bad).then(|| b.into_owned())
        });
        match bytes {
            Some(b) => {
                out.extend_from_slice(&b);
                rest = &tail[7..];
            }
            None => {
                out.extend_from_slice(b"\\");
                rest = &tail[1..];
            }
        }
    }
    out.extend_from_slice(rest.as_bytes());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A line of the overlay (page mm, y down) and a letter.
    const SVG: &str = r#"<svg xmlns="http://www.w3.org/2000/svg"><line x1="0" y1="0" x2="10" y2="-5" stroke="black"/><text x="1" y="1" font-size="3.5">b</text></svg>"#;

    fn copy(original: &str) -> String {
        let bytes = into_copy(original.as_bytes(), SVG, &|x, y| (x, -y), 1.0).unwrap();
        String::from_utf8(bytes).unwrap()
    }

    /// An R2000 file with no TABLES and no handles, as docs/check.md's
    /// example: its reader numbers the entities from 1, so an overlay's
    /// handle 1, 2 … took the student's numbers (ezdxf's audit dropped
    /// the student's lines); and an unknown layer is drawn in the
    /// student's colour, so each entity names the overlay's.
    const BARE: &str = "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nPLAN\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF\n";

    #[test]
    fn a_file_without_handles_gets_an_overlay_without_handles() {
        let c = copy(BARE);
        assert!(c.starts_with(&BARE[..BARE.find("0\nENDSEC\n0\nEOF").unwrap()]));
        let added: Vec<&str> = c[BARE.len() - "0\nENDSEC\n0\nEOF\n".len()..].lines().collect();
        let codes: Vec<&str> = added.iter().step_by(2).map(|l| l.trim()).collect();
        assert!(!codes.contains(&"5") && !codes.contains(&"330"), "{c}");
        assert!(added.contains(&"AcDbEntity"), "{c}");
        // No LAYER table: the colour on each entity.
        let lines = added.iter().filter(|l| **l == "LINE").count();
        let blue = added.windows(2).filter(|w| w[0].trim() == "62" && w[1] == "5").count();
        assert!(lines >= 1 && blue > lines, "{c}");
    }

    /// A UTF-8 byte order mark (which the answer's reader skips) was
    /// read as a group code that is no number: exit 5, no copy.
    #[test]
    fn a_byte_order_mark_is_kept_and_skipped() {
        let c = copy(&format!("\u{FEFF}{BARE}"));
        assert!(c.starts_with('\u{FEFF}') && c.contains("MECHPLAN-CHECK"));
    }

    /// A file cut short after its entities (no ENDSEC, no EOF), which the
    /// reader grades: the section closed after the overlay.
    #[test]
    fn a_file_cut_short_is_closed() {
        let cut = &BARE[..BARE.find("0\nENDSEC\n0\nEOF").unwrap()];
        let c = copy(cut);
        assert!(c.starts_with(cut) && c.ends_with("  0\nENDSEC\n  0\nEOF\n"), "{c}");
        let no_eol = cut.trim_end();
        let c = copy(no_eol);
        assert!(c.starts_with(&format!("{no_eol}\n  0\n")), "{c}");
        let eof = format!("{cut}0\nEOF\n");
        assert!(copy(&eof).ends_with("  0\nENDSEC\n0\nEOF\n"));
    }

    /// A marked copy checked again: the old overlay replaced, not a second
    /// one (and a second verdict) over it.
    #[test]
    fn a_copy_marked_again_has_one_overlay() {
        let once = copy(BARE);
        assert_eq!(copy(&once), once);
        let handled = "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$HANDSEED\n5\n30\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n5\n2F\n8\nPLAN\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF\n";
        let once = copy(handled);
        let twice = copy(&once);
        let count = |s: &str| s.matches("MECHPLAN-CHECK").count();
        assert_eq!(count(&twice), count(&once), "{twice}");
        assert!(twice.contains("\n2F\n8\nPLAN\n"));
    }

    #[test]
    fn escaped_letters_take_the_code_page() {
        let s = "v \\U+2014 \\U+0431 \\U+03BC";
        assert_eq!(
            encoded(s, encoding_rs::WINDOWS_1251),
            b"v \x97 \xE1 \\U+03BC".to_vec()
        );
        assert_eq!(
            encoded(s, encoding_rs::UTF_8),
            "v \u{2014} \u{431} \u{3BC}".as_bytes().to_vec()
        );
    }
}
