//! Route (a): the method of closed vector contours, group by group.
//!
//! Each Assur group closes a contour from one known link, through its own
//! links and pairs, to another known link. Written in the pairs' own
//! coordinates (the relative rotation at a revolute pair, the relative
//! slide at a prismatic pair) the velocity contour is
//! `V_K1 + Σ q̇_j·ξ_j = V_K2`, three scalar equations per contour, where
//! ξ_j is the pair's unit twist (`(1, −k×r_P)` for a revolute pair at P,
//! `(0, u)` for a slide along u). Differentiating once more gives the same
//! matrix with the known terms `q̇_j·[V_j, ξ_j]`: the normal components
//! ω²·l and the Coriolis terms 2·ω·v_rel of the textbook come out of these
//! brackets. A dyad gives one contour (3×3, inverted in
//! closed form), a three-leash group two contours (6×6).

mod algebra;
mod twist;

use super::{Drive, Drives, Motion, Order};
use crate::error::{Error, Result};
use crate::kinematics::positions::{Configuration, describe_input};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Chained, Conn, Dyad, Joint, Step, Structure, Triad};
use kurbo::Vec2;
use nalgebra::SMatrix;

use algebra::walk;
pub(crate) use algebra::{
    Inverse, Reach, contour_matrix, in_group_units, invert_lu, invert3, per_length, rhs,
    subtract_drift, subtract_on, walk_pairs,
};
use twist::unit_twist;
pub(crate) use twist::{Twist, bracket, state, twist_motion};

/// Velocity and acceleration of input `i`'s link: a crank about its
/// pivot, a slider along a guide of the frame.
pub fn input_motion(m: &Mechanism, c: &Configuration, i: usize, rate: f64, rate2: f64) -> Motion {
    let spec = m.scene.input_at(i);
    let pose = c.pose(spec.link());
    match *spec {
        InputSpec::Crank { pivot, .. } => {
            let o = c.point(m, m.frame(), pivot);
            Motion::from_point(pose, o, Vec2::ZERO, Vec2::ZERO, rate, rate2)
        }
        InputSpec::Slider { pair, .. } => {
            let u = c.pose(m.frame()).dir(m.prismatics[pair].line_dir);
            Motion::from_point(pose, pose.origin, u * rate, u * rate2, 0.0, 0.0)
        }
    }
}

/// The motion of the link that driving pair `k` places, its other link
/// `known` moving as `known_mo`, the slide's rate and its rate `rate2`:
/// the twist of the known link plus the relative slide, and its rate plus
/// the slide's own and the bracket (the Coriolis term 2·ω·v_rel).
pub fn across(
    m: &Mechanism,
    c: &Configuration,
    k: usize,
    known: usize,
    known_mo: &Motion,
    rate: f64,
    rate2: f64,
) -> Motion {
    let pr = &m.prismatics[k];
    let other = if pr.guide == known {
        pr.slider
    } else {
        pr.guide
    };
    let o = c.point(m, pr.slider, pr.point);
    let conn = Conn {
        joint: Joint::P(k),
        from: known,
        to: other,
    };
    let xi = unit_twist(m, c, &conn, o);
    let (v, dv) = state(known_mo, o);
    let vel = v + xi * rate;
    let acc = dv + xi * rate2 + bracket(v, xi) * rate;
    twist_motion(c.pose(other), o, vel, acc)
}

/// The motion of the link a chained input places, its known link moving
/// as `known_mo`, at the input's drive `d` ([`across`]).
#[inline]
pub(crate) fn chained_motion(
    m: &Mechanism,
    c: &Configuration,
    ch: Chained,
    known_mo: &Motion,
    d: Drive,
) -> Motion {
    across(m, c, ch.pair, ch.known, known_mo, d.rate, d.rate2)
}

/// The driving pair of a cylinder in a dyad, traversed along the dyad's
/// contour (from the link in the cylinder's slot to the other for slot 0,
/// back for slot 1), and whether the contour passes through it (the
/// middle pair on the other link) or the other link only hangs on it.
pub(crate) fn driven_pair(d: &Dyad) -> Option<(Conn, usize, bool)> {
    let cy = d.cylinder?;
    let own = d.links[cy.slot];
    let (conn, on) = if cy.slot == 0 {
        (
            Conn {
                joint: Joint::P(cy.pair),
                from: own,
                to: cy.other,
            },
            d.mid.from == cy.other,
        )
    } else {
        (
            Conn {
                joint: Joint::P(cy.pair),
                from: cy.other,
                to: own,
            },
            d.mid.to == cy.other,
        )
    };
    Some((conn, cy.input, on))
}

/// A pair whose rate is given (a cylinder's driving pair) in a group's
/// contour: the pair, its rate and rate of rate, and the contour it lies
/// on (None: off the contours, it only carries a link hanging on it).
#[derive(Clone, Copy)]
struct Driven {
    conn: Conn,
    rate: f64,
    rate2: f64,
    contour: Option<usize>,
}

