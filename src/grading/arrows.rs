//! Arrowheads of a drawing (a force plan's vectors drawn in an editor or
//! a CAD): which end of a line is its vector's head.
//!
//! An arrowhead is either marked on its line (an SVG `marker-end` or
//! `marker-start`) or drawn beside it as a small filled triangle (an SVG
//! closed path or polygon of three corners; a DXF SOLID, a closed
//! three-vertex polyline, either inside an inserted block too). A
//! triangle is a segment's arrowhead at one of its ends when it touches
//! that end (within [`TOUCH_MM`]) and points away from the segment's
//! other end (its tip, the corner opposite its shortest side, lies that
//! way within [`AXIS_DEG`]): at a joint of two vectors, where one's head
//! meets the next one's tail, the triangle is the first one's only.

use kurbo::Point;

/// How far from a line's end an arrowhead may be, mm.
pub(crate) const TOUCH_MM: f64 = 1.0;
/// The largest arrowhead read: its longest side, mm.
pub(crate) const SIZE_MM: f64 = 20.0;
/// How far a triangle's axis may turn from its segment, degrees.
const AXIS_DEG: f64 = 25.0;

/// An arrowhead of a drawing.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Head {
    /// A marker on line `line`: at its last point (`at_end`), else its
    /// first.
    Marked { line: usize, at_end: bool },
    /// A small filled triangle's corners, and the line that draws its
    /// outline when one does (no vector's).
    Triangle {
        corners: [Point; 3],
        line: Option<usize>,
    },
}

/// A triangle's corners when `points` (a closed outline: the first point
/// repeated last or not) are three distinct corners no longer than
/// [`SIZE_MM`] a side.
pub(crate) fn triangle(points: &[Point]) -> Option<[Point; 3]> {
    let mut ps: Vec<Point> = points.to_vec();
    if ps.len() == 4 && (ps[3] - ps[0]).hypot() < 1e-9 {
        ps.pop();
    }
    let [a, b, c] = ps[..] else { return None };
    let sides = [(b - a).hypot(), (c - b).hypot(), (a - c).hypot()];
    let area = (b - a).cross(c - a).abs() / 2.0;
    let longest = sides.iter().copied().fold(0.0, f64::max);
    (longest.is_finite() && longest <= SIZE_MM && area > 1e-6 * longest * longest)
        .then_some([a, b, c])
}

/// The lines that draw an arrowhead (not a vector).
pub(crate) fn head_lines(heads: &[Head]) -> Vec<usize> {
    heads
        .iter()
        .filter_map(|h| match h {
            Head::Triangle { line, .. } => *line,
            Head::Marked { .. } => None,
        })
        .collect()
}

/// Whether a triangle is the arrowhead of segment `from` → `end` at `end`.
fn points_at(corners: &[Point; 3], from: Point, end: Point) -> bool {
    let u = end - from;
    if u.hypot() == 0.0 {
        return false;
    }
    let (touches, _) = distance(corners, end);
    // The tip: the corner opposite the shortest side.
    let k = (0..3)
        .min_by(|&i, &j| side(corners, i).total_cmp(&side(corners, j)))
        .unwrap_or(0);
    let base = corners[(k + 1) % 3].midpoint(corners[(k + 2) % 3]);
    let axis = corners[k] - base;
    touches <= TOUCH_MM
        && axis.hypot() > 0.0
        && axis.dot(u) >= AXIS_DEG.to_radians().cos() * axis.hypot() * u.hypot()
}

/// The length of the side opposite corner `k`.
fn side(c: &[Point; 3], k: usize) -> f64 {
    (c[(k + 2) % 3] - c[(k + 1) % 3]).hypot()
}

/// How far a point is from a triangle (0 inside), and whether inside.
fn distance(c: &[Point; 3], p: Point) -> (f64, bool) {
    let s = |a: Point, b: Point| (b - a).cross(p - a);
    let (d1, d2, d3) = (s(c[0], c[1]), s(c[1], c[2]), s(c[2], c[0]));
    let neg = d1 < 0.0 || d2 < 0.0 || d3 < 0.0;
    let pos = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
    if !(neg && pos) {
        return (0.0, true);
    }
    let to_side = |a: Point, b: Point| {
        let ab = b - a;
        let t = ((p - a).dot(ab) / ab.hypot2()).clamp(0.0, 1.0);
        (p - (a + ab * t)).hypot()
    };
    let d = to_side(c[0], c[1])
        .min(to_side(c[1], c[2]))
        .min(to_side(c[2], c[0]));
    (d, false)
}

