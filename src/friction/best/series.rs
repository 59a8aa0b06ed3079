//! The fitted series of `best`'s outside coefficients, summed at one e²: what
//! [`BestContact::new`](super::BestContact::new) interpolates once per contact, and the
//! per-call reference form [`BestSeries`] (693 terms per call; [`Best`](super::Best)'s per-step
//! form takes the coefficients from a flash table instead).

use super::quartic::Quartic;
use super::{Branch, table, table_thin};
use crate::Real;
use crate::friction::{Constants, FrictionLaw, SlipState, Traction};
use crate::math::{Backend, Libm};

/// m₁ below which the thin-patch series (`table_thin.rs`, e² > 0.99) replaces the wide one
/// (`table.rs`, e² ∈ [0, 0.99]).
pub(super) const M1_THIN: f64 = table::G0 * table::G0;

/// Terms in ẑ of the wide and the thin table.
const NW: usize = table::DZ + 1;
const NT: usize = table_thin::DZ + 1;

/// The seven outside coefficients as functions of z at one e²: the wide series (e² ≤ 0.99) or
/// the thin one, each with its fixed length (so every loop over it has a fixed trip count).
pub(super) enum Series<T> {
    Wide(Fit<T, NW>),
    Thin(Fit<T, NT>),
}

/// `d[j][l]` Chebyshev coefficients in ẑ = 2z − 1 (e² fixed) of coefficient j, corrected to
/// the exact ends.
pub(super) struct Fit<T, const Z: usize> {
    d: [[T; Z]; 7],
    /// Exact minus series at z = 0 and at z = 1.
    end0: [T; 7],
    end1: [T; 7],
}

impl<T: Real, const Z: usize> Fit<T, Z> {
    /// Sums a table's series in λ (clamped to [−1, 1]) and corrects it to the exact ends
    /// (`bnd` on the ellipse, `inf` at u = ∞).
    fn new<const G: usize>(table: &[[[f32; Z]; G]; 7], lam: T, bnd: [T; 7], inf: [T; 7]) -> Self {
        let lam = lam.max(-T::ONE).min(T::ONE);
        let mut tk = [T::ZERO; G];
        let (mut t0, mut t1) = (T::ONE, lam);
        for t in tk.iter_mut() {
            *t = t0;
            let t2 = T::TWO * lam * t1 - t0;
            (t0, t1) = (t1, t2);
        }
        let mut d = [[T::ZERO; Z]; 7];
        for (dj, tj) in d.iter_mut().zip(table.iter()) {
            for (row, &t) in tj.iter().zip(tk.iter()) {
                for (dl, &c) in dj.iter_mut().zip(row.iter()) {
                    *dl += T::from_f64(f64::from(c)) * t;
                }
            }
        }
        let mut end0 = [T::ZERO; 7];
        let mut end1 = [T::ZERO; 7];
        for (((dj, e0), e1), (b, i)) in d
            .iter()
            .zip(end0.iter_mut())
            .zip(end1.iter_mut())
            .zip(bnd.iter().zip(inf.iter()))
        {
            let (mut at0, mut at1, mut sign) = (T::ZERO, T::ZERO, T::ONE);
            for &c in dj.iter() {
                at0 += sign * c;
                at1 += c;
                sign = -sign;
            }
            *e0 = *b - at0;
            *e1 = *i - at1;
        }
        Fit { d, end0, end1 }
    }

    /// The seven coefficients at z ∈ [0, 1].
    #[inline(always)]
    fn at(&self, z: T) -> [T; 7] {
        let zh = T::TWO * z - T::ONE;
        let mut out = [T::ZERO; 7];
        for (((o, dj), &e0), &e1) in out
            .iter_mut()
            .zip(self.d.iter())
            .zip(self.end0.iter())
            .zip(self.end1.iter())
        {
            // Clenshaw
            let (mut b1, mut b2) = (T::ZERO, T::ZERO);
            for &c in dj.iter().skip(1).rev() {
                let b0 = T::TWO * zh * b1 - b2 + c;
                (b1, b2) = (b0, b1);
            }
            let d0 = dj.first().copied().unwrap_or(T::ZERO);
            // z² shapes: the ends are corrected without adding slope at z = 0.
            let z2 = z * z;
            *o = zh * b1 - b2 + d0 + e0 * (T::ONE - z2) + e1 * z2;
        }
        out
    }
}

