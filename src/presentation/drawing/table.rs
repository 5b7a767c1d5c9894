//! Ruled tables on a sheet (ГОСТ 2.105: a heading row, ruled columns, the
//! unit of every quantity): what was measured on a plan, and the course
//! sheet's tables of every position. Cells are text in the lecture's
//! notation (`v_B3B`, `a^K_B3B2`), numbers with the language's decimal
//! sign.

use super::canvas::{Canvas, Line, SMALL, lettering, runs_width};
use crate::format::num;
use crate::kinematics::construction::{Dir, Op, Plan, PlanKind, PointId};
use crate::words::construction::Lang;
use crate::words::notation::runs;
use kurbo::Point;

/// Row height and the space around a cell's text, mm.
const ROW: f64 = 6.0;
const HEAD_ROW: f64 = 8.0;
const PAD: f64 = 1.6;

/// The table's measures at the lettering in force (larger on the course
/// sheets: [`super::canvas::with_lettering`]): rows, heading row, padding.
fn measures() -> (f64, f64, f64) {
    let k = lettering();
    (ROW * k, HEAD_ROW * k, PAD * k)
}

/// A ruled table: a heading row and rows of cells, every cell text in the
/// lecture's notation; the first column left-aligned, the others centred.
#[derive(Clone, Debug, Default)]
pub struct Ruled {
    pub head: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Ruled {
    fn widths(&self) -> Vec<f64> {
        let (_, _, pad) = measures();
        let small = SMALL * lettering();
        let n = self.head.len();
        (0..n)
            .map(|j| {
                std::iter::once(&self.head[j])
                    .chain(self.rows.iter().filter_map(|r| r.get(j)))
                    .map(|t| runs_width(&runs(t), small))
                    .fold(6.0f64, f64::max)
                    + 2.0 * pad
            })
            .collect()
    }

    /// Width and height, mm.
    pub fn size(&self) -> (f64, f64) {
        let (row, head_row, _) = measures();
        (
            self.widths().iter().sum(),
            head_row + row * self.rows.len() as f64,
        )
    }

    /// The table on a canvas, its top left corner at the origin (the
    /// table hangs below it).
    pub fn draw(&self) -> Canvas {
        let (row, head_row, pad) = measures();
        let lift = 0.9 * lettering();
        let mut c = Canvas::default();
        let ws = self.widths();
        let (w, h) = self.size();
        let xs: Vec<f64> = std::iter::once(0.0)
            .chain(ws.iter().scan(0.0, |x, d| {
                *x += d;
                Some(*x)
            }))
            .collect();
        // The outline and the heading's rule in main lines, the rest thin.
        c.path(
            vec![
                Point::new(0.0, 0.0),
                Point::new(w, 0.0),
                Point::new(w, -h),
                Point::new(0.0, -h),
                Point::new(0.0, 0.0),
            ],
            Line::Main,
        );
        c.path(
            vec![Point::new(0.0, -head_row), Point::new(w, -head_row)],
            Line::Main,
        );
        for x in &xs[1..xs.len() - 1] {
            c.path(vec![Point::new(*x, 0.0), Point::new(*x, -h)], Line::Main);
        }
        for k in 1..self.rows.len() {
            let y = -head_row - row * k as f64;
            c.path(vec![Point::new(0.0, y), Point::new(w, y)], Line::Thin);
        }
        let cell = |c: &mut Canvas, j: usize, y: f64, t: &str| {
            if j == 0 {
                c.rich(Point::new(xs[0] + pad, y), t, SMALL, "table", "start");
            } else {
                c.rich(
                    Point::new(0.5 * (xs[j] + xs[j + 1]), y),
                    t,
                    SMALL,
                    "table",
                    "middle",
                );
            }
        };
        for (j, t) in self.head.iter().enumerate() {
            cell(&mut c, j, -head_row / 2.0 - lift, t);
        }
        for (k, r) in self.rows.iter().enumerate() {
            let y = -head_row - row * k as f64 - row / 2.0 - lift;
            for (j, t) in r.iter().enumerate() {
                cell(&mut c, j, y, t);
            }
        }
        c
    }
}

/// A number as the language writes it: a decimal comma in Ukrainian and
/// Russian (the lecture writes 0,001 м/мм).
pub fn number(x: f64, l: Lang) -> String {
    // The minus sign of typesetting (−), not the hyphen.
    crate::words::numbers::decimals(&num(x).replace('-', "\u{2212}"), l)
}

/// A unit in the language: м/с, рад/с².
pub fn unit(u: &str, l: Lang) -> String {
    crate::presentation::tables::unit(u, l)
}

/// The words of the tables.
fn heads(l: Lang) -> [&'static str; 4] {
    crate::words::catalogue(l).sheets.plan_table.each_ref().map(|s| s.as_str())
}

/// An angular rate's magnitude as printed, with its sense (none when it
/// prints as zero: a rounding residue has no sense to show).
pub fn rate(x: f64, l: Lang) -> String {
    let n = number(x.abs(), l);
    if n.chars().any(|c| ('1'..='9').contains(&c)) {
        format!("{n}{}", sense(x))
    } else {
        n
    }
}

/// The sense of an angular rate: ↺ counter-clockwise, ↻ clockwise.
pub fn sense(x: f64) -> &'static str {
    if x > 0.0 {
        " ↺"
    } else if x < 0.0 {
        " ↻"
    } else {
        ""
    }
}

