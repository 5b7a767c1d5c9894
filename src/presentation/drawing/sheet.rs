//! A sheet of paper: the format (ГОСТ 2.301, landscape), the frame
//! (ГОСТ 2.104: 20 mm on the left for binding, 5 mm elsewhere), the
//! heading, the main title block (ГОСТ 2.104 form 1, 185 × 55 mm in the
//! bottom right corner) and the fields where figures go. Page coordinates
//! are millimetres from the top left corner, y down; a [`Canvas`] (y up)
//! is placed by the page position of its origin.

use super::SheetSize;
use super::canvas::{Canvas, FONT, SMALL, THIN, fmt, lettering, runs_width, xml};
use crate::words::notation::runs;
use crate::model::scene::SheetInfo;
use crate::words::catalogue::TitleBlockPhrases;
use crate::words::construction::Lang;
use kurbo::{Point, Rect};
use std::fmt::Write as _;

/// The frame's margins, mm: the binding edge and the others.
pub const LEFT: f64 = 20.0;
pub const MARGIN: f64 = 5.0;
/// The main title block, form 1 (ГОСТ 2.104), mm.
pub const BLOCK_W: f64 = 185.0;
pub const BLOCK_H: f64 = 55.0;
/// The band under the frame's top edge that holds a sheet's heading and
/// scale, mm.
pub const HEADING: f64 = 16.0;
/// The clearance between the frame (or a neighbour) and a figure, mm.
pub const PAD: f64 = 6.0;

/// The frame's line: the main line S of ГОСТ 2.303.
const FRAME: f64 = 0.7;

/// A page being composed.
pub struct Page {
    pub size: SheetSize,
    /// Upright (A4 with a title block), else landscape.
    upright: bool,
    body: String,
}

impl Page {
    /// A landscape page of format `size`.
    pub fn new(size: SheetSize) -> Page {
        Page::for_sheet(size, false)
    }

    /// The page of a sheet of format `size`, with or without a title
    /// block: A4 with one upright, its block across the frame's foot
    /// (ГОСТ 2.301, 2.104), every other format landscape.
    pub fn for_sheet(size: SheetSize, title_block: bool) -> Page {
        let upright = upright(size, title_block);
        let (w, h) = page_mm(size, title_block);
        let mut body = String::new();
        let _ = writeln!(
            body,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}mm" height="{h}mm" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, sans-serif">"#
        );
        let _ = writeln!(body, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        let f = frame_of(size, upright);
        let _ = writeln!(
            body,
            r#"<rect class="frame" x="{}" y="{}" width="{}" height="{}" fill="none" stroke="black" stroke-width="{FRAME}"/>"#,
            fmt(f.x0),
            fmt(f.y0),
            fmt(f.width()),
            fmt(f.height())
        );
        Page {
            size,
            upright,
            body,
        }
    }

    /// This page's frame.
    fn frame(&self) -> Rect {
        frame_of(self.size, self.upright)
    }

    /// Raw SVG into the page.
    pub fn push(&mut self, svg: &str) {
        self.body.push_str(svg);
    }

    /// Draw canvas `c` with its box `b` (drawing coordinates; the canvas'
    /// own bounds if `None`) centred in the page rectangle `into`.
    pub fn place(&mut self, c: &Canvas, into: Rect, b: Option<Rect>) {
        let b = b.unwrap_or_else(|| c.bounds());
        let ox = into.center().x - b.center().x;
        // Page y = oy − drawing y: the box's centre goes to the rect's.
        let oy = into.center().y + b.center().y;
        c.write(&mut self.body, ox, oy);
    }

    /// Draw canvas `c` with its origin at page point (`ox`, `oy`).
    pub fn write_canvas(&mut self, c: &Canvas, ox: f64, oy: f64) {
        c.write(&mut self.body, ox, oy);
    }

    /// Draw canvas `c` with the top left corner of its bounds at `at`.
    pub fn place_at(&mut self, c: &Canvas, at: Point) {
        let b = c.bounds();
        c.write(&mut self.body, at.x - b.x0, at.y + b.y1);
    }

