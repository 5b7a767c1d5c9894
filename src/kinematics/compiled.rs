//! Route (a) compiled per mechanism: the positions and the closed vector
//! contours of [`crate::kinematics::positions`] and
//! [`crate::kinematics::analytic::contour`], with everything that does
//! not depend on the position worked out once, at load.
//!
//! [`Program::new`] walks the structure's stages once and turns them into
//! two flat lists of typed steps over link and input indices: one that
//! places the links ([`Place`]: a crank, a slider, each kind of dyad, a
//! class III group) and one that finds their rates ([`Rate`]: the frame,
//! the inputs, each group's contours). What the interpreted route looks
//! up or recomputes at every position is a constant of the step: a point's
//! local coordinates on its links, a group's link lengths, the angle and
//! length of the segment a link is posed by, the sine and cosine of a
//! guide's fixed angle, which links a contour reads as known, the order in
//! which its walk reaches its links. A position then runs the steps on a
//! [`State`] whose buffers are made once: no maps, no allocation.
//!
//! The arithmetic is the interpreted route's, operation for operation, so
//! the numbers are the same to the bit (`tests/compiled.rs` checks every
//! fixture and every stress scene over their sweeps, the errors too). A
//! tolerance that only decides a failure (a tangency accepted to the
//! rounding of its numbers) is not computed on the way: where a step
//! cannot place its group by its plain closed form it hands the group to
//! the interpreted solver, which accepts the tangency or gives the same
//! error as the interpreted route. The singular contour is refused by the
//! same test ([`crate::accuracy::Accuracy::min_contour_determinant`]).

use crate::accuracy::ACCURACY;
use crate::error::Result;
use crate::geom::{Line, Pose, circle_circle, circle_line, perp};
use crate::kinematics::analytic::contour::{
    self, Inverse, Twist, bracket, driven_pair, invert_lu, invert3,
};
use crate::kinematics::analytic::{Coords, Drive, Drives, Motion, Order};
use crate::kinematics::positions::{
    self, Branches, Configuration, dyad_error, pair_of, point_of, sketch_input, triad_error,
};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Conn, DyadKind, InputRole, Joint, Stage, Structure};
use kurbo::{Point, Vec2};
use nalgebra::{SMatrix, SVector};

/// The angle and the length of a constant local segment (the one a link
/// is posed by): `atan2` and `hypot` done once.
#[derive(Clone, Copy, Debug)]
struct Segment {
    v: Vec2,
    angle: f64,
    len: f64,
}

impl Segment {
    fn new(v: Vec2) -> Segment {
        Segment {
            v,
            angle: v.atan2(),
            len: v.hypot(),
        }
    }
    /// The pose that puts local point `lp` at `at_p` and turns this
    /// segment (from `lp`) onto `at_q − at_p`: the interpreted
    /// `set_by_two_local` with its constant half done.
    #[inline(always)]
    fn pose(&self, lp: Vec2, at_p: Point, at_q: Point) -> Pose {
        let (w, l) = (at_q - at_p, self.v);
        let angle = w.atan2() - self.angle;
        let norm = w.hypot() * self.len;
        let turn = (l.dot(w) / norm, l.cross(w) / norm);
        Pose::through_turned(at_p, lp, angle, turn)
    }
}

/// A point of a link: the link and the point's local coordinates on it.
#[derive(Clone, Copy, Debug)]
struct On {
    link: usize,
    local: Vec2,
}

impl On {
    fn new(m: &Mechanism, link: usize, p: usize) -> On {
        On {
            link,
            local: m.local(link, p),
        }
    }
    #[inline(always)]
    fn world(&self, c: &Configuration) -> Point {
        c.pose(self.link).apply(self.local)
    }
}

/// A class II group RRR: the circles about B (on K1) and D (on K2) meet
/// at C.
#[derive(Clone, Debug)]
struct Rrr {
    group: usize,
    sign: f64,
    links: [usize; 2],
    b: On,
    d: On,
    /// B and C on link 1, D and C on link 2.
    b1: Vec2,
    d2: Vec2,
    seg1: Segment,
    seg2: Segment,
}

/// A class II group RRP: the circle about B meets the guide line.
#[derive(Clone, Debug)]
struct Rrp {
    group: usize,
    sign: f64,
    links: [usize; 2],
    b: On,
    b1: Vec2,
    seg1: Segment,
    r1: f64,
    /// The known link K2 of the guide pair, and whether it is the guide.
    k2: usize,
    k2_guide: bool,
    delta: f64,
    /// The point of K2 the line is drawn from (the line's point on the
    /// guide, the slider's point on the slider) and the offset of C from
    /// the other's in link 2 (turned by link 2's angle).
    anchor: Vec2,
    offset: Vec2,
    line_dir: Vec2,
    /// C on link 2.
    c2: Vec2,
}

/// A class II group RPR: the rocking guide's angle in closed form.
#[derive(Clone, Debug)]
struct Rpr {
    group: usize,
    sign: f64,
    guide: usize,
    slider: usize,
    /// The guide's and the slider's pins on their known links, and on
    /// the guide and the slider.
    jg: On,
    js: On,
    jg_local: Vec2,
    js_local: Vec2,
    h: f64,
    alpha: f64,
    delta: f64,
}

