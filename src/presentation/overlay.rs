//! A check's overlay (`check --svg`, and the same drawing in a DXF
//! answer's marked copy): the right plan at the student's scale, pale;
//! over it, in the student's ink, each point the student drew (a cross,
//! its plan letters starred: b*, n₂*); where each step puts the point
//! from the student's own earlier points, within its tolerance (a thin
//! circle), and a wrong point's way off that place (red); the lines of
//! the step where a mistake enters (the two lines of an intersection, the
//! laid-off vector, the figure), red, with the step's number; and a
//! legend of these marks. Every label is placed once everything is drawn,
//! by the canvas's placing ([`Canvas::label`]), clear of the others and
//! of the points and lines.

use crate::grading::answer::{Answer, Given};
use crate::grading::{Judgement, Report, StepReport, resolve};
use crate::kinematics::construction::{Op, Plan, PlanKind};
use crate::kinematics::solve::Analysis;
use crate::presentation::drawing::canvas::{Canvas, Class, FONT, Label, MAIN, Prim, SMALL, THIN};
use crate::presentation::drawing::{DrawOptions, page_svg, plan, reduction, table};
use crate::presentation::gradebook::written_wrong;
use crate::words::catalogue::CheckPhrases;
use crate::words::check::{self, fill};
use kurbo::{Point, Vec2};

/// The student's ink: blue, apart from the pale right plan and the red
/// of what is wrong.
pub const STUDENT_INK: &str = "#1f5fa8";
/// The ink of what is wrong: the wrong step's lines and number, a point's
/// way off its place.
pub const WRONG_INK: &str = "#c00000";
/// How strongly the right plan is drawn under the marks (grey on paper;
/// a CAD draws it in the overlay layer's colour).
const RIGHT_PLAN_OPACITY: f64 = 0.4;
/// Half the size of a student's cross (mm).
const CROSS: f64 = 1.2;
/// How far a wrong step's line runs past the points it passes (mm), as
/// the plans' construction lines do.
const PAST: f64 = 6.0;

/// The overlay as an SVG sheet. A drawing too large for A1's field is
/// drawn reduced before its labels are placed (its title says 1:n), so
/// that the labels keep clear of each other at the size they are drawn.
pub fn overlay(an: &Analysis, ans: &Answer, r: &Report) -> String {
    let opt = DrawOptions::default();
    let (mut c, mut title) = overlay_canvas(an, ans, r, 1.0);
    let n = reduction(c.bounds(), &opt);
    if n > 1.0 {
        (c, title) = overlay_canvas(an, ans, r, 1.0 / n);
        title = format!("{title} (1:{})", table::number(n, r.lang));
    }
    page_svg("check".into(), title, &c, None, &opt).svg
}

