//! The contact ellipse's shape: eccentricity c = e² from the curvature ratio g = P/Q, and the
//! complete elliptic integrals at m = c, by four methods.
//!
//! # The equation
//!
//! The eccentricity depends on the geometry only (not on the load):
//!
//! ```text
//! G(c) = g,   G(c) = (1 − c)(K − E)/(E − (1 − c)K) = (1 − c)·D(c)/B(c)
//! ```
//!
//! (parameter m = c; B, D as in [`crate::elliptic`]). G(0) = 1, G′(0) = −3/4, G decreases
//! monotonically to 0 as c → 1. At the solution m₁·D = g·B, so **E = (1 + g)·B** and
//! **m₁ = 1 − c = g·B/D** hold exactly; the methods below use both.
//!
//! # Methods (zero-sized types implementing [`Eccentricity`])
//!
//! | method | per call | max error on c | max error on a, b, N (relative) |
//! |---|---|---|---|
//! | [`Newton`] | construction: 6 (f64) / 4 (f32) Newton steps + AGM | f64 1.9e-15, f32 9.0e-7 rel. | f64 1.5e-15, f32 7.6e-7 |
//! | [`Table`] | per step: 3 `sqrt`, 3 quintics, 1 division | f64 6.1e-13, f32 1.9e-7 rel. | f64 3.6e-12, f32 3.7e-7 |
//! | [`Linear`] | the paper's two-segment G*, a multiply + AGM | 5.5e-2 abs. | a 2.2e-2, b 1.22, N 0.12 |
//! | [`HamrockDowson`] | c = 1 − g^{4/π}: `ln`, `exp` + AGM | 1.6e-2 abs. | a 4.4e-3, b 0.31, N 4.7e-2 |
//!
//! Measured over g ∈ [1e-4, 1] against `tools/data/hertz_ref.csv` (mpmath; 1,702 rows, 1,500 of
//! them a dense sweep of g — the `f32` errors are rounding noise over the whole domain), asserted
//! by `host-tests/hertz.rs`, tabulated in `bench-results/hertz.md`. The large b errors of the
//! approximate methods come from m₁ = (b/a)² at small g: Linear's m₁ is off by up to 4×,
//! Hamrock–Dowson's by 53%.

mod table_data;

use crate::elliptic::{Agm, Integrals, Method, Parameter};
use crate::error::finite;
use crate::geometry::Curvatures;
use crate::math::{Backend, Libm};
use crate::{Error, Real};

/// A validated curvature ratio g = P/Q ∈ [[`Ratio::MIN`], 1].
///
/// The domain guards every eccentricity method: [`Table`] and [`crate::normal::Fitted`] are
/// fitted on it, and [`Newton`], exact in `f64` down to g ≈ 1.5e-11 and in `f32` down to
/// g ≈ 5e-7 (below, m₁ = (b/a)² leaves the elliptic domain and is clamped; see
/// [`Newton::solve_unchecked`]), keeps a margin of 200× (`f32`). Below 1e-4: [`Ratio::new`]
/// returns [`Error::CurvatureRatioOutOfRange`]; [`Ratio::clamped`] returns 1e-4 (tested in
/// `host-tests/stability.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ratio<T>(T);

impl<T: Real> Ratio<T> {
    /// Smallest supported g: 1e-4 (Q/P = 10⁴, c = 1 − 1.7e-5, b/a = 4.1e-3).
    pub const MIN: f64 = 1e-4;

    /// From g ∈ [1e-4, 1]; otherwise [`Error::CurvatureRatioOutOfRange`] or
    /// [`Error::NonFinite`].
    pub fn new(g: T) -> Result<Self, Error> {
        let g = finite(g, "g")?;
        if g >= T::from_f64(Self::MIN) && g <= T::ONE {
            Ok(Ratio(g))
        } else {
            Err(Error::CurvatureRatioOutOfRange)
        }
    }

    /// g = P/Q of validated curvatures; [`Error::CurvatureRatioOutOfRange`] if P/Q < 1e-4.
    pub fn of(curvatures: &Curvatures<T>) -> Result<Self, Error> {
        Self::new(curvatures.ratio())
    }

