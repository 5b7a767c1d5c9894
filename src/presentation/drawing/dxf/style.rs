//! What the DXF's parts share: the text style, the ГОСТ 2.303 linetypes
//! and the layers' lineweights, the writing of numbers and text.

/// The text style of every text, named as LibreCAD's ГОСТ 2.304 stroke
/// font (type A) is named: LibreCAD (2.2) takes a text's font from its
/// style's name, case aside, and reads no font file; this one, shipped
/// with it (`lc_opengost-ar.lff`), has Latin, Cyrillic (Ukrainian and
/// Russian) and Greek. Any other name and LibreCAD draws its `standard`
/// font, each Cyrillic or Greek letter a ◊ (issue 40).
pub const STYLE: &str = "lc_opengost-ar";
/// Its font file, for the readers that read it (AutoCAD, KOMPAS, ezdxf):
/// TrueType, Latin, Cyrillic and Greek, the SVG's own font, whose widths
/// the title block's width factors are measured in. LibreCAD ignores it.
pub const FONT_FILE: &str = "DejaVuSans.ttf";

/// The linetypes, after ГОСТ 2.303 (mm; a dash positive, a gap negative,
/// a dot 0), the same periods as the SVG's dash arrays. Their names are
/// the common CAD names of the three kinds (DASHED, DASHDOT, and DIVIDE
/// for dash-dot-dot): a CAD that reads the file's LTYPE table (AutoCAD,
/// KOMPAS, ezdxf) draws these patterns, one that knows linetypes by name
/// only (LibreCAD) draws its own of the same kind rather than a solid
/// line.
pub const LTYPES: [(&str, &str, &[f64]); 3] = [
    ("DASHED", "Dashed (GOST 2.303) __ __ __", &[4.0, -1.5]),
    (
        "DASHDOT",
        "Dash-dot thin (GOST 2.303) ____ . ____ .",
        &[12.0, -1.8, 0.0, -1.8],
    ),
    (
        "DIVIDE",
        "Dash-dot-dot (GOST 2.303) ____ . . ____ . .",
        &[12.0, -1.8, 0.0, -1.8, 0.0, -1.8],
    ),
];

/// A layer's linetype and lineweight (1/100 mm) by its name.
pub fn layer_style(name: &str) -> (&'static str, i32) {
    match name {
        "main" | "vector" => ("Continuous", 50),
        "bold" => ("Continuous", 80),
        "frame" => ("Continuous", 70),
        "dashed" => ("DASHED", 25),
        "dash-dot" => ("DASHDOT", 25),
        "dash-dot-dot" => ("DIVIDE", 25),
        "0" => ("Continuous", -3),
        _ => ("Continuous", 25),
    }
}

/// A number as DXF writes it here: to 0.0001 mm, no trailing zeros.
pub fn num(x: f64) -> String {
    crate::format::fixed(x, 4)
}

/// Text for a DXF string value: UTF-8 as R2007 writes it, no line ends;
/// the tables' turning arrows (↺ U+21BA, ↻ U+21BB), which none of
/// LibreCAD's fonts has, as the closed circle arrows of the same sense
/// (⥀ U+2940, ⥁ U+2941), which its ГОСТ font and DejaVu Sans both have;
/// the structure formula's arrow (→ U+2192, in no arrow of that font) as
/// "->".
pub fn escape(s: &str) -> String {
    s.replace(['\n', '\r'], " ")
        .replace('↺', "⥀")
        .replace('↻', "⥁")
        .replace('→', "->")
}

