//! What a student draws and hands in: the plan's points in mm from the
//! pole (keys as answers write them: `b`, `s2`, `b3` for B as a point of
//! the guide 3), the values read off them, and the answer file (JSON as
//! docs/check.md, "The answer file", defines it).

use super::rigid::{Accelerations, Model, Velocities, perp};
use kurbo::Vec2;
use mechplan::PlanKind;
use rand::Rng;
use rand::rngs::StdRng;
use serde_json::{Map, Value, json};

/// Where a plan point comes from: a scene point (on the links that carry
/// it), or a scene point as a point of a moving guide (the coincident
/// point of a prismatic pair: `b3`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    Named(usize),
    On { point: usize, link: usize },
}

/// The points a student draws on a plan of `m`, with their keys: every
/// scene point a moving link carries (a point of the frame is the pole),
/// then every pair's point as a point of its guide where the guide moves
/// and the pair is not driven (a cylinder's relative velocity is laid
/// off from its barrel's point, which the plan does not name).
pub fn keys(m: &Model) -> Vec<(String, Source)> {
    let mut out = Vec::new();
    for p in 0..m.names.len() {
        if m.carrier(p).is_some() && !m.links[m.frame].points.contains(&p) {
            out.push((m.names[p].to_lowercase(), Source::Named(p)));
        }
    }
    let driven: Vec<usize> = m
        .inputs
        .iter()
        .filter_map(|i| match i {
            super::rigid::Input::Slide { pair, .. } => Some(*pair),
            _ => None,
        })
        .collect();
    for (k, q) in m.pairs.iter().enumerate() {
        if q.guide != m.frame && !driven.contains(&k) {
            let key = format!("{}{}", m.names[q.point].to_lowercase(), m.links[q.guide].id);
            if !out.iter().any(|(k, _)| *k == key) {
                out.push((
                    key,
                    Source::On {
                        point: q.point,
                        link: q.guide,
                    },
                ));
            }
        }
    }
    out
}

/// A plan as the method gives it: each key's vector (SI: m/s or m/s²).
#[derive(Clone, Debug)]
pub struct Vectors(pub Vec<(String, Source, Vec2)>);

/// The velocity plan of the fields `v`.
pub fn velocity_plan(m: &Model, v: &Velocities) -> Vectors {
    plan_of(m, &|l, p| v.at(m, l, m.at[p]))
}

/// The acceleration plan of the fields `a`.
pub fn acceleration_plan(m: &Model, a: &Accelerations) -> Vectors {
    plan_of(m, &|l, p| a.at(m, l, m.at[p]))
}

fn plan_of(m: &Model, field: &dyn Fn(usize, usize) -> Vec2) -> Vectors {
    Vectors(
        keys(m)
            .into_iter()
            .map(|(k, s)| {
                let v = match s {
                    Source::Named(p) => field(m.carrier(p).unwrap(), p),
                    Source::On { point, link } => field(link, point),
                };
                (k, s, v)
            })
            .collect(),
    )
}

impl Vectors {
    /// The largest vector's length.
    pub fn largest(&self) -> f64 {
        self.0.iter().map(|x| x.2.hypot()).fold(0.0, f64::max)
    }
    /// The plan drawn at μ: each point in mm from the pole.
    pub fn at_scale(&self, mu: f64) -> Drawing {
        Drawing(
            self.0
                .iter()
                .map(|(k, s, v)| (k.clone(), *s, *v / mu))
                .collect(),
        )
    }
}

/// A drawing: each point in mm from the pole.
#[derive(Clone, Debug)]
pub struct Drawing(pub Vec<(String, Source, Vec2)>);

