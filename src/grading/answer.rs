//! The student's answer: a JSON file (format in `docs/check.md`) or an SVG
//! drawn in a vector editor, read into items to check.

use crate::error::{Error, Issue, Result};
use crate::json::{escape, locate_bad_numbers, parse_strict};
use crate::kinematics::construction::PlanKind;
pub use super::numbers::{
    MAX_ANGLE_DEG, MAX_ANSWER_BYTES, MAX_PLAN_MM, check_size, coordinate_issue, delta_issue,
    mu_issue,
};
use super::numbers::{
    bounded, issue, keep, number, parse_with_sense, positive, rounding_of_value,
    typed_rounding, value_issue,
};
pub use super::position::StatedPosition;
use serde_json::Value;

/// One thing the student gave.
#[derive(Clone, Debug, PartialEq)]
pub enum Given {
    /// A measured segment between two plan points, mm.
    Segment { from: String, to: String, mm: f64 },
    /// The direction of a segment, degrees counter-clockwise from +x.
    Angle { from: String, to: String, deg: f64 },
    /// A plan point's coordinates relative to the pole, mm.
    Point { name: String, at: [f64; 2] },
    /// A derived value: |v_X| or |a_X| (m/s, m/s²), or a link's ω or ε
    /// (signed, counter-clockwise positive).
    Value { quantity: Quantity, value: f64 },
}

#[derive(Clone, Debug, PartialEq)]
pub enum Quantity {
    /// |v_X| or |a_X| of a named point.
    Point(String),
    /// ω or ε of a link (by id).
    Rate(String),
    /// The relative (sliding) acceleration a^r of a prismatic pair, as
    /// written after `a^r_` (`B3B2`): the segment from the Coriolis
    /// point to the slider's point.
    Sliding(String),
    /// The Coriolis acceleration a^k of a prismatic pair (`a^k_B3B2`).
    Coriolis(String),
}

#[derive(Clone, Debug)]
pub struct Item {
    /// Where it came from (JSON pointer, or "svg: label b").
    pub pointer: String,
    /// As the student wrote it ("p_v b", "ω2").
    pub key: String,
    pub given: Given,
    /// How far the number as typed may be from what was read: half a unit
    /// of its last digit (a point: the radius of both coordinates'
    /// roundings), in the item's unit (mm, degrees, SI). 0 for what is
    /// drawn (an SVG or DXF answer), whose coordinates are the drawing's.
    pub rounding: f64,
}

/// A value the student states as read off the velocity plan an
/// acceleration plan was drawn on (`velocity.values`): judged against the
/// true value, and used, as stated, by every step that needs it.
#[derive(Clone, Debug, PartialEq)]
pub struct Stated {
    /// Where it came from (`/velocity/values/omega2`).
    pub pointer: String,
    /// As the student wrote it (`omega2`, `v_B3B2`).
    pub key: String,
    pub quantity: StatedQuantity,
    /// Signed (counter-clockwise positive) for ω; a magnitude for v_rel.
    pub value: f64,
    /// Half a unit of its last digit as written (SI).
    pub rounding: f64,
}

/// What a stated value is.
#[derive(Clone, Debug, PartialEq)]
pub enum StatedQuantity {
    /// ω of a link (its id).
    Omega(String),
    /// The relative sliding velocity of a point of one link on another,
    /// as written after `v_` (`B3B2`: B of link 3 on link 2), resolved on
    /// the scene's names when judged.
    Slide(String),
}

#[derive(Clone, Debug)]
pub struct Answer {
    pub plan: PlanKind,
    /// The position it is of, as stated (`"position"`, `"positions_from"`,
    /// `--position`), read in the study's numbering unless it says its own.
    pub position: StatedPosition,
    /// The student's scale (real units per mm).
    pub mu: f64,
    /// Pencil precision, mm.
    pub delta: f64,
    pub items: Vec<Item>,
    /// For an acceleration plan: the scale of the student's velocity plan,
    /// (m/s)/mm, whose measured ω give the normal components (their
    /// drafting error grows with it). `None`: the standard scale.
    pub mu_v: Option<f64>,
    /// For an acceleration plan: the values the student took from the
    /// velocity plan (ω of links, relative sliding velocities); each is
    /// judged against the true value, and the acceleration plan is
    /// replayed as built with them.
    pub stated: Vec<Stated>,
}