    /// The heading in the band under the frame's top: the title, wrapped
    /// to the band's width, and the scale line under it.
    pub fn heading(&mut self, title: &str, scale: Option<&str>) {
        let f = self.frame();
        let mut c = Canvas::default();
        let width = f.width() - 2.0 * PAD;
        // One line if it fits at 5 mm, else a smaller font.
        let size = [5.0, FONT, SMALL]
            .into_iter()
            .find(|&s| super::canvas::runs_width(&crate::words::notation::runs(title), s) <= width)
            .unwrap_or(SMALL);
        c.rich(Point::new(0.0, 0.0), title, size, "heading", "start");
        if let Some(s) = scale {
            c.rich(Point::new(0.0, -7.0), s, FONT, "scale", "start");
        }
        c.write(&mut self.body, f.x0 + PAD, f.y0 + 9.0);
    }

    /// The main title block, form 1, in the frame's bottom right corner.
    pub fn title_block(&mut self, t: &TitleBlock) {
        let f = self.frame();
        let mut b = Block {
            x1: f.x1,
            y1: f.y1,
            s: String::new(),
        };
        b.rules();
        b.fill(t, self.size);
        self.body.push_str(&b.s);
    }

    pub fn finish(mut self) -> String {
        self.body.push_str("</svg>\n");
        self.body
    }
}

/// The main title block being written. Form 1 is given from the block's
/// bottom right corner (`x1`, `y1` on the page): `x` to the left, `y` up.
struct Block {
    x1: f64,
    y1: f64,
    s: String,
}

impl Block {
    /// The page place of the form's (`x`, `y`).
    fn p(&self, x: f64, y: f64) -> (String, String) {
        (fmt(self.x1 - x), fmt(self.y1 - y))
    }