    /// g clamped into [1e-4, 1] (NaN → 1e-4): total, for per-step use when the geometry
    /// changes every step and was validated upstream.
    #[inline(always)]
    pub fn clamped(g: T) -> Self {
        Ratio(g.clamp_to(T::from_f64(Self::MIN), T::ONE))
    }

    /// g
    #[inline(always)]
    pub fn get(self) -> T {
        self.0
    }
}

/// The contact ellipse's shape: c = e² = 1 − b²/a², m₁ = 1 − c = (b/a)² (each held to full
/// relative precision) and K, E, B, D at parameter m = c.
///
/// The friction law's small-slip slopes follow directly: A = (3/2)·D, B_f = (3/2)·B,
/// C = (3/8)·E (see [`crate::friction::Constants::from_shape`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape<T> {
    c: T,
    m1: T,
    integrals: Integrals<T>,
}

impl<T: Real> Shape<T> {
    /// The circle: c = 0, K = E = π/2, B = D = π/4. No elliptic integral is evaluated.
    pub fn circle() -> Self {
        Shape {
            c: T::ZERO,
            m1: T::ONE,
            integrals: Integrals {
                k: T::FRAC_PI_2,
                e: T::FRAC_PI_2,
                b: T::FRAC_PI_4,
                d: T::FRAC_PI_4,
            },
        }
    }

    /// The shape at c by the AGM. Both c and m₁ = 1 − c are passed; the one that is small
    /// (and so known to full relative precision) builds the [`Parameter`]: c if c < ½, else m₁.
    /// Inputs are clamped into the elliptic domain, so this is total.
    fn by_agm(c: T, m1: T) -> Self {
        let min = Parameter::<T>::min_complement();
        let p = if c < T::HALF {
            Parameter::new(c.clamp_to(T::ZERO, T::ONE - min))
        } else {
            Parameter::from_complement(m1.clamp_to(min, T::ONE))
        };
        match p {
            Ok(p) => Shape {
                c: p.m(),
                m1: p.m1(),
                integrals: Agm::integrals(p),
            },
            Err(_) => Self::circle(),
        }
    }

    /// c = e² = 1 − (b/a)²
    #[inline(always)]
    pub fn e2(&self) -> T {
        self.c
    }
    /// m₁ = 1 − c = (b/a)²
    #[inline(always)]
    pub fn m1(&self) -> T {
        self.m1
    }
    /// K(c), E(c), B(c), D(c).
    #[inline(always)]
    pub fn integrals(&self) -> Integrals<T> {
        self.integrals
    }
}

/// A method for the eccentricity: a zero-sized type chosen by generics.
pub trait Eccentricity {
    /// Short name used by the evaluator CLI and benchmark labels.
    const NAME: &'static str;
    /// The shape at a validated ratio. Total: finite for every valid g.
    fn shape<T: Real>(g: Ratio<T>) -> Shape<T>;
}

/// Exact eccentricity by Newton's method with a fixed iteration count (construction-time).
///
/// # Formula
///
/// - g ≥ 0.8 (c ≤ 0.27): unknown c, equation c·u(c)/B(c) = 1 − g with
///   u = (B − m₁D)/c = (1 − G)·B/c, u, B and their derivatives by their Maclaurin series
///   (40 terms f64, 20 f32); start c₀ = 4(1 − g)/3. Free of cancellation as c → 0: relative
///   precision on c holds down to g = 1.
/// - g < 0.8: unknown t = ln m₁ (m₁ = 1 − c carried directly, never formed as 1 − c),
///   residual r = ln(m₁D/B) − ln g, dr/dt = 3/2 − (B − m₁D)/(2c)·(1/D + 1/B), K/E/B/D by
///   [`Agm`]; start at Hamrock–Dowson m₁ = g^{4/π}.
///
/// Iterations: 6 (f64) / 4 (f32) in both branches; then K, E, B, D by [`Agm`]. M4F: 1,200
/// instructions (f32), 116,700 (f64); host ≈ 0.6 / 1.1 µs.
///
/// # Domain, error, cost
///
/// g ∈ [1e-4, 1]; g = 1 is the circle exactly. Measured max relative error vs mpmath
/// (`bench-results/hertz.md`): f64 — c 1.9e-15, m₁ 3.4e-15, K/E/B/D ≤ 2.1e-15, and through
/// [`crate::normal::Hertz`] a, b, N ≤ 1.5e-15; f32 — c 9.0e-7, m₁ 1.6e-6, K/E/B/D ≤ 1.1e-6,
/// a, b, N ≤ 7.6e-7. A denser check (900 g incl. 150 within 1e-12…0.1 of 1, via `contact_eval`)
/// found c ≤ 2.0e-15 (f64) and ≤ 1.2e-6 (f32, near g ≈ 0.78, where c = 1 − m₁ ≈ 0.3 is formed). Cost: construction only — per iteration one AGM, `ln`, `exp`
/// (large-c branch) or a 40-term series (small-c branch). Not for per-step use: see [`Table`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Newton;

