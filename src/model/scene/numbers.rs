//! Numbers: finite and within [`MAX_MAGNITUDE`], angles reduced exactly
//! in the file's unit with their rounding. (The field of each non-finite
//! number the JSON parser stops at is found by
//! [`crate::json::locate_bad_numbers`], for answers too.)

use super::reader::{Reader, kind};
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