    fn line(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), w: f64) {
        let (a, b) = self.p(x0, y0);
        let (c, d) = self.p(x1, y1);
        let _ = writeln!(
            self.s,
            r#"<line class="title-block" x1="{a}" y1="{b}" x2="{c}" y2="{d}" stroke="black" stroke-width="{}"/>"#,
            fmt(w)
        );
    }

    /// Text `what` (nothing if empty) at the form's (`x`, `y`), in a cell
    /// `width` mm wide; where the sheet's lettering is enlarged (the
    /// course sheets, [`with_lettering`]) at that factor and at least
    /// 3.5 mm. Narrowed to its cell where wider (as ГОСТ 2.304's narrow
    /// type A would write it): the form's column words are 2.5 mm, the
    /// least size of ГОСТ 2.304's series, not 2 mm, on every sheet.
    fn text(
        &mut self,
        (x, y): (f64, f64),
        (size, width): (f64, f64),
        anchor: &str,
        what: &str,
        class: &str,
    ) {
        if what.is_empty() {
            return;
        }
        let k = lettering();
        let size = if k > 1.0 { (size * k).max(3.5) } else { size };
        let (a, b) = self.p(x, y);
        let anchor = if anchor == "start" {
            String::new()
        } else {
            format!(r#" text-anchor="{anchor}""#)
        };
        let narrow = if runs_width(&runs(what), size) > width {
            format!(
                r#" textLength="{}" lengthAdjust="spacingAndGlyphs""#,
                fmt(width)
            )
        } else {
            String::new()
        };
        let _ = writeln!(
            self.s,
            r#"<text class="{class}" x="{a}" y="{b}" font-size="{}"{anchor}{narrow}>{}</text>"#,
            fmt(size),
            xml(what)
        );
    }

    /// The form's lines: main, then thin (the rows of the left part, the
    /// cells of the letter).
    fn rules(&mut self) {
        let main = FRAME;
        for ((x0, y0), (x1, y1)) in [
            ((BLOCK_W, 55.0), (0.0, 55.0)),
            ((BLOCK_W, 55.0), (BLOCK_W, 0.0)),
            ((120.0, 40.0), (0.0, 40.0)),
            ((BLOCK_W, 35.0), (120.0, 35.0)),
            ((50.0, 35.0), (0.0, 35.0)),
            ((BLOCK_W, 30.0), (120.0, 30.0)),
            ((50.0, 20.0), (0.0, 20.0)),
            ((120.0, 15.0), (0.0, 15.0)),
            ((178.0, 55.0), (178.0, 30.0)),
        ] {
            self.line((x0, y0), (x1, y1), main);
        }
        for x in [168.0, 145.0, 130.0, 120.0] {
            self.line((x, 55.0), (x, 0.0), main);
        }
        self.line((50.0, 40.0), (50.0, 0.0), main);
        self.line((35.0, 40.0), (35.0, 20.0), main);
        self.line((18.0, 40.0), (18.0, 20.0), main);
        self.line((30.0, 20.0), (30.0, 15.0), main);
        for y in [50.0, 45.0, 40.0, 25.0, 20.0, 15.0, 10.0, 5.0] {
            self.line((BLOCK_W, y), (120.0, y), THIN);
        }
        self.line((45.0, 35.0), (45.0, 20.0), THIN);
        self.line((40.0, 35.0), (40.0, 20.0), THIN);
    }

    /// The form's words in `t.lang` and its fields from `t`, the format
    /// `size` under the frame.
    fn fill(&mut self, t: &TitleBlock, size: SheetSize) {
        let w = words(t.lang);
        let small = |b: &mut Block, at: (f64, f64), cell: f64, anchor: &str, what: &str| {
            b.text(at, (2.5, cell - 1.0), anchor, what, "title-block");
        };
        // Headings of the columns (baselines 1.5 mm above a 5 mm row's
        // bottom, centred in their cells).
        for ((x, cell), h) in [
            (181.5, 7.0),
            (173.0, 10.0),
            (156.5, 23.0),
            (137.5, 15.0),
            (125.0, 10.0),
        ]
        .into_iter()
        .zip(&w.heads)
        {
            small(self, (x, 31.3), cell, "middle", h);
        }
        let who = [t.author.as_deref(), t.checker.as_deref(), None, None, None];
        for ((y, role), who) in [26.3, 21.3, 16.3, 6.3, 1.3]
            .into_iter()
            .zip(&w.roles)
            .zip(who)
        {
            small(self, (184.0, y), 17.0, "start", role);
            if let Some(n) = who {
                self.text(
                    (167.0, y),
                    (2.5, 21.0),
                    "start",
                    &fit(n, 18),
                    "title-block-field",
                );
            }
        }
        for ((x, width), cell) in [(42.5, 15.0), (26.5, 17.0), (9.0, 18.0)]
            .into_iter()
            .zip(&w.cells)
        {
            small(self, (x, 36.3), width, "middle", cell);
        }
        // "Sheet 1": the sheet column's word and this sheet's number.
        small(
            self,
            (49.0, 16.3),
            20.0,
            "start",
            &format!("{} {}", w.heads[1], t.sheet.0),
        );
        small(
            self,
            (29.0, 16.3),
            29.0,
            "start",
            &format!("{} {}", w.sheets, t.sheet.1),
        );
        // The fields.
        self.text(
            (60.0, 45.5),
            (5.0, 110.0),
            "middle",
            &fit(&t.designation, 30),
            "designation",
        );
        let title = wrap(&t.title, 24, 3);
        for (i, l) in title.iter().enumerate() {
            let n = title.len() as f64;
            let y = 27.5 + 2.6 * (n - 1.0) - 5.2 * i as f64;
            self.text((85.0, y), (3.5, 66.0), "middle", l, "drawing-title");
        }
        self.text(
            (9.0, 26.3),
            (3.5, 16.0),
            "middle",
            &fit(&t.scale, 8),
            "title-block-field",
        );
        // The letter, one a cell from the left of its three 5 mm cells.
        for (i, ch) in t.letter.chars().take(3).enumerate() {
            self.text(
                (47.5 - 5.0 * i as f64, 26.3),
                (3.5, 4.0),
                "middle",
                &ch.to_string(),
                "title-block-field",
            );
        }
        for (i, l) in wrap(&t.organisation, 22, 2).iter().enumerate() {
            self.text(
                (25.0, 9.0 - 4.5 * i as f64),
                (3.5, 46.0),
                "middle",
                l,
                "title-block-field",
            );
        }
        // Under the frame: the format, as ГОСТ 2.104 writes it there.
        self.text(
            (40.0, -3.8),
            (2.5, 40.0),
            "start",
            &format!("{} {size:?}", w.format),
            "title-block",
        );
    }
}