impl Newton {
    /// Newton iterations used for `T`.
    pub const fn iterations<T: Real>() -> usize {
        if T::MANTISSA_DIGITS > 24 { 6 } else { 4 }
    }

    /// (c, m₁) with G(c) = g.
    pub fn solve<T: Real>(g: Ratio<T>) -> (T, T) {
        Self::solve_unchecked(g.get(), Self::iterations::<T>())
    }

    /// The same iteration at a raw g with a chosen iteration count, **without** the [`Ratio`]
    /// domain check: for convergence studies (`examples/stability.rs`), not for callers, who
    /// should go through [`Ratio`]. Total: g is clamped into [`T::MIN_POSITIVE`](Real::MIN_POSITIVE), 1]
    /// (NaN → `MIN_POSITIVE`) and m₁ into [m₁_min, 1] ([`Parameter::min_complement`]).
    ///
    /// Below [`Ratio::MIN`] (measured against mpmath down to g = 1e-12,
    /// `tools/data/stability_shape.csv`; `examples/stability.rs` →
    /// `docs/report/stability/newton_small_g.csv`, `newton_iterations.csv`): the iteration
    /// itself does not degrade — 3 steps reach 1e-14 in `f64` (2 reach 2e-6 in `f32`) at every
    /// g < 0.69, although the Hamrock–Dowson start is 53 % off in m₁ at g = 1e-4, 81 % at 1e-6,
    /// 93 % at 1e-8. What fails is the floor m₁_min of [`Parameter`]: `f32` m₁ < 2⁻²⁴ below
    /// g ≈ 5e-7 (m₁ error 25 % at g = 4.2e-7, 63× at 1e-8), `f64` m₁ < 1e-12 below
    /// g ≈ 1.5e-11 (7 % at 1.3e-11); m₁ is then clamped to the floor (finite, wrong).
    pub fn solve_unchecked<T: Real>(g: T, iterations: usize) -> (T, T) {
        // g > 1 → 1 (the circle); g < MIN_POSITIVE (incl. ≤ 0 and NaN) → MIN_POSITIVE.
        let g = g.clamp_to(T::MIN_POSITIVE, T::ONE);
        if g >= T::ONE {
            (T::ZERO, T::ONE)
        } else if g >= T::from_f64(0.8) {
            let c = Self::small_c(g, iterations);
            (c, T::ONE - c)
        } else {
            let m1 = Self::large_c(g, iterations);
            (T::ONE - m1, m1)
        }
    }

