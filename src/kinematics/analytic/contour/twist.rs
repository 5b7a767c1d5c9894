//! Planar twists: a link's angular rate and the velocity of the point at
//! the origin, their Lie bracket, a link's twist and twist rate about a
//! fixed point, a pair's unit twist.

use crate::geom::{Pose, perp};
use crate::kinematics::analytic::Motion;
use crate::kinematics::positions::Configuration;
use crate::model::mechanism::Mechanism;
use crate::model::structure::{Conn, Joint};
use kurbo::{Point, Vec2};

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
pub(super) fn unit_twist(m: &Mechanism, c: &Configuration, conn: &Conn, o: Point) -> Twist {
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

/// The motion of a link posed at `pose` whose twist about the fixed
/// point `o` is `v` and twist rate `a`: the acceleration of its material
/// point at o is the twist rate's plus ω×v.
#[inline]
pub(crate) fn twist_motion(pose: Pose, o: Point, v: Twist, a: Twist) -> Motion {
    Motion::from_point(pose, o, v.v, a.v + perp(v.v) * v.w, v.w, a.w)
}
