//! Rigid shapes by the contract's rule, exact to the data.
//!
//! A link's first two points form its base (origin and +x axis); every
//! further point P is placed by its distances to two earlier points of the
//! link, on the side of their line where the sketch has it. Three choices
//! keep the shape as exact as the data:
//!
//! - Where no length from `lengths` enters P's placement (nor that of its
//!   two reference points), the triangle rule would only reproduce the
//!   sketch: P takes its own sketch position in the link's frame, with no
//!   round trip through distances ([`Placement::Sketch`]).
//! - A triangle is computed stably however thin it is: sides sorted, the
//!   area from Kahan's four bracketed factors, the foot of the apex from a
//!   cancellation-free grouping of the law of cosines ([`apex`]). A needle
//!   1e9 : 1 keeps a few ulps of its longest side.
//! - P is on the line of its two references only where the data put it
//!   there: the sketch draws it on that line to the rounding of its
//!   coordinates **and** the distances close the degenerate triangle to
//!   the rounding of the data ([`Placement::OnLine`]). No tolerance on
//!   distances ever snaps a real triangle onto its base.
//!
//! The *decisions* (which rule, which side) are taken once, from the data
//! as written; [`shape`] takes them, or follows them when given. The data
//! sensitivity check rebuilds the shapes from data moved by a few units of
//! rounding with the same decisions: rounding must not change the rule.

use crate::format::format_quantity as quantity;
use crate::model::scene::Scene;
use kurbo::{Point, Vec2};

/// Unit roundoff of f64 (half the machine epsilon).
const U: f64 = f64::EPSILON / 2.0;

/// How one point of a link is placed in the link's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Placement {
    /// The first point: the origin of the link's frame.
    Origin,
    /// The second point: on the frame's +x axis at its distance from the first.
    Base,
    /// The sketch position, carried into the link's frame (no length of
    /// `lengths` is involved: the triangle rule would give the same).
    Sketch,
    /// On the line through earlier points `refs` (indices in the link).
    OnLine { refs: (usize, usize) },
    /// The apex of the triangle on `refs`, on side `side` (+1 to the left of
    /// refs.0 → refs.1, −1 to the right).
    Triangle { refs: (usize, usize), side: f64 },
}

/// A problem with one point of a link: the index of the point in the
/// link's list and the message.
#[derive(Clone, Debug)]
pub struct ShapeIssue {
    /// Index of the point in the link's `points`; `None`: the link as a whole.
    pub point: Option<usize>,
    pub message: String,
}

/// The given length between two points, if `lengths` has it.
pub fn given(scene: &Scene, a: usize, b: usize) -> Option<f64> {
    scene
        .lengths
        .iter()
        .find(|l| (l.a == a && l.b == b) || (l.a == b && l.b == a))
        .map(|l| l.value)
}

fn sketch(scene: &Scene, p: usize) -> Point {
    scene.points[p].sketch
}

/// The distance the rule uses between two points: `lengths`, else the sketch.
pub fn distance(scene: &Scene, a: usize, b: usize) -> f64 {
    given(scene, a, b).unwrap_or_else(|| sketch(scene, a).distance(sketch(scene, b)))
}

/// The two reference points of the k-th point of a link (indices in the
/// link): those that `lengths` pairs with it first, in the link's order,
/// then the earliest others.
pub fn references(scene: &Scene, pts: &[usize], k: usize) -> (usize, usize) {
    let p = pts[k];
    let mut refs = (0..k).filter(|&j| given(scene, p, pts[j]).is_some());
    let mut rest = (0..k).filter(|&j| given(scene, p, pts[j]).is_none());
    let j1 = refs.next().or_else(|| rest.next()).expect("k ≥ 2");
    let j2 = refs.next().or_else(|| rest.next()).expect("k ≥ 2");
    (j1, j2)
}

/// The rounding of the sketch's data around a link: its points' largest
/// coordinate magnitude. Distances and directions read off the sketch are
/// known to a few units of rounding of this.
fn sketch_magnitude(scene: &Scene, pts: &[usize]) -> f64 {
    pts.iter()
        .map(|&p| sketch(scene, p).to_vec2().hypot())
        .fold(0.0, f64::max)
}