/// One row of what a plan gives: the quantity, its segment and length on
/// the plan, its value with the unit (an angular rate with its sense).
#[derive(Clone, Debug)]
pub struct Row {
    pub quantity: String,
    pub segment: String,
    pub mm: Option<f64>,
    pub value: f64,
    pub unit: &'static str,
    pub rate: bool,
}

/// Every quantity a plan lays off or measures, in the order of the
/// construction: the known vectors laid off (v_B, a^n_BA, the Coriolis
/// a^K), the relative slide along a moving guide (v_B3B, a^r) that the
/// lecture measures there, the measured segments and the angular rates
/// they give.
pub fn plan_rows(plan: &Plan) -> Vec<Row> {
    let (lin, ang) = match plan.kind {
        PlanKind::Velocity => ("m/s", "rad/s"),
        PlanKind::Acceleration => ("m/s²", "rad/s²"),
    };
    let at = |i: usize| plan.points[i].at;
    let name = |i: usize| plan.points[i].name();
    let seg = |a: usize, b: usize| format!("{}{}", name(a), name(b));
    let len = |a: usize, b: usize| (at(b) - at(a)).hypot();
    let mut rows: Vec<Row> = Vec::new();
    let push = |rows: &mut Vec<Row>, r: Row| {
        if !rows.iter().any(|x| x.quantity == r.quantity) {
            rows.push(r);
        }
    };
    for step in &plan.steps {
        match &step.op {
            Op::LayOff {
                from,
                to,
                what,
                value,
                ..
            } => push(
                &mut rows,
                Row {
                    quantity: laid_off(plan, what, *from, *to),
                    segment: seg(*from, *to),
                    mm: Some(len(*from, *to)),
                    value: *value,
                    unit: lin,
                    rate: false,
                },
            ),
            Op::Intersect { lines, out, .. } => {
                for l in lines.iter().filter(|l| matches!(l.dir, Dir::Guide(_))) {
                    let (a, b) = (l.through, *out);
                    let guide = under(plan, a, b).to_uppercase();
                    let quantity = match plan.kind {
                        // The slide of B3 along the guide, relative to B.
                        PlanKind::Velocity => {
                            format!("v_{}{guide}", plan.points[b].scene_name().to_uppercase())
                        }
                        // From the Coriolis vector's end: a^r.
                        PlanKind::Acceleration => plan
                            .steps
                            .iter()
                            .find_map(|s| match &s.op {
                                Op::LayOff { to, what, .. } if *to == a => {
                                    Some(symbol(what).replacen("^K", "^r", 1))
                                }
                                _ => None,
                            })
                            .unwrap_or_else(|| {
                                format!("a^r_{}{guide}", plan.points[b].scene_name().to_uppercase())
                            }),
                    };
                    push(
                        &mut rows,
                        Row {
                            quantity,
                            segment: seg(a, b),
                            mm: Some(len(a, b)),
                            value: len(a, b) * plan.mu,
                            unit: lin,
                            rate: false,
                        },
                    );
                }
            }
            Op::Measure {
                from,
                to,
                quantity,
                value,
                rate,
                ..
            } => {
                push(
                    &mut rows,
                    Row {
                        quantity: quantity.clone(),
                        segment: seg(*from, *to),
                        mm: Some(len(*from, *to)),
                        value: *value,
                        unit: lin,
                        rate: false,
                    },
                );
                if let Some((r, v, _)) = rate {
                    push(
                        &mut rows,
                        Row {
                            quantity: r.clone(),
                            segment: String::new(),
                            mm: None,
                            value: *v,
                            unit: ang,
                            rate: true,
                        },
                    );
                }
            }
            _ => {}
        }
    }
    rows
}

