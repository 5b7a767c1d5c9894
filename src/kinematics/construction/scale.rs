//! Scale coefficients μ from standard values: the plans' 1, 2, 2.5, 4,
//! 5 × 10^k ([`Series::Plans`]: velocities, accelerations, forces,
//! diagrams) and ГОСТ 2.302's scales of a drawing for lengths
//! ([`Series::Drawing`]: the plan of the mechanism, its positions, its
//! free bodies), whose reductions run 1:10, 1:15, 1:20, 1:25, 1:40, 1:50,
//! 1:75, 1:100, 1:200, 1:400, 1:500, 1:800, 1:1000 (no 1:250).

const MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 4.0, 5.0];

/// ГОСТ 2.302's scales of a drawing as n of "1:n" (μ_l = n/1000 m per
/// mm): the enlargements 100:1 … 2:1, full size, the reductions 1:2 …
/// 1:1000 and those it allows for large objects, 1:2000 … 1:50 000.
const DRAWING_N: [f64; 33] = [
    0.01, 0.02, 0.025, 0.05, 0.1, 0.2, 0.25, 0.4, 0.5, 1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 15.0, 20.0,
    25.0, 40.0, 50.0, 75.0, 100.0, 200.0, 400.0, 500.0, 800.0, 1000.0, 2000.0, 5000.0, 10000.0,
    20000.0, 25000.0, 50000.0,
];

/// Which standard values a scale is taken from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Series {
    /// The plans' 1, 2, 2.5, 4, 5 × 10^k (any unit per mm).
    Plans,
    /// ГОСТ 2.302's scales of a drawing, μ_l in m/mm; past its ends
    /// (100:1 and 1:50 000) its rule for larger enlargements, (100·k):1,
    /// and the plans' values for still larger reductions.
    Drawing,
}

impl Series {
    /// The smallest value of the series not below `target` (real value
    /// per mm), `target` finite and above zero.
    pub fn at_least(self, target: f64) -> f64 {
        // Within the decades any drawing reaches (a NaN as 1): the
        // searches below then end in a few dozen steps.
        let target = if target.is_nan() { 1.0 } else { target.clamp(1e-15, 1e15) };
        match self {
            Series::Plans => standard_of_ratio(target),
            Series::Drawing => drawing_of_ratio(target),
        }
    }

    /// The smallest value of the series with which `largest` (a real
    /// value) is drawn no longer than `max_mm`; 0 when there is nothing
    /// to fit (so that it never dominates).
    pub fn scale(self, largest: f64, max_mm: f64) -> f64 {
        if !fits_something(largest) {
            return 0.0;
        }
        self.at_least(largest / max_mm)
    }

    /// The next value of the series above `mu` (a value of it or not).
    pub fn above(self, mu: f64) -> f64 {
        self.at_least(mu * (1.0 + 1e-9))
    }
}

/// The smallest "1:n" of ГОСТ 2.302 with n not below `n` (from 0.01,
/// 100:1): the reduction that brings a drawing `n` times too large within
/// its sheet, and the table [`Series::Drawing`] looks its values up in.
pub fn drawing_reduction(n: f64) -> f64 {
    DRAWING_N
        .iter()
        .copied()
        .find(|&v| v >= n * (1.0 - 1e-12))
        // Past 1:50 000, the plans' row.
        .unwrap_or_else(|| standard_of_ratio(n))
}

/// The smallest of ГОСТ 2.302's scales (μ_l, m/mm) not below `target`.
fn drawing_of_ratio(target: f64) -> f64 {
    let n = target * 1e3;
    let smallest = DRAWING_N[0];
    if n < smallest * (1.0 - 1e-12) {
        // The standard's (100·k):1, k from the plans' row (1, 2, 2.5, 4,
        // 5 × 10^j, so that the next scale is at most ×2 away, not k/(k−1)):
        // the largest k with n = 1/(100·k) not below the target.
        return round_sig(1e-5 / standard_at_most(1.0 / (100.0 * n)));
    }
    round_sig(drawing_reduction(n) * 1e-3)
}

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

