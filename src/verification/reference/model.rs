//! The scene rebuilt in extended precision: its numbers taken as the
//! exact values they are (units recovered, exact values where given),
//! the links' rigid shapes by the contract's rule, the prismatic pairs.

use super::real::{Real, V2};
use crate::kinematics::analytic::equations::Prism;
use crate::model::mechanism::Mechanism;
use crate::model::scene::{Direction, Scene, Through};
use crate::model::shape::Placement;

/// The shortest decimal that the scene's conversion (× `unit`) maps onto
/// `x`, in extended precision times the exact unit; `x` itself when the
/// unit is 1.
fn recover(x: f64, unit: f64, exact_unit: impl Fn() -> Real) -> Real {
    if unit == 1.0 || x == 0.0 {
        return Real::from_f64(x);
    }
    let d = x / unit;
    for digits in 1..=17 {
        let s = format!("{:.*e}", digits - 1, d);
        if s.parse::<f64>().map(|v| v * unit) == Ok(x)
            && let Some(r) = Real::from_decimal(&s)
        {
            return r * exact_unit();
        }
    }
    Real::from_f64(x)
}

/// The scene's numbers in extended precision: lengths and angles in
/// their exact units, the sketch's points, the given lengths, the guides'
/// directions.
pub(super) struct Numbers<'s> {
    sc: &'s Scene,
    exact: &'s Exact,
    /// Every point of the sketch (an exact value where given).
    pub sketch: Vec<V2>,
}

impl<'s> Numbers<'s> {
    pub fn new(sc: &'s Scene, exact: &'s Exact) -> Numbers<'s> {
        let mut nums = Numbers {
            sc,
            exact,
            sketch: Vec::new(),
        };
        nums.sketch = sc
            .points
            .iter()
            .map(|p| match exact.points.iter().find(|e| e.0 == p.name) {
                Some((_, x, y)) => V2::new(x.clone(), y.clone()),
                None => V2::new(nums.length(p.sketch.x), nums.length(p.sketch.y)),
            })
            .collect();
        nums
    }

    /// A length of the scene (in metres) as the file gave it.
    pub fn length(&self, x: f64) -> Real {
        let lu = self.sc.length_unit;
        let len_unit = move || {
            if lu == 1e-3 {
                Real::one() / Real::from_f64(1000.0)
            } else {
                Real::from_f64(lu)
            }
        };
        recover(x, lu, len_unit)
    }

    /// An angle of the scene (in radians) as the file gave it.
    fn angle(&self, x: f64) -> Real {
        let au = self.sc.angle_unit;
        let ang_unit = move || {
            if au == std::f64::consts::PI / 180.0 {
                Real::pi() / Real::from_f64(180.0)
            } else {
                Real::from_f64(au)
            }
        };
        recover(x, au, ang_unit)
    }

    /// The length the scene gives between points a and b, if any.
    fn given(&self, a: usize, b: usize) -> Option<Real> {
        let l = self
            .sc
            .lengths
            .iter()
            .find(|l| (l.a == a && l.b == b) || (l.a == b && l.b == a))?;
        Some(match self.exact.lengths.iter().find(|e| e.0 == l.key) {
            Some((_, v)) => v.clone(),
            None => self.length(l.value),
        })
    }

    /// The distance of points a and b: given, else the sketch's.
    fn dist(&self, a: usize, b: usize) -> Real {
        self.given(a, b)
            .unwrap_or_else(|| self.sketch[a].sub(&self.sketch[b]).norm())
    }

    /// The world direction of slider k's guide line in the sketch.
    fn guide_dir(&self, k: usize) -> V2 {
        let sketch = &self.sketch;
        match self.sc.sliders[k].line.direction {
            Direction::Angle(a) => {
                let (s, c) = self.angle(a).sin_cos();
                V2::new(c, s)
            }
            Direction::Along(q, r) => {
                let v = sketch[r].sub(&sketch[q]);
                let n = v.norm();
                v.scale(&(Real::one() / n))
            }
        }
    }
}

