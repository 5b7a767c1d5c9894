//! The fast path's linear algebra without the heap (issue 41): the
//! Jacobian of a mechanism of at most [`MAX`] unknowns, its LU factors and
//! their solves on the stack, by the same arithmetic as nalgebra's
//! (partial pivoting by the first largest magnitude, the multipliers
//! scaled by the pivot's reciprocal, the eliminations and substitutions
//! column by column, the matrix-vector product summed column by column),
//! operation for operation, so to the same bits. Larger systems keep
//! nalgebra's own. The unit tests below compare both on random and
//! singular matrices; `tests/check_golden.rs` the whole check.

use nalgebra::DMatrix;

/// The most unknowns (and equations) held on the stack.
pub(super) const MAX: usize = 9;

/// A vector of the check's (an answer's unknowns, an equation's
/// right-hand side): on the stack up to nine numbers, [`MAX`].
pub type Col = crate::kinematics::analytic::equations::Rows<f64>;

/// A square matrix of at most [`MAX`] rows, column-major as nalgebra's
/// (entry (r, c) at c·n + r).
#[derive(Clone, Copy)]
pub(super) struct Square {
    n: usize,
    a: [f64; MAX * MAX],
}

impl Square {
    /// The n × n zero matrix; `None` above [`MAX`].
    pub(super) fn zeros(n: usize) -> Option<Square> {
        (n <= MAX).then_some(Square {
            n,
            a: [0.0; MAX * MAX],
        })
    }

    pub(super) fn n(&self) -> usize {
        self.n
    }

    /// Adds `v` to entry (r, c).
    pub(super) fn add(&mut self, r: usize, c: usize, v: f64) {
        self.a[c * self.n + r] += v;
    }

    /// Column `c`.
    pub(super) fn column(&self, c: usize) -> &[f64] {
        &self.a[c * self.n..(c + 1) * self.n]
    }

    /// self·x − b, as nalgebra's `&j * x - b`.
    pub(super) fn mul_sub(&self, x: &[f64], b: &[f64]) -> Col {
        // The common sizes (one, two, three moving links) with n known to
        // the compiler (inlined for each constant), as `Square::lu`.
        let out = match self.n {
            3 => self.mul_sub_of(x, b, 3),
            6 => self.mul_sub_of(x, b, 6),
            9 => self.mul_sub_of(x, b, 9),
            n => self.mul_sub_of(x, b, n),
        };
        Col::from_buf_and_len(out, self.n)
    }

    /// [`Square::mul_sub`] of this matrix of `n` unknowns, into the first
    /// n numbers.
    #[inline(always)]
    fn mul_sub_of(&self, x: &[f64], b: &[f64], n: usize) -> [f64; MAX] {
        let mut out = [0.0; MAX];
        let y = &mut out[..n];
        for (c, &xc) in x[..n].iter().enumerate() {
            let col = &self.a[c * n..(c + 1) * n];
            if c == 0 {
                for (y, a) in y.iter_mut().zip(col) {
                    *y = a * xc;
                }
            } else {
                for (y, a) in y.iter_mut().zip(col) {
                    *y += a * xc;
                }
            }
        }
        for (y, b) in y.iter_mut().zip(b) {
            *y -= b;
        }
        out
    }

    /// The same matrix as nalgebra's.
    pub(super) fn to_dmatrix(self) -> DMatrix<f64> {
        DMatrix::from_column_slice(self.n, self.n, &self.a[..self.n * self.n])
    }

    /// The LU factors with partial pivoting, as `nalgebra::LU::new`.
    pub(super) fn lu(&self) -> Lu {
        // The common sizes with n known to the compiler (inlined for each
        // constant); the same operations in the same order.
        match self.n {
            3 => self.lu_of(3),
            6 => self.lu_of(6),
            9 => self.lu_of(9),
            n => self.lu_of(n),
        }
    }

    /// [`Square::lu`] of this matrix of `n` unknowns.
    #[inline(always)]
    fn lu_of(&self, n: usize) -> Lu {
        let mut a = self.a;
        let mut swaps = [(0u8, 0u8); MAX];
        let mut len = 0;
        for i in 0..n {
            let mut piv = i;
            let mut max = a[i * n + i].abs();
            for r in i + 1..n {
                let v = a[i * n + r].abs();
                if v > max {
                    (max, piv) = (v, r);
                }
            }
            let diag = a[i * n + piv];
            if diag == 0.0 {
                continue;
            }
            if piv != i {
                swaps[len] = (i as u8, piv as u8);
                len += 1;
                for c in 0..=i {
                    a.swap(c * n + i, c * n + piv);
                }
            }
            let inv = 1.0 / diag;
            let (left, right) = a.split_at_mut((i + 1) * n);
            let coeffs = &mut left[i * n + i + 1..];
            for x in coeffs.iter_mut() {
                *x *= inv;
            }
            for k in i + 1..n {
                let col = &mut right[(k - i - 1) * n..(k - i) * n];
                if piv != i {
                    col.swap(i, piv);
                }
                let p = col[i];
                for (x, c) in col[i + 1..].iter_mut().zip(coeffs.iter()) {
                    *x += -p * c;
                }
            }
        }
        Lu { n, a, swaps, len }
    }
}