/// Is `p` drawn on the line through `a` and `b`, to the rounding of the
/// three points' coordinates? Returns the side (+1 left, −1 right) and
/// whether it is on the line.
fn sketch_side(a: Point, b: Point, p: Point) -> (f64, bool) {
    let (ab, ap) = (b - a, p - a);
    let cross = ab.cross(ap);
    // Each coordinate carries up to U·|x| of the decimal's rounding, each
    // difference and product a few U more: a bound on the cross product's
    // error, to first order, with a safety factor.
    let mag = a.to_vec2().hypot() + b.to_vec2().hypot() + p.to_vec2().hypot();
    let tol = 16.0 * U * ((mag + ab.hypot()) * ap.hypot() + ab.hypot() * (mag + ap.hypot()));
    (if cross >= 0.0 { 1.0 } else { -1.0 }, cross.abs() <= tol)
}

/// The apex P of a triangle on base `a → b` with |P − a| = r1 and
/// |P − b| = r2, on side `side`: `Ok((P, h))` with h the height, or
/// `Err(deficit)` when the sides violate the triangle inequality by
/// `deficit` (> 0). `flat` puts P on the line (h = 0) whatever the area.
///
/// Stable for needle-like triangles: the area by Kahan's formula (sides
/// sorted p ≥ q ≥ r, K = ¼·√((p+(q+r))(r−(p−q))(r+(p−q))(p+(q−r))),
/// each bracket as written), and the foot of the apex x = (d² + r1² − r2²)
/// / 2d with the difference of the two closest squares taken as a product
/// (d−r2)(d+r2) or (r1−r2)(r1+r2), where it cancels exactly (Sterbenz).
pub fn apex(a: Vec2, b: Vec2, r1: f64, r2: f64, side: f64, flat: bool) -> Result<(Vec2, f64), f64> {
    let ab = b - a;
    let d = ab.hypot();
    let mut s = [d, r1, r2];
    s.sort_by(|x, y| y.total_cmp(x));
    let [p, q, r] = s;
    let deficit = (p - q) - r;
    let h = if flat {
        0.0
    } else if deficit > 0.0 {
        return Err(deficit);
    } else {
        let f = (p + (q + r)) * (r - (p - q)) * (r + (p - q)) * (p + (q - r));
        // K = √f / 4 and h = 2K / d.
        0.5 * f.max(0.0).sqrt() / d
    };
    let x = if flat {
        // On the line at r1 from a: behind a when b's distance is the
        // largest, ahead of it otherwise (exact, with no arithmetic).
        if r2 > r1 && r2 > d { -r1 } else { r1 }
    } else if r1 <= d {
        ((d - r2) * (d + r2) + r1 * r1) / (2.0 * d)
    } else {
        ((r1 - r2) * (r1 + r2) + d * d) / (2.0 * d)
    };
    let e = ab / d;
    Ok((a + e * x + e.turn_90() * (side * h), h))
}

/// The decimal a length was written as: the shortest decimal that the
/// reader's conversion (× `unit`, m per unit of the file) maps onto `x`,
/// as (digits, exponent) with x = digits·10^exponent · unit.
fn decimal(x: f64, unit: f64) -> Option<(u64, i32)> {
    let from = |s: &str| -> Option<(u64, i32)> {
        let (mant, exp) = s.split_once('e')?;
        let exp: i32 = exp.parse().ok()?;
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        let digits: u64 = format!("{int}{frac}").parse().ok()?;
        Some((digits, exp - frac.len() as i32))
    };
    if unit == 1.0 {
        return from(&format!("{x:e}"));
    }
    let d = x / unit;
    (1..=17).find_map(|digits| {
        let s = format!("{:.*e}", digits - 1, d);
        (s.parse::<f64>().ok()? * unit == x)
            .then(|| from(&s))
            .flatten()
    })
}

/// Do three lengths, read as the decimals they were written as, close a
/// degenerate triangle exactly (the largest the sum of the other two)?
fn decimals_close(unit: f64, lens: [f64; 3]) -> bool {
    let Some(dec) = lens
        .iter()
        .map(|&x| decimal(x, unit))
        .collect::<Option<Vec<_>>>()
    else {
        return false;
    };
    let e0 = dec.iter().map(|d| d.1).min().expect("three");
    // Aligned to the smallest exponent; a shift past 10^20 cannot close
    // exactly (the sum would need more digits than a double's decimal).
    let Some(mut v) = dec
        .iter()
        .map(|&(m, e)| 10u128.checked_pow((e - e0) as u32)?.checked_mul(m as u128))
        .collect::<Option<Vec<u128>>>()
    else {
        return false;
    };
    v.sort_unstable();
    v[0].checked_add(v[1]) == Some(v[2])
}

/// The slack allowed in a distance of a link's shape: the rounding of the
/// data it comes from (the given lengths and the sketch's coordinates) and
/// of the arithmetic, with a safety factor. `lens`: the lengths involved.
fn rounding_slack(lens: f64, sketch_mag: f64) -> f64 {
    32.0 * U * (lens + sketch_mag)
}