/// One step of the positions.
#[derive(Clone, Debug)]
enum Place {
    /// A crank about its pivot: its pose through the pivot at `at`
    /// (`local` on the crank), turned by the input angle less `offset`.
    Crank {
        input: usize,
        link: usize,
        at: Point,
        local: Vec2,
        offset: f64,
    },
    /// A slider on a guide of the frame: its point at `q0 + dir·s`, its
    /// angle `delta` (cosine and sine `turn`).
    Slider {
        input: usize,
        link: usize,
        q0: Point,
        dir: Vec2,
        local: Vec2,
        delta: f64,
        turn: (f64, f64),
    },
    /// A driving slider on a moving guide: pair `pair` places `other`
    /// from `known`.
    Chained {
        input: usize,
        known: usize,
        pair: usize,
        other: usize,
    },
    Rrr(Box<Rrr>),
    Rrp(Box<Rrp>),
    Rpr(Box<Rpr>),
    /// Any other dyad (PRP, RPP, a cylinder's): the interpreted closed form.
    Dyad {
        group: usize,
    },
    /// A class III group: Newton from its tracked pose.
    Triad {
        group: usize,
    },
}

/// The twist of a pair's unit rate about a point, as a step computes it:
/// a revolute pair at its point on link `link`, a prismatic pair along
/// its guide's direction (negated when the contour enters the guide).
#[derive(Clone, Copy, Debug)]
enum PairTwist {
    R {
        at: On,
    },
    P {
        guide: usize,
        dir: Vec2,
        to_slider: bool,
    },
}

impl PairTwist {
    fn new(m: &Mechanism, conn: &Conn) -> PairTwist {
        match conn.joint {
            Joint::R(p) => PairTwist::R {
                at: On::new(m, conn.to, p),
            },
            Joint::P(k) => {
                let pr = &m.prismatics[k];
                PairTwist::P {
                    guide: pr.guide,
                    dir: pr.line_dir,
                    to_slider: conn.to == pr.slider,
                }
            }
        }
    }
    #[inline(always)]
    fn twist(&self, c: &Configuration, o: Point) -> Twist {
        match *self {
            PairTwist::R { at } => Twist {
                w: 1.0,
                v: -perp(at.world(c) - o),
            },
            PairTwist::P {
                guide,
                dir,
                to_slider,
            } => {
                let u = c.pose(guide).dir(dir);
                Twist {
                    w: 0.0,
                    v: if to_slider { u } else { -u },
                }
            }
        }
    }
}

/// Where a contour reads a link's twist: a link known before the group
/// (its index in the group's list of known links) or one its walk found
/// (the index in the order found).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Src {
    Known(usize),
    Found(usize),
}

/// One step of a contour's walk: the next link's twist is the twist at
/// `base` plus (`forward`) or minus the relative twist across pair `j`
/// (`j` = N: the driven pair).
#[derive(Clone, Copy, Debug)]
struct Walk {
    base: Src,
    j: usize,
    forward: bool,
}

/// A driven pair (a cylinder's) on or off a dyad's contour.
#[derive(Clone, Copy, Debug)]
struct DrivenPair {
    twist: PairTwist,
    input: usize,
    contour: Option<usize>,
    from: Src,
}

/// The most links a group reads as known (a three-leash group: three
/// outer links), walks to (four), or walks over pairs (six and a driven one).
const MAX_KNOWN: usize = 6;
const MAX_WALK: usize = 8;

/// One group's contours, compiled: `N` pairs (3 for a dyad, 6 for a
/// three-leash group), the contours as (pair, sign) lists, their ends,
/// the walk.
#[derive(Clone, Debug)]
struct Contour<const N: usize> {
    group: usize,
    /// The twists are taken about this link's origin.
    o_link: usize,
    pairs: [PairTwist; N],
    driven: Option<DrivenPair>,
    contours: &'static [&'static [(usize, f64)]],
    ends: [(Src, Src); 2],
    known: [usize; MAX_KNOWN],
    n_known: usize,
    walk: [Walk; MAX_WALK],
    n_walk: usize,
    /// Where the walk finds each pair's `from` link (the drift terms).
    drift_from: [Src; N],
    /// The group's links in ascending order, where each one's twist is.
    links: [(usize, Src); 4],
    n_links: usize,
    invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
}

/// A dyad's single contour through its three pairs.
const DYAD_CONTOURS: &[&[(usize, f64)]] = &[&[(0, 1.0), (1, 1.0), (2, 1.0)]];
/// A three-leash group's two contours.
const TRIAD_CONTOURS: &[&[(usize, f64)]] = &[
    &[(0, 1.0), (1, 1.0), (2, -1.0), (3, -1.0)],
    &[(0, 1.0), (1, 1.0), (4, -1.0), (5, -1.0)],
];

/// The contours' compiler: which links are known, the walk over the pairs
/// exactly as [`contour`]'s walk takes it.
struct Compiling<'s> {
    solved: &'s [bool],
    known: [usize; MAX_KNOWN],
    n_known: usize,
    found: [usize; 4],
    n_found: usize,
}

impl Compiling<'_> {
    fn get(&mut self, l: usize) -> Option<Src> {
        if self.solved[l] {
            if let Some(i) = self.known[..self.n_known].iter().position(|&k| k == l) {
                return Some(Src::Known(i));
            }
            assert!(self.n_known < MAX_KNOWN, "a group reads at most six links");
            self.known[self.n_known] = l;
            self.n_known += 1;
            return Some(Src::Known(self.n_known - 1));
        }
        self.found[..self.n_found]
            .iter()
            .position(|&k| k == l)
            .map(Src::Found)
    }
    fn add(&mut self, l: usize) {
        self.found[self.n_found] = l;
        self.n_found += 1;
    }
}

