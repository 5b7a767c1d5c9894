//! The construction as the kernel records it: every step in ids (plan
//! points by index, points and links of the mechanism by index), and the
//! naming pass that puts the record into words at the end of a full build
//! (the plan points' keys, labels and figures, the measured quantities'
//! names, the steps). A numbers-only build skips it.

use super::plan::{
    Dir, Measured, Op, Plan, PlanKind, PlanLine, PointId, Quantity, Setup, Step, Why,
};
use crate::model::mechanism::Mechanism;
use kurbo::Vec2;
use std::collections::HashSet;

/// A point's name in a step's text.
#[derive(Clone, Copy, Debug)]
pub(super) enum Name {
    /// A point of the mechanism: `B`.
    Point(usize),
    /// A point of the mechanism as a point of a link: `B3`.
    On(usize, usize),
    /// The special point of a class III group on its base link: `S4`.
    Special(usize),
    /// The figure's name of a plan point (a point no named point of the
    /// link is at: a coincident point `B3`).
    Figure(usize),
}

/// A segment of the mechanism, its two ends' names run together.
pub(super) type Seg = (Name, Name);

/// An angular rate of a link: `ω2`, `ε2`.
#[derive(Clone, Copy, Debug)]
pub(super) enum Rate {
    Omega(usize),
    Epsilon(usize),
}

/// A direction, typed ([`Dir`] in words).
#[derive(Clone, Copy, Debug)]
pub(super) enum Way {
    /// ⊥ the segment.
    Perp(Seg),
    /// ∥ the segment from its first point toward its second.
    Toward(Seg),
    /// ∥ the guide of a link.
    Guide(usize),
    /// v_XuXk turned by 90° in the sense of ωg, g the guide (the
    /// lecture's transport rotation: ω3 of the shaper's kulisa 3).
    Turned {
        x: Name,
        unknown: usize,
        known: usize,
        guide: usize,
    },
    /// ⊥ the segment in the sense of a rate.
    PerpSense(Seg, Rate),
}

/// A line drawn on the plan ([`PlanLine`] in words).
#[derive(Clone, Copy, Debug)]
pub(super) struct Ray {
    pub through: usize,
    pub unit: Vec2,
    pub way: Way,
    pub err: f64,
    pub shift: f64,
}

/// A rate (squared or not) times the length of a segment: `ω2²·l_AB`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Product {
    pub rate: Rate,
    pub squared: bool,
    pub seg: Seg,
}

impl Product {
    /// `rate`·l_seg.
    pub fn new(rate: Rate, seg: Seg) -> Product {
        Product {
            rate,
            squared: false,
            seg,
        }
    }
    /// `rate`²·l_seg.
    pub fn squared(rate: Rate, seg: Seg) -> Product {
        Product {
            rate,
            squared: true,
            seg,
        }
    }
}

/// The vector laid off.
#[derive(Clone, Copy, Debug)]
pub(super) enum What {
    /// A relative vector: `ω2·l_AB`.
    Product(Product),
    /// A normal (`'n'`) or tangential (`'t'`) component of X about J:
    /// `a^n_XJ = ω2²·l_JX`.
    Component {
        sup: char,
        x: Name,
        j: Name,
        is: Product,
    },
    /// The Coriolis acceleration of X of link `unknown` sliding on `known`,
    /// `guide` the one of the two that is the guide: a^K = 2·ω_guide·v_rel
    /// (the lecture's a^K_B3B = 2·ω3·v_B3B).
    Coriolis {
        x: Name,
        unknown: usize,
        known: usize,
        guide: usize,
    },
    /// The driving slider's own velocity (acceleration): `v_B`.
    Drive(Name),
    /// The given relative velocity (relative acceleration) of X of link
    /// `moving` on link `known`, a driving pair's slide: `v_B3B2`
    /// (`a^r_B3B2`).
    Given {
        x: Name,
        moving: usize,
        known: usize,
    },
}

/// One vector equation: X from a known point through a rigid link (normal
/// and tangential parts) or a slide (Coriolis and relative parts); or
/// through a cylinder (`via`: X of link `.0` whose pair with the rigid
/// link `.1` slides as given), both.
#[derive(Clone, Copy, Debug)]
pub(super) struct Relation {
    pub x: Name,
    pub base: Name,
    pub rigid: bool,
    pub rotating: bool,
    pub via: Option<(usize, usize)>,
}

