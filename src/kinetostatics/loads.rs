//! The known loads on the links at one position, d'Alembert's way: each
//! link's inertia force −m·a_S at its centre and inertia couple −J·ε, its
//! weight m·g at the centre, and the scene's external forces and couples
//! (a per-position list at this position's value). The force plans, the
//! lever of Zhukovsky and both routes of this module read the same list.

use crate::kinematics::solve::{Analysis, Position};
use kurbo::{Point, Vec2};

/// What a load is, for the report and the graphical methods built on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    /// −m·a_S, −J·ε.
    Inertia,
    /// m·g.
    Gravity,
    /// The scene's `dynamics.forces` / `dynamics.moments`.
    External,
}

/// A known load on a link: a force `f` (N) through the place `at`, or a
/// couple `m` (N·m, counter-clockwise positive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Load {
    Force {
        link: usize,
        /// The named point it acts at (the centre, or the scene's point).
        point: usize,
        /// Where that point is at this position.
        at: Point,
        f: Vec2,
        origin: Origin,
    },
    Couple {
        link: usize,
        m: f64,
        origin: Origin,
    },
}

impl Load {
    pub fn link(&self) -> usize {
        match *self {
            Load::Force { link, .. } | Load::Couple { link, .. } => link,
        }
    }
    pub fn origin(&self) -> Origin {
        match *self {
            Load::Force { origin, .. } | Load::Couple { origin, .. } => origin,
        }
    }
    /// Its moment about `o` (a force's arm × force; a couple itself).
    pub fn moment_about(&self, o: Point) -> f64 {
        match *self {
            Load::Force { at, f, .. } => (at - o).cross(f),
            Load::Couple { m, .. } => m,
        }
    }
}

/// The inertia of a link with mass at one position: the force −m·a_S at
/// its centre S and the couple −J·ε.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia {
    pub link: usize,
    pub centre: usize,
    /// Where S is.
    pub at: Point,
    /// S's acceleration, for the plans of forces built on it.
    pub a_s: Vec2,
    pub f: Vec2,
    pub m: f64,
}

/// Every link's inertia (the links with mass, in the scene's order) at
/// solved position `s`; `None` without a `dynamics` object.
pub fn inertia(an: &Analysis, s: &Position) -> Option<Vec<Inertia>> {
    let d = an.mech.scene.dynamics.as_ref()?;
    let m = &an.mech;
    let out = d
        .links
        .iter()
        .map(|lm| {
            let at = s.config.point(m, lm.link, lm.centre);
            let mo = s.motion[lm.link].expect("with dynamics every link is solved with its rates");
            let a_s = mo.acceleration(at);
            Inertia {
                link: lm.link,
                centre: lm.centre,
                at,
                a_s,
                f: a_s * -lm.m,
                m: -lm.j * mo.epsilon,
            }
        })
        .collect();
    Some(out)
}

/// Every known load at solved position `s`, the `k`-th position (from 0)
/// of the scene: inertia, then weights, then the external loads in the
/// order written. Empty without a `dynamics` object.
pub fn loads(an: &Analysis, s: &Position, k: usize) -> Vec<Load> {
    let Some(d) = an.mech.scene.dynamics.as_ref() else {
        return Vec::new();
    };
    let m = &an.mech;
    let mut out = Vec::new();
    for i in inertia(an, s).unwrap_or_default() {
        out.push(Load::Force {
            link: i.link,
            point: i.centre,
            at: i.at,
            f: i.f,
            origin: Origin::Inertia,
        });
        out.push(Load::Couple {
            link: i.link,
            m: i.m,
            origin: Origin::Inertia,
        });
    }
    for lm in &d.links {
        out.push(Load::Force {
            link: lm.link,
            point: lm.centre,
            at: s.config.point(m, lm.link, lm.centre),
            f: d.g * lm.m,
            origin: Origin::Gravity,
        });
    }
    for f in &d.forces {
        let at = s.config.point(m, f.link, f.point);
        let value = match &f.table {
            None => f.f.at(k),
            Some(t) => {
                let (d, working) = stroke(s, f.link, at, t.from);
                t.at(d, working)
            }
        };
        out.push(Load::Force {
            link: f.link,
            point: f.point,
            at,
            f: value,
            origin: Origin::External,
        });
    }
    for c in &d.moments {
        out.push(Load::Couple {
            link: c.link,
            m: c.m.at(k),
            origin: Origin::External,
        });
    }
    out
}

/// A tabled force's argument at solved position `s`: its point's
/// displacement |P − from| (m), and whether the point moves away from
/// `from` (the working stroke; standing still counts as working).
pub fn stroke(s: &Position, link: usize, at: Point, from: Point) -> (f64, bool) {
    let d = at - from;
    let v = s.motion[link].map_or(Vec2::ZERO, |mo| mo.velocity(at));
    (d.hypot(), v.dot(d) >= 0.0)
}

/// Every tabled force's displacement at solved position `s` within its
/// table's rows (to a billionth of the table's span), else the pointer of
/// the first one outside, with the displacement and the rows' range.
pub fn tables_cover(an: &Analysis, s: &Position) -> Option<(String, f64, f64, f64)> {
    let d = an.mech.scene.dynamics.as_ref()?;
    let m = &an.mech;
    d.forces.iter().enumerate().find_map(|(i, f)| {
        let t = f.table.as_ref()?;
        let at = s.config.point(m, f.link, f.point);
        let (x, _) = stroke(s, f.link, at, t.from);
        let (lo, hi) = (t.s[0], t.s[t.s.len() - 1]);
        let slack = 1e-9 * (hi - lo);
        (x < lo - slack || x > hi + slack).then(|| (format!("/dynamics/forces/{i}/F/s"), x, lo, hi))
    })
}