#[allow(clippy::too_many_arguments)]
fn compile_contour<const N: usize>(
    m: &Mechanism,
    group: usize,
    conns: [Conn; N],
    contours: &'static [&'static [(usize, f64)]],
    ends: &[(usize, usize)],
    links: &[usize],
    driven: Option<(Conn, usize, Option<usize>)>,
    solved: &[bool],
    invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
) -> Contour<N> {
    let mut cp = Compiling {
        solved,
        known: [0; MAX_KNOWN],
        n_known: 0,
        found: [usize::MAX; 4],
        n_found: 0,
    };
    let known = |cp: &mut Compiling, l: usize| {
        let s = cp.get(l).expect("attachment solved first");
        assert!(matches!(s, Src::Known(_)), "attachment solved first");
        s
    };
    let mut end_src = [(Src::Known(0), Src::Known(0)); 2];
    for (e, &(k1, k2)) in end_src.iter_mut().zip(ends) {
        *e = (known(&mut cp, k1), known(&mut cp, k2));
    }
    // The walk: the pairs in order, each pass over those still pending,
    // as `contour::walk` takes them.
    let mut all = [conns[0]; MAX_WALK];
    all[..N].copy_from_slice(&conns);
    let n = match driven {
        Some((conn, _, _)) => {
            all[N] = conn;
            N + 1
        }
        None => N,
    };
    let mut walk = [Walk {
        base: Src::Known(0),
        j: 0,
        forward: true,
    }; MAX_WALK];
    let mut n_walk = 0;
    let mut pending = [true; MAX_WALK];
    let mut left = n;
    while left > 0 {
        let before = left;
        for j in 0..n {
            if !pending[j] {
                continue;
            }
            let cn = all[j];
            match (cp.get(cn.from), cp.get(cn.to)) {
                (Some(base), None) => {
                    walk[n_walk] = Walk {
                        base,
                        j,
                        forward: true,
                    };
                    n_walk += 1;
                    cp.add(cn.to);
                }
                (None, Some(base)) => {
                    walk[n_walk] = Walk {
                        base,
                        j,
                        forward: false,
                    };
                    n_walk += 1;
                    cp.add(cn.from);
                }
                (Some(_), Some(_)) => {}
                (None, None) => continue,
            }
            pending[j] = false;
            left -= 1;
        }
        assert!(left < before, "group pairs form a connected contour");
    }
    let reached = |cp: &mut Compiling, l: usize| cp.get(l).expect("every group link reached");
    let drift_from: [Src; N] = std::array::from_fn(|j| reached(&mut cp, conns[j].from));
    let driven = driven.map(|(conn, input, contour)| DrivenPair {
        twist: PairTwist::new(m, &conn),
        input,
        contour,
        from: reached(&mut cp, conn.from),
    });
    let mut sorted = [(usize::MAX, Src::Known(0)); 4];
    for (s, &l) in sorted.iter_mut().zip(links) {
        *s = (l, reached(&mut cp, l));
    }
    sorted[..links.len()].sort_unstable_by_key(|s| s.0);
    Contour {
        group,
        o_link: links[0],
        pairs: conns.map(|cn| PairTwist::new(m, &cn)),
        driven,
        contours,
        ends: end_src,
        known: cp.known,
        n_known: cp.n_known,
        walk,
        n_walk,
        drift_from,
        links: sorted,
        n_links: links.len(),
        invert,
    }
}

impl<const N: usize> Contour<N> {
    /// The group's rates, written to `out`; `None` when its velocity
    /// contour is singular. The arithmetic of `contour::group`, in its order.
    fn run(
        &self,
        c: &Configuration,
        out: &mut [Option<Motion>],
        drives: &[Drive],
        order: Order,
    ) -> Option<()> {
        let o = c.pose(self.o_link).origin;
        let xi: [Twist; N] = std::array::from_fn(|j| self.pairs[j].twist(c, o));
        let xd = self.driven.map(|d| d.twist.twist(c, o));
        let reach = xi
            .iter()
            .map(|t| if t.w != 0.0 { t.v.hypot() } else { 0.0 })
            .fold(0.0, f64::max);
        let per_length = if reach > 0.0 { 1.0 / reach } else { 1.0 };
        let contours = self.contours;
        let in_group_units = |mut r: SVector<f64, N>| {
            for ci in 0..contours.len() {
                r[3 * ci + 1] *= per_length;
                r[3 * ci + 2] *= per_length;
            }
            r
        };
        let mut a = SMatrix::<f64, N, N>::zeros();
        for (ci, contour) in contours.iter().enumerate() {
            for &(j, sg) in contour.iter() {
                a[(3 * ci, j)] = sg * xi[j].w;
                a[(3 * ci + 1, j)] = sg * xi[j].v.x * per_length;
                a[(3 * ci + 2, j)] = sg * xi[j].v.y * per_length;
            }
        }
        let mut ks = [(Twist::default(), Twist::default()); MAX_KNOWN];
        for (k, &l) in ks.iter_mut().zip(&self.known[..self.n_known]) {
            *k = contour::state(&out[l].expect("attachment solved first"), o);
        }
        let inverse = (self.invert)(&a)?;
        let ends = &self.ends[..contours.len()];
        let known = |s: Src| match s {
            Src::Known(i) => ks[i],
            Src::Found(_) => unreachable!("a contour ends on known links"),
        };
        let on_contour = |rhs: &mut SVector<f64, N>, t: Twist| {
            if let Some(ci) = self.driven.and_then(|d| d.contour) {
                rhs[3 * ci] -= t.w;
                rhs[3 * ci + 1] -= t.v.x;
                rhs[3 * ci + 2] -= t.v.y;
            }
        };
        let driven_rates = self
            .driven
            .map(|d| (drives[d.input].rate, drives[d.input].rate2));
        let mut rhs_v = rhs::<N>(ends, |s| known(s).0);
        if let (Some((rate, _)), Some(x)) = (driven_rates, xd) {
            on_contour(&mut rhs_v, x * rate);
        }
        let qd = inverse.solve(&in_group_units(rhs_v));
        let mut vel = [Twist::default(); 4];
        for (k, w) in self.walk[..self.n_walk].iter().enumerate() {
            let base = match w.base {
                Src::Known(i) => ks[i].0,
                Src::Found(f) => vel[f],
            };
            let step = match (driven_rates, xd) {
                (Some((rate, _)), Some(x)) if w.j == N => x * rate,
                _ => xi[w.j] * qd[w.j],
            };
            vel[k] = if w.forward { base + step } else { base - step };
        }
        let vel_of = |s: Src| match s {
            Src::Known(i) => ks[i].0,
            Src::Found(f) => vel[f],
        };
        let mut acc = [Twist::default(); 4];
        let accelerations = order == Order::Acceleration;
        if accelerations {
            let drift: [Twist; N] =
                std::array::from_fn(|j| bracket(vel_of(self.drift_from[j]), xi[j]) * qd[j]);
            let mut rhs = rhs::<N>(ends, |s| known(s).1);
            for (ci, contour) in contours.iter().enumerate() {
                for &(j, sg) in contour.iter() {
                    rhs[3 * ci] -= sg * drift[j].w;
                    rhs[3 * ci + 1] -= sg * drift[j].v.x;
                    rhs[3 * ci + 2] -= sg * drift[j].v.y;
                }
            }
            let driven_acc = match (self.driven, driven_rates, xd) {
                (Some(d), Some((rate, rate2)), Some(x)) => {
                    let t = x * rate2 + bracket(vel_of(d.from), x) * rate;
                    on_contour(&mut rhs, t);
                    t
                }
                _ => Twist::default(),
            };
            let qdd = inverse.solve(&in_group_units(rhs));
            for (k, w) in self.walk[..self.n_walk].iter().enumerate() {
                let base = match w.base {
                    Src::Known(i) => ks[i].1,
                    Src::Found(f) => acc[f],
                };
                let step = if w.j == N {
                    driven_acc
                } else {
                    xi[w.j] * qdd[w.j] + drift[w.j]
                };
                acc[k] = if w.forward { base + step } else { base - step };
            }
        }
        for &(l, s) in &self.links[..self.n_links] {
            let v = vel_of(s);
            let a = match s {
                Src::Found(f) if accelerations => acc[f],
                _ => Twist::default(),
            };
            out[l] = Some(Motion::from_point(
                c.pose(l),
                o,
                v.v,
                a.v + perp(v.v) * v.w,
                v.w,
                a.w,
            ));
        }
        Some(())
    }
}