/// Split "p_v b", "p_v-b", "ab" into two names; without a separator, the
/// split must be the only one whose halves are both names in `known`.
pub fn split_segment(key: &str, known: &dyn Fn(&str) -> bool) -> Option<(String, String)> {
    let parts: Vec<&str> = key
        .split(|c: char| c.is_whitespace() || c == '-')
        .filter(|s| !s.is_empty())
        .collect();
    if parts.len() == 2 {
        return Some((parts[0].to_string(), parts[1].to_string()));
    }
    if parts.len() != 1 {
        return None;
    }
    let chars: Vec<(usize, char)> = key.char_indices().collect();
    let splits: Vec<(String, String)> = (1..chars.len())
        .map(|i| (key[..chars[i].0].to_string(), key[chars[i].0..].to_string()))
        .filter(|(a, b)| known(a) && known(b))
        .collect();
    if splits.len() == 1 {
        splits.into_iter().next()
    } else {
        None
    }
}

/// Parse "ω2", "omega2", "w2", "ε3", "eps3", "epsilon3" → (is ε, link id);
/// "v_B", "vB", "a_D" → (is a, point name); "v_B3B2", "a_B3B2" (a
/// point of one link relative to another, resolved on the scene);
/// "a^r_B3B2", "ar_B3B2" → ('r', …), "a^k_B3B2", "ak_B3B2" (or the lecture's capital a^K_B3B2) → ('k', …).
fn quantity(key: &str) -> Option<(char, String)> {
    for (prefix, kind) in [
        ("a^r_", 'r'),
        ("ar_", 'r'),
        ("a^k_", 'k'),
        ("ak_", 'k'),
        ("a^K_", 'k'),
        ("aK_", 'k'),
    ] {
        if let Some(rest) = key.strip_prefix(prefix)
            && rest.chars().next().is_some_and(|c| c.is_ascii_uppercase())
        {
            return Some((kind, rest.to_string()));
        }
    }
    for (prefix, kind) in [
        ("omega", 'w'),
        ("ω", 'w'),
        ("w", 'w'),
        ("epsilon", 'e'),
        ("eps", 'e'),
        ("ε", 'e'),
    ] {
        if let Some(rest) = key.strip_prefix(prefix) {
            let rest = rest.trim_start_matches('_');
            if !rest.is_empty() && rest.chars().all(|c| c.is_ascii_alphanumeric()) {
                return Some((kind, rest.to_string()));
            }
        }
    }
    for (prefix, kind) in [("v_", 'v'), ("a_", 'a'), ("v", 'v'), ("a", 'a')] {
        if let Some(rest) = key.strip_prefix(prefix)
            && rest.chars().next().is_some_and(|c| c.is_ascii_uppercase())
        {
            return Some((kind, rest.to_string()));
        }
    }
    None
}

/// A plan's name in the messages.
fn plan_name(p: PlanKind) -> &'static str {
    if p == PlanKind::Velocity {
        "velocity"
    } else {
        "acceleration"
    }
}

