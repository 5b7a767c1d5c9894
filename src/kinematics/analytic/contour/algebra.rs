//! The contours' algebra, shared by the interpreted route and the
//! compiled one ([`crate::kinematics::compiled`]) so that both do the same
//! arithmetic in the same order: the contour matrix and its known side in
//! the group's own unit of length, the walk over a group's pairs, the
//! inversion of the matrix with dimensionless columns.

use super::Twist;
use crate::accuracy::ACCURACY;
use crate::model::structure::Conn;
use nalgebra::{SMatrix, SVector};

/// The reciprocal of a group's reach (the longest arm of its revolute
/// pairs' twists): the contour's rows in the group's own unit of length.
#[inline]
pub(crate) fn per_length(xi: &[Twist]) -> f64 {
    let reach = xi
        .iter()
        .map(|t| if t.w != 0.0 { t.v.hypot() } else { 0.0 })
        .fold(0.0, f64::max);
    if reach > 0.0 { 1.0 / reach } else { 1.0 }
}

/// The contours' matrix: the twists `xi` of the pairs with their signs,
/// the velocity rows in the group's unit of length.
#[inline]
pub(crate) fn contour_matrix<const N: usize>(
    contours: &[&[(usize, f64)]],
    xi: &[Twist; N],
    per_length: f64,
) -> SMatrix<f64, N, N> {
    let mut a = SMatrix::<f64, N, N>::zeros();
    for (ci, contour) in contours.iter().enumerate() {
        for &(j, sg) in contour.iter() {
            a[(3 * ci, j)] = sg * xi[j].w;
            a[(3 * ci + 1, j)] = sg * xi[j].v.x * per_length;
            a[(3 * ci + 2, j)] = sg * xi[j].v.y * per_length;
        }
    }
    a
}

/// A known side `r` of `contours` contours with its velocity rows in the
/// group's unit of length.
#[inline]
pub(crate) fn in_group_units<const N: usize>(
    mut r: SVector<f64, N>,
    contours: usize,
    per_length: f64,
) -> SVector<f64, N> {
    for ci in 0..contours {
        r[3 * ci + 1] *= per_length;
        r[3 * ci + 2] *= per_length;
    }
    r
}

/// The twist `t` of a given slide moved to the known side of the
/// contour it lies on (none: off the contours, nothing to move).
#[inline]
pub(crate) fn subtract_on<const N: usize>(
    rhs: &mut SVector<f64, N>,
    contour: Option<usize>,
    t: Twist,
) {
    if let Some(ci) = contour {
        rhs[3 * ci] -= t.w;
        rhs[3 * ci + 1] -= t.v.x;
        rhs[3 * ci + 2] -= t.v.y;
    }
}

/// The pairs' drift terms (their brackets) moved to the known side of
/// the acceleration contours.
#[inline]
pub(crate) fn subtract_drift<const N: usize>(
    rhs: &mut SVector<f64, N>,
    contours: &[&[(usize, f64)]],
    drift: &[Twist; N],
) {
    for (ci, contour) in contours.iter().enumerate() {
        for &(j, sg) in contour.iter() {
            rhs[3 * ci] -= sg * drift[j].w;
            rhs[3 * ci + 1] -= sg * drift[j].v.x;
            rhs[3 * ci + 2] -= sg * drift[j].v.y;
        }
    }
}

/// The known side of the contours: the twist (or twist rate) of each
/// contour's end link less that of its start link.
#[inline]
pub(crate) fn rhs<const N: usize, K: Copy>(
    ends: &[(K, K)],
    f: impl Fn(K) -> Twist,
) -> SVector<f64, N> {
    let mut r = SVector::<f64, N>::zeros();
    for (ci, &(k1, k2)) in ends.iter().enumerate() {
        let t = f(k2) - f(k1);
        r[3 * ci] = t.w;
        r[3 * ci + 1] = t.v.x;
        r[3 * ci + 2] = t.v.y;
    }
    r
}

/// How a group's walk reaches its links: whether a link's twist is
/// there (known before the group, or found by the walk), and the link
/// found across pair `j` from `base` (`forward`: from the pair's `from`
/// to its `to`).
pub(crate) trait Reach {
    type Base: Copy;
    fn get(&mut self, l: usize) -> Option<Self::Base>;
    fn found(&mut self, j: usize, base: Self::Base, forward: bool, l: usize);
}

