//! The DXF file around the entities: the header, the tables (viewport,
//! linetypes, layers, text styles, block records …), the model and paper
//! space blocks and the objects (root dictionary, layouts), with the
//! fixed handles below 0x20: tables 1–A, dictionaries B–F, the paper
//! space's block 18–19, the layouts 1A–1B, the model space's block 1C–1D,
//! the block records 1E (paper) and 1F (model); the symbols' blocks
//! (`blocks`) with handles among the entities'.

use super::blocks::{Block, definitions, records};
use super::entities::W;
use super::style::{FONT_FILE, LTYPES, STYLE, layer_style, num};
use std::fmt::Write as _;

/// A table's head.
fn table(t: &mut W, name: &str, handle: &str, count: usize) {
    t.p(0, "TABLE");
    t.p(2, name);
    t.p(5, handle);
    t.p(330, 0);
    t.p(100, "AcDbSymbolTable");
    t.p(70, count);
}

/// A table record's head, its handle from `d`.
fn record(t: &mut W, d: &mut W, kind: &str, owner: &str, sub: &str, name: &str) {
    let hh = d.h();
    t.p(0, kind);
    t.p(5, hh);
    t.p(330, owner);
    t.p(100, "AcDbSymbolTableRecord");
    t.p(100, sub);
    t.p(2, name);
    t.p(70, 0);
}

/// VPORT, LTYPE, LAYER and STYLE.
fn drawing_tables(tables: &mut W, d: &mut W, (w, h): (f64, f64), layers: &[String]) {
    // VPORT: the sheet in view.
    table(tables, "VPORT", "8", 1);
    record(tables, d, "VPORT", "8", "AcDbViewportTableRecord", "*Active");
    tables.pt(10, (0.0, 0.0));
    tables.pt(11, (1.0, 1.0));
    tables.p(12, num(w / 2.0));
    tables.p(22, num(h / 2.0));
    tables.p(40, num(h * 1.05));
    tables.p(41, num(w / h));
    tables.p(0, "ENDTAB");
    // LTYPE.
    table(tables, "LTYPE", "5", 3 + LTYPES.len());
    for name in ["ByBlock", "ByLayer", "Continuous"] {
        record(tables, d, "LTYPE", "5", "AcDbLinetypeTableRecord", name);
        tables.p(3, if name == "Continuous" { "Solid line" } else { "" });
        tables.p(72, 65);
        tables.p(73, 0);
        tables.p(40, 0);
    }
    for (name, desc, pat) in LTYPES {
        record(tables, d, "LTYPE", "5", "AcDbLinetypeTableRecord", name);
        tables.p(3, desc);
        tables.p(72, 65);
        tables.p(73, pat.len());
        tables.p(40, num(pat.iter().map(|x| x.abs()).sum()));
        for x in pat {
            tables.p(49, num(*x));
            tables.p(74, 0);
        }
    }
    tables.p(0, "ENDTAB");
    // LAYER.
    table(tables, "LAYER", "2", layers.len());
    for l in layers {
        let (lt, wt) = layer_style(l);
        record(tables, d, "LAYER", "2", "AcDbLayerTableRecord", l);
        tables.p(62, 7);
        tables.p(6, lt);
        tables.p(370, wt);
        tables.p(390, "F");
    }
    tables.p(0, "ENDTAB");
    // STYLE.
    table(tables, "STYLE", "3", 2);
    for (name, font) in [("Standard", "txt"), (STYLE, FONT_FILE)] {
        record(tables, d, "STYLE", "3", "AcDbTextStyleTableRecord", name);
        tables.p(40, 0);
        tables.p(41, 1);
        tables.p(50, 0);
        tables.p(71, 0);
        tables.p(42, 2.5);
        tables.p(3, font);
        tables.p(4, "");
    }
    tables.p(0, "ENDTAB");
}

