//! JSON: numbers and vectors as result files write them ([`number`],
//! [`vec2`]), and strict reading: serde_json keeps the last of two equal keys
//! silently, so a scene with `"A"` twice under `points` would lose a point
//! without a word. This reader builds the same `serde_json::Value` but
//! records every repeated key with its JSON pointer; a number serde_json
//! stops at (`NaN`, `Infinity`, `1e999`) is located by its field
//! ([`locate_bad_numbers`]), for scenes and answers alike.

use serde::de::{self, DeserializeSeed, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};
use std::cell::RefCell;
use std::fmt;

/// Escape one JSON-pointer token (RFC 6901).
pub fn escape(token: &str) -> String {
    token.replace('~', "~0").replace('/', "~1")
}

struct Strict<'a> {
    path: String,
    repeats: &'a RefCell<Vec<String>>,
}

impl<'de> DeserializeSeed<'de> for Strict<'_> {
    type Value = Value;
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Strict<'_> {
    type Value = Value;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Value, E> {
        Number::from_f64(v)
            .map(Value::Number)
            .ok_or_else(|| E::custom(format!("{}: non-finite number", self.path)))
    }
    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }
    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(v) = seq.next_element_seed(Strict {
            path: format!("{}/{}", self.path, out.len()),
            repeats: self.repeats,
        })? {
            out.push(v);
        }
        Ok(Value::Array(out))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            let path = format!("{}/{}", self.path, escape(&key));
            let v = map.next_value_seed(Strict {
                path: path.clone(),
                repeats: self.repeats,
            })?;
            if out.contains_key(&key) {
                self.repeats
                    .borrow_mut()
                    .push(format!("{path}: the name \"{key}\" is repeated"));
            } else {
                out.insert(key, v);
            }
        }
        Ok(Value::Object(out))
    }
}

/// Parse JSON text; an error is a human message (with line and column for
/// syntax errors, JSON pointers for repeated keys).
pub fn parse_strict(text: &str) -> Result<Value, Vec<String>> {
    let repeats = RefCell::new(Vec::new());
    let mut de = serde_json::Deserializer::from_str(text);
    let seed = Strict {
        path: String::new(),
        repeats: &repeats,
    };
    let value = seed
        .deserialize(&mut de)
        .and_then(|v| de.end().map(|_| v))
        .map_err(|e| vec![describe_syntax_error(text, &e)])?;
    let repeats = repeats.into_inner();
    if repeats.is_empty() {
        Ok(value)
    } else {
        Err(repeats)
    }
}

/// serde_json says "expected value" for `NaN`; say what is really wrong.
fn describe_syntax_error(text: &str, e: &serde_json::Error) -> String {
    let (line, col) = (e.line(), e.column());
    let at = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| l.chars().skip(col.saturating_sub(1)).collect::<String>())
        .unwrap_or_default();
    let at = at.trim_start();
    let non_finite = ["NaN", "Infinity", "-Infinity", "inf", "-inf", "nan"]
        .iter()
        .any(|w| at.starts_with(w));
    if non_finite {
        format!(
            "line {line}, column {col}: non-finite number (NaN or Infinity) is not allowed; every number must be finite"
        )
    } else if e.to_string().contains("number out of range") {
        format!("line {line}, column {col}: number out of range (not a finite 64-bit float)")
    } else {
        format!("malformed JSON: {e}")
    }
}

/// serde_json stops at `NaN`, `Infinity` or `1e999` with only a line and
/// column, but the contract names the field. Put a marker string in place of
/// each such number and read the text again: where a marker lands in the tree
/// is the field's JSON pointer. `None` when the text has no such number, more
/// than a few, or other syntax errors besides (the plain message then stands).
pub fn locate_bad_numbers(text: &str) -> Option<Vec<String>> {
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
            Value::Object(o) => o
                .iter()
                .for_each(|(k, x)| walk(x, &format!("{at}/{}", escape(k)), out)),
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

/// A number for a result file, round-trip-exact but tidy: integers print
/// as integers, no `-0`.
pub fn number(x: f64) -> serde_json::Value {
    let x = if x == 0.0 { 0.0 } else { x };
    serde_json::json!(x)
}

/// A vector for a result file: `[x, y]`.
pub fn vec2(v: kurbo::Vec2) -> serde_json::Value {
    serde_json::json!([number(v.x), number(v.y)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_key_is_reported_with_pointer() {
        let e = parse_strict(r#"{"points": {"A": [0, 0], "A": [1, 1]}}"#).unwrap_err();
        assert_eq!(e, vec!["/points/A: the name \"A\" is repeated".to_string()]);
    }

    #[test]
    fn nan_is_named() {
        let e = parse_strict("{\"a\": NaN}").unwrap_err();
        assert!(e[0].contains("non-finite"), "{e:?}");
    }

    #[test]
    fn order_is_kept() {
        let v = parse_strict(r#"{"b": 1, "a": 2}"#).unwrap();
        let keys: Vec<_> = v.as_object().unwrap().keys().cloned().collect();
        assert_eq!(keys, vec!["b", "a"]);
    }
}
