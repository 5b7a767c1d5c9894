//! The result as a terminal table (`solve`, the default format): per
//! position the points' places, velocities and accelerations and the
//! links' rates, each with the routes' agreement and the printed bound;
//! in a language's words (its catalogue's) and decimal mark.

use super::tables::{self, Cell, Kind, Table};
use crate::kinematics::analytic::Order;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use crate::verification::crosscheck::{CrossCheck, Method};
use crate::words::catalogue::fill;
use crate::words::construction::Lang;
use crate::words::numbers::{decimals, unit};
use crate::words::terminal::{results, worst};
use std::fmt::Write as _;

/// The senses of rotation in `l`: counter-clockwise, clockwise, zero.
fn senses(l: Lang) -> &'static [String; 3] {
    &crate::words::catalogue(l).tables.senses
}

/// The width of the senses' column: the longest sense, and at least 5.
fn sense_width(l: Lang) -> usize {
    senses(l).iter().map(|s| s.chars().count()).fold(5, usize::max)
}

/// The sense of rotation in `l`, zero (`-`) for a value that is zero up
/// to rounding (`scale` is the largest value of its kind at that
/// position).
fn sense(x: f64, scale: f64, l: Lang) -> &'static str {
    let [ccw, cw, zero] = senses(l);
    if x.abs() <= 1e-12 * scale {
        zero
    } else if x > 0.0 {
        ccw
    } else if x < 0.0 {
        cw
    } else {
        zero
    }
}

/// A table for the terminal in `l`: points with |v|, |a|; links with ω,
/// ε and senses.
#[cfg(feature = "internals")]
pub fn to_table(an: &Analysis, solved: &[Solved], l: Lang) -> String {
    let mut t = table_head(an, l);
    for (i, s) in solved.iter().enumerate() {
        t += &table_position(an, i, s, l);
    }
    t
}

/// The table's title (the scene's, as written) and structure line.
pub(super) fn table_head(an: &Analysis, l: Lang) -> String {
    let m = &an.mech;
    let mut t = String::new();
    let title = m.scene.title_in(l);
    if !title.is_empty() {
        let _ = writeln!(t, "{title}");
    }
    let _ = writeln!(
        t,
        "{}: W = {}, {}   [{}]",
        results(l).structure,
        an.structure.dof,
        an.structure.formula(m),
        group_kinds(an)
    );
    t
}

/// The Assur groups in order of attachment with their kinds:
/// "II(2,3) RRR; II(4,5) RRP".
pub(crate) fn group_kinds(an: &Analysis) -> String {
    let m = &an.mech;
    let kinds: Vec<String> = an
        .structure
        .groups
        .iter()
        .map(|g| format!("{} {}", g.label(m), g.kind()))
        .collect();
    kinds.join("; ")
}

/// A table of results for the terminal: a line per row, the columns the
/// terminal has room for (every number; not the measured segments, which
/// `solve --steps` gives) aligned under their headings, numbers to fixed
/// decimals, a rate followed by its sense (in `l`).
/// `x`, or 0 where it prints as zero to `d` decimals: no "-0.000000".
fn unsigned_zero(x: f64, d: usize) -> f64 {
    if (x * 10f64.powi(d as i32)).round() == 0.0 { 0.0 } else { x }
}

fn table_text(table: &Table, l: Lang) -> String {
    let sw = sense_width(l);
    // Width and decimals of the terminal's column of a kind.
    let form = |k: Kind| match k {
        Kind::Name => Some((6, 0)),
        Kind::Coordinate => Some((11, 6)),
        Kind::Magnitude | Kind::Rate => Some((12, 6)),
        Kind::Direction => Some((8, 2)),
        Kind::Angle => Some((11, 4)),
        Kind::Segment | Kind::Measured => None,
    };
    let columns: Vec<(usize, usize, usize)> = (0..table.columns.len())
        .filter_map(|i| form(table.columns[i].kind).map(|(w, d)| (i, w, d)))
        .collect();
    let mut t = String::from("  ");
    for (n, &(i, w, _)) in columns.iter().enumerate() {
        let c = &table.columns[i];
        let head = match &c.unit {
            Some(u) => format!("{} [{u}]", c.head),
            None => c.head.clone(),
        };
        let sep = if n > 0 { " " } else { "" };
        let _ = match c.kind {
            Kind::Name => write!(t, "{sep}{head:<w$}"),
            Kind::Rate => write!(t, "{sep}{head:>w$} {:>sw$}", ""),
            _ => write!(t, "{sep}{head:>w$}"),
        };
    }
    t.push('\n');
    for row in table.groups.iter().flat_map(|g| &g.rows) {
        t.push_str("  ");
        for (n, &(i, w, d)) in columns.iter().enumerate() {
            let sep = if n > 0 { " " } else { "" };
            let _ = match &row[i] {
                Cell::Notation(s) | Cell::Plain(s) if table.columns[i].kind == Kind::Name => {
                    write!(t, "{sep}{s:<w$}")
                }
                Cell::Notation(s) | Cell::Plain(s) => write!(t, "{sep}{s:>w$}"),
                Cell::Number(x) => write!(t, "{sep}{:>w$.d$}", unsigned_zero(*x, d)),
                Cell::Rate { value, scale } => {
                    let v = unsigned_zero(*value, d);
                    write!(t, "{sep}{v:>w$.d$} {:>sw$}", sense(*value, *scale, l))
                }
                // Not known: nothing, nor anything after it.
                Cell::Missing => Ok(()),
                // Not among the terminal's columns.
                Cell::Segment { .. } | Cell::Measured { .. } => Ok(()),
            };
        }
        t.push('\n');
    }
    t
}

