//! The rate steps of a compiled [`Program`]: each group's closed vector
//! contours compiled once (the twist of each pair, which links the group
//! reads as known, the order in which the walk reaches its links), run
//! with the arithmetic of [`crate::kinematics::analytic::contour`] in its
//! order, and the [`Rate`] step list (the frame, the inputs, the groups)
//! with [`Program`]'s running of it. A plain dyad's contour is handed to
//! its scalar form ([`super::dyad3`]).

use super::dyad3::Dyad3;
use super::place::On;
use super::{Program, State};
use crate::error::Result;
use crate::geom::perp;
use crate::kinematics::analytic::contour::{self, Contours, Inverse, Reach, Twist, bracket};
use crate::kinematics::analytic::{Drive, Drives, Motion, Order};
use crate::kinematics::positions::Configuration;
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Chained, Conn, Joint};
use kurbo::{Point, Vec2};
use nalgebra::SMatrix;

/// The twist of a pair's unit rate about a point, as a step computes it:
/// a revolute pair at its point on link `link`, a prismatic pair along
/// its guide's direction (negated when the contour enters the guide).
#[derive(Clone, Copy, Debug)]
pub(super) enum PairTwist {
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
    pub(super) fn twist(&self, c: &Configuration, o: Point) -> Twist {
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
pub(super) enum Src {
    Known(usize),
    Found(usize),
}

/// One step of a contour's walk: the next link's twist is the twist at
/// `base` plus (`forward`) or minus the relative twist across pair `j`
/// (`j` = N: the driven pair).
#[derive(Clone, Copy, Debug)]
pub(super) struct Walk {
    pub(super) base: Src,
    pub(super) j: usize,
    pub(super) forward: bool,
}

/// A driven pair (a cylinder's) on or off a dyad's contour.
#[derive(Clone, Copy, Debug)]
pub(super) struct DrivenPair {
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
pub(super) struct Contour<const N: usize> {
    pub(super) group: usize,
    /// The twists are taken about this link's origin.
    pub(super) o_link: usize,
    pub(super) pairs: [PairTwist; N],
    pub(super) driven: Option<DrivenPair>,
    contours: &'static [&'static [(usize, f64)]],
    pub(super) ends: [(Src, Src); 2],
    pub(super) known: [usize; MAX_KNOWN],
    n_known: usize,
    pub(super) walk: [Walk; MAX_WALK],
    pub(super) n_walk: usize,
    /// Where the walk finds each pair's `from` link (the drift terms).
    pub(super) drift_from: [Src; N],
    /// The group's links in ascending order, where each one's twist is.
    pub(super) links: [(usize, Src); 4],
    pub(super) n_links: usize,
    invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
}

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

/// The walk as compiled: each step it takes, in order.
struct Walking<'c, 's> {
    cp: &'c mut Compiling<'s>,
    walk: [Walk; MAX_WALK],
    n_walk: usize,
}

impl Reach for Walking<'_, '_> {
    type Base = Src;
    fn get(&mut self, l: usize) -> Option<Src> {
        self.cp.get(l)
    }
    fn found(&mut self, j: usize, base: Src, forward: bool, l: usize) {
        self.walk[self.n_walk] = Walk { base, j, forward };
        self.n_walk += 1;
        self.cp.add(l);
    }
}

/// Compile group `group`'s contours `on`: its links `links` (the first
/// the one whose origin the twists are taken about), a cylinder's driven
/// pair (with its input and the contour it lies on), the links `solved`
/// before it.
pub(super) fn compile_contour<const N: usize>(
    m: &Mechanism,
    group: usize,
    on: &Contours<N>,
    links: &[usize],
    driven: Option<(Conn, usize, Option<usize>)>,
    solved: &[bool],
) -> Contour<N> {
    let (conns, contours, ends, invert) = (on.pairs, on.contours, on.ends(), on.invert);
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
    let mut walking = Walking {
        cp: &mut cp,
        walk: [Walk {
            base: Src::Known(0),
            j: 0,
            forward: true,
        }; MAX_WALK],
        n_walk: 0,
    };
    contour::walk_pairs(&all[..n], &mut walking);
    let (walk, n_walk) = (walking.walk, walking.n_walk);
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
    pub(super) fn run(
        &self,
        c: &Configuration,
        out: &mut [Option<Motion>],
        drives: &[Drive],
        order: Order,
    ) -> Option<()> {
        let o = c.pose(self.o_link).origin;
        let xi: [Twist; N] = std::array::from_fn(|j| self.pairs[j].twist(c, o));
        let xd = self.driven.map(|d| d.twist.twist(c, o));
        let per_length = contour::per_length(&xi);
        let contours = self.contours;
        let a = contour::contour_matrix::<N>(contours, &xi, per_length);
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
        let on_contour = self.driven.and_then(|d| d.contour);
        let driven_rates = self
            .driven
            .map(|d| (drives[d.input].rate, drives[d.input].rate2));
        let mut rhs_v = contour::rhs::<N, _>(ends, |s| known(s).0);
        if let (Some((rate, _)), Some(x)) = (driven_rates, xd) {
            contour::subtract_on(&mut rhs_v, on_contour, x * rate);
        }
        let qd = inverse.solve(&contour::in_group_units(rhs_v, contours.len(), per_length));
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
            let mut rhs = contour::rhs::<N, _>(ends, |s| known(s).1);
            contour::subtract_drift(&mut rhs, contours, &drift);
            let driven_acc = match (self.driven, driven_rates, xd) {
                (Some(d), Some((rate, rate2)), Some(x)) => {
                    let t = x * rate2 + bracket(vel_of(d.from), x) * rate;
                    contour::subtract_on(&mut rhs, on_contour, t);
                    t
                }
                _ => Twist::default(),
            };
            let qdd = inverse.solve(&contour::in_group_units(rhs, contours.len(), per_length));
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
            let a = match s {
                Src::Found(f) if accelerations => acc[f],
                _ => Twist::default(),
            };
            out[l] = Some(contour::twist_motion(c.pose(l), o, vel_of(s), a));
        }
        Some(())
    }
}

/// One step of the rates.
#[derive(Clone, Debug)]
pub(super) enum Rate {
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
    Chained(Chained),
    Dyad3(Box<Dyad3>),
    Dyad(Box<Contour<3>>),
    Triad(Box<Contour<6>>),
}

impl Program<'_> {
    /// [`Program::rates`], the drives by reference.
    pub(super) fn rates_of(&self, st: &mut State, drives: &[Drive], order: Order) -> Result<()> {
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
                Rate::Chained(ch) => {
                    let kmo = out[ch.known].expect("solved before");
                    out[ch.other] =
                        Some(contour::chained_motion(m, c, *ch, &kmo, drives[ch.input]));
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
}