/// A dyad's contour in scalars: no driven pair, and the walk every
/// dyad of the structure takes (K1 → L1 → L2, K2 known), so the matrix,
/// its inverse and the walk are written out. The arithmetic is that of
/// [`Contour::run`] (and of nalgebra's 3×3 determinant, inverse and
/// product that it calls), operation for operation.
#[derive(Clone, Debug)]
struct Dyad3 {
    group: usize,
    links: [usize; 2],
    ends: [usize; 2],
    pairs: [PairTwist; 3],
}

impl Dyad3 {
    /// The scalar form of `g`, when its walk is the plain one.
    fn of(g: &Contour<3>) -> Option<Dyad3> {
        let plain = g.driven.is_none()
            && g.n_walk == 2
            && matches!(
                g.walk[0],
                Walk {
                    base: Src::Known(_),
                    j: 0,
                    forward: true
                }
            )
            && matches!(
                g.walk[1],
                Walk {
                    base: Src::Found(0),
                    j: 1,
                    forward: true
                }
            )
            && g.drift_from[0] == g.walk[0].base
            && g.drift_from[1] == Src::Found(0)
            && g.drift_from[2] == Src::Found(1)
            && g.ends[0].0 == g.walk[0].base
            && g.n_links == 2;
        let (Src::Known(k1), Src::Known(k2)) = g.ends[0] else {
            return None;
        };
        let link = |s: Src| g.links[..2].iter().find(|e| e.1 == s).map(|e| e.0);
        let (Some(l1), Some(l2)) = (link(Src::Found(0)), link(Src::Found(1))) else {
            return None;
        };
        (plain && l1 == g.o_link).then(|| Dyad3 {
            group: g.group,
            links: [l1, l2],
            ends: [g.known[k1], g.known[k2]],
            pairs: g.pairs,
        })
    }

