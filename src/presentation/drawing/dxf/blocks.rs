//! The sheet's symbols as blocks: each SVG group `<g data-symbol="kind"
//! data-x data-y data-angle>` (a joint, a fixed pivot, a slider block, a
//! centre of mass; canvas `Prim::Symbol`) becomes an INSERT of a block
//! defined in its own coordinates: about the symbol's base point (the
//! joint's centre, the pivot's pair, the block's middle), turned back by
//! its angle. Symbols whose geometry comes out the same share one block
//! (`JOINT`, `PIVOT`, `SLIDER`, `MASS`), another geometry of the same kind
//! is a block of its own (`SLIDER_2`, …), so that every INSERT lands
//! where the SVG drew the symbol. (Symbols hold no text: a text in one
//! would keep the block's upright.)

use super::entities::{Common, Entities, Target, W};
use crate::error::Result;

/// A block definition: its name, what its entities read as (to tell
/// symbols alike), the handles of its record, BLOCK and ENDBLK, and its
/// entities owned by the record.
pub(super) struct Block {
    pub(super) name: String,
    kind: String,
    key: String,
    pub(super) record: String,
    pub(super) begin: String,
    pub(super) end: String,
    pub(super) body: String,
}

/// A symbol of kind `kind` as the INSERT of its block at `base`, turned
/// by `deg` (counter-clockwise); `draw` writes its entities in the block's
/// own coordinates. The block is defined (into `defs`) when no symbol
/// before had the same entities.
pub(super) fn insert_symbol(
    e: &mut Entities,
    defs: &mut Vec<Block>,
    (kind, base, deg): (&str, (f64, f64), f64),
    draw: &dyn Fn(&mut Entities) -> Result<()>,
) -> Result<()> {
    // The symbol's entities as they read, handles from one start.
    let mut probe = Entities {
        w: W::new(),
        owner: "0".into(),
        layers: Vec::new(),
        target: Target::sheet(),
    };
    draw(&mut probe)?;
    let key = probe.w.out;
    let i = match defs.iter().position(|b| b.key == key) {
        Some(i) => i,
        None => {
            let (record, begin) = (e.w.h(), e.w.h());
            let mut body = Entities {
                w: W {
                    out: String::new(),
                    next: e.w.next,
                },
                owner: record.clone(),
                layers: std::mem::take(&mut e.layers),
                target: Target::sheet(),
            };
            draw(&mut body)?;
            e.w.next = body.w.next;
            e.layers = body.layers;
            let end = e.w.h();
            let same = defs.iter().filter(|b| b.kind == kind).count();
            let name = match same {
                0 => kind.to_uppercase(),
                k => format!("{}_{}", kind.to_uppercase(), k + 1),
            };
            defs.push(Block {
                name,
                kind: kind.to_string(),
                key,
                record,
                begin,
                end,
                body: body.w.out,
            });
            defs.len() - 1
        }
    };
    let c = Common {
        layer: kind.to_string(),
        color: None,
        weight: None,
    };
    e.insert(&c, &defs[i].name, base, deg);
    Ok(())
}

/// The block records of the symbols' blocks, after the model and paper
/// spaces' (BLOCK_RECORD table).
pub(super) fn records(t: &mut W, defs: &[Block]) {
    for b in defs {
        t.p(0, "BLOCK_RECORD");
        t.p(5, &b.record);
        t.p(330, 1);
        t.p(100, "AcDbSymbolTableRecord");
        t.p(100, "AcDbBlockTableRecord");
        t.p(2, &b.name);
        t.p(340, 0);
        t.p(70, 0);
        t.p(280, 1);
        t.p(281, 0);
    }
}

/// The symbols' block definitions (BLOCKS section): BLOCK, the entities
/// in the block's coordinates, ENDBLK.
pub(super) fn definitions(out: &mut W, defs: &[Block]) {
    for b in defs {
        out.p(0, "BLOCK");
        out.p(5, &b.begin);
        out.p(330, &b.record);
        out.p(100, "AcDbEntity");
        out.p(8, 0);
        out.p(100, "AcDbBlockBegin");
        out.p(2, &b.name);
        out.p(70, 0);
        out.pt(10, (0.0, 0.0));
        out.p(3, &b.name);
        out.p(1, "");
        out.out += &b.body;
        out.p(0, "ENDBLK");
        out.p(5, &b.end);
        out.p(330, &b.record);
        out.p(100, "AcDbEntity");
        out.p(8, 0);
        out.p(100, "AcDbBlockEnd");
    }
}

#[cfg(test)]
mod tests {
    use super::super::dxf;

