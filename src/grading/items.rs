//! The answer's items as a construction expects them: the plan point a
//! name stands for, each item's expected value, tolerance and the least
//! difference the pencil can show.

use super::answer::{self, Given, Item, Quantity};
use crate::error::Issue;
use crate::format::num;
use crate::kinematics::construction::{Op, Plan, PlanKind, PointId};
use crate::kinematics::solve::Analysis;
use crate::lang::Lang;
use crate::words::catalogue::CheckPhrases;
use crate::words::check;
use kurbo::Vec2;
use std::collections::{HashMap, HashSet};

/// The plan whose pole `name` is, if it names one pole only: `p_v` (`pv`)
/// the velocity plan's, `p_a` (`pa`) the acceleration plan's; `p` and `π`
/// are either's.
pub(super) fn pole_of(name: &str) -> Option<PlanKind> {
    match name.trim().to_lowercase().as_str() {
        "pv" | "p_v" => Some(PlanKind::Velocity),
        "pa" | "p_a" => Some(PlanKind::Acceleration),
        _ => None,
    }
}

/// Resolve a name of the answer to a plan point: the pole's names (`p`,
/// `π`, and `p_v`, `pv` on a velocity plan, `p_a`, `pa` on an
/// acceleration plan: the other plan's pole is not this one's), named
/// points (their lower-case names), construction points (n2, k3, b3 or
/// their keys n_2, k_3, b_3).
pub fn resolve(plan: &Plan, name: &str) -> Option<usize> {
    let n = name.trim().to_lowercase();
    // A point of the scene named like the pole (the piston P: `p`) is that
    // point; the pole is then `p_v` or `p_a`.
    let named = |p: &crate::kinematics::construction::PlanPoint| p.key.to_lowercase() == n;
    if let Some(i) = plan.points.iter().skip(1).position(named) {
        return Some(i + 1);
    }
    if ["p", "π"].contains(&n.as_str()) {
        return Some(0);
    }
    if let Some(kind) = pole_of(&n) {
        return (kind == plan.kind).then_some(0);
    }
    plan.points
        .iter()
        .position(|p| p.name().to_lowercase() == n || p.key.replace('_', "").to_lowercase() == n)
}

/// One item on one plan: what it is, its expected value and tolerance,
/// the given value (compared modulo a turn for directions), the unit, how
/// small a difference the pencil can show in that unit, the item in mm on
/// the plan, and the plan point whose step draws it.
pub(super) struct Expected {
    pub(super) what: String,
    pub(super) expected: f64,
    pub(super) given: f64,
    pub(super) tol: f64,
    pub(super) unit: &'static str,
    /// The pencil precision δ in the item's unit: a mistake that moves the
    /// item by less cannot be seen on paper.
    pub(super) visible: f64,
    /// (expected, given) in mm on the plan.
    pub(super) on_plan: Option<(f64, f64)>,
    pub(super) point: Option<usize>,
    /// For a point: where this plan has it (mm from the pole).
    pub(super) place: Option<Vec2>,
}

impl Expected {
    /// The item's tolerance as a length on a plan at scale `mu`, mm (a
    /// value's by its segment); `None` for a direction.
    pub(super) fn tol_mm(&self, mu: f64) -> Option<f64> {
        match self.unit {
            "mm" => Some(self.tol),
            "°" => None,
            _ => Some(
                self.on_plan
                    .filter(|_| self.expected != 0.0)
                    .map_or(self.tol / mu, |(x, _)| self.tol * x / self.expected.abs()),
            ),
        }
    }
    /// How far another construction's expectation of this item is from
    /// this one's.
    pub(super) fn moved(&self, other: &Expected) -> f64 {
        match (self.place, other.place) {
            (Some(a), Some(b)) => (a - b).hypot(),
            _ => (self.expected - other.expected).abs(),
        }
    }
}