/// The walk over a group's pairs outward from the known links, in the
/// pairs' order, each pass over the pairs still pending: the one order
/// the interpreted contours and the compiled ones take.
pub(crate) fn walk_pairs<R: Reach>(conns: &[Conn], r: &mut R) {
    let n = conns.len();
    let mut pending = [true; 8];
    let mut left = n;
    while left > 0 {
        let before = left;
        for j in 0..n {
            if !pending[j] {
                continue;
            }
            let cn = &conns[j];
            match (r.get(cn.from), r.get(cn.to)) {
                (Some(base), None) => r.found(j, base, true, cn.to),
                (None, Some(base)) => r.found(j, base, false, cn.from),
                (Some(_), Some(_)) => {}
                (None, None) => continue,
            }
            pending[j] = false;
            left -= 1;
        }
        assert!(left < before, "group pairs form a connected contour");
    }
}

/// The twists a walk finds: `base` gives the known links', `step(j)` the
/// relative twist across pair j.
struct Twists<B, S> {
    base: B,
    step: S,
    found: [(usize, Twist); 4],
    count: usize,
}

impl<B: Fn(usize) -> Option<Twist>, S: Fn(usize) -> Twist> Reach for Twists<B, S> {
    type Base = Twist;
    fn get(&mut self, l: usize) -> Option<Twist> {
        (self.base)(l).or_else(|| {
            self.found[..self.count]
                .iter()
                .find(|e| e.0 == l)
                .map(|e| e.1)
        })
    }
    fn found(&mut self, j: usize, base: Twist, forward: bool, l: usize) {
        let t = if forward {
            base + (self.step)(j)
        } else {
            base - (self.step)(j)
        };
        self.found[self.count] = (l, t);
        self.count += 1;
    }
}

/// The twist of every link of a group: walk the pairs outward from the
/// known links (`base`), in the pairs' order, each pass over the pairs
/// still pending; `step(j)` is the relative twist across pair j.
pub(super) fn walk(
    conns: &[Conn],
    step: impl Fn(usize) -> Twist,
    base: impl Fn(usize) -> Option<Twist>,
) -> ([(usize, Twist); 4], usize) {
    let mut twists = Twists {
        base,
        step,
        found: [(usize::MAX, Twist::default()); 4],
        count: 0,
    };
    walk_pairs(conns, &mut twists);
    (twists.found, twists.count)
}

/// Make the columns dimensionless (a revolute column has a length scale):
/// the scaled matrix and the scales.
fn scaled<const N: usize>(a: &SMatrix<f64, N, N>) -> (SMatrix<f64, N, N>, [f64; N]) {
    let scale: [f64; N] = std::array::from_fn(|j| a.column(j).norm().max(f64::MIN_POSITIVE));
    let mut an = *a;
    for (j, sc) in scale.iter().enumerate() {
        an.column_mut(j).scale_mut(1.0 / sc);
    }
    (an, scale)
}

/// The inverse of a group's contour matrix, once per position: the
/// velocity and the acceleration contours share it.
pub(crate) struct Inverse<const N: usize> {
    /// Inverse of the matrix with dimensionless columns.
    inv: SMatrix<f64, N, N>,
    /// The columns' scales.
    scale: [f64; N],
}

impl<const N: usize> Inverse<N> {
    #[inline]
    pub(crate) fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let x = self.inv * b;
        SVector::<f64, N>::from_fn(|j, _| x[j] / self.scale[j])
    }
}

/// A dyad's 3×3 contour matrix inverted in closed form (cofactors); `None`
/// when it is singular relative to the scale of its columns.
pub(crate) fn invert3(a: &SMatrix<f64, 3, 3>) -> Option<Inverse<3>> {
    let (an, scale) = scaled(a);
    if an.determinant().abs() < ACCURACY.min_contour_determinant {
        return None;
    }
    Some(Inverse {
        inv: an.try_inverse()?,
        scale,
    })
}

/// A three-leash group's 6×6 matrix (two contours) by LU; `None` when it
/// is singular relative to the scale of its columns.
pub(crate) fn invert_lu(a: &SMatrix<f64, 6, 6>) -> Option<Inverse<6>> {
    let (an, scale) = scaled(a);
    let lu = an.lu();
    if lu.determinant().abs() < ACCURACY.min_contour_determinant {
        return None;
    }
    Some(Inverse {
        inv: lu.try_inverse()?,
        scale,
    })
}
