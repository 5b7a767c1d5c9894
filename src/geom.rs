//! Planar geometry on top of kurbo: rigid poses, infinite lines, and the
//! three intersections the position analysis needs (circle∩circle,
//! circle∩line, line∩line). Degenerate geometry is a value, never a NaN.

use kurbo::{Point, Vec2};

/// Rotate `v` by `angle` radians counter-clockwise (y up).
#[inline]
pub fn rotate(v: Vec2, angle: f64) -> Vec2 {
    let (s, c) = angle.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// `k × v`: the vector turned by +90° (counter-clockwise), as in ω × r.
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    v.turn_90()
}

/// Wrap an angle to (−π, π].
pub fn wrap_pi(a: f64) -> f64 {
    let t = std::f64::consts::TAU;
    let mut x = a % t;
    if x <= -std::f64::consts::PI {
        x += t;
    } else if x > std::f64::consts::PI {
        x -= t;
    }
    x
}

/// The pose of a link: where its local frame sits in the world.
/// `world(p) = origin + R(angle)·p`. The pose carries the sine and cosine
/// of its angle, computed once where it is made: every point of a link is
/// placed by the same rotation, and the trigonometry would otherwise be
/// repeated for each (it was a quarter of a position's time).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub origin: Point,
    pub angle: f64,
    sin: f64,
    cos: f64,
}

impl Pose {
    pub const IDENTITY: Pose = Pose {
        origin: Point::ORIGIN,
        angle: 0.0,
        sin: 0.0,
        cos: 1.0,
    };

    /// The pose with origin `origin` turned by `angle`.
    #[inline]
    pub fn new(origin: Point, angle: f64) -> Pose {
        let (sin, cos) = angle.sin_cos();
        Pose {
            origin,
            angle,
            sin,
            cos,
        }
    }

    /// The pose with origin `origin` turned by `angle`, whose sine and
    /// cosine are `sin_cos` (`angle.sin_cos()`, computed already: the
    /// same pose as [`Pose::new`], to the bit, without computing them
    /// again).
    #[inline]
    pub fn with_sin_cos(origin: Point, angle: f64, (sin, cos): (f64, f64)) -> Pose {
        Pose {
            origin,
            angle,
            sin,
            cos,
        }
    }

    /// World position of a point given in the link's local frame.
    #[inline]
    pub fn apply(&self, local: Vec2) -> Point {
        self.origin + self.dir(local)
    }

    /// World direction of a direction given in the local frame.
    #[inline]
    pub fn dir(&self, local: Vec2) -> Vec2 {
        Vec2::new(
            self.cos * local.x - self.sin * local.y,
            self.sin * local.x + self.cos * local.y,
        )
    }

    /// Local coordinates of a world point (the inverse of [`Pose::apply`]).
    #[inline]
    pub fn local(&self, world: Point) -> Vec2 {
        let d = world - self.origin;
        Vec2::new(
            self.cos * d.x + self.sin * d.y,
            -self.sin * d.x + self.cos * d.y,
        )
    }

    /// This pose followed by `rel` (a pose in this pose's frame): the
    /// world pose of a frame placed at `rel` in this one.
    pub fn then(&self, rel: &Pose) -> Pose {
        Pose::new(self.apply(rel.origin.to_vec2()), self.angle + rel.angle)
    }

    /// The inverse pose: this pose's frame placed in the frame it is given in.
    pub fn inverse(&self) -> Pose {
        let angle = -self.angle;
        let turned = Pose::new(Point::ORIGIN, angle);
        Pose::new(Point::ORIGIN - turned.dir(self.origin.to_vec2()), angle)
    }

    /// The pose that puts local point `local` at world point `at`, turned by `angle`.
    pub fn through(at: Point, local: Vec2, angle: f64) -> Pose {
        let (sin, cos) = angle.sin_cos();
        Pose::through_turned(at, local, angle, (cos, sin))
    }

    /// As [`Pose::through`], with the cosine and sine of `angle` already
    /// known (from two directions, without trigonometry).
    pub fn through_turned(at: Point, local: Vec2, angle: f64, (cos, sin): (f64, f64)) -> Pose {
        let turned = Pose {
            origin: Point::ORIGIN,
            angle,
            sin,
            cos,
        };
        Pose {
            origin: at - turned.dir(local),
            ..turned
        }
    }
}

/// An infinite line: a point on it and a unit direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line {
    pub point: Point,
    pub dir: Vec2,
}

impl Line {
    pub fn new(point: Point, dir: Vec2) -> Line {
        Line {
            point,
            dir: dir.normalize(),
        }
    }
    /// Signed distance of `p` from the line, positive to the left of `dir`.
    pub fn signed_distance(&self, p: Point) -> f64 {
        self.dir.cross(p - self.point)
    }
}

/// Result of intersecting two lines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LineCut {
    /// One point, with the sine of the angle between the lines (reliability).
    Point { at: Point, sin_angle: f64 },
    /// Parallel (or coincident) to within `rel_tol` of the angle.
    Parallel,
}