/// The largest standard value (1, 2, 2.5, 4, 5 × 10^j) not above `r`
/// (at least 1).
fn standard_at_most(r: f64) -> f64 {
    let mut j = r.log10().floor() as i32 + 1;
    while j >= 0 {
        for m in MANTISSAS.into_iter().rev() {
            let v = m * 10f64.powi(j);
            if v <= r * (1.0 + 1e-12) {
                return v;
            }
        }
        j -= 1;
    }
    1.0
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
    if !x.is_normal() {
        return x;
    }
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

    #[test]
    fn lengths_take_gost_2_302s_scales_of_a_drawing() {
        // ГОСТ 2.302-68 as printed: enlargements, full size, reductions.
        let gost = [
            "100:1", "50:1", "40:1", "20:1", "10:1", "5:1", "4:1", "2.5:1", "2:1", "1:1", "1:2",
            "1:2.5", "1:4", "1:5", "1:10", "1:15", "1:20", "1:25", "1:40", "1:50", "1:75",
            "1:100", "1:200", "1:400", "1:500", "1:800", "1:1000",
        ];
        let mu = |s: &str| {
            let (a, b) = s.split_once(':').unwrap();
            b.parse::<f64>().unwrap() / a.parse::<f64>().unwrap() * 1e-3
        };
        let d = Series::Drawing;
        for w in gost.windows(2) {
            let (lo, hi) = (mu(w[0]), mu(w[1]));
            assert!((d.at_least(lo) - lo).abs() < 1e-15 * lo, "{} itself", w[0]);
            // Every ratio between two neighbours takes the larger: no
            // value between them (1:250 is not one).
            for t in [0.01, 0.5, 0.99] {
                let r = lo + t * (hi - lo);
                assert!((d.at_least(r) - hi).abs() < 1e-12 * hi, "{r} between {w:?}");
            }
            assert!((d.above(lo) - hi).abs() < 1e-12 * hi, "after {}", w[0]);
        }
        assert_eq!(d.scale(0.0, 200.0), 0.0);
        // A sketch of 3 m within 200 mm: 1:15; 12 m: 1:75.
        assert!((d.scale(3.0, 200.0) - 0.015).abs() < 1e-15);
        assert!((d.scale(12.0, 200.0) - 0.075).abs() < 1e-15);
        // Past 100:1, (100·k):1: 1 mm within 150 mm is 150:1 at most, so 100:1.
        assert!((d.scale(1e-3, 150.0) - 1e-5).abs() < 1e-20);
        // 0.1 mm within 150 mm: 1500:1 at most → (100·10):1, k from the
        // plans' row; the next larger scale is (100·20):1, not (100·16):1.
        let m = d.scale(1e-4, 150.0);
        assert!((m - 1e-3 / 1000.0).abs() < 1e-18, "{m}");
        assert!((d.above(m) - 1e-3 / 500.0).abs() < 1e-18);
        // Far past the standard's ends, and bad input, in a few steps.
        for t in [1e-300, 0.0, -1.0, f64::NAN, f64::INFINITY, 1e300] {
            let mu = d.at_least(t);
            assert!(mu.is_finite() && mu > 0.0, "{t}: {mu}");
            let p = Series::Plans.at_least(t);
            assert!(p.is_finite() && p > 0.0, "{t}: {p}");
            if t < 1.0 {
                assert!(d.above(mu) > mu && Series::Plans.above(p) > p, "{t}");
            }
        }
        // A fill from the smallest drawing up steps at most ×2.5.
        let mut mu = d.at_least(1e-12);
        while mu < 1e6 {
            let next = d.above(mu);
            assert!(next > mu && next <= 2.5 * mu * (1.0 + 1e-9), "{mu} → {next}");
            mu = next;
        }
        // Reductions of a sheet: 1:3 → 1:4, 1:12 → 1:15, 1:230 → 1:400.
        assert_eq!(drawing_reduction(3.0), 4.0);
        assert_eq!(drawing_reduction(12.0), 15.0);
        assert_eq!(drawing_reduction(230.0), 400.0);
        assert_eq!(drawing_reduction(1.0), 1.0);
    }
}