/// LU factors of a [`Square`] ([`Square::lu`]).
#[derive(Clone, Copy)]
pub(crate) struct Lu {
    n: usize,
    a: [f64; MAX * MAX],
    swaps: [(u8, u8); MAX],
    len: usize,
}

impl Lu {
    /// The number of unknowns.
    pub(super) fn n(&self) -> usize {
        self.n
    }

    /// Solves in place as `nalgebra::LU::solve_mut`; false where a pivot
    /// vanishes. (The check solves several at once, [`Lu::solve_rows`];
    /// this one is the unit tests' reference for it.)
    #[cfg(test)]
    fn solve_mut(&self, b: &mut [f64]) -> bool {
        let (n, a) = (self.n, &self.a);
        let b = &mut b[..n];
        for &(i, j) in &self.swaps[..self.len] {
            b.swap(i as usize, j as usize);
        }
        for i in 0..n.saturating_sub(1) {
            let (done, rest) = b.split_at_mut(i + 1);
            let coeff = done[i];
            for (x, l) in rest.iter_mut().zip(&a[i * n + i + 1..(i + 1) * n]) {
                *x += -coeff * l;
            }
        }
        for i in (0..n).rev() {
            let diag = a[i * n + i];
            if diag == 0.0 {
                return false;
            }
            let (rest, done) = b.split_at_mut(i);
            let coeff = done[0] / diag;
            done[0] = coeff;
            for (x, u) in rest.iter_mut().zip(&a[i * n..i * n + i]) {
                *x += -coeff * u;
            }
        }
        true
    }

    /// Solves for `k` right-hand sides at once, in place: `b` holds them
    /// row by row (entry (r, c) at r·k + c). Each column takes exactly the
    /// operations of [`Lu::solve_mut`] in the same order, so the same
    /// bits; the columns' independent divisions and updates interleave
    /// instead of waiting on one another. False where a pivot vanishes.
    pub(super) fn solve_rows(&self, b: &mut [f64], k: usize) -> bool {
        // The common counts with the row's length known to the compiler
        // (its updates unrolled across the columns; each column's
        // operations unchanged).
        match k {
            1 => self.solve_k::<1>(b),
            2 => self.solve_k::<2>(b),
            3 => self.solve_k::<3>(b),
            4 => self.solve_k::<4>(b),
            6 => self.solve_k::<6>(b),
            8 => self.solve_k::<8>(b),
            9 => self.solve_k::<9>(b),
            _ => self.solve_any(b, k),
        }
    }

    /// [`Lu::solve_rows`] of `K` right-hand sides.
    fn solve_k<const K: usize>(&self, b: &mut [f64]) -> bool {
        // The common sizes with n known to the compiler, as `Square::lu`.
        match self.n {
            3 => self.solve_k_of::<K>(b, 3),
            6 => self.solve_k_of::<K>(b, 6),
            9 => self.solve_k_of::<K>(b, 9),
            n => self.solve_k_of::<K>(b, n),
        }
    }

    /// [`Lu::solve_k`] of `n` unknowns.
    #[inline(always)]
    fn solve_k_of<const K: usize>(&self, b: &mut [f64], n: usize) -> bool {
        let a = &self.a;
        let (b, _) = b[..n * K].as_chunks_mut::<K>();
        for &(i, j) in &self.swaps[..self.len] {
            b.swap(i as usize, j as usize);
        }
        for i in 0..n.saturating_sub(1) {
            let (done, rest) = b.split_at_mut(i + 1);
            let coeffs = done[i];
            for (row, l) in rest.iter_mut().zip(&a[i * n + i + 1..(i + 1) * n]) {
                for (x, coeff) in row.iter_mut().zip(&coeffs) {
                    *x += -coeff * l;
                }
            }
        }
        for i in (0..n).rev() {
            let diag = a[i * n + i];
            if diag == 0.0 {
                return false;
            }
            let (rest, done) = b.split_at_mut(i);
            for x in done[0].iter_mut() {
                *x /= diag;
            }
            let coeffs = done[0];
            for (row, u) in rest.iter_mut().zip(&a[i * n..i * n + i]) {
                for (x, coeff) in row.iter_mut().zip(&coeffs) {
                    *x += -coeff * u;
                }
            }
        }
        true
    }

