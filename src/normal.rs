//! Normal contact: approach h (and its rate ḣ) → contact patch (a, b, N, p0) for a fixed
//! geometry, by exact Hertz or by the eccentricity-free volumetric law, with optional damping.
//!
//! # Hertz (model.md §1)
//!
//! With the shape (c, K, E, B, D) from [`crate::shape`] and the effective modulus E*:
//!
//! ```text
//! a² = h·D/(P·K),   b² = (1 − c)·a² = h·B/(Q·K),   N = k_H·h^{3/2},
//! k_H = (2π/3)·E*·√(D/P)/K^{3/2}   (so N = (2π/3)·E*·h·a/K),
//! p0 = 3N/(2πab) = E*·h/(K·b),     U = (2/5)·N·h   (elastic energy)
//! ```
//!
//! Everything but h is folded into four constants when the law is built, so the per-step call
//! [`NormalLaw::patch`] costs one square root and four multiplies: a = a′√h, b = b′√h,
//! N = k_H·h·√h, p0 = p0′√h.
//!
//! # Contact loss
//!
//! h ≤ 0 (or NaN) → [`Patch::empty`]: zero force and a zero-size patch. Not an error.
//!
//! # Example
//!
//! ```
//! use contensou::geometry::{Curvatures, Race};
//! use contensou::normal::{Hertz, Material, Modulus, NormalLaw, HuntCrossley};
//! use contensou::shape::Newton;
//!
//! // 209 bearing, ball on the inner race: built once.
//! let curv = Curvatures::ball_race(0.0127, 0.0066, 0.065, 0.0, Race::Inner)?;
//! let steel = Material::new(2.08e11, 0.3)?;
//! let law = Hertz::new::<Newton>(&curv, Modulus::of(steel, steel)?)?;
//! // Per step: a square root and a few multiplies.
//! let patch = law.patch(5e-6);
//! assert!(patch.a > patch.b && patch.n > 0.0);
//! let damped = law.damped_patch(5e-6, 0.01, &HuntCrossley::new(0.3)?);
//! assert!(damped.n > patch.n);
//! assert!(law.patch(-1e-6).is_empty()); // contact loss is not an error
//! # Ok::<(), contensou::Error>(())
//! ```

mod fit_data;

use crate::error::finite;
use crate::geometry::{Curvatures, positive};
use crate::math::{Backend, Libm};
use crate::shape::{Eccentricity, Ratio, Shape};
use crate::{Error, Real};

/// One body's elastic material: Young's modulus E (Pa) and Poisson's ratio ν, validated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material<T> {
    young: T,
    poisson: T,
}

impl<T: Real> Material<T> {
    /// E > 0, ν ∈ (−1, 0.5]. Errors: [`Error::ModulusNotPositive`],
    /// [`Error::PoissonRatioOutOfRange`], [`Error::NonFinite`].
    pub fn new(young: T, poisson: T) -> Result<Self, Error> {
        let young = finite(young, "Young's modulus")?;
        let poisson = finite(poisson, "Poisson's ratio")?;
        if !positive(young) {
            return Err(Error::ModulusNotPositive);
        }
        if !(poisson > -T::ONE && poisson <= T::HALF) {
            return Err(Error::PoissonRatioOutOfRange);
        }
        Ok(Material { young, poisson })
    }

    /// Young's modulus E (Pa).
    pub fn young(&self) -> T {
        self.young
    }
    /// Poisson's ratio ν.
    pub fn poisson(&self) -> T {
        self.poisson
    }
}

/// The effective (contact) modulus E* (Pa), validated: finite and > 0.
///
/// # Example
///
/// ```
/// use contensou::normal::{Material, Modulus};
///
/// // Steel on steel: E* = E/(2(1 − ν²)).
/// let steel = Material::new(2.1e11_f64, 0.3)?;
/// let estar = Modulus::of(steel, steel)?;
/// assert!((estar.get() / (2.1e11 / (2.0 * (1.0 - 0.09))) - 1.0).abs() < 1e-12);
/// // Given directly, e.g. wood (E = 9.1e9 Pa, ν = 0.3) on a rigid floor: E* = E/(1 − ν²).
/// let wood = Modulus::new(9.1e9_f64 / (1.0 - 0.09))?;
/// assert!((wood.get() - 1e10).abs() < 1.0 && Modulus::<f64>::new(0.0).is_err());
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Modulus<T>(T);

