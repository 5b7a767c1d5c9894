//! The tables of results of a position, built once as data (columns and
//! rows of cells) and rendered by the terminal's table
//! ([`crate::presentation::report`], `solve --format table`) and by the
//! handout ([`crate::presentation::drawing::html`]): the points (where,
//! how fast, which way), the links (angle, ω, ε with their senses) and what
//! was measured on the plans.
//!
//! A column says what it holds ([`Kind`]); each medium shows the kinds it
//! has room for: the terminal every number (the measured segments are in
//! `solve --steps`), the handout the magnitudes, the rates and the
//! measured segments (where the points are and which way they move, its
//! drawings show). Numbers are kept as numbers: each medium writes them
//! in its own way.

use crate::format::num;
use crate::kinematics::analytic::Order;
use crate::kinematics::construction::{Measured, Plan, PlanKind, Plans};
use crate::kinematics::solve::Analysis;
use crate::pipeline::Solved;
use crate::words::catalogue::TablePhrases;
use crate::words::construction::Lang;

/// What a column holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Which point or link the row is about.
    Name,
    /// A point's coordinate, m.
    Coordinate,
    /// A magnitude: |v|, |a|.
    Magnitude,
    /// The direction of a vector, degrees.
    Direction,
    /// A link's angle, degrees.
    Angle,
    /// A signed angular rate, with its sense.
    Rate,
    /// A segment measured on a plan, with its length.
    Segment,
    /// A value measured on a plan, with its drafting bound.
    Measured,
}

/// A column: what it holds, its heading and unit (in the table's language).
#[derive(Clone, Debug)]
pub struct Column {
    pub kind: Kind,
    /// The quantity's symbol or the column's word: "|v|", "point".
    pub head: String,
    /// The unit, when the heading does not say it.
    pub unit: Option<String>,
}

/// A cell of a row.
#[derive(Clone, Debug)]
pub enum Cell {
    /// A point's name or a quantity, in the lecture's notation (`B3`,
    /// `v_BA`): on the page with its subscripts.
    Notation(String),
    /// A link's id, as it is.
    Plain(String),
    /// A number.
    Number(f64),
    /// A signed angular rate (counter-clockwise positive); zero when it is
    /// below 1e-12 of `scale`, the largest rate of its kind at the position.
    Rate { value: f64, scale: f64 },
    /// A segment of a plan and its length, mm: `p_vb = 34.46`.
    Segment { name: String, mm: f64 },
    /// A measured value (a [`Cell::Number`] or a [`Cell::Rate`]) with its
    /// drafting bound and unit.
    Measured {
        value: Box<Cell>,
        bound: f64,
        unit: String,
    },
    /// Not known at this position (a link not solved).
    Missing,
}

/// Rows under a title of their own (a plan's), or under none.
#[derive(Clone, Debug)]
pub struct Group {
    pub title: Option<String>,
    pub rows: Vec<Vec<Cell>>,
}

/// A table: a caption, columns, and rows in groups.
#[derive(Clone, Debug)]
pub struct Table {
    pub caption: String,
    /// A class the handout gives it (`measured`).
    pub class: Option<&'static str>,
    pub columns: Vec<Column>,
    pub groups: Vec<Group>,
}

/// The tables' words in `l` (its catalogue's).
fn words(l: Lang) -> &'static TablePhrases {
    &crate::words::catalogue(l).tables
}

/// A unit in language `l`: "м/с²" for "m/s²".
pub fn unit(u: &str, l: Lang) -> String {
    crate::words::numbers::unit(u, l)
}

fn column(kind: Kind, head: &str, u: Option<&str>, l: Lang) -> Column {
    Column {
        kind,
        head: head.to_string(),
        unit: u.map(|u| unit(u, l)),
    }
}

/// How many orders of rates the analysis has: 0 (positions only), 1
/// (velocities), 2 (accelerations too).
fn orders(an: &Analysis) -> usize {
    match an.order {
        None => 0,
        Some(Order::Acceleration) => 2,
        Some(_) => 1,
    }
}

/// A table of one group with no title. Its columns are cut to `wide`, and
/// each row to its columns, missing cells at the end where a rate is not
/// known: the builders below give every column they have.
fn table(caption: &str, mut columns: Vec<Column>, wide: usize, rows: Vec<Vec<Cell>>) -> Table {
    columns.truncate(wide);
    let rows = rows
        .into_iter()
        .map(|mut row| {
            row.resize(columns.len(), Cell::Missing);
            row
        })
        .collect();
    Table {
        caption: caption.to_string(),
        class: None,
        columns,
        groups: vec![Group { title: None, rows }],
    }
}