/// The overlay written into a copy of the student's own DXF file
/// `original` (`check --dxf`): the same drawing as [`overlay`]'s, its
/// title above it, placed at the student's pole in the file's units, on
/// the layer [`crate::grading::dxf::OVERLAY_LAYER`].
pub fn overlay_dxf(
    an: &Analysis,
    ans: &Answer,
    r: &Report,
    original: &[u8],
) -> crate::error::Result<Vec<u8>> {
    let text = crate::grading::dxf::decode(original)?;
    let (pole, unit) = crate::grading::dxf::pole_in_file(&text, Some(ans.plan))?;
    let (mut c, title) = overlay_canvas(an, ans, r, 1.0);
    let b = c.bounds();
    c.text(
        Point::new(b.x0, b.y1 + 2.0 * FONT),
        Label::new(title, ""),
        FONT,
        "heading",
    );
    // The canvas's y is up, its origin the student's pole (the answer's
    // points are millimetres from it); written as SVG (y down) and placed
    // back in the file's units.
    let mut svg = String::from(r#"<svg xmlns="http://www.w3.org/2000/svg">"#);
    c.write(&mut svg, 0.0, 0.0);
    svg.push_str("</svg>");
    let place = |x: f64, y: f64| (pole.x + x / unit, pole.y - y / unit);
    crate::presentation::drawing::dxf::overlay::into_copy(original, &svg, &place, 1.0 / unit)
}

/// A point the student drew: the key as written, the plan's label of it
/// and where it is (mm from the pole).
struct Drawn {
    key: String,
    label: Label,
    at: Vec2,
}

/// What the legend shows: the marks drawn.
#[derive(Default)]
struct Shown {
    /// The first point's label, for the legend's sample.
    sample: Option<Label>,
    circles: bool,
    off: bool,
    /// The wrong step's lines: drawn from the student's points (`true`)
    /// or on the right plan.
    wrong_step: Option<bool>,
    /// The items wrong that no step's mistake covers (a value read wrong
    /// off points drawn right), as the gradebook names them.
    written: Vec<String>,
}

/// The overlay's drawing (y up, the pole at the origin, every length `k`
/// times its size on the plan) and its title.
fn overlay_canvas(an: &Analysis, ans: &Answer, r: &Report, k: f64) -> (Canvas, String) {
    let w = check::phrases(r.lang);
    let mut c = Canvas::default();
    let right = scaled(&r.plan_built, k);
    c.group(("right-plan", RIGHT_PLAN_OPACITY, "black"), |c| {
        plan::draw_labels_later(&right, c, &an.points)
    });
    let plan_labels = std::mem::take(&mut c.pending);
    let drawn = drawn_points(ans, &r.plan_built, k);
    let mut shown = Shown {
        sample: drawn.first().map(|d| d.label.clone()),
        written: written_wrong(r),
        ..Shown::default()
    };
    // The wrong steps' lines, and where their numbers go.
    let marks = wrong_steps(&mut c, r, k, &mut shown);
    if let Some(steps) = &r.steps {
        step_places(&mut c, steps, k, &mut shown);
    }
    c.group(("student", 1.0, STUDENT_INK), |c| {
        for d in &drawn {
            cross(c, d);
        }
    });
    keep_labels_off_points(&mut c);
    // The labels: the right plan's, the student's, the wrong steps'.
    c.pending = plan_labels;
    c.group(("right-plan-labels", RIGHT_PLAN_OPACITY, "black"), Canvas::place_pending);
    c.group(("student-labels", 1.0, STUDENT_INK), |c| {
        for d in drawn {
            let id = Some(format!("student-label-{}", d.key));
            c.label(d.at.to_point(), d.label.with_tail("*"), SMALL, id);
        }
    });
    if !marks.is_empty() {
        c.group(("wrong-step-labels", 1.0, WRONG_INK), |c| {
            for (n, at) in marks {
                let text = fill(&w.overlay.step, &[("step", &n.to_string())]);
                c.label(at, Label::new(text, ""), SMALL, Some(format!("wrong-step-label-{n}")));
            }
        });
    }
    legend(&mut c, w, &shown);
    (c, title(r, w))
}

/// `plan` with every point `k` times as far from the pole (and, in a
/// replay, where the student drew and where each step puts the point).
fn scaled(plan: &Plan, k: f64) -> Plan {
    let mut p = plan.clone();
    if k != 1.0 {
        for q in &mut p.points {
            q.at *= k;
        }
        for j in &mut p.judged {
            j.predicted *= k;
            j.given *= k;
        }
    }
    p
}

/// The points the answer draws, each with the plan's letters of it.
fn drawn_points(ans: &Answer, right: &Plan, k: f64) -> Vec<Drawn> {
    ans.items
        .iter()
        .filter_map(|it| {
            let Given::Point { name, at } = &it.given else {
                return None;
            };
            let label = match resolve(right, name) {
                Some(i) => {
                    let (base, sub) = &right.points[i].label;
                    Label::new(base.clone(), sub.clone())
                }
                None => Label::new(name.clone(), ""),
            };
            Some(Drawn {
                key: it.key.clone(),
                label,
                at: Vec2::new(at[0], at[1]) * k,
            })
        })
        .collect()
}

/// A student's point: a cross, kept clear of labels.
fn cross(c: &mut Canvas, d: &Drawn) {
    let p = d.at.to_point();
    for (i, (u, v)) in [(-1.0, -1.0), (-1.0, 1.0)].into_iter().enumerate() {
        let e = Vec2::new(u, v) * CROSS;
        c.prims.push(Prim::Seg {
            a: p + e,
            b: p - e,
            class: Class::Thin,
            id: (i == 0).then(|| format!("student-{}", d.key)),
        });
        c.avoid.push((p + e, p - e));
    }
}

/// Each judged step's place (where it puts the point from the student's
/// own earlier points) within its tolerance, a thin circle kept clear of
/// labels where they can; a wrong point's way off it, red.
fn step_places(c: &mut Canvas, steps: &StepReport, k: f64, shown: &mut Shown) {
    for v in &steps.steps {
        let at = (v.predicted * k).to_point();
        let radius = v.tolerance * k;
        c.prims.push(Prim::Circle {
            c: at,
            r: radius,
            fill: "none",
            stroke: THIN,
            id: Some(format!("step-{}-{}", v.step.0, v.point)),
        });
        ring(c, at, radius);
        shown.circles = true;
        if v.judgement == Judgement::Wrong {
            let given = (v.given * k).to_point();
            c.group(("off", 1.0, WRONG_INK), |c| {
                c.prims.push(Prim::Seg {
                    a: at,
                    b: given,
                    class: Class::Thin,
                    id: Some(format!("off-{}-{}", v.step.0, v.point)),
                });
            });
            c.avoid_thin.push((at, given));
            shown.off = true;
        }
    }
}

/// A circle's outline in the thin lines labels keep off where they can.
fn ring(c: &mut Canvas, at: Point, r: f64) {
    let n = 24;
    let q = |i: usize| at + Vec2::from_angle(std::f64::consts::TAU * i as f64 / n as f64) * r;
    for i in 0..n {
        c.avoid_thin.push((q(i), q(i + 1)));
    }
}

/// The points drawn (the right plan's dots) kept clear of labels: a label
/// over a point would hide it or seem to name it.
fn keep_labels_off_points(c: &mut Canvas) {
    let dots: Vec<(Point, f64)> = c
        .prims
        .iter()
        .filter_map(|p| match p {
            Prim::Circle { c, r, id: Some(id), .. } if id.starts_with("pt-") => Some((*c, *r)),
            _ => None,
        })
        .collect();
    for (at, r) in dots {
        let q = [(-r, -r), (r, -r), (r, r), (-r, r)].map(|(x, y)| at + Vec2::new(x, y));
        for i in 0..4 {
            c.avoid.push((q[i], q[(i + 1) % 4]));
        }
    }
}

/// What a wrong step's mark draws: a line, a vector, a ring about a point
/// (a step that draws no line: the pole, a point coinciding with another).
enum Mark {
    Line(Point, Point),
    Vector(Point, Point),
    Ring(Point),
}

impl Mark {
    /// Where the step's number goes beside it.
    fn middle(&self) -> Point {
        match *self {
            Mark::Line(a, b) | Mark::Vector(a, b) => a.midpoint(b),
            Mark::Ring(c) => c,
        }
    }
}

/// The lines of each step where a mistake enters, red, drawn as the
/// right construction draws them: from the student's own points where the
/// answer was judged step by step, else on the right plan. Returns each
/// step's number and where its number goes.
fn wrong_steps(c: &mut Canvas, r: &Report, k: f64, shown: &mut Shown) -> Vec<(usize, Point)> {
    // Each step named: its number and sentence, on the plan it is a step
    // of (the replay of the student's points, or the right plan).
    let (unscaled, steps): (&Plan, Vec<&(usize, String)>) = match &r.steps {
        Some(st) => (&st.replay, st.mistakes.iter().map(|f| &f.step).collect()),
        None => (
            &r.plan_built,
            r.diagnosis
                .iter()
                .filter(|d| d.mistake.is_some())
                .filter_map(|d| d.step.as_ref())
                .collect(),
        ),
    };
    let plan = scaled(unscaled, k);
    let mut numbers = Vec::new();
    for (n, sentence) in steps {
        let n = *n;
        if numbers.iter().any(|(m, _)| *m == n) {
            continue;
        }
        // A step of that plan as the report quotes it (not one a mistake
        // adds, which the plan has not; the student's own length may
        // follow the sentence).
        let Some(step) = n
            .checked_sub(1)
            .filter(|&i| i < plan.steps.len() && sentence.starts_with(&check::step(unscaled, i, r.lang)))
            .map(|i| &plan.steps[i])
        else {
            continue;
        };
        let marks = step_marks(&plan, &step.op);
        let Some(first) = marks.first() else {
            continue;
        };
        numbers.push((n, first.middle()));
        c.group(("wrong-step", 1.0, WRONG_INK), |c| {
            for (i, m) in marks.iter().enumerate() {
                let id = Some(format!("wrong-step-{n}-{i}"));
                match *m {
                    Mark::Vector(a, b) => c.vector(a, b, Class::Vector, id),
                    Mark::Line(a, b) => {
                        c.prims.push(Prim::Seg {
                            a,
                            b,
                            class: Class::Vector,
                            id,
                        });
                        c.avoid.push((a, b));
                    }
                    Mark::Ring(at) => {
                        c.prims.push(Prim::Circle {
                            c: at,
                            r: RING,
                            fill: "none",
                            stroke: MAIN,
                            id,
                        });
                        ring(c, at, RING);
                    }
                }
            }
        });
        shown.wrong_step = Some(r.steps.is_some());
    }
    numbers
}

/// The radius of a wrong step's ring about a point (mm).
const RING: f64 = 1.6;

/// What a step draws, from the points it is drawn from as they are on
/// `plan` (a replay: where the student drew them) to where it puts its
/// point ([`Plan::place`]).
fn step_marks(plan: &Plan, op: &Op) -> Vec<Mark> {
    let at = |i: usize| plan.points[i].at.to_point();
    let made = |i: usize| plan.place(i).to_point();
    // The line through `from` along `u` from before the first of `ts`
    // (distances along it) to past the last.
    let along = |from: Point, u: Vec2, ts: &[f64]| {
        let lo = ts.iter().copied().fold(0.0, f64::min) - PAST / 2.0;
        let hi = ts.iter().copied().fold(0.0, f64::max) + PAST;
        Mark::Line(from + u * lo, from + u * hi)
    };
    match op {
        Op::Pole { .. } => vec![Mark::Ring(Point::ORIGIN)],
        Op::LayOff { from, to, .. } => vec![Mark::Vector(at(*from), made(*to))],
        // Each line from the point it is drawn through to past where it
        // meets the other and past the student's point.
        Op::Intersect { lines, out, .. } => lines
            .iter()
            .map(|l| {
                let p = at(l.through);
                along(p, l.unit, &[(made(*out) - p).dot(l.unit), (at(*out) - p).dot(l.unit)])
            })
            .collect(),
        Op::Similar { a, b, out, .. } => {
            let (a, b, o) = (at(*a), at(*b), made(*out));
            vec![Mark::Line(a, b), Mark::Line(b, o), Mark::Line(o, a)]
        }
        // The segment divided, run on to the point where it lies beyond.
        Op::Divide { a, b, out, .. } => {
            let (a, b, o) = (at(*a), at(*b), made(*out));
            let len = (b - a).hypot();
            let mut marks = Vec::new();
            if len > 1e-9 {
                let u = (b - a) / len;
                let ts = [0.0, len, (o - a).dot(u)];
                let lo = ts.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = ts.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                marks.push(Mark::Line(a + u * lo, a + u * hi));
            }
            marks.push(Mark::Ring(o));
            marks
        }
        Op::Coincide { with, .. } => vec![Mark::Ring(at(*with))],
        Op::Measure { from, to, .. } => vec![Mark::Line(at(*from), at(*to))],
        _ => Vec::new(),
    }
}

/// The legend, under the drawing: a sample of each mark drawn and what it
/// means; then the items written wrong that no mark shows.
fn legend(c: &mut Canvas, w: &CheckPhrases, shown: &Shown) {
    let o = &w.overlay;
    let b = c.bounds();
    let (x, mut y) = (b.x0, b.y0 - 8.0);
    let row = 6.0;
    let size = SMALL;
    let text_at = |y: f64| Point::new(x + 16.0, y - 0.35 * size);
    let mut n = 0;
    let mut line = |c: &mut Canvas, y: &mut f64, text: &str| {
        c.rich_id(text_at(*y), text, size, ("legend", "start"), format!("legend-{n}"));
        n += 1;
        *y -= row;
    };
    // The right plan: a vector, pale as the plan.
    c.group(("right-plan", RIGHT_PLAN_OPACITY, "black"), |c| {
        c.vector(Point::new(x, y), Point::new(x + 12.0, y), Class::Main, None);
    });
    line(c, &mut y, &o.right_plan);
    if let Some(sample) = &shown.sample {
        let d = Drawn {
            key: "legend".into(),
            label: sample.clone(),
            at: Vec2::new(x + 3.0, y),
        };
        c.group(("student", 1.0, STUDENT_INK), |c| {
            cross(c, &d);
            c.text(
                Point::new(x + 5.5, y - 0.35 * size),
                sample.clone().with_tail("*"),
                size,
                "legend",
            );
        });
        line(c, &mut y, &o.your_point);
    }
    if shown.circles {
        c.prims.push(Prim::Circle {
            c: Point::new(x + 6.0, y),
            r: 2.0,
            fill: "none",
            stroke: THIN,
            id: None,
        });
        line(c, &mut y, &o.step_place);
    }
    if shown.off {
        c.group(("off", 1.0, WRONG_INK), |c| {
            c.prims.push(Prim::Seg {
                a: Point::new(x, y),
                b: Point::new(x + 12.0, y),
                class: Class::Thin,
                id: None,
            });
        });
        line(c, &mut y, &o.off);
    }
    if let Some(own) = shown.wrong_step {
        c.group(("wrong-step", 1.0, WRONG_INK), |c| {
            c.vector(Point::new(x, y), Point::new(x + 12.0, y), Class::Vector, None);
        });
        line(c, &mut y, if own { &o.wrong_step_own } else { &o.wrong_step_right });
    }
    // The items written wrong, in red under the marks.
    if !shown.written.is_empty() {
        c.group(("written-wrong", 1.0, WRONG_INK), |c| {
            for (i, item) in shown.written.iter().enumerate() {
                c.rich_id(text_at(y), item, size, ("legend", "start"), format!("written-wrong-{i}"));
                y -= row;
            }
        });
    }
}

/// The overlay's title: the plan, the position, how many items are
/// right, and the first mistake with its step.
fn title(r: &Report, w: &CheckPhrases) -> String {
    let mut title = fill(
        &w.overlay_title,
        &[
            ("plan", &w.plan[usize::from(r.plan == PlanKind::Acceleration)]),
            ("position", &r.position.to_string()),
            ("right", &r.right().to_string()),
            ("count", &r.verdicts.len().to_string()),
        ],
    );
    if let Some(d) = &r.diagnosis
        && let Some(m) = &d.mistake
    {
        match &d.step {
            Some((n, _)) => {
                let step = fill(&w.overlay.step, &[("step", &n.to_string())]);
                title.push_str(&format!(" — {step}: {m}"));
            }
            None => title.push_str(&format!(" — {m}")),
        }
    }
    title
}