/// The symbol of a vector laid off from `from` to `to`: its own ("a^n_BA"
/// of "a^n_BA = ω1²·l_AB", "v_B" of a driving slider's, "a^r_B3B2" of a
/// cylinder's given relative acceleration), or for a bare
/// product ("ω1·l_O1A") the velocity of the point it reaches, the
/// tangential acceleration on the acceleration plan.
fn laid_off(plan: &Plan, what: &str, from: usize, to: usize) -> String {
    // A symbol of its own: a component with its product, a driving
    // slider's v_B, a cylinder's given slide v_B3B2 and a^r_B3B2.
    if what.contains(" = ")
        || what.starts_with("v_")
        || what.starts_with("a_")
        || what.starts_with("a^")
    {
        return symbol(what);
    }
    let up = |i: usize| plan.points[i].scene_name().to_uppercase();
    match plan.kind {
        PlanKind::Velocity if from == 0 => format!("v_{}", up(to)),
        PlanKind::Velocity => format!("v_{}{}", up(to), up(from)),
        PlanKind::Acceleration => {
            // ω²·l_JX lays off the normal acceleration of X about J, ε·l_JX
            // the tangential one; X is the point the tangential part
            // reaches (from the normal part's end, on the same segment).
            let seg = |w: &str| w.split("·l_").nth(1).map(str::to_string);
            let sup = if what.contains('²') { "n" } else { "t" };
            let x = if sup == "t" {
                Some(up(to))
            } else {
                plan.steps.iter().find_map(|s| match &s.op {
                    Op::LayOff {
                        from: f,
                        to: t,
                        what: w,
                        ..
                    } if *f == to && seg(w).is_some() && seg(w) == seg(what) => Some(up(*t)),
                    _ => None,
                })
            };
            match (seg(what), x) {
                (Some(l), Some(x)) if l.len() > x.len() && l.ends_with(&x) => {
                    format!("a^{sup}_{x}{}", &l[..l.len() - x.len()])
                }
                _ => format!("a^t_{}", up(to)),
            }
        }
    }
}

/// The name of the guide's point under `b`, for a slide of `b` along a
/// guide drawn through the plan point `a`: D0 for D on the frame's guide,
/// even when the construction drew the line through b₀ (B and D on one
/// guide: every frame point sits at the pole), as the lecture writes
/// v_DD0 whatever point of the guide the line passed through.
fn under(plan: &Plan, a: usize, b: usize) -> String {
    match (plan.points[a].id, plan.points[b].id) {
        (PointId::Coincident { point: p, .. }, PointId::Named(q)) if p != q => {
            format!("{}{}", plan.points[b].scene_letter(), plan.points[a].label.1)
        }
        _ => plan.points[a].scene_name(),
    }
}

/// A laid-off vector's symbol: "a^n_BA" of "a^n_BA = ω1²·l_AB".
fn symbol(what: &str) -> String {
    what.split(" = ").next().unwrap_or(what).trim().to_string()
}

/// The table of a plan's quantities (`plan_rows`), to what a reading of
/// the plan supports: each segment to 0.1 mm, each value to three
/// significant digits.
pub fn plan_table(plan: &Plan, l: Lang) -> Ruled {
    let three = super::pack::round3;
    let h = heads(l);
    Ruled {
        head: h.iter().map(|s| s.to_string()).collect(),
        rows: plan_rows(plan)
            .into_iter()
            .map(|r| {
                let v = if r.rate {
                    let v = rate(three(r.value), l);
                    match v.split_once(' ') {
                        Some((n, s)) => format!("{n} {} {s}", unit(r.unit, l)),
                        None => format!("{v} {}", unit(r.unit, l)),
                    }
                } else {
                    format!("{} {}", number(three(r.value), l), unit(r.unit, l))
                };
                vec![
                    r.quantity,
                    r.segment,
                    r.mm
                        .map(|x| number((x * 10.0).round() / 10.0, l))
                        .unwrap_or_else(|| "—".into()),
                    v,
                ]
            })
            .collect(),
    }
}