/// VIEW, UCS, APPID, DIMSTYLE and BLOCK_RECORD.
fn other_tables(tables: &mut W, d: &mut W, defs: &[Block]) {
    for (name, handle) in [("VIEW", "6"), ("UCS", "7")] {
        table(tables, name, handle, 0);
        tables.p(0, "ENDTAB");
    }
    table(tables, "APPID", "9", 1);
    record(tables, d, "APPID", "9", "AcDbRegAppTableRecord", "ACAD");
    tables.p(0, "ENDTAB");
    // DIMSTYLE: its records' handles are code 105.
    tables.p(0, "TABLE");
    tables.p(2, "DIMSTYLE");
    tables.p(5, "A");
    tables.p(330, 0);
    tables.p(100, "AcDbSymbolTable");
    tables.p(70, 1);
    tables.p(100, "AcDbDimStyleTable");
    tables.p(71, 0);
    let hh = d.h();
    tables.p(0, "DIMSTYLE");
    tables.p(105, hh);
    tables.p(330, "A");
    tables.p(100, "AcDbSymbolTableRecord");
    tables.p(100, "AcDbDimStyleTableRecord");
    tables.p(2, "Standard");
    tables.p(70, 0);
    tables.p(0, "ENDTAB");
    // BLOCK_RECORD: the model and paper spaces, the symbols' blocks.
    table(tables, "BLOCK_RECORD", "1", 2 + defs.len());
    for (name, handle, layout) in [("*Model_Space", "1F", "1A"), ("*Paper_Space", "1E", "1B")] {
        tables.p(0, "BLOCK_RECORD");
        tables.p(5, handle);
        tables.p(330, 1);
        tables.p(100, "AcDbSymbolTableRecord");
        tables.p(100, "AcDbBlockTableRecord");
        tables.p(2, name);
        tables.p(340, layout);
        tables.p(70, 0);
        tables.p(280, 1);
        tables.p(281, 0);
    }
    records(tables, defs);
    tables.p(0, "ENDTAB");
}

/// The model and paper space blocks, then the symbols'.
fn blocks(defs: &[Block]) -> W {
    let mut blocks = W::new();
    for (name, rec, begin, end, paper) in [
        ("*Model_Space", "1F", "1C", "1D", false),
        ("*Paper_Space", "1E", "18", "19", true),
    ] {
        blocks.p(0, "BLOCK");
        blocks.p(5, begin);
        blocks.p(330, rec);
        blocks.p(100, "AcDbEntity");
        if paper {
            blocks.p(67, 1);
        }
        blocks.p(8, 0);
        blocks.p(100, "AcDbBlockBegin");
        blocks.p(2, name);
        blocks.p(70, 0);
        blocks.pt(10, (0.0, 0.0));
        blocks.p(3, name);
        blocks.p(1, "");
        blocks.p(0, "ENDBLK");
        blocks.p(5, end);
        blocks.p(330, rec);
        blocks.p(100, "AcDbEntity");
        if paper {
            blocks.p(67, 1);
        }
        blocks.p(8, 0);
        blocks.p(100, "AcDbBlockEnd");
    }
    definitions(&mut blocks, defs);
    blocks
}

/// The layout's paper by its ISO name as AutoCAD's PDF plotter writes it
/// (`ISO_A1_(841.00_x_594.00_MM)`), empty for a size not of the A series.
fn paper_name(w: f64, h: f64) -> String {
    let (long, short) = (w.max(h), w.min(h));
    let a = [(1189.0, 841.0), (841.0, 594.0), (594.0, 420.0), (420.0, 297.0), (297.0, 210.0)];
    match a
        .iter()
        .position(|&(l, s)| (l - long).abs() < 0.5 && (s - short).abs() < 0.5)
    {
        Some(i) => format!("ISO_A{i}_({w:.2}_x_{h:.2}_MM)"),
        None => String::new(),
    }
}

/// The root dictionary (C), the groups (D), the layouts (E) with Model
/// (1A) and Layout1 (1B), the plot style names (B, F).
fn objects((w, h): (f64, f64)) -> W {
    let mut objs = W::new();
    let dict = |o: &mut W, handle: &str, owner: &str, items: &[(&str, &str)]| {
        o.p(0, "DICTIONARY");
        o.p(5, handle);
        o.p(330, owner);
        o.p(100, "AcDbDictionary");
        o.p(281, 1);
        for (k, v) in items {
            o.p(3, k);
            o.p(350, v);
        }
    };
    dict(
        &mut objs,
        "C",
        "0",
        &[
            ("ACAD_GROUP", "D"),
            ("ACAD_LAYOUT", "E"),
            ("ACAD_PLOTSTYLENAME", "B"),
        ],
    );
    dict(&mut objs, "D", "C", &[]);
    dict(&mut objs, "E", "C", &[("Layout1", "1B"), ("Model", "1A")]);
    // The plot style names: a dictionary with a default of "Normal".
    objs.p(0, "ACDBDICTIONARYWDFLT");
    objs.p(5, "B");
    objs.p(330, "C");
    objs.p(100, "AcDbDictionary");
    objs.p(281, 1);
    objs.p(3, "Normal");
    objs.p(350, "F");
    objs.p(100, "AcDbDictionaryWithDefault");
    objs.p(340, "F");
    objs.p(0, "ACDBPLACEHOLDER");
    objs.p(5, "F");
    objs.p(330, "B");
    for (name, handle, rec, order) in [("Model", "1A", "1F", 0), ("Layout1", "1B", "1E", 1)] {
        objs.p(0, "LAYOUT");
        objs.p(5, handle);
        objs.p(330, "E");
        objs.p(100, "AcDbPlotSettings");
        objs.p(1, "");
        objs.p(4, if order == 0 { String::new() } else { paper_name(w, h) });
        objs.p(6, "");
        objs.p(40, 0);
        objs.p(41, 0);
        objs.p(42, 0);
        objs.p(43, 0);
        objs.p(44, num(w));
        objs.p(45, num(h));
        objs.p(46, 0);
        objs.p(47, 0);
        objs.p(48, 0);
        objs.p(49, 0);
        objs.p(140, 0);
        objs.p(141, 0);
        objs.p(142, 1);
        objs.p(143, 1);
        objs.p(70, if order == 0 { 1712 } else { 688 });
        objs.p(72, 1);
        objs.p(73, 0);
        objs.p(74, 5);
        objs.p(7, "");
        objs.p(75, 16);
        objs.p(147, 1);
        objs.p(148, 0);
        objs.p(149, 0);
        objs.p(100, "AcDbLayout");
        objs.p(1, name);
        objs.p(70, 1);
        objs.p(71, order);
        objs.pt(10, (0.0, 0.0));
        objs.pt(11, (w, h));
        objs.pt(12, (0.0, 0.0));
        objs.pt(14, (0.0, 0.0));
        objs.pt(15, (w, h));
        objs.p(146, 0);
        objs.pt(13, (0.0, 0.0));
        objs.pt(16, (1.0, 0.0));
        objs.pt(17, (0.0, 1.0));
        objs.p(76, 0);
        objs.p(330, rec);
    }

    objs
}