impl<T: Real> Modulus<T> {
    /// From E* directly. Errors: [`Error::ModulusNotPositive`], [`Error::NonFinite`].
    pub fn new(estar: T) -> Result<Self, Error> {
        let estar = finite(estar, "E*")?;
        if estar > T::ZERO {
            Ok(Modulus(estar))
        } else {
            Err(Error::ModulusNotPositive)
        }
    }

    /// 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂. Errors: [`Error::ModulusNotPositive`] if the result
    /// under- or overflows (e.g. E below ≈1e-38 Pa in `f32`).
    pub fn of(a: Material<T>, b: Material<T>) -> Result<Self, Error> {
        let compliance = (T::ONE - a.poisson.sq()) / a.young + (T::ONE - b.poisson.sq()) / b.young;
        let estar = T::ONE / compliance;
        if estar.is_finite() && estar > T::ZERO {
            Ok(Modulus(estar))
        } else {
            Err(Error::ModulusNotPositive)
        }
    }

    /// E* (Pa)
    #[inline(always)]
    pub fn get(self) -> T {
        self.0
    }
}

/// The contact patch at one step: what the friction law and the wrench consume.
///
/// Contact frame per the crate conventions: x along the major semi-axis `a`, y along the minor
/// semi-axis `b`. Pressure σ(x, y) = p0·√(1 − x²/a² − y²/b²), whose integral is the elastic
/// normal force. On contact loss every length and force is 0 (see [`Patch::empty`]); `e2`, `m1`
/// still describe the geometry.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Patch<T> {
    /// Approach h (m): penetration of distant points; > 0 in contact.
    pub h: T,
    /// Major semi-axis a (m), along x.
    pub a: T,
    /// Minor semi-axis b = a√(1 − e²) (m), along y.
    pub b: T,
    /// Normal force N ≥ 0 (N) on body B from body A along +z, including damping if any.
    pub n: T,
    /// Peak pressure p0 = 3N_el/(2πab) (Pa) of the elastic (Hertz) pressure distribution.
    pub p0: T,
    /// e² = c = 1 − b²/a²: the elliptic parameter m of the friction integrals.
    pub e2: T,
    /// m₁ = 1 − e² = (b/a)², kept to full relative precision for elongated patches.
    pub m1: T,
}

impl<T: Real> Patch<T> {
    /// Contact loss: h = a = b = N = p0 = 0, with the geometry's e², m₁.
    #[inline(always)]
    pub fn empty(e2: T, m1: T) -> Self {
        Patch {
            h: T::ZERO,
            a: T::ZERO,
            b: T::ZERO,
            n: T::ZERO,
            p0: T::ZERO,
            e2,
            m1,
        }
    }

    /// No contact (N = 0 and a = 0).
    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        self.a == T::ZERO
    }
}

/// A damping law: the total normal force from the elastic force and (h, ḣ). ḣ > 0 is
/// compression (approach growing). The result is clamped to ≥ 0 by the caller (no adhesion).
pub trait Damping<T> {
    /// `true` only for a law whose [`Damping::force`] returns `elastic` unchanged
    /// ([`Undamped`]): [`NormalLaw::damped_patch`] then returns the elastic patch as it is,
    /// with no force call and no clamp (a normal law's elastic force is already ≥ 0, see
    /// [`Patch::n`]). Default `false`.
    const ELASTIC: bool = false;

    /// Total normal force before clamping, given the elastic force `elastic` = k_H h^{3/2}.
    fn force(&self, elastic: T, h: T, hdot: T) -> T;
}

/// No damping: N = N_el.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Undamped;

impl<T: Real> Damping<T> for Undamped {
    const ELASTIC: bool = true;

    #[inline(always)]
    fn force(&self, elastic: T, _h: T, _hdot: T) -> T {
        elastic
    }
}

