//! Scale coefficients μ from the standard drafting values (ГОСТ 2.302):
//! 1, 2, 2.5, 4, 5 × 10^k.

const MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 4.0, 5.0];

/// The smallest standard μ with which `largest` (a real value) is drawn no
/// longer than `max_mm`. With the standard steps (at most ×2 apart) the
/// largest segment then lies between `max_mm`/2 and `max_mm`.
pub fn standard_scale(largest: f64, max_mm: f64) -> f64 {
    if largest.is_nan() || largest <= 0.0 || !largest.is_finite() {
        // Nothing to fit: the smallest scale, so that it never dominates.
        return 0.0;
    }
    let target = largest / max_mm;
    let mut k = target.log10().floor() as i32 - 1;
    loop {
        for m in MANTISSAS {
            let mu = m * 10f64.powi(k);
            // Compare with a little slack so that exact fits are kept.
            if mu >= target * (1.0 - 1e-12) {
                return round_sig(mu);
            }
        }
        k += 1;
    }
}

/// Round to 12 significant digits so that 2.5e-3 prints as 0.0025.
fn round_sig(x: f64) -> f64 {
    let p = 10f64.powi(11 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_to_fit_never_dominates() {
        assert_eq!(standard_scale(0.0, 150.0), 0.0);
    }

    #[test]
    fn picks_standard_values_that_fit() {
        assert_eq!(standard_scale(1.0, 150.0), 0.01);
        assert_eq!(standard_scale(2.0, 150.0), 0.02);
        assert_eq!(standard_scale(3.5, 150.0), 0.025);
        assert_eq!(standard_scale(0.45, 150.0), 0.004);
        assert_eq!(standard_scale(1500.0, 150.0), 10.0);
        for x in [0.0123, 0.77, 3.3, 19.0, 456.0, 9999.0] {
            let mu = standard_scale(x, 150.0);
            let mm = x / mu;
            assert!((75.0..=150.0).contains(&mm), "{x}: {mu} gives {mm} mm");
        }
    }
}