impl<T: Real> Series<T> {
    pub(super) fn new<B: Backend>(k: &Constants<T>, q: &Quartic<T>, gamma: T) -> Self {
        let ln_m1 = B::ln(k.m1());
        let g5 = T::from_f64(0.4) / (T::ONE + gamma);
        let inf = [T::ONE, T::ZERO, T::ONE, T::ZERO, -g5, g5 * k.m(), T::ZERO];
        let bnd = q.boundary(gamma);
        // e² ∈ [0, 0.99]: λ = 1 + log₁₀ m₁; beyond, the thin-patch table in ln m₁ down to
        // m₁ = 9e-6 (past the contract's end, 1.70e-5 at P/Q = 1e-4; λ clamped below that).
        if k.m1() >= T::from_f64(M1_THIN) {
            let lam = ln_m1 * T::from_f64(table::LAM_SCALE) - T::from_f64(table::LAM_SHIFT);
            Series::Wide(Fit::new(&table::TABLE, lam, bnd, inf))
        } else {
            let lam =
                ln_m1 * T::from_f64(table_thin::LAM_SCALE) - T::from_f64(table_thin::LAM_SHIFT);
            Series::Thin(Fit::new(&table_thin::TABLE, lam, bnd, inf))
        }
    }

    /// The seven coefficients at z ∈ [0, 1].
    pub(super) fn at(&self, z: T) -> [T; 7] {
        match self {
            Series::Wide(f) => f.at(z),
            Series::Thin(f) => f.at(z),
        }
    }
}

/// `best` with the fitted series summed per call (the form [`Best`](super::Best)'s
/// `traction` had before the flash table): the reference for the table and its fallback. Same
/// inside-the-ellipse quartic, branches and domain; outside, the 693-term series at this e².
/// Measured max error against the exact integrals (`host-tests/friction_best.rs`): e² ∈ [0, 0.99]
/// 1.8e-6 fN / 7.4e-7 fNa (`f64`), 2.0e-6 / 8.7e-7 (`f32`); the thin patches (e² from 0.99 to
/// the contract's end, the second series) 3.3e-5 / 7.9e-7, both precisions. Cost: M4F 1,324 instructions on
/// average per dimensionless call (`f32`, 106 … 3,103), 87,114 in `f64`; host ≈ 100 ns. For
/// per-step use take [`Best`](super::Best) (the flash table, a fraction of the cost).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BestSeries;

impl BestSeries {
    /// Measured max error against the exact integrals, every e² of the contract (to m₁ =
    /// 1.70e-5), all ψ, u ∈ [0, ∞] (`f64`; measured 1.8e-6 / 7.4e-7 for e² ≤ 0.99, 3.3e-5 /
    /// 7.4e-7 on the thin-patch series): (force in fN, torque in fNa).
    pub const ERROR: (f64, f64) = (4.0e-5, 1.0e-6);

    fn per_call<B: Backend, T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        super::per_call(k, s, |q, gamma, z| Series::new::<B>(k, q, gamma).at(z))
    }
}

/// `impl FrictionLaw for $law`: the per-call series with the backend `$backend` (its `ln`).
macro_rules! series_law {
    ($(#[$attr:meta])* $law:ident, $name:literal, $backend:ty) => {
        $(#[$attr])*
        impl FrictionLaw for $law {
            const NAME: &'static str = $name;
            type Branch = Branch;
            const RAMP_BELOW_DELTA: bool = true;

            super::best_ramps!();
            crate::friction::law::constants_are_prepared!();

            fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
                BestSeries::per_call::<$backend, T>(k, s)
            }
        }
    };
}

series_law!(BestSeries, "best-series", Libm);

/// [`BestSeries`] with micromath's `ln` for the series' λ = 1 + log₁₀ m₁ (feature
/// `micromath`; `f32` only, libm for `f64`). The square roots stay [`Real::sqrt`] (the
/// confocal coordinates need them exact). [`FrictionLaw::prepare`] gives the [`Constants`]
/// unchanged: the per-contact form of `best` is [`BestContact`](super::BestContact), which
/// calls no `ln`.
///
/// Formula, domain, branches: as [`BestSeries`]; `f64` is [`BestSeries`]. Measured max error
/// against the exact integrals (`f32`, the 4,329 states of host-tests/micromath.rs, asserted
/// there): **2.6e-6 fN / 8.9e-7 fNa** ([`BestSeries`]: 2.0e-6 / 8.8e-7 on the same set). Cost:
/// M4F **1,298** instructions on average (`f32`; [`BestSeries`] 1,324), host ≈ 195 ns. No
/// longer chosen anywhere: [`Best`](super::Best)'s per-step flash-table form calls no `ln` and
/// costs 271.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BestMicromath;

series_law!(
    #[cfg(feature = "micromath")]
    #[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
    BestMicromath,
    "best-micromath",
    crate::math::Micromath
);
