//! The frame's walls on the plan of the mechanism: a guide's wall line with
//! its gaps where links cross it, and the hatching on the side away from
//! the links (ГОСТ 2.770); the sizes of guides, blocks and walls.

use super::canvas::{Canvas, Class};
use crate::geom::perp;
use kurbo::{Point, Vec2};

/// Draw a fixed guide's wall: its line, and its hatching beyond its own
/// blocks on the side fewer lines (`bodies`) and other blocks cross (they
/// pass the wall through gaps in it), else away from `centre`.
pub(super) fn draw_wall(
    c: &mut Canvas,
    (o, u, on): Wall,
    bodies: &[(Point, Point)],
    blocks: &[Block],
    centre: Point,
) {
    let ts = on.iter().map(|&(_, q)| (q - o).dot(u));
    let (lo, hi) = ts.fold((f64::MAX, f64::MIN), |(a, b), t| (a.min(t), b.max(t)));
    let (lo, hi) = (lo - GUIDE_HALF, hi + GUIDE_HALF);
    c.seg(o + u * lo, o + u * hi, Class::Main);
    let line = WallLine { o, u, lo, hi };
    let n = perp(u);
    let (above, below) = (
        line.gaps(1.0, &on, bodies, blocks),
        line.gaps(-1.0, &on, bodies, blocks),
    );
    let cut = |g: &[(f64, f64)]| g.iter().map(|g| g.1 - g.0).sum::<f64>();
    let toward_centre = (centre - o).dot(n);
    let side = if (cut(&above) - cut(&below)).abs() > 1e-9 {
        if cut(&above) < cut(&below) { 1.0 } else { -1.0 }
    } else if toward_centre > 0.0 {
        -1.0
    } else {
        1.0
    };
    let gaps = if side > 0.0 { above } else { below };
    line.hatch(c, side, &gaps);
}

/// A fixed guide's line: from `o + u·lo` to `o + u·hi`.
struct WallLine {
    o: Point,
    u: Vec2,
    lo: f64,
    hi: f64,
}

impl WallLine {
    /// The gaps (along the line) the wall on `side` (±1) needs for the
    /// lines crossing it and for the blocks of other sliders (not `on` it).
    fn gaps(
        &self,
        side: f64,
        on: &[(usize, Point)],
        bodies: &[(Point, Point)],
        blocks: &[Block],
    ) -> Vec<(f64, f64)> {
        let WallLine { o, u, lo, hi } = *self;
        let n = perp(u);
        let (near, far) = (side * WALL, side * (WALL + HATCH));
        let (b0, b1) = (o + u * lo + n * near, o + u * hi + n * near);
        let mut gaps: Vec<(f64, f64)> = bodies
            .iter()
            .filter_map(|&(p, q)| {
                let t0 = crossing_at(p, q, b0, b1);
                let t1 = crossing_at(p, q, b0 + n * (far - near), b1 + n * (far - near));
                t0.or(t1).map(|t| lo + t * (hi - lo))
            })
            .map(|t| (t - 1.2, t + 1.2))
            .collect();
        for (l, _, b) in blocks {
            if on.iter().any(|&(sl, _)| sl == *l) {
                continue;
            }
            // Across the wall's band: the block's extent across and along.
            let across = b.iter().map(|&p| (p - o).dot(n));
            let (a0, a1) = across.fold((f64::MAX, f64::MIN), |(x, y), v| (x.min(v), y.max(v)));
            if a1 < near.min(far) - 0.3 || a0 > near.max(far) + 0.3 {
                continue;
            }
            let along = b.iter().map(|&p| (p - o).dot(u));
            let (t0, t1) = along.fold((f64::MAX, f64::MIN), |(x, y), v| (x.min(v), y.max(v)));
            gaps.push((t0 - 0.6, t1 + 0.6));
        }
        gaps
    }

    /// Draw the wall on `side`: its line in pieces between the `gaps`, and
    /// its strokes where their feet are free.
    fn hatch(&self, c: &mut Canvas, side: f64, gaps: &[(f64, f64)]) {
        let WallLine { o, u, lo, hi } = *self;
        let n = perp(u);
        let free = |t: f64| !gaps.iter().any(|g| (g.0..=g.1).contains(&t));
        // The wall's line, in pieces between the gaps.
        let at = |t: f64| o + u * t + n * side * WALL;
        let steps = ((hi - lo) / 0.25).ceil() as usize;
        let mut start: Option<f64> = None;
        for k in 0..=steps {
            let t = lo + (hi - lo) * k as f64 / steps as f64;
            match (free(t), start) {
                (true, None) => start = Some(t),
                (false, Some(t0)) => {
                    c.seg(at(t0), at(t - (hi - lo) / steps as f64), Class::Hatch);
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(t0) = start {
            c.seg(at(t0), at(hi), Class::Hatch);
        }
        let count = ((hi - lo) / 3.0).round().max(1.0) as usize;
        for k in 0..=count {
            let t = lo + (hi - lo) * k as f64 / count as f64;
            // The stroke leans back along the wall: its foot must be free.
            if !free(t) || !free(t - HATCH) {
                continue;
            }
            let p = at(t);
            c.seg(p, p + (n * side - u) * HATCH, Class::Hatch);
        }
    }
}

/// A fixed guide's wall: a point of its line, its direction, and the
/// sliders on it with their points.
pub(super) type Wall = (Point, Vec2, Vec<(usize, Point)>);

/// Where segment `p`–`q` crosses segment `a`–`b`, as a share of `a`–`b`.
pub(super) fn crossing_at(p: Point, q: Point, a: Point, b: Point) -> Option<f64> {
    let (r, s) = (q - p, b - a);
    let den = r.cross(s);
    if den.abs() < 1e-12 {
        return None;
    }
    let t = (a - p).cross(s) / den;
    let v = (a - p).cross(r) / den;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&v)).then_some(v)
}

/// A slider block: its slider, its point and its corners (mm).
pub(super) type Block = (usize, Point, [Point; 4]);

/// Half the length of a fixed guide's line beyond its sliders (mm).
const GUIDE_HALF: f64 = 18.0;

/// A slider block's half length and half width (mm).
pub(super) const BLOCK: (f64, f64) = (5.0, 3.0);

/// How far a fixed guide's wall lies from its line: beyond the blocks.
const WALL: f64 = BLOCK.1 + 1.2;

/// The depth of a wall's hatching (mm).
const HATCH: f64 = 1.6;