/// The expected value and tolerance of an item on `plan`, named in
/// `lang`; `Err` names an unknown letter or link.
pub(super) fn expect(
    an: &Analysis,
    plan: &Plan,
    it: &answer::Item,
    delta: f64,
    lang: Lang,
) -> std::result::Result<Expected, Issue> {
    let on = On {
        an,
        plan,
        it,
        delta,
        lang,
    };
    let mut e = match &it.given {
        Given::Segment { from, mm, .. } => on.segment(from, *mm),
        Given::Angle { from, deg, .. } => on.angle(from, *deg),
        Given::Point { name, at } => on.point(name, *at),
        Given::Value {
            quantity: Quantity::Point(name),
            value,
        } => on.point_value(name, *value),
        Given::Value {
            quantity: Quantity::Rate(id),
            value,
        } => on.rate(id, *value),
        Given::Value {
            quantity: Quantity::Sliding(raw),
            value,
        } => on.pair(raw, Part::Sliding, *value),
        Given::Value {
            quantity: Quantity::Coriolis(raw),
            value,
        } => on.pair(raw, Part::Coriolis, *value),
    }?;
    // The number as typed may be off what was read by half a unit of its
    // last digit (in the item's unit), but by no more than the item's own
    // tolerance: v_B = 0.3 for 0.345 is a wrong reading, not a rounding.
    e.tol += it.rounding.min(e.tol);
    Ok(e)
}

/// An item `it` on `plan`, the pencil precision `delta`, named in `lang`.
struct On<'a> {
    an: &'a Analysis,
    plan: &'a Plan,
    it: &'a answer::Item,
    delta: f64,
    lang: Lang,
}