    /// Small-c branch: solve c·u(c)/B(c) = 1 − g by series.
    fn small_c<T: Real>(g: T, iterations: usize) -> T {
        let eps = T::ONE - g; // exact for g ≥ 1/2
        let mut c = T::from_f64(4.0 / 3.0) * eps;
        let terms = if T::MANTISSA_DIGITS > 24 { 40 } else { 20 };
        for _ in 0..iterations {
            // (π/2)·Σ over n of: B: w_n² cⁿ/(2n+2); D: w_n w_{n+1} cⁿ;
            // (B − D)/c: −w_n² n/(n+1) c^{n−1} (n ≥ 1), w_n = C(2n, n)/4ⁿ.
            let (mut b, mut db, mut d, mut dd, mut bd, mut dbd) =
                (T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO);
            let mut w = T::ONE;
            let mut pow = T::ONE; // cⁿ
            let mut pow_1 = T::ZERO; // c^{n−1}
            let mut pow_2 = T::ZERO; // c^{n−2}
            for n in 0..terms {
                let nf = T::from_usize(n);
                let w_next = w * (T::TWO * nf + T::ONE) / (T::TWO * nf + T::TWO);
                let wb = w * w / (T::TWO * nf + T::TWO);
                let wd = w * w_next;
                let wbd = -w * w * nf / (nf + T::ONE);
                b += wb * pow;
                db += wb * nf * pow_1;
                d += wd * pow;
                dd += wd * nf * pow_1;
                bd += wbd * pow_1;
                dbd += wbd * (nf - T::ONE) * pow_2;
                pow_2 = pow_1;
                pow_1 = pow;
                pow *= c;
                w = w_next;
            }
            // u = (B − D)/c + D, the common factor π/2 cancels in u/B.
            let u = bd + d;
            let du = dbd + dd;
            let f = c * u / b - eps;
            let df = u / b + c * (du / b - u * db / (b * b));
            c = (c - f / df).clamp_to(T::ZERO, T::from_f64(0.5));
        }
        c
    }

    /// Large-c branch: Newton in t = ln m₁.
    fn large_c<T: Real>(g: T, iterations: usize) -> T {
        let ln_g = g.ln();
        let min = Parameter::<T>::min_complement();
        let mut m1 = (T::from_f64(4.0 / core::f64::consts::PI) * ln_g).exp();
        for _ in 0..iterations {
            let Ok(p) = Parameter::from_complement(m1.clamp_to(min, T::from_f64(0.8))) else {
                break;
            };
            let (m, m1p) = (p.m(), p.m1());
            let i = Agm::integrals(p);
            let r = (m1p * i.d / i.b).ln() - ln_g;
            let dr =
                T::from_f64(1.5) - (i.b - m1p * i.d) / (T::TWO * m) * (T::ONE / i.d + T::ONE / i.b);
            m1 = m1p * (-r / dr).exp();
        }
        m1.clamp_to(min, T::ONE)
    }
}

impl Eccentricity for Newton {
    const NAME: &'static str = "newton";

    fn shape<T: Real>(g: Ratio<T>) -> Shape<T> {
        if g.get() >= T::ONE {
            return Shape::circle();
        }
        let (c, m1) = Self::solve(g);
        Shape::by_agm(c, m1)
    }
}

/// The paper's two-segment eccentricity (Kosenko & Aleksandrov §4, for Vilke's algorithm).
///
/// # Formula
///
/// G*(c) = 1 − (3/4)c on [0, c₁], G*(c) = (1 − (3/4)c₁)/(1 − c₁)·(1 − c) on [c₁, 1], c₁ = 0.4,
/// solved explicitly: g ≥ 0.7 → c = 4(1 − g)/3; g < 0.7 → m₁ = (6/7)g. Then K, E, B, D by
/// [`Agm`] at that c.
///
/// # Domain, error, cost
///
/// g ∈ [1e-4, 1]. Reproduces the paper: P/Q = 0.41721 (exact c = 0.687) → c = 0.642391.
/// Measured max error (f32 and f64 alike): c 5.5e-2 absolute; m₁ up to 4× too large at small
/// g; K 12%, E 3.4%; a 2.2%, b 122%, N 12% relative (`bench-results/hertz.md`).
/// Cost: one multiply + one AGM (no `ln`/`exp`); host ≈ 60 ns; M4F 180 instructions (f32),
/// 12,582 (f64).
///
/// # Beyond the knee
///
/// G* is a fit for c ≤ c₁ = 0.4 (g ≥ 0.7) only. Measured against mpmath
/// (`tools/data/stability_shape.csv`, chart `docs/report/stability/linear_gstar.csv`): at the
/// knee g = 0.7 both segments give c = 0.4 (continuous; error c 0.022, N 0.62 %); past it the
/// c error peaks at 0.054 (g ≈ 0.27) and the N error grows to 7.7 % at g = 0.1, 12.2 % at
/// g = [`Ratio::MIN`]; b, through m₁ = (6/7)·g against the exact m₁ ≈ g/ln(…), is 29 % off at
/// g = 0.1 and 122 % at 1e-4. Always finite (the [`Ratio`] domain is the guard; tested at the
/// knee and at [`Ratio::MIN`] in `host-tests/stability.rs`). Use [`Table`] (≤ 3.7e-7 `f32`,
/// 94 instructions) when elongated contacts matter.
#[derive(Clone, Copy, Debug, Default)]
pub struct Linear;