/// The vector equations of a step.
#[derive(Clone, Copy, Debug)]
pub(super) enum Eqn {
    /// A dyad's two relations.
    Pair(Relation, Relation),
    /// The crank's point A about its pivot O: v_A = ω1·l_OA.
    CrankVelocity { a: Name, o: Name, link: usize },
    /// a_A = a^n_AO + a^t_AO.
    CrankAcceleration { a: Name, o: Name },
    /// a_A = a^n_AO (ε1 = 0).
    CrankNormal { a: Name, o: Name, link: usize },
    /// A class III group's special point on its base from two leashes
    /// (each leash's outer joint and inner joint).
    Special { base: usize, leashes: [Seg; 2] },
    /// X of link `moving` from the coincident point `base` of `known`
    /// across a driving pair, every part known: v_X = v_Xk + v_rel;
    /// a_X = a_Xk (+ a^K on a rotating guide) + a^r.
    Driven {
        x: Name,
        base: Name,
        moving: usize,
        known: usize,
        rotating: bool,
    },
}

/// What a measurement reads.
#[derive(Clone, Copy, Debug)]
pub(super) enum Reading {
    /// The velocity (acceleration) of a named point.
    Point(usize),
    /// The relative segment of `link` between J and X (its length `length`,
    /// m), and the link's rate `rate` from it.
    Relative {
        link: usize,
        j: Name,
        x: Name,
        length: f64,
        rate: f64,
    },
}

/// How a figure's point is drawn.
#[derive(Clone, Copy, Debug)]
pub(super) enum By {
    /// The triangle similar to the link's (by two arcs).
    Similar { link: usize },
    /// The segment divided in the ratio.
    Divide { ratio: f64 },
}

/// One drafting operation in ids ([`Op`] in words).
#[derive(Clone, Copy, Debug)]
pub(super) enum Act {
    Pole,
    LayOff {
        from: usize,
        to: usize,
        what: What,
        value: f64,
        way: Way,
    },
    Intersect {
        lines: [Ray; 2],
        out: usize,
        sin_angle: f64,
    },
    /// The point `out` of a link's figure on plan points `a`, `b`.
    Figure {
        a: usize,
        b: usize,
        out: usize,
        figure: [Name; 3],
        by: By,
    },
    /// `translates`: the translating link, or `None` for the frame.
    Coincide {
        out: usize,
        with: usize,
        translates: Option<usize>,
    },
    Measure {
        from: usize,
        to: usize,
        value: f64,
        reading: Reading,
    },
    Same {
        link: usize,
        from_link: usize,
    },
    Equation(Eqn),
}

/// A vector known in magnitude and direction, doubly underlined as the
/// lecture marks it.
fn known(s: &str) -> String {
    s.chars().flat_map(|c| [c, '\u{0333}']).collect()
}

/// A vector known in direction only, singly underlined.
fn direction_known(s: &str) -> String {
    s.chars().flat_map(|c| [c, '\u{0332}']).collect()
}

/// A scene point's letter and subscript on the plans: its name in lower
/// case, split where the digits begin (S2: s₂). A letter the construction
/// uses for its own points takes a prime (the piston P is p′, never a
/// second p beside the pole p_v; the ram's K is k′ beside the Coriolis
/// point k₃), so that no scene point reads as a construction point. The
/// key (the result file's) stays the plain lower-case name.
fn lower_label(name: &str) -> (String, String) {
    let lower = name.to_lowercase();
    let split = lower
        .find(|c: char| c.is_ascii_digit() || c == '_')
        .unwrap_or(lower.len());
    let (a, b) = lower.split_at(split);
    let mut letter = a.to_string();
    if super::plan::CONSTRUCTION_LETTERS.contains(&a) {
        letter.push('′');
    }
    (letter, b.trim_start_matches('_').to_string())
}