/// Velocities (and accelerations when `order` asks) of every solved link.
/// `drive`: each input's coordinate and rates (ω, ε of a crank; v, a of a
/// driving slider).
pub fn solve(
    m: &Mechanism,
    s: &Structure,
    need: &[bool],
    c: &Configuration,
    drive: impl Into<Drives>,
    order: Order,
) -> Result<Vec<Option<Motion>>> {
    let drives: Drives = drive.into();
    // The motions found so far; a group reads the twists of its known
    // links off them (`state`).
    let mut out: Vec<Option<Motion>> = vec![None; m.links.len()];
    let frame = Motion::from_point(
        c.pose(m.frame()),
        kurbo::Point::ORIGIN,
        Vec2::ZERO,
        Vec2::ZERO,
        0.0,
        0.0,
    );
    out[m.frame()] = Some(frame);
    let mut motions: [(usize, Motion); 4] = [(0, frame); 4];
    for step in s.steps(m) {
        match step {
            Step::Frame { input, link } => {
                let d = drives[input];
                out[link] = Some(input_motion(m, c, input, d.rate, d.rate2));
            }
            Step::Chained(ch) => {
                if let Some(kmo) = out[ch.known] {
                    out[ch.other] = Some(chained_motion(m, c, ch, &kmo, drives[ch.input]));
                }
            }
            Step::Group { index, .. } if !need[index] => {}
            Step::Group { group, .. } => {
                let count = solve_group(m, c, group, &drives, &out, order, &mut motions)
                    .ok_or_else(|| singular(m, group, &drives))?;
                for &(l, mo) in &motions[..count] {
                    out[l] = Some(mo);
                }
            }
        }
    }
    Ok(out)
}

/// The transfer functions at the positions `c` (input coordinate `q`):
/// the rates at unit input rate and zero rate of rate ([`solve`]).
pub fn transfer(
    m: &Mechanism,
    s: &Structure,
    need: &[bool],
    c: &Configuration,
    q: f64,
    order: Order,
) -> Result<Vec<Option<Motion>>> {
    let unit = Drive {
        q,
        rate: 1.0,
        rate2: 0.0,
    };
    solve(m, s, need, c, unit, order)
}

/// A dyad's single contour through its three pairs.
const DYAD_CONTOURS: &[&[(usize, f64)]] = &[&[(0, 1.0), (1, 1.0), (2, 1.0)]];
/// A three-leash group's two contours.
const TRIAD_CONTOURS: &[&[(usize, f64)]] = &[
    &[(0, 1.0), (1, 1.0), (2, -1.0), (3, -1.0)],
    &[(0, 1.0), (1, 1.0), (4, -1.0), (5, -1.0)],
];

/// A group's contours: its `N` pairs in contour order, the contours as
/// (pair index, sign) lists from the known link of an end to the known
/// link of the other end, and the inversion of their matrix.
#[derive(Clone, Copy)]
pub(crate) struct Contours<const N: usize> {
    pub pairs: [Conn; N],
    pub contours: &'static [&'static [(usize, f64)]],
    ends: [(usize, usize); 2],
    pub invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
}

impl<const N: usize> Contours<N> {
    /// Each contour's (start, end) known links.
    pub fn ends(&self) -> &[(usize, usize)] {
        &self.ends[..self.contours.len()]
    }
}

/// A dyad's contour: its pairs from K1 to K2, inverted in closed form.
pub(crate) fn dyad_contours(d: &Dyad) -> Contours<3> {
    let ends = (d.ext1.from, d.ext2.to);
    Contours {
        pairs: [d.ext1, d.mid, d.ext2],
        contours: DYAD_CONTOURS,
        ends: [ends, ends],
        invert: invert3,
    }
}

/// A three-leash group's two contours: from the first leash's known
/// link to the second's and the third's, inverted by LU.
pub(crate) fn triad_contours(t: &Triad) -> Contours<6> {
    Contours {
        pairs: [t.ext[0], t.int[0], t.int[1], t.ext[1], t.int[2], t.ext[2]],
        contours: TRIAD_CONTOURS,
        ends: [
            (t.ext[0].from, t.ext[1].from),
            (t.ext[0].from, t.ext[2].from),
        ],
        invert: invert_lu,
    }
}

/// One group's rates at the drives `drives`, the links before it known
/// (`out`): [`group`] with the group's contours; `None` when its velocity
/// contour is singular.
fn solve_group(
    m: &Mechanism,
    c: &Configuration,
    g: &AssurGroup,
    drives: &Drives,
    out: &[Option<Motion>],
    order: Order,
    motions: &mut [(usize, Motion); 4],
) -> Option<usize> {
    // The pairs of the group, in contour order: each contour is a list
    // of (pair index, sign) from a known link to a known link.
    match g {
        AssurGroup::Dyad(d) => {
            let driven = driven_pair(d).map(|(conn, input, on)| Driven {
                conn,
                rate: drives[input].rate,
                rate2: drives[input].rate2,
                contour: on.then_some(0),
            });
            let on = dyad_contours(d);
            group::<3>(m, c, &on, out, order, &d.placed_links(), driven, motions)
        }
        AssurGroup::Triad(t) => {
            let on = triad_contours(t);
            group::<6>(m, c, &on, out, order, &t.placed_links(), None, motions)
        }
    }
}

