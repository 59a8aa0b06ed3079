//! The validated time step Δt and the contact-space inverse-mass matrix W.
//!
//! # W
//!
//! For K contacts, u = (u₁, …, u_K) with uᵢ = (v_n, v_x, v_y, ω) of body B relative to body A
//! at contact i, in contact i's frame (v_n = −ḣ: separation speed; crate conventions). An
//! impulse Δt·wⱼ on B (and its opposite on A) at contact j, wⱼ = (N, F_x, F_y, T_z) in contact
//! j's frame, changes uᵢ by Δt·W_ij·wⱼ: W = J M⁻¹ Jᵀ, K × K blocks of 4 × 4 (W_ij couples
//! contact i's velocity to contact j's wrench; W_ji = W_ijᵀ). [`crate::step::Body`] builds it
//! from rigid bodies.
//!
//! # Validation (fixed cost)
//!
//! - every entry finite ([`Error::NonFinite`] `"W"`);
//! - diagonal entries ≥ 0 ([`Error::InverseMassNotPositiveSemidefinite`]);
//! - symmetric: |W_ab − W_ba| ≤ [`SYMMETRY_TOLERANCE`]·√(W_aa·W_bb) (relative to the
//!   diagonal, so that W may mix units: 1/kg against 1/(kg·m²)); a zero diagonal entry (a
//!   direction no impulse moves, e.g. both bodies fixed there) needs its row and column exactly
//!   zero: W_ab ≠ W_ba there is [`Error::InverseMassNotSymmetric`], W_ab = W_ba ≠ 0 breaks
//!   W_ab² ≤ W_aa·W_bb ([`Error::InverseMassNotPositiveSemidefinite`]). The stored matrix is (W + Wᵀ)/2. A W assembled as
//!   L·Lᵀ (or J·M⁻¹·Jᵀ) in floating point is positive semidefinite as rounded only if its
//!   diagonal does not underflow: with entries below √`T::MIN_POSITIVE` relative to the others
//!   (f32: 1.1e-19) a diagonal entry can round to 0 or lose its digits while its row keeps
//!   them, and W is refused as not positive semidefinite — scale the units (the fuzz target
//!   `step` accepts every L·Lᵀ whose factors are 0 or within [1e-6, 1e6] in magnitude).
//! - positive semidefinite: the LDLᵀ factorisation of the diagonally scaled matrix
//!   S = D^{-1/2} W D^{-1/2} (unit diagonal; D = diag W) with a pivot floor: a pivot below
//!   −[`PSD_TOLERANCE`] is an error, a pivot within ±[`PSD_TOLERANCE`] is taken as zero (its
//!   column must then vanish to the same tolerance), else it factorises. The floor is
//!   absolute: a rank-deficient W whose dependent row repeats an ill-conditioned combination
//!   of the rows before it can be refused by its own rounding (f64 W = L·Lᵀ with |L_jk| ≈ 33
//!   in the scaled factor: pivot −2.1e-13 against 5.7e-14; a floor growing as
//!   (1 + Σ_k |L_jk|)² accepts it but changes which W the scenes' fallback sees — not done). n = 4K rows: n³/6
//!   multiply-adds, no branch on the data beyond the pivot tests.

use crate::error::finite;
use crate::{Error, Real};

/// Relative symmetry tolerance of [`InverseMass`], in units of the precision's machine epsilon:
/// |W_ab − W_ba| ≤ 64·ε·√(W_aa·W_bb), i.e. 7.6e-6 (`f32`), 1.4e-14 (`f64`) — what rounding
/// leaves when a caller builds the two halves by different arithmetic.
pub const SYMMETRY_TOLERANCE: f64 = 64.0;

/// Pivot tolerance of the positive-semidefinite check on the unit-diagonal scaled matrix, in
/// units of machine epsilon: 256·ε (`f32` 3.1e-5, `f64` 5.7e-14).
pub const PSD_TOLERANCE: f64 = 256.0;