/// Hunt–Crossley: N = k_H h^{3/2}·(1 + (3/2)·c_d·ḣ), clamped ≥ 0. c_d (s/m) ≥ 0.
/// Cost: 2 multiplies and an add.
///
/// # Choosing c_d
///
/// - **From a coefficient of restitution** e at impact speed v: **c_d ≈ (1 − e)/v**, i.e.
///   e ≈ 1 − c_d·v for c_d·v ≪ 1. Derivation: to first order the approach and the rebound
///   follow the elastic motion, so the energy lost is
///   2·(3/2)c_d·k_H∫₀^{h_m} h^{3/2}·ḣ dh = c_d·m·v³ (with ½mv² = (2/5)k_H h_m^{5/2}), and
///   1 − e² = 2c_d·v. Measured by integrating impacts through this law
///   (`host-tests/restitution.rs`): e depends on c_d·v only (not on m, k_H or the geometry);
///   |(1 − e)/(c_d·v) − 1| ≤ c_d·v, and closer still **e ≈ 1/(1 + c_d·v)**, within 7.5e-5 for
///   c_d·v ≤ 0.1. E.g. steel on steel, e = 0.9 at 0.1 m/s: c_d ≈ 1 s/m.
/// - **From the damping of the contact's own vibration** at rest under a load N₀ (approach h₀,
///   mass m): linearised, the stiffness is (3/2)N₀/h₀, the damping (3/2)c_d·N₀, so
///   ω_n² = 3N₀/(2m·h₀) and the damping ratio is **ζ = c_d·ω_n·h₀/2**. The tippe top's
///   c_d = 5 s/m (`scenes::tippe_top::Params::paper`, feature `scenes`) gives e ≈ 1 − 5v and ζ ≈ 0.4 % at its
///   1.5 kHz contact vibration.
///
/// ```
/// use contensou::geometry::Curvatures;
/// use contensou::normal::{Hertz, HuntCrossley, Modulus, NormalLaw};
/// use contensou::shape::Newton;
///
/// // e = 0.95 wanted for impacts near 0.05 m/s: c_d = (1 − e)/v = 1 s/m.
/// let damping = HuntCrossley::new((1.0 - 0.95) / 0.05)?;
/// let law = Hertz::new::<Newton>(&Curvatures::sphere_plane(5e-3)?, Modulus::new(1.15e11)?)?;
/// let (h, approach_speed) = (1e-7, 0.05);
/// let loading = law.damped_patch(h, approach_speed, &damping).n; // ḣ > 0: compression
/// let unloading = law.damped_patch(h, -approach_speed, &damping).n;
/// assert!(loading > law.patch(h).n && unloading < law.patch(h).n);
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HuntCrossley<T> {
    three_halves_cd: T,
}

impl<T: Real> HuntCrossley<T> {
    /// Errors: [`Error::DampingNegative`] if c_d < 0, [`Error::NonFinite`].
    pub fn new(cd: T) -> Result<Self, Error> {
        let cd = non_negative_damping(cd)?;
        Ok(HuntCrossley {
            three_halves_cd: T::from_f64(1.5) * cd,
        })
    }
}

impl<T: Real> HuntCrossley<T> {
    /// (3/2)·c_d, for the batch kernels (src/batch/).
    #[inline(always)]
    pub(crate) fn three_halves_cd(&self) -> T {
        self.three_halves_cd
    }
}

impl<T: Copy> HuntCrossley<T> {
    /// The coefficient through `f` (the dual form of the Jacobian).
    #[inline(always)]
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> HuntCrossley<U> {
        HuntCrossley {
            three_halves_cd: f(self.three_halves_cd),
        }
    }
}

impl<T: Real> Damping<T> for HuntCrossley<T> {
    #[inline(always)]
    fn force(&self, elastic: T, _h: T, hdot: T) -> T {
        elastic * (T::ONE + self.three_halves_cd * hdot)
    }
}

/// Compression-only viscous term (Kosenko's Modelica contact library):
/// N = k_H h^{3/2} + d·h·ḣ while ḣ > 0, N = k_H h^{3/2} during restitution. d (N·s/m²) ≥ 0.
/// Cost: 2 multiplies, a compare and an add.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompressionDamping<T> {
    d: T,
}

impl<T: Real> CompressionDamping<T> {
    /// Errors: [`Error::DampingNegative`] if d < 0, [`Error::NonFinite`].
    pub fn new(d: T) -> Result<Self, Error> {
        Ok(CompressionDamping {
            d: non_negative_damping(d)?,
        })
    }
}

impl<T: Real> CompressionDamping<T> {
    /// The coefficient d, for the batch kernels (src/batch/).
    #[inline(always)]
    pub(crate) fn coefficient(&self) -> T {
        self.d
    }
}

