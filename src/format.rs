//! Numbers as mechplan writes them, one family: [`num`] the plans' and
//! steps' measured values (four significant digits, trailing zeros
//! dropped); [`format_number`] and [`format_quantity`] numbers in messages,
//! to significant digits: a distance of 2e-12 m is "2e-12 m", never
//! "0.000000 m".

/// Numbers as a student writes them: up to 4 significant digits.
pub fn num(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 9) as usize;
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" { "0".into() } else { s }
}

/// 1e-8, 2.5e-3: a compact scientific number.
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:.1e}");
    s.replace(".0e", "e")
}

/// Significant digits of [`format_number`].
pub const DIGITS: usize = 4;

/// `x` to four significant digits: fixed for 0.001 ≤ |x| < 1000 (trailing
/// zeros kept, they are significant: "0.3500", "12.00"), else scientific
/// with the mantissa's trailing zeros dropped ("2e-12", "1.25e3"); "0" for
/// zero (either sign), "inf", "-inf", "NaN" as Rust writes them.
pub fn format_number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return x.to_string();
    }
    // The exponent after rounding to DIGITS significant digits.
    let sci = format!("{:.*e}", DIGITS - 1, x);
    let (mantissa, exp) = sci.split_once('e').expect("scientific notation");
    let exp: i32 = exp.parse().expect("an integer exponent");
    if (-3..=2).contains(&exp) {
        let decimals = (DIGITS as i32 - 1 - exp) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{}e{exp}", trim_zeros(mantissa))
    }
}

/// `x` to `decimals` places with the trailing zeros (and a bare point)
/// dropped and no "-0": the drawings' coordinates ("12.5", "0"), the
/// terminal table's numbers.
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    let s = trim_zeros(&s);
    if s == "-0" { "0".into() } else { s.into() }
}

/// A decimal number's text without the trailing zeros of its fraction,
/// nor its point when nothing follows ("1.2500" → "1.25", "3.0" → "3");
/// a number without a point as it is.
fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// `x` and its unit: `format_quantity(2e-12, "m")` is "2e-12 m",
/// `format_quantity(0.35, "m")` "0.3500 m", `format_quantity(1250.0, "m")`
/// "1.25e3 m"; no unit, no space.
pub fn format_quantity(x: f64, unit: &str) -> String {
    if unit.is_empty() {
        format_number(x)
    } else {
        format!("{} {unit}", format_number(x))
    }
}

/// `shown` (a value in the unit it is shown in: degrees, metres) in the
/// fewest significant digits whose decimal `back` turns into `exact`
/// (the value as computed: radians, metres) — "60" for the 60° of a
/// file that came back through radians as 59.99999999999999°, while two
/// values a nano-degree apart still read apart. Without such a decimal,
/// `shown` to its last digit.
pub fn read_back(shown: f64, exact: f64, back: &dyn Fn(f64) -> f64) -> String {
    if !shown.is_finite() {
        return shown.to_string();
    }
    (1..=17)
        .filter_map(|p| format!("{:.*e}", p - 1, shown).parse::<f64>().ok())
        .find(|&d| back(d) == exact)
        .unwrap_or(shown)
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_at_every_magnitude() {
        for (x, want) in [
            (2e-12, "2e-12"),
            (-2e-12, "-2e-12"),
            (0.35, "0.3500"),
            (1250.0, "1.25e3"),
            (1000.0, "1e3"),
            (999.96, "1e3"),
            (999.94, "999.9"),
            (0.001, "0.001000"),
            (0.00099996, "0.001000"),
            (0.00099994, "9.999e-4"),
            (12.0, "12.00"),
            (-0.5, "-0.5000"),
            (1.23456e-7, "1.235e-7"),
            (6.02e23, "6.02e23"),
            (0.0, "0"),
            (-0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NAN, "NaN"),
        ] {
            assert_eq!(format_number(x), want, "{x:e}");
        }
        assert_eq!(format_quantity(2e-12, "m"), "2e-12 m");
        assert_eq!(format_quantity(0.35, "m"), "0.3500 m");
        assert_eq!(format_quantity(1250.0, "m"), "1.25e3 m");
        assert_eq!(format_quantity(3.0, ""), "3.000");
        assert_eq!(fixed(12.5, 2), "12.5");
        assert_eq!(fixed(3.0, 6), "3");
        assert_eq!(fixed(-0.001, 2), "0");
        assert_eq!(fixed(-1.26, 1), "-1.3");
    }

    #[test]
    fn values_read_back_in_their_fewest_digits() {
        let rad = std::f64::consts::PI / 180.0;
        let deg = |d: f64| d * rad;
        let q = 60.0 * rad;
        assert_eq!(q.to_degrees().to_string(), "59.99999999999999");
        assert_eq!(read_back(q.to_degrees(), q, &deg), "60");
        let near = f64::from_bits(q.to_bits() + 1);
        assert_ne!(read_back(near.to_degrees(), near, &deg), "60");
        assert_eq!(read_back(0.07, 0.07, &|x| x), "0.07");
        assert_eq!(read_back(-0.0, 0.0, &|x| x), "-0");
    }
}
