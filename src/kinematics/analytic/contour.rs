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

use super::{Drives, Motion, Order};
use crate::accuracy::ACCURACY;
use crate::error::{Error, Result};
use crate::geom::perp;
use crate::kinematics::positions::{Configuration, describe_input};
use crate::model::mechanism::Mechanism;
use crate::model::scene::InputSpec;
use crate::model::structure::{AssurGroup, Conn, Dyad, InputRole, Joint, Stage, Structure};
use kurbo::{Point, Vec2};
use nalgebra::{SMatrix, SVector};

/// A planar twist: angular rate and the velocity of the point at the origin.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Twist {
    pub w: f64,
    pub v: Vec2,
}

impl std::ops::Add for Twist {
    type Output = Twist;
    #[inline]
    fn add(self, o: Twist) -> Twist {
        Twist {
            w: self.w + o.w,
            v: self.v + o.v,
        }
    }
}
impl std::ops::Sub for Twist {
    type Output = Twist;
    #[inline]
    fn sub(self, o: Twist) -> Twist {
        Twist {
            w: self.w - o.w,
            v: self.v - o.v,
        }
    }
}
impl std::ops::Mul<f64> for Twist {
    type Output = Twist;
    #[inline]
    fn mul(self, k: f64) -> Twist {
        Twist {
            w: self.w * k,
            v: self.v * k,
        }
    }
}

/// The Lie bracket [a, b] of planar twists: how b, carried by a body
/// moving with a, changes in time.
#[inline]
pub(crate) fn bracket(a: Twist, b: Twist) -> Twist {
    Twist {
        w: 0.0,
        v: perp(b.v) * a.w - perp(a.v) * b.w,
    }
}

/// Twist and twist rate of a link about the fixed point `o`: the
/// velocity of the link's material point at `o`, and the rate of that
/// spatial twist. The rate of the spatial velocity v_o is not the
/// acceleration of the material point at o: a_o = v̇_o + ω×v_o.
#[inline]
pub(crate) fn state(mo: &Motion, o: Point) -> (Twist, Twist) {
    let v = mo.velocity(o);
    (
        Twist { w: mo.omega, v },
        Twist {
            w: mo.epsilon,
            v: mo.acceleration(o) - perp(v) * mo.omega,
        },
    )
}