impl<T: Copy> CompressionDamping<T> {
    /// The coefficient through `f` (the dual form of the Jacobian).
    #[inline(always)]
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> CompressionDamping<U> {
        CompressionDamping { d: f(self.d) }
    }
}

impl<T: Real> Damping<T> for CompressionDamping<T> {
    #[inline(always)]
    fn force(&self, elastic: T, h: T, hdot: T) -> T {
        elastic + self.d * h * hdot.max(T::ZERO)
    }
}

fn non_negative_damping<T: Real>(x: T) -> Result<T, Error> {
    let x = finite(x, "damping coefficient")?;
    if x >= T::ZERO {
        Ok(x)
    } else {
        Err(Error::DampingNegative)
    }
}

/// A normal-force law with its per-geometry constants folded in. All methods are total.
pub trait NormalLaw<T: Real> {
    /// `true` only if [`NormalLaw::patch`] (and [`NormalLaw::damped_patch`]) never return a
    /// negative or NaN `a` or `n`, for any h (every law of this crate: a = a′√h, N = k_H·h·√h
    /// with a′, k_H > 0 for h > 0, zeros otherwise). [`crate::contact::Contact::wrench`] then
    /// skips the friction wrapper's clamps of a and N, which could only change such values.
    /// Default `false` (the clamps stay).
    const NON_NEGATIVE: bool = false;

    /// The patch at approach h: a square root and four multiplies. h ≤ 0 → [`Patch::empty`].
    fn patch(&self, h: T) -> Patch<T>;

    /// k_H in N = k_H·h^{3/2} (N/m^{3/2}).
    fn stiffness(&self) -> T;

    /// Inverse: the approach h = (N/k_H)^{2/3} (m) that carries the normal force N ≥ 0;
    /// N ≤ 0 → 0. Uses `cbrt`: construction/host use only (≈1,600 instructions in `f32` on
    /// the M4F).
    fn approach(&self, n: T) -> T {
        if n > T::ZERO {
            (n / self.stiffness()).sq().cbrt()
        } else {
            T::ZERO
        }
    }

    /// Elastic energy U = (2/5)·k_H·h^{5/2} (J); 0 for h ≤ 0.
    fn energy(&self, h: T) -> T {
        if h > T::ZERO {
            T::from_f64(0.4) * self.stiffness() * h * h * h.sqrt()
        } else {
            T::ZERO
        }
    }

    /// The patch with a damping law: N = max(0, damping(N_el, h, ḣ)); a, b, p0 stay the
    /// elastic ones. h ≤ 0 → [`Patch::empty`].
    #[inline]
    fn damped_patch<D: Damping<T>>(&self, h: T, hdot: T, damping: &D) -> Patch<T> {
        let mut patch = self.patch(h);
        if !D::ELASTIC && !patch.is_empty() {
            patch.n = damping.force(patch.n, h, hdot).max(T::ZERO);
        }
        patch
    }
}

/// Exact Hertz with the per-geometry constants precomputed (see the module docs).
///
/// Error: that of the shape it is built from (exact with [`crate::shape::Newton`]; measured
/// figures per method in `bench-results/hertz.md`). Cost per [`NormalLaw::patch`]: one
/// `sqrt`, four multiplies, one compare; M4F 33 instructions, ≈66 cycles in f32 (incl. the rig's
/// 8-instruction call floor), 685 in f64 (soft float); host ≈ 9–15 ns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hertz<T> {
    a_coef: T,
    b_coef: T,
    k_h: T,
    p0_coef: T,
    e2: T,
    m1: T,
}

impl<T: Copy> Hertz<T> {
    /// Every constant through `f` (the dual form of the Jacobian: constants lifted).
    #[inline(always)]
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Hertz<U> {
        Hertz {
            a_coef: f(self.a_coef),
            b_coef: f(self.b_coef),
            k_h: f(self.k_h),
            p0_coef: f(self.p0_coef),
            e2: f(self.e2),
            m1: f(self.m1),
        }
    }
}

impl<T: Real> Hertz<T> {
    /// Build with the eccentricity method `M`. A circle (P = Q) takes the circular fast path.
    ///
    /// Errors: [`Error::CurvatureRatioOutOfRange`] if P/Q < 1e-4.
    pub fn new<M: Eccentricity>(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
    ) -> Result<Self, Error> {
        if curvatures.p() == curvatures.q() {
            return Ok(Self::circular(curvatures.p(), estar));
        }
        let g = Ratio::of(curvatures)?;
        Ok(Self::from_shape(curvatures, &M::shape(g), estar))
    }