impl On<'_> {
    /// The item's problem `message`.
    fn issue(&self, message: String) -> Issue {
        Issue {
            pointer: self.it.pointer.clone(),
            message,
        }
    }

    /// The item's name in the report's language: `phrase` of the check's
    /// phrases with its one blank `blank` filled by `value`.
    fn named(
        &self,
        phrase: impl Fn(&CheckPhrases) -> &String,
        blank: &str,
        value: &str,
    ) -> String {
        check::fill(phrase(check::phrases(self.lang)), &[(blank, value)])
    }

    fn unknown(&self, n: &str) -> Issue {
        self.issue(format!(
            "unknown plan point \"{n}\" (this plan has: {})",
            names(self.plan)
        ))
    }

    /// The two plan points of segment `key`.
    fn ends(&self, key: &str) -> std::result::Result<(usize, usize), Issue> {
        let plan = self.plan;
        let known = |s: &str| resolve(plan, s).is_some();
        let (a, b) = answer::split_segment(key, &known).ok_or_else(|| {
            self.issue(format!("cannot read \"{key}\" as two plan points; write them with a space, e.g. \"p_v b\" ({})", names(plan)))
        })?;
        Ok((
            resolve(plan, &a).ok_or_else(|| self.unknown(&a))?,
            resolve(plan, &b).ok_or_else(|| self.unknown(&b))?,
        ))
    }

    /// A measured segment, mm.
    fn segment(&self, from: &str, mm: f64) -> std::result::Result<Expected, Issue> {
        let (p, delta) = (&self.plan.points, self.delta);
        let (a, b) = self.ends(from)?;
        let len = (p[b].at - p[a].at).hypot();
        Ok(Expected {
            what: self.named(|w| &w.item_segment, "seg", &format!("{}{}", p[a].name(), p[b].name())),
            expected: len,
            given: mm,
            tol: p[a].err + p[b].err + delta,
            unit: "mm",
            visible: delta,
            on_plan: Some((len, mm)),
            point: Some(a.max(b)),
            place: None,
        })
    }

    /// A segment's direction, degrees, compared modulo a turn.
    fn angle(&self, from: &str, deg: f64) -> std::result::Result<Expected, Issue> {
        let (p, delta) = (&self.plan.points, self.delta);
        let (a, b) = self.ends(from)?;
        let d = p[b].at - p[a].at;
        let len = d.hypot();
        let deg_of = |mm: f64| {
            if len > 0.0 {
                (mm / len).min(std::f64::consts::PI).to_degrees()
            } else {
                180.0
            }
        };
        let exp = d.atan2().to_degrees();
        // Compare directions modulo a turn.
        let given = exp + crate::geom::wrap_pi((deg - exp).to_radians()).to_degrees();
        Ok(Expected {
            what: self.named(|w| &w.item_direction, "seg", &format!("{}{}", p[a].name(), p[b].name())),
            expected: exp,
            given,
            tol: deg_of(p[a].err + p[b].err + delta),
            unit: "°",
            visible: deg_of(delta),
            on_plan: None,
            point: Some(a.max(b)),
            place: None,
        })
    }

    /// A plan point's place, mm from the pole.
    fn point(&self, name: &str, at: [f64; 2]) -> std::result::Result<Expected, Issue> {
        let (p, delta) = (&self.plan.points, self.delta);
        let i = resolve(self.plan, name).ok_or_else(|| self.unknown(name))?;
        // Distance from the expected place is the difference; "expected" 0.
        let d = (Vec2::new(at[0], at[1]) - p[i].at).hypot();
        Ok(Expected {
            what: self.named(|w| &w.item_point, "name", &p[i].name()),
            expected: 0.0,
            given: d,
            tol: p[i].err + delta,
            unit: "mm",
            visible: delta,
            on_plan: Some((0.0, d)),
            point: Some(i),
            place: Some(p[i].at),
        })
    }

    /// |v_X| or |a_X| of a named point.
    fn point_value(&self, name: &str, value: f64) -> std::result::Result<Expected, Issue> {
        let (plan, delta) = (self.plan, self.delta);
        let (p, mu) = (&plan.points, plan.mu);
        let m = &self.an.mech;
        let (sym, unit) = if plan.kind == PlanKind::Velocity {
            ("v", "m/s")
        } else {
            ("a", "m/s²")
        };
        let values = || {
            let on: Vec<String> = (0..m.scene.points.len())
                .filter(|&q| plan.of_point[q].is_some())
                .map(|q| format!("{sym}_{}", m.point_name(q)))
                .collect();
            on.join(", ")
        };
        // v_B3B2, a_B3B2: B of link 3 relative to link 2, the segment
        // b2b3.
        if m.scene.point_index(name).is_none() && slide_of(m, name).is_some() {
            return self.pair(name, Part::Whole, value);
        }
        let pi = m.scene.point_index(name).ok_or_else(|| {
            self.issue(format!(
                "unknown point \"{name}\" (this plan gives: {})",
                values()
            ))
        })?;
        let i = plan.of_point[pi].ok_or_else(|| {
            self.issue(format!(
                "point \"{name}\" is not on this plan (it gives: {})",
                values()
            ))
        })?;
        let len = p[i].at.hypot();
        Ok(Expected {
            what: format!("{sym}_{name}"),
            expected: len * mu,
            given: value,
            tol: (p[i].err + delta) * mu,
            unit,
            visible: delta * mu,
            on_plan: Some((len, value / mu)),
            point: Some(i),
            place: None,
        })
    }

    /// ω or ε of a link (signed where the plan shows the sense).
    fn rate(&self, id: &str, value: f64) -> std::result::Result<Expected, Issue> {
        let (plan, delta) = (self.plan, self.delta);
        let mu = plan.mu;
        let m = &self.an.mech;
        let (sym, unit) = if plan.kind == PlanKind::Velocity {
            ("ω", "rad/s")
        } else {
            ("ε", "rad/s²")
        };
        let rates = || {
            let on: Vec<String> = (0..plan.rates.len())
                .filter(|&l| plan.rates[l].is_some())
                .map(|l| format!("{sym}{}", m.link_id(l)))
                .collect();
            on.join(", ")
        };
        let l = m.scene.link_index(id).ok_or_else(|| {
            self.issue(format!(
                "unknown link \"{id}\" (this plan gives: {})",
                rates()
            ))
        })?;
        let (r, bound) = plan.rates[l].ok_or_else(|| {
            self.issue(format!(
                "link {id} is not constructed on this plan (it gives: {})",
                rates()
            ))
        })?;
        let len = plan.rate_len[l];
        let measured = plan
            .measured
            .iter()
            .find(|q| q.quantity == format!("{sym}{id}"));
        // A sense that cannot be read off this plan: magnitudes only.
        let (r, given) = if plan.rate_sense[l] {
            (r, value)
        } else {
            (r.abs(), value.abs())
        };
        Ok(Expected {
            what: format!("{sym}{id}"),
            expected: r,
            given,
            tol: bound,
            unit,
            visible: if len > 0.0 { delta * mu / len } else { bound },
            on_plan: (len > 0.0).then(|| (r.abs() * len / mu, value.abs() * len / mu)),
            point: measured.map(|q| q.to),
            place: None,
        })
    }
}