    /// The group's rates, written to `out`; `None` when its velocity
    /// contour is singular.
    #[inline]
    fn run(&self, c: &Configuration, out: &mut [Option<Motion>], order: Order) -> Option<()> {
        let [l1, l2] = self.links;
        let o = c.pose(l1).origin;
        let [p0, p1, p2] = &self.pairs;
        let (x0, x1, x2) = (p0.twist(c, o), p1.twist(c, o), p2.twist(c, o));
        // The longest arm: the square root is monotone and correctly
        // rounded, so the root of the largest square is the largest root
        // (`Vec2::hypot` is `hypot2().sqrt()`), with one root taken.
        let arm2 = |t: Twist| if t.w != 0.0 { t.v.hypot2() } else { 0.0 };
        let reach = f64::max(f64::max(f64::max(0.0, arm2(x0)), arm2(x1)), arm2(x2)).sqrt();
        let pl = if reach > 0.0 { 1.0 / reach } else { 1.0 };
        // The contour's columns in the group's units, made dimensionless.
        let col = |t: Twist| {
            let a = [t.w, t.v.x * pl, t.v.y * pl];
            let s = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
                .sqrt()
                .max(f64::MIN_POSITIVE);
            let k = 1.0 / s;
            ([a[0] * k, a[1] * k, a[2] * k], s)
        };
        let ([m11, m21, m31], s0) = col(x0);
        let ([m12, m22, m32], s1) = col(x1);
        let ([m13, m23, m33], s2) = col(x2);
        let minor_m12_m23 = m22 * m33 - m32 * m23;
        let minor_m11_m23 = m21 * m33 - m31 * m23;
        let minor_m11_m22 = m21 * m32 - m31 * m22;
        let det = m11 * minor_m12_m23 - m12 * minor_m11_m23 + m13 * minor_m11_m22;
        if det.abs() < ACCURACY.min_contour_determinant || det == 0.0 {
            return None;
        }
        let inv = [
            [
                minor_m12_m23 / det,
                (m13 * m32 - m33 * m12) / det,
                (m12 * m23 - m22 * m13) / det,
            ],
            [
                -minor_m11_m23 / det,
                (m11 * m33 - m31 * m13) / det,
                (m13 * m21 - m23 * m11) / det,
            ],
            [
                minor_m11_m22 / det,
                (m12 * m31 - m32 * m11) / det,
                (m11 * m22 - m21 * m12) / det,
            ],
        ];
        let solve = |t: Twist| {
            let b = [t.w, t.v.x * pl, t.v.y * pl];
            let y = |r: usize| inv[r][0] * b[0] + inv[r][1] * b[1] + inv[r][2] * b[2];
            [y(0) / s0, y(1) / s1, y(2) / s2]
        };
        let [k1, k2] = self.ends;
        let st = |l: usize| contour::state(&out[l].expect("attachment solved first"), o);
        let ((v1, a1), (v2, a2)) = (st(k1), st(k2));
        let qd = solve(v2 - v1);
        let vl1 = v1 + x0 * qd[0];
        let vl2 = vl1 + x1 * qd[1];
        let (al1, al2) = if order == Order::Acceleration {
            let d0 = bracket(v1, x0) * qd[0];
            let d1 = bracket(vl1, x1) * qd[1];
            let d2 = bracket(vl2, x2) * qd[2];
            let r = a2 - a1;
            let r = Twist {
                w: r.w - d0.w - d1.w - d2.w,
                v: Vec2::new(
                    r.v.x - d0.v.x - d1.v.x - d2.v.x,
                    r.v.y - d0.v.y - d1.v.y - d2.v.y,
                ),
            };
            let qdd = solve(r);
            let al1 = a1 + (x0 * qdd[0] + d0);
            (al1, al1 + (x1 * qdd[1] + d1))
        } else {
            (Twist::default(), Twist::default())
        };
        for (l, v, a) in [(l1, vl1, al1), (l2, vl2, al2)] {
            out[l] = Some(Motion::from_point(
                c.pose(l),
                o,
                v.v,
                a.v + perp(v.v) * v.w,
                v.w,
                a.w,
            ));
        }
        Some(())
    }
}

/// One step of the rates.
#[derive(Clone, Debug)]
enum Rate {
    /// The frame at rest.
    Frame,
    /// A crank about its pivot (`pivot` on the frame).
    Crank {
        input: usize,
        link: usize,
        pivot: Vec2,
    },
    /// A slider along a guide of the frame (`dir` on the frame).
    Slider {
        input: usize,
        link: usize,
        dir: Vec2,
    },
    /// A driving slider on a moving guide.
    Chained {
        input: usize,
        known: usize,
        pair: usize,
        other: usize,
    },
    Dyad3(Box<Dyad3>),
    Dyad(Box<Contour<3>>),
    Triad(Box<Contour<6>>),
}

/// Route (a) of one mechanism, compiled: the positions and the contours
/// as flat lists of typed steps ([`crate::kinematics::compiled`]).
#[derive(Clone, Debug)]
pub struct Program<'a> {
    m: &'a Mechanism,
    s: &'a Structure,
    place: Vec<Place>,
    rate: Vec<Rate>,
    /// The largest step of each input over which class III groups are
    /// tracked; empty when the program solves none.
    triad_step: Vec<f64>,
    /// The sketch's pose of each class III group's base, and its branches.
    branches: Branches,
}

/// The buffers one sweep of a [`Program`] works in: the poses and the
/// motions of the links (the links the program does not solve stay
/// `None`), the tracked class III groups and the last input coordinates.
#[derive(Clone, Debug)]
pub struct State {
    pub config: Configuration,
    pub motion: Vec<Option<Motion>>,
    triad_pose: Vec<Pose>,
    last_q: Coords,
}

