//! Sheet 1's data beside its drawings, as a course sheet states them:
//! the structure (Chebyshev's W = 3n − 2p₅ − p₄ and the structure formula
//! with its Assur groups by class and kind), the given data (lengths, the
//! input's motion, masses), the output's stroke H with the crank angles of
//! the working and idle strokes and K, and the plans' values at the
//! analysed position against the analytic solution.
//!
//! Everything here is read from what the study solved (the positions,
//! their plans, [`SheetData`]): nothing is solved again.

use super::canvas::{Canvas, SMALL};
use super::pack::{Figure, round3};
use super::table::{Ruled, number, rate, unit};
use crate::kinematics::construction::Plan;
use crate::kinematics::construction::plan::Quantity;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::model::structure::AssurGroup;
use crate::pipeline::Solved;
use crate::studies::sheet_data::SheetData;
use crate::words::catalogue::fill;
use crate::words::construction::Lang;
use kurbo::Point;

/// How finely a student reads a segment off a plan, mm: the pencil
/// precision the construction's error model takes (δ = 0.5 mm).
pub const READING: f64 = 0.5;

/// The height of a line of text above a table, mm (at the lettering in
/// force).
fn line() -> f64 {
    5.0 * super::canvas::lettering()
}

/// The structure, the stroke and the given data: lines of text over a
/// table of the data.
pub(super) fn given(an: &Analysis, solved: &[Solved], data: &SheetData, lang: Lang) -> Figure {
    let w = &crate::words::catalogue(lang).course_sheet;
    let mut lines = structure_lines(an, lang);
    if let Some(s) = &data.stroke {
        lines.extend(stroke_lines(an, s, lang));
    }
    let table = side_by_side(&w.given_head, given_rows(an, solved, lang));
    Figure {
        id: "given".into(),
        caption: vec![w.given_caption.clone()],
        canvas: over_table(&lines, &table),
        scales: Vec::new(),
    }
}

/// A table of (quantity, value) rows folded into up to three pairs of
/// columns side by side (ten rows a pair at least), so that a long list
/// of data is a block, not a column.
fn side_by_side(head: &[String; 2], rows: Vec<Vec<String>>) -> Ruled {
    let pairs = rows.len().div_ceil(10).clamp(1, 3);
    let per = rows.len().div_ceil(pairs).max(1);
    let chunks: Vec<&[Vec<String>]> = rows.chunks(per).collect();
    let out = (0..per)
        .map(|i| {
            chunks
                .iter()
                .flat_map(|c| match c.get(i) {
                    Some(r) => r.clone(),
                    None => vec![String::new(), String::new()],
                })
                .collect()
        })
        .collect();
    Ruled {
        head: (0..chunks.len()).flat_map(|_| head.to_vec()).collect(),
        rows: out,
    }
}

/// `lines` of text, then `table` under them.
fn over_table(lines: &[String], table: &Ruled) -> Canvas {
    let mut c = table.draw();
    let n = lines.len();
    for (i, t) in lines.iter().enumerate() {
        let y = 2.0 + line() * (n - 1 - i) as f64 + 0.35 * SMALL * super::canvas::lettering();
        c.rich(Point::new(0.0, y), t, SMALL, "", "start");
    }
    c
}

/// Chebyshev's count and the structure formula, then each group by its
/// class and kind.
fn structure_lines(an: &Analysis, lang: Lang) -> Vec<String> {
    let m = &an.mech;
    let w = &crate::words::catalogue(lang).course_sheet;
    let n = m.links.len() - 1;
    let p5 = m.revolutes.len() + m.prismatics.len();
    // No higher pairs in a linkage: p₄ = 0.
    let dof = 3 * n as i64 - 2 * p5 as i64;
    let mut out = vec![
        format!(
            "{}: W = 3n − 2p_5 − p_4 = 3·{n} − 2·{p5} − 0 = {dof}",
            w.mobility
        ),
        format!(
            "{}: {}",
            w.formula,
            an.structure.formula(m).replace("->", "→")
        ),
    ];
    let sheets = &crate::words::catalogue(lang).sheets;
    for g in &an.structure.groups {
        let ids: Vec<&str> = g.links().iter().map(|&l| m.link_id(l)).collect();
        let links = ids.join(", ");
        out.push(match g {
            AssurGroup::Dyad(d) => fill(
                &sheets.group,
                &[
                    ("class", "II"),
                    ("kind", &d.kind.number().to_string()),
                    ("links", &links),
                    ("letters", d.kind.name()),
                ],
            ),
            _ => fill(&sheets.group_triad, &[("links", &links)]),
        });
    }
    out
}