/// Unit twist of a pair about the point `o`, traversed from `conn.from`
/// to `conn.to`; the rate that multiplies it is ω_to − ω_from (revolute)
/// or the slide of the slider along its guide (prismatic).
fn unit_twist(m: &Mechanism, c: &Configuration, conn: &Conn, o: Point) -> Twist {
    match conn.joint {
        Joint::R(p) => {
            let at = c.point(m, conn.to, p);
            Twist {
                w: 1.0,
                v: -perp(at - o),
            }
        }
        Joint::P(k) => {
            let pr = &m.prismatics[k];
            let u = c.pose(pr.guide).dir(pr.line_dir);
            Twist {
                w: 0.0,
                v: if conn.to == pr.slider { u } else { -u },
            }
        }
    }
}

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
    Motion::from_point(
        c.pose(other),
        o,
        vel.v,
        acc.v + perp(vel.v) * vel.w,
        vel.w,
        acc.w,
    )
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
    for &st in &s.stages {
        let gi = match st {
            Stage::Input(i) => {
                let d = drives[i];
                match s.roles[i] {
                    InputRole::Frame => {
                        out[m.scene.input_at(i).link()] =
                            Some(input_motion(m, c, i, d.rate, d.rate2));
                    }
                    InputRole::Chained { known, pair } => {
                        if let Some(kmo) = out[known] {
                            let pr = &m.prismatics[pair];
                            let other = if pr.guide == known {
                                pr.slider
                            } else {
                                pr.guide
                            };
                            out[other] = Some(across(m, c, pair, known, &kmo, d.rate, d.rate2));
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
        let singular = || singular(m, g, &drives);
        // The pairs of the group, in contour order: each contour is a list
        // of (pair index, sign) from a known link to a known link.
        let done = match g {
            AssurGroup::Dyad(d) => {
                let driven = driven_pair(d).map(|(conn, input, on)| Driven {
                    conn,
                    rate: drives[input].rate,
                    rate2: drives[input].rate2,
                    contour: on.then_some(0),
                });
                let mut links = [0usize; 3];
                links[..2].copy_from_slice(&d.links);
                let n = match d.cylinder {
                    Some(cy) => {
                        links[2] = cy.other;
                        3
                    }
                    None => 2,
                };
                group::<3>(
                    m,
                    c,
                    [d.ext1, d.mid, d.ext2],
                    &[&[(0, 1.0), (1, 1.0), (2, 1.0)]],
                    &[(d.ext1.from, d.ext2.to)],
                    &out,
                    order,
                    invert3,
                    &links[..n],
                    driven,
                    &mut motions,
                )
            }
            AssurGroup::Triad(t) => group::<6>(
                m,
                c,
                [t.ext[0], t.int[0], t.int[1], t.ext[1], t.int[2], t.ext[2]],
                &[
                    &[(0, 1.0), (1, 1.0), (2, -1.0), (3, -1.0)],
                    &[(0, 1.0), (1, 1.0), (4, -1.0), (5, -1.0)],
                ],
                &[
                    (t.ext[0].from, t.ext[1].from),
                    (t.ext[0].from, t.ext[2].from),
                ],
                &out,
                order,
                invert_lu,
                &[t.leashes[0], t.leashes[1], t.leashes[2], t.base],
                None,
                &mut motions,
            ),
        };
        let count = done.ok_or_else(singular)?;
        for &(l, mo) in &motions[..count] {
            out[l] = Some(mo);
        }
    }
    Ok(out)
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
/// singular. `contours`: (pair index, sign) from the known link `ends[i].0`
/// to the known link `ends[i].1`.
#[allow(clippy::too_many_arguments)]
fn group<const N: usize>(
    m: &Mechanism,
    c: &Configuration,
    conns: [Conn; N],
    contours: &[&[(usize, f64)]],
    ends: &[(usize, usize)],
    known: &[Option<Motion>],
    order: Order,
    invert: fn(&SMatrix<f64, N, N>) -> Option<Inverse<N>>,
    links: &[usize],
    driven: Option<Driven>,
    motions: &mut [(usize, Motion); 4],
) -> Option<usize> {
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
    let reach = xi
        .iter()
        .map(|t| if t.w != 0.0 { t.v.hypot() } else { 0.0 })
        .fold(0.0, f64::max);
    let per_length = if reach > 0.0 { 1.0 / reach } else { 1.0 };
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
    let state_of = |l: usize| known[l].map(|mo| state(&mo, o));
    let known = |l: usize| state_of(l).expect("attachment solved first");
    let inverse = invert(&a)?;
    let mut rhs_v = rhs::<N>(ends, |l| known(l).0);
    // The given slide on a contour is a known term.
    let on_contour = |d: &Driven, rhs: &mut SVector<f64, N>, t: Twist| {
        if let Some(ci) = d.contour {
            rhs[3 * ci] -= t.w;
            rhs[3 * ci + 1] -= t.v.x;
            rhs[3 * ci + 2] -= t.v.y;
        }
    };
    if let (Some(d), Some(x)) = (driven, xd) {
        on_contour(&d, &mut rhs_v, x * d.rate);
    }
    let qd = inverse.solve(&in_group_units(rhs_v));
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
        let mut rhs = rhs::<N>(ends, |l| known(l).1);
        for (ci, contour) in contours.iter().enumerate() {
            for &(j, sg) in contour.iter() {
                rhs[3 * ci] -= sg * drift[j].w;
                rhs[3 * ci + 1] -= sg * drift[j].v.x;
                rhs[3 * ci + 2] -= sg * drift[j].v.y;
            }
        }
        // The driven pair's given slide rate and its bracket (Coriolis).
        let driven_acc = match (driven, xd) {
            (Some(d), Some(x)) => {
                let t = x * d.rate2 + bracket(vel_of(d.conn.from).unwrap(), x) * d.rate;
                on_contour(&d, &mut rhs, t);
                t
            }
            _ => Twist::default(),
        };
        let qdd = inverse.solve(&in_group_units(rhs));
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
    // At most four links: an insertion sort, not the general sort.
    let mut sorted = [0usize; 4];
    sorted[..links.len()].copy_from_slice(links);
    for i in 1..links.len() {
        let mut j = i;
        while j > 0 && sorted[j - 1] > sorted[j] {
            sorted.swap(j - 1, j);
            j -= 1;
        }
    }
    for (k, &l) in sorted[..links.len()].iter().enumerate() {
        let v = vel_of(l).expect("every group link reached");
        let a = acc[..na]
            .iter()
            .find(|e| e.0 == l)
            .map(|e| e.1)
            .unwrap_or_default();
        motions[k] = (
            l,
            Motion::from_point(c.pose(l), o, v.v, a.v + perp(v.v) * v.w, v.w, a.w),
        );
    }
    Some(links.len())
}

/// The known side of the contours: the twist (or twist rate) of each
/// contour's end link less that of its start link.
pub(crate) fn rhs<const N: usize>(
    ends: &[(usize, usize)],
    f: impl Fn(usize) -> Twist,
) -> SVector<f64, N> {
    let mut r = SVector::<f64, N>::zeros();
    for (ci, &(k1, k2)) in ends.iter().enumerate() {
        let t = f(k2) - f(k1);
        r[3 * ci] = t.w;
        r[3 * ci + 1] = t.v.x;
        r[3 * ci + 2] = t.v.y;
    }
    r
}

/// The twist of every link of a group: walk the pairs outward from the
/// known links (`base`), in the pairs' order, each pass over the pairs
/// still pending; `step(j)` is the relative twist across pair j.
fn walk(
    conns: &[Conn],
    step: impl Fn(usize) -> Twist,
    base: impl Fn(usize) -> Option<Twist>,
) -> ([(usize, Twist); 4], usize) {
    let mut found = [(usize::MAX, Twist::default()); 4];
    let mut count = 0;
    let get = |found: &[(usize, Twist); 4], count: usize, l: usize| {
        base(l).or_else(|| found[..count].iter().find(|e| e.0 == l).map(|e| e.1))
    };
    let n = conns.len();
    let mut pending = [true; 8];
    let mut left = n;
    while left > 0 {
        let before = left;
        for j in 0..n {
            if !pending[j] {
                continue;
            }
            let cn = &conns[j];
            match (get(&found, count, cn.from), get(&found, count, cn.to)) {
                (Some(vf), None) => {
                    found[count] = (cn.to, vf + step(j));
                    count += 1;
                }
                (None, Some(vt)) => {
                    found[count] = (cn.from, vt - step(j));
                    count += 1;
                }
                (Some(_), Some(_)) => {}
                (None, None) => continue,
            }
            pending[j] = false;
            left -= 1;
        }
        assert!(left < before, "group pairs form a connected contour");
    }
    (found, count)
}

/// Make the columns dimensionless (a revolute column has a length scale):
/// the scaled matrix and the scales.
fn scaled<const N: usize>(a: &SMatrix<f64, N, N>) -> (SMatrix<f64, N, N>, [f64; N]) {
    let scale: [f64; N] = std::array::from_fn(|j| a.column(j).norm().max(f64::MIN_POSITIVE));
    let mut an = *a;
    for (j, sc) in scale.iter().enumerate() {
        an.column_mut(j).scale_mut(1.0 / sc);
    }
    (an, scale)
}

/// The inverse of a group's contour matrix, once per position: the
/// velocity and the acceleration contours share it.
pub(crate) struct Inverse<const N: usize> {
    /// Inverse of the matrix with dimensionless columns.
    inv: SMatrix<f64, N, N>,
    /// The columns' scales.
    scale: [f64; N],
}

impl<const N: usize> Inverse<N> {
    #[inline]
    pub(crate) fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let x = self.inv * b;
        SVector::<f64, N>::from_fn(|j, _| x[j] / self.scale[j])
    }
}

/// A dyad's 3×3 contour matrix inverted in closed form (cofactors); `None`
/// when it is singular relative to the scale of its columns.
pub(crate) fn invert3(a: &SMatrix<f64, 3, 3>) -> Option<Inverse<3>> {
    let (an, scale) = scaled(a);
    if an.determinant().abs() < ACCURACY.min_contour_determinant {
        return None;
    }
    Some(Inverse {
        inv: an.try_inverse()?,
        scale,
    })
}

/// A three-leash group's 6×6 matrix (two contours) by LU; `None` when it
/// is singular relative to the scale of its columns.
pub(crate) fn invert_lu(a: &SMatrix<f64, 6, 6>) -> Option<Inverse<6>> {
    let (an, scale) = scaled(a);
    let lu = an.lu();
    if lu.determinant().abs() < ACCURACY.min_contour_determinant {
        return None;
    }
    Some(Inverse {
        inv: lu.try_inverse()?,
        scale,
    })
}
