//! [`BestContact`]: `best` for one contact shape, its series interpolated once into cubic
//! pieces in z.

use super::quartic::Quartic;
use super::series::{M1_THIN, Series};
use super::{Branch, assemble, bounded, confocal, inside};
use crate::Real;
use crate::friction::{Constants, SlipState, Traction, larger};
use crate::jacobian::Dual;
use crate::math::Libm;

/// Number of cubic pieces in z of [`BestContact`]: 8 for e² ≤ 0.99, 12 for the thinner
/// patches (m₁ < 0.01), whose coefficients bend faster near the ellipse.
pub(crate) const PIECES: usize = 12;
const PIECES_WIDE: usize = 8;

/// The stored pieces: `[piece][coefficient][monomial]`.
pub(crate) type Pieces<T> = [[[T; 4]; 7]; PIECES];

/// The `best` law for one contact shape (e² fixed): the quartic's constants and the seven
/// outside coefficients as 8 cubic pieces in z, built once by [`BestContact::new`]
/// (see the [module docs](crate::friction::best)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BestContact<T> {
    quartic: Quartic<T>,
    m: T,
    g1: T,
    /// The number of pieces used (8 or 12), as `T` (no `usize` field: the struct has one
    /// layout on every target, which the C API's storage relies on).
    nt: T,
    /// `pieces[i][j]`: cubic in r = n·z − i of coefficient j (monomial, r ∈ [0, 1]).
    pieces: Pieces<T>,
}

impl<T: Real> BestContact<T> {
    /// Measured max error against the exact integrals, every e² of the contract (to m₁ =
    /// 1.70e-5, P/Q = 1e-4), all ψ, u ∈ [0, ∞], `f64` and `f32` (measured 5.2e-5 / 4.0e-6 at
    /// e² = 0.99; ≤ 4.4e-5 / 3.1e-6 beyond): (force in fN, torque in fNa). See
    /// `host-tests/friction_best.rs`.
    pub const ERROR: (f64, f64) = (5.5e-5, 4.5e-6);

    /// From the patch constants: sums the fitted series at this e² and interpolates them at
    /// the Chebyshev–Lobatto nodes r ∈ {0, 1/4, 3/4, 1} of each of 8 pieces (12 for m₁ < 0.01;
    /// a piece's right end is the next one's left end, summed once). Total.
    pub fn new(k: &Constants<T>) -> Self {
        let quartic = Quartic::new(k);
        let gamma = k.m1().sqrt();
        let series = Series::new::<Libm>(k, &quartic, gamma);
        let mut pieces: Pieces<T> = [[[T::ZERO; 4]; 7]; PIECES];
        let n = if k.m1() >= T::from_f64(M1_THIN) {
            PIECES_WIDE
        } else {
            PIECES
        };
        let nt = T::from_usize(n);
        // Inverse Vandermonde of the nodes: monomial coefficients from node values.
        let inv: [[f64; 4]; 4] = [
            [1.0, 0.0, 0.0, 0.0],
            [-19.0 / 3.0, 8.0, -8.0 / 3.0, 1.0],
            [32.0 / 3.0, -56.0 / 3.0, 40.0 / 3.0, -16.0 / 3.0],
            [-16.0 / 3.0, 32.0 / 3.0, -32.0 / 3.0, 16.0 / 3.0],
        ];
        let half = series.at(T::HALF / nt);
        // a piece's right end is the next piece's left end: summed once
        let mut left = series.at(T::ZERO);
        for (i, piece) in pieces.iter_mut().take(n).enumerate() {
            let at = |r: f64| series.at((T::from_usize(i) + T::from_f64(r)) / nt);
            let vals = [left, at(0.25), at(0.75), at(1.0)];
            left = vals[3];
            for (j, cubic) in piece.iter_mut().enumerate() {
                // Coefficient j at the four nodes (`get` keeps the build provably panic-free).
                let col = vals.map(|v| v.get(j).copied().unwrap_or(T::ZERO));
                for (cp, row) in cubic.iter_mut().zip(inv.iter()) {
                    *cp = row
                        .iter()
                        .zip(col.iter())
                        .fold(T::ZERO, |acc, (&w, &v)| acc + T::from_f64(w) * v);
                }
                // exact at the left end, and at the right end up to one rounding of the sum
                // (the inverse Vandermonde's entries up to 56/3 would amplify rounding).
                let [c0, c1, c2, _] = *cubic;
                cubic[0] = col[0];
                cubic[3] = col[3] - c0 - c1 - c2;
                if i == 0 {
                    // At the ellipse the coefficients grow like z² (zero slope): keep it, so
                    // the law has no √-like onset there. c₀ + c₂r² + c₃r³ through r = 1/2, 1.
                    let half_j = half.get(j).copied().unwrap_or(T::ZERO);
                    let (h, e) = (half_j - col[0], col[3] - col[0]);
                    let eight = T::from_f64(8.0);
                    cubic[1] = T::ZERO;
                    cubic[3] = T::TWO * e - eight * h;
                    cubic[2] = e - cubic[3];
                }
            }
        }
        if let Some(end) = pieces.get_mut(n) {
            // z = 1 (u = ∞) with fewer pieces than the storage: a constant piece, the value there
            for (cubic, &v) in end.iter_mut().zip(left.iter()) {
                *cubic = [v, T::ZERO, T::ZERO, T::ZERO];
            }
        }
        BestContact {
            quartic,
            m: k.m(),
            g1: T::ONE + gamma,
            nt,
            pieces,
        }
    }

