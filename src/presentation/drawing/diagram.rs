//! The kinematic diagrams sheet, as the lecture's Fig. 2.6 draws them: the
//! displacement, velocity-analogue and acceleration-analogue diagrams one
//! above the other, abscissas parallel and ordinate axes on one vertical;
//! divisions 0…N; the chords of each curve; the poles P1, P2 on the
//! abscissas at H1, H2 left of the origin with their rays to the ordinate
//! axis; the ordinates carried to the interval midpoints (velocity) or to
//! the nodes (acceleration) and joined; the analytic curve thin beside.

use super::canvas::{Canvas, Class, Label, SMALL};
use super::table::{number, unit};
use super::{DrawOptions, Sheet, page_svg};
use crate::kinematics::solve::Analysis;
use crate::studies::sheet_data::SheetData;
use crate::studies::diagrams::{DENSE, Diagrams};
use crate::words::catalogue::fill;
use crate::words::construction::Lang;
use kurbo::{Point, Vec2};

/// The gap between two diagrams, mm.
const GAP: f64 = 14.0;

/// The diagrams' sheet.
pub fn sheet(an: &Analysis, d: &Diagrams, opt: &DrawOptions) -> Sheet {
    let c = figure(an, d, opt.lang);
    page_svg(super::SheetKind::Diagrams.stem(), title(an, d, opt.lang), &c, None, opt)
}

/// The sheet's heading: what the diagrams are of, localised.
pub fn title(an: &Analysis, d: &Diagrams, lang: Lang) -> String {
    let m = &an.mech;
    let sym = symbol(an, d);
    let n = d.n;
    let w = &crate::words::catalogue(lang).sheets;
    let what = match (d.point, d.slide) {
        (Some(p), _) => fill(&w.diagram_point, &[("p", m.point_name(p))]),
        (None, true) => fill(&w.diagram_slider, &[("id", m.link_id(d.output))]),
        (None, false) => fill(&w.diagram_link, &[("id", m.link_id(d.output))]),
    };
    let (head, chords) = (&w.diagrams_of, &w.chords);
    format!("{head} {what}: {sym}, {sym}′, {sym}″ (N = {n}, {chords})")
}

/// The coordinate's symbol: s for a slide, φ with the link's number.
fn symbol(an: &Analysis, d: &Diagrams) -> String {
    if d.slide {
        "s".to_string()
    } else {
        format!("φ{}", an.mech.link_id(d.output))
    }
}

/// The three diagrams on one canvas, their scales under them.
pub fn figure(an: &Analysis, d: &Diagrams, lang: Lang) -> Canvas {
    let mut c = Canvas::default();
    let st = Stack::new(an, d, lang);
    let sym = symbol(an, d);
    // The ordinate axis, through all three diagrams.
    c.seg(
        Point::new(0.0, st.bottom),
        Point::new(0.0, st.top),
        Class::Thin,
    );
    c.arrow(Point::new(0.0, st.top), Vec2::new(0.0, 1.0));
    // Displacement: the curve, its points 0, 1′, 2′ … and the chords.
    st.divisions(&mut c, 0, None, &sym);
    st.displacement(&mut c);
    // Velocity analogue: P1's rays parallel to the chords, their ordinates
    // carried to the midpoints, the curve through them.
    st.divisions(&mut c, 1, Some((d.h1, "P1")), &format!("{sym}′"));
    st.velocity(&mut c);
    // Acceleration analogue from the velocity diagram's chords, with P2.
    st.divisions(&mut c, 2, Some((d.h2, "P2")), &format!("{sym}″"));
    st.acceleration(&mut c);
    st.scales(&mut c, &sym);
    c.place_pending();
    c
}

/// The three diagrams stacked: the abscissa's division (mm) and length,
/// the displacements in mm, each diagram's ordinate origin (displacement,
/// velocity, acceleration) and the ordinate axis' ends.
struct Stack<'a> {
    an: &'a Analysis,
    d: &'a Diagrams,
    lang: Lang,
    dx: f64,
    l: f64,
    s_mm: Vec<f64>,
    oy: [f64; 3],
    /// Each diagram's highest ordinate (mm): the upper end of its part of
    /// the ordinate axis, where its name stands.
    ends: [f64; 3],
    top: f64,
    bottom: f64,
}

