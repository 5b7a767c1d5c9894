//! A force plan's overlay (`check --svg` of a `"plan": "force"` answer;
//! docs/check.md, "The overlay"): the right force polygon at the
//! student's μ_F, pale, as the force sheets draw it
//! ([`force_polygon::draw`]); over it each vector the answer gives with a
//! length (a segment, or a value at μ_F) and a direction, drawn from the
//! right plan's point it starts from at the student's length and
//! direction — green where its items are right, red where one is wrong
//! (with its tolerance circle about the right vector's end), grey where
//! they are not judged —, each named with a star; the items written
//! wrong that no vector shows; the report's diagnosis; and a legend.
//! Everything drawn is read from the [`ForceReport`]: nothing is solved.

use crate::grading::forces::ForceReport;
use crate::grading::{Judgement, Verdict};
use crate::kinetostatics::force_plan::Force;
use crate::presentation::drawing::canvas::{Canvas, Class, Prim, SMALL, THIN, wrap};
use crate::presentation::drawing::{DrawOptions, force_polygon, page_svg, reduction, table};
use crate::presentation::gradebook::items_wrong;
use crate::presentation::overlay::WRONG_INK;
use crate::words::catalogue::CheckPhrases;
use crate::words::check::{self, fill};
use crate::words::numbers;
use kurbo::{Point, Vec2};

/// The ink of a student's vector whose items are right.
pub const RIGHT_INK: &str = "#1a7f2e";
/// The ink of a student's vector not judged (too small, or fitting a
/// typical mistake as well).
pub const UNDECIDED_INK: &str = "#808080";
/// How strongly the right polygon is drawn under the student's vectors.
const RIGHT_PLAN_OPACITY: f64 = 0.4;
/// The width of the legend's and the caption's lines (mm).
const TEXT_WIDTH: f64 = 170.0;

/// How a student's vector was judged: its group's class and ink.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mark {
    Right,
    Wrong,
    Undecided,
}

impl Mark {
    fn style(self) -> (&'static str, &'static str) {
        match self {
            Mark::Right => ("right-item", RIGHT_INK),
            Mark::Wrong => ("wrong-item", WRONG_INK),
            Mark::Undecided => ("undecided-item", UNDECIDED_INK),
        }
    }
}

/// A vector the student gave: the plan's vector it is, where it is
/// drawn (mm, `k` times the plan's), its tolerance circle's radius about
/// the right end, and how it was judged.
struct Given {
    vector: usize,
    a: Point,
    b: Point,
    tolerance: f64,
    mark: Mark,
}

/// The overlay as an SVG sheet; a drawing too large for A1's field is
/// drawn reduced (its title says 1:n).
pub fn force_overlay(r: &ForceReport) -> String {
    let opt = DrawOptions::default();
    let mut c = overlay_canvas(r, 1.0);
    let mut title = title(r, check::phrases(r.lang));
    let n = reduction(c.bounds(), &opt);
    if n > 1.0 {
        c = overlay_canvas(r, 1.0 / n);
        title = format!("{title} (1:{})", table::number(n, r.lang));
    }
    page_svg("check".into(), title, &c, None, &opt).svg
}

/// The overlay's drawing, every length `k` times its size on the plan.
fn overlay_canvas(r: &ForceReport, k: f64) -> Canvas {
    let w = check::phrases(r.lang);
    let mut c = Canvas::default();
    let mut plan = r.plan.clone();
    for p in &mut plan.points {
        *p *= k;
    }
    let name = |f: Force| {
        plan.vectors
            .iter()
            .position(|v| v.force == f)
            .and_then(|i| r.names.get(i).cloned())
    };
    c.group(("right-plan", RIGHT_PLAN_OPACITY, "black"), |c| {
        force_polygon::draw(&plan, &name, c, (1.0, false), "right");
    });
    let given = given_vectors(r, k);
    for g in &given {
        let (class, ink) = g.mark.style();
        c.group((class, 1.0, ink), |c| {
            c.vector(g.a, g.b, Class::Vector, Some(format!("student-vec-{}", g.vector)));
            if g.mark == Mark::Wrong {
                let end = (r.plan.points[r.plan.vectors[g.vector].to] * k).to_point();
                c.prims.push(Prim::Circle {
                    c: end,
                    r: g.tolerance,
                    fill: "none",
                    stroke: THIN,
                    id: Some(format!("tolerance-{}", g.vector)),
                });
            }
        });
    }
    // The names, once every line is drawn: clear of them and each other.
    for g in &given {
        let (_, ink) = g.mark.style();
        let label = r.names[g.vector].clone().with_tail("*");
        c.group(("student-labels", 1.0, ink), |c| {
            let id = Some(format!("student-label-{}", g.vector));
            c.label(g.a.midpoint(g.b), label, SMALL, id);
        });
    }
    let drawn: Vec<usize> = given.iter().map(|g| g.vector).collect();
    legend(&mut c, w, r, &given, &drawn);
    c
}