impl Linear {
    /// (c, m₁) from G*(c) = g.
    #[inline]
    pub fn solve<T: Real>(g: Ratio<T>) -> (T, T) {
        let g = g.get();
        if g >= T::from_f64(0.7) {
            let c = T::from_f64(4.0 / 3.0) * (T::ONE - g);
            (c, T::ONE - c)
        } else {
            let m1 = T::from_f64(6.0 / 7.0) * g;
            (T::ONE - m1, m1)
        }
    }
}

impl Eccentricity for Linear {
    const NAME: &'static str = "linear";

    #[inline]
    fn shape<T: Real>(g: Ratio<T>) -> Shape<T> {
        let (c, m1) = Self::solve(g);
        Shape::by_agm(c, m1)
    }
}

/// The practitioners' closed form (Hamrock & Dowson 1976 / Brewe & Hamrock): k = a/b ≈
/// (Q/P)^{2/π}, so m₁ = 1/k² = g^{4/π}, c = 1 − g^{4/π}. Then K, E, B, D by [`Agm`].
///
/// # Domain, error, cost
///
/// g ∈ [1e-4, 1]; exact at g = 1. Measured max error (f32 and f64 alike): c 1.6e-2 absolute
/// (relative → 1 − 3/π ≈ 4.5% as g → 1); m₁ 53%, K 5.4%, E 0.74%; a 0.44%, b 31%, N 4.7%
/// relative (`bench-results/hertz.md`). Cost: `ln` + `exp` + one AGM (host ≈ 140–190 ns; M4F 277
/// instructions f32, 17,857 f64):
/// construction-time, since `pow` is not for the hot path.
#[derive(Clone, Copy, Debug, Default)]
pub struct HamrockDowson;

impl HamrockDowson {
    /// (c, m₁) = (1 − g^{4/π}, g^{4/π}).
    pub fn solve<T: Real>(g: Ratio<T>) -> (T, T) {
        hamrock_dowson::<Libm, T>(g)
    }
}

/// (c, m₁) = (1 − g^{4/π}, g^{4/π}) with `ln` and `exp` from the backend `B`.
#[inline(always)]
fn hamrock_dowson<B: Backend, T: Real>(g: Ratio<T>) -> (T, T) {
    let m1 = B::exp(T::from_f64(4.0 / core::f64::consts::PI) * B::ln(g.get()));
    (T::ONE - m1, m1)
}

impl Eccentricity for HamrockDowson {
    const NAME: &'static str = "hamrock-dowson";

    fn shape<T: Real>(g: Ratio<T>) -> Shape<T> {
        let (c, m1) = Self::solve(g);
        Shape::by_agm(c, m1)
    }
}

/// [`HamrockDowson`] with `ln` and `exp` from [`Micromath`](crate::math::Micromath) (feature
/// `micromath`; `f32` only, libm for `f64`): m₁ = exp((4/π)·ln g), c = 1 − m₁, then K, E, B, D
/// by [`Agm`] (libm square roots, `vsqrt.f32`).
///
/// Domain: g ∈ [1e-4, 1]; exact at g = 1 (ln 1 = 0, exp 0 = 1 exactly); `f64` is
/// [`HamrockDowson`]. Measured max error (`f32`, the 200 elliptic rows of
/// tools/data/hertz_ref.csv, asserted by host-tests/micromath.rs): c **1.65e-2** absolute
/// ([`HamrockDowson`] 1.61e-2), a, b, N **0.308** relative (the same: the closed form's own
/// error dominates micromath's 2.4e-3 in `exp`). Cost: M4F **295** instructions (`f32`;
/// [`HamrockDowson`] 277: micromath's `exp` costs more than libm's), host ≈ 112 ns (as
/// [`HamrockDowson`]). Not worth using: no cheaper, no better.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, Default)]
pub struct HamrockDowsonMicromath;

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl Eccentricity for HamrockDowsonMicromath {
    const NAME: &'static str = "hamrock-dowson-micromath";

    fn shape<T: Real>(g: Ratio<T>) -> Shape<T> {
        let (c, m1) = hamrock_dowson::<crate::math::Micromath, T>(g);
        Shape::by_agm(c, m1)
    }
}