impl<'a> Stack<'a> {
    fn new(an: &'a Analysis, d: &'a Diagrams, lang: Lang) -> Stack<'a> {
        let dx = d.h / d.mu_phi;
        let l = dx * d.n as f64;
        // Vertical extents of the three curves (mm), for stacking.
        let s_mm: Vec<f64> = d.s.iter().map(|v| v / d.mu_s).collect();
        let ext = |v: &mut dyn Iterator<Item = f64>| {
            v.fold((0.0f64, 0.0f64), |(lo, hi), y| (lo.min(y), hi.max(y)))
        };
        let es = ext(&mut s_mm
            .iter()
            .copied()
            .chain(d.dense.iter().map(|p| p.0 / d.mu_s)));
        let ev = ext(&mut d
            .y1
            .iter()
            .copied()
            .chain(d.dense.iter().map(|p| p.1 / d.mu_v)));
        let ea = ext(&mut d
            .y2
            .iter()
            .copied()
            .chain(d.dense.iter().map(|p| p.2 / d.mu_a)));
        let oy_s = 0.0;
        let oy_v = oy_s + es.0 - GAP - ev.1;
        let oy_a = oy_v + ev.0 - GAP - ea.1;
        Stack {
            an,
            d,
            lang,
            dx,
            l,
            s_mm,
            oy: [oy_s, oy_v, oy_a],
            ends: [oy_s + es.1 + 8.0, oy_v + ev.1 + 4.0, oy_a + ea.1 + 4.0],
            top: oy_s + es.1 + 8.0,
            bottom: oy_a + ea.0 - 4.0,
        }
    }

    /// The abscissa of division `k` (fractional between divisions), mm.
    fn x(&self, k: f64) -> f64 {
        k * self.dx
    }

    /// The analytic curve `f` (mm) of the dense samples over the abscissa
    /// at ordinate origin `oy`.
    fn dense_pts(&self, f: &dyn Fn(&(f64, f64, f64)) -> f64, oy: f64) -> Vec<Point> {
        self.d
            .dense
            .iter()
            .enumerate()
            .map(|(j, p)| Point::new(self.x(j as f64 / DENSE as f64), oy + f(p)))
            .collect()
    }

    /// Diagram `i`'s abscissa with its divisions numbered, its name at the
    /// upper end of its part of the ordinate axis (the abscissa's name at
    /// its arrow, as drawings write axes: at their ends, not the origin)
    /// and, for an analogue, its pole `pole` (distance H, name) left of
    /// the origin.
    fn divisions(&self, c: &mut Canvas, i: usize, pole: Option<(f64, &str)>, name: &str) {
        let (an, d, lang, l) = (self.an, self.d, self.lang, self.l);
        let oy = self.oy[i];
        let n = d.n;
        let left = pole.map(|(h, _)| -h).unwrap_or(0.0) - 4.0;
        c.seg(Point::new(left, oy), Point::new(l + 8.0, oy), Class::Thin);
        c.arrow(Point::new(l + 8.0, oy), Vec2::new(1.0, 0.0));
        let (x_name, x_sub, _) = d.abscissa(an);
        c.label(
            Point::new(l + 8.0, oy),
            Label::new(x_name, x_sub),
            SMALL,
            None,
        );
        let step = n.div_ceil(12);
        for k in 0..=n {
            let p = Point::new(self.x(k as f64), oy);
            c.seg(
                p - Vec2::new(0.0, 1.0),
                p + Vec2::new(0.0, 1.0),
                Class::Thin,
            );
            if k % step == 0 {
                // 0 left of the ordinate axis, which runs through it.
                let dx = if k == 0 { -3.0 } else { -1.0 };
                c.text(
                    p + Vec2::new(dx, -4.5),
                    Label::new(k.to_string(), ""),
                    SMALL,
                    "",
                );
            }
        }
        // The curve's name, the pole and its distance H are placed after
        // the rays and projection lines are drawn, where none crosses them.
        let end = Point::new(0.0, self.ends[i]);
        c.label_later(end, Label::new(name, ""), SMALL, Some(format!("axis-{i}")));
        if let Some((h, pname)) = pole {
            let p = Point::new(-h, oy);
            c.dot(p, pname.to_string());
            c.label_later(p, Label::new("P", &pname[1..]), SMALL, None);
            let mm = unit("mm", lang);
            c.label_later(
                Point::new(-h / 2.0, oy),
                Label::new("H", &pname[1..]).with_tail(format!(" = {} {mm}", number(h, lang))),
                SMALL,
                None,
            );
        }
    }

    /// The displacement curve, its points and chords.
    fn displacement(&self, c: &mut Canvas) {
        let (d, oy_s) = (self.d, self.oy[0]);
        curve(c, &self.dense_pts(&|p| p.0 / d.mu_s, oy_s), Class::Main);
        for k in 0..d.n {
            let (a, b) = (
                Point::new(self.x(k as f64), oy_s + self.s_mm[k]),
                Point::new(self.x(k as f64 + 1.0), oy_s + self.s_mm[k + 1]),
            );
            c.seg(a, b, Class::Thin);
            c.dot(a, format!("s{k}"));
        }
    }

    /// The velocity analogue: P1's rays, the ordinates carried to the
    /// interval midpoints, the curve through them, the analytic one thin.
    fn velocity(&self, c: &mut Canvas) {
        let (d, oy_v) = (self.d, self.oy[1]);
        let mut graphical = Vec::new();
        for (k, &y) in d.y1.iter().enumerate() {
            let on_axis = Point::new(0.0, oy_v + y);
            c.seg(Point::new(-d.h1, oy_v), on_axis, Class::Thin);
            let at = Point::new(self.x(k as f64 + 0.5), oy_v + y);
            c.seg(on_axis, at, Class::Thin);
            c.dot(at, format!("v{k}"));
            graphical.push(at);
        }
        curve(c, &graphical, Class::Main);
        curve(c, &self.dense_pts(&|p| p.1 / d.mu_v, oy_v), Class::Thin);
    }

    /// The acceleration analogue: P2's rays, the ordinates carried to the
    /// nodes, the curve through them, the analytic one thin.
    fn acceleration(&self, c: &mut Canvas) {
        let (d, oy_a, n) = (self.d, self.oy[2], self.d.n);
        let mut graphical = Vec::new();
        for (k, &y) in
            d.y2.iter()
                .enumerate()
                .chain(std::iter::once((n, &d.y2[0])))
        {
            let on_axis = Point::new(0.0, oy_a + y);
            if k < n {
                c.seg(Point::new(-d.h2, oy_a), on_axis, Class::Thin);
            }
            let at = Point::new(self.x(k as f64), oy_a + y);
            c.seg(on_axis, at, Class::Thin);
            c.dot(at, format!("a{k}"));
            graphical.push(at);
        }
        curve(c, &graphical, Class::Main);
        curve(c, &self.dense_pts(&|p| p.2 / d.mu_a, oy_a), Class::Thin);
    }

    /// The scales under the diagrams, as the lecture writes them.
    fn scales(&self, c: &mut Canvas, sym: &str) {
        let (an, d, lang, l) = (self.an, self.d, self.lang, self.l);
        let n = d.n;
        let mm = unit("mm", lang);
        let unit_ = unit(if d.slide { "m" } else { "rad" }, lang);
        let (x, per, span) = if d.stroke {
            let (a, b, _) = d.abscissa(an);
            (a + &b, "m", number(d.h * n as f64, lang))
        } else {
            ("φ".to_string(), "rad", "2π".to_string())
        };
        // Where the abscissa starts: φ1 from the start of the working
        // stroke (node 0), as the lecture's diagrams.
        let dw = &crate::words::catalogue(lang).diagrams;
        let start = if d.stroke {
            String::new()
        } else {
            let angle = number(d.phi0.to_degrees().rem_euclid(360.0), lang);
            format!(",  0: {}", fill(&dw.turn, &[("angle", &angle)]))
        };
        let lines = [
            format!(
                "μ_{sym} = {} {unit_}/{mm},  μ_{x} = {span}/{} = {} {}/{mm}{start}",
                number(d.mu_s, lang),
                number(l, lang),
                number(d.mu_phi, lang),
                unit(per, lang)
            ),
            format!(
                "μ_{sym}′ = μ_{sym}/(H1·μ_{x}) = {} ({unit_}/{})/{mm}",
                number(d.mu_v, lang),
                unit(per, lang)
            ),
            format!(
                "μ_{sym}″ = μ_{sym}′/(H2·μ_{x}) = {} ({unit_}/{}²)/{mm}",
                number(d.mu_a, lang),
                unit(per, lang)
            ),
        ];
        for (i, t) in lines.iter().enumerate() {
            c.rich(
                Point::new(0.0, self.bottom - 8.0 - 5.0 * i as f64),
                t,
                SMALL,
                "",
                "start",
            );
        }
    }
}

/// A polyline through `pts`, segment by segment.
fn curve(c: &mut Canvas, pts: &[Point], class: Class) {
    for w in pts.windows(2) {
        c.seg(w[0], w[1], class);
    }
}

/// Whether the scene asks for the diagrams sheet (`want.drawings` has
/// "diagrams").
pub fn asked(an: &Analysis) -> bool {
    an.mech.scene.want.drawings.iter().any(|w| w == "diagrams")
}

/// The diagrams sheet a scene asks for ([`asked`]): the output of the last
/// group, N = 12 as the lecture draws them, from the diagrams solved in
/// `data` (an internal error where they were not).
pub fn wanted(an: &Analysis, data: &SheetData, opt: &DrawOptions) -> crate::error::Result<Option<Sheet>> {
    if !asked(an) {
        return Ok(None);
    }
    let d = data.diagrams.as_ref().ok_or_else(|| {
        crate::error::Error::Internal(
            "the diagrams sheet needs the diagrams (studies::sheet_data), not given".into(),
        )
    })?;
    Ok(Some(sheet(an, &d.at_length(LENGTH), opt)))
}

/// The abscissa of a revolution, mm.
pub const LENGTH: f64 = 180.0;