/// The header, `seed` the first handle not used.
fn header(seed: u32, (w, h): (f64, f64)) -> W {
    let mut head = W::new();
    let var = |o: &mut W, name: &str| o.p(9, name);
    var(&mut head, "$ACADVER");
    head.p(1, "AC1021");
    var(&mut head, "$DWGCODEPAGE");
    head.p(3, "ANSI_1252");
    var(&mut head, "$HANDSEED");
    head.p(5, format!("{seed:X}"));
    var(&mut head, "$INSUNITS");
    head.p(70, 4);
    var(&mut head, "$MEASUREMENT");
    head.p(70, 1);
    var(&mut head, "$LUNITS");
    head.p(70, 2);
    var(&mut head, "$EXTMIN");
    head.pt(10, (0.0, 0.0));
    var(&mut head, "$EXTMAX");
    head.pt(10, (w, h));
    // The model space's limits and the paper space's ($PLIM…, which
    // LibreCAD takes for its page: without them it prints on A4 portrait):
    // the paper.
    for limits in ["$LIM", "$PLIM"] {
        var(&mut head, &format!("{limits}MIN"));
        head.p(10, 0);
        head.p(20, 0);
        var(&mut head, &format!("{limits}MAX"));
        head.p(10, num(w));
        head.p(20, num(h));
    }
    var(&mut head, "$LTSCALE");
    head.p(40, 1);
    var(&mut head, "$PSLTSCALE");
    head.p(70, 0);
    var(&mut head, "$LWDISPLAY");
    head.p(290, 1);
    var(&mut head, "$TEXTSTYLE");
    head.p(7, STYLE);
    var(&mut head, "$CLAYER");
    head.p(8, 0);

    head
}

/// The whole file around the entities.
pub(super) fn document(wh: (f64, f64), layers: &[String], defs: &[Block], ents: W) -> String {
    let mut d = W::new();
    d.next = ents.next;
    let mut tables = W::new();
    drawing_tables(&mut tables, &mut d, wh, layers);
    other_tables(&mut tables, &mut d, defs);
    let blocks = blocks(defs);
    let objs = objects(wh);
    let head = header(d.next + 1, wh);
    let mut out = String::new();
    let section = |out: &mut String, name: &str, body: &str| {
        let _ = write!(out, "  0\nSECTION\n  2\n{name}\n{body}  0\nENDSEC\n");
    };
    section(&mut out, "HEADER", &head.out);
    section(&mut out, "CLASSES", "");
    section(&mut out, "TABLES", &tables.out);
    section(&mut out, "BLOCKS", &blocks.out);
    section(&mut out, "ENTITIES", &ents.out);
    section(&mut out, "OBJECTS", &objs.out);
    out += "  0\nEOF\n";
    out
}

#[cfg(test)]
mod tests {
    use super::paper_name;

    #[test]
    fn layouts_name_their_paper() {
        assert_eq!(paper_name(841.0, 594.0), "ISO_A1_(841.00_x_594.00_MM)");
        assert_eq!(paper_name(210.0, 297.0), "ISO_A4_(210.00_x_297.00_MM)");
        assert_eq!(paper_name(300.0, 200.0), "");
    }
}
