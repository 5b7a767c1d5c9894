//! The result as a terminal table (`solve`, the default format): per
//! position the points' places, velocities and accelerations and the
//! links' rates, each with the routes' agreement and the printed bound.

use super::tables::{self, Cell, Kind, Table};
use crate::kinematics::analytic::Order;
use crate::kinematics::solve::Analysis;
use crate::model::scene::InputSpec;
use crate::pipeline::Solved;
use crate::verification::crosscheck::Method;
use crate::words::construction::Lang;
use std::fmt::Write as _;

/// The sense of rotation, "-" for a value that is zero up to rounding
/// (`scale` is the largest value of its kind at that position).
fn sense(x: f64, scale: f64) -> &'static str {
    if x.abs() <= 1e-12 * scale {
        "-"
    } else if x > 0.0 {
        "ccw"
    } else if x < 0.0 {
        "cw"
    } else {
        "-"
    }
}

/// A table for the terminal: points with |v|, |a|; links with ω, ε and senses.
pub fn to_table(an: &Analysis, solved: &[Solved]) -> String {
    let mut t = table_head(an);
    for (i, s) in solved.iter().enumerate() {
        t += &table_position(an, i, s);
    }
    t
}

/// The table's title and structure lines.
pub(super) fn table_head(an: &Analysis) -> String {
    let m = &an.mech;
    let mut t = String::new();
    if !m.scene.title.is_empty() {
        let _ = writeln!(t, "{}", m.scene.title);
    }
    let _ = writeln!(
        t,
        "structure: W = {}, {}   [{}]",
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
/// decimals, a rate followed by its sense.
fn table_text(table: &Table) -> String {
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
            Kind::Rate => write!(t, "{sep}{head:>w$} {:>5}", ""),
            _ => write!(t, "{sep}{head:>w$}"),
        };
    }
    t.push('\n');
    for row in table.groups.iter().flat_map(|g| &g.rows) {
        t.push_str("  ");
        for (n, &(i, w, d)) in columns.iter().enumerate() {
            let sep = if n > 0 { " " } else { "" };
            let _ = match &row[i] {
                Cell::Notation(s) | Cell::Plain(s) => write!(t, "{sep}{s:<w$}"),
                Cell::Number(x) => write!(t, "{sep}{x:>w$.d$}"),
                Cell::Rate { value, scale } => {
                    write!(t, "{sep}{value:>w$.d$} {:>5}", sense(*value, *scale))
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

/// The table of position `i` (from 0).
pub(super) fn table_position(an: &Analysis, i: usize, s: &Solved) -> String {
    let m = &an.mech;
    let mut t = String::new();
    let vel = an.order.is_some();
    let acc = an.order == Some(Order::Acceleration);
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
                        "φ{k} = {:.3}°, ω{k} = {} rad/s, ε{k} = {} rad/s²",
                        d.q.to_degrees().rem_euclid(360.0),
                        fmt(d.rate),
                        fmt(d.rate2)
                    )
                }
                InputSpec::Slider { .. } => format!(
                    "s{sub} = {} m, v{sub} = {} m/s, a{sub} = {} m/s²",
                    fmt(d.q),
                    fmt(d.rate),
                    fmt(d.rate2)
                ),
            }
        })
        .collect::<Vec<_>>()
        .join("; ");
    let _ = writeln!(t, "position {}: {input}", i + 1);
    t += &table_text(&tables::points(an, s, Lang::En));
    t += &table_text(&tables::links(an, s, Lang::En));
    let slides = s.slides(an);
    if vel && !slides.is_empty() {
        for sl in &slides {
            let pr = &m.prismatics[sl.pair];
            let _ = write!(
                t,
                "  slide of {} on {} at {}: v_rel = {:.6} m/s",
                m.link_id(pr.slider),
                m.link_id(pr.guide),
                m.point_name(pr.point),
                sl.v
            );
            if acc {
                let _ = write!(t, ", a_rel = {:.6} m/s²", sl.a);
                if pr.guide != m.frame() {
                    let _ = write!(t, ", |a_Coriolis| = {:.6} m/s²", sl.coriolis.hypot());
                }
            }
            let _ = writeln!(t);
        }
    }
    if let Some(c) = &s.check {
        let _ = match c.method {
            Method::Routes => writeln!(
                t,
                "  cross-check: max rel diff {:.1e} ({}); contour route {:.0} µs, constraint route {:.0} µs",
                c.max_rel_diff,
                c.worst,
                c.contour_time * 1e6,
                c.constraint_time * 1e6
            ),
            Method::Residuals { .. } => writeln!(
                t,
                "  cross-check by residuals: max rel residual {:.1e} ({}); contour route {:.0} µs, check {:.0} µs",
                c.max_rel_diff,
                c.worst,
                c.contour_time * 1e6,
                c.constraint_time * 1e6
            ),
        };
    }
    t
}

fn fmt(x: f64) -> String {
    crate::format::fixed(x, 6)
}
