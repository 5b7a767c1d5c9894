//! The projective map between a photo's pixels and the sheet's
//! millimetres, from the four corners of a rectangle of known size (a
//! marks file's `rectangle_px`, `rectangle_mm`): a direct 8×8 solve on
//! normalised coordinates, so that a photo of thousands of pixels is as
//! well conditioned as a unit square.

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// The map from a photo's pixels to the sheet's millimetres (x right, y
/// up, the rectangle's bottom-left corner at the origin).
#[derive(Clone, Copy, Debug)]
pub struct Homography(Matrix3<f64>);

impl Homography {
    /// The homography taking `from[i]` to `to[i]` (four correspondences,
    /// no three collinear), solved directly with h₃₃ = 1 on coordinates
    /// centred and scaled to unit size for conditioning; `None` where
    /// the system is singular.
    pub fn from_corners(from: &[[f64; 2]; 4], to: &[[f64; 2]; 4]) -> Option<Homography> {
        let (tf, tt) = (normaliser(from), normaliser(to));
        let apply = |t: &Matrix3<f64>, p: [f64; 2]| {
            let q = t * Vector3::new(p[0], p[1], 1.0);
            [q.x, q.y]
        };
        let mut a = SMatrix::<f64, 8, 8>::zeros();
        let mut b = SVector::<f64, 8>::zeros();
        for i in 0..4 {
            let [x, y] = apply(&tf, from[i]);
            let [u, v] = apply(&tt, to[i]);
            let r = 2 * i;
            a.row_mut(r)
                .copy_from_slice(&[x, y, 1.0, 0.0, 0.0, 0.0, -u * x, -u * y]);
            a.row_mut(r + 1)
                .copy_from_slice(&[0.0, 0.0, 0.0, x, y, 1.0, -v * x, -v * y]);
            b[r] = u;
            b[r + 1] = v;
        }
        let h = a.lu().solve(&b)?;
        let hn = Matrix3::new(h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7], 1.0);
        let m = tt.try_inverse()? * hn * tf;
        (m.iter().all(|x| x.is_finite()) && m.determinant().abs() > 0.0).then_some(Homography(m))
    }

    /// Point `p` mapped; `None` at or beyond the horizon (w ≤ 0 where the
    /// rectangle's corners have w > 0).
    pub fn map(&self, p: [f64; 2]) -> Option<[f64; 2]> {
        let q = self.0 * Vector3::new(p[0], p[1], 1.0);
        (q.z > 0.0 && q.x.is_finite() && q.y.is_finite()).then(|| [q.x / q.z, q.y / q.z])
    }

    /// The inverse map (sheet mm to photo px).
    #[cfg(test)]
    pub fn inverse(&self) -> Option<Homography> {
        let m = self.0.try_inverse()?;
        // Keep w > 0 on the sheet's side of the horizon.
        let m = if (m * Vector3::new(0.0, 0.0, 1.0)).z < 0.0 { -m } else { m };
        Some(Homography(m))
    }

    /// The map's local scale at `p`: the square root of its Jacobian's
    /// determinant (for px → mm, mm per px).
    pub fn scale_at(&self, p: [f64; 2]) -> Option<f64> {
        let e = 0.5;
        let f = |dx: f64, dy: f64| self.map([p[0] + dx, p[1] + dy]);
        let (xp, xm, yp, ym) = (f(e, 0.0)?, f(-e, 0.0)?, f(0.0, e)?, f(0.0, -e)?);
        let j = [
            (xp[0] - xm[0]) / (2.0 * e),
            (xp[1] - xm[1]) / (2.0 * e),
            (yp[0] - ym[0]) / (2.0 * e),
            (yp[1] - ym[1]) / (2.0 * e),
        ];
        Some((j[0] * j[3] - j[1] * j[2]).abs().sqrt())
    }
}

/// The similarity moving `pts`' centroid to the origin and their mean
/// distance from it to √2 (Hartley's normalisation).
fn normaliser(pts: &[[f64; 2]; 4]) -> Matrix3<f64> {
    let c = pts.iter().fold([0.0, 0.0], |s, p| [s[0] + p[0] / 4.0, s[1] + p[1] / 4.0]);
    let d = pts
        .iter()
        .map(|p| (p[0] - c[0]).hypot(p[1] - c[1]))
        .sum::<f64>()
        / 4.0;
    let s = if d > 0.0 { std::f64::consts::SQRT_2 / d } else { 1.0 };
    Matrix3::new(s, 0.0, -s * c[0], 0.0, s, -s * c[1], 0.0, 0.0, 1.0)
}

