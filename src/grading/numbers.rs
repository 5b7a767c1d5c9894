//! An answer's numbers as written: finite, within what a drawing can
//! hold (the limits below), and how far each may be from what was read
//! before it was rounded to the digits typed.

use crate::error::{Error, Issue, Result};
use serde_json::Value;

/// Half a unit of the last digit of a number as written (`"3.40"`,
/// `"-12"`, `"1.5e-3"`, the number of `"1.07 cw"`): how far it may be from
/// what was read before it was rounded to those digits.
pub fn rounding_of(text: &str) -> f64 {
    let t = text.trim().trim_start_matches(['-', '+']);
    let (mantissa, exponent) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().unwrap_or(0)),
        None => (t, 0),
    };
    let decimals = mantissa.find('.').map_or(0, |i| mantissa.len() - i - 1) as i32;
    0.5 * 10f64.powi(exponent - decimals)
}

/// [`rounding_of`] a JSON number or a number with its sense.
pub(super) fn rounding_of_value(v: &Value) -> f64 {
    match v {
        Value::Number(n) => rounding_of(&n.to_string()),
        Value::String(s) => {
            let lower = s.trim().to_lowercase();
            let n = lower
                .strip_suffix("ccw")
                .or_else(|| lower.strip_suffix("cw"))
                .unwrap_or(&lower);
            rounding_of(n)
        }
        _ => 0.0,
    }
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

pub(super) fn issue(pointer: impl Into<String>, message: impl Into<String>) -> Issue {
    Issue {
        pointer: pointer.into(),
        message: message.into(),
    }
}

pub(super) fn number(v: &Value, at: &str, issues: &mut Vec<Issue>) -> Option<f64> {
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
pub(super) fn bounded(
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
pub(super) fn positive(v: &Value, at: &str, why: &str, issues: &mut Vec<Issue>) -> Option<f64> {
    number(v, at, issues).filter(|&x| {
        let ok = x > 0.0;
        if !ok {
            issues.push(issue(at, why));
        }
        ok
    })
}

/// Record `problem` if there is one; whether there was none.
pub(super) fn keep(problem: Option<Issue>, issues: &mut Vec<Issue>) -> bool {
    match problem {
        Some(i) => {
            issues.push(i);
            false
        }
        None => true,
    }
}

/// The rounding of a coordinate as typed ([`rounding_of`]), and whether
/// it was typed with a decimal point or an exponent (not a whole number).
pub(super) fn typed_rounding(v: &Value) -> (f64, bool) {
    let whole = v.as_i64().is_some() || v.as_u64().is_some();
    (rounding_of_value(v), !whole)
}

/// The issue of a value `x` (SI) at `pointer`, if it is absurd.
pub(super) fn value_issue(x: f64, pointer: &str) -> Option<Issue> {
    (x.abs() > MAX_VALUE).then(|| {
        issue(
            pointer,
            format!("{} is absurd: a value is at most {MAX_VALUE:e} (m/s, m/s², rad/s, rad/s²)", shown(x)),
        )
    })
}

/// "1.2 cw" → −1.2, "1.2 ccw" → 1.2, "-0.4" → −0.4, in any case ("CW");
/// a sign and a sense together ("-3.40 cw") contradict each other and are
/// refused, never read one way or the other.
pub(super) fn parse_with_sense(s: &str) -> std::result::Result<f64, String> {
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