fn symmetry_tolerance<T: Real>() -> T {
    T::EPSILON * T::from_f64(SYMMETRY_TOLERANCE)
}

/// A validated time step Δt > 0 (s), finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeStep<T>(T);

impl<T: Real> TimeStep<T> {
    /// Errors: [`Error::NonFinite`] `"dt"` for NaN or ±∞, [`Error::StepNotPositive`] for
    /// Δt ≤ 0 (including −0 and subnormal zero-like values are accepted if > 0).
    pub fn new(dt: T) -> Result<Self, Error> {
        let dt = finite(dt, "dt")?;
        if dt > T::ZERO {
            Ok(TimeStep(dt))
        } else {
            Err(Error::StepNotPositive)
        }
    }

    /// Δt (s).
    #[inline(always)]
    pub fn get(&self) -> T {
        self.0
    }
}

/// The validated inverse-mass matrix W of K contacts (4K × 4K, K × K blocks of 4 × 4; see the
/// [module docs](self)). `block(i, j)[a][b]` = ∂(uᵢ)_a/∂(Δt·wⱼ)_b.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InverseMass<T, const K: usize> {
    blocks: [[[[T; 4]; 4]; K]; K],
}

impl<T: Real> InverseMass<T, 1> {
    /// One contact's 4 × 4 W (rows and columns (v_n, v_x, v_y, ω)). Same errors as
    /// [`InverseMass::new`].
    pub fn single(w: [[T; 4]; 4]) -> Result<Self, Error> {
        Self::new([[w]])
    }

    /// One contact's W from its ten upper-triangle entries in the order
    /// `w_nn, w_nx, w_ny, w_nw, w_xx, w_xy, w_xw, w_yy, w_yw, w_ww` (w = spin), as the
    /// `contact_eval step` columns. Same errors as [`InverseMass::new`] (symmetric by
    /// construction).
    pub fn from_upper(u: [T; 10]) -> Result<Self, Error> {
        let [nn, nx, ny, nw, xx, xy, xw, yy, yw, ww] = u;
        Self::single([
            [nn, nx, ny, nw],
            [nx, xx, xy, xw],
            [ny, xy, yy, yw],
            [nw, xw, yw, ww],
        ])
    }
}

impl<T: Real, const K: usize> InverseMass<T, K> {
    /// From the K × K blocks (`blocks[i][j]` = W_ij). Validates (see the [module docs](self)):
    /// [`Error::NonFinite`] `"W"`, [`Error::InverseMassNotSymmetric`],
    /// [`Error::InverseMassNotPositiveSemidefinite`]. Stores the symmetric part.
    pub fn new(blocks: [[[[T; 4]; 4]; K]; K]) -> Result<Self, Error> {
        let w = InverseMass { blocks };
        let n = 4 * K;
        for r in 0..n {
            for c in 0..n {
                finite(w.get(r, c), "W")?;
            }
        }
        for r in 0..n {
            if w.get(r, r) < T::ZERO {
                return Err(Error::InverseMassNotPositiveSemidefinite);
            }
        }
        let tol = symmetry_tolerance::<T>();
        let mut sym = w;
        for r in 0..n {
            for c in (r + 1)..n {
                let (a, b) = (w.get(r, c), w.get(c, r));
                let scale = (w.get(r, r) * w.get(c, c)).sqrt();
                if scale == T::ZERO {
                    // A zero diagonal entry with a non-zero entry in its row: no tolerance
                    // scales there, so W_ab ≠ W_ba is the asymmetry; W_ab = W_ba ≠ 0 breaks
                    // W_ab² ≤ W_aa·W_bb = 0, not positive semidefinite (a W = L·Lᵀ whose
                    // diagonal entry underflowed to 0 while its row did not, as rounded).
                    if a != b {
                        return Err(Error::InverseMassNotSymmetric);
                    }
                    if a != T::ZERO {
                        return Err(Error::InverseMassNotPositiveSemidefinite);
                    }
                } else if (a - b).abs() > tol * scale {
                    return Err(Error::InverseMassNotSymmetric);
                }
                let m = (a + b) * T::HALF;
                sym.set(r, c, m);
                sym.set(c, r, m);
            }
        }
        if !sym.semidefinite() {
            return Err(Error::InverseMassNotPositiveSemidefinite);
        }
        Ok(sym)
    }