/// Which part of a prismatic pair's relative motion an item gives.
#[derive(Clone, Copy, PartialEq)]
enum Part {
    /// v_B3B2 (the sliding velocity) or a_B3B2 (the whole relative
    /// acceleration): the segment between the pair's two points.
    Whole,
    /// a^r_B3B2: from the Coriolis point to the point it is laid toward.
    Sliding,
    /// a^k_B3B2: from the point it is laid off from to the Coriolis point.
    Coriolis,
}

impl On<'_> {
    /// A value of the prismatic pair `raw` (`B3B2`), read off this plan's
    /// segment for `part`.
    fn pair(&self, raw: &str, part: Part, value: f64) -> std::result::Result<Expected, Issue> {
        let (plan, delta) = (self.plan, self.delta);
        let (p, mu) = (&plan.points, plan.mu);
        let m = &self.an.mech;
        let (sym, unit) = match (plan.kind, part) {
            (PlanKind::Velocity, Part::Whole) => ("v_", "m/s"),
            (PlanKind::Velocity, _) => {
                return Err(self.issue(format!(
                    "\"{}\" belongs to the acceleration plan, but this answer is the velocity plan",
                    self.it.key
                )));
            }
            (_, Part::Whole) => ("a_", "m/s²"),
            (_, Part::Sliding) => ("a^r_", "m/s²"),
            (_, Part::Coriolis) => ("a^k_", "m/s²"),
        };
        let (q, l1, l2) = slide_of(m, raw).ok_or_else(|| {
            self.issue(format!(
                "cannot read \"{raw}\" as a point of one link relative to another (B3B2: B of link 3 on link 2)"
            ))
        })?;
        // The pair's point as a point of link l on this plan: its own
        // named point where the link carries it, else its coincident one.
        let on_link = |l: usize| {
            if l == m.frame() {
                // The frame's every point is the pole.
                return Some(0);
            }
            p.iter()
                .position(|x| x.id == PointId::Coincident { point: q, link: l })
                .or_else(|| {
                    m.links[l]
                        .points
                        .contains(&q)
                        .then(|| plan.of_point[q])
                        .flatten()
                })
        };
        let pts = on_link(l1).zip(on_link(l2));
        // The steps that lay off the pair's Coriolis acceleration and its
        // given relative vector (a driven pair: a cylinder), as (from, to).
        let laid = |of: &dyn Fn(PointId) -> bool| {
            plan.steps.iter().find_map(|st| match &st.op {
                Op::LayOff { from, to, .. } if of(p[*to].id) => Some((*from, *to)),
                _ => None,
            })
        };
        let cor = laid(&|id| {
            matches!(id, PointId::Coriolis { link } if link == l1 || link == l2)
        });
        let rel = laid(&|id| {
            matches!(id, PointId::Relative { link } if link == l1 || link == l2)
        });
        if pts.is_none() && rel.is_none() && cor.is_none() {
            return Err(self.issue(format!(
                "{sym}{raw}: this plan has no points of {} on links {} and {} to read it off",
                m.point_name(q),
                m.link_id(l1),
                m.link_id(l2)
            )));
        }
        // The segments whose vector sum the item is.
        let segments: Vec<(usize, usize)> = match part {
            Part::Coriolis => cor.into_iter().collect(),
            Part::Sliding => match (rel, cor, pts) {
                (Some(r), ..) => vec![r],
                (None, Some((from, k)), Some((i1, i2))) => {
                    vec![(k, if from == i1 { i2 } else { i1 })]
                }
                (None, _, Some(ends)) => vec![ends],
                // A driven pair whose given relative acceleration is 0:
                // nothing laid off.
                (None, _, None) => Vec::new(),
            },
            Part::Whole => match (pts, rel) {
                (Some(ends), _) => vec![ends],
                (None, r) => cor.into_iter().chain(r).collect(),
            },
        };
        let len = segments
            .iter()
            .map(|&(a, z)| p[z].at - p[a].at)
            .fold(Vec2::ZERO, |x, y| x + y)
            .hypot();
        // A segment laid off is as good as its own step (its end's error
        // less its start's: δ and its value's); one between two points
        // found apart, their errors added.
        let own = |a: usize, z: usize| {
            [cor, rel]
                .into_iter()
                .flatten()
                .any(|step| step == (a, z))
                .then(|| (p[z].err - p[a].err).max(0.0))
        };
        let err: f64 = segments
            .iter()
            .map(|&(a, z)| own(a, z).unwrap_or(p[a].err + p[z].err))
            .sum();
        let last = segments.iter().map(|&(a, z)| a.max(z)).max();
        Ok(Expected {
            what: format!("{sym}{raw}"),
            expected: len * mu,
            given: value,
            tol: (err + delta) * mu,
            unit,
            visible: delta * mu,
            on_plan: Some((len, value / mu)),
            point: last,
            place: None,
        })
    }
}

