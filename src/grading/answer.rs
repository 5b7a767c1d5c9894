//! The student's answer: a JSON file (format in `docs/check.md`) or an SVG
//! drawn in a vector editor, read into items to check.

use crate::error::{Error, Issue, Result};
use crate::json::{escape, locate_bad_numbers, parse_strict};
use crate::kinematics::construction::PlanKind;
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
}

#[derive(Clone, Debug)]
pub struct Item {
    /// Where it came from (JSON pointer, or "svg: label b").
    pub pointer: String,
    /// As the student wrote it ("p_v b", "ω2").
    pub key: String,
    pub given: Given,
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
    /// For an acceleration plan: the angular velocities the student took
    /// from the velocity plan (link id, signed ω); the acceleration plan is
    /// checked as built with them.
    pub omegas: Vec<(String, f64)>,
}

/// The largest answer file read, JSON or SVG (8 MiB): a hand-drawn plan
/// is a few kilobytes; a file beyond this is refused before it is read.
pub const MAX_ANSWER_BYTES: usize = 8 << 20;

/// The farthest a plan point may be from the pole, and the longest
/// segment, mm: no sheet is 10 m across (A0 is 1.19 m); a larger number is
/// a slip of the file, not a drawing.
pub const MAX_PLAN_MM: f64 = 10_000.0;

/// The coarsest pencil precision δ, mm: a δ of centimetres would accept
/// any plan.
pub const MAX_DELTA_MM: f64 = 10.0;

/// The scales μ a plan may have, (m/s)/mm or (m/s²)/mm: outside this no
/// drawing is a plan of a real mechanism (at 10⁻⁶, 1 m/s is 1 km long).
pub const MU_RANGE: (f64, f64) = (1e-6, 1e6);

/// The largest direction written, degrees either way (two turns).
pub const MAX_ANGLE_DEG: f64 = 720.0;

/// The largest value written (SI units: m/s, m/s², rad/s, rad/s²): a
/// thousand times any machine's, so μ in the wrong units is still
/// diagnosed.
pub const MAX_VALUE: f64 = 1e12;

/// The issue of a scale `mu` at `pointer`, if it is not one a plan has.
pub fn mu_issue(mu: f64, pointer: &str) -> Option<Issue> {
    let (lo, hi) = MU_RANGE;
    (!(mu.is_finite() && (lo..=hi).contains(&mu))).then(|| {
        issue(
            pointer,
            format!(
                "μ = {} is not a plan's scale: μ is a number of (m/s)/mm or (m/s²)/mm from {lo:e} to {hi:e}",
                shown(mu)
            ),
        )
    })
}

/// The issue of a pencil precision `delta` (mm) at `pointer`, if it is
/// not one.
pub fn delta_issue(delta: f64, pointer: &str) -> Option<Issue> {
    (!(delta.is_finite() && delta > 0.0 && delta <= MAX_DELTA_MM)).then(|| {
        issue(
            pointer,
            format!(
                "δ = {} mm is not a pencil's precision: it is more than 0 and at most {MAX_DELTA_MM} mm",
                shown(delta)
            ),
        )
    })
}

/// The issue of a plan coordinate `x` (mm) at `pointer`, if it is off
/// any sheet.
pub fn coordinate_issue(x: f64, pointer: &str) -> Option<Issue> {
    (!(x.is_finite() && x.abs() <= MAX_PLAN_MM)).then(|| {
        issue(
            pointer,
            format!(
                "{} mm is off any sheet: a plan point is at most {MAX_PLAN_MM} mm from the pole",
                shown(x)
            ),
        )
    })
}

/// The refusal of an answer of `bytes` bytes, if it is too large.
pub fn check_size(bytes: u64) -> Result<()> {
    if bytes > MAX_ANSWER_BYTES as u64 {
        return Err(Error::fields(vec![issue(
            "",
            format!(
                "the answer file has {bytes} bytes; an answer may have at most {MAX_ANSWER_BYTES} (8 MiB)"
            ),
        )]));
    }
    Ok(())
}

fn issue(pointer: impl Into<String>, message: impl Into<String>) -> Issue {
    Issue {
        pointer: pointer.into(),
        message: message.into(),
    }
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
/// "v_B", "vB", "a_D" → (is a, point name).
fn quantity(key: &str) -> Option<(char, String)> {
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

fn number(v: &Value, at: &str, issues: &mut Vec<Issue>) -> Option<f64> {
    match v.as_f64() {
        Some(x) if x.is_finite() => Some(x),
        _ => {
            let found = match v {
                Value::String(s) => format!("the text \"{s}\""),
                Value::Null => "null".into(),
                Value::Bool(b) => b.to_string(),
                Value::Array(_) => "a list".into(),
                Value::Object(_) => "an object".into(),
                Value::Number(n) => n.to_string(),
            };
            issues.push(issue(
                at,
                format!("expected a finite number, found {found}"),
            ));
            None
        }
    }
}

/// A finite number of at most `limit` either way; beyond it the issue
/// `why` says of the number as written.
fn bounded(
    v: &Value,
    at: &str,
    limit: f64,
    why: impl Fn(&str) -> String,
    issues: &mut Vec<Issue>,
) -> Option<f64> {
    let x = number(v, at, issues)?;
    if x.abs() > limit {
        issues.push(issue(at, why(&shown(x))));
        return None;
    }
    Some(x)
}

/// A number as a message shows it: `1e300`, not its 301 digits.
fn shown(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A finite number that must be positive (`why` says so when it is not).
fn positive(v: &Value, at: &str, why: &str, issues: &mut Vec<Issue>) -> Option<f64> {
    number(v, at, issues).filter(|&x| {
        let ok = x > 0.0;
        if !ok {
            issues.push(issue(at, why));
        }
        ok
    })
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
    let (mu_v, omegas) = velocity_plan(o, plan, &mut issues);
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
        omegas,
    })
}

/// Record `problem` if there is one; whether there was none.
fn keep(problem: Option<Issue>, issues: &mut Vec<Issue>) -> bool {
    match problem {
        Some(i) => {
            issues.push(i);
            false
        }
        None => true,
    }
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
                    items.push(Item {
                        pointer: ptr,
                        key: key.clone(),
                        given: Given::Point {
                            name: key,
                            at: [x, y],
                        },
                    });
                }
            }
            _ => issues.push(issue(&ptr, "expected [x, y] in mm from the pole")),
        }
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
            Ok(it) => items.push(it),
            Err(i) => issues.push(i),
        }
    }
    items
}