impl Drawing {
    pub fn get(&self, key: &str) -> Option<Vec2> {
        self.0.iter().find(|x| x.0 == key).map(|x| x.2)
    }
    pub fn set(&mut self, key: &str, at: Vec2) {
        if let Some(x) = self.0.iter_mut().find(|x| x.0 == key) {
            x.2 = at;
        }
    }
    /// Scene point `p`'s place on the drawing: its own point, or the pole
    /// for a point of the frame alone.
    pub fn of_point(&self, p: usize) -> Vec2 {
        self.0
            .iter()
            .find(|x| x.1 == Source::Named(p))
            .map_or(Vec2::ZERO, |x| x.2)
    }
    /// Every point moved by `noise` (by key).
    pub fn moved(&self, noise: &[Vec2]) -> Drawing {
        Drawing(
            self.0
                .iter()
                .zip(noise)
                .map(|((k, s, v), n)| (k.clone(), *s, *v + *n))
                .collect(),
        )
    }
    /// Every coordinate rounded to `step` mm (as typed).
    pub fn rounded(&self, step: f64) -> Drawing {
        let r = |x: f64| (x / step).round() * step;
        Drawing(
            self.0
                .iter()
                .map(|(k, s, v)| {
                    let (x, y) = (r(v.x), r(v.y));
                    // Rounded decimals as typed: 12.3, not 12.300000000000001.
                    let t = |x: f64| format!("{x:.3}").parse::<f64>().unwrap();
                    (k.clone(), *s, Vec2::new(t(x), t(y)))
                })
                .collect(),
        )
    }
    /// The farthest distance between the same points of two drawings.
    pub fn farthest_from(&self, other: &Drawing) -> f64 {
        self.0
            .iter()
            .zip(&other.0)
            .map(|(a, b)| (a.2 - b.2).hypot())
            .fold(0.0, f64::max)
    }
}

/// A point uniform in the disc of radius `r`.
pub fn disc(rng: &mut StdRng, r: f64) -> Vec2 {
    loop {
        let (x, y): (f64, f64) = (rng.random_range(-1.0..=1.0), rng.random_range(-1.0..=1.0));
        if x * x + y * y <= 1.0 {
            return Vec2::new(x * r, y * r);
        }
    }
}

/// The pencil's noise of every point of a drawing of `n` points, each
/// within δ (uniform in the disc).
pub fn pencil(rng: &mut StdRng, n: usize, delta: f64) -> Vec<Vec2> {
    (0..n).map(|_| disc(rng, delta)).collect()
}

/// `x` with `n` significant digits, as a student writes it.
pub fn significant(x: f64, n: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = x.abs().log10().floor() as i32;
    let digits = n - 1 - e;
    let s = format!("{:.*}", digits.max(0) as usize, x);
    if digits >= 0 {
        s.parse().unwrap()
    } else {
        let f = 10f64.powi(-digits);
        (x / f).round() * f
    }
}

/// A value read off a plan drawn at μ, as a student writes it: three
/// significant digits, and more where three would move it by more than
/// 0.1 mm on the plan (a plan much larger than the standard one).
pub fn read_value(x: f64, mu: f64) -> f64 {
    significant(x, digits(x, mu))
}

/// How many significant digits a value `x` read off a plan at μ is
/// written with ([`read_value`]).
pub fn digits(x: f64, mu: f64) -> i32 {
    if x == 0.0 || !x.is_finite() {
        return 3;
    }
    let e = x.abs().log10().floor() as i32;
    let mut n = 3;
    while 0.5 * 10f64.powi(e - n + 1) > 0.1 * mu && n < 12 {
        n += 1;
    }
    n
}

/// The standard scale of a plan whose largest vector is `largest`: the
/// smallest of 1, 2, 2.5, 4, 5 × 10ᵏ that draws it within 120 mm.
pub fn standard_mu(largest: f64) -> f64 {
    let want = largest / 120.0;
    let mut e = want.log10().floor() as i32 - 1;
    loop {
        for m in [1.0, 2.0, 2.5, 4.0, 5.0] {
            let mu = m * 10f64.powi(e);
            if mu >= want {
                return significant(mu, 3);
            }
        }
        e += 1;
    }
}

/// The links whose rate a student reads off a plan: moving, not turning
/// with a crank input (its ω, ε are given) nor with the frame through
/// prismatic pairs (a slider on the frame does not turn), with two points
/// (the first two it lists; a point of the frame is the pole), their rate
/// from the relative vector between them.
pub fn readable_links(m: &Model) -> Vec<(usize, usize, usize)> {
    let cranks: Vec<usize> = m
        .inputs
        .iter()
        .filter_map(|i| match i {
            super::rigid::Input::Crank { link, .. } => Some(*link),
            _ => None,
        })
        .collect();
    (0..m.links.len())
        .filter(|&l| {
            let class = rotating_with(m, l);
            m.moving(l) && !class.contains(&m.frame) && !class.iter().any(|c| cranks.contains(c))
        })
        .filter_map(|l| {
            let p = &m.links[l].points;
            (p.len() >= 2 && (m.at[p[1]] - m.at[p[0]]).hypot() > 0.0).then(|| (l, p[0], p[1]))
        })
        .collect()
}