/// Read an answer JSON. Names are checked against the plan later; here the
/// file's own shape: known fields, numbers, positive lengths, μ present.
pub fn from_json(text: &str) -> Result<Answer> {
    check_size(text.len() as u64)?;
    let v = parse_strict(text).map_err(|e| Error::json(locate_bad_numbers(text).unwrap_or(e)))?;
    let mut issues = Vec::new();
    let Some(o) = v.as_object() else {
        return Err(Error::fields(vec![issue("", "an answer is a JSON object")]));
    };
    for k in o.keys() {
        if ![
            "plan", "position", "positions_from", "mu", "delta", "segments", "angles", "points",
            "values", "title", "velocity",
        ]
        .contains(&k.as_str())
        {
            issues.push(issue(format!("/{}", escape(k)), format!("unknown field \"{k}\" (allowed: plan, position, positions_from, mu, delta, segments, angles, points, values, velocity)")));
            // A photographed plan's marks (`grading::photo`, which reads
            // them into this answer: it is read there, not here).
            if k == "photo" {
                issues.push(issue("/photo", "a marks file of a photographed plan is read by check::photo::from_marks (as mechplan check and Study::check_answer read it), not as an answer's text"));
            }
        }
    }
    let plan = match o.get("plan").and_then(Value::as_str) {
        Some("velocity") => Some(PlanKind::Velocity),
        Some("acceleration") => Some(PlanKind::Acceleration),
        _ => {
            issues.push(issue(
                "/plan",
                "missing or wrong: \"velocity\" or \"acceleration\"",
            ));
            None
        }
    };
    let position = super::position::read(o, &mut issues);
    let mu = match o.get("mu") {
        None => {
            issues.push(issue(
                "/mu",
                "missing: the scale μ of your plan ((m/s)/mm or (m/s²)/mm)",
            ));
            None
        }
        Some(m) => positive(m, "/mu", "a scale must be positive", &mut issues)
            .filter(|&m| keep(mu_issue(m, "/mu"), &mut issues)),
    };
    let delta = match o.get("delta") {
        None => Some(0.5),
        Some(d) => positive(
            d,
            "/delta",
            "the pencil precision must be positive",
            &mut issues,
        )
        .filter(|&d| keep(delta_issue(d, "/delta"), &mut issues)),
    };
    let mut items = measured_items(o, &mut issues);
    items.extend(value_items(o, plan, &mut issues));
    // The velocity plan an acceleration plan was drawn from.
    let (mu_v, stated) = velocity_plan(o, plan, &mut issues);
    if items.is_empty() && issues.is_empty() {
        issues.push(issue(
            "",
            "the answer gives nothing to check: add segments, angles, points or values",
        ));
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    Ok(Answer {
        plan: plan.unwrap(),
        position: position.unwrap(),
        mu: mu.unwrap(),
        delta: delta.unwrap(),
        items,
        mu_v,
        stated,
    })
}

/// The entries of the answer's object `name` as (pointer, key, value);
/// none if it is missing, with an issue if it is not an object.
fn section(
    o: &serde_json::Map<String, Value>,
    name: &str,
    issues: &mut Vec<Issue>,
) -> Vec<(String, String, Value)> {
    match o.get(name) {
        None => Vec::new(),
        Some(Value::Object(m)) => m
            .iter()
            .map(|(k, v)| (format!("/{name}/{}", escape(k)), k.clone(), v.clone()))
            .collect(),
        Some(_) => {
            issues.push(issue(format!("/{name}"), "expected an object"));
            Vec::new()
        }
    }
}

/// What the student measured on the plan: the segments (mm, not
/// negative), the angles (degrees) and the points (mm from the pole).
fn measured_items(o: &serde_json::Map<String, Value>, issues: &mut Vec<Issue>) -> Vec<Item> {
    let mut items = Vec::new();
    let mut typed: Vec<[(f64, bool); 2]> = Vec::new();
    for (ptr, key, v) in section(o, "segments", issues) {
        let longest = |x: &str| {
            format!("{x} mm is longer than any sheet: a segment is at most {MAX_PLAN_MM} mm")
        };
        if let Some(mm) = bounded(&v, &ptr, MAX_PLAN_MM, longest, issues) {
            if mm < 0.0 {
                issues.push(issue(
                    &ptr,
                    format!("a measured length cannot be negative ({mm} mm)"),
                ));
                continue;
            }
            items.push(Item {
                pointer: ptr,
                key: key.clone(),
                given: Given::Segment {
                    from: key.clone(),
                    to: String::new(),
                    mm,
                },
                rounding: rounding_of_value(&v),
            });
        }
    }
    for (ptr, key, v) in section(o, "angles", issues) {
        let turns = |x: &str| {
            format!("{x}° is not a direction as written: give it in degrees from -{MAX_ANGLE_DEG} to {MAX_ANGLE_DEG}")
        };
        if let Some(deg) = bounded(&v, &ptr, MAX_ANGLE_DEG, turns, issues) {
            items.push(Item {
                pointer: ptr,
                key: key.clone(),
                given: Given::Angle {
                    from: key.clone(),
                    to: String::new(),
                    deg,
                },
                rounding: rounding_of_value(&v),
            });
        }
    }
    for (ptr, key, v) in section(o, "points", issues) {
        match v.as_array() {
            Some(a) if a.len() == 2 => {
                let mut coordinate = |k: usize| {
                    let at = format!("{ptr}/{k}");
                    number(&a[k], &at, issues)
                        .filter(|&x| keep(coordinate_issue(x, &at), issues))
                };
                let (x, y) = (coordinate(0), coordinate(1));
                if let (Some(x), Some(y)) = (x, y) {
                    typed.push([typed_rounding(&a[0]), typed_rounding(&a[1])]);
                    items.push(Item {
                        pointer: ptr,
                        key: key.clone(),
                        given: Given::Point {
                            name: key,
                            at: [x, y],
                        },
                        rounding: 0.0,
                    });
                }
            }
            _ => issues.push(issue(&ptr, "expected [x, y] in mm from the pole")),
        }
    }
    // A whole number among coordinates typed with decimals is one of
    // them with its zeros left off ("12" for 12.0): it is rounded as the
    // coarsest of them is; in an answer of whole numbers, to a millimetre.
    let coarsest = typed
        .iter()
        .flatten()
        .filter_map(|t| t.1.then_some(t.0))
        .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |m| m.max(r))));
    let points = items.iter_mut().filter(|i| matches!(i.given, Given::Point { .. }));
    for (it, [x, y]) in points.zip(&typed) {
        let of = |(r, decimal): (f64, bool)| if decimal { r } else { coarsest.unwrap_or(r) };
        it.rounding = of(*x).hypot(of(*y));
    }
    items
}