/// The output's stroke H (or swing ψ), the crank angles of the working
/// and idle strokes and K = φ_w/φ_i.
fn stroke_lines(an: &Analysis, s: &crate::studies::stroke::Stroke, lang: Lang) -> Vec<String> {
    let w = &crate::words::catalogue(lang).course_sheet;
    let id = an.mech.link_id(s.output);
    let first = if s.slide {
        format!(
            "{}: H = {} {}",
            fill(&w.stroke_slide, &[("id", id)]),
            number(round3(s.h), lang),
            unit("m", lang)
        )
    } else {
        format!(
            "{}: ψ = {}°",
            fill(&w.stroke_rocker, &[("id", id)]),
            number(round_to(s.h.to_degrees(), 1), lang)
        )
    };
    let deg = |x: f64| number(round_to(x.to_degrees(), 1), lang);
    vec![
        first,
        format!(
            "{}: φ_{} = {}°; {}: φ_{} = {}°",
            w.working,
            w.w,
            deg(s.working),
            w.idle,
            w.i,
            deg(s.idle)
        ),
        format!(
            "{}: K = φ_{}/φ_{} = {}",
            w.k,
            w.w,
            w.i,
            number(round_to(s.k(), 3), lang)
        ),
    ]
}

/// `x` to `d` decimals.
fn round_to(x: f64, d: i32) -> f64 {
    let p = 10f64.powi(d);
    (x * p).round() / p
}

/// The given data: the lengths (the scene's, else each link's points
/// from its first one, measured at the first position), the inputs'
/// motion, and the masses and moments of inertia.
fn given_rows(an: &Analysis, solved: &[Solved], lang: Lang) -> Vec<Vec<String>> {
    let m = &an.mech;
    let sc = &m.scene;
    let metre = unit("m", lang);
    let mut rows = Vec::new();
    let name = |p: usize| sc.points[p].name.replace(['-', ' ', '_'], "");
    if !sc.lengths.is_empty() {
        for l in &sc.lengths {
            rows.push(vec![
                format!("l_{}{}, {metre}", name(l.a), name(l.b)),
                number(round3(l.value), lang),
            ]);
        }
    } else if let Some(first) = solved.first() {
        for (i, link) in sc.links.iter().enumerate() {
            let Some((&a, rest)) = link.points.split_first() else {
                continue;
            };
            for &b in rest {
                let d = (first.point(an, b).at - first.point(an, a).at).hypot();
                if d > 0.0 && i < m.links.len() {
                    rows.push(vec![
                        format!("l_{}{}, {metre}", name(a), name(b)),
                        number(round3(d), lang),
                    ]);
                }
            }
        }
    }
    for input in sc.inputs() {
        let id = m.link_id(input.link());
        match *input {
            InputSpec::Crank { omega, epsilon, .. } => {
                rows.push(vec![
                    format!("ω_{id}, {}", unit("rad/s", lang)),
                    rate(round3(omega), lang),
                ]);
                if epsilon != 0.0 {
                    rows.push(vec![
                        format!("ε_{id}, {}", unit("rad/s²", lang)),
                        rate(round3(epsilon), lang),
                    ]);
                }
            }
            InputSpec::Slider { v, a, .. } => {
                rows.push(vec![
                    format!("v_{id}, {}", unit("m/s", lang)),
                    number(round3(v), lang),
                ]);
                if a != 0.0 {
                    rows.push(vec![
                        format!("a_{id}, {}", unit("m/s²", lang)),
                        number(round3(a), lang),
                    ]);
                }
            }
        }
    }
    if let Some(d) = &sc.dynamics {
        for lm in &d.links {
            let id = m.link_id(lm.link);
            rows.push(vec![
                format!("m_{id}, {}", unit("kg", lang)),
                number(round3(lm.m), lang),
            ]);
            if lm.j > 0.0 {
                rows.push(vec![
                    format!("J_{}, {}", name(lm.centre), unit("kg·m²", lang)),
                    number(round3(lm.j), lang),
                ]);
            }
        }
    }
    rows
}