/// The table of the points at a position: name, x, y, then |v| and the
/// direction of v, |a| and the direction of a, as far as the analysis goes.
pub fn points(an: &Analysis, s: &Solved, l: Lang) -> Table {
    let columns = vec![
        column(Kind::Name, &words(l).point, None, l),
        column(Kind::Coordinate, "x", Some("m"), l),
        column(Kind::Coordinate, "y", Some("m"), l),
        column(Kind::Magnitude, "|v|", Some("m/s"), l),
        column(Kind::Direction, "∠v", Some("°"), l),
        column(Kind::Magnitude, "|a|", Some("m/s²"), l),
        column(Kind::Direction, "∠a", Some("°"), l),
    ];
    // A vector's magnitude and direction; a vector at rest beside the
    // position's largest (a billionth of it: a dead centre's rounding) has
    // no direction to give.
    let (v_top, a_top) = an.points.iter().fold((0.0f64, 0.0f64), |(v, a), &p| {
        s.point(an, p)
            .rates
            .map_or((v, a), |(pv, pa)| (v.max(pv.hypot()), a.max(pa.hypot())))
    });
    let polar = |v: kurbo::Vec2, top: f64| {
        let r = v.hypot();
        match r > 1e-9 * top {
            true => [Cell::Number(r), Cell::Number(v.atan2().to_degrees())],
            false => [Cell::Number(0.0), Cell::Plain("—".into())],
        }
    };
    let rows = an
        .points
        .iter()
        .map(|&p| {
            let ps = s.point(an, p);
            let mut row = vec![
                Cell::Notation(an.mech.point_name(p).to_string()),
                Cell::Number(ps.at.x),
                Cell::Number(ps.at.y),
            ];
            if let Some((v, a)) = ps.rates {
                row.extend(polar(v, v_top));
                row.extend(polar(a, a_top));
            }
            row
        })
        .collect();
    table(&words(l).points, columns, 3 + 2 * orders(an), rows)
}

/// The largest |ω| and |ε| of the links at a position: the scales below
/// which a rate is zero.
fn rate_scales(s: &Solved) -> (f64, f64) {
    s.motion
        .iter()
        .flatten()
        .fold((0.0f64, 0.0f64), |(w, e), mo| {
            (w.max(mo.omega.abs()), e.max(mo.epsilon.abs()))
        })
}

/// The table of the moving links at a position: id, angle, then ω and ε
/// with their senses, as far as the analysis goes.
pub fn links(an: &Analysis, s: &Solved, l: Lang) -> Table {
    let m = &an.mech;
    let columns = vec![
        column(Kind::Name, &words(l).link, None, l),
        column(Kind::Angle, &words(l).angle, Some("°"), l),
        column(Kind::Rate, "ω", Some("rad/s"), l),
        column(Kind::Rate, "ε", Some("rad/s²"), l),
    ];
    let (ws, es) = rate_scales(s);
    let rows = (0..m.links.len())
        .filter(|&k| an.link(k) && k != m.frame())
        .map(|k| {
            let angle = crate::geom::wrap_pi(s.config.pose(k).angle).to_degrees();
            let mut row = vec![Cell::Plain(m.link_id(k).to_string()), Cell::Number(angle)];
            if let Some(mo) = s.motion[k] {
                let rate = |value, scale| Cell::Rate { value, scale };
                row.extend([rate(mo.omega, ws), rate(mo.epsilon, es)]);
            }
            row
        })
        .collect();
    table(&words(l).links, columns, 2 + orders(an), rows)
}

/// A measured segment's name: its ends' names run together ("p_vb", "ab").
pub fn segment(plan: &Plan, q: &Measured) -> String {
    format!("{}{}", plan.points[q.from].name(), plan.points[q.to].name())
}

/// The unit of a measured quantity (an angular rate's or a point's).
fn measured_unit(plan: &Plan, q: &Measured) -> &'static str {
    match (q.quantity.starts_with(['ω', 'ε']), plan.kind) {
        (true, PlanKind::Velocity) => "rad/s",
        (true, PlanKind::Acceleration) => "rad/s²",
        (false, PlanKind::Velocity) => "m/s",
        (false, PlanKind::Acceleration) => "m/s²",
    }
}

/// What was measured on the plans of a position: a group per plan (titled
/// with its worst intersection angle and δ), a row per quantity: the
/// quantity, the segment and its length, the value with its drafting
/// bound (an angular rate as its magnitude and sense, as in the links').
/// `titles`: the plans' names (of velocities, of accelerations).
pub fn measured(plans: &Plans, titles: [&str; 2], l: Lang) -> Table {
    let mm = unit("mm", l);
    let groups = [Some(&plans.velocity), plans.acceleration.as_ref()]
        .into_iter()
        .zip(titles)
        .filter_map(|(plan, title)| Some((plan?, title)))
        .map(|(plan, title)| {
            let title = format!(
                "{title}: {} {}°, δ = {} {mm}",
                &words(l).worst,
                num(plan.worst_angle_deg()),
                num(plan.delta)
            );
            let rows = plan
                .measured
                .iter()
                .map(|q| {
                    let u = measured_unit(plan, q);
                    let value = if u.starts_with("rad") {
                        Cell::Rate {
                            value: q.value,
                            scale: q.value.abs(),
                        }
                    } else {
                        Cell::Number(q.value)
                    };
                    vec![
                        Cell::Notation(q.quantity.clone()),
                        Cell::Segment {
                            name: segment(plan, q),
                            mm: q.mm,
                        },
                        Cell::Measured {
                            value: Box::new(value),
                            bound: q.bound,
                            unit: unit(u, l),
                        },
                    ]
                })
                .collect();
            Group {
                title: Some(title),
                rows,
            }
        })
        .collect();
    Table {
        caption: words(l).measured.to_string(),
        class: Some("measured"),
        columns: vec![
            column(Kind::Name, "", None, l),
            column(Kind::Segment, &words(l).segment, Some("mm"), l),
            column(Kind::Measured, &words(l).value, None, l),
        ],
        groups,
    }
}