/// Intersect two lines; `min_sin` is the smallest |sin(angle)| accepted.
pub fn intersect_lines(a: &Line, b: &Line, min_sin: f64) -> LineCut {
    let s = a.dir.cross(b.dir);
    if s.abs() <= min_sin {
        return LineCut::Parallel;
    }
    let t = (b.point - a.point).cross(b.dir) / s;
    LineCut::Point {
        at: a.point + a.dir * t,
        sin_angle: s.abs(),
    }
}

/// The two points where a circle (centre `c`, radius `r`) meets a line, or
/// `None` when they do not meet. `branch` (+1 / −1) picks the point whose
/// displacement from the foot of the perpendicular runs along (+1) or
/// against (−1) the line's direction: an orientation sign, not a root order.
/// A tangency within `tol` (length) is accepted as a double point.
pub fn circle_line(c: Point, r: f64, line: &Line, branch: f64, tol: f64) -> Option<Point> {
    let foot = line.point + line.dir * (c - line.point).dot(line.dir);
    let h = (c - foot).hypot();
    let d2 = r * r - h * h;
    let t = if d2 >= 0.0 {
        d2.sqrt()
    } else if h - r <= tol {
        0.0
    } else {
        return None;
    };
    Some(foot + line.dir * (branch * t))
}

/// The intersection of two circles (centres `a`, `b`, radii `ra`, `rb`),
/// picking the point on the side `branch` of the directed line a→b
/// (+1 left, −1 right). Tangency within `tol` is accepted.
pub fn circle_circle(a: Point, ra: f64, b: Point, rb: f64, branch: f64, tol: f64) -> Option<Point> {
    let d = b - a;
    let dist = d.hypot();
    if dist == 0.0 {
        return None;
    }
    let u = d / dist;
    let x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
    let h2 = ra * ra - x * x;
    let h = if h2 >= 0.0 {
        h2.sqrt()
    } else if (dist - (ra + rb)).abs() <= tol || (dist - (ra - rb).abs()).abs() <= tol {
        0.0
    } else {
        return None;
    };
    Some(a + u * x + perp(u) * (branch * h))
}

/// Sign with a dead band: +1, −1, or 0 when |x| ≤ tol.
pub fn sign_tol(x: f64, tol: f64) -> f64 {
    if x > tol {
        1.0
    } else if x < -tol {
        -1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_circle_left_and_right() {
        let a = Point::new(0.0, 0.0);
        let b = Point::new(2.0, 0.0);
        let l = circle_circle(a, 2f64.sqrt(), b, 2f64.sqrt(), 1.0, 1e-12).unwrap();
        let r = circle_circle(a, 2f64.sqrt(), b, 2f64.sqrt(), -1.0, 1e-12).unwrap();
        assert!((l - Point::new(1.0, 1.0)).hypot() < 1e-15);
        assert!((r - Point::new(1.0, -1.0)).hypot() < 1e-15);
        assert!(circle_circle(a, 0.5, b, 0.5, 1.0, 1e-12).is_none());
    }

    #[test]
    fn parallel_lines_are_a_value() {
        let a = Line::new(Point::ORIGIN, Vec2::new(1.0, 0.0));
        let b = Line::new(Point::new(0.0, 1.0), Vec2::new(1.0, 1e-15));
        assert_eq!(intersect_lines(&a, &b, 1e-12), LineCut::Parallel);
        let c = Line::new(Point::new(3.0, -1.0), Vec2::new(0.0, 1.0));
        match intersect_lines(&a, &c, 1e-12) {
            LineCut::Point { at, sin_angle } => {
                assert!((at - Point::new(3.0, 0.0)).hypot() < 1e-15);
                assert!((sin_angle - 1.0).abs() < 1e-15);
            }
            LineCut::Parallel => panic!("perpendicular lines reported parallel"),
        }
    }

    #[test]
    fn circle_line_branches_follow_direction() {
        let line = Line::new(Point::new(0.0, 1.0), Vec2::new(1.0, 0.0));
        let p = circle_line(Point::ORIGIN, 2.0, &line, 1.0, 1e-12).unwrap();
        let m = circle_line(Point::ORIGIN, 2.0, &line, -1.0, 1e-12).unwrap();
        assert!((p.x - 3f64.sqrt()).abs() < 1e-15 && (p.y - 1.0).abs() < 1e-15);
        assert!((m.x + 3f64.sqrt()).abs() < 1e-15);
        assert!(circle_line(Point::ORIGIN, 0.5, &line, 1.0, 1e-12).is_none());
    }

    #[test]
    fn wrap_is_half_open() {
        assert!((wrap_pi(std::f64::consts::PI) - std::f64::consts::PI).abs() < 1e-15);
        assert!((wrap_pi(-std::f64::consts::PI) - std::f64::consts::PI).abs() < 1e-15);
        assert!((wrap_pi(7.0) - (7.0 - std::f64::consts::TAU)).abs() < 1e-15);
    }
}