    /// A sheet of two joints, a pivot stood on its side and a slider on a
    /// guide at 30°, with a letter.
    const SVG: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">
<g data-symbol="joint" data-x="10" data-y="10">
<circle cx="10" cy="10" r="1.2" fill="white" stroke="black" stroke-width="0.5"/>
</g>
<g data-symbol="joint" data-x="20.5" data-y="30.25">
<circle cx="20.5" cy="30.25" r="1.2" fill="white" stroke="black" stroke-width="0.5"/>
</g>
<g data-symbol="pivot" data-x="50" data-y="25" data-angle="90">
<line class="main" x1="51" y1="24.1" x2="54" y2="22.5" stroke="black" stroke-width="0.5"/>
<circle cx="50" cy="25" r="1.2" fill="white" stroke="black" stroke-width="0.5"/>
</g>
<g data-symbol="slider" data-x="70" data-y="20" data-angle="30">
<polygon points="64.17 24.1 72.83 19.1 75.83 24.3 67.17 29.3" fill="white" stroke="black" stroke-width="0.5"/>
</g>
<text class="label" x="5" y="45" font-size="3.5">A</text>
</svg>"#;

    /// The file's code pairs.
    fn pairs(d: &str) -> Vec<(i32, &str)> {
        let lines: Vec<&str> = d.lines().collect();
        lines
            .chunks(2)
            .map(|p| (p[0].trim().parse().unwrap(), p[1]))
            .collect()
    }

    /// The pairs from the one (`code`, `value`) on up to the next (0, `to`).
    fn part<'a>(ps: &[(i32, &'a str)], code: i32, value: &str, to: &str) -> Vec<(i32, &'a str)> {
        let from = ps.iter().position(|p| *p == (code, value)).unwrap();
        let rest = &ps[from..];
        let end = rest.iter().position(|p| *p == (0, to)).unwrap();
        rest[..end].to_vec()
    }

    /// The values of code `code` in `ps`.
    fn of<'a>(ps: &[(i32, &'a str)], code: i32) -> Vec<&'a str> {
        ps.iter().filter(|p| p.0 == code).map(|p| p.1).collect()
    }

    /// Entities of kind `kind` in `ps`, each as its pairs.
    fn entities<'a>(ps: &[(i32, &'a str)], kind: &str) -> Vec<Vec<(i32, &'a str)>> {
        let mut out: Vec<Vec<(i32, &str)>> = Vec::new();
        let mut inside = false;
        for &p in ps {
            if p.0 == 0 {
                inside = p.1 == kind;
                if inside {
                    out.push(Vec::new());
                }
            } else if inside {
                out.last_mut().unwrap().push(p);
            }
        }
        out
    }

    #[test]
    fn symbols_are_inserts_of_shared_blocks() {
        let d = dxf(SVG).unwrap();
        let ps = pairs(&d);
        let names = ["*Model_Space", "*Paper_Space", "JOINT", "PIVOT", "SLIDER"];
        let blocks = part(&ps, 2, "BLOCKS", "ENDSEC");
        let begins = entities(&blocks, "BLOCK");
        let begun: Vec<&str> = begins.iter().map(|b| of(b, 2)[0]).collect();
        assert_eq!(begun, names);
        let table = part(&ps, 2, "BLOCK_RECORD", "ENDTAB");
        let records = entities(&table, "BLOCK_RECORD");
        assert_eq!(records.iter().map(|r| of(r, 2)[0]).collect::<Vec<_>>(), names);
        // Each block owned by its record.
        for (b, r) in begins.iter().zip(&records) {
            assert_eq!(of(b, 330), of(r, 5));
        }
        let inserts = entities(&part(&ps, 2, "ENTITIES", "ENDSEC"), "INSERT");
        let placed: Vec<(&str, &str, &str, Option<&str>)> = inserts
            .iter()
            .map(|i| (of(i, 2)[0], of(i, 10)[0], of(i, 20)[0], of(i, 50).first().copied()))
            .collect();
        assert_eq!(
            placed,
            [
                ("JOINT", "10", "40", None),
                ("JOINT", "20.5", "19.75", None),
                ("PIVOT", "50", "25", Some("90")),
                ("SLIDER", "70", "30", Some("30")),
            ]
        );
        // The joint's circle about its block's base point.
        let joint = part(&blocks, 2, "JOINT", "ENDBLK");
        let circle = &entities(&joint, "CIRCLE")[0];
        assert_eq!((of(circle, 10), of(circle, 20), of(circle, 330)), (vec!["0"], vec!["0"], of(&records[2], 5)));
    }

    /// mechplan's own reader of answers (check) places the INSERTs' lines
    /// where the SVG drew them: the slider's outline turned by 30°, the
    /// pivot's line by 90°.
    #[test]
    fn the_answers_reader_inserts_them_in_place() {
        let got = crate::grading::dxf::parse(&dxf(SVG).unwrap()).unwrap();
        // The answers' reader turns y down: (x, y − H) of the SVG's.
        let page = |x: f64, y: f64| kurbo::Point::new(x, y - 50.0);
        let want = [
            vec![page(51.0, 24.1), page(54.0, 22.5)],
            vec![page(64.17, 24.1), page(72.83, 19.1), page(75.83, 24.3), page(67.17, 29.3)],
        ];
        assert_eq!(got.lines.len(), 2, "{:?}", got.lines);
        for (l, w) in got.lines.iter().zip(&want) {
            assert!(
                l.len() >= w.len() && w.iter().zip(l).all(|(p, q)| (*p - *q).hypot() < 1e-3),
                "{l:?} not {w:?}"
            );
        }
    }
}