/// A link's shape: local coordinates of its points (parallel to the
/// link's `points`), and the angle of its frame in the sketch.
#[derive(Clone, Debug)]
pub struct Shape {
    pub local: Vec<Vec2>,
    pub sketch_angle: f64,
}

/// The shape of link `l`: its placements (decided from the data here, or
/// followed from `decided`) and its local coordinates. Errors: the points
/// whose triangle does not close, a point drawn on a line its distances
/// put off it, a base of zero length.
pub fn shape(
    scene: &Scene,
    l: usize,
    decided: Option<&[Placement]>,
) -> Result<(Vec<Placement>, Shape), Vec<ShapeIssue>> {
    let pts = &scene.links[l].points;
    if l == scene.frame {
        let local = pts.iter().map(|&p| sketch(scene, p).to_vec2()).collect();
        return Ok((
            Vec::new(),
            Shape {
                local,
                sketch_angle: 0.0,
            },
        ));
    }
    if pts.len() < 2 {
        let local = vec![Vec2::ZERO; pts.len()];
        return Ok((
            Vec::new(),
            Shape {
                local,
                sketch_angle: 0.0,
            },
        ));
    }
    let sh = Shaping {
        scene,
        l,
        pts,
        mag: sketch_magnitude(scene, pts),
    };
    let (o, x1) = (sketch(scene, pts[0]), sketch(scene, pts[1]));
    let axis = x1 - o;
    let d01 = distance(scene, pts[0], pts[1]);
    // Zero length: exactly, or within the rounding of the coordinates that
    // draw it (never relative to the size of the whole sketch).
    let sketched_zero = axis.hypot() <= 4.0 * U * (o.to_vec2().hypot() + x1.to_vec2().hypot());
    if d01 == 0.0 || sketched_zero {
        return Err(vec![sh.issue(
            None,
            format!(
                "zero-length link: its first two points \"{}\" and \"{}\" coincide",
                sh.name(pts[0]),
                sh.name(pts[1])
            ),
        )]);
    }
    let (sin, cos) = (axis.y / axis.hypot(), axis.x / axis.hypot());
    let to_frame = |p: Point| {
        let w = p - o;
        Vec2::new(cos * w.x + sin * w.y, -sin * w.x + cos * w.y)
    };
    let mut local = vec![Vec2::ZERO; pts.len()];
    local[1] = Vec2::new(d01, 0.0);
    let mut placements = vec![Placement::Origin, Placement::Base];
    // A point is "as sketched" in the link's frame when no given length
    // entered its placement (nor its references').
    let mut as_sketched = vec![true, given(scene, pts[0], pts[1]).is_none()];
    let mut issues = Vec::new();
    for k in 2..pts.len() {
        let p = pts[k];
        let (j1, j2) = references(scene, pts, k);
        let (q1, q2) = (pts[j1], pts[j2]);
        let refs = Refs {
            k,
            j: (j1, j2),
            r: (distance(scene, p, q1), distance(scene, p, q2)),
            d: (local[j2] - local[j1]).hypot(),
        };
        let free = given(scene, p, q1).is_none() && given(scene, p, q2).is_none();
        let sketched = free && as_sketched[j1] && as_sketched[j2];
        as_sketched.push(sketched);
        let placement = match decided {
            Some(plan) => plan[k],
            None if sketched => Placement::Sketch,
            None => sh.decide(&refs, &mut issues),
        };
        placements.push(placement);
        if placement == Placement::Sketch {
            local[k] = to_frame(sketch(scene, p));
            continue;
        }
        if let Some(at) = sh.place(&refs, placement, &local, &mut issues) {
            local[k] = at;
        }
    }
    if !issues.is_empty() {
        return Err(issues);
    }
    sh.check(&placements, &local)?;
    Ok((
        placements,
        Shape {
            local,
            sketch_angle: axis.atan2(),
        },
    ))
}

/// A link's shape under way: the scene, the link and its points, the
/// magnitude of their sketch coordinates.
struct Shaping<'s> {
    scene: &'s Scene,
    l: usize,
    pts: &'s [usize],
    mag: f64,
}

/// The point `k` of a link being placed: its references `j` (indices in
/// the link), its distances `r` to them and theirs `d` in the shape.
struct Refs {
    k: usize,
    j: (usize, usize),
    r: (f64, f64),
    d: f64,
}

