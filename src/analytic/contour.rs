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
//! brackets. A dyad gives one contour (3×3, solved by Cramer's rule in
//! closed form), a three-leash group two contours (6×6).

use super::{Drive, Motion, Order};
use crate::error::{Error, Result};
use crate::geom::perp;
use crate::mechanism::Mechanism;
use crate::positions::{Configuration, describe_input};
use crate::scene::InputSpec;
use crate::structure::{AssurGroup, Conn, Joint, Structure};
use kurbo::Vec2;
use nalgebra::{DMatrix, DVector};

/// A contour: (index of a pair in the group, ±1 for the sense it is traversed in).
type Contour = Vec<(usize, f64)>;

/// A planar twist: angular rate and the velocity of the point at the origin.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Twist {
    w: f64,
    v: Vec2,
}

impl std::ops::Add for Twist {
    type Output = Twist;
    fn add(self, o: Twist) -> Twist {
        Twist {
            w: self.w + o.w,
            v: self.v + o.v,
        }
    }
}
impl std::ops::Sub for Twist {
    type Output = Twist;
    fn sub(self, o: Twist) -> Twist {
        Twist {
            w: self.w - o.w,
            v: self.v - o.v,
        }
    }
}
impl std::ops::Mul<f64> for Twist {
    type Output = Twist;
    fn mul(self, k: f64) -> Twist {
        Twist {
            w: self.w * k,
            v: self.v * k,
        }
    }
}

/// The Lie bracket [a, b] of planar twists: how b, carried by a body
/// moving with a, changes in time.
fn bracket(a: Twist, b: Twist) -> Twist {
    Twist {
        w: 0.0,
        v: perp(b.v) * a.w - perp(a.v) * b.w,
    }
}

/// Twist and twist rate of a link. The rate of the spatial velocity v_O
/// is not the acceleration of the material point at O: a_O = v̇_O + ω×v_O.
fn state(mo: &Motion) -> (Twist, Twist) {
    (
        Twist {
            w: mo.omega,
            v: mo.v0,
        },
        Twist {
            w: mo.epsilon,
            v: mo.a0 - perp(mo.v0) * mo.omega,
        },
    )
}