/// A link's rate read off a drawing at μ: ω (velocity plan) or ε
/// (acceleration plan) from the relative vector between its two points,
/// cross(r, Δ)/|r|², signed counter-clockwise.
pub fn rate_off(m: &Model, d: &Drawing, mu: f64, (_, p, q): (usize, usize, usize)) -> f64 {
    let r = m.at[q] - m.at[p];
    let rel = (d.of_point(q) - d.of_point(p)) * mu;
    r.cross(rel) / r.hypot2()
}

/// The ω a student reads off their velocity plan at μ_v (each end of the
/// relative segment within δ), written with three significant digits.
pub fn read_omegas(
    m: &Model,
    v: &Velocities,
    mu_v: f64,
    delta: f64,
    rng: Option<&mut StdRng>,
) -> Vec<(usize, f64)> {
    let mut rng = rng;
    readable_links(m)
        .into_iter()
        .map(|(l, p, q)| {
            let r = m.at[q] - m.at[p];
            let noise = match rng.as_mut() {
                Some(g) => (disc(g, delta) - disc(g, delta)) * mu_v,
                None => Vec2::ZERO,
            };
            let rel = perp(r) * v.omega[l] + noise;
            (l, significant(r.cross(rel) / r.hypot2(), 3))
        })
        .collect()
}

/// The ω of every link a student's acceleration plan uses: the stated
/// ones, and a link without one takes its prismatic partners' (the pair
/// lets no relative rotation); the rest (the crank, the frame) as they
/// are.
pub fn omegas_used(m: &Model, v: &Velocities, stated: &[(usize, f64)]) -> Vec<f64> {
    let mut w = v.omega.clone();
    let mut set = vec![false; w.len()];
    for &(l, x) in stated {
        w[l] = x;
        set[l] = true;
    }
    for _ in 0..m.pairs.len() {
        for q in &m.pairs {
            for (a, b) in [(q.slider, q.guide), (q.guide, q.slider)] {
                if set[a] && !set[b] && m.moving(b) {
                    w[b] = w[a];
                    set[b] = true;
                }
            }
        }
    }
    w
}

/// The links that share link `l`'s rotation through prismatic pairs
/// (with `l`).
pub fn rotating_with(m: &Model, l: usize) -> Vec<usize> {
    let mut class = vec![l];
    loop {
        let before = class.len();
        for q in &m.pairs {
            for (a, b) in [(q.slider, q.guide), (q.guide, q.slider)] {
                if class.contains(&a) && !class.contains(&b) {
                    class.push(b);
                }
            }
        }
        if class.len() == before {
            return class;
        }
    }
}

/// The points of links drawn as a similar figure on two earlier points of
/// their link: (X, link, base A, base B) — X listed third or later, and
/// its link determined without X (the links at X take it from there).
pub fn figure_points(m: &Model) -> Vec<(usize, usize, usize, usize)> {
    let mut out = Vec::new();
    for l in 0..m.links.len() {
        let pts = &m.links[l].points;
        if !m.moving(l) || pts.len() < 3 {
            continue;
        }
        for &x in &pts[2..] {
            if !m.links[m.frame].points.contains(&x)
                && m.velocities(&super::rigid::Options {
                    given: vec![(x, l, Vec2::ZERO)],
                    ..Default::default()
                })
                .is_some()
            {
                out.push((x, l, pts[0], pts[1]));
            }
        }
    }
    out
}

/// Where two arcs drawn from `a` and `b` with radii `ra`, `rb` cross, on
/// the side `side` of a→b (the sign of cross(b − a, x − a)); `None` where
/// they do not.
pub fn arcs(a: Vec2, ra: f64, b: Vec2, rb: f64, side: f64) -> Option<Vec2> {
    let d = (b - a).hypot();
    let along = (d * d + ra * ra - rb * rb) / (2.0 * d);
    let h2 = ra * ra - along * along;
    if d == 0.0 || h2 < 0.0 {
        return None;
    }
    let u = (b - a) / d;
    Some(a + u * along + perp(u) * (side.signum() * h2.sqrt()))
}

/// The answer file a student hands in.
#[derive(Clone, Debug)]
pub struct AnswerFile {
    pub plan: PlanKind,
    pub position: usize,
    pub mu: f64,
    pub title: String,
    pub points: Vec<(String, Vec2)>,
    pub segments: Vec<(String, f64)>,
    pub angles: Vec<(String, f64)>,
    pub values: Vec<(String, f64)>,
    /// An acceleration answer's velocity plan: μ_v and the ω read off it
    /// (link id, signed), and sliding velocities by their keys (v_B3B2).
    pub velocity: Option<(f64, Vec<(String, f64)>)>,
}