    /// From validated curvatures (only P is used) and a shape already known — e.g. from
    /// [`crate::shape::Table`] each step:
    /// `Hertz::from_shape(&curv, &Table::shape(Ratio::clamped(curv.ratio())), estar)`. Total.
    ///
    /// a′ = √(D/(P·K)), b′ = √(m₁)·a′, k_H = (2π/3)·E*·a′/K, p0′ = E*/(K·b′) (with b = b′√h this
    /// is E*·h/(K·b)). Cost: 3 divisions, 2 `sqrt`, 6 multiplies.
    #[inline]
    pub fn from_shape(curvatures: &Curvatures<T>, shape: &Shape<T>, estar: Modulus<T>) -> Self {
        let p = curvatures.p();
        let i = shape.integrals();
        let inv_k = T::ONE / i.k;
        let a2 = i.d * inv_k / p;
        let a_coef = a2.sqrt();
        let b_coef = (shape.m1() * a2).sqrt();
        let estar_over_k = estar.get() * inv_k;
        Hertz {
            a_coef,
            b_coef,
            k_h: T::from_f64(2.0 * core::f64::consts::PI / 3.0) * estar_over_k * a_coef,
            p0_coef: estar_over_k / b_coef,
            e2: shape.e2(),
            m1: shape.m1(),
        }
    }

    /// The circular fast path, P = Q = 1/(2R) (sphere on plane with R = 1/(2P)): a = b = √(Rh),
    /// N = (4/3)E*√R·h^{3/2}, p0 = (2E*/π)·√(h/R). Evaluates no elliptic integral. `p` must be
    /// > 0 (from [`Curvatures::p`]).
    pub fn circular(p: T, estar: Modulus<T>) -> Self {
        Self::circle_of_radius(T::HALF / p, estar)
    }

    fn circle_of_radius(r: T, estar: Modulus<T>) -> Self {
        let sqrt_r = r.sqrt();
        let e = estar.get();
        Hertz {
            a_coef: sqrt_r,
            b_coef: sqrt_r,
            k_h: T::from_f64(4.0 / 3.0) * e * sqrt_r,
            p0_coef: T::TWO * e / (T::PI * sqrt_r),
            e2: T::ZERO,
            m1: T::ONE,
        }
    }
}

impl<T: Real> NormalLaw<T> for Hertz<T> {
    const NON_NEGATIVE: bool = true;

    #[inline]
    fn patch(&self, h: T) -> Patch<T> {
        self.patch_with::<Libm>(h)
    }

    #[inline(always)]
    fn stiffness(&self) -> T {
        self.k_h
    }
}

impl<T: Real> Hertz<T> {
    /// [`NormalLaw::patch`] with √h from the backend `B`.
    #[inline(always)]
    fn patch_with<B: Backend>(&self, h: T) -> Patch<T> {
        if !positive(h) {
            return Patch::empty(self.e2, self.m1);
        }
        let sh = B::sqrt(h);
        Patch {
            h,
            a: self.a_coef * sh,
            b: self.b_coef * sh,
            n: self.k_h * h * sh,
            p0: self.p0_coef * sh,
            e2: self.e2,
            m1: self.m1,
        }
    }
}

/// [`Hertz`] with the per-step √h from micromath (feature `micromath`; `f32` only, libm for
/// `f64`): a = a′√h, b = b′√h, N = k_H·h·√h, p0 = p0′√h with micromath's bit-shift square root.
/// Built like [`Hertz`] ([`HertzMicromath::new`]) or from one (`HertzMicromath::from(law)`),
/// whose constants it keeps.
///
/// Domain: every h (h ≤ 0 → [`Patch::empty`]); `f64` is [`Hertz`]. micromath's √h is never
/// below the true root and at most 6.07 % above it (exact at h = 4ᵏ), so a, b, p0 and N are
/// biased high by that factor. Measured max relative error of a, b, N, p0 (`f32`, Newton
/// constants, tools/data/hertz_ref.csv; and N over h ∈ [1e-12, 1] m; asserted by
/// host-tests/micromath.rs): **6.1e-2** (median 1.5e-2; [`Hertz`] 5.0e-7). Cost per
/// [`NormalLaw::patch`]: M4F **32** instructions, ≈50 cycles (`f32`; [`Hertz`] 33 and ≈66:
/// `vsqrt.f32` takes 14 cycles), host ≈ 9–12 ns.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzMicromath<T>(pub(crate) Hertz<T>);

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl<T: Real> HertzMicromath<T> {
    /// As [`Hertz::new`]: built with the eccentricity method `M`. Errors:
    /// [`Error::CurvatureRatioOutOfRange`] if P/Q < 1e-4.
    pub fn new<M: Eccentricity>(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
    ) -> Result<Self, Error> {
        Hertz::new::<M>(curvatures, estar).map(HertzMicromath)
    }
}

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl<T: Real> From<Hertz<T>> for HertzMicromath<T> {
    fn from(law: Hertz<T>) -> Self {
        HertzMicromath(law)
    }
}

