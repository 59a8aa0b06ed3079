//! The dense linear solve of the step: (I − Δt·G·W)·w̄ = r on the active contacts, by Gaussian
//! elimination with partial pivoting over the 4K × 4K block layout. Fixed cost for a given K
//! (n = 4K: n³/3 multiply-adds), no allocation.

use crate::Real;

/// A 4K × 4K matrix in K × K blocks of 4 × 4.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Blocks<T, const K: usize>(pub(crate) [[[[T; 4]; 4]; K]; K]);

impl<T: Real, const K: usize> Blocks<T, K> {
    pub(crate) fn zero() -> Self {
        Blocks([[[[T::ZERO; 4]; 4]; K]; K])
    }

    #[inline(always)]
    pub(crate) fn get(&self, r: usize, c: usize) -> T {
        match self.0.get(r / 4).and_then(|row| row.get(c / 4)) {
            Some(b) => b[r % 4][c % 4],
            None => T::ZERO,
        }
    }

    #[inline(always)]
    pub(crate) fn set(&mut self, r: usize, c: usize, v: T) {
        if let Some(b) = self.0.get_mut(r / 4).and_then(|row| row.get_mut(c / 4)) {
            b[r % 4][c % 4] = v;
        }
    }
}

#[inline(always)]
fn at<T: Real, const K: usize>(x: &[[T; 4]; K], r: usize) -> T {
    x.get(r / 4).map_or(T::ZERO, |b| b[r % 4])
}

#[inline(always)]
fn put<T: Real, const K: usize>(x: &mut [[T; 4]; K], r: usize, v: T) {
    if let Some(b) = x.get_mut(r / 4) {
        b[r % 4] = v;
    }
}

/// Solves m·x = rhs in place (x returned in `rhs`). `false` (and `rhs` unspecified) when a
/// pivot is zero or not finite, or the solution is not finite: the caller falls back.
pub(crate) fn solve<T: Real, const K: usize>(m: &mut Blocks<T, K>, rhs: &mut [[T; 4]; K]) -> bool {
    let n = 4 * K;
    for col in 0..n {
        // Partial pivoting: the largest magnitude in this column at or below the diagonal.
        let mut p = col;
        let mut best = m.get(col, col).abs();
        for r in (col + 1)..n {
            let v = m.get(r, col).abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        if !(best > T::ZERO) || !best.is_finite() {
            return false;
        }
        if p != col {
            for c in 0..n {
                let (a, b) = (m.get(col, c), m.get(p, c));
                m.set(col, c, b);
                m.set(p, c, a);
            }
            let (a, b) = (at(rhs, col), at(rhs, p));
            put(rhs, col, b);
            put(rhs, p, a);
        }
        let piv = m.get(col, col);
        for r in (col + 1)..n {
            let f = m.get(r, col) / piv;
            if f != T::ZERO {
                for c in (col + 1)..n {
                    m.set(r, c, m.get(r, c) - f * m.get(col, c));
                }
                put(rhs, r, at(rhs, r) - f * at(rhs, col));
            }
            m.set(r, col, T::ZERO);
        }
    }
    for r in (0..n).rev() {
        let mut s = at(rhs, r);
        for c in (r + 1)..n {
            s -= m.get(r, c) * at(rhs, c);
        }
        let x = s / m.get(r, r);
        if !x.is_finite() {
            return false;
        }
        put(rhs, r, x);
    }
    true
}