/// Unit twist of a pair, traversed from `conn.from` to `conn.to`; the rate
/// that multiplies it is ω_to − ω_from (revolute) or the slide of the
/// slider along its guide (prismatic).
fn unit_twist(m: &Mechanism, c: &Configuration, conn: &Conn) -> Twist {
    match conn.joint {
        Joint::R(p) => {
            let at = c.point(m, conn.to, p);
            Twist {
                w: 1.0,
                v: -perp(at.to_vec2()),
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

/// Velocity and acceleration of the input link.
pub fn input_motion(m: &Mechanism, c: &Configuration, rate: f64, rate2: f64) -> Motion {
    let link = m.scene.input.link();
    let pose = c.pose(link);
    match m.scene.input {
        InputSpec::Crank { pivot, .. } => {
            let o = c.point(m, m.frame(), pivot);
            Motion::from_point(pose, o, Vec2::ZERO, Vec2::ZERO, rate, rate2)
        }
        InputSpec::Slider { pair, .. } => {
            let u = c.pose(m.frame()).dir(m.prismatics[pair].line_dir);
            Motion {
                pose,
                omega: 0.0,
                epsilon: 0.0,
                v0: u * rate,
                a0: u * rate2,
            }
        }
    }
}

/// Velocities (and accelerations when `order` asks) of every solved link.
/// `rate`, `rate2`: ω1, ε1 of a crank (v, a of a driving slider).
pub fn solve(
    m: &Mechanism,
    s: &Structure,
    need: &[bool],
    c: &Configuration,
    drive: Drive,
    order: Order,
) -> Result<Vec<Option<Motion>>> {
    let mut out: Vec<Option<Motion>> = vec![None; m.links.len()];
    out[m.frame()] = Some(Motion::from_point(
        c.pose(m.frame()),
        kurbo::Point::ORIGIN,
        Vec2::ZERO,
        Vec2::ZERO,
        0.0,
        0.0,
    ));
    out[m.scene.input.link()] = Some(input_motion(m, c, drive.rate, drive.rate2));
    for (gi, g) in s.groups.iter().enumerate() {
        if !need[gi] {
            continue;
        }
        // The pairs of the group, in contour order: each contour is a list
        // of (pair index, sign) from a known link to a known link.
        let (conns, contours, ends): (Vec<Conn>, Vec<Contour>, Vec<(usize, usize)>) = match g {
            AssurGroup::Dyad(d) => (
                vec![d.ext1, d.mid, d.ext2],
                vec![vec![(0, 1.0), (1, 1.0), (2, 1.0)]],
                vec![(d.ext1.from, d.ext2.to)],
            ),
            AssurGroup::Triad(t) => (
                vec![t.ext[0], t.int[0], t.int[1], t.ext[1], t.int[2], t.ext[2]],
                vec![
                    vec![(0, 1.0), (1, 1.0), (2, -1.0), (3, -1.0)],
                    vec![(0, 1.0), (1, 1.0), (4, -1.0), (5, -1.0)],
                ],
                vec![
                    (t.ext[0].from, t.ext[1].from),
                    (t.ext[0].from, t.ext[2].from),
                ],
            ),
        };
        let xi: Vec<Twist> = conns.iter().map(|cn| unit_twist(m, c, cn)).collect();
        let n = conns.len();
        let mut a = DMatrix::<f64>::zeros(n, n);
        for (ci, contour) in contours.iter().enumerate() {
            for &(j, sg) in contour {
                a[(3 * ci, j)] = sg * xi[j].w;
                a[(3 * ci + 1, j)] = sg * xi[j].v.x;
                a[(3 * ci + 2, j)] = sg * xi[j].v.y;
            }
        }
        let known = |l: usize| state(out[l].as_ref().expect("attachment solved first"));
        let rhs_of = |f: &dyn Fn(usize) -> Twist| {
            let mut r = DVector::<f64>::zeros(n);
            for (ci, &(k1, k2)) in ends.iter().enumerate() {
                let t = f(k2) - f(k1);
                r[3 * ci] = t.w;
                r[3 * ci + 1] = t.v.x;
                r[3 * ci + 2] = t.v.y;
            }
            r
        };
        let qd =
            solve_small(&a, &rhs_of(&|l| known(l).0), m.size).ok_or_else(|| Error::Singular {
                at: describe_input(m, drive.q),
                why: format!(
                    "the velocity contour of group {} is singular (a dead point)",
                    g.label(m)
                ),
            })?;
        // Twist of every link of the group: walk the pairs outward.
        let mut vel: Vec<Option<Twist>> = (0..m.links.len())
            .map(|l| out[l].as_ref().map(|mo| state(mo).0))
            .collect();
        let mut pending: Vec<usize> = (0..n).collect();
        while !pending.is_empty() {
            let before = pending.len();
            pending.retain(|&j| {
                let cn = &conns[j];
                match (vel[cn.from], vel[cn.to]) {
                    (Some(vf), None) => {
                        vel[cn.to] = Some(vf + xi[j] * qd[j]);
                        false
                    }
                    (None, Some(vt)) => {
                        vel[cn.from] = Some(vt - xi[j] * qd[j]);
                        false
                    }
                    (Some(_), Some(_)) => false,
                    (None, None) => true,
                }
            });
            assert!(
                pending.len() < before,
                "group pairs form a connected contour"
            );
        }
        // Accelerations: the same matrix, known terms from the brackets.
        let mut acc: Vec<Option<Twist>> = vec![None; m.links.len()];
        if order == Order::Acceleration {
            let drift: Vec<Twist> = (0..n)
                .map(|j| bracket(vel[conns[j].from].unwrap(), xi[j]) * qd[j])
                .collect();
            let mut rhs = rhs_of(&|l| known(l).1);
            for (ci, contour) in contours.iter().enumerate() {
                for &(j, sg) in contour {
                    rhs[3 * ci] -= sg * drift[j].w;
                    rhs[3 * ci + 1] -= sg * drift[j].v.x;
                    rhs[3 * ci + 2] -= sg * drift[j].v.y;
                }
            }
            let qdd = solve_small(&a, &rhs, m.size).expect("same matrix as the velocity contour");
            for l in 0..m.links.len() {
                acc[l] = out[l].as_ref().map(|mo| state(mo).1);
            }
            let mut pending: Vec<usize> = (0..n).collect();
            while !pending.is_empty() {
                pending.retain(|&j| {
                    let cn = &conns[j];
                    let d = xi[j] * qdd[j] + drift[j];
                    match (acc[cn.from], acc[cn.to]) {
                        (Some(af), None) => {
                            acc[cn.to] = Some(af + d);
                            false
                        }
                        (None, Some(at)) => {
                            acc[cn.from] = Some(at - d);
                            false
                        }
                        (Some(_), Some(_)) => false,
                        (None, None) => true,
                    }
                });
            }
        }
        for l in g.links() {
            let v = vel[l].expect("every group link reached");
            let a = acc[l].unwrap_or_default();
            out[l] = Some(Motion {
                pose: c.pose(l),
                omega: v.w,
                epsilon: a.w,
                v0: v.v,
                a0: a.v + perp(v.v) * v.w,
            });
        }
    }
    Ok(out)
}

/// Solve a 3×3 system by Cramer's rule (the closed form of a dyad) or a
/// larger one by LU; `None` when the system is singular relative to the
/// scale of its columns.
fn solve_small(a: &DMatrix<f64>, b: &DVector<f64>, size: f64) -> Option<DVector<f64>> {
    // Make the columns dimensionless: a revolute column has a length scale.
    let n = a.ncols();
    let scale: Vec<f64> = (0..n)
        .map(|j| a.column(j).norm().max(f64::MIN_POSITIVE))
        .collect();
    let mut an = a.clone();
    for (j, sc) in scale.iter().enumerate() {
        an.column_mut(j).scale_mut(1.0 / sc);
    }
    let _ = size;
    let x = if n == 3 {
        let det = an.determinant();
        if det.abs() < 1e-12 {
            return None;
        }
        let mut x = DVector::zeros(3);
        for j in 0..3 {
            let mut aj = an.clone();
            aj.set_column(j, b);
            x[j] = aj.determinant() / det;
        }
        x
    } else {
        let lu = an.lu();
        let det = lu.determinant();
        if det.abs() < 1e-12 {
            return None;
        }
        lu.solve(b)?
    };
    Some(DVector::from_iterator(n, (0..n).map(|j| x[j] / scale[j])))
}