/// `NormalLaw` for a law that is a [`Hertz`] (its field `.0`) built another way: the patch
/// by `Hertz::patch_with` over the square root's backend `$backend`, the stiffness k_H.
macro_rules! over_hertz {
    ($(#[$m:meta])* $law:ident, $backend:ty) => {
        $(#[$m])*
        impl<T: Real> NormalLaw<T> for $law<T> {
            const NON_NEGATIVE: bool = true;

            #[inline]
            fn patch(&self, h: T) -> Patch<T> {
                self.0.patch_with::<$backend>(h)
            }
            #[inline(always)]
            fn stiffness(&self) -> T {
                self.0.k_h
            }
        }
    };
}

over_hertz!(
    #[cfg(feature = "micromath")]
    #[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
    HertzMicromath,
    crate::math::Micromath
);

/// The volumetric (eccentricity-free) law — **not** Hertz for P ≠ Q: the Hertz circle with
/// the Gaussian radius R_e = 1/(2√(PQ)) (a law built only from the overlap volume
/// V = πh²/(2√(PQ)), area S = πh/√(PQ) and h reduces to it). A stand-in for "V. G. Vilke's
/// formula" of the paper (§4), which is not published there.
///
/// # Formula, domain, error, cost
///
/// N = (4/3)E*√R_e·h^{3/2}, a = b = √(R_e h), e² = 0. Exact for P = Q. Measured force error
/// vs exact Hertz at equal h (`bench-results/hertz.md`), always low: −0.14% at g = P/Q = 0.77,
/// −1.2% at 0.46, −4.7% at 0.22, −9.8% at 0.1, −30.3% at 0.01, −50.5% at 1e-3, −66.5% at
/// 1e-4. Cost per step: as [`Hertz::patch`]; construction: one `sqrt` and one division, no
/// elliptic integral. Built from the curvatures and stepped every call (varying geometry):
/// 52 M4F instructions (`f32`), 1,638 (`f64`), QEMU row `hertz,volumetric`.
///
/// # Stated domain
///
/// Within [`Volumetric::MAX_ERROR`] = 1 % for g ≥ [`Volumetric::MIN_RATIO`] = 0.5 (measured
/// −0.99 % at g = 0.5 against mpmath, `tools/data/stability_shape.csv`; the error grows
/// monotonically as g falls, chart `docs/report/stability/volumetric.csv`).
/// [`Volumetric::checked`] refuses geometries past that edge; [`Volumetric::new`] accepts every
/// geometry (unchanged behaviour) and stays finite, with the error above. For elongated
/// contacts use [`Fitted`] (≤ 1.3e-5 over g ∈ [1e-4, 1], same per-step cost).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volumetric<T>(pub(crate) Hertz<T>);

impl<T: Real> Volumetric<T> {
    /// Smallest g = P/Q accepted by [`Volumetric::checked`]: the force error stays within
    /// [`Volumetric::MAX_ERROR`] for g ∈ [0.5, 1].
    pub const MIN_RATIO: f64 = 0.5;
    /// The error bound that [`Volumetric::MIN_RATIO`] guarantees: 1 % of N (relative, at equal h).
    pub const MAX_ERROR: f64 = 0.01;

    /// From validated curvatures and modulus, any g = P/Q. Total. The force error grows as g
    /// falls (see the type's docs): −1 % at g = 0.5, −66.5 % at 1e-4. Prefer
    /// [`Volumetric::checked`] unless the geometry is known to be nearly circular.
    pub fn new(curvatures: &Curvatures<T>, estar: Modulus<T>) -> Self {
        Volumetric(Hertz::circle_of_radius(curvatures.gaussian_radius(), estar))
    }

    /// [`Volumetric::new`] only within its stated domain g = P/Q ≥ [`Volumetric::MIN_RATIO`]
    /// (force error ≤ 1 %). Errors: [`Error::CurvatureRatioOutOfRange`] for g < 0.5 (NaN cannot
    /// occur: the curvatures are validated).
    pub fn checked(curvatures: &Curvatures<T>, estar: Modulus<T>) -> Result<Self, Error> {
        if curvatures.ratio() >= T::from_f64(Self::MIN_RATIO) {
            Ok(Self::new(curvatures, estar))
        } else {
            Err(Error::CurvatureRatioOutOfRange)
        }
    }
}

over_hertz!(Volumetric, Libm);

/// A fitted, eccentricity-free Hertz law: no eccentricity solve, no elliptic integral, no
/// table — three fixed polynomials in y = 1 − g^{1/8} (g = P/Q), fitted to exact Hertz.
///
/// # Formula
///
/// ```text
/// k_H = (4/3)·E*·φ(g)/√(2P),   a = α(g)·√(h/(2P)),   b = β(g)·√(h/(2Q)),   m₁ = (b/a)²,
/// φ = (π/√2)·√D/K^{3/2},  α = √(2D/K),  β = √(2B/K)   (exact forms; all 1 at g = 1)
/// ```
///
/// each replaced by a degree-6 polynomial in y (mpmath `chebyfit`, generated by
/// `tools/gen_fitted_law.py` into `src/normal/fit_data.rs`).
///
/// # Domain, error, cost
///
/// g ∈ [1e-4, 1]. Measured max relative error vs exact Hertz (`tools/data/hertz_ref.csv`):
/// N 1.3e-5, a 3.6e-5, b 5.5e-5 (f64 and f32); e² = 1 − m₁ inherits the a, b errors
/// (≈ 1e-4 absolute, exact-ish only as g → 0). Roughly 2,000× better than [`Volumetric`] at
/// g = 0.1. Construction: 3 `sqrt` (g^{1/8}), 3 Horner sextics, 1 `sqrt`, 2 divisions —
/// cheap enough per step when the geometry changes: [`Fitted::clamped`] + `patch` = 134 M4F
/// instructions (f32), 6,995 (f64). Per step: as [`Hertz::patch`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fitted<T>(pub(crate) Hertz<T>);

impl<T: Real> Fitted<T> {
    /// From validated curvatures. Errors: [`Error::CurvatureRatioOutOfRange`] if P/Q < 1e-4.
    pub fn new(curvatures: &Curvatures<T>, estar: Modulus<T>) -> Result<Self, Error> {
        Ratio::of(curvatures)?;
        Ok(Self::clamped(curvatures, estar))
    }

    /// Total, for per-step use when the geometry changes: g = P/Q is clamped into
    /// [1e-4, 1] ([`Ratio::clamped`]) instead of rejected. Cost includes the division P/Q.
    #[inline]
    pub fn clamped(curvatures: &Curvatures<T>, estar: Modulus<T>) -> Self {
        let p = curvatures.p();
        let g = Ratio::clamped(curvatures.ratio());
        let root4 = g.get().sqrt().sqrt();
        let y = T::ONE - root4.sqrt();
        let poly = |c: &[f64; 7]| {
            c.iter()
                .rev()
                .fold(T::ZERO, |acc, &k| acc * y + T::from_f64(k))
        };
        let (phi, alpha, beta) = (
            poly(&fit_data::PHI),
            poly(&fit_data::ALPHA),
            poly(&fit_data::BETA),
        );
        let inv_sqrt_2p = T::ONE / (T::TWO * p).sqrt();
        let a_coef = alpha * inv_sqrt_2p;
        let b_coef = beta * root4 * root4 * inv_sqrt_2p;
        let k_h = T::from_f64(4.0 / 3.0) * estar.get() * phi * inv_sqrt_2p;
        let m1 = (b_coef / a_coef).sq().min(T::ONE);
        Fitted(Hertz {
            a_coef,
            b_coef,
            k_h,
            p0_coef: T::from_f64(1.5 / core::f64::consts::PI) * k_h / (a_coef * b_coef),
            e2: T::ONE - m1,
            m1,
        })
    }
}

over_hertz!(Fitted, Libm);