/// Whether a sheet of format `size` stands upright: A4 with a title
/// block (ГОСТ 2.301 and 2.104 put A4 upright, the block across its
/// foot; 185 mm, the block's width, is exactly its frame's).
pub fn upright(size: SheetSize, title_block: bool) -> bool {
    title_block && size == SheetSize::A4
}

/// Width and height of a sheet's page, mm ([`upright`] or landscape).
pub fn page_mm(size: SheetSize, title_block: bool) -> (f64, f64) {
    let (w, h) = size.mm();
    if upright(size, title_block) {
        (h, w)
    } else {
        (w, h)
    }
}

/// The frame's rectangle on a landscape page.
pub fn frame(size: SheetSize) -> Rect {
    frame_of(size, false)
}

/// The frame's rectangle on the page, upright or landscape.
pub fn frame_of(size: SheetSize, upright: bool) -> Rect {
    let (w, h) = page_mm(size, upright);
    Rect::new(LEFT, MARGIN, w - MARGIN, h - MARGIN)
}

/// The main title block's rectangle on the page of a sheet that has one.
pub fn block(size: SheetSize) -> Rect {
    let f = frame_of(size, upright(size, true));
    Rect::new(f.x1 - BLOCK_W, f.y1 - BLOCK_H, f.x1, f.y1)
}

/// The field of a sheet with one figure: inside the frame, below the
/// heading, less `right` mm on the right (a table) and, with a title
/// block, the larger of the rectangles above it and beside it.
pub fn field(size: SheetSize, title_block: bool, right: f64) -> Rect {
    let f = frame_of(size, upright(size, title_block));
    let r = Rect::new(f.x0 + PAD, f.y0 + HEADING, f.x1 - PAD - right, f.y1 - PAD);
    if !title_block {
        return r;
    }
    let b = block(size);
    let above = Rect::new(r.x0, r.y0, r.x1, r.y1.min(b.y0 - PAD));
    let beside = Rect::new(r.x0, r.y0, r.x1.min(b.x0 - PAD), r.y1);
    if above.area() >= beside.area() {
        above
    } else {
        beside
    }
}

/// What the title block says, ready to write.
pub struct TitleBlock {
    pub lang: Lang,
    pub designation: String,
    pub title: String,
    pub author: Option<String>,
    pub checker: Option<String>,
    pub organisation: String,
    pub scale: String,
    /// The letter cells' letters (field 4).
    pub letter: String,
    /// This sheet's number and the number of sheets.
    pub sheet: (usize, usize),
}

impl TitleBlock {
    /// From the scene's `sheet` object, named `name` (the sheet's own
    /// name; the course sheet passes the scene's `sheet.title`).
    pub fn new(info: &SheetInfo, name: &str, lang: Lang, sheet: (usize, usize)) -> TitleBlock {
        TitleBlock {
            lang,
            designation: info.designation.clone().unwrap_or_default(),
            title: name.to_string(),
            author: info.author.clone(),
            checker: info.checker.clone(),
            organisation: info.organisation.clone().unwrap_or_default(),
            scale: info.scale.clone().unwrap_or_else(|| "—".into()),
            letter: info
                .letter
                .clone()
                .unwrap_or_else(|| crate::words::catalogue(lang).title_block.letter.clone()),
            sheet,
        }
    }
}

/// At most `n` characters, an ellipsis marking a cut.
fn fit(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

/// Words wrapped to lines of at most `width` characters, at most `lines`
/// lines (the last cut with an ellipsis).
fn wrap(s: &str, width: usize, lines: usize) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for w in s.split_whitespace() {
        match out.last_mut() {
            Some(l) if l.chars().count() + 1 + w.chars().count() <= width => {
                l.push(' ');
                l.push_str(w);
            }
            _ => out.push(w.to_string()),
        }
    }
    if out.len() > lines {
        let rest = out[lines - 1..].join(" ");
        out.truncate(lines - 1);
        out.push(fit(&rest, width));
    }
    out.into_iter().map(|l| fit(&l, width)).collect()
}

/// The title block's words in `l` (its catalogue's).
fn words(l: Lang) -> &'static TitleBlockPhrases {
    &crate::words::catalogue(l).title_block
}
