//! `draw --format dxf` read back by another program: the six-link with its
//! course sheet, its diagrams sheet with title blocks, the shaper (uk), the compressor (ru) and the six-link with
//! dynamics (force sheets, the lever, the course force sheet) drawn as SVG
//! and as DXF, and tests/dxf_check.py (ezdxf) holding every DXF sheet to
//! its SVG twin: no audit error, millimetres, within the paper, every text
//! (string, height, layer, place to 0.01 mm), every line (the plans'
//! vectors: the plan points), circle and arrowhead.
//!
//! Needs python3 with ezdxf: the system's, else installed by pip into
//! target/pydeps (tests/common); without them the test fails.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

fn draw(args: &[&str], out: &Path) {
    let _ = std::fs::remove_dir_all(out);
    let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
        .arg("draw")
        .args(args)
        .arg("-o")
        .arg(out)
        .output()
        .expect("mechplan runs");
    assert!(
        o.status.success(),
        "mechplan draw {args:?} failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn dxf_sheets_match_their_svg_twins() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base: PathBuf = std::env::temp_dir().join(format!("mechplan-dxf-{}", std::process::id()));
    // The diagrams sheet and the title block on every sheet.
    std::fs::create_dir_all(&base).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("fixtures/six_link_fig2_10.json")).unwrap(),
    )
    .unwrap();
    v["want"]["drawings"] = serde_json::json!(["mechanism", "velocity", "diagrams"]);
    let diagrams = base.join("diagrams.json");
    std::fs::write(&diagrams, v.to_string()).unwrap();
    let diagrams = diagrams.display().to_string();
    let cases: [(&str, &[&str]); 5] = [
        ("diagrams", &[diagrams.as_str(), "--title-block"]),
        ("six_link", &["fixtures/six_link_fig2_10.json", "--course"]),
        (
            "shaper_uk",
            &["fixtures/shaper_fig2_11.json", "--lang", "uk"],
        ),
        (
            "compressor_ru",
            &["fixtures/compressor_fig2_12.json", "--lang", "ru"],
        ),
        (
            "dynamics",
            &["fixtures/dynamics/six_link_fig2_10.json", "--course"],
        ),
    ];
    for (name, args) in cases {
        let args: Vec<String> = args
            .iter()
            .map(|a| {
                if a.ends_with(".json") && !Path::new(a).is_absolute() {
                    root.join(a).display().to_string()
                } else {
                    a.to_string()
                }
            })
            .collect();
        let mut args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (svg, dxf) = (
            base.join(format!("{name}-svg")),
            base.join(format!("{name}-dxf")),
        );
        draw(&args, &svg);
        args.extend(["--format", "dxf"]);
        draw(&args, &dxf);
        let manifest = std::fs::read_to_string(dxf.join("sheets.json")).unwrap();
        assert!(
            manifest.contains(".dxf\""),
            "{name}: sheets.json lists the DXF sheets"
        );
        let out = held_to_twins(name, &svg, &dxf);
        eprint!("{out}");
        // Every run draws the mechanism: its joints are blocks.
        let symbols: usize = out
            .split(" symbols")
            .next()
            .and_then(|s| s.rsplit(' ').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or(0);
        assert!(symbols > 0, "{name}: no symbol checked as a block: {out}");
    }
    let _ = std::fs::remove_dir_all(&base);
}