/// A relative sliding quantity as written after `v_` (`B3B2`: point B
/// of link 3 relative to link 2): the point and the two links (indices),
/// read on the scene's names (a point's name may end in digits, as a
/// link's id: every split is tried, the point's name repeated).
pub(super) fn slide_of(m: &crate::model::mechanism::Mechanism, raw: &str) -> Option<(usize, usize, usize)> {
    let scene = &m.scene;
    let mut found = None;
    for (p, point) in scene.points.iter().enumerate() {
        for exact in [true, false] {
            let name = &point.name;
            let starts = if exact {
                raw.starts_with(name.as_str())
            } else {
                raw.to_lowercase().starts_with(&name.to_lowercase())
            };
            if !starts || raw.len() <= name.len() {
                continue;
            }
            let rest = &raw[name.len()..];
            let hay = if exact { rest.to_string() } else { rest.to_lowercase() };
            let needle = if exact { name.clone() } else { name.to_lowercase() };
            let Some(i) = hay.find(&needle).filter(|&i| i > 0) else {
                continue;
            };
            let (l1, l2) = (&rest[..i], &rest[i + name.len()..]);
            if let (Some(a), Some(b)) = (scene.link_index(l1), scene.link_index(l2))
                && a != b
            {
                found = found.or(Some((p, a, b)));
            }
        }
    }
    found
}

pub(super) fn names(plan: &Plan) -> String {
    let mut v: Vec<String> = plan.points.iter().map(|p| p.name()).collect();
    v.dedup();
    v.join(", ")
}

/// What an item gives, whatever its spelling: a plan point's place, a
/// segment's length or direction (its two ends either way round), a
/// point's value (by the scene's point), a link's rate.
#[derive(Clone, Copy, Debug, Hash, PartialEq, Eq)]
enum Said {
    Point(usize),
    Segment(usize, usize),
    Angle(usize, usize),
    Value(usize),
    Rate(usize),
}

