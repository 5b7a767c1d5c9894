//! Which of a drawing's lines make the plan: those joined to the pole's
//! line, each touching the next ([`plan_lines`]). A teacher reads a sheet
//! so — the vectors meet at their points, while a frame, a title block or
//! a mechanism's scheme beside the plan touch none of them — and a label
//! names a point only at an end of these lines.

use crate::error::{Error, Issue, Result};
use kurbo::Point;
use std::collections::{HashMap, HashSet};

/// How near a line's end must come to another line to be drawn from it,
/// mm: a CAD's object snap puts it there exactly, a hand without the snap
/// within a pencil's width; a frame or a title block is drawn farther
/// from the plan than that.
pub const TOUCH_MM: f64 = 1.0;

/// The most segment samples kept to find which lines touch (a segment
/// past the budget is found touching at its ends only): a plan of a few
/// dozen lines on an A0 sheet needs some thousands.
const MAX_SAMPLES: usize = 4_000_000;

/// The most (line end, nearby segment) pairs looked at: a drawing crowded
/// past it is refused, not read for minutes.
const MAX_TOUCH_CHECKS: usize = 300_000_000;

/// The side of the cells segments are found in, mm: a segment sampled
/// every half cell has a sample within a quarter cell plus [`TOUCH_MM`]
/// of any point touching it, so in that point's cell or one of the eight
/// around it.
const CELL_MM: f64 = 8.0;

/// The cell a point is in (`as` saturates: far-off coordinates share the
/// outermost cells).
fn cell(p: Point) -> (i64, i64) {
    (
        (p.x / CELL_MM).floor() as i64,
        (p.y / CELL_MM).floor() as i64,
    )
}

/// The distance from `p` to the segment `a`–`b`.
fn to_segment(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let len2 = ab.hypot2();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - a.lerp(b, t)).hypot()
}

/// Segments in the cells they pass through: each its line's index and its
/// two ends.
type Segments = HashMap<(i64, i64), Vec<(usize, Point, Point)>>;

/// Which of the drawing's lines are the plan's: those joined to a line
/// through the pole's end `pole`, one by one, each touching the next (a
/// point of one — an end or a polyline's vertex — within [`TOUCH_MM`] of
/// the other, at its end or along it), as a plan's vectors meet at their
/// points. A frame, a title block's lines, a mechanism's scheme or a
/// second plan beside the plan touch none of its lines and are left out:
/// a label beside a frame's corner names no point.
///
/// Linear in the drawing's size: segments are sampled every half cell
/// into cells of [`CELL_MM`], and each point looks only at its cell and
/// the eight around it.
pub(super) fn plan_lines(lines: &[Vec<Point>], pole: Point) -> Result<Vec<bool>> {
    let finite = |p: &Point| p.x.is_finite() && p.y.is_finite();
    let mut cells: Segments = HashMap::new();
    let mut budget = MAX_SAMPLES;
    for (i, l) in lines.iter().enumerate() {
        let segments: Vec<(Point, Point)> = match l.as_slice() {
            [p] => vec![(*p, *p)],
            l => l.windows(2).map(|w| (w[0], w[1])).collect(),
        };
        for (a, b) in segments {
            if !(finite(&a) && finite(&b)) {
                continue;
            }
            let len = (b - a).hypot();
            let wanted = ((len / (CELL_MM / 2.0)).ceil().min(usize::MAX as f64) as usize).max(1);
            let steps = if wanted <= budget {
                budget -= wanted;
                wanted
            } else {
                1
            };
            let mut last = None;
            for k in 0..=steps {
                let c = cell(a.lerp(b, k as f64 / steps as f64));
                if last != Some(c) {
                    cells.entry(c).or_default().push((i, a, b));
                    last = Some(c);
                }
            }
        }
    }
    let mut parent: Vec<usize> = (0..lines.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut checks = 0usize;
    for (j, l) in lines.iter().enumerate() {
        for v in l.iter().filter(|p| finite(p)) {
            let (cx, cy) = cell(*v);
            for dx in -1..=1i64 {
                for dy in -1..=1i64 {
                    let key = (cx.saturating_add(dx), cy.saturating_add(dy));
                    for &(i, a, b) in cells.get(&key).into_iter().flatten() {
                        checks += 1;
                        if checks > MAX_TOUCH_CHECKS {
                            return Err(Error::fields(vec![Issue {
                                pointer: String::new(),
                                message: format!(
                                    "the drawing's lines are too crowded to be read (more than {MAX_TOUCH_CHECKS} line ends beside other lines); a plan is a few dozen lines: leave out hatching drawn as lines"
                                ),
                            }]));
                        }
                        let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                        if ri != rj && to_segment(*v, a, b) <= TOUCH_MM {
                            parent[ri] = rj;
                        }
                    }
                }
            }
        }
    }
    let poles: HashSet<usize> = (0..lines.len())
        .filter(|&i| lines[i].contains(&pole))
        .map(|i| root(&mut parent, i))
        .collect();
    Ok((0..lines.len())
        .map(|i| poles.contains(&root(&mut parent, i)))
        .collect())
}


#[cfg(test)]
mod tests {
    use super::*;

    /// The plan's vectors join at their ends and along a vector (a point
    /// on a segment, s2 on ab); a frame around them and a title block's
    /// lines touching the frame are not the plan, nor a line 2 mm off.
    #[test]
    fn the_plan_is_the_lines_joined_to_the_pole() {
        let p = |x: f64, y: f64| Point::new(x, y);
        let lines = vec![
            vec![p(0.0, 0.0), p(50.0, 0.0)],                // pole to a
            vec![p(50.0, 0.0), p(50.0, 40.0)],              // a to b
            vec![p(0.0, 0.0), p(50.0, 40.0)],               // pole to b
            vec![p(50.3, 20.0), p(80.0, 20.0)],             // from a point on ab
            vec![p(0.0, 2.0), p(-30.0, 20.0)],              // 2 mm off the pole
            vec![p(-100.0, -100.0), p(200.0, -100.0), p(200.0, 100.0), p(-100.0, 100.0), p(-100.0, -100.0)],
            vec![p(150.0, -100.0), p(150.0, -80.0)],        // title block
            vec![p(150.0, -80.0), p(200.0, -80.0)],
        ];
        let on = plan_lines(&lines, p(0.0, 0.0)).unwrap();
        assert_eq!(on, vec![true, true, true, true, false, false, false, false]);
    }
}
