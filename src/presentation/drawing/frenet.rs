//! Families of link positions (paper `001`, Figs 2, 3 and 5): the link
//! drawn as a segment at equal steps Δs of the arc of its guide curve, with
//! the trajectories of its ends (the guide curve's, that of A, thick).

use super::canvas::{Canvas, Class, Label};
use super::{DrawOptions, Sheet, page_svg};
use crate::kinematics::construction::scale::Series;
use crate::studies::frenet;
use kurbo::Point;
use std::f64::consts::TAU;

/// One family: the ends of the segment at arc length s.
struct Family {
    name: &'static str,
    title: String,
    /// The curvature of the guide circle (A's path).
    k: f64,
    /// Revolutions of A until the figure closes.
    turns: usize,
    /// The segment runs from A (its start is A's path, drawn thick).
    from_a: bool,
    ends: Box<dyn Fn(f64) -> (Point, Point)>,
}

/// A segment A–B of length ρ on a circle of radius r (eq. 5) turning
/// relative to the trihedron by φ = a·s (eq. 6); `both`: the segment also
/// runs from A the other way by ρ.
fn linear(r: f64, rho: f64, a: f64, both: bool) -> Box<dyn Fn(f64) -> (Point, Point)> {
    let k = 1.0 / r;
    Box::new(move |s| {
        let (pa, alpha) = frenet::on_circle(k, s);
        let b = frenet::in_trihedron(pa, alpha, rho, a * s);
        let start = if both {
            frenet::in_trihedron(pa, alpha, -rho, a * s)
        } else {
            pa
        };
        (start, b)
    })
}

/// The slider-crank's rod (eq. 7, or eq. 7 with the opposite sign); `both`:
/// the rod extended beyond A by its length.
fn rod(k: f64, l: f64, sign: f64, both: bool) -> Box<dyn Fn(f64) -> (Point, Point)> {
    Box::new(move |s| {
        let (pa, alpha) = frenet::on_circle(k, s);
        let phi = sign * frenet::rod_angle(k, l, s);
        let b = frenet::in_trihedron(pa, alpha, l, phi);
        let start = if both {
            frenet::in_trihedron(pa, alpha, -l, phi)
        } else {
            pa
        };
        (start, b)
    })
}

/// The families of Figs 2, 3 and 5 of `001` with the paper's numbers
/// (Fig. 3 does not state r: r = 5 as in Fig. 2).
fn families() -> Vec<Family> {
    let (r, k5, l5) = (5.0, 0.2, 8.0);
    vec![
        Family {
            name: "fig2a",
            turns: 1,
            from_a: true,
            title: "001 Fig. 2 a: ρ = 2.5, r = 5, φ = 0.2·s (ω_B = ω_A)".into(),
            k: 1.0 / r,
            ends: linear(r, 2.5, 0.2, false),
        },
        Family {
            name: "fig2b",
            turns: 1,
            from_a: true,
            title: "001 Fig. 2 b: φ = −0.2·s (ω_B = −ω_A: translation)".into(),
            k: 1.0 / r,
            ends: linear(r, 2.5, -0.2, false),
        },
        Family {
            name: "fig2c",
            turns: 1,
            from_a: false,
            title: "001 Fig. 2 c: φ = 0.2·s, the segment extended beyond A".into(),
            k: 1.0 / r,
            ends: linear(r, 2.5, 0.2, true),
        },
        Family {
            name: "fig3a",
            turns: 2,
            from_a: false,
            title: "001 Fig. 3 a: ρ = 4 both ways from A, ω_B = 1.5·ω_A".into(),
            k: 1.0 / r,
            ends: linear(r, 4.0, 1.5 / r, true),
        },
        Family {
            name: "fig3b",
            turns: 2,
            from_a: false,
            title: "001 Fig. 3 b: ρ = 4, ω_B = −1.5·ω_A".into(),
            k: 1.0 / r,
            ends: linear(r, 4.0, -1.5 / r, true),
        },
        Family {
            name: "fig3c",
            turns: 2,
            from_a: false,
            title: "001 Fig. 3 c: ρ = 2, ω_B = 1.5·ω_A".into(),
            k: 1.0 / r,
            ends: linear(r, 2.0, 1.5 / r, true),
        },
        Family {
            name: "fig5a",
            turns: 1,
            from_a: true,
            title: "001 Fig. 5 a: slider-crank rod, k = 0.2, AB = 8, φ by eq. (7)".into(),
            k: k5,
            ends: rod(k5, l5, 1.0, false),
        },
        Family {
            name: "fig5b",
            turns: 1,
            from_a: true,
            title: "001 Fig. 5 b: φ of eq. (7) with the opposite sign".into(),
            k: k5,
            ends: rod(k5, l5, -1.0, false),
        },
        Family {
            name: "fig5c",
            turns: 1,
            from_a: false,
            title: "001 Fig. 5 c: eq. (7), the rod extended beyond A by AB".into(),
            k: k5,
            ends: rod(k5, l5, 1.0, true),
        },
    ]
}

/// The sheets of the families, `count` segments per revolution of A (the
/// figures of Fig. 3 close after two revolutions).
pub fn sheets(count: usize, opt: &DrawOptions) -> Vec<Sheet> {
    let fine = 720;
    families()
        .into_iter()
        .map(|f| {
            let turn = TAU / f.k * f.turns as f64;
            let fine = fine * f.turns;
            let count = count * f.turns;
            let at = |j: usize, n: usize| (f.ends)(turn * j as f64 / n as f64);
            // The scale: the family's extent within the sheet's free area.
            let pts: Vec<(Point, Point)> = (0..=fine).map(|j| at(j, fine)).collect();
            let (mut lo, mut hi) = (
                Point::new(f64::MAX, f64::MAX),
                Point::new(f64::MIN, f64::MIN),
            );
            for (a, b) in &pts {
                for p in [a, b] {
                    lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
                    hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
                }
            }
            let mu = Series::Drawing.scale(hi.x - lo.x, 220.0).max(Series::Drawing.scale(hi.y - lo.y, 150.0));
            let to = |p: Point| Point::new(p.x / mu, p.y / mu);
            let mut c = Canvas::default();
            for j in 0..count {
                let (a, b) = at(j, count);
                c.seg(to(a), to(b), Class::Thin);
            }
            for w in pts.windows(2) {
                let (a0, b0) = w[0];
                let (a1, b1) = w[1];
                c.seg(to(b0), to(b1), Class::Thin);
                let class = if f.from_a { Class::Main } else { Class::Thin };
                c.seg(to(a0), to(a1), class);
            }
            // A's own path (the guide circle) where the segment starts beyond A.
            let k = f.k;
            if !f.from_a {
                for j in 0..fine {
                    let p0 = frenet::on_circle(k, turn * j as f64 / fine as f64).0;
                    let p1 = frenet::on_circle(k, turn * (j + 1) as f64 / fine as f64).0;
                    c.seg(to(p0), to(p1), Class::Main);
                }
            }
            let (a0, _) = frenet::on_circle(k, 0.0);
            c.dot(to(a0), "A0".into());
            c.label(to(a0), Label::new("A", "0"), super::canvas::SMALL, None);
            page_svg(
                f.name.into(),
                f.title,
                &c,
                Some(super::scale_text("l", mu, "m", opt.lang)),
                opt,
            )
        })
        .collect()
}
