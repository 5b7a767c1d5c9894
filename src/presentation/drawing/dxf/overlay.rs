//! `check --dxf`: a checked answer's overlay written into a copy of the
//! student's own DXF file, on a layer of its own ([`OVERLAY_LAYER`]), so
//! that the teacher returns the marked drawing in the CAD it was drawn in.
//! The copy is the student's bytes unchanged (code page, line ends,
//! handles, everything drawn) with three insertions: the layer's record
//! at the end of the LAYER table, the overlay's entities at the end of the
//! ENTITIES section, and `$HANDSEED` moved past the handles they take.
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
    let mut start = 0;
    for (i, &c) in b.iter().enumerate() {
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
    /// Where the LAYER table ends (its ENDTAB), and the table's handle.
    layer_end: Option<usize>,
    layer_table: Option<String>,
    layer_there: bool,
    /// The model space's block record, the owner of its entities.
    model_space: Option<String>,
    styles: Vec<String>,
    /// Where the ENTITIES section ends (its ENDSEC).
    entities_end: Option<usize>,
}

fn text(v: &[u8]) -> String {
    String::from_utf8_lossy(v).into_owned()
}

fn scan(ps: &[Pair]) -> Found {
    let mut f = Found::default();
    let (mut section, mut table, mut var) = (String::new(), String::new(), String::new());
    // The handle of the table record (or table) being read.
    let mut handle = String::new();
    for (i, p) in ps.iter().enumerate() {
        let v = text(p.value);
        match p.code {
            0 => {
                handle.clear();
                match v.as_str() {
                    "SECTION" => section = ps.get(i + 1).map(|q| text(q.value)).unwrap_or_default(),
                    "ENDSEC" => {
                        if section == "ENTITIES" && f.entities_end.is_none() {
                            f.entities_end = Some(p.at);
                        }
                        section.clear();
                    }
                    "TABLE" => table = ps.get(i + 1).map(|q| text(q.value)).unwrap_or_default(),
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
    let Some(end) = f.entities_end else {
        return Err(Error::Internal(
            "the answer's DXF has no end of its ENTITIES section to add the overlay to".into(),
        ));
    };
    // R13 (AC1012) and later have handles, owners and subclass markers.
    let version = f.version.clone().unwrap_or_default();
    let legacy = version.as_str() < "AC1012";
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
        if !legacy {
            let h = w.h();
            layer.p(5, h);
            layer.p(330, f.layer_table.clone().unwrap_or_else(|| "0".into()));
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
            ascii: true,
            shading: false,
            style,
            scale,
            layer: Some(OVERLAY_LAYER.into()),
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
    let mut cuts: Vec<(usize, usize, Vec<u8>)> = vec![(end, end, ends(&e.w.out))];
    if let (Some(at), false) = (f.layer_end, f.layer_there) {
        cuts.push((at, at, ends(&layer.out)));
    }
    if let Some((s, t)) = f.handseed.filter(|_| !legacy) {
        cuts.push((s, t, seed.into_bytes()));
    }
    cuts.sort_by_key(|c| c.0);
    let mut out = Vec::with_capacity(original.len() + e.w.out.len() + 256);
    let mut from = 0;
    for (s, t, bytes) in cuts {
        out.extend_from_slice(&original[from..s]);
        out.extend_from_slice(&bytes);
        from = t;
    }
    out.extend_from_slice(&original[from..]);
    Ok(out)
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