/// Precomputed inverse g → c, K, E, B, D for per-step use when the geometry changes.
///
/// # Formula
///
/// x = g^{1/8} (three square roots) indexes 32 uniform cells on [(1e-4)^{1/8}, 1]; in each,
/// degree-5 polynomials (Chebyshev-node interpolants of mpmath values, generated by
/// `tools/gen_shape_table.py` into `src/shape/table_data.rs`) give r₁ = c/(1 − g), B and D.
/// Then, using the identities at the solution,
///
/// ```text
/// c = (1 − g)·r₁,  m₁ = g·B/D,  K = B + D,  E = (1 + g)·B
/// ```
///
/// so c keeps its relative precision as g → 1 and m₁ as g → 0.
///
/// # Domain, error, cost, size
///
/// g ∈ [1e-4, 1] (the [`Ratio`] domain). Measured max relative error vs mpmath
/// (`bench-results/hertz.md`): f64 — c 6.1e-13, m₁ 4.6e-12, K/E/B/D ≤ 4.6e-12, and a, b, N
/// through [`crate::normal::Hertz::from_shape`] ≤ 3.6e-12; f32 — c 1.9e-7, m₁ 3.7e-7,
/// K/E/B/D ≤ 4.0e-7, a, b, N ≤ 3.7e-7. Cost: 3 `sqrt`, 3 Horner quintics, 1 division (host
/// ≈ 35–70 ns); M4F 94 instructions (f32), 4,791 (f64), and 143 / 6,875 with g = P/Q and a, b, N, p0
/// (`Hertz::from_shape(..).patch(h)`) — within the 150-instruction f32 budget. Size: 32 × 18 coefficients = 2,304 bytes
/// (`f32`) or 4,608 bytes (`f64`); only the table of the precision used is linked.
#[derive(Clone, Copy, Debug, Default)]
pub struct Table;

impl Table {
    /// Bytes of the coefficient table linked for `T`.
    pub const fn bytes<T: Real>() -> usize {
        table_data::CELLS * table_data::WIDTH * core::mem::size_of::<T>()
    }
}

/// The coefficient table in `T`'s own precision (no per-call conversion).
#[inline(always)]
fn coefficients<T: Real>() -> &'static [[T::Base; table_data::WIDTH]; table_data::CELLS] {
    T::of_precision(&table_data::TABLE_F32, &table_data::TABLE_F64)
}

/// Horner on the coefficients `row[offset..offset + DEGREE + 1]`, constant term first.
#[inline(always)]
fn horner<T: Real>(row: &[T::Base; table_data::WIDTH], offset: usize, u: T) -> T {
    let mut acc = T::ZERO;
    for (k, &c) in row
        .iter()
        .skip(offset)
        .take(table_data::DEGREE + 1)
        .rev()
        .enumerate()
    {
        let c = T::from_base(c);
        acc = if k == 0 { c } else { acc * u + c };
    }
    acc
}

impl Eccentricity for Table {
    const NAME: &'static str = "table";

    #[inline]
    fn shape<T: Real>(g: Ratio<T>) -> Shape<T> {
        let table = coefficients::<T>();
        let g = g.get();
        let x = g.sqrt().sqrt().sqrt();
        let s = (x - T::from_f64(table_data::X0)) * T::from_f64(table_data::INV_WIDTH);
        let s = s.clamp_to(T::ZERO, T::from_usize(table_data::CELLS));
        let i = s.trunc_usize().min(table_data::CELLS - 1);
        let u = s - T::from_usize(i);
        let row = &table[i];
        let n = table_data::DEGREE + 1;
        let r1 = horner::<T>(row, 0, u);
        let b = horner::<T>(row, n, u);
        let d = horner::<T>(row, 2 * n, u);
        Shape {
            c: (T::ONE - g) * r1,
            m1: g * b / d,
            integrals: Integrals {
                k: b + d,
                e: (T::ONE + g) * b,
                b,
                d,
            },
        }
    }
}