/// A plan point's key and label by its id, before a repeated key is told
/// apart by primes.
pub(super) fn key_label(id: PointId, kind: PlanKind, m: &Mechanism) -> (String, (String, String)) {
    let by = |letter: &str, link: usize| {
        let l = m.link_id(link);
        (format!("{letter}_{l}"), (letter.to_string(), l.to_string()))
    };
    match id {
        PointId::Pole => match kind {
            PlanKind::Velocity => ("p_v".into(), ("p".into(), "v".into())),
            PlanKind::Acceleration => ("p_a".into(), ("p".into(), "a".into())),
        },
        PointId::Named(p) => {
            let name = m.point_name(p);
            (name.to_lowercase(), lower_label(name))
        }
        PointId::Coincident { point, link } => {
            let name = m.point_name(point);
            let l = m.link_id(link);
            (
                format!("{}_{l}", name.to_lowercase()),
                (lower_label(name).0, l.to_string()),
            )
        }
        PointId::Normal { link } => by("n", link),
        PointId::Coriolis { link } => {
            let (key, (_, sub)) = by("k", link);
            (key, ("k".to_string(), sub))
        }
        PointId::Relative { link } => by("r", link),
        PointId::Special { base } => {
            let (key, (_, sub)) = by("s", base);
            (key, (SPECIAL.to_string(), sub))
        }
    }
}

/// The letter of Assur's special point on the plans (σ₃ for the base link
/// 3): not s, which reads as a centre of mass (S3, s₃), nor any point's
/// letter. Its name in the steps is the capital, Σ3.
const SPECIAL: &str = "σ";

/// The words of a plan: puts the record `acts` of its construction into
/// the plan's names and steps.
pub(super) fn narrate(plan: &mut Plan, acts: &[Act], st: &Setup) {
    let m = st.m;
    let mut seen = HashSet::new();
    for p in &mut plan.points {
        let (mut key, mut label) = key_label(p.id, plan.kind, m);
        while seen.contains(&key) {
            // A second n₂ on one plan is n′₂ (then n″₂): the prime marks
            // the letter, as the subscript still names the link.
            key.push('\'');
            label.0.push('′');
        }
        seen.insert(key.clone());
        (p.key, p.label) = (key, label);
    }
    let w = Words { m, plan };
    let quantities: Vec<String> = plan.measured.iter().map(|q| w.quantity(q)).collect();
    let steps = acts.iter().map(|a| Step { op: w.op(a, st) }).collect();
    plan.steps = steps;
    for (q, name) in plan.measured.iter_mut().zip(quantities) {
        q.quantity = name;
    }
}

/// The words of one plan's record.
struct Words<'a> {
    m: &'a Mechanism,
    plan: &'a Plan,
}

