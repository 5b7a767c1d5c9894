//! The `dynamics` object (contract, "Additions"): what the force analysis
//! needs besides the motion — gravity, each link's mass, moment of inertia
//! and centre, the external forces and couples (constant or one value per
//! position). Always SI (kg, kg·m², N, N·m, m/s²), whatever `units` says:
//! `units` is about the drawing, as `omega` is always rad/s.

use super::reader::{Reader, kind, ptr};
use super::{LinkSpec, NamedPoint};
use kurbo::Vec2;
use serde_json::Value;

/// The most moving links the force analysis takes: its equilibrium
/// system is dense, 3 equations a link (an LU of 600 × 600 at every
/// position).
pub const MAX_MOVING_LINKS: usize = 200;

/// The scene's `dynamics`: gravity, masses, external loads.
#[derive(Clone, Debug, PartialEq)]
pub struct DynamicsSpec {
    /// The acceleration of gravity, m/s² (absent: no gravity, [0, 0]).
    pub g: Vec2,
    /// The links with mass, in the order written.
    pub links: Vec<LinkMass>,
    pub forces: Vec<ForceSpec>,
    pub moments: Vec<MomentSpec>,
}

/// A link's mass `m` (kg), its moment of inertia `j` about its centre
/// (kg·m²) and the centre, a point of the link.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkMass {
    pub link: usize,
    pub m: f64,
    pub j: f64,
    pub centre: usize,
}

/// A value the same at every position, or one per position (a working
/// resistance over the stroke, an indicator diagram's gas force).
#[derive(Clone, Debug, PartialEq)]
pub enum PerPosition<T> {
    Constant(T),
    List(Vec<T>),
}

impl<T: Copy> PerPosition<T> {
    /// The value at position `k` (from 0).
    pub fn at(&self, k: usize) -> T {
        match self {
            PerPosition::Constant(x) => *x,
            PerPosition::List(v) => v[k],
        }
    }
}

/// An external force `f` (N) on `link` at its point `point`.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceSpec {
    pub link: usize,
    pub point: usize,
    pub f: PerPosition<Vec2>,
}

/// An external couple `m` (N·m, counter-clockwise positive) on `link`.
#[derive(Clone, Debug, PartialEq)]
pub struct MomentSpec {
    pub link: usize,
    pub m: PerPosition<f64>,
}

impl Reader {
    /// Read `dynamics`; `positions` is the number of positions the scene
    /// has (None when `positions` itself is wrong: lists are then not
    /// checked against it).
    pub(super) fn dynamics(
        &mut self,
        v: Option<&Value>,
        points: &[NamedPoint],
        links: &[LinkSpec],
        frame: Option<usize>,
        positions: Option<usize>,
    ) -> Option<DynamicsSpec> {
        let v = v?;
        let o = self.object(v, "/dynamics")?;
        let moving = links.len().saturating_sub(1);
        if moving > MAX_MOVING_LINKS {
            self.err(
                "/dynamics",
                format!(
                    "the force analysis takes at most {MAX_MOVING_LINKS} moving links (one dense system of 3 equations each); the scene has {moving}"
                ),
            );
            return None;
        }
        self.only_keys(o, "/dynamics", &["g", "links", "forces", "moments"]);
        let mut d = DynamicsSpec {
            g: Vec2::ZERO,
            links: Vec::new(),
            forces: Vec::new(),
            moments: Vec::new(),
        };
        if let Some(g) = o.get("g") {
            d.g = self.vector(g, "/dynamics/g").unwrap_or(Vec2::ZERO);
        }
        if let Some(ls) = o.get("links")
            && let Some(lo) = self.object(ls, "/dynamics/links")
        {
            for (id, e) in lo {
                let at = ptr("/dynamics/links", id);
                let link = self.moving_link(&Value::String(id.clone()), &at, links, frame);
                if let Some(x) = self.link_mass(e, &at, link, points, links) {
                    d.links.push(x);
                }
            }
        }
        let list = |r: &mut Self, key: &str| -> Vec<(String, &Value)> {
            let at = format!("/dynamics/{key}");
            match o.get(key) {
                None => Vec::new(),
                Some(Value::Array(a)) => a
                    .iter()
                    .enumerate()
                    .map(|(k, x)| (format!("{at}/{k}"), x))
                    .collect(),
                Some(_) => {
                    r.err(at, "expected a list");
                    Vec::new()
                }
            }
        };
        for (at, e) in list(self, "forces") {
            let Some(fo) = self.object(e, &at) else {
                continue;
            };
            self.only_keys(fo, &at, &["link", "point", "F"]);
            let link = self
                .required(fo.get("link"), &format!("{at}/link"))
                .and_then(|x| self.moving_link(x, &format!("{at}/link"), links, frame));
            let point = self
                .required(fo.get("point"), &format!("{at}/point"))
                .and_then(|x| self.point_ref(x, &format!("{at}/point"), points));
            if let (Some(l), Some(p)) = (link, point) {
                self.on_link(p, l, &format!("{at}/point"), points, links);
            }
            let f = self
                .required(fo.get("F"), &format!("{at}/F"))
                .and_then(|x| {
                    // A list of vectors, else one vector.
                    let listed = x
                        .as_array()
                        .is_some_and(|a| a.is_empty() || a[0].is_array());
                    self.per_position(x, &format!("{at}/F"), listed, positions, Self::vector)
                });
            if let (Some(link), Some(point), Some(f)) = (link, point, f) {
                d.forces.push(ForceSpec { link, point, f });
            }
        }
        for (at, e) in list(self, "moments") {
            let Some(mo) = self.object(e, &at) else {
                continue;
            };
            self.only_keys(mo, &at, &["link", "M"]);
            let link = self
                .required(mo.get("link"), &format!("{at}/link"))
                .and_then(|x| self.moving_link(x, &format!("{at}/link"), links, frame));
            let m = self
                .required(mo.get("M"), &format!("{at}/M"))
                .and_then(|x| {
                    self.per_position(x, &format!("{at}/M"), x.is_array(), positions, Self::number)
                });
            if let (Some(link), Some(m)) = (link, m) {
                d.moments.push(MomentSpec { link, m });
            }
        }
        Some(d)
    }

