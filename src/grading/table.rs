//! What an answer gives of each plan point, as a replay takes it: a point
//! drawn (`points`, a drawing's label), or a table's measures of it — a
//! segment from the pole with its direction is the point itself; a
//! segment from the pole without it, or the value |v_X| (|a_X|) alone,
//! puts the point on a circle about the pole ([`Drawing::circles`]). Each
//! is then judged at the step that draws it from the student's own earlier
//! points, as a drawn point is: a table is judged by its own steps, not
//! only against the true plan.

use super::answer::{Given, Quantity, split_segment};
use super::candidates::Builds;
use super::items::resolve;
use crate::kinematics::construction::{Drawing, Plan, PointId};
use kurbo::Vec2;

/// How an item gives a plan point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Gives {
    /// Drawn, or a segment from the pole with its direction: its place.
    Place(Vec2, f64),
    /// A length from the pole (a segment, or a value over μ): its circle.
    Circle(f64, f64),
}

/// The plan point `standard` has at index `i`, as a replay finds it: its
/// id and which of that id's points it is.
fn id_of(standard: &Plan, i: usize) -> (PointId, usize) {
    let id = standard.points[i].id;
    (id, standard.points[..i].iter().filter(|p| p.id == id).count())
}

/// The plan point a segment `key` runs to from the pole, and whether it
/// is written from the pole (`p_v b`) or to it (`b p_v`).
fn from_pole(standard: &Plan, key: &str) -> Option<(usize, bool)> {
    let known = |s: &str| resolve(standard, s).is_some();
    let (a, b) = split_segment(key, &known)?;
    match (resolve(standard, &a)?, resolve(standard, &b)?) {
        (0, i) if i != 0 => Some((i, true)),
        (i, 0) if i != 0 => Some((i, false)),
        _ => None,
    }
}

/// The plan point (index in `standard`) item `k` of the answer gives, and
/// how: every point drawn; a segment from the pole (with its direction
/// where the answer gives one, the direction's item then giving it too);
/// a value of a named point where the answer gives nothing else of it.
pub(super) fn gives(b: &Builds, standard: &Plan) -> Vec<Option<(usize, Gives)>> {
    let items = &b.ans.items;
    let drawn: Vec<Option<usize>> = items
        .iter()
        .map(|it| match &it.given {
            Given::Point { name, .. } => resolve(standard, name).filter(|&i| i != 0),
            _ => None,
        })
        .collect();
    let angle_of = |i: usize| {
        items.iter().enumerate().find_map(|(k, it)| match &it.given {
            Given::Angle { from, deg, .. } => {
                let (j, out) = from_pole(standard, from)?;
                let deg = if out { *deg } else { deg + 180.0 };
                (j == i).then_some((k, deg, it.rounding))
            }
            _ => None,
        })
    };
    let mut out: Vec<Option<(usize, Gives)>> = vec![None; items.len()];
    let mut taken: Vec<usize> = drawn.iter().flatten().copied().collect();
    for (k, it) in items.iter().enumerate() {
        if let (Some(i), Given::Point { at, .. }) = (drawn[k], &it.given) {
            out[k] = Some((i, Gives::Place(Vec2::new(at[0], at[1]), it.rounding)));
        }
    }
    for (k, it) in items.iter().enumerate() {
        let Given::Segment { from, mm, .. } = &it.given else {
            continue;
        };
        let Some((i, _)) = from_pole(standard, from).filter(|(i, _)| !taken.contains(i)) else {
            continue;
        };
        taken.push(i);
        out[k] = Some(match angle_of(i) {
            Some((a, deg, rounding)) => {
                let at = Vec2::from_angle(deg.to_radians()) * *mm;
                // Along the segment its length's rounding, across it its
                // direction's.
                let r = it.rounding.hypot(mm * rounding.to_radians());
                out[a] = Some((i, Gives::Place(at, r)));
                (i, Gives::Place(at, r))
            }
            None => (i, Gives::Circle(*mm, it.rounding)),
        });
    }
    for (k, it) in items.iter().enumerate() {
        let Given::Value {
            quantity: Quantity::Point(name),
            value,
        } = &it.given
        else {
            continue;
        };
        let Some(i) = b
            .an
            .mech
            .scene
            .point_index(name)
            .and_then(|p| standard.of_point[p])
            .filter(|&i| i != 0 && !taken.contains(&i))
        else {
            continue;
        };
        taken.push(i);
        let mu = b.ans.mu;
        // A value's digits place its circle no worse than the pencil's
        // twice: v_B = 0.6 written for 0.58 is read off coarsely, and a
        // 12 mm ring would let any point through.
        let rounding = (it.rounding / mu).min(2.0 * b.ans.delta);
        out[k] = Some((i, Gives::Circle(value / mu, rounding)));
    }
    out
}

/// The answer's points and circles as a replay takes them.
pub(super) fn drawing(b: &Builds, standard: &Plan) -> Drawing {
    let mut out = Drawing {
        points: Vec::new(),
        triads: standard.triads.clone(),
        circles: Vec::new(),
    };
    let mut seen = Vec::new();
    for (i, g) in gives(b, standard).into_iter().flatten() {
        if seen.contains(&i) {
            continue;
        }
        seen.push(i);
        let (id, nth) = id_of(standard, i);
        match g {
            Gives::Place(at, r) => out.points.push((id, nth, at, r)),
            Gives::Circle(radius, r) => out.circles.push((id, nth, radius, r)),
        }
    }
    out
}
