//! Sheets as bytes: SVG as it is, PNG (resvg), PDF (svg2pdf) one file per
//! sheet and one book of every sheet, and the manifest (`sheets.json`)
//! that says which files a run wrote, so that the next run into the same
//! folder can remove the sheets of its own it no longer draws. Writing
//! them is the front door's (`crate::study`).

use super::{Format, Sheet};
#[cfg(feature = "render")]
pub use render::{pdf, pdf_book, png};
#[cfg(all(feature = "render", feature = "internals"))]
pub use render::tree;
#[cfg(not(feature = "render"))]
pub use unrendered::{pdf, pdf_book, png};

/// The manifest's file name.
pub const MANIFEST: &str = "sheets.json";
/// The PDF book's file name (`--format pdf`).
pub const BOOK: &str = "sheets.pdf";

/// How the manifest of a run (every file written, each sheet's title
/// and scales) starts, before its sheets' entries.
pub const MANIFEST_HEAD: &str = "{\n  \"mechplan\": 1,\n  \"sheets\": [";

/// Sheet `s`'s entry in the manifest, written to `file`, after `listed`
/// others: made and printed on its own (a run of thousands of sheets
/// writes their text as it goes, not a tree of them), indented into the
/// document as the document printed whole is.
pub fn manifest_entry(s: &Sheet, file: &str, listed: usize) -> String {
    let entry = serde_json::to_string_pretty(&sheet_entry(s, file)).unwrap_or_default();
    let lead = if listed == 0 { "\n    " } else { ",\n    " };
    format!("{lead}{}", entry.replace('\n', "\n    "))
}

/// How the manifest of `listed` sheets ends.
pub fn manifest_tail(listed: usize, format: Format) -> String {
    let mut text = String::from(if listed == 0 { "]" } else { "\n  ]" });
    if format == Format::Pdf {
        text += &format!(",\n  \"book\": \"{BOOK}\"");
    }
    text + "\n}\n"
}

/// A sheet's entry in the manifest: its file, title, size, scales and
/// position.
fn sheet_entry(s: &Sheet, file: &str) -> serde_json::Value {
    // A kind of scale the sheet has once is a number; one its figures
    // have at several values (the force panels' μ_l, the course sheet's
    // μ_a of each acceleration plan), a list of them in the order of the
    // figures.
    let mut scales = serde_json::Map::new();
    for (k, v) in &s.scales {
        let all: Vec<f64> = s.scales.iter().filter(|x| x.0 == *k).map(|x| x.1).collect();
        let one = all.iter().all(|x| x == v);
        scales.entry(k.to_string()).or_insert_with(|| match one {
            true => serde_json::json!(v),
            false => serde_json::json!(all),
        });
    }
    let mut sheet = serde_json::json!({
        "file": file,
        "title": s.title,
        "size": format!("{:?}", s.size),
        "scales": scales,
    });
    if let Some(k) = s.position {
        sheet["position"] = serde_json::json!(k);
    }
    sheet
}

/// Rendering with resvg and svg2pdf (the `render` feature).
#[cfg(feature = "render")]
mod render {
    use super::Sheet;
    use crate::error::{Error, Result};