/// The derived values: a number, or a magnitude with its sense.
fn value_items(
    o: &serde_json::Map<String, Value>,
    plan: Option<PlanKind>,
    issues: &mut Vec<Issue>,
) -> Vec<Item> {
    let mut items = Vec::new();
    for (ptr, key, v) in section(o, "values", issues) {
        let value = match &v {
            Value::String(s) => match parse_with_sense(s) {
                Ok(x) => Some(x),
                Err(why) => {
                    issues.push(issue(&ptr, why));
                    continue;
                }
            },
            v => v.as_f64().filter(|x| x.is_finite()),
        };
        let Some(value) = value else {
            issues.push(issue(&ptr, "expected a number (signed: counter-clockwise positive) or \"1.2 cw\" / \"1.2 ccw\""));
            continue;
        };
        if let Some(i) = value_issue(value, &ptr) {
            issues.push(i);
            continue;
        }
        match value_item(plan, ptr, key, value) {
            Ok(it) => items.push(Item {
                rounding: rounding_of_value(&v),
                ..it
            }),
            Err(i) => issues.push(i),
        }
    }
    items
}

/// The value `key` (v_B, ω2 …) of the answer's `plan` as an item.
fn value_item(
    plan: Option<PlanKind>,
    ptr: String,
    key: String,
    value: f64,
) -> std::result::Result<Item, Issue> {
    // A quantity of the other plan is a slip of the file, not of the
    // plan: refuse it rather than read a_B as v_B.
    let kind_of = |c: char| match c {
        'w' | 'v' => PlanKind::Velocity,
        _ => PlanKind::Acceleration,
    };
    if let (Some(p), Some((c, _))) = (plan, quantity(&key))
        && kind_of(c) != p
    {
        return Err(issue(
            &ptr,
            format!(
                "\"{key}\" belongs to the {} plan, but this answer is the {} plan",
                plan_name(kind_of(c)),
                plan_name(p),
            ),
        ));
    }
    match quantity(&key) {
        Some(('w' | 'e', link)) => Ok(Item {
            pointer: ptr,
            key,
            given: Given::Value {
                quantity: Quantity::Rate(link),
                value,
            },
            rounding: 0.0,
        }),
        Some((c, name)) => {
            if value < 0.0 {
                return Err(issue(&ptr, "a magnitude cannot be negative"));
            }
            let quantity = match c {
                'r' => Quantity::Sliding(name),
                'k' => Quantity::Coriolis(name),
                _ => Quantity::Point(name),
            };
            Ok(Item {
                pointer: ptr,
                key,
                given: Given::Value { quantity, value },
                rounding: 0.0,
            })
        }
        None => Err(issue(
            &ptr,
            format!("unknown quantity \"{key}\": use v_B, a_D, ω2 (omega2), ε3 (eps3), v_B3B2, a^r_B3B2, a^k_B3B2"),
        )),
    }
}