/// The table of position `i` (from 0) in `l`, every number in its
/// decimal mark.
pub(super) fn table_position(an: &Analysis, i: usize, s: &Solved, l: Lang) -> String {
    let m = &an.mech;
    let mut t = String::new();
    let _ = writeln!(t);
    let several = m.scene.several_inputs();
    let input = m
        .scene
        .inputs()
        .zip(s.drives.iter())
        .map(|(spec, d)| {
            // Several inputs carry their links' ids (φ1, φ4; s3, s6).
            let id = m.link_id(spec.link());
            let sub = if several { id } else { "" };
            match spec {
                InputSpec::Crank { .. } => {
                    let k = if several { id } else { "1" };
                    format!(
                        "φ{k} = {:.3}°, ω{k} = {} {}, ε{k} = {} {}",
                        d.q.to_degrees().rem_euclid(360.0),
                        fmt(d.rate),
                        unit("rad/s", l),
                        fmt(d.rate2),
                        unit("rad/s²", l)
                    )
                }
                InputSpec::Slider { .. } => format!(
                    "s{sub} = {} {}, v{sub} = {} {}, a{sub} = {} {}",
                    fmt(d.q),
                    unit("m", l),
                    fmt(d.rate),
                    unit("m/s", l),
                    fmt(d.rate2),
                    unit("m/s²", l)
                ),
            }
        })
        .collect::<Vec<_>>()
        .join("; ");
    let position = &crate::words::catalogue(l).sheets.position;
    let _ = writeln!(t, "{position} {}: {input}", super::position_number(an, i));
    t += &table_text(&tables::points(an, s, l), l);
    t += &table_text(&tables::links(an, s, l), l);
    t += &slides_text(an, s, l);
    if let Some(c) = &s.check {
        t += &check_text(c, l);
    }
    // Every number in the language's decimal mark (a comma in uk and ru).
    decimals(&t, l)
}

/// The position's slides, a line each, in `l`: the relative velocity and
/// acceleration (and the Coriolis acceleration on a moving guide).
fn slides_text(an: &Analysis, s: &Solved, l: Lang) -> String {
    let m = &an.mech;
    let mut t = String::new();
    let Some(order) = an.order else { return t };
    let r = results(l);
    let (ms, ms2) = (unit("m/s", l), unit("m/s²", l));
    for sl in &s.slides(an) {
        let pr = &m.prismatics[sl.pair];
        let slide = fill(
            &r.slide,
            &[
                ("slider", m.link_id(pr.slider)),
                ("guide", m.link_id(pr.guide)),
                ("point", m.point_name(pr.point)),
            ],
        );
        let _ = write!(t, "  {slide}: v_rel = {:.6} {ms}", unsigned_zero(sl.v, 6));
        if order == Order::Acceleration {
            let _ = write!(t, ", a_rel = {:.6} {ms2}", unsigned_zero(sl.a, 6));
            if pr.guide != m.frame() {
                let coriolis = &r.coriolis;
                let _ = write!(t, ", |{coriolis}| = {:.6} {ms2}", sl.coriolis.hypot());
            }
        }
        let _ = writeln!(t);
    }
    t
}

/// The position's cross-check line in `l`: the largest difference (or
/// residual), where, and what the routes cost.
fn check_text(c: &CrossCheck, l: Lang) -> String {
    let r = results(l);
    let diff = format!("{:.1e}", c.max_rel_diff);
    let worst = worst(&c.worst, l);
    let us = |x: f64| format!("{:.0}", x * 1e6);
    let (contour, other) = (us(c.contour_time), us(c.constraint_time));
    let line = match c.method {
        Method::Routes => fill(
            &r.routes,
            &[
                ("diff", &diff),
                ("worst", &worst),
                ("contour", &contour),
                ("constraint", &other),
                ("us", &r.microseconds),
            ],
        ),
        Method::Residuals { .. } => fill(
            &r.residuals,
            &[
                ("diff", &diff),
                ("worst", &worst),
                ("contour", &contour),
                ("check", &other),
                ("us", &r.microseconds),
            ],
        ),
    };
    format!("  {line}\n")
}

fn fmt(x: f64) -> String {
    crate::format::fixed(x, 6)
}
