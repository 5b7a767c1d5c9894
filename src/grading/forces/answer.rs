//! Reading a student's force plan: a JSON answer (`"plan": "force"`) or
//! a drawing from a vector editor that states μ_F.

use crate::error::{Error, Issue, Result};
use crate::json::{locate_bad_numbers, parse_strict};
use crate::grading::arrows;
use serde_json::{Map, Value};

/// A student's force plan.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceAnswer {
    /// The position it is of, as stated (`"position"`, `"positions_from"`,
    /// `--position`).
    pub position: crate::grading::answer::StatedPosition,
    /// The links of the plan (a group's, or the input link).
    pub links: Vec<String>,
    /// μ_F, N/mm.
    pub mu: f64,
    /// Pencil precision δ, mm.
    pub delta: f64,
    /// μ_l of the student's drawing of the mechanism (m/mm): the arms of
    /// the moment equations were measured on it.
    pub mu_l: Option<f64>,
    /// (JSON pointer, force key, given).
    pub segments: Vec<(String, String, f64)>,
    pub angles: Vec<(String, String, f64)>,
    pub values: Vec<(String, String, f64)>,
}

pub(super) fn issue(at: &str, msg: impl Into<String>) -> Issue {
    Issue {
        pointer: at.to_string(),
        message: msg.into(),
    }
}

/// Whether an answer's text is a force plan's (`"plan": "force"`).
pub fn is_force_answer(text: &str) -> bool {
    serde_json::from_str::<Value>(text)
        .ok()
        .is_some_and(|v| v.get("plan").and_then(Value::as_str) == Some("force"))
}

/// Read a force-plan answer, every problem with its JSON pointer.
pub fn from_json(text: &str) -> Result<ForceAnswer> {
    crate::grading::answer::check_size(text.len() as u64)?;
    let v = parse_strict(text).map_err(|e| Error::json(locate_bad_numbers(text).unwrap_or(e)))?;
    let mut issues = Vec::new();
    let Some(o) = v.as_object() else {
        return Err(Error::fields(vec![issue("", "an answer is a JSON object")]));
    };
    const FIELDS: [&str; 11] = [
        "plan", "position", "positions_from", "links", "mu", "delta", "mu_l", "segments",
        "angles", "values", "title",
    ];
    for k in o.keys() {
        if !FIELDS.contains(&k.as_str()) {
            issues.push(issue(
                &format!("/{k}"),
                format!("unknown field \"{k}\" (allowed: {})", FIELDS.join(", ")),
            ));
        }
    }
    let position = crate::grading::position::read(o, &mut issues).unwrap_or_default();
    let links = links(o, &mut issues);
    let mu = positive(o, "mu", &mut issues).filter(|&m| {
        // A scale no drawing has (a subnormal, 10³⁰⁰ N/mm) makes every
        // segment nothing or infinite: refused, never judged.
        let sane = (1e-6..=1e9).contains(&m);
        if !sane {
            issues.push(issue(
                "/mu",
                format!("μ_F = {m} N/mm draws no plan: a scale between 1e-6 and 1e9 N/mm"),
            ));
        }
        sane
    });
    if !o.contains_key("mu") {
        issues.push(issue(
            "/mu",
            "missing: the scale μ_F of your force plan (N/mm)",
        ));
    }
    let delta = positive(o, "delta", &mut issues)
        .filter(|&d| {
            let bad = super::super::answer::delta_issue(d, "/delta");
            let ok = bad.is_none();
            issues.extend(bad);
            ok
        })
        .unwrap_or(0.5);
    let mu_l = positive(o, "mu_l", &mut issues);
    let segments = table(o, "segments", &mut issues);
    let angles = table(o, "angles", &mut issues);
    let values = table(o, "values", &mut issues);
    for (at, _, x) in &segments {
        if *x < 0.0 {
            issues.push(issue(at, "a segment's length is not negative"));
        }
    }
    if segments.is_empty() && angles.is_empty() && values.is_empty() {
        issues.push(issue(
            "",
            "nothing to check: give segments (mm), angles (degrees) or values (N, N·m)",
        ));
    }
    if !issues.is_empty() {
        return Err(Error::fields(issues));
    }
    Ok(ForceAnswer {
        position,
        links,
        mu: mu.expect("checked"),
        delta,
        mu_l,
        segments,
        angles,
        values,
    })
}

/// The answer's field `k`, a positive number when given.
fn positive(o: &Map<String, Value>, k: &str, issues: &mut Vec<Issue>) -> Option<f64> {
    let x = o.get(k)?;
    match x.as_f64() {
        Some(x) if x.is_finite() && x > 0.0 => Some(x),
        _ => {
            issues.push(issue(&format!("/{k}"), "expected a positive number"));
            None
        }
    }
}

/// The ids of the plan's links.
fn links(o: &Map<String, Value>, issues: &mut Vec<Issue>) -> Vec<String> {
    match o.get("links").and_then(Value::as_array) {
        Some(a) if !a.is_empty() && a.iter().all(Value::is_string) => a
            .iter()
            .map(|x| x.as_str().unwrap_or_default().to_string())
            .collect(),
        _ => {
            issues.push(issue(
                "/links",
                "missing or wrong: the ids of the plan's links, as in the scene (a group's two, or the input link's)",
            ));
            Vec::new()
        }
    }
}