/// The issue of a value `x` (SI) at `pointer`, if it is absurd.
fn value_issue(x: f64, pointer: &str) -> Option<Issue> {
    (x.abs() > MAX_VALUE).then(|| {
        issue(
            pointer,
            format!("{} is absurd: a value is at most {MAX_VALUE:e} (m/s, m/s², rad/s, rad/s²)", shown(x)),
        )
    })
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
        }),
        Some((_, point)) => {
            if value < 0.0 {
                return Err(issue(&ptr, "a magnitude cannot be negative"));
            }
            Ok(Item {
                pointer: ptr,
                key,
                given: Given::Value {
                    quantity: Quantity::Point(point),
                    value,
                },
            })
        }
        None => Err(issue(
            &ptr,
            format!("unknown quantity \"{key}\": use v_B, a_D, ω2 (omega2), ε3 (eps3)"),
        )),
    }
}

/// The velocity plan an acceleration answer was drawn from: its scale
/// and the ω taken from it.
fn velocity_plan(
    o: &serde_json::Map<String, Value>,
    plan: Option<PlanKind>,
    issues: &mut Vec<Issue>,
) -> (Option<f64>, Vec<(String, f64)>) {
    let (mut mu_v, mut omegas) = (None, Vec::new());
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
                Some(Value::Object(vals)) => omegas = velocity_values(vals, issues),
                Some(_) => issues.push(issue("/velocity/values", "expected an object")),
            }
        }
        Some(_) => issues.push(issue(
            "/velocity",
            "expected an object: { \"mu\": the velocity plan's scale, \"values\": { \"omega2\": … } }",
        )),
    }
    (mu_v, omegas)
}

/// The ω (link id, signed) the student took from the velocity plan.
fn velocity_values(
    vals: &serde_json::Map<String, Value>,
    issues: &mut Vec<Issue>,
) -> Vec<(String, f64)> {
    let mut omegas: Vec<(String, f64)> = Vec::new();
    let mut pointers: Vec<String> = Vec::new();
    for (k, v) in vals {
        let ptr = format!("/velocity/values/{}", escape(k));
        let value = match v {
            Value::String(s) => parse_with_sense(s)
                .map_err(|w| issues.push(issue(&ptr, w)))
                .ok(),
            v => number(v, &ptr, issues),
        }
        .filter(|&x| keep(value_issue(x, &ptr), issues));
        match (quantity(k), value) {
            (Some(('w', link)), Some(_)) if omegas.iter().any(|(l, _)| *l == link) => {
                let first = omegas.iter().position(|(l, _)| *l == link).unwrap_or(0);
                issues.push(issue(
                    &ptr,
                    format!(
                        "ω{link} is given twice (also {}); give each once",
                        pointers[first]
                    ),
                ));
            }
            (Some(('w', link)), Some(x)) => {
                omegas.push((link, x));
                pointers.push(ptr);
            }
            (_, None) => {}
            _ => issues.push(issue(
                &ptr,
                format!("\"{k}\": the velocity plan's values here are the links' ω (omega2, ω3)"),
            )),
        }
    }
    omegas
}

/// "1.2 cw" → −1.2, "1.2 ccw" → 1.2, "-0.4" → −0.4, in any case ("CW");
/// a sign and a sense together ("-3.40 cw") contradict each other and are
/// refused, never read one way or the other.
fn parse_with_sense(s: &str) -> std::result::Result<f64, String> {
    let t = s.trim();
    let lower = t.to_lowercase();
    let (num, sense) = if let Some(n) = lower.strip_suffix("ccw") {
        (n.to_string(), Some(1.0))
    } else if let Some(n) = lower.strip_suffix("cw") {
        (n.to_string(), Some(-1.0))
    } else {
        (lower.clone(), None)
    };
    let num = num.trim();
    let bad = || {
        format!(
            "cannot read \"{t}\": write a number (counter-clockwise positive) or a magnitude with its sense, \"1.2 cw\" / \"1.2 ccw\""
        )
    };
    let x: f64 = num.parse().map_err(|_| bad())?;
    if !x.is_finite() {
        return Err(bad());
    }
    match sense {
        None => Ok(x),
        Some(_) if num.starts_with(['-', '+']) => Err(format!(
            "\"{t}\" gives both a sign and a sense of rotation: write \"{} {}\" or the signed number alone",
            num.trim_start_matches(['-', '+']),
            if lower.ends_with("ccw") { "ccw" } else { "cw" }
        )),
        Some(sign) => Ok(x * sign),
    }
}

