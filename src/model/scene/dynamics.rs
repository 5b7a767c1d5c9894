//! The `dynamics` object (contract, "Additions"): what the force analysis
//! needs besides the motion — gravity, each link's mass, moment of inertia
//! and centre, the external forces and couples (constant or one value per
//! position). Always SI (kg, kg·m², N, N·m, m/s²), whatever `units` says:
//! `units` is about the drawing, as `omega` is always rad/s.

use super::reader::{Reader, kind, ptr};
use super::spec::{
    DynamicsSpec, ForceSpec, ForceTable, LinkMass, LinkSpec, MAX_MOVING_LINKS, MomentSpec,
    NamedPoint, PerPosition,
};
use kurbo::Vec2;
use serde_json::Value;

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
            let given = self.required(fo.get("F"), &format!("{at}/F"));
            let (f, table) = match given {
                Some(x) if x.is_object() => (
                    Some(PerPosition::Constant(Vec2::ZERO)),
                    self.force_table(x, &format!("{at}/F"), points).map(Some),
                ),
                Some(x) => {
                    // A list of vectors, else one vector.
                    let listed = x
                        .as_array()
                        .is_some_and(|a| a.is_empty() || a[0].is_array());
                    let f =
                        self.per_position(x, &format!("{at}/F"), listed, positions, Self::vector);
                    (f, Some(None))
                }
                None => (None, None),
            };
            if let (Some(link), Some(point), Some(f), Some(table)) = (link, point, f, table) {
                d.forces.push(ForceSpec {
                    link,
                    point,
                    f,
                    table,
                });
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

    /// `{ "from", "s", "working", "back" }`: a force against its point's
    /// displacement from `from` (a point's name, or [x, y] in m).
    fn force_table(&mut self, v: &Value, at: &str, points: &[NamedPoint]) -> Option<ForceTable> {
        let o = self.object(v, at)?;
        self.only_keys(o, at, &["from", "s", "working", "back"]);
        let at_from = format!("{at}/from");
        let from = match self.required(o.get("from"), &at_from)? {
            x @ Value::String(_) => self
                .point_ref(x, &at_from, points)
                .map(|p| points[p].sketch),
            x => self.vector(x, &at_from).map(|v| v.to_point()),
        };
        let at_s = format!("{at}/s");
        let s: Option<Vec<f64>> = match self.required(o.get("s"), &at_s) {
            Some(Value::Array(a)) if a.len() >= 2 => a
                .iter()
                .enumerate()
                .map(|(k, x)| self.number(x, &format!("{at_s}/{k}")))
                .collect(),
            Some(_) => {
                self.err(&at_s, "expected a list of at least two displacements (m)");
                None
            }
            None => None,
        };
        if let Some(s) = &s
            && (s[0] < 0.0 || s.windows(2).any(|w| w[1] <= w[0]))
        {
            self.err(
                &at_s,
                "the displacements must start at 0 or above and increase",
            );
            return None;
        }
        let rows = |r: &mut Self, key: &str, required: bool| -> Option<Vec<Vec2>> {
            let at_k = format!("{at}/{key}");
            let x = match o.get(key) {
                None if !required => return Some(Vec::new()),
                x => r.required(x, &at_k)?,
            };
            let Some(a) = x.as_array() else {
                r.err(
                    &at_k,
                    "expected a list of forces [x, y] (N), one per displacement",
                );
                return None;
            };
            let f: Option<Vec<Vec2>> = a
                .iter()
                .enumerate()
                .map(|(k, x)| r.vector(x, &format!("{at_k}/{k}")))
                .collect();
            let f = f?;
            if let Some(s) = &s
                && f.len() != s.len()
            {
                r.err(
                    &at_k,
                    format!(
                        "{} forces for {} displacements: one force per displacement",
                        f.len(),
                        s.len()
                    ),
                );
                return None;
            }
            Some(f)
        };
        let working = rows(self, "working", true);
        let back = rows(self, "back", false);
        Some(ForceTable {
            from: from?,
            s: s?,
            working: working?,
            back: back?,
        })
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