impl<'a> Program<'a> {
    /// Compile the positions and route (a) of the groups `need` asks for,
    /// on the branches the sketch shows (refused as
    /// [`crate::kinematics::positions::PositionSolver::new`] refuses).
    pub fn new(m: &'a Mechanism, s: &'a Structure, need: &[bool]) -> Result<Program<'a>> {
        let branches = Branches::from_sketch(m, s)?;
        let frame = m.frame();
        let mut solved = vec![false; m.links.len()];
        solved[frame] = true;
        let mut place = Vec::new();
        let mut rate = vec![Rate::Frame];
        let mut triads = false;
        for &st in &s.stages {
            let gi = match st {
                Stage::Input(i) => {
                    match s.roles[i] {
                        InputRole::Frame => {
                            let (p, r) = input_steps(m, i);
                            solved[m.scene.input_at(i).link()] = true;
                            place.push(p);
                            rate.push(r);
                        }
                        InputRole::Chained { known, pair } => {
                            let pr = &m.prismatics[pair];
                            let other = if pr.guide == known {
                                pr.slider
                            } else {
                                pr.guide
                            };
                            if solved[known] {
                                solved[other] = true;
                                let (input, known) = (i, known);
                                place.push(Place::Chained {
                                    input,
                                    known,
                                    pair,
                                    other,
                                });
                                rate.push(Rate::Chained {
                                    input,
                                    known,
                                    pair,
                                    other,
                                });
                            }
                        }
                        InputRole::InGroup { .. } => {}
                    }
                    continue;
                }
                Stage::Group(gi) => gi,
            };
            if !need[gi] {
                continue;
            }
            let g = &s.groups[gi];
            let sign = branches.sign[gi];
            match g {
                AssurGroup::Dyad(d) => {
                    place.push(dyad_place(m, gi, d, sign));
                    let driven =
                        driven_pair(d).map(|(conn, input, on)| (conn, input, on.then_some(0)));
                    let mut links = [0usize; 3];
                    links[..2].copy_from_slice(&d.links);
                    let n = match d.cylinder {
                        Some(cy) => {
                            links[2] = cy.other;
                            3
                        }
                        None => 2,
                    };
                    let g = compile_contour::<3>(
                        m,
                        gi,
                        [d.ext1, d.mid, d.ext2],
                        DYAD_CONTOURS,
                        &[(d.ext1.from, d.ext2.to)],
                        &links[..n],
                        driven,
                        &solved,
                        invert3,
                    );
                    rate.push(match Dyad3::of(&g) {
                        Some(d3) => Rate::Dyad3(Box::new(d3)),
                        None => Rate::Dyad(Box::new(g)),
                    });
                }
                AssurGroup::Triad(t) => {
                    triads = true;
                    place.push(Place::Triad { group: gi });
                    rate.push(Rate::Triad(Box::new(compile_contour::<6>(
                        m,
                        gi,
                        [t.ext[0], t.int[0], t.int[1], t.ext[1], t.int[2], t.ext[2]],
                        TRIAD_CONTOURS,
                        &[
                            (t.ext[0].from, t.ext[1].from),
                            (t.ext[0].from, t.ext[2].from),
                        ],
                        &[t.leashes[0], t.leashes[1], t.leashes[2], t.base],
                        None,
                        &solved,
                        invert_lu,
                    ))));
                }
            }
            for l in g.links() {
                solved[l] = true;
            }
        }
        let triad_step = if triads {
            (0..m.scene.input_count())
                .map(|i| positions::triad_step(m, s, need, i))
                .collect()
        } else {
            Vec::new()
        };
        Ok(Program {
            m,
            s,
            place,
            rate,
            triad_step,
            branches,
        })
    }

    /// A state to run this program in: the sketch's positions tracked from.
    pub fn state(&self) -> State {
        let n = self.m.links.len();
        State {
            config: Configuration {
                poses: vec![None; n],
            },
            motion: vec![None; n],
            triad_pose: self.branches.triad_pose.clone(),
            last_q: sketch_input(self.m),
        }
    }

    /// The number of steps (positions and rates).
    pub fn len(&self) -> usize {
        self.place.len() + self.rate.len()
    }

    /// Whether the program has no steps (never: the frame's rate is one).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Positions at the input coordinate `q` (a single input), reached
    /// continuously from the last solved position, as
    /// [`crate::kinematics::positions::PositionSolver::solve`].
    #[inline]
    pub fn positions(&self, st: &mut State, q: f64) -> Result<()> {
        self.positions_coords(st, Coords::one(q))
    }

    /// Positions at the input coordinates `q`, reached continuously from
    /// the last solved position (class III groups tracked in small
    /// steps), as [`crate::kinematics::positions::PositionSolver::solve_coords`].
    pub fn positions_coords(&self, st: &mut State, q: Coords) -> Result<()> {
        if !self.triad_step.is_empty() {
            let span = positions::span(self.m, &st.last_q, &q);
            let n = span
                .iter()
                .enumerate()
                .map(|(i, d)| (d.abs() / self.triad_step[i]).ceil())
                .fold(0.0, f64::max) as usize;
            for k in 1..n {
                let mut qk = st.last_q;
                for (x, d) in qk.iter_mut().zip(span.iter()) {
                    *x += d * k as f64 / n as f64;
                }
                self.place(st, &qk)?;
            }
        }
        self.place(st, &q)?;
        st.last_q = q;
        Ok(())
    }

    /// Positions at `q` from the current tracked state, without stepping,
    /// as [`crate::kinematics::positions::PositionSolver::solve_at_coords`].
    pub fn positions_at(&self, st: &mut State, q: Coords) -> Result<()> {
        self.place(st, &q)
    }

    /// [`Program::positions_at`], the coordinates by reference.
    fn place(&self, st: &mut State, q: &[f64]) -> Result<()> {
        let (m, s) = (self.m, self.s);
        let c = &mut st.config;
        c.poses[m.frame()] = Some(Pose::IDENTITY);
        for step in &self.place {
            match step {
                Place::Crank {
                    input,
                    link,
                    at,
                    local,
                    offset,
                } => c.poses[*link] = Some(Pose::through(*at, *local, q[*input] - offset)),
                Place::Slider {
                    input,
                    link,
                    q0,
                    dir,
                    local,
                    delta,
                    turn,
                } => {
                    c.poses[*link] = Some(Pose::through_turned(
                        *q0 + *dir * q[*input],
                        *local,
                        *delta,
                        *turn,
                    ))
                }
                Place::Chained {
                    input,
                    known,
                    pair,
                    other,
                } => {
                    let kp = c.pose(*known);
                    c.poses[*other] =
                        Some(positions::place_across(m, *pair, *known, &kp, q[*input]));
                }
                Place::Rrr(g) => {
                    let (b, dd) = (g.b.world(c), g.d.world(c));
                    match circle_circle(b, g.seg1.len, dd, g.seg2.len, g.sign, -1.0) {
                        Some(x) => {
                            c.poses[g.links[0]] = Some(g.seg1.pose(g.b1, b, x));
                            c.poses[g.links[1]] = Some(g.seg2.pose(g.d2, dd, x));
                        }
                        None => self.dyad(c, g.group, q)?,
                    }
                }
                Place::Rrp(g) => {
                    let b = g.b.world(c);
                    let kp = c.pose(g.k2);
                    let th2 = if g.k2_guide {
                        kp.angle + g.delta
                    } else {
                        kp.angle - g.delta
                    };
                    let (sin, cos) = th2.sin_cos();
                    let rot = |v: Vec2| Vec2::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y);
                    let line = if g.k2_guide {
                        Line {
                            point: kp.apply(g.anchor) + rot(g.offset),
                            dir: kp.dir(g.line_dir),
                        }
                    } else {
                        Line {
                            point: kp.apply(g.anchor) + rot(g.offset),
                            dir: rot(g.line_dir),
                        }
                    };
                    match circle_line(b, g.r1, &line, g.sign, -1.0) {
                        Some(x) => {
                            c.poses[g.links[0]] = Some(g.seg1.pose(g.b1, b, x));
                            c.poses[g.links[1]] =
                                Some(Pose::through_turned(x, g.c2, th2, (cos, sin)));
                        }
                        None => self.dyad(c, g.group, q)?,
                    }
                }
                Place::Rpr(g) => {
                    let (jg, js) = (g.jg.world(c), g.js.world(c));
                    let w = js - jg;
                    let dist = w.hypot();
                    let sn = g.h / dist;
                    // Above a bound of the tolerance the interpreted form
                    // judges by (its rounding of the group's numbers),
                    // clear of every failure it tests.
                    let bound = 2.0
                        * ACCURACY.tangency_roundings
                        * f64::EPSILON
                        * (g.h.abs() + jg.x.abs() + jg.y.abs() + js.x.abs() + js.y.abs());
                    if sn.is_finite() && g.h.abs() - dist <= 0.0 && dist > bound {
                        let sn = sn.clamp(-1.0, 1.0);
                        let gamma_minus_beta = sn.atan2(g.sign * (1.0 - sn * sn).max(0.0).sqrt());
                        let psi = w.atan2() - gamma_minus_beta - g.alpha;
                        c.poses[g.guide] = Some(Pose::through(jg, g.jg_local, psi));
                        c.poses[g.slider] = Some(Pose::through(js, g.js_local, psi + g.delta));
                    } else {
                        self.dyad(c, g.group, q)?;
                    }
                }
                Place::Dyad { group } => self.dyad(c, *group, q)?,
                Place::Triad { group } => {
                    let AssurGroup::Triad(t) = &s.groups[*group] else {
                        unreachable!("a class III group")
                    };
                    let pose = positions::solve_triad(m, t, st.triad_pose[*group], c)
                        .map_err(|why| triad_error(m, s, *group, q, why))?;
                    st.triad_pose[*group] = pose;
                }
            }
        }
        Ok(())
    }

    /// Dyad `gi` by the interpreted closed form (its tolerances, its errors).
    #[cold]
    fn dyad(&self, c: &mut Configuration, gi: usize, q: &[f64]) -> Result<()> {
        let (m, s) = (self.m, self.s);
        let AssurGroup::Dyad(d) = &s.groups[gi] else {
            unreachable!("a class II group")
        };
        let cyl = d.cylinder.map(|cy| (cy, q[cy.input]));
        positions::solve_dyad(m, d, cyl, self.branches.sign[gi], c)
            .map_err(|why| dyad_error(m, s, gi, q, why))
    }

    /// Velocities (and accelerations when `order` asks) of every solved
    /// link at the positions in `st`, as
    /// [`crate::kinematics::analytic::contour::solve`] gives them.
    pub fn rates(&self, st: &mut State, drive: impl Into<Drives>, order: Order) -> Result<()> {
        self.rates_of(st, &drive.into(), order)
    }

    /// [`Program::rates`], the drives by reference.
    fn rates_of(&self, st: &mut State, drives: &[Drive], order: Order) -> Result<()> {
        let m = self.m;
        let (c, out) = (&st.config, &mut st.motion);
        for step in &self.rate {
            match step {
                Rate::Frame => {
                    out[m.frame()] = Some(Motion::from_point(
                        c.pose(m.frame()),
                        Point::ORIGIN,
                        Vec2::ZERO,
                        Vec2::ZERO,
                        0.0,
                        0.0,
                    ))
                }
                Rate::Crank { input, link, pivot } => {
                    let d = drives[*input];
                    let o = c.pose(m.frame()).apply(*pivot);
                    out[*link] = Some(Motion::from_point(
                        c.pose(*link),
                        o,
                        Vec2::ZERO,
                        Vec2::ZERO,
                        d.rate,
                        d.rate2,
                    ));
                }
                Rate::Slider { input, link, dir } => {
                    let d = drives[*input];
                    let pose = c.pose(*link);
                    let u = c.pose(m.frame()).dir(*dir);
                    out[*link] = Some(Motion::from_point(
                        pose,
                        pose.origin,
                        u * d.rate,
                        u * d.rate2,
                        0.0,
                        0.0,
                    ));
                }
                Rate::Chained {
                    input,
                    known,
                    pair,
                    other,
                } => {
                    let d = drives[*input];
                    let kmo = out[*known].expect("solved before");
                    out[*other] = Some(contour::across(m, c, *pair, *known, &kmo, d.rate, d.rate2));
                }
                Rate::Dyad3(g) => {
                    if g.run(c, out, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
                Rate::Dyad(g) => {
                    if g.run(c, out, drives, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
                Rate::Triad(g) => {
                    if g.run(c, out, drives, order).is_none() {
                        return Err(self.singular(g.group, drives));
                    }
                }
            }
        }
        Ok(())
    }

    #[cold]
    fn singular(&self, gi: usize, drives: &[Drive]) -> crate::error::Error {
        contour::singular(self.m, &self.s.groups[gi], &Drives::new(drives))
    }

    /// Positions at `drive`'s coordinates (tracked from the last) and
    /// their rates: one step of a sweep.
    pub fn solve(&self, st: &mut State, drive: impl Into<Drives>, order: Order) -> Result<()> {
        let drives: Drives = drive.into();
        self.positions_coords(st, drives.coords())?;
        self.rates_of(st, &drives, order)
    }

    /// [`Program::solve`] of a mechanism with one input: the same steps,
    /// without gathering the inputs into [`Drives`] and [`Coords`].
    #[inline]
    pub fn solve_one(&self, st: &mut State, drive: Drive, order: Order) -> Result<()> {
        assert_eq!(self.m.scene.input_count(), 1, "a mechanism with one input");
        if self.triad_step.is_empty() {
            self.place(st, &[drive.q])?;
            st.last_q = Coords::one(drive.q);
        } else {
            self.positions_coords(st, Coords::one(drive.q))?;
        }
        self.rates_of(st, &[drive], order)
    }
}

/// The steps of an input on the frame: its place and its rate.
fn input_steps(m: &Mechanism, i: usize) -> (Place, Rate) {
    match *m.scene.input_at(i) {
        InputSpec::Crank { link, pivot, .. } => {
            let pts = &m.links[link].points;
            let other = if pts[0] == pivot { pts[1] } else { pts[0] };
            let w = m.local(link, other) - m.local(link, pivot);
            let at = m.links[m.frame()]
                .sketch_pose
                .apply(m.local(m.frame(), pivot));
            (
                Place::Crank {
                    input: i,
                    link,
                    at,
                    local: m.local(link, pivot),
                    offset: w.atan2(),
                },
                Rate::Crank {
                    input: i,
                    link,
                    pivot: m.local(m.frame(), pivot),
                },
            )
        }
        InputSpec::Slider { link, pair, .. } => {
            let pr = &m.prismatics[pair];
            let line = pr.line(&Pose::IDENTITY);
            let (sin, cos) = pr.delta.sin_cos();
            (
                Place::Slider {
                    input: i,
                    link,
                    q0: positions::sketch_slider_ref(m, pair),
                    dir: line.dir,
                    local: pr.slider_local,
                    delta: pr.delta,
                    turn: (cos, sin),
                },
                Rate::Slider {
                    input: i,
                    link,
                    dir: pr.line_dir,
                },
            )
        }
    }
}

/// The step that places dyad `gi`: its kind's closed form with its
/// constants, or the interpreted one (PRP, RPP, a cylinder's).
fn dyad_place(m: &Mechanism, gi: usize, d: &crate::model::structure::Dyad, sign: f64) -> Place {
    if d.cylinder.is_some() {
        return Place::Dyad { group: gi };
    }
    let [l1, l2] = d.links;
    match d.kind {
        DyadKind::Rrr => {
            let (pb, pc, pd) = (
                point_of(d.ext1.joint),
                point_of(d.mid.joint),
                point_of(d.ext2.joint),
            );
            let (b1, c1) = (m.local(l1, pb), m.local(d.mid.from, pc));
            let (d2, c2) = (m.local(l2, pd), m.local(d.mid.to, pc));
            Place::Rrr(Box::new(Rrr {
                group: gi,
                sign,
                links: d.links,
                b: On::new(m, d.ext1.from, pb),
                d: On::new(m, d.ext2.to, pd),
                b1,
                d2,
                seg1: Segment::new(c1 - b1),
                seg2: Segment::new(c2 - d2),
            }))
        }
        DyadKind::Rrp => {
            let (pb, pc) = (point_of(d.ext1.joint), point_of(d.mid.joint));
            let k = pair_of(d.ext2.joint);
            let k2 = d.ext2.to;
            let pr = &m.prismatics[k];
            let x = m.local(l2, pc);
            let k2_guide = pr.guide == k2;
            let (anchor, offset) = if k2_guide {
                (pr.line_point, x - pr.slider_local)
            } else {
                (pr.slider_local, x - pr.line_point)
            };
            let (b1, c1) = (m.local(l1, pb), m.local(d.mid.from, pc));
            Place::Rrp(Box::new(Rrp {
                group: gi,
                sign,
                links: d.links,
                b: On::new(m, d.ext1.from, pb),
                b1,
                seg1: Segment::new(c1 - b1),
                r1: (c1 - b1).hypot(),
                k2,
                k2_guide,
                delta: pr.delta,
                anchor,
                offset,
                line_dir: pr.line_dir,
                c2: x,
            }))
        }
        DyadKind::Rpr => {
            let rg = positions::rocking_guide(m, d);
            let pin = |p: usize| {
                if p == point_of(d.ext1.joint) {
                    On::new(m, d.ext1.from, p)
                } else {
                    On::new(m, d.ext2.to, p)
                }
            };
            Place::Rpr(Box::new(Rpr {
                group: gi,
                sign,
                guide: rg.guide,
                slider: rg.slider,
                jg: pin(rg.pin_guide),
                js: pin(rg.pin_slider),
                jg_local: m.local(rg.guide, rg.pin_guide),
                js_local: m.local(rg.slider, rg.pin_slider),
                h: rg.h,
                alpha: rg.alpha,
                delta: rg.delta,
            }))
        }
        DyadKind::Prp | DyadKind::Rpp => Place::Dyad { group: gi },
    }
}

/// The known side of the contours: the twist (or twist rate) of each
/// contour's end link less that of its start link (`contour::rhs`).
#[inline]
fn rhs<const N: usize>(ends: &[(Src, Src)], f: impl Fn(Src) -> Twist) -> SVector<f64, N> {
    let mut r = SVector::<f64, N>::zeros();
    for (ci, &(k1, k2)) in ends.iter().enumerate() {
        let t = f(k2) - f(k1);
        r[3 * ci] = t.w;
        r[3 * ci + 1] = t.v.x;
        r[3 * ci + 2] = t.v.y;
    }
    r
}