    /// The parts the batch kernel (src/batch/best.rs) reads: the quartic, m, 1 + γ, the number
    /// of pieces used (as `T`) and the pieces.
    #[inline(always)]
    pub(crate) fn parts(&self) -> (&Quartic<T>, T, T, T, &Pieces<T>) {
        (&self.quartic, self.m, self.g1, self.nt, &self.pieces)
    }

    /// The dimensionless traction (F/(fN), T_z/(fNa)) and the branch for a slip state.
    /// Total: finite output for every state.
    #[inline(always)]
    pub fn traction(&self, s: &SlipState<T>) -> (Traction<T>, Branch) {
        if let Some(r) = inside(&self.quartic, s) {
            return r;
        }
        let (c, sn, tau, one_minus) = confocal(self.m, self.g1, s.x(), s.y(), s.w());
        let zn = larger(one_minus, T::ZERO).sqrt() * self.nt;
        // with 8 pieces, z = 1 lands on the constant piece 8 (its value at u = ∞)
        let i = zn.trunc_usize().min(PIECES - 1);
        let r = zn - T::from_usize(i);
        let piece = &self.pieces[i];
        let co = piece.map(|p| p[0] + r * (p[1] + r * (p[2] + r * p[3])));
        (bounded(assemble(c, sn, tau, &co)), Branch::Outside)
    }

    /// [`BestContact::traction`] on a dual slip state: the same operations, the constants
    /// lifted where they are read (the quartic's twelve, and only the piece in use, not the
    /// tables), so that the value is the plain call's bit for bit.
    #[inline(always)]
    pub(crate) fn traction_dual<const K: usize>(
        &self,
        s: &SlipState<Dual<T, K>>,
    ) -> (Traction<Dual<T, K>>, Branch) {
        let lift = Dual::<T, K>::constant;
        if let Some(r) = inside(&self.quartic.map(lift), s) {
            return r;
        }
        let (c, sn, tau, one_minus) = confocal(lift(self.m), lift(self.g1), s.x(), s.y(), s.w());
        let zn = larger(one_minus, Dual::ZERO).sqrt() * lift(self.nt);
        let i = zn.trunc_usize().min(PIECES - 1);
        let r = zn - Dual::from_usize(i);
        let piece = &self.pieces[i];
        let co = piece.map(|p| lift(p[0]) + r * (lift(p[1]) + r * (lift(p[2]) + r * lift(p[3]))));
        (bounded(assemble(c, sn, tau, &co)), Branch::Outside)
    }
}
