//! The rate steps of a compiled [`Program`]: each group's closed vector
//! contours compiled once (the twist of each pair, which links the group
//! reads as known, the order in which the walk reaches its links), run
//! with the arithmetic of [`crate::kinematics::analytic::contour`] in its
//! order, and the [`Rate`] step list (the frame, the inputs, the groups)
//! with [`Program`]'s running of it. A plain dyad's contour is handed to
//! its scalar form ([`super::dyad3`]).

use super::twists::{Contour, DrivenPair, MAX_KNOWN, MAX_WALK, PairTwist, Src, Walk};
use super::dyad3::Dyad3;
use crate::kinematics::analytic::contour::{self, Contours, Reach};
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Chained, Conn};
use kurbo::Vec2;

/// The contours' compiler: which links are known, the walk over the pairs
/// exactly as [`contour`]'s walk takes it.
struct Compiling<'s> {
    pub(super) solved: &'s [bool],
    pub(super) known: [usize; MAX_KNOWN],
    pub(super) n_known: usize,
    pub(super) found: [usize; 4],
    pub(super) n_found: usize,
}

impl Compiling<'_> {
    pub(super) fn get(&mut self, l: usize) -> Option<Src> {
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
    pub(super) fn add(&mut self, l: usize) {
        self.found[self.n_found] = l;
        self.n_found += 1;
    }
}

/// The walk as compiled: each step it takes, in order.
struct Walking<'c, 's> {
    pub(super) cp: &'c mut Compiling<'s>,
    pub(super) walk: [Walk; MAX_WALK],
    pub(super) n_walk: usize,
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

