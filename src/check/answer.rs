//! The student's answer: a JSON file (format in `docs/check.md`) or an SVG
//! drawn in a vector editor, read into items to check.

use crate::construction::PlanKind;
use crate::error::{Error, Issue, Result};
use crate::json::{escape, parse_strict};
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
    /// 1-based position of the scene's positions.
    pub position: usize,
    /// The student's scale (real units per mm).
    pub mu: f64,
    /// Pencil precision, mm.
    pub delta: f64,
    pub items: Vec<Item>,
}

/// The largest answer file read, JSON or SVG (8 MiB): a hand-drawn plan
/// is a few kilobytes; a file beyond this is refused before it is read.
pub const MAX_ANSWER_BYTES: usize = 8 << 20;

/// The refusal of an answer of `bytes` bytes, if it is too large.
pub fn check_size(bytes: u64) -> Result<()> {
    if bytes > MAX_ANSWER_BYTES as u64 {
        return Err(Error::Scene(vec![issue(
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
            issues.push(issue(at, "expected a finite number"));
            None
        }
    }
}

/// Read an answer JSON. Names are checked against the plan later; here the
/// file's own shape: known fields, numbers, positive lengths, μ present.
pub fn from_json(text: &str) -> Result<Answer> {
    check_size(text.len() as u64)?;
    let v = parse_strict(text).map_err(Error::Json)?;
    let mut issues = Vec::new();
    let Some(o) = v.as_object() else {
        return Err(Error::Scene(vec![issue("", "an answer is a JSON object")]));
    };
    for k in o.keys() {
        if ![
            "plan", "position", "mu", "delta", "segments", "angles", "points", "values", "title",
        ]
        .contains(&k.as_str())
        {
            issues.push(issue(format!("/{}", escape(k)), format!("unknown field \"{k}\" (allowed: plan, position, mu, delta, segments, angles, points, values)")));
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
    let position = match o.get("position") {
        None => Some(1),
        Some(p) => match p.as_u64() {
            Some(n) if n >= 1 => Some(n as usize),
            _ => {
                issues.push(issue("/position", "expected a position number from 1"));
                None
            }
        },
    };
    let mu = match o.get("mu") {
        None => {
            issues.push(issue(
                "/mu",
                "missing: the scale μ of your plan ((m/s)/mm or (m/s²)/mm)",
            ));
            None
        }
        Some(m) => number(m, "/mu", &mut issues).filter(|&m| {
            let ok = m > 0.0;
            if !ok {
                issues.push(issue("/mu", "a scale must be positive"));
            }
            ok
        }),
    };
    let delta = match o.get("delta") {
        None => Some(0.5),
        Some(d) => number(d, "/delta", &mut issues).filter(|&d| {
            let ok = d > 0.0;
            if !ok {
                issues.push(issue("/delta", "the pencil precision must be positive"));
            }
            ok
        }),
    };
    let mut items = Vec::new();
    let section = |name: &str, issues: &mut Vec<Issue>| -> Vec<(String, String, Value)> {
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
    };
    for (ptr, key, v) in section("segments", &mut issues) {
        if let Some(mm) = number(&v, &ptr, &mut issues) {
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
    for (ptr, key, v) in section("angles", &mut issues) {
        if let Some(deg) = number(&v, &ptr, &mut issues) {
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
    for (ptr, key, v) in section("points", &mut issues) {
        match v.as_array() {
            Some(a) if a.len() == 2 => {
                let (x, y) = (
                    number(&a[0], &format!("{ptr}/0"), &mut issues),
                    number(&a[1], &format!("{ptr}/1"), &mut issues),
                );
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
    for (ptr, key, v) in section("values", &mut issues) {
        let value = match &v {
            Value::String(s) => parse_with_sense(s),
            v => v.as_f64().filter(|x| x.is_finite()),
        };
        let Some(value) = value else {
            issues.push(issue(&ptr, "expected a number (signed: counter-clockwise positive) or \"1.2 cw\" / \"1.2 ccw\""));
            continue;
        };
        match quantity(&key) {
            Some(('w' | 'e', link)) => items.push(Item {
                pointer: ptr,
                key,
                given: Given::Value {
                    quantity: Quantity::Rate(link),
                    value,
                },
            }),
            Some((_, point)) => {
                if value < 0.0 {
                    issues.push(issue(&ptr, "a magnitude cannot be negative"));
                    continue;
                }
                items.push(Item {
                    pointer: ptr,
                    key,
                    given: Given::Value {
                        quantity: Quantity::Point(point),
                        value,
                    },
                })
            }
            None => issues.push(issue(
                &ptr,
                format!("unknown quantity \"{key}\": use v_B, a_D, ω2 (omega2), ε3 (eps3)"),
            )),
        }
    }
    if items.is_empty() && issues.is_empty() {
        issues.push(issue(
            "",
            "the answer gives nothing to check: add segments, angles, points or values",
        ));
    }
    if !issues.is_empty() {
        return Err(Error::Scene(issues));
    }
    Ok(Answer {
        plan: plan.unwrap(),
        position: position.unwrap(),
        mu: mu.unwrap(),
        delta: delta.unwrap(),
        items,
    })
}

/// "1.2 cw" → −1.2, "1.2 ccw" → 1.2, "-0.4" → −0.4.
fn parse_with_sense(s: &str) -> Option<f64> {
    let s = s.trim();
    let (num, sign) = if let Some(n) = s.strip_suffix("ccw") {
        (n, 1.0)
    } else if let Some(n) = s.strip_suffix("cw") {
        (n, -1.0)
    } else {
        (s, 1.0)
    };
    let x: f64 = num.trim().parse().ok()?;
    x.is_finite().then_some(x * sign)
}