impl AnswerFile {
    /// The answer as JSON text (docs/check.md, "The answer file").
    pub fn to_json(&self) -> String {
        let mut o = Map::new();
        let plan = match self.plan {
            PlanKind::Velocity => "velocity",
            PlanKind::Acceleration => "acceleration",
        };
        o.insert("title".into(), json!(self.title));
        o.insert("plan".into(), json!(plan));
        o.insert("position".into(), json!(self.position));
        o.insert("mu".into(), json!(self.mu));
        o.insert("delta".into(), json!(0.5));
        let section = |list: &[(String, f64)]| {
            Value::Object(list.iter().map(|(k, x)| (k.clone(), json!(x))).collect())
        };
        if !self.segments.is_empty() {
            o.insert("segments".into(), section(&self.segments));
        }
        if !self.angles.is_empty() {
            o.insert("angles".into(), section(&self.angles));
        }
        if !self.points.is_empty() {
            o.insert(
                "points".into(),
                Value::Object(
                    self.points
                        .iter()
                        .map(|(k, v)| (k.clone(), json!([v.x, v.y])))
                        .collect(),
                ),
            );
        }
        if !self.values.is_empty() {
            o.insert("values".into(), section(&self.values));
        }
        if let Some((mu_v, w)) = &self.velocity {
            let mut v = Map::new();
            v.insert("mu".into(), json!(mu_v));
            if !w.is_empty() {
                v.insert(
                    "values".into(),
                    Value::Object(
                        w.iter()
                            .map(|(id, x)| {
                                // A sliding velocity by its key (v_B3B2),
                                // an ω by its link's id.
                                let key = if id.starts_with("v_") {
                                    id.clone()
                                } else {
                                    format!("omega{id}")
                                };
                                (key, json!(x))
                            })
                            .collect(),
                    ),
                );
            }
            o.insert("velocity".into(), Value::Object(v));
        }
        Value::Object(o).to_string()
    }
}

/// The values a student reads off their drawing at μ: each named point's
/// magnitude (v_B, a_D), each readable link's rate (ω2 on a velocity
/// plan, ε3 on an acceleration plan), written as [`read_value`] (a rate
/// as its relative segment's value).
pub fn values_off(m: &Model, kind: PlanKind, d: &Drawing, mu: f64) -> Vec<(String, f64)> {
    let (v, rate) = match kind {
        PlanKind::Velocity => ("v", "omega"),
        PlanKind::Acceleration => ("a", "eps"),
    };
    let mut out: Vec<(String, f64)> =
        d.0.iter()
            .filter_map(|(_, s, at)| match s {
                Source::Named(p) => Some((
                    format!("{v}_{}", m.names[*p]),
                    read_value(at.hypot() * mu, mu),
                )),
                Source::On { .. } => None,
            })
            .collect();
    for r in readable_links(m) {
        // As its relative segment's value |ω|·l (|ε|·l).
        let (w, l) = (rate_off(m, d, mu, r), (m.at[r.2] - m.at[r.1]).hypot());
        out.push((
            format!("{rate}{}", m.links[r.0].id),
            significant(w, digits(w * l, mu)),
        ));
    }
    out
}

/// Numbers of an answer by key (segments in mm, directions in degrees).
pub type Numbers = Vec<(String, f64)>;

/// The segments from the pole a student measures on a drawing (mm, to
/// 0.1 mm) and their directions (degrees counter-clockwise from +x, to
/// 0.1°), keyed as answers write them: `p_v b`, `p_a b`.
pub fn table(kind: PlanKind, d: &Drawing) -> (Numbers, Numbers) {
    let pole = match kind {
        PlanKind::Velocity => "p_v",
        PlanKind::Acceleration => "p_a",
    };
    let tenth = |x: f64| format!("{x:.1}").parse::<f64>().unwrap();
    let mut seg = Vec::new();
    let mut ang = Vec::new();
    for (k, _, at) in &d.0 {
        let key = format!("{pole} {k}");
        seg.push((key.clone(), tenth(at.hypot())));
        ang.push((key, tenth(at.y.atan2(at.x).to_degrees())));
    }
    (seg, ang)
}