/// The plans' values at the analysed position against the analytic
/// solution: each quantity the plans measure, its segment read to
/// [`READING`] mm, the value that reading gives, the analytic value and
/// their difference, a row per point or link (the velocity plan's on the
/// left, the acceleration plan's on the right); `None` without plans.
pub(super) fn compare(an: &Analysis, solved: &[Solved], data: &SheetData, lang: Lang) -> Option<Figure> {
    let k = data.chosen.analysed(solved.len());
    let s = solved.get(k)?;
    let plans = s.plans.as_ref()?;
    let w = &crate::words::catalogue(lang).course_sheet;
    let vel = rows_of(an, s, &plans.velocity, lang);
    let acc = plans
        .acceleration
        .as_ref()
        .map(|a| rows_of(an, s, a, lang))
        .unwrap_or_default();
    if vel.is_empty() {
        return None;
    }
    let mut head = w.compare_head.to_vec();
    let blank = || vec![String::new(); 5];
    let rows = if acc.is_empty() {
        vel.into_iter().map(|r| r.1).collect()
    } else {
        head.extend(w.compare_head.iter().cloned());
        // Each point's (link's) acceleration beside its velocity (its
        // angular acceleration beside its ω); the others after them.
        let mut rows: Vec<Vec<String>> = Vec::new();
        let mut left: Vec<bool> = vec![false; acc.len()];
        for (of, v) in &vel {
            let mut r = v.clone();
            match acc.iter().position(|a| a.0 == *of) {
                Some(i) => {
                    left[i] = true;
                    r.extend(acc[i].1.iter().cloned());
                }
                None => r.extend(blank()),
            }
            rows.push(r);
        }
        for (a, _) in acc.iter().zip(&left).filter(|(_, l)| !**l) {
            let mut r = blank();
            r.extend(a.1.iter().cloned());
            rows.push(r);
        }
        rows
    };
    let table = Ruled { head, rows };
    let number_k = crate::presentation::position_number(an, k).to_string();
    let note = fill(&w.compare_note, &[("d", &number(READING, lang))]);
    Some(Figure {
        id: "compare".into(),
        caption: vec![fill(&w.compare_caption, &[("k", &number_k)])],
        canvas: over_table(&[note], &table),
        scales: Vec::new(),
    })
}

/// Whether the table compares point `p`: a pair's point (where links
/// join, or a slider's), not one the input link carries (its velocity is
/// given, laid off exactly) nor a point of one link alone (a centre of
/// mass: the results tables give it).
fn compared(an: &Analysis, p: usize) -> bool {
    let m = &an.mech;
    let input = an.mech.scene.inputs().any(|i| an.carrier(p) == i.link());
    !input
        && (m.revolutes.iter().any(|r| r.point == p) || m.prismatics.iter().any(|r| r.point == p))
}

/// The rows of one plan: each measured quantity (a point's velocity or
/// acceleration, a link's ω or ε) by magnitude, with what it is of.
fn rows_of(an: &Analysis, s: &Solved, plan: &Plan, lang: Lang) -> Vec<(Quantity, Vec<String>)> {
    let acc = plan.kind == crate::kinematics::construction::PlanKind::Acceleration;
    let mut rows = Vec::new();
    for q in &plan.measured {
        if q.mm <= 0.0 || q.quantity.is_empty() {
            continue;
        }
        let (exact, u) = match q.of {
            Quantity::Point(p) if !compared(an, p) => continue,
            Quantity::Point(p) => {
                let Some((v, a)) = s.point(an, p).rates else {
                    continue;
                };
                (if acc { a } else { v }.hypot(), if acc { "m/s²" } else { "m/s" })
            }
            Quantity::Rate(l) => {
                let Some(mo) = s.motion[l] else { continue };
                (
                    if acc { mo.epsilon } else { mo.omega }.abs(),
                    if acc { "rad/s²" } else { "rad/s" },
                )
            }
        };
        let read = (q.mm / READING).round() * READING;
        let plan_value = read * q.value.abs() / q.mm;
        let diff = if exact > 0.0 {
            number(round_to(100.0 * (plan_value - exact) / exact, 1), lang)
        } else {
            "—".into()
        };
        rows.push((
            q.of,
            vec![
                format!("{}, {}", q.quantity, unit(u, lang)),
                number(read, lang),
                number(round3(plan_value), lang),
                number(round3(exact), lang),
                diff,
            ],
        ));
    }
    rows
}
