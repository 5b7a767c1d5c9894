//! Scale coefficients μ from the standard drafting values (ГОСТ 2.302):
//! 1, 2, 2.5, 4, 5 × 10^k.


const MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 4.0, 5.0];

/// Where a plan drawn at a standard scale must fit, mm: its longest vector
/// and its whole extent. Which field is the caller's decision (the
/// presentation's sheet); [`Field::default`] is the one the callers pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Field {
    /// The longest vector from the pole at most this long.
    pub longest: f64,
    /// The whole plan at most this wide …
    pub width: f64,
    /// … and this high.
    pub height: f64,
}

impl Default for Field {
    /// The longest vector at most 150 mm, the whole plan within
    /// 240 × 130 mm: the free area of an A4 landscape sheet.
    fn default() -> Self {
        Field {
            longest: 150.0,
            width: 240.0,
            height: 130.0,
        }
    }
}

impl Field {
    /// The smallest standard μ at which a plan fits, from where its points
    /// fall at unit scale (real values); 1 for a plan all at the pole
    /// (everything at rest: any scale draws it).
    pub fn scale(&self, points: impl Iterator<Item = kurbo::Vec2>) -> f64 {
        let mu = self.ratio(points).map_or(0.0, standard_of_ratio);
        if mu > 0.0 { mu } else { 1.0 }
    }

    /// The largest ratio of a plan's extents (real values, at unit scale)
    /// to the field's: its longest vector, width and height; `None` when
    /// there is nothing to fit.
    fn ratio(&self, points: impl Iterator<Item = kurbo::Vec2>) -> Option<f64> {
        let (mut largest, mut lo, mut hi) = (0.0f64, (f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
        for p in points {
            largest = largest.max(p.hypot());
            lo = (lo.0.min(p.x), lo.1.min(p.y));
            hi = (hi.0.max(p.x), hi.1.max(p.y));
        }
        // The standard scale grows with the ratio it fits (the smallest
        // standard value above it), so the largest of the three scales is
        // the one of the largest ratio: one search instead of three.
        [
            (largest, self.longest),
            (hi.0 - lo.0, self.width),
            (hi.1 - lo.1, self.height),
        ]
        .into_iter()
        .filter(|&(x, _)| fits_something(x))
        .map(|(x, max_mm)| x / max_mm)
        .fold(None, |a: Option<f64>, t| Some(a.map_or(t, |a| a.max(t))))
    }
}

/// The smallest standard μ with which `largest` (a real value) is drawn no
/// longer than `max_mm`. With the standard steps (at most ×2 apart) the
/// largest segment then lies between `max_mm`/2 and `max_mm`.
pub fn standard_scale(largest: f64, max_mm: f64) -> f64 {
    if !fits_something(largest) {
        // Nothing to fit: the smallest scale, so that it never dominates.
        return 0.0;
    }
    standard_of_ratio(largest / max_mm)
}

/// Whether a value has a scale to fit it by (finite, above zero).
fn fits_something(largest: f64) -> bool {
    !(largest.is_nan() || largest <= 0.0 || !largest.is_finite())
}

/// The smallest standard value not below `target` (real value per mm).
fn standard_of_ratio(target: f64) -> f64 {
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

/// The ratios (real value per mm) for which [`Field::scale`] picks the
/// standard value `mu`, narrowed by a hundred-billionth at both ends
/// (so that rounding at the ends never matters): every ratio in
/// `lo..=hi` gives `mu`. `None` when `mu` is not a standard value.
#[cfg(any(test, feature = "internals"))]
pub fn band(mu: f64) -> Option<(f64, f64)> {
    if !(mu.is_finite() && mu > 0.0) {
        return None;
    }
    let k0 = mu.log10().floor() as i32;
    for k in k0 - 1..=k0 + 1 {
        for (i, m) in MANTISSAS.into_iter().enumerate() {
            if (m * 10f64.powi(k) - mu).abs() <= 1e-9 * mu {
                let below = match i {
                    0 => MANTISSAS[4] * 10f64.powi(k - 1),
                    _ => MANTISSAS[i - 1] * 10f64.powi(k),
                };
                return Some((below * (1.0 + 1e-11), mu * (1.0 - 1e-11)));
            }
        }
    }
    None
}

/// The next standard value above `mu` (a standard value or not).
pub fn standard_above(mu: f64) -> f64 {
    standard_scale(mu * (1.0 + 1e-9), 1.0)
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
    fn one_search_gives_the_largest_of_the_three_scales() {
        let f = Field::default();
        let mut x = 0.37f64;
        for _ in 0..2000 {
            // A pseudo-random walk over many decades.
            x = (x * 7919.0 + 0.123).fract();
            let p = [
                kurbo::Vec2::new(x * 10f64.powi((x * 13.0) as i32 - 6), -x),
                kurbo::Vec2::new(-3.0 * x, 10f64.powi((x * 7.0) as i32 - 3)),
            ];
            let largest = p.iter().map(|v| v.hypot()).fold(0.0, f64::max);
            let (w, h) = ((p[0].x - p[1].x).abs(), (p[0].y - p[1].y).abs());
            let three = standard_scale(largest, f.longest)
                .max(standard_scale(w, f.width))
                .max(standard_scale(h, f.height));
            assert_eq!(f.scale(p.into_iter()), three, "{p:?}");
        }
        assert_eq!(f.scale(std::iter::empty()), 1.0);
        assert_eq!(f.scale([kurbo::Vec2::ZERO].into_iter()), 1.0);
    }

    #[test]
    fn a_band_holds_the_ratios_of_its_scale_and_no_others() {
        let mut x = 0.61f64;
        for _ in 0..2000 {
            x = (x * 7919.0 + 0.123).fract();
            let ratio = (x * 20.0 - 10.0).exp();
            let mu = standard_of_ratio(ratio);
            let (lo, hi) = band(mu).expect("a standard value");
            assert!(
                lo <= ratio * (1.0 + 1e-10) && ratio <= hi * (1.0 + 1e-10),
                "{ratio}"
            );
            for r in [lo, hi, lo + 0.5 * (hi - lo)] {
                assert_eq!(standard_of_ratio(r), mu, "{r} in the band of {mu}");
            }
            assert!(standard_of_ratio(lo * (1.0 - 1e-9)) < mu);
            assert!(standard_of_ratio(hi * (1.0 + 1e-9)) > mu);
        }
        assert_eq!(band(1.0).map(|b| b.1 < 1.0), Some(true));
        assert_eq!(band(0.3), None);
    }

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