    /// A font database with the system's fonts (DejaVu on the project's machines).
    fn options() -> usvg::Options<'static> {
        let mut o = usvg::Options::default();
        o.fontdb_mut().load_system_fonts();
        o.font_family = "DejaVu Sans".into();
        o
    }

    /// Parse a sheet's SVG with usvg (for PNG, PDF and the rendered checks).
    pub fn tree(svg: &str) -> Result<usvg::Tree> {
        usvg::Tree::from_str(svg, &options())
            .map_err(|e| Error::Internal(format!("the drawing is not valid SVG: {e}")))
    }

    /// Render a sheet to PNG at `dpi`.
    pub fn png(svg: &str, dpi: f64) -> Result<Vec<u8>> {
        let tree = tree(svg)?;
        let size = tree.size();
        // usvg sizes the sheet in CSS pixels (96 per inch).
        let k = (dpi / 96.0) as f32;
        let (pw, ph) = (
            (size.width() * k).ceil() as u32,
            (size.height() * k).ceil() as u32,
        );
        let mut pixmap = tiny_skia::Pixmap::new(pw, ph)
            .ok_or_else(|| Error::structure("the sheet is too large to render"))?;
        resvg::render(
            &tree,
            tiny_skia::Transform::from_scale(k, k),
            &mut pixmap.as_mut(),
        );
        pixmap
            .encode_png()
            .map_err(|e| Error::Internal(format!("PNG encoding failed: {e}")))
    }

    /// Convert a sheet to PDF, at true size: the sheet's SVG is sized in
    /// millimetres, which usvg takes as CSS pixels at 96 per inch; the page
    /// is in points, 72 per inch (svg2pdf's default of 72 dpi made every
    /// page 4/3 too large, and every μ on it wrong when printed at 100 %).
    pub fn pdf(svg: &str) -> Result<Vec<u8>> {
        let tree = tree(svg)?;
        svg2pdf::to_pdf(
            &tree,
            svg2pdf::ConversionOptions::default(),
            svg2pdf::PageOptions { dpi: 96.0 },
        )
        .map_err(|e| Error::Internal(format!("PDF conversion failed: {e}")))
    }

    /// Every sheet as a page of one PDF, each page the size of its sheet:
    /// each sheet becomes a form XObject (svg2pdf) drawn over its page.
    pub fn pdf_book(sheets: &[Sheet]) -> Result<Vec<u8>> {
        use pdf_writer::{Content, Finish, Name, Pdf, Rect, Ref};
        let mut alloc = Ref::new(1);
        let catalog = alloc.bump();
        let tree_id = alloc.bump();
        let mut pdf = Pdf::new();
        let mut pages = Vec::new();
        let mut chunks = Vec::new();
        for s in sheets {
            let t = tree(&s.svg)?;
            // CSS pixels (96 per inch) to points (72 per inch).
            let (w, h) = (t.size().width() * 0.75, t.size().height() * 0.75);
            let (chunk, id) = svg2pdf::to_chunk(&t, svg2pdf::ConversionOptions::default())
                .map_err(|e| Error::Internal(format!("PDF conversion failed: {e}")))?;
            let mut map = std::collections::HashMap::new();
            let chunk = chunk.renumber(|old| *map.entry(old).or_insert_with(|| alloc.bump()));
            let svg_id = map[&id];
            let (page, content) = (alloc.bump(), alloc.bump());
            let mut c = Content::new();
            c.transform([w, 0.0, 0.0, h, 0.0, 0.0]);
            c.x_object(Name(b"S1"));
            pdf.stream(content, &c.finish());
            let mut p = pdf.page(page);
            p.media_box(Rect::new(0.0, 0.0, w, h));
            p.parent(tree_id);
            p.contents(content);
            p.resources().x_objects().pair(Name(b"S1"), svg_id);
            p.finish();
            pages.push(page);
            chunks.push(chunk);
        }
        pdf.catalog(catalog).pages(tree_id);
        pdf.pages(tree_id)
            .kids(pages.iter().copied())
            .count(pages.len() as i32);
        for c in &chunks {
            pdf.extend(c);
        }
        Ok(pdf.finish())
    }
}

/// Without the `render` feature, PNG and PDF are refused by name.
#[cfg(not(feature = "render"))]
mod unrendered {
    use super::Sheet;
    use crate::error::{Error, Result};

    fn refused(format: &str) -> Error {
        Error::scene(
            "format",
            format!("{format} sheets need mechplan built with its `render` feature (on by default); this build writes SVG only"),
        )
    }

    /// Refused: PNG needs the `render` feature.
    pub fn png(_svg: &str, _dpi: f64) -> Result<Vec<u8>> {
        Err(refused("PNG"))
    }

    /// Refused: PDF needs the `render` feature.
    pub fn pdf(_svg: &str) -> Result<Vec<u8>> {
        Err(refused("PDF"))
    }

    /// Refused: PDF needs the `render` feature.
    pub fn pdf_book(_sheets: &[Sheet]) -> Result<Vec<u8>> {
        Err(refused("PDF"))
    }
}