/// The links' rigid shapes by the contract's rule (as mechanism.rs builds
/// them): each link's points in its own frame, and its angle in the sketch.
pub(super) fn shapes(m: &Mechanism, nums: &Numbers) -> (Vec<Vec<V2>>, Vec<Real>) {
    let sc = &m.scene;
    let sketch = &nums.sketch;
    let mut local: Vec<Vec<V2>> = Vec::new();
    let mut sketch_angle: Vec<Real> = Vec::new();
    for (l, link) in m.links.iter().enumerate() {
        let pts = &link.points;
        if l == m.frame() {
            local.push(pts.iter().map(|&p| sketch[p].clone()).collect());
            sketch_angle.push(Real::zero());
            continue;
        }
        let mut loc = vec![V2::zero(); pts.len()];
        if pts.len() == 1 {
            let k = sc
                .sliders
                .iter()
                .position(|s| s.slider == l)
                .expect("a one-point link is a slider (checked)");
            sketch_angle.push(nums.guide_dir(k).atan2());
            local.push(loc);
            continue;
        }
        let axis = sketch[pts[1]].sub(&sketch[pts[0]]);
        sketch_angle.push(axis.atan2());
        loc[1] = V2::new(nums.dist(pts[0], pts[1]), Real::zero());
        let axis_len = axis.norm();
        let (ca, sa) = (axis.x.clone() / &axis_len, axis.y.clone() / &axis_len);
        for k in 2..pts.len() {
            place_point(m, nums, l, k, (&ca, &sa), &mut loc);
        }
        local.push(loc);
    }
    (local, sketch_angle)
}

/// Point k of link l in the link's frame (`loc`, its points before k
/// placed): the placement mechanism.rs decided (crate::model::shape), in
/// extended precision; `(ca, sa)` the cosine and sine of the link's axis.
fn place_point(
    m: &Mechanism,
    nums: &Numbers,
    l: usize,
    k: usize,
    (ca, sa): (&Real, &Real),
    loc: &mut [V2],
) {
    let sketch = &nums.sketch;
    let pts = &m.links[l].points;
    let p = pts[k];
    let (j1, j2, flat, side) = match m.placements[l][k] {
        Placement::Sketch => {
            // The sketch position in the link's frame.
            loc[k] = sketch[p].sub(&sketch[pts[0]]).rotate(&-sa, ca);
            return;
        }
        Placement::OnLine { refs } => (refs.0, refs.1, true, 1.0),
        Placement::Triangle { refs, side } => (refs.0, refs.1, false, side),
        Placement::Origin | Placement::Base => unreachable!("first two points"),
    };
    let (r1, r2) = (nums.dist(p, pts[j1]), nums.dist(p, pts[j2]));
    let (a, b) = (loc[j1].clone(), loc[j2].clone());
    let ab = b.sub(&a);
    let d = ab.norm();
    let e = ab.scale(&(Real::one() / &d));
    let x = (d.square() + r1.square() - r2.square()) / (Real::from_f64(2.0) * &d);
    let h2 = r1.square() - x.square();
    let foot = a.add(&e.scale(&x));
    loc[k] = if flat || h2.is_negative() {
        foot
    } else {
        let h = h2.sqrt() * Real::from_f64(side);
        foot.add(&e.perp().scale(&h))
    };
}

/// Point p in link l's frame, from the shapes `local`.
pub(super) fn local_of(m: &Mechanism, local: &[Vec<V2>], l: usize, p: usize) -> V2 {
    let i = m.links[l]
        .points
        .iter()
        .position(|&x| x == p)
        .expect("point on link");
    local[l][i].clone()
}

/// The prismatic pairs in extended precision, in the frames of their links.
pub(super) fn prisms(
    m: &Mechanism,
    nums: &Numbers,
    local: &[Vec<V2>],
    sketch_angle: &[Real],
) -> Vec<Prism<Real>> {
    let local_of = |l: usize, p: usize| local_of(m, local, l, p);
    let mut prism = Vec::new();
    for (k, s) in m.scene.sliders.iter().enumerate() {
        let ga = &sketch_angle[s.guide];
        let (gs, gc) = ga.sin_cos();
        let through = match s.line.through {
            Through::Point(p) => local_of(s.guide, p),
            Through::Coords(c) => V2::new(nums.length(c.x), nums.length(c.y)),
        };
        let dir = match s.line.direction {
            Direction::Angle(_) => nums.guide_dir(k).rotate(&-&gs, &gc),
            Direction::Along(q, r) => {
                let v = local_of(s.guide, r).sub(&local_of(s.guide, q));
                let n = v.norm();
                v.scale(&(Real::one() / n))
            }
        };
        let line_point = through.add(&dir.perp().scale(&nums.length(s.line.offset)));
        prism.push(Prism {
            slider: s.slider,
            guide: s.guide,
            slider_local: local_of(s.slider, s.point),
            line_point,
            line_dir: dir,
            delta: &sketch_angle[s.slider] - ga,
        });
    }
    prism
}

/// The exact values of some of the scene's numbers, by point name and
/// length key ("A-B"), where the file can only hold their f64 roundings
/// (√3 and the like): the reference is then that of the exact mechanism.
#[derive(Clone, Debug, Default)]
pub struct Exact {
    pub points: Vec<(String, Real, Real)>,
    pub lengths: Vec<(String, Real)>,
}