    /// Block W_ij (contact i's velocity from contact j's wrench); zero out of range.
    #[inline(always)]
    pub fn block(&self, i: usize, j: usize) -> [[T; 4]; 4] {
        self.blocks
            .get(i)
            .and_then(|row| row.get(j))
            .copied()
            .unwrap_or([[T::ZERO; 4]; 4])
    }

    /// All blocks.
    #[inline(always)]
    pub fn blocks(&self) -> &[[[[T; 4]; 4]; K]; K] {
        &self.blocks
    }

    /// Entry (r, c) of the 4K × 4K matrix (r = 4i + a). Out of range: 0.
    #[inline(always)]
    pub fn get(&self, r: usize, c: usize) -> T {
        match self.blocks.get(r / 4).and_then(|row| row.get(c / 4)) {
            Some(b) => b[r % 4][c % 4],
            None => T::ZERO,
        }
    }

    #[inline(always)]
    fn set(&mut self, r: usize, c: usize, v: T) {
        if let Some(b) = self
            .blocks
            .get_mut(r / 4)
            .and_then(|row| row.get_mut(c / 4))
        {
            b[r % 4][c % 4] = v;
        }
    }

    /// (W·x)_r for x given per contact.
    #[inline]
    pub(crate) fn row_times(&self, r: usize, x: &[[T; 4]; K]) -> T {
        let mut s = T::ZERO;
        // Zipped, not indexed by j: when this is not inlined (opt-level z), `row[j]` kept a
        // bounds check (a panic path, tools/no-panic.sh).
        if let Some(blocks) = self.blocks.get(r / 4) {
            for (b, xj) in blocks.iter().zip(x.iter()) {
                let row = &b[r % 4];
                s += row[0] * xj[0] + row[1] * xj[1] + row[2] * xj[2] + row[3] * xj[3];
            }
        }
        s
    }

    /// LDLᵀ of the unit-diagonal scaling with the pivot floor (module docs). True when
    /// positive semidefinite within [`PSD_TOLERANCE`] ulps.
    fn semidefinite(&self) -> bool {
        let n = 4 * K;
        let tol = T::EPSILON * T::from_f64(PSD_TOLERANCE);
        // Scaled copy S, factorised in place (lower triangle: L below the diagonal, D on it).
        let mut s = *self;
        let isq = |r: usize| {
            let d = self.get(r, r);
            if d > T::ZERO {
                T::ONE / d.sqrt()
            } else {
                T::ZERO
            }
        };
        for r in 0..n {
            for c in 0..n {
                s.set(r, c, self.get(r, c) * isq(r) * isq(c));
            }
        }
        for j in 0..n {
            // d_j = S_jj − Σ_k<j L_jk² d_k
            let mut d = s.get(j, j);
            for k in 0..j {
                let l = s.get(j, k);
                d -= l * l * s.get(k, k);
            }
            if d < -tol {
                return false;
            }
            let zero_pivot = d <= tol;
            s.set(j, j, if zero_pivot { T::ZERO } else { d });
            for i in (j + 1)..n {
                // S_ij − Σ_k<j L_ik L_jk d_k
                let mut v = s.get(i, j);
                for k in 0..j {
                    v -= s.get(i, k) * s.get(j, k) * s.get(k, k);
                }
                if zero_pivot {
                    // A (near-)zero pivot: the rest of its column must vanish too (a 2 × 2
                    // minor d·S_ii − v² ≥ 0 with d ≈ 0 forces v ≈ 0).
                    if v.abs() > tol.sqrt() {
                        return false;
                    }
                    s.set(i, j, T::ZERO);
                } else {
                    s.set(i, j, v / d);
                }
            }
        }
        true
    }
}