impl Words<'_> {
    fn vel(&self) -> bool {
        self.plan.kind == PlanKind::Velocity
    }
    /// `v` or `a`.
    fn v(&self) -> &'static str {
        if self.vel() { "v" } else { "a" }
    }
    fn link(&self, l: usize) -> &str {
        self.m.link_id(l)
    }
    fn name(&self, n: Name) -> String {
        let m = self.m;
        match n {
            Name::Point(p) => m.point_name(p).to_string(),
            Name::On(p, l) => format!("{}{}", m.point_name(p), m.link_id(l)),
            Name::Special(b) => format!("{}{}", SPECIAL.to_uppercase(), m.link_id(b)),
            Name::Figure(i) => self.plan.points[i].figure(),
        }
    }
    fn seg(&self, (a, b): Seg) -> String {
        self.name(a) + &self.name(b)
    }
    fn rate(&self, r: Rate) -> String {
        match r {
            Rate::Omega(l) => format!("ω{}", self.link(l)),
            Rate::Epsilon(l) => format!("ε{}", self.link(l)),
        }
    }
    /// The rate of a link on this plan: ω on the velocity plan, ε on the
    /// acceleration plan.
    fn own_rate(&self, l: usize) -> String {
        self.rate(if self.vel() {
            Rate::Omega(l)
        } else {
            Rate::Epsilon(l)
        })
    }
    fn product(&self, p: Product) -> String {
        let sq = if p.squared { "²" } else { "" };
        format!("{}{sq}·l_{}", self.rate(p.rate), self.seg(p.seg))
    }
    fn quantity(&self, q: &Measured) -> String {
        match q.of {
            Quantity::Rate(l) => self.own_rate(l),
            Quantity::Point(p) => format!("{}_{}", self.v(), self.m.point_name(p)),
        }
    }
    /// v_XuXk: the velocity of X of link u relative to link k.
    fn relative(&self, x: Name, u: usize, k: usize) -> String {
        let x = self.name(x);
        format!("v_{x}{}{x}{}", self.link(u), self.link(k))
    }
    fn what(&self, w: What) -> String {
        match w {
            What::Product(p) => self.product(p),
            What::Component { sup, x, j, is } => format!(
                "a^{sup}_{}{} = {}",
                self.name(x),
                self.name(j),
                self.product(is)
            ),
            What::Coriolis {
                x,
                unknown,
                known,
                guide,
            } => {
                let v = self.relative(x, unknown, known);
                let x = self.name(x);
                let (u, k, g) = (self.link(unknown), self.link(known), self.link(guide));
                format!("a^K_{x}{u}{x}{k} = 2·ω{g}·{v}")
            }
            What::Drive(x) => format!("{}_{}", self.v(), self.name(x)),
            What::Given { x, moving, known } => self.given(x, moving, known),
        }
    }
    /// The given relative vector of X of `moving` on `known`: v_XmXk on
    /// the velocity plan, a^r_XmXk on the acceleration plan.
    fn given(&self, x: Name, moving: usize, known: usize) -> String {
        let v = self.relative(x, moving, known);
        if self.vel() {
            v
        } else {
            format!("a^r{}", &v[1..])
        }
    }
    fn dir(&self, w: Way) -> Dir {
        match w {
            Way::Perp(s) => Dir::Perp(self.seg(s)),
            Way::Toward((a, b)) => Dir::Toward(self.name(a), self.name(b)),
            Way::Guide(l) => Dir::Guide(self.link(l).to_string()),
            Way::Turned {
                x,
                unknown,
                known,
                guide,
            } => Dir::Turned(
                self.relative(x, unknown, known),
                self.rate(Rate::Omega(guide)),
            ),
            Way::PerpSense(s, r) => Dir::PerpSense(self.seg(s), self.rate(r)),
        }
    }
    fn line(&self, r: &Ray) -> PlanLine {
        PlanLine {
            through: r.through,
            unit: r.unit,
            dir: self.dir(r.way),
            err: r.err,
            shift: r.shift,
        }
    }
    fn relation(&self, r: Relation) -> String {
        if let Some((moving, rigid)) = r.via {
            return self.cylinder(r, moving, rigid);
        }
        let (x, base) = (self.name(r.x), self.name(r.base));
        if self.vel() {
            return format!(
                "v_{x} = {} + {}",
                known(&format!("v_{base}")),
                direction_known(&format!("v_{x}{base}"))
            );
        }
        let mut parts = vec![known(&format!("a_{base}"))];
        let (along, across) = if r.rigid { ('n', 't') } else { ('K', 'r') };
        if r.rotating {
            parts.push(known(&format!("a^{along}_{x}{base}")));
        }
        parts.push(direction_known(&format!("a^{across}_{x}{base}")));
        format!("a_{x} = {}", parts.join(" + "))
    }
    /// X of link `moving` through a cylinder whose link `rigid` turns
    /// about the known point: v_X = v_J + v_XmXr (given) + v_XrJ (⊥);
    /// a_X = a_J + a^n_XrJ + a^K_XmXr + a^r_XmXr + a^t_XrJ (⊥).
    fn cylinder(&self, r: Relation, moving: usize, rigid: usize) -> String {
        let (x, base) = (self.name(r.x), self.name(r.base));
        let xr = format!("{x}{}", self.link(rigid));
        let rel = self.relative(r.x, moving, rigid);
        if self.vel() {
            return format!(
                "v_{x} = {} + {} + {}",
                known(&format!("v_{base}")),
                known(&rel),
                direction_known(&format!("v_{xr}{base}"))
            );
        }
        let mut parts = vec![known(&format!("a_{base}"))];
        if r.rotating {
            parts.push(known(&format!("a^n_{xr}{base}")));
            parts.push(known(&format!("a^K{}", &rel[1..])));
        }
        parts.push(known(&format!("a^r{}", &rel[1..])));
        parts.push(direction_known(&format!("a^t_{xr}{base}")));
        format!("a_{x} = {}", parts.join(" + "))
    }
    fn equation(&self, e: Eqn) -> String {
        match e {
            Eqn::Driven {
                x,
                base,
                moving,
                known: k,
                rotating,
            } => {
                let (xn, bn) = (self.name(x), self.name(base));
                let v = self.v();
                let mut parts = vec![known(&format!("{v}_{bn}"))];
                if !self.vel() && rotating {
                    parts.push(known(&format!("a^K{}", &self.relative(x, moving, k)[1..])));
                }
                parts.push(known(&self.given(x, moving, k)));
                format!("{v}_{xn} = {}", parts.join(" + "))
            }
            Eqn::Pair(a, b) => format!("{}; {}", self.relation(a), self.relation(b)),
            Eqn::CrankVelocity { a, o, link } => {
                let (an, seg) = (self.name(a), self.seg((o, a)));
                format!("v_{an} = ω{}·l_{seg}, v_{an} ⊥ {seg}", self.link(link))
            }
            Eqn::CrankAcceleration { a, o } => {
                let (an, on) = (self.name(a), self.name(o));
                format!("a_{an} = a^n_{an}{on} + a^t_{an}{on}")
            }
            Eqn::CrankNormal { a, o, link } => {
                let (an, on) = (self.name(a), self.name(o));
                format!("a_{an} = a^n_{an}{on} (ε{} = 0)", self.link(link))
            }
            Eqn::Special { base, leashes } => {
                let (s, v, b) = (self.name(Name::Special(base)), self.v(), self.link(base));
                let [(e1, j1), (e2, j2)] = leashes.map(|(e, j)| (self.name(e), self.name(j)));
                let via = |e: &str, j: &str| format!("{v}_{s} = {v}_{e} + {v}_{j}{e} + {v}_{s}{j}");
                format!(
                    "special point {s} = {e1}{j1} ∩ {e2}{j2} on link {b}: {}; {}",
                    via(&e1, &j1),
                    via(&e2, &j2)
                )
            }
        }
    }
    fn op(&self, a: &Act, st: &Setup) -> Op {
        let m = self.m;
        match *a {
            Act::Pole => Op::Pole {
                fixed: m.links[m.frame()]
                    .points
                    .iter()
                    .filter(|p| st.points.contains(p))
                    .map(|&p| m.point_name(p).to_lowercase())
                    .collect(),
            },
            Act::LayOff {
                from,
                to,
                what,
                value,
                way,
            } => Op::LayOff {
                from,
                to,
                what: self.what(what),
                value,
                dir: self.dir(way),
            },
            Act::Intersect {
                lines,
                out,
                sin_angle,
            } => Op::Intersect {
                lines: [self.line(&lines[0]), self.line(&lines[1])],
                out,
                sin_angle,
            },
            Act::Figure {
                a,
                b,
                out,
                figure,
                by,
            } => {
                let figure = figure.map(|n| self.name(n));
                match by {
                    By::Similar { link } => Op::Similar {
                        a,
                        b,
                        out,
                        figure,
                        link: self.link(link).to_string(),
                    },
                    By::Divide { ratio } => Op::Divide {
                        a,
                        b,
                        out,
                        figure,
                        ratio,
                    },
                }
            }
            Act::Coincide {
                out,
                with,
                translates,
            } => Op::Coincide {
                out,
                with,
                why: match translates {
                    None => Why::Fixed,
                    Some(l) => Why::Translates(self.link(l).to_string()),
                },
            },
            Act::Measure {
                from,
                to,
                value,
                reading,
            } => match reading {
                Reading::Point(p) => Op::Measure {
                    from,
                    to,
                    quantity: format!("{}_{}", self.v(), m.point_name(p)),
                    value,
                    length: None,
                    rate: None,
                },
                Reading::Relative {
                    link,
                    j,
                    x,
                    length,
                    rate,
                } => {
                    let (jn, xn) = (self.name(j), self.name(x));
                    let quantity = if self.vel() {
                        format!("v_{xn}{jn}")
                    } else {
                        format!("a^t_{xn}{jn}")
                    };
                    Op::Measure {
                        from,
                        to,
                        quantity,
                        value,
                        length: Some(length),
                        rate: Some((self.own_rate(link), rate, (jn, xn))),
                    }
                }
            },
            Act::Same { link, from_link } => Op::Same {
                link: self.link(link).to_string(),
                from_link: self.link(from_link).to_string(),
                what: (if self.vel() { "ω" } else { "ε" }).to_string(),
            },
            Act::Equation(e) => Op::Equation {
                text: self.equation(e),
            },
        }
    }
}