/// The example of docs/sheets.md ("An example: a vector of a plan"): the
/// four-bar's velocity plan at position 1 holds those four entities as
/// the page shows them, but for their handles (5) and owners (330).
#[test]
fn the_documented_dxf_sheet_excerpt_is_what_draw_writes() {
    let excerpt = common::dxf_block("docs/sheets.md");
    let out = std::env::temp_dir().join(format!("mechplan-dxf-doc-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    draw(
        &[
            "fixtures/four_bar.json",
            "--format",
            "dxf",
            "--position",
            "1",
        ],
        &out,
    );
    let file = std::fs::read_to_string(out.join("velocity_1.dxf")).unwrap();
    // Entities as lists of (code, value), handles and owners left out.
    let entities = |text: &str| -> Vec<Vec<(i32, String)>> {
        let mut all: Vec<Vec<(i32, String)>> = Vec::new();
        for (c, v) in pairs(text) {
            if c == 0 {
                all.push(Vec::new());
            }
            if c != 5
                && c != 330
                && let Some(e) = all.last_mut()
            {
                e.push((c, v));
            }
        }
        all
    };
    let written = entities(&file);
    let shown = entities(&excerpt);
    assert_eq!(shown.len(), 4);
    for e in &shown {
        assert!(written.contains(e), "not in velocity_2.dxf: {e:?}");
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// Issue #28's first proof over the whole gallery (docs/gallery/make.sh):
/// every fixture's sheets at position 1 (the positions sheet, the
/// mechanism, the plans), every dynamics fixture's sheets at position 3 (else 1)
/// (force sheets, the lever) and the six-link's in Ukrainian, the
/// boom's course sheet, the instant centres, the kinematic diagrams and
/// the Frenet figures, each written as SVG and as DXF and held to its
/// twin by tests/dxf_check.py.
#[test]
fn every_gallery_sheet_reads_back_as_its_svg_twin() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base: PathBuf =
        std::env::temp_dir().join(format!("mechplan-dxf-gallery-{}", std::process::id()));
    let mut cases: Vec<(String, Vec<String>)> = Vec::new();
    let fixture = |f: &str| root.join(f).display().to_string();
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(root.join("fixtures"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 13);
    for p in &scenes {
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        let args = vec![
            "draw".into(),
            p.display().to_string(),
            "--position".into(),
            "1".into(),
        ];
        cases.push((name, args));
    }
    for f in [
        "arm_two_cylinders",
        "compressor_fig2_12",
        "shaper_fig2_11",
        "worked_slider_crank",
    ] {
        let args = vec![
            "draw".into(),
            fixture(&format!("fixtures/dynamics/{f}.json")),
            "--position".into(),
            // Position 3 as the gallery's force sheets, where there is one.
            if f == "worked_slider_crank" { "1" } else { "3" }.into(),
        ];
        cases.push((format!("dynamics-{f}"), args));
    }
    let more: [(&str, &[&str]); 5] = [
        (
            "six_link_uk",
            &[
                "draw",
                "fixtures/dynamics/six_link_fig2_10.json",
                "--lang",
                "uk",
                "--position",
                "2",
            ],
        ),
        (
            "boom_course",
            &["draw", "fixtures/boom_cylinder.json", "--course"],
        ),
        (
            "centres",
            &[
                "draw",
                "fixtures/four_bar.json",
                "--centres",
                "--position",
                "5",
            ],
        ),
        (
            "diagrams",
            &["diagram", "fixtures/offset_slider_crank.json"],
        ),
        ("frenet", &["frenet"]),
    ];
    for (name, args) in more {
        let args = args
            .iter()
            .map(|a| {
                if a.ends_with(".json") {
                    fixture(a)
                } else {
                    a.to_string()
                }
            })
            .collect();
        cases.push((name.into(), args));
    }
    let mut sheets = 0;
    for (name, args) in &cases {
        let (svg, dxf) = (
            base.join(format!("{name}-svg")),
            base.join(format!("{name}-dxf")),
        );
        for (out, extra) in [(&svg, vec![]), (&dxf, vec!["--format", "dxf"])] {
            let o = Command::new(env!("CARGO_BIN_EXE_mechplan"))
                .args(args)
                .args(extra)
                .arg("-o")
                .arg(out)
                .output()
                .expect("mechplan runs");
            assert!(
                o.status.success(),
                "mechplan {args:?}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
        }
        sheets += std::fs::read_dir(&dxf)
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .unwrap()
                    .path()
                    .extension()
                    .is_some_and(|x| x == "dxf")
            })
            .count();
        held_to_twins(name, &svg, &dxf);
    }
    assert!(sheets >= 80, "{sheets} sheets");
    let _ = std::fs::remove_dir_all(&base);
}

/// The DXF sheets in `dxf` held to their SVG twins in `svg` by
/// tests/dxf_check.py (ezdxf): its report, or a panic naming `name` and
/// what differs.
fn held_to_twins(name: &str, svg: &Path, dxf: &Path) -> String {
    let o = common::python_with_ezdxf()
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/dxf_check.py"))
        .arg(svg)
        .arg(dxf)
        .output()
        .expect("python3 runs");
    assert!(
        o.status.success(),
        "{name}: the DXF sheets differ from the SVG ones:\n{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A DXF file's code pairs.
fn pairs(d: &str) -> Vec<(i32, String)> {
    let lines: Vec<&str> = d.lines().collect();
    lines
        .chunks(2)
        .map(|p| (p[0].trim().parse().unwrap(), p[1].to_string()))
        .collect()
}

/// The entities of kind `kind` between (2, `section`) and the next ENDSEC,
/// each as its pairs.
fn entities(ps: &[(i32, String)], section: &str, kind: &str) -> Vec<Vec<(i32, String)>> {
    let from = ps.iter().position(|p| p.0 == 2 && p.1 == section).unwrap();
    let mut out: Vec<Vec<(i32, String)>> = Vec::new();
    let mut inside = false;
    for p in &ps[from..] {
        if p.0 == 0 {
            if p.1 == "ENDSEC" {
                break;
            }
            inside = p.1 == kind;
            if inside {
                out.push(Vec::new());
            }
        } else if inside {
            out.last_mut().unwrap().push(p.clone());
        }
    }
    out
}

fn value(e: &[(i32, String)], code: i32) -> Option<&str> {
    e.iter().find(|p| p.0 == code).map(|p| p.1.as_str())
}

/// The mechanism's symbols (ГОСТ 2.770: moving joints, fixed pivots, slider
/// blocks, centres of mass) are blocks: each symbol the SVG groups
/// (`g data-symbol`) is one INSERT, on the layer of its kind, at the
/// group's base point, of a block the file defines (BLOCK_RECORD, BLOCK);
/// all the joints of a sheet are one block, `JOINT`, and all its pivots
/// standing square (up, down, on a side) one block turned. Without Python: tests/dxf_check.py also checks
/// where the inserted geometry lands.
#[test]
fn joints_and_sliders_are_blocks() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = std::env::temp_dir().join(format!("mechplan-dxf-blocks-{}", std::process::id()));
    let fixture = root.join("fixtures/six_link_fig2_10.json");
    let fixture = fixture.to_str().unwrap();
    let (svg, dxf) = (base.join("svg"), base.join("dxf"));
    draw(&[fixture], &svg);
    draw(&[fixture, "--format", "dxf"], &dxf);
    let mut joints = 0;
    // The six-link's twelve positions, numbered from 0 as its sheets are.
    for k in 0..12 {
        let s = std::fs::read_to_string(svg.join(format!("mechanism_{k}.svg"))).unwrap();
        let d = std::fs::read_to_string(dxf.join(format!("mechanism_{k}.dxf"))).unwrap();
        let doc = roxmltree::Document::parse(&s).unwrap();
        let groups: Vec<roxmltree::Node> = doc
            .descendants()
            .filter(|n| n.has_tag_name("g") && n.attribute("data-symbol").is_some())
            .collect();
        let ps = pairs(&d);
        let inserts = entities(&ps, "ENTITIES", "INSERT");
        let defined: Vec<String> = entities(&ps, "BLOCKS", "BLOCK")
            .iter()
            .map(|b| value(b, 2).unwrap().to_string())
            .collect();
        let records: Vec<String> = entities(&ps, "TABLES", "BLOCK_RECORD")
            .iter()
            .map(|b| value(b, 2).unwrap().to_string())
            .collect();
        assert_eq!(
            inserts.len(),
            groups.len(),
            "mechanism_{k}: one INSERT a symbol"
        );
        for kind in ["joint", "pivot", "slider"] {
            assert!(
                groups
                    .iter()
                    .any(|g| g.attribute("data-symbol") == Some(kind)),
                "mechanism_{k}: no {kind} drawn"
            );
        }
        let mut square: Option<String> = None;
        for (g, i) in groups.iter().zip(&inserts) {
            let kind = g.attribute("data-symbol").unwrap();
            let name = value(i, 2).unwrap();
            assert!(name.starts_with(&kind.to_uppercase()), "{kind} as {name}");
            assert!(
                defined.iter().any(|b| b == name),
                "mechanism_{k}: {name} not defined"
            );
            assert!(
                records.iter().any(|b| b == name),
                "mechanism_{k}: {name} has no record"
            );
            assert_eq!(value(i, 8), Some(kind));
            let h = 210.0;
            let at = |c: i32| value(i, c).unwrap().parse::<f64>().unwrap();
            let x: f64 = g.attribute("data-x").unwrap().parse().unwrap();
            let y: f64 = g.attribute("data-y").unwrap().parse().unwrap();
            assert!((at(10) - x).abs() < 1e-6 && (at(20) - (h - y)).abs() < 1e-6);
            if kind == "joint" {
                assert_eq!(name, "JOINT", "mechanism_{k}: every joint is one block");
                joints += 1;
            }
            // Pivots standing up, down or on their sides: one block turned.
            if kind == "pivot"
                && [None, Some("90"), Some("180"), Some("270")].contains(&g.attribute("data-angle"))
            {
                let first = square.get_or_insert_with(|| name.to_string());
                assert_eq!(
                    name, first,
                    "mechanism_{k}: the square pivots are one block"
                );
            }
        }
    }
    assert!(joints >= 12 * 4, "{joints} joints");
    let _ = std::fs::remove_dir_all(&base);
}

/// The style LibreCAD draws Cyrillic and Greek in (issue 40). LibreCAD
/// (2.2) takes a text's font from its style's *name*, case aside, and
/// reads no TrueType file: every text of a sheet is in the style
/// `lc_opengost-ar`, the name of the ГОСТ 2.304 stroke font LibreCAD ships
/// (`lc_opengost-ar.lff`), whose font file for the other readers (AutoCAD,
/// KOMPAS, ezdxf) is `DejaVuSans.ttf`; `$TEXTSTYLE` is it too. Then,
/// independently of the writer: where LibreCAD's fonts are on the machine
/// (Debian's `librecad-data`), that font has a glyph for every character
/// the shaper's Ukrainian and Russian DXF sheets (with dynamics and the
/// course sheets) write; without it, that half is skipped with a note.
/// No font file is copied into the repository.
#[test]
fn texts_are_in_the_style_named_as_librecads_gost_font() {
    const FONT: &str = "lc_opengost-ar";
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = std::env::temp_dir().join(format!("mechplan-dxf-font-{}", std::process::id()));
    let fixture = root.join("fixtures/dynamics/shaper_fig2_11.json");
    let fixture = fixture.to_str().unwrap();
    let mut used = std::collections::BTreeMap::<char, String>::new();
    let mut texts = 0;
    for lang in ["uk", "ru"] {
        let out = base.join(lang);
        draw(
            &[fixture, "--course", "--lang", lang, "--format", "dxf"],
            &out,
        );
        let mut sheets: Vec<PathBuf> = std::fs::read_dir(&out)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "dxf"))
            .collect();
        sheets.sort();
        assert!(sheets.len() > 3, "{lang}: {} DXF sheets", sheets.len());
        for sheet in &sheets {
            let name = format!("{lang}/{}", sheet.file_name().unwrap().to_string_lossy());
            let ps = pairs(&std::fs::read_to_string(sheet).unwrap());
            let styles = entities(&ps, "TABLES", "STYLE");
            let ours = styles
                .iter()
                .find(|s| value(s, 2) == Some(FONT))
                .unwrap_or_else(|| panic!("{name}: no text style {FONT}"));
            assert_eq!(value(ours, 3), Some("DejaVuSans.ttf"), "{name}");
            let at = ps.iter().position(|p| p.0 == 9 && p.1 == "$TEXTSTYLE");
            assert_eq!(
                at.map(|i| ps[i + 1].1.as_str()),
                Some(FONT),
                "{name}: $TEXTSTYLE"
            );
            for kind in ["TEXT", "MTEXT"] {
                for e in entities(&ps, "ENTITIES", kind)
                    .iter()
                    .chain(&entities(&ps, "BLOCKS", kind))
                {
                    assert_eq!(value(e, 7), Some(FONT), "{name}: a {kind}'s style");
                    texts += 1;
                    let s: String = e
                        .iter()
                        .filter(|p| p.0 == 1 || p.0 == 3)
                        .map(|p| p.1.as_str())
                        .collect();
                    let s = if kind == "MTEXT" { mtext_text(&s) } else { s };
                    for c in s.chars().filter(|c| !c.is_whitespace()) {
                        used.entry(c).or_insert_with(|| format!("{name}: {s}"));
                    }
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&base);
    assert!(texts > 100, "{texts} texts");
    for c in ['ї', 'є', 'і', 'ы', 'μ', 'φ', 'ω'] {
        assert!(used.contains_key(&c), "no {c} on the sheets: {used:?}");
    }
    let Some(lff) = [
        "/usr/share/librecad/fonts",
        "/usr/local/share/librecad/fonts",
    ]
    .iter()
    .map(|d| Path::new(d).join(format!("{FONT}.lff")))
    .find(|p| p.is_file()) else {
        eprintln!(
            "skipped: LibreCAD's {FONT}.lff is not on this machine \
             (apt-get install librecad-data): the glyphs are not checked"
        );
        return;
    };
    // A glyph of an .lff starts with a line `[XXXX]`, its code point in hex.
    let glyphs: std::collections::BTreeSet<char> = std::fs::read_to_string(&lff)
        .unwrap()
        .lines()
        .filter_map(|l| l.strip_prefix('[')?.split_once(']'))
        .filter_map(|(hex, _)| u32::from_str_radix(hex.trim_start_matches('#'), 16).ok())
        .filter_map(char::from_u32)
        .collect();
    assert!(
        glyphs.len() > 300,
        "{}: {} glyphs",
        lff.display(),
        glyphs.len()
    );
    let missing: Vec<String> = used
        .iter()
        .filter(|(c, _)| !glyphs.contains(c))
        .map(|(c, at)| format!("{c} (U+{:04X}, in {at})", *c as u32))
        .collect();
    assert!(
        missing.is_empty(),
        "{} has no glyph for {} character(s) the sheets write, LibreCAD draws each as ◊:\n{}",
        lff.display(),
        missing.len(),
        missing.join("\n")
    );
}

/// What an MTEXT's content prints: its stacks (`\Sn^KC;`, `\S^v;`) as
/// their characters, `\\`, `\{`, `\}` as the character escaped.
fn mtext_text(s: &str) -> String {
    let mut out = String::new();
    let mut it = s.chars();
    let mut stack = false;
    while let Some(c) = it.next() {
        match c {
            '\\' => match it.next() {
                Some('S') => stack = true,
                Some(x) => out.push(x),
                None => {}
            },
            '^' if stack => {}
            ';' if stack => stack = false,
            _ => out.push(c),
        }
    }
    out
}
