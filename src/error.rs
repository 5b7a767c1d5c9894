//! Errors. User errors (a bad scene, a mechanism that cannot be assembled or
//! is singular) carry enough context to fix the input; they map to exit
//! status 2 in the binary.

use std::fmt;

/// One problem in a scene file, located by its JSON pointer.
#[derive(Clone, Debug, PartialEq)]
pub struct Issue {
    pub pointer: String,
    pub message: String,
}

impl fmt::Display for Issue {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        if self.pointer.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.pointer, self.message)
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    /// Not JSON, or JSON with repeated names.
    #[error("{}", .0.join("\n"))]
    Json(Vec<String>),
    /// Every problem found in the scene, each with its JSON pointer.
    #[error("{}", list(.0))]
    Scene(Vec<Issue>),
    /// Mobility ≠ 1, or the links do not decompose into Assur groups.
    #[error("{0}")]
    Structure(String),
    /// A group does not close at some input position.
    #[error("{group} cannot be assembled at {at}: {why}")]
    Assembly {
        group: String,
        at: String,
        why: String,
    },
    /// A singular position: the kinematic equations have no unique solution.
    #[error("singular position at {at}: {why}")]
    Singular { at: String, why: String },
}

fn list(v: &[Issue]) -> String {
    v.iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

impl Error {
    pub fn scene(pointer: impl Into<String>, message: impl Into<String>) -> Error {
        Error::Scene(vec![Issue {
            pointer: pointer.into(),
            message: message.into(),
        }])
    }
}

pub type Result<T> = std::result::Result<T, Error>;

/// A quantity for a message, in significant digits: `2e-12 m`, `0.35 m`,
/// `1.25e3 m/s` — never a small value printed as `0.000000`.
pub fn quantity(x: f64, unit: &str) -> String {
    let n = number(x);
    if unit.is_empty() {
        n
    } else {
        format!("{n} {unit}")
    }
}

/// A number in six significant digits, without trailing zeros; plain
/// decimals from 1e-4 to 1e6, scientific notation outside.
pub fn number(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let a = x.abs();
    let s = if (1e-4..1e6).contains(&a) {
        let digits = (5 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.5e}")
    };
    // Trailing zeros of the mantissa say nothing.
    let (mant, exp) = match s.find('e') {
        Some(i) => (&s[..i], &s[i..]),
        None => (&s[..], ""),
    };
    let mant = if mant.contains('.') {
        mant.trim_end_matches('0').trim_end_matches('.')
    } else {
        mant
    };
    format!("{mant}{exp}")
}

#[cfg(test)]
mod tests {
    #[test]
    fn small_quantities_keep_their_digits() {
        assert_eq!(super::quantity(2e-12, "m"), "2e-12 m");
        assert_eq!(super::quantity(0.35, "m"), "0.35 m");
        assert_eq!(super::quantity(-1250000.0, "m/s"), "-1.25e6 m/s");
        assert_eq!(super::number(0.123456789), "0.123457");
        assert_eq!(super::number(123.0), "123");
        assert_eq!(super::number(0.0), "0");
    }
}