/// The error of a group whose velocity contour is singular at `drives`.
pub(crate) fn singular(m: &Mechanism, g: &AssurGroup, drives: &Drives) -> Error {
    Error::singular(
        describe_input(m, &drives.coords()),
        format!(
            "the velocity contour of group {} is singular (a dead point)",
            g.label(m)
        ),
    )
}

/// One group's contours: the rates in its pairs, then the motion of each
/// of its links (`links`, written to `motions` in ascending link order, the
/// order of [`AssurGroup::links`]); `None` when the velocity contour is
/// singular.
#[allow(clippy::too_many_arguments)]
fn group<const N: usize>(
    m: &Mechanism,
    c: &Configuration,
    on: &Contours<N>,
    known: &[Option<Motion>],
    order: Order,
    links: &[usize],
    driven: Option<Driven>,
    motions: &mut [(usize, Motion); 4],
) -> Option<usize> {
    let (conns, contours, ends) = (on.pairs, on.contours, on.ends());
    // The twists are taken about a point of the group (the pose of its
    // first link), so that the contour's numbers are the group's own size.
    let o = c.pose(links[0]).origin;
    let xi: [Twist; N] = conns.map(|cn| unit_twist(m, c, &cn, o));
    // The driven pair: its unit twist, and the conns walked (the group's
    // and the driven one last).
    let xd = driven.map(|d| unit_twist(m, c, &d.conn, o));
    let mut all = [conns[0]; 8];
    all[..N].copy_from_slice(&conns);
    let walked = match driven {
        Some(d) => {
            all[N] = d.conn;
            N + 1
        }
        None => N,
    };
    let all = &all[..walked];
    // The contour's velocity rows in the group's own unit of length (its
    // joints' reach from o): a small group is as well conditioned as a
    // large one of the same shape, and its dead point is judged so.
    let per_length = per_length(&xi);
    let a = contour_matrix::<N>(contours, &xi, per_length);
    let state_of = |l: usize| known[l].map(|mo| state(&mo, o));
    let known = |l: usize| state_of(l).expect("attachment solved first");
    let inverse = (on.invert)(&a)?;
    let mut rhs_v = rhs::<N, _>(ends, |l| known(l).0);
    // The given slide on a contour is a known term.
    if let (Some(d), Some(x)) = (driven, xd) {
        subtract_on(&mut rhs_v, d.contour, x * d.rate);
    }
    let qd = inverse.solve(&in_group_units(rhs_v, contours.len(), per_length));
    let step_v = |j: usize| match (driven, xd) {
        (Some(d), Some(x)) if j == N => x * d.rate,
        _ => xi[j] * qd[j],
    };
    let (vel, nv) = walk(all, step_v, |l| state_of(l).map(|k| k.0));
    let vel_of = |l: usize| {
        state_of(l)
            .map(|k| k.0)
            .or_else(|| vel[..nv].iter().find(|e| e.0 == l).map(|e| e.1))
    };
    // Accelerations: the same matrix, known terms from the brackets.
    let mut acc = [(usize::MAX, Twist::default()); 4];
    let mut na = 0;
    if order == Order::Acceleration {
        let drift: [Twist; N] =
            std::array::from_fn(|j| bracket(vel_of(conns[j].from).unwrap(), xi[j]) * qd[j]);
        let mut rhs = rhs::<N, _>(ends, |l| known(l).1);
        subtract_drift(&mut rhs, contours, &drift);
        // The driven pair's given slide rate and its bracket (Coriolis).
        let driven_acc = match (driven, xd) {
            (Some(d), Some(x)) => {
                let t = x * d.rate2 + bracket(vel_of(d.conn.from).unwrap(), x) * d.rate;
                subtract_on(&mut rhs, d.contour, t);
                t
            }
            _ => Twist::default(),
        };
        let qdd = inverse.solve(&in_group_units(rhs, contours.len(), per_length));
        (acc, na) = walk(
            all,
            |j| {
                if j == N {
                    driven_acc
                } else {
                    xi[j] * qdd[j] + drift[j]
                }
            },
            |l| state_of(l).map(|k| k.1),
        );
    }
    let sorted = sorted_links(links);
    for (k, &l) in sorted[..links.len()].iter().enumerate() {
        let v = vel_of(l).expect("every group link reached");
        let a = acc[..na]
            .iter()
            .find(|e| e.0 == l)
            .map(|e| e.1)
            .unwrap_or_default();
        motions[k] = (l, twist_motion(c.pose(l), o, v, a));
    }
    Some(links.len())
}

/// A group's links (at most four) in ascending order: an insertion sort,
/// not the general sort.
fn sorted_links(links: &[usize]) -> [usize; 4] {
    let mut sorted = [0usize; 4];
    sorted[..links.len()].copy_from_slice(links);
    for i in 1..links.len() {
        let mut j = i;
        while j > 0 && sorted[j - 1] > sorted[j] {
            sorted.swap(j - 1, j);
            j -= 1;
        }
    }
    sorted
}