/// The vectors the answer gives with a length and a direction, each from
/// the right plan's point it starts from.
fn given_vectors(r: &ForceReport, k: f64) -> Vec<Given> {
    let mut out: Vec<Given> = Vec::new();
    for (i, v) in r.plan.vectors.iter().enumerate() {
        let items: Vec<&Verdict> = r
            .verdicts
            .iter()
            .filter(|x| x.unit != "N·m" && r.vector_of(&x.key) == Some(i))
            .collect();
        let of = |unit: &str| items.iter().find(|x| x.unit == unit);
        let Some(angle) = of("°") else {
            continue;
        };
        // A length on the plan: the segment, else the value at μ_F; its
        // tolerance in mm the same way.
        let (len, tol) = match (of("mm"), of("N")) {
            (Some(s), _) => (s.given, s.tolerance),
            (None, Some(f)) => (f.given / r.mu, f.tolerance / r.mu),
            _ => continue,
        };
        let tol = if tol > 0.0 {
            tol
        } else {
            len * angle.tolerance.to_radians().sin().abs()
        };
        let mark = if items.iter().any(|x| x.judgement == Judgement::Wrong) {
            Mark::Wrong
        } else if items.iter().all(|x| x.judgement == Judgement::Right) {
            Mark::Right
        } else {
            Mark::Undecided
        };
        let a = (r.plan.points[v.from] * k).to_point();
        let b = a + Vec2::from_angle(angle.given.to_radians()) * len * k;
        out.push(Given {
            vector: i,
            a,
            b,
            tolerance: tol * k,
            mark,
        });
    }
    out
}

/// The legend under the drawing: a sample of each mark drawn and what it
/// means; in red, the items written wrong that no vector drawn shows;
/// then the diagnosis.
fn legend(c: &mut Canvas, w: &CheckPhrases, r: &ForceReport, given: &[Given], drawn: &[usize]) {
    let o = &w.overlay;
    let b = c.bounds();
    let (x, mut y) = (b.x0, b.y0 - 8.0);
    let row = 6.0;
    let text_at = |y: f64| Point::new(x + 16.0, y - 0.35 * SMALL);
    let mut n = 0;
    let mut line = |c: &mut Canvas, y: &mut f64, text: &str| {
        c.rich_id(text_at(*y), text, SMALL, ("legend", "start"), format!("legend-{n}"));
        n += 1;
        *y -= row;
    };
    c.group(("right-plan", RIGHT_PLAN_OPACITY, "black"), |c| {
        c.vector(Point::new(x, y), Point::new(x + 12.0, y), Class::Vector, None);
    });
    line(c, &mut y, &o.force_right_plan);
    for (mark, text) in [
        (Mark::Right, &o.force_right),
        (Mark::Wrong, &o.force_wrong),
        (Mark::Undecided, &o.force_undecided),
    ] {
        if !given.iter().any(|g| g.mark == mark) {
            continue;
        }
        let (class, ink) = mark.style();
        c.group((class, 1.0, ink), |c| {
            c.vector(Point::new(x, y), Point::new(x + 12.0, y), Class::Vector, None);
            if mark == Mark::Wrong {
                c.prims.push(Prim::Circle {
                    c: Point::new(x + 12.0, y),
                    r: 1.5,
                    fill: "none",
                    stroke: THIN,
                    id: None,
                });
            }
        });
        line(c, &mut y, text);
    }
    // The items written wrong that no vector drawn shows (a value, M_b,
    // a segment given without its direction).
    let shown = |v: &Verdict| {
        v.unit != "N·m" && r.vector_of(&v.key).is_some_and(|i| drawn.contains(&i))
    };
    let written = items_wrong(&r.verdicts, r.lang, |v| !shown(v));
    let diagnosis = match &r.diagnosis {
        Some(d) => Some(fill(&w.force_diagnosis, &[("mistake", d)])),
        None => (r.wrong() > 0).then(|| w.force_not_recognised.clone()),
    };
    c.group(("written-wrong", 1.0, WRONG_INK), |c| {
        for (i, item) in written.iter().enumerate() {
            c.rich_id(text_at(y), item, SMALL, ("legend", "start"), format!("written-wrong-{i}"));
            y -= row;
        }
        if let Some(d) = diagnosis {
            let at = |y: f64| Point::new(x, y - 0.35 * SMALL);
            for (i, l) in wrap(d.trim(), TEXT_WIDTH, SMALL).iter().enumerate() {
                c.rich_id(at(y), l, SMALL, ("legend", "start"), format!("diagnosis-{i}"));
                y -= row * 0.8;
            }
        }
    });
}

/// The overlay's title: the plan's links, the position, μ_F, how many
/// items are right.
fn title(r: &ForceReport, w: &CheckPhrases) -> String {
    let right = r
        .verdicts
        .iter()
        .filter(|v| v.judgement == Judgement::Right)
        .count();
    let mu = numbers::decimals(&crate::format::num(r.mu), r.lang);
    fill(
        &w.overlay.force_title,
        &[
            ("links", &r.links.join(", ")),
            ("position", &r.position.to_string()),
            ("mu", &mu),
            ("right", &right.to_string()),
            ("count", &r.verdicts.len().to_string()),
        ],
    )
}