/// What item `it` gives on `plan`, and its name in a message; `None` for
/// an item whose names do not resolve (`expect` says why).
fn said(an: &Analysis, plan: &Plan, it: &Item) -> Option<(Said, String)> {
    let p = &plan.points;
    let ends = |key: &str| {
        let known = |s: &str| resolve(plan, s).is_some();
        let (a, b) = answer::split_segment(key, &known)?;
        let (a, b) = (resolve(plan, &a)?, resolve(plan, &b)?);
        Some(((a.min(b), a.max(b)), format!("{} {}", p[a].name(), p[b].name())))
    };
    let rate_sym = if plan.kind == PlanKind::Velocity {
        "ω"
    } else {
        "ε"
    };
    let value_sym = if plan.kind == PlanKind::Velocity {
        "v"
    } else {
        "a"
    };
    let scene = &an.mech.scene;
    Some(match &it.given {
        Given::Point { name, .. } => {
            let i = resolve(plan, name)?;
            (Said::Point(i), format!("point {}", p[i].name()))
        }
        Given::Segment { from, .. } => {
            let ((a, b), n) = ends(from)?;
            (Said::Segment(a, b), format!("segment {n}"))
        }
        Given::Angle { from, .. } => {
            let ((a, b), n) = ends(from)?;
            (Said::Angle(a, b), format!("the direction of {n}"))
        }
        Given::Value {
            quantity: Quantity::Point(name),
            ..
        } => (
            Said::Value(scene.point_index(name)?),
            format!("{value_sym}_{name}"),
        ),
        Given::Value {
            quantity: Quantity::Rate(id),
            ..
        } => (
            Said::Rate(scene.link_index(id)?),
            format!("{rate_sym}{id}"),
        ),
        Given::Value {
            quantity: Quantity::Sliding(_) | Quantity::Coriolis(_),
            ..
        } => return None,
    })
}

/// Items of `items` that give what an earlier one gives, under the same
/// or another spelling (`n2` and `n_2`, `p_v b` and `b p_v`, `v_B` and
/// `vB`, `omega2` and `ω2`): one issue per thing given more than once, at
/// the second item, naming the others. A drawing's labels of one point at
/// the same line end are one point labelled twice, not a problem; at
/// different ends they give two places, named in the message.
pub(super) fn given_twice(an: &Analysis, plan: &Plan, items: &[Item]) -> Vec<Issue> {
    let drawn = |it: &Item| it.pointer.starts_with("svg");
    let place = |it: &Item| match it.given {
        Given::Point { at, .. } => Some(at),
        _ => None,
    };
    // Per thing given: its name, the items that give it, and the places of
    // the drawing's labels of it (bits of x and y).
    let mut groups: Vec<(String, Vec<usize>, HashSet<[u64; 2]>)> = Vec::new();
    let mut seen: HashMap<Said, usize> = HashMap::new();
    for (k, it) in items.iter().enumerate() {
        let Some((what, name)) = said(an, plan, it) else {
            continue;
        };
        let g = *seen.entry(what).or_insert_with(|| {
            groups.push((name, Vec::new(), HashSet::new()));
            groups.len() - 1
        });
        let label = place(it)
            .filter(|_| drawn(it))
            .map(|[x, y]| [x.to_bits(), y.to_bits()]);
        if label.is_none_or(|at| groups[g].2.insert(at)) {
            groups[g].1.push(k);
        }
    }
    let mut issues = Vec::new();
    for (name, ks, _) in groups.into_iter().filter(|(_, ks, _)| ks.len() > 1) {
        let pointer = items[ks[1]].pointer.clone();
        let times = match ks.len() {
            2 => "twice".to_string(),
            n => format!("{n} times"),
        };
        let others: Vec<&str> = ks
            .iter()
            .map(|&k| items[k].pointer.as_str())
            .filter(|&q| q != pointer)
            .collect();
        let mut also = others.iter().take(3).copied().collect::<Vec<_>>().join(", ");
        if others.len() > 3 {
            also.push_str(&format!(" and {} more", others.len() - 3));
        }
        let mut message = format!("{name} is given {times}");
        if !also.is_empty() {
            message.push_str(&format!(" (also {also})"));
        }
        if ks.iter().all(|&k| drawn(&items[k])) {
            let places: Vec<String> = ks
                .iter()
                .take(3)
                .filter_map(|&k| place(&items[k]))
                .map(|[x, y]| format!("({}, {})", num(x), num(y)))
                .collect();
            message.push_str(&format!(
                ", by labels at different line ends: {}{} mm from the pole; label each point once",
                places.join(", "),
                if ks.len() > 3 { " …" } else { "" }
            ));
        } else {
            message.push_str("; give each once");
        }
        issues.push(Issue { pointer, message });
    }
    issues
}