/// The answer's object `k` of force names to numbers, as (pointer, name,
/// number).
fn table(o: &Map<String, Value>, k: &str, issues: &mut Vec<Issue>) -> Vec<(String, String, f64)> {
    let Some(x) = o.get(k) else { return Vec::new() };
    let Some(t) = x.as_object() else {
        issues.push(issue(
            &format!("/{k}"),
            "expected an object of force names to numbers",
        ));
        return Vec::new();
    };
    t.iter()
        .filter_map(|(name, x)| {
            let at = format!("/{k}/{name}");
            match x.as_f64().filter(|x| x.is_finite()) {
                Some(x) => Some((at, name.clone(), x)),
                None => {
                    issues.push(issue(&at, "expected a finite number"));
                    None
                }
            }
        })
        .collect()
}

/// Whether an SVG answer is a force plan: it states μ_F ("μ_F = 2 N/mm").
pub fn is_force_svg(text: &str) -> bool {
    crate::grading::read::drawing(text)
        .ok()
        .is_some_and(|d| crate::grading::drawing::stated_mu(&d.labels, "_F").is_some())
}

/// How far from the middle of its vector a force's label may be, mm.
const SNAP_MM: f64 = 10.0;

/// A force plan drawn in a vector editor: its vectors as lines (a path or
/// a line element each, or a path's segments), each labelled with the
/// force's name (`R_34`, `R34`, `Φ4` …) near its middle, and the scale
/// written on it ("μ_F = 2 N/mm"; `mu` overrides). Read: each label's
/// nearest segment (by its middle, within 10 mm) gives the force's length;
/// the plan is the one whose forces the labels name (no `links` needed).
pub fn from_svg(
    text: &str,
    mu: Option<f64>,
    delta: f64,
    position: crate::grading::answer::StatedPosition,
) -> Result<ForceAnswer> {
    // A problem of the drawing as a whole: no pointer ("svg" would be
    // read as the option --svg); the file is named by the caller.
    let bad = |m: String| {
        Error::fields(vec![Issue {
            pointer: String::new(),
            message: m,
        }])
    };
    let d = crate::grading::read::drawing(text)?;
    let Some(mu) = mu.or_else(|| crate::grading::drawing::stated_mu(&d.labels, "_F")) else {
        return Err(bad(
            "no scale: write \"μ_F = … N/mm\" on the drawing or give --mu".into(),
        ));
    };
    if !(mu.is_finite() && (1e-6..=1e9).contains(&mu)) {
        return Err(bad(format!(
            "μ_F = {mu} N/mm draws no plan: a scale between 1e-6 and 1e9 N/mm"
        )));
    }
    // (each label looks among every segment, each triangle near its
    // corner: a hostile file's thousands are refused, not ground through)
    let most = crate::grading::arrows::MAX_HEADS;
    if d.heads.len() > most || d.labels.len() > most {
        return Err(bad(format!(
            "the drawing has {} arrowheads and {} labels: a force plan has tens, at most {most} of each are read",
            d.heads.len(),
            d.labels.len()
        )));
    }
    // Each vector: a segment of a line that draws no arrowhead, with
    // its sense when its arrowhead tells it.
    let mut skip = vec![false; d.lines.len()];
    for l in crate::grading::arrows::head_lines(&d.heads) {
        if let Some(x) = skip.get_mut(l) {
            *x = true;
        }
    }
    let drawn: Vec<(kurbo::Point, kurbo::Point, usize, usize)> = d
        .lines
        .iter()
        .enumerate()
        .filter(|(l, _)| !skip[*l])
        .flat_map(|(l, ps)| ps.windows(2).enumerate().map(move |(k, w)| (w[0], w[1], l, k)))
        .filter(|(a, b, ..)| (*b - *a).hypot() > 0.0)
        .collect();
    let senses = arrows::senses(&d.heads, &d.lines, &drawn);
    let segments: Vec<(kurbo::Point, kurbo::Point, Option<bool>)> = drawn
        .iter()
        .zip(senses)
        .map(|(&(a, b, ..), s)| (a, b, s))
        .collect();
    let (mut items, mut angles) = (Vec::new(), Vec::new());
    for (name, at) in &d.labels {
        if name.is_empty() || name.contains('=') {
            continue;
        }
        let nearest = segments
            .iter()
            .map(|&(a, b, sense)| ((a.midpoint(b) - *at).hypot(), a, b, sense))
            .filter(|(dist, ..)| dist.is_finite() && *dist <= SNAP_MM)
            .min_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, a, b, sense)) = nearest {
            let at = format!("{}: label {name}", d.kind);
            items.push((at.clone(), name.clone(), (b - a).hypot()));
            // The arrowhead's end is the vector's head.
            match sense {
                Some(true) => angles.push((at, name.clone(), arrows::direction(a, b))),
                Some(false) => angles.push((at, name.clone(), arrows::direction(b, a))),
                None => {}
            }
        }
    }
    if items.is_empty() {
        return Err(bad(
            "no force's label next to the middle of a line: label each vector with its force's name (R_34 …)".into(),
        ));
    }
    Ok(ForceAnswer {
        position,
        links: Vec::new(),
        mu,
        delta,
        mu_l: None,
        segments: items,
        angles,
        values: Vec::new(),
    })
}
