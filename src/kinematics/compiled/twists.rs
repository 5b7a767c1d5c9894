//! A group's closed vector contour compiled: the pairs' twists, where
//! each known velocity comes from, the walks along the contour, and the
//! contour's solution for the unknown rates.

use super::place::On;
use crate::geom::perp;
use crate::kinematics::analytic::contour::{self, Inverse, Twist, bracket};
use crate::kinematics::analytic::{Drive, Motion, Order};
use crate::kinematics::positions::Configuration;
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Conn, Joint};
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
    pub(super) fn new(m: &Mechanism, conn: &Conn) -> PairTwist {
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
    pub(super) twist: PairTwist,
    pub(super) input: usize,
    pub(super) contour: Option<usize>,
    pub(super) from: Src,
}

/// The most links a group reads as known (a three-leash group: three
/// outer links), walks to (four), or walks over pairs (six and a driven one).
pub(super) const MAX_KNOWN: usize = 6;

pub(super) const MAX_WALK: usize = 8;

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
    pub(super) contours: &'static [&'static [(usize, f64)]],
    pub(super) ends: [(Src, Src); 2],
    pub(super) known: [usize; MAX_KNOWN],
    pub(super) n_known: usize,
    pub(super) walk: [Walk; MAX_WALK],
    pub(super) n_walk: usize,
    /// Where the walk finds each pair's `from` link (the drift terms).
    pub(super) drift_from: [Src; N],
    /// The group's links in ascending order, where each one's twist is.
    pub(super) links: [(usize, Src); 4],
    pub(super) n_links: usize,
    pub(super) invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
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