/// The most segment ends a triangle looks among (a joint of a force plan
/// holds a few; a cell of a hostile file, thousands).
const MAX_NEAR: usize = 64;

/// The most arrowheads a drawing may hold (a force plan has tens).
pub(crate) const MAX_HEADS: usize = 10_000;

/// The sense of each segment `(a, b, line, k)` (segment `k` of line
/// `line`, points `a` → `b`): `Some(true)` when its only arrowhead is at
/// `b`, `Some(false)` at `a`, `None` when it has none or one at each end.
/// A triangle that could be the head of several segments (at a joint
/// where the next vector turns back along the one before) is the one
/// left once the segments whose head is known elsewhere are set aside;
/// one still in doubt is no segment's.
pub(crate) fn senses(heads: &[Head], lines: &[Vec<Point>], segs: &[(Point, Point, usize, usize)]) -> Vec<Option<bool>> {
    let mut at = vec![(false, false); segs.len()];
    // Each line's markers (at its start, at its end), read once: linear in
    // the lines and the heads, whatever a hostile file holds.
    let mut marks = vec![(false, false); lines.len()];
    for h in heads {
        if let Head::Marked { line, at_end } = *h
            && let Some(m) = marks.get_mut(line)
        {
            if at_end { m.1 = true } else { m.0 = true }
        }
    }
    // Segment ends by grid cell, where a triangle looks for them.
    let cell = |p: Point| ((p.x / 32.0).floor() as i64, (p.y / 32.0).floor() as i64);
    let mut grid: std::collections::HashMap<(i64, i64), Vec<usize>> = Default::default();
    for (i, &(a, b, line, k)) in segs.iter().enumerate() {
        let last = k + 2 == lines[line].len();
        at[i].1 |= marks[line].1 && last;
        at[i].0 |= marks[line].0 && k == 0;
        for p in [a, b] {
            grid.entry(cell(p)).or_default().push(i);
        }
    }
    let mut open: Vec<Vec<(usize, bool)>> = Vec::new();
    for h in heads {
        let Head::Triangle { corners, .. } = h else { continue };
        let (cx, cy) = cell(corners[0]);
        let near: Vec<usize> = (-1..=1)
            .flat_map(|dx| (-1..=1).map(move |dy| (cx + dx, cy + dy)))
            .flat_map(|c| grid.get(&c).into_iter().flatten().copied())
            .collect();
        // A triangle among more segment ends than a plan's joint holds is
        // no one's (a hostile pile of lines: bounded work per triangle).
        if near.len() > MAX_NEAR {
            open.push(Vec::new());
            continue;
        }
        let mut cands: Vec<(usize, bool)> = Vec::new();
        for i in near {
            let (a, b, ..) = segs[i];
            for (end, yes) in [(true, points_at(corners, a, b)), (false, points_at(corners, b, a))] {
                if yes && !cands.contains(&(i, end)) {
                    cands.push((i, end));
                }
            }
        }
        open.push(cands);
    }
    let set = |at: &mut Vec<(bool, bool)>, (i, end): (usize, bool)| {
        if end { at[i].1 = true } else { at[i].0 = true }
    };
    loop {
        let mut changed = false;
        for cands in open.iter_mut().filter(|c| !c.is_empty()) {
            if cands.len() > 1 {
                // A segment whose head is known at its other end is not
                // this triangle's.
                let keep: Vec<(usize, bool)> = cands
                    .iter()
                    .copied()
                    .filter(|&(i, end)| !(if end { at[i].0 } else { at[i].1 }))
                    .collect();
                if !keep.is_empty() {
                    *cands = keep;
                }
            }
            if cands.len() == 1 {
                set(&mut at, cands[0]);
                cands.clear();
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    at.into_iter()
        .map(|ends| match ends {
            (false, true) => Some(true),
            (true, false) => Some(false),
            _ => None,
        })
        .collect()
}

/// A DXF LWPOLYLINE's arrowheads drawn by its width (`codes`: its
/// groups, 40 and 41 each vertex's start and end width): a segment whose
/// width tapers to 0 is a triangle, its base at the segment's start, its
/// tip at its end, pushed to `heads` (its corners; the size is checked
/// in mm by [`triangle`]). Its vertices back, the shaft's end left out
/// where the head goes on straight along it (shaft and head one vector).
pub(crate) fn taper(
    ps: &[(Point, f64)],
    codes: &[(i32, &str)],
    heads: &mut Vec<(Vec<Point>, Option<usize>)>,
) -> Vec<(Point, f64)> {
    let mut w = vec![(0.0, 0.0); ps.len()];
    let mut k: Option<usize> = None;
    let num = |v: &str| v.trim().parse::<f64>().ok().filter(|x| x.is_finite());
    for &(c, v) in codes {
        match c {
            10 => k = Some(k.map_or(0, |k| k + 1)),
            40 | 41 => {
                if let (Some(x), Some(n)) = (k.and_then(|k| w.get_mut(k)), num(v)) {
                    if c == 40 { x.0 = n } else { x.1 = n }
                }
            }
            _ => {}
        }
    }
    let mut out: Vec<(Point, f64)> = Vec::new();
    for (i, &(p, bulge)) in ps.iter().enumerate() {
        let Some(&(tip, _)) = ps.get(i + 1) else {
            out.push((p, bulge));
            continue;
        };
        let u = tip - p;
        if bulge == 0.0 && w[i].0 > 0.0 && w[i].1 == 0.0 && u.hypot() > 0.0 {
            let n = kurbo::Vec2::new(-u.y, u.x).normalize() * (w[i].0 / 2.0);
            heads.push((vec![tip, p + n, p - n], None));
            // The shaft going on straight into the head: one vector.
            if let Some(&(prev, 0.0)) = out.last() {
                let v = p - prev;
                if v.dot(u) > 0.0 && v.cross(u).abs() <= 1e-3 * v.hypot() * u.hypot() {
                    continue;
                }
            }
        }
        out.push((p, bulge));
    }
    out
}

/// The direction of a vector drawn from `a` to `b` (mm, y down as
/// drawn), degrees counter-clockwise from +x in [0, 360), y up.
pub(crate) fn direction(a: Point, b: Point) -> f64 {
    let d = (-(b.y - a.y)).atan2(b.x - a.x).to_degrees();
    if d < 0.0 { d + 360.0 } else { d }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle at the joint of two vectors is the arriving one's head,
    /// not the leaving one's tail.
    #[test]
    fn a_triangle_at_a_joint_is_the_arriving_vectors() {
        let (a, j, c) = (
            Point::new(0.0, 0.0),
            Point::new(30.0, 0.0),
            Point::new(30.0, -30.0),
        );
        let tri = [j, Point::new(26.0, -1.0), Point::new(26.0, 1.0)];
        let heads = vec![Head::Triangle {
            corners: tri,
            line: None,
        }];
        let lines = vec![vec![a, j], vec![j, c]];
        let segs = [(a, j, 0, 0), (j, c, 1, 0)];
        assert_eq!(senses(&heads, &lines, &segs), vec![Some(true), None]);
        // The next vector turning back along the first: its own head
        // at its end tells the joint's is the first's.
        let back = Point::new(20.0, 0.0);
        let lines = vec![vec![a, j], vec![j, back]];
        let mut heads = heads;
        heads.push(Head::Triangle {
            corners: [back, Point::new(24.0, -1.0), Point::new(24.0, 1.0)],
            line: None,
        });
        let segs = [(a, j, 0, 0), (j, back, 1, 0)];
        assert_eq!(senses(&heads, &lines, &segs), vec![Some(true), Some(true)]);
        assert_eq!(direction(j, c), 90.0);
        assert!(triangle(&[a, j, c, a]).is_none(), "too big");
        assert!(triangle(&tri).is_some());
    }
}