impl Shaping<'_> {
    fn name(&self, p: usize) -> &str {
        self.scene.points[p].name.as_str()
    }

    fn issue(&self, point: Option<usize>, message: String) -> ShapeIssue {
        ShapeIssue {
            point,
            message,
        }
    }

    /// The placement of a point whose placement a given length enters,
    /// decided from the data: on its references' line or the apex of
    /// their triangle on the sketch's side (an issue when the sketch draws
    /// it on the line but its distances make a triangle).
    fn decide(&self, refs: &Refs, issues: &mut Vec<ShapeIssue>) -> Placement {
        let (scene, pts) = (self.scene, self.pts);
        let (k, (j1, j2), (r1, r2), d) = (refs.k, refs.j, refs.r, refs.d);
        let (p, q1, q2) = (pts[k], pts[j1], pts[j2]);
        let (side, drawn_on_line) =
            sketch_side(sketch(scene, q1), sketch(scene, q2), sketch(scene, p));
        // Do the distances close a degenerate triangle, to rounding?
        let mut s = [d, r1, r2];
        s.sort_by(|x, y| y.total_cmp(x));
        let lengths_flat = (s[0] - s[1] - s[2]).abs() <= rounding_slack(d + r1 + r2, self.mag);
        // Three given lengths whose decimals close exactly: the
        // data put P on the line, whatever the drawing shows.
        let base = given(scene, q1, q2).filter(|_| {
            // The references' distance in the shape is that length
            // exactly only for the base pair.
            (j1, j2) == (0, 1) || (j1, j2) == (1, 0)
        });
        let exactly_flat = match (given(scene, p, q1), given(scene, p, q2), base) {
            (Some(a), Some(b), Some(c)) => decimals_close(scene.length_unit, [a, b, c]),
            _ => false,
        };
        if drawn_on_line && !lengths_flat {
            issues.push(self.issue(
                Some(k),
                format!(
                    "point \"{}\" is drawn on the line through \"{}\" and \"{}\", but its distances make a triangle: draw it on the side it belongs",
                    self.name(p),
                    self.name(q1),
                    self.name(q2)
                ),
            ));
        }
        if drawn_on_line || exactly_flat {
            Placement::OnLine { refs: (j1, j2) }
        } else {
            Placement::Triangle {
                refs: (j1, j2),
                side,
            }
        }
    }

    /// The place in the link's frame of a point on its references' line
    /// or at their triangle's apex (`placement`), the points before it
    /// placed (`local`); `None` (an issue) when its references coincide.
    fn place(
        &self,
        refs: &Refs,
        placement: Placement,
        local: &[Vec2],
        issues: &mut Vec<ShapeIssue>,
    ) -> Option<Vec2> {
        let (scene, pts) = (self.scene, self.pts);
        let (k, (j1, j2), (r1, r2), d) = (refs.k, refs.j, refs.r, refs.d);
        let (p, q1, q2) = (pts[k], pts[j1], pts[j2]);
        let (flat, side) = match placement {
            Placement::Triangle { side, .. } => (false, side),
            _ => (true, 1.0),
        };
        if d <= 4.0 * U * (local[j1].hypot() + local[j2].hypot()) {
            // Two coincident references fix no place (found by fuzzing:
            // the triangle's base of length zero gave NaN).
            issues.push(self.issue(
                Some(k),
                format!(
                    "point \"{}\" cannot be placed: its reference points \"{}\" and \"{}\" coincide (give lengths that pair it with two distinct points of the link)",
                    self.name(p),
                    self.name(q1),
                    self.name(q2)
                ),
            ));
            return None;
        }
        Some(match apex(local[j1], local[j2], r1, r2, side, flat) {
            Ok((at, _)) => at,
            // A degenerate triangle to the rounding of the data: on the
            // line (the data cannot tell more).
            Err(deficit) if deficit <= rounding_slack(d + r1 + r2, self.mag) => {
                apex(local[j1], local[j2], r1, r2, side, true)
                    .expect("a flat apex always exists")
                    .0
            }
            Err(deficit) => {
                issues.push(self.issue(
                    Some(k),
                    format!(
                        "link \"{}\" cannot be rigid: point \"{}\" at {} from \"{}\" and {} from \"{}\", which are {} apart (the triangle inequality fails by {})",
                        scene.links[self.l].id,
                        self.name(p),
                        quantity(r1, "m"),
                        self.name(q1),
                        quantity(r2, "m"),
                        self.name(q2),
                        quantity(d, "m"),
                        quantity(deficit, "m"),
                    ),
                ));
                local[j1]
            }
        })
    }

    /// Every distance the rule used must hold in the shape, to rounding: a
    /// self-check of the construction, never a silent change of the data.
    fn check(&self, placements: &[Placement], local: &[Vec2]) -> Result<(), Vec<ShapeIssue>> {
        let (scene, pts) = (self.scene, self.pts);
        for k in 1..pts.len() {
            let (refs, flat) = match placements[k] {
                Placement::Base => ((0, 0), false),
                Placement::OnLine { refs } => (refs, true),
                Placement::Triangle { refs, .. } => (refs, false),
                _ => continue,
            };
            for j in [refs.0, refs.1] {
                let want = distance(scene, pts[k], pts[j]);
                let got = (local[k] - local[j]).hypot();
                // On a line the distances agree only to their own rounding.
                let slack = rounding_slack(want + local[k].hypot() + local[j].hypot(), self.mag)
                    * if flat { 4.0 } else { 1.0 };
                if (got - want).abs() > slack {
                    return Err(vec![self.issue(
                        Some(k),
                        format!(
                            "internal: the shape of link \"{}\" puts \"{}\" {} from \"{}\" where the data say {}",
                            scene.links[self.l].id,
                            self.name(pts[k]),
                            quantity(got, "m"),
                            self.name(pts[j]),
                            quantity(want, "m")
                        ),
                    )]);
                }
            }
        }
        Ok(())
    }
}

