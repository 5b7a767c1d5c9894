//! Link positions in the Frenet trihedron of a guide curve (paper `001`).
//!
//! A link end A runs along a plane curve of curvature k(s); the trihedron
//! at A turns by α = ∫k ds, so A = (∫cos α ds, ∫sin α ds) (eq. 2), and a
//! point B of the link at distance ρ and angle φ(s) from the tangent is
//! A + ρ·(cos(φ + α), sin(φ + α)) (eq. 3). On a circle of radius r = 1/k,
//! with A starting at its lowest point, A = (r sin ks, −r cos ks) (eq. 5).
//!
//! For the slider-crank (crank r = 1/k about O, rod AB = L, B on the
//! vertical through O) the rod's angle to the tangent is
//! φ = 90° − ks + arcsin(sin ks / (Lk)) (eq. 7), and a rod point at
//! distance ρ from A traces (eq. 8)
//! x = (L − ρ)/(Lk)·sin ks,  y = ρ/(Lk)·√(L²k² − sin² ks) − cos(ks)/k.

use kurbo::{Point, Vec2};

/// A on a circle of curvature `k` after arc length `s` (eq. 5): the
/// circle's centre at the origin, A starting at its lowest point and
/// running counter-clockwise; the tangent turns by α = ks.
pub fn on_circle(k: f64, s: f64) -> (Point, f64) {
    let a = k * s;
    (Point::new(a.sin() / k, -a.cos() / k), a)
}

/// A point at distance `rho` and angle `phi` from the tangent of the
/// trihedron at `a` turned by `alpha` (eq. 3).
pub fn in_trihedron(a: Point, alpha: f64, rho: f64, phi: f64) -> Point {
    a + Vec2::from_angle(phi + alpha) * rho
}

/// The slider-crank rod's angle to the tangent of the crank circle (eq. 7).
pub fn rod_angle(k: f64, l: f64, s: f64) -> f64 {
    std::f64::consts::FRAC_PI_2 - k * s + ((k * s).sin() / (l * k)).asin()
}

/// The slider-crank's rod point at distance `rho` from A (eq. 8, as
/// printed in `001`).
#[cfg(feature = "internals")]
pub fn rod_point(k: f64, l: f64, rho: f64, s: f64) -> Point {
    let ks = k * s;
    Point::new(
        (l - rho) / (l * k) * ks.sin(),
        rho / (l * k) * (l * l * k * k - ks.sin().powi(2)).sqrt() - ks.cos() / k,
    )
}

/// The same point by the general formulation (eqs. 3, 5, 7).
#[cfg(feature = "internals")]
pub fn rod_point_general(k: f64, l: f64, rho: f64, s: f64) -> Point {
    let (a, alpha) = on_circle(k, s);
    in_trihedron(a, alpha, rho, rod_angle(k, l, s))
}