/// The velocity plan an acceleration answer was drawn from: its scale
/// and the values taken from it.
fn velocity_plan(
    o: &serde_json::Map<String, Value>,
    plan: Option<PlanKind>,
    issues: &mut Vec<Issue>,
) -> (Option<f64>, Vec<Stated>) {
    let (mut mu_v, mut stated) = (None, Vec::new());
    match o.get("velocity") {
        None => {}
        Some(_) if plan == Some(PlanKind::Velocity) => issues.push(issue(
            "/velocity",
            "a velocity plan has no velocity plan of its own: give \"velocity\" with an acceleration plan",
        )),
        Some(Value::Object(vo)) => {
            for k in vo.keys() {
                if !["mu", "values"].contains(&k.as_str()) {
                    issues.push(issue(
                        format!("/velocity/{}", escape(k)),
                        format!("unknown field \"{k}\" (allowed: mu, values)"),
                    ));
                }
            }
            if let Some(m) = vo.get("mu") {
                mu_v = positive(m, "/velocity/mu", "a scale must be positive", issues)
                    .filter(|&m| keep(mu_issue(m, "/velocity/mu"), issues));
            }
            match vo.get("values") {
                None => {}
                Some(Value::Object(vals)) => stated = velocity_values(vals, issues),
                Some(_) => issues.push(issue("/velocity/values", "expected an object")),
            }
        }
        Some(_) => issues.push(issue(
            "/velocity",
            "expected an object: { \"mu\": the velocity plan's scale, \"values\": { \"omega2\": … } }",
        )),
    }
    (mu_v, stated)
}

/// The values the student took from the velocity plan: the links' ω
/// (signed) and relative sliding velocities (`v_B3B2`, magnitudes).
fn velocity_values(vals: &serde_json::Map<String, Value>, issues: &mut Vec<Issue>) -> Vec<Stated> {
    let mut stated: Vec<Stated> = Vec::new();
    for (k, v) in vals {
        let ptr = format!("/velocity/values/{}", escape(k));
        let value = match v {
            Value::String(s) => parse_with_sense(s)
                .map_err(|w| issues.push(issue(&ptr, w)))
                .ok(),
            v => number(v, &ptr, issues),
        }
        .filter(|&x| keep(value_issue(x, &ptr), issues));
        let quantity = match quantity(k) {
            Some(('w', link)) => StatedQuantity::Omega(link),
            Some(('v', rel)) => StatedQuantity::Slide(rel),
            _ => {
                issues.push(issue(
                    &ptr,
                    format!("\"{k}\": the velocity plan's values here are the links' ω (omega2, ω3) and relative sliding velocities (v_B3B2)"),
                ));
                continue;
            }
        };
        let Some(value) = value else { continue };
        if let Some(first) = stated.iter().find(|s| s.quantity == quantity) {
            issues.push(issue(
                &ptr,
                format!("{k} is given twice (also {}); give each once", first.pointer),
            ));
            continue;
        }
        if matches!(quantity, StatedQuantity::Slide(_)) && value < 0.0 {
            issues.push(issue(&ptr, "a relative sliding velocity is given as a magnitude: it cannot be negative"));
            continue;
        }
        stated.push(Stated {
            pointer: ptr,
            key: k.clone(),
            quantity,
            value,
            rounding: rounding_of_value(v),
        });
    }
    stated
}

