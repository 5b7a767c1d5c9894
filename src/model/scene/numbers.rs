//! Numbers: finite and within [`MAX_MAGNITUDE`], angles reduced exactly
//! in the file's unit with their rounding, and the field of each
//! non-finite number the JSON parser stops at.

use super::reader::{Reader, kind, ptr};
use super::{MAX_MAGNITUDE, U};
use serde_json::Value;

impl Reader {
    pub(super) fn number(&mut self, v: &Value, at: &str) -> Option<f64> {
        match v.as_f64() {
            Some(x) if x.is_finite() && x.abs() <= MAX_MAGNITUDE => Some(x),
            Some(x) if x.is_finite() => {
                self.err(at, format!("{x:e} is too large (|x| ≤ {MAX_MAGNITUDE:e}): its square would not be a finite number"));
                None
            }
            Some(_) => {
                self.err(at, "non-finite number");
                None
            }
            None => {
                self.err(at, format!("expected a number, found {}", kind(v)));
                None
            }
        }
    }

    /// An angle of the file in radians, reduced once, exactly, in the unit
    /// it was written in (whole turns off: `x % 360` is exact in degrees),
    /// before any route sees it: 1e6 turns plus 30° is 30°, for both.
    pub(super) fn angle(&self, x: f64) -> f64 {
        if self.ang == 1.0 {
            x % std::f64::consts::TAU
        } else {
            (x % 360.0) * self.ang
        }
    }

    /// The rounding of an angle written `x` in the file's unit, in rad:
    /// the decimal's own (half an ulp of what is written: of all its turns
    /// in radians, of the reduced angle in degrees, whose reduction is
    /// exact), and the conversion's.
    pub(super) fn angle_rounding(&self, x: f64) -> f64 {
        let written = if self.ang == 1.0 { x } else { x % 360.0 };
        2.0 * U * written.abs() * self.ang + U * self.angle(x).abs()
    }
}

/// serde_json stops at `NaN`, `Infinity` or `1e999` with only a line and
/// column, but the contract names the field. Put a marker string in place of
/// each such number and read the text again: where a marker lands in the tree
/// is the field's JSON pointer. `None` when the text has no such number, more
/// than a few, or other syntax errors besides (the plain message then stands).
pub(super) fn locate_bad_numbers(text: &str) -> Option<Vec<String>> {
    const MARK: &str = r"\u0001mechplan-bad-number-";
    let mut text = text.to_owned();
    let mut found = Vec::new();
    let value = loop {
        let e = match serde_json::from_str::<Value>(&text) {
            Ok(v) => break v,
            Err(e) if found.len() < 32 => e,
            Err(_) => return None,
        };
        // serde_json's column is 1-based, in bytes, and falls inside the token.
        let line_start: usize = text
            .split_inclusive('\n')
            .take(e.line().saturating_sub(1))
            .map(str::len)
            .sum();
        let at = line_start + e.column().saturating_sub(1);
        let b = text.as_bytes();
        let tok = |c: u8| c.is_ascii_alphanumeric() || matches!(c, b'+' | b'-' | b'.');
        if at >= b.len() || !tok(b[at]) {
            return None;
        }
        let start = (0..at).rev().find(|&i| !tok(b[i])).map_or(0, |i| i + 1);
        let end = (at..b.len()).find(|&i| !tok(b[i])).unwrap_or(b.len());
        let token = text[start..end].to_owned();
        if token.parse::<f64>().map_or(true, f64::is_finite) {
            return None;
        }
        text.replace_range(start..end, &format!("\"{MARK}{}\"", found.len()));
        found.push((token, e.line()));
    };
    fn walk(v: &Value, at: &str, out: &mut Vec<(usize, String)>) {
        match v {
            Value::String(s) => {
                if let Some(k) = s
                    .strip_prefix("\u{1}mechplan-bad-number-")
                    .and_then(|k| k.parse().ok())
                {
                    out.push((k, at.to_owned()));
                }
            }
            Value::Array(a) => a
                .iter()
                .enumerate()
                .for_each(|(i, x)| walk(x, &format!("{at}/{i}"), out)),
            Value::Object(o) => o.iter().for_each(|(k, x)| walk(x, &ptr(at, k), out)),
            _ => {}
        }
    }
    let mut at = Vec::new();
    walk(&value, "", &mut at);
    at.sort();
    let msgs: Vec<String> = at
        .into_iter()
        .filter_map(|(k, pointer)| {
            let (token, line) = found.get(k)?;
            Some(format!(
                "{pointer}: non-finite number {token} (line {line}); every number must be finite"
            ))
        })
        .collect();
    (!msgs.is_empty()).then_some(msgs)
}