/// The slack in comparing a given length with the distance the shape of a
/// moving link puts between two of its points: the rounding of the data.
pub fn length_slack(scene: &Scene, pts: &[usize], value: f64, la: Vec2, lb: Vec2) -> f64 {
    rounding_slack(
        value + la.hypot() + lb.hypot(),
        sketch_magnitude(scene, pts),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A needle 1e9 : 1: the height and the foot to a few ulps of the
    /// longest side (the naive formula loses all of the height).
    #[test]
    fn needle_triangle_is_stable() {
        let (a, b) = (Vec2::ZERO, Vec2::new(1e9, 0.0));
        // Apex at (0.5e9, 0.5): r1 = r2 = √(0.25e18 + 0.25).
        let r = (0.25e18f64 + 0.25).sqrt();
        let (p, h) = apex(a, b, r, r, 1.0, false).unwrap();
        assert!((p.x - 0.5e9).abs() <= 4.0 * 1e9 * f64::EPSILON, "{p:?}");
        // h is determined by r only to ulp(r)·r/h: compare with that.
        let dh = f64::EPSILON * r * r / 0.5;
        assert!((h - 0.5).abs() <= 4.0 * dh.max(f64::EPSILON), "{h}");
    }

    /// A thin triangle 1e6 : 1e6 : 1 on its short side: the apex to ulps.
    #[test]
    fn tall_triangle_on_short_base() {
        let (a, b) = (Vec2::ZERO, Vec2::new(1.0, 0.0));
        let r = (1e12f64 + 0.25).sqrt();
        let (p, _) = apex(a, b, r, r, -1.0, false).unwrap();
        assert!((p.x - 0.5).abs() <= 1e-15, "{p:?}");
        assert!((p.y + 1e6).abs() <= 4.0 * 1e6 * f64::EPSILON, "{p:?}");
    }

    /// Collinear data on the line, beyond either end or between.
    #[test]
    fn flat_apex_is_on_the_line() {
        let (a, b) = (Vec2::new(1.0, 1.0), Vec2::new(3.0, 1.0));
        let (p, _) = apex(a, b, 3.0, 1.0, 1.0, true).unwrap();
        assert_eq!(p, Vec2::new(4.0, 1.0));
        let (p, _) = apex(a, b, 1.0, 3.0, 1.0, true).unwrap();
        assert_eq!(p, Vec2::new(0.0, 1.0));
        let (p, _) = apex(a, b, 0.5, 1.5, 1.0, true).unwrap();
        assert_eq!(p, Vec2::new(1.5, 1.0));
    }

    #[test]
    fn decimals_close_exactly() {
        assert!(decimals_close(1.0, [0.1, 0.2, 0.3]));
        assert!(!decimals_close(1.0, [0.1, 0.2, 0.30000000000000004]));
        assert!(decimals_close(
            1e-3,
            [100.0 * 1e-3, 0.2 * 1e-3, 100.2 * 1e-3]
        ));
        // 1 + 1e-30 is 1 as a double, but not as the decimals written.
        assert!(!decimals_close(1.0, [1e-30, 1.0, 1.0 + 1e-30]));
    }

    #[test]
    fn impossible_triangle_reports_its_deficit() {
        let e = apex(Vec2::ZERO, Vec2::new(1.0, 0.0), 0.2, 0.3, 1.0, false).unwrap_err();
        assert!((e - 0.5).abs() < 1e-15);
    }
}