    fn required<'a>(&mut self, v: Option<&'a Value>, at: &str) -> Option<&'a Value> {
        if v.is_none() {
            self.err(at, "missing");
        }
        v
    }

    /// A vector [x, y] of numbers (no unit conversion: dynamics is SI).
    fn vector(&mut self, v: &Value, at: &str) -> Option<Vec2> {
        match v.as_array() {
            Some(a) if a.len() == 2 => {
                let x = self.number(&a[0], &format!("{at}/0"));
                let y = self.number(&a[1], &format!("{at}/1"));
                Some(Vec2::new(x?, y?))
            }
            _ => {
                self.err(at, format!("expected a vector [x, y], found {}", kind(v)));
                None
            }
        }
    }

    /// A link that moves: the frame carries no equilibrium equation, so
    /// a mass or a load on it would be silently lost.
    fn moving_link(
        &mut self,
        v: &Value,
        at: &str,
        links: &[LinkSpec],
        frame: Option<usize>,
    ) -> Option<usize> {
        let l = self.link_ref(v, at, links)?;
        if Some(l) == frame {
            self.err(
                at,
                "the frame, link \"0\", does not move: its mass and the loads on it take no part in the force analysis",
            );
            return None;
        }
        Some(l)
    }

    fn on_link(
        &mut self,
        p: usize,
        l: usize,
        at: &str,
        points: &[NamedPoint],
        links: &[LinkSpec],
    ) -> bool {
        let on = links[l].points.contains(&p);
        if !on {
            self.err(
                at,
                format!(
                    "point \"{}\" is not a point of link \"{}\"",
                    points[p].name, links[l].id
                ),
            );
        }
        on
    }

    fn link_mass(
        &mut self,
        v: &Value,
        at: &str,
        link: Option<usize>,
        points: &[NamedPoint],
        links: &[LinkSpec],
    ) -> Option<LinkMass> {
        let o = self.object(v, at)?;
        self.only_keys(o, at, &["m", "J", "centre"]);
        let non_negative = |r: &mut Self, key: &str, what: &str| -> Option<f64> {
            let at = format!("{at}/{key}");
            let v = r.required(o.get(key), &at)?;
            let x = r.number(v, &at)?;
            if x < 0.0 {
                r.err(at, format!("{what} must not be negative, found {x}"));
                return None;
            }
            Some(x)
        };
        let m = non_negative(self, "m", "a mass (kg)");
        let j = non_negative(self, "J", "a moment of inertia (kg·m²)");
        let at_c = format!("{at}/centre");
        let centre = self
            .required(o.get("centre"), &at_c)
            .and_then(|x| self.point_ref(x, &at_c, points));
        let (link, centre) = (link?, centre?);
        if !self.on_link(centre, link, &at_c, points, links) {
            return None;
        }
        Some(LinkMass {
            link,
            m: m?,
            j: j?,
            centre,
        })
    }

    /// One value (`one`), or (`listed`) a list of one value per
    /// position, as many as the scene has positions.
    fn per_position<T>(
        &mut self,
        v: &Value,
        at: &str,
        listed: bool,
        positions: Option<usize>,
        one: impl Fn(&mut Self, &Value, &str) -> Option<T>,
    ) -> Option<PerPosition<T>> {
        if !listed {
            return one(self, v, at).map(PerPosition::Constant);
        }
        let a = v.as_array().expect("a listed value is a JSON list");
        let mut out = Vec::with_capacity(a.len());
        let mut ok = true;
        for (k, x) in a.iter().enumerate() {
            match one(self, x, &format!("{at}/{k}")) {
                Some(x) => out.push(x),
                None => ok = false,
            }
        }
        if let Some(n) = positions
            && n != a.len()
        {
            self.err(
                at,
                format!(
                    "a list of {} values, but the scene has {n} position{}: one value per position",
                    a.len(),
                    if n == 1 { "" } else { "s" }
                ),
            );
            return None;
        }
        ok.then_some(PerPosition::List(out))
    }
}