    /// [`Lu::solve_rows`] of any count of right-hand sides.
    fn solve_any(&self, b: &mut [f64], k: usize) -> bool {
        let (n, a) = (self.n, &self.a);
        let b = &mut b[..n * k];
        for &(i, j) in &self.swaps[..self.len] {
            let (i, j) = (i as usize, j as usize);
            for c in 0..k {
                b.swap(i * k + c, j * k + c);
            }
        }
        for i in 0..n.saturating_sub(1) {
            let (done, rest) = b.split_at_mut((i + 1) * k);
            let coeffs = &done[i * k..];
            for (row, l) in rest.chunks_exact_mut(k).zip(&a[i * n + i + 1..(i + 1) * n]) {
                for (x, coeff) in row.iter_mut().zip(coeffs) {
                    *x += -coeff * l;
                }
            }
        }
        for i in (0..n).rev() {
            let diag = a[i * n + i];
            if diag == 0.0 {
                return false;
            }
            let (rest, done) = b.split_at_mut(i * k);
            let coeffs = &mut done[..k];
            for x in coeffs.iter_mut() {
                *x /= diag;
            }
            for (row, u) in rest.chunks_exact_mut(k).zip(&a[i * n..i * n + i]) {
                for (x, coeff) in row.iter_mut().zip(coeffs.iter()) {
                    *x += -coeff * u;
                }
            }
        }
        true
    }

    /// J⁻¹ row by row into `out` (n·n entries), the same bits as
    /// `nalgebra::LU::try_inverse`; false where a pivot vanishes.
    pub(super) fn inverse_rows(&self, out: &mut [f64]) -> bool {
        let n = self.n;
        let out = &mut out[..n * n];
        out.fill(0.0);
        for i in 0..n {
            out[i * n + i] = 1.0;
        }
        self.solve_rows(out, n)
    }

    /// The solution of J·x = b, as `nalgebra::LU::solve`.
    #[cfg(test)]
    fn solve(&self, b: &nalgebra::DVector<f64>) -> Option<nalgebra::DVector<f64>> {
        let mut x = b.clone();
        self.solve_mut(x.as_mut_slice()).then_some(x)
    }

    /// det J, as `nalgebra::LU::determinant`.
    pub(super) fn determinant(&self) -> f64 {
        let mut d = 1.0;
        for i in 0..self.n {
            d *= self.a[i * self.n + i];
        }
        d * if self.len.is_multiple_of(2) { 1.0 } else { -1.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// A small deterministic generator (xorshift), values in [−1, 1].
    fn numbers(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    /// Random matrices of every size, some with repeated, zero or exactly
    /// dependent columns and zeros on the way: the factors, solves,
    /// inverses, determinants and products the same bits as nalgebra's.
    #[test]
    fn same_bits_as_nalgebra() {
        let mut next = numbers(0x9e37_79b9_7f4a_7c15);
        let mut singular = 0;
        for case in 0..3000 {
            let n = 1 + case % MAX;
            let mut sq = Square::zeros(n).unwrap();
            for c in 0..n {
                for r in 0..n {
                    let x = next();
                    // Sparse like a Jacobian, and now and then singular.
                    let v = match case % 5 {
                        0 if x.abs() < 0.5 => 0.0,
                        1 if c == n - 1 && n > 1 => sq.a[r],
                        2 if c == n - 1 => 0.0,
                        _ => x * 10f64.powi((case % 7) as i32 - 3),
                    };
                    sq.add(r, c, v);
                }
            }
            let dm = sq.to_dmatrix();
            let (ours, theirs) = (sq.lu(), dm.clone().lu());
            assert_eq!(
                bits(&ours.a[..n * n]),
                bits(theirs.lu_internal().as_slice()),
                "factors, case {case}"
            );
            assert_eq!(
                ours.determinant().to_bits(),
                theirs.determinant().to_bits(),
                "case {case}"
            );
            let b = DVector::from_fn(n, |_, _| next());
            let x = DVector::from_fn(n, |_, _| next());
            match (ours.solve(&b), theirs.solve(&b)) {
                (Some(p), Some(q)) => assert_eq!(bits(p.as_slice()), bits(q.as_slice())),
                (None, None) => singular += 1,
                other => panic!("case {case}: {other:?}"),
            }
            let inv = theirs.try_inverse();
            let mut rows = [0.0; MAX * MAX];
            assert_eq!(ours.inverse_rows(&mut rows), inv.is_some(), "case {case}");
            if let Some(inv) = &inv {
                assert_eq!(bits(&rows[..n * n]), bits(inv.transpose().as_slice()));
            }
            // Several right-hand sides at once, as many as the check
            // solves together.
            for k in [1, 2, 3, 4, 5, 6, 8, 9] {
                let several = DMatrix::from_fn(n, k, |_, _| next());
                let mut by_rows: Vec<f64> = several.transpose().as_slice().to_vec();
                let solved = theirs.solve(&several);
                assert_eq!(ours.solve_rows(&mut by_rows, k), solved.is_some());
                if let Some(x) = solved {
                    assert_eq!(bits(&by_rows), bits(x.transpose().as_slice()), "case {case}");
                }
            }
            assert_eq!(
                bits(&sq.mul_sub(x.as_slice(), b.as_slice())),
                bits((&dm * &x - &b).as_slice()),
                "case {case}"
            );
        }
        assert!(singular > 100, "{singular} singular cases");
    }
}
