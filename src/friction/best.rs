//! `best`: an exact-grade fast Contensou–Erismann law — the exact quartic while the
//! instantaneous centre (IC) lies inside the ellipse, and outside the exact confocal structure
//! with seven fitted one-dimensional coefficients.
//!
//! # Formula
//!
//! Slip state (x, y, w) (see [`SlipState`]); the exact law's symmetries (F_x odd in x, F_y
//! odd in y, T_z odd in w, even otherwise) are built in: every formula below takes x² and y²,
//! and the signs come from the signed x (in cos ν or Y), y (sin ν or X) and w (τ, or w/|w|).
//! The IC is (X₀, Y₀) = (−y, x)/w.
//!
//! - **IC inside** (x² + m₁y² ≤ m₁w²): the exact quartic
//!   Ψ = C + (B/2)X₀² + (A/2)Y₀² + c₄₀(X₀⁴ + Y₀⁴/m₁) + c₂₂X₀²Y₀²,
//!   c₄₀ = −[(2−m)E − 2m₁K]/(8m²) = −(B − m₁A)/(12m) (Taylor series in m for m < 0.05),
//!   c₂₂ = −(A + 12c₄₀)/2: F_x = −∂Ψ/∂Y₀, F_y = ∂Ψ/∂X₀, T_z = −Ψ + X₀Ψ_X + Y₀Ψ_Y.
//! - **IC outside**: confocal coordinates a_c ≥ 1, ν of the IC (X₀ = −a_c sin ν,
//!   Y₀ = b_c cos ν, b_c² = a_c² − m), q = sin²ν, τ = (1 + γ)/(a_c + b_c) ∈ (0, 1]:
//!   F_x = −cos ν·(a_x + b_x q), F_y = −sin ν·(a_y + b_y q), T_z = τ·(a_T + b_T q + c_T q²).
//!   This structure is exact (re-verified to 2e-14 by `tools/gen_best_table.py`); only the
//!   seven coefficients, smooth functions of (e², z), z = √(1 − τ) ∈ [0, 1], are fitted:
//!   tensor Chebyshev series in (ln γ, z) of degree (8, 10) from the exact integrals
//!   (`best/table.rs`), plus a correction in z² that makes them exact at z = 0 (the ellipse,
//!   from the quartic) and at z = 1 (u = ∞: F = −v_P/|v_P|, T_z = T₁/u). The torque
//!   polynomial is clamped to its passive sign. The exact coefficients leave the ellipse like
//!   z² (they are smooth in a_c); the fit keeps that zero slope in z, so the law has no √-like
//!   onset at the boundary.
//!
//! [`BestContact`] (per contact, e² fixed) interpolates the series once into 8 cubic pieces in z
//! (Chebyshev–Lobatto nodes), so a call outside is four square roots, four or five divisions
//! and seven cubics, and inside one division and the quartic. [`Best`], the [`FrictionLaw`] (e² may change every call), sums the series per call.
//!
//! # Domain and special cases
//!
//! Every [`SlipState`] and every e². The fit covers e² ∈ [0, 0.99]; above that it uses
//! e² = 0.99's shape between exact ends (still exact inside, on the ellipse and at u = ∞), and
//! the error outside grows: measured (`f64`) 3.3e-2 fN / 3.0e-3 fNa at e² = 0.995, 9.3e-2 /
//! 8.1e-3 at 0.999, 0.19 / 1.4e-2 as e² → 1. Everywhere |F| is scaled back onto |F| ≤ 1 where
//! the fit would overshoot it (by up to 4e-4 past 0.99, by rounding below). The dimensionless core ignores δ; the dimensional
//! wrapper ramps it to zero below the slip scale δ ([`FrictionLaw::RAMP_BELOW_DELTA`]). Rest
//! gives zero, pure translation −v_P/|v_P| exactly, pure spin −C·sgn ω exactly.
//! Exact (to rounding) inside the ellipse, on its boundary and as u → ∞; continuous across the
//! boundary and between the cubic pieces (to a few rounding steps); symmetries bit-exact;
//! passive: each component opposes its own velocity (the torque by a clamp; the force brackets
//! a + b·q stay ≥ 0.3 over the table, and the quartic's by its structure), checked on random
//! states with |F| ≤ 1.
//!
//! # Error
//!
//! Against [`exact::traction`](super::exact::traction), max over a dense independent set
//! (`host-tests/friction_best.rs`: 32 values of e² ∈ [0, 0.99] clustered towards 0.99, 29 ψ in
//! all quadrants and on the axes, ≈90 u per direction: log grid 0.01 … 3e2, u_b(1 ± δ) for
//! δ = 1e-9 … 0.3, u ≈ 1, 1e4, 1e7, ∞):
//!
//! | form | force (fN) f64 / f32 | torque (fNa) f64 / f32 |
//! |---|---|---|
//! | [`BestContact`] | 5.2e-5 / 5.2e-5 | 4.0e-6 / 4.1e-6 |
//! | [`Best`] | 1.8e-6 / 2.0e-6 | 7.4e-7 / 8.7e-7 |
//!
//! worst at e² = 0.99 just outside the ellipse (u ≈ 1.03–1.1·u_b), where the coefficients vary
//! fastest in z (there the first cubic piece of [`BestContact`], which keeps the exact zero
//! slope in z at the ellipse, dominates).
//!
//! # Cost
//!
//! Cortex-M4F, `f32`, QEMU stage `friction` (mixed set: u log-uniform in [0.01, 100], ψ uniform,
//! e² = 0.5; the rig's 8-instruction call floor included):
//! [`BestContact::traction`] **107 instructions** on average (63 inside … 172 outside;
//! `simplified`: 66, so 1.62× on average, 2.6× worst on the set; 125 on the same set at
//! e² = 0.99, worst 174); the dimensional `Friction::<f32, Best>::tangential_prepared` 144
//! (`simplified`'s `tangential` 122); the full wrench `Contact::wrench` with fixed geometry 182
//! (144 with `simplified`); [`BestContact::new`] ([`FrictionLaw::prepare`]) 19,281 once per
//! contact; the per-call form [`Best`]`::traction` (e² changing every call) 1,324 on average,
//! 3,103 worst (the 693-term series is summed per call). `f64` (soft float): 5,931 / 87,114 per
//! call. Flash: the table is 7 × 9 × 11 `f32` = 2,772 bytes (+ 64 bytes of series);
//! RAM per contact: `BestContact<f32>` 948 bytes. Host (criterion, x86-64, mixed set): ≈20 ns
//! per call (`BestContact`), ≈100 ns (`Best`); `bench-results/friction.csv`.

mod table;

use super::{Constants, FrictionLaw, SlipState, Traction, larger};
use crate::Real;
use crate::math::{Backend, Libm};

/// Number of cubic pieces in z of [`BestContact`].
const PIECES: usize = 8;

/// The `best` law with e² read per call (see the [module docs](self)); the per-contact form,
/// much cheaper per call, is [`BestContact`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Best;

/// Where the IC lies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// No slip: zero traction.
    Rest,
    /// IC inside or on the ellipse: the exact quartic.
    Inside,
    /// IC outside (including pure translation): the confocal form.
    Outside,
}

/// The quartic's constants (first quadrant, X = |X₀|, Y = |Y₀|).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Quartic<T> {
    a: T,
    b: T,
    c: T,
    /// 2c₂₂
    k22: T,
    /// 4c₄₀
    k40: T,
    /// 4c₄₀/m₁
    k40m: T,
    /// B/2, A/2
    hb: T,
    ha: T,
    /// 3c₄₀, 3c₂₂, 3c₄₀/m₁
    t40: T,
    t22: T,
    t40m: T,
    m1: T,
}

/// c₄₀(m) = −[(2−m)E − 2(1−m)K]/(8m²), Taylor coefficients (m < 0.05: error < 1e-13).
const C40_SERIES: [f64; 8] = [
    -0.07363107781851078,
    -0.018407769454627694,
    -0.008628641931856732,
    -0.00503337446024976,
    -0.003303151989538905,
    -0.0023358003354596543,
    -0.001739684624847555,
    -0.0013461845311320366,
];

impl<T: Real> Quartic<T> {
    #[inline(always)]
    fn new(k: &Constants<T>) -> Self {
        let (m, m1, a, b) = (k.m(), k.m1(), k.slope_x(), k.slope_y());
        let c40 = if m < T::from_f64(0.05) {
            C40_SERIES
                .iter()
                .rev()
                .fold(T::ZERO, |acc, &c| acc * m + T::from_f64(c))
        } else {
            // B(m) − m₁D(m) = (2/3)(B − m₁A); c₄₀ = −(B(m) − m₁D(m))/(8m)
            -(b - m1 * a) / (T::from_f64(12.0) * m)
        };
        let c22 = -T::HALF * (a + T::from_f64(12.0) * c40);
        let k40 = T::from_f64(4.0) * c40;
        let three = T::from_f64(3.0);
        let t40 = three * c40;
        Quartic {
            a,
            b,
            c: k.spin_torque(),
            k22: T::TWO * c22,
            k40,
            k40m: k40 / m1,
            hb: T::HALF * b,
            ha: T::HALF * a,
            t40,
            t22: three * c22,
            t40m: t40 / m1,
            m1,
        }
    }

    /// (−F_x, −F_y, T_z) for X = y/|w|, Y = x/|w| (T_z for w > 0): F_x is odd in Y and even in
    /// X, F_y the reverse, T_z even in both.
    #[inline(always)]
    fn eval(&self, x: T, y: T) -> (T, T, T) {
        let (x2, y2) = (x * x, y * y);
        let fx = y * (self.a + self.k22 * x2 + self.k40m * y2);
        let fy = x * (self.b + self.k40 * x2 + self.k22 * y2);
        // −Ψ + XΨ_X + YΨ_Y: the quadratic terms once, the quartic ones three times.
        let tz = -self.c
            + x2 * (self.hb + self.t40 * x2 + self.t22 * y2)
            + y2 * (self.ha + self.t40m * y2);
        (fx, fy, tz)
    }

    /// The seven outside coefficients on the boundary (a_c = 1, τ = 1), from the quartic at
    /// (X₀, Y₀) = (−sin ν, γ cos ν).
    fn boundary(&self, gamma: T) -> [T; 7] {
        let (a, b, c, m1) = (self.a, self.b, self.c, self.m1);
        let c40 = T::from_f64(0.25) * self.k40;
        let c22 = T::HALF * self.k22;
        let three = T::from_f64(3.0);
        [
            gamma * (a + self.k40),
            gamma * (self.k22 - self.k40),
            b + self.k22 * m1,
            self.k40 - self.k22 * m1,
            -c + T::HALF * a * m1 + three * c40 * m1,
            T::HALF * (b - a * m1) + three * m1 * (c22 - T::TWO * c40),
            three * (c40 * (T::ONE + m1) - c22 * m1),
        ]
    }
}

/// The seven outside coefficients as functions of z: `d[j][l]` Chebyshev coefficients in
/// ẑ = 2z − 1 (e² fixed), corrected to the exact ends.
struct Series<T> {
    d: [[T; table::DZ + 1]; 7],
    /// Exact minus series at z = 0 and at z = 1.
    end0: [T; 7],
    end1: [T; 7],
}

impl<T: Real> Series<T> {
    fn new<B: Backend>(k: &Constants<T>, q: &Quartic<T>, gamma: T) -> Self {
        // λ = 1 + ln(m₁)/ln 10 ∈ [−1, 1] for e² ∈ [0, 0.99]
        let lam = (T::ONE + B::ln(k.m1()) * T::from_f64(1.0 / core::f64::consts::LN_10))
            .max(-T::ONE)
            .min(T::ONE);
        let mut tk = [T::ZERO; table::DG + 1];
        let (mut t0, mut t1) = (T::ONE, lam);
        for t in tk.iter_mut() {
            *t = t0;
            let t2 = T::TWO * lam * t1 - t0;
            (t0, t1) = (t1, t2);
        }
        let mut d = [[T::ZERO; table::DZ + 1]; 7];
        for (dj, tj) in d.iter_mut().zip(table::TABLE.iter()) {
            for (row, &t) in tj.iter().zip(tk.iter()) {
                for (dl, &c) in dj.iter_mut().zip(row.iter()) {
                    *dl += T::from_f64(f64::from(c)) * t;
                }
            }
        }
        let g5 = T::from_f64(0.4) / (T::ONE + gamma);
        let inf = [T::ONE, T::ZERO, T::ONE, T::ZERO, -g5, g5 * k.m(), T::ZERO];
        let bnd = q.boundary(gamma);
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
        Series { d, end0, end1 }
    }

    /// The seven coefficients at z ∈ [0, 1].
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

/// Confocal coordinates of the IC for x, y, w (IC outside or pure translation):
/// (cos ν, sin ν, τ, 1 − |τ|), with the signs of x and y on cos ν and sin ν and that of w on τ.
#[inline(always)]
fn confocal<T: Real>(m: T, g1: T, x: T, y: T, w: T) -> (T, T, T, T) {
    let p = x * x + y * y;
    let w2 = w * w;
    let mw2 = m * w2;
    let dlt = p - mw2;
    let mx2w2 = mw2 * x * x;
    let r = (dlt * dlt + T::from_f64(4.0) * mx2w2).sqrt();
    // (a_c w)², (b_c w)² without cancellation
    let a2 = T::HALF * (p + mw2 + r);
    let b2 = if dlt >= T::ZERO {
        T::HALF * (dlt + r)
    } else {
        T::TWO * mx2w2 / (r - dlt)
    };
    let (ac, bc) = (a2.sqrt(), larger(b2.sqrt(), T::MIN_POSITIVE));
    let tau = g1 * w / (ac + bc);
    (x / bc, y / ac, tau, T::ONE - tau.abs())
}

/// Puts the signs back and clamps the coefficients to their passive signs.
#[inline(always)]
fn assemble<T: Real>(c: T, sn: T, tau: T, k: &[T; 7]) -> Traction<T> {
    let q = sn * sn;
    // a + b·q ≥ 0.3 over the fitted domain (tested): no clamp needed for the forces, whose
    // signs come from c = cos ν and sn = sin ν (computed from the signed x and y).
    // τ carries the sign of w; the polynomial is clamped to its passive sign (≤ 0).
    let t = k[4] + q * (k[5] + k[6] * q);
    Traction {
        fx: -c * (k[0] + k[1] * q),
        fy: -sn * (k[2] + k[3] * q),
        tz: tau * if t < T::ZERO { t } else { T::ZERO },
    }
}

/// |F| ≤ 1: past the fitted range (e² > 0.99) the fit can overshoot it by up to 4e-4 (inside
/// the range only by rounding); scale back onto the unit disk (a positive factor: passivity
/// and continuity are kept). One compare on the common path.
#[inline(always)]
fn bounded<T: Real>(t: Traction<T>) -> Traction<T> {
    let f2 = t.fx * t.fx + t.fy * t.fy;
    if f2 > T::ONE { rescale(t, f2) } else { t }
}

#[cold]
#[inline(never)]
fn rescale<T: Real>(t: Traction<T>, f2: T) -> Traction<T> {
    let r = T::ONE / f2.sqrt();
    Traction {
        fx: t.fx * r,
        fy: t.fy * r,
        tz: t.tz,
    }
}

/// Inside branch or rest: `None` when the IC is outside. The forces take their signs from the
/// signed x, y (F_x odd in x, F_y odd in y, both even in the rest), the torque from w.
#[inline(always)]
fn inside<T: Real>(q: &Quartic<T>, s: &SlipState<T>) -> Option<(Traction<T>, Branch)> {
    let (x, y, w) = (s.x(), s.y(), s.w());
    if x * x + q.m1 * y * y > q.m1 * w * w {
        return None;
    }
    if w == T::ZERO {
        return Some((Traction::default(), Branch::Rest));
    }
    let iw = T::ONE / w.abs();
    let (fx, fy, tz) = q.eval(y * iw, x * iw);
    // Exact: the brackets of fx, fy are > 0 and tz ≤ −0.003 (e² = 0.99) by the quartic's
    // structure.
    Some((
        Traction {
            fx: -fx,
            fy: -fy,
            // tz < 0; w/|w| = ±1 up to one rounding, exactly odd in w
            tz: tz * (w * iw),
        },
        Branch::Inside,
    ))
}

/// κ(e²): the largest stiffness of `best`'s ramped law in units of fN/δ — the supremum, over
/// every slip direction and every spin ratio aω/δ ∈ [0, ∞), of the largest eigenvalue of the
/// translational Jacobian −(δ/fN)·∂F/∂v_P. The stable explicit step
/// ([`Friction::stable_step`](super::Friction::stable_step) for `Best`) is limit·mδ/(κ·fN).
///
/// # Formula
///
/// With D′ = (A − B)/m = −2c₂₂ (the quartic's coefficient; 3π/32 at m = 0), γ = √m₁:
///
/// ```text
/// ρ* = A/(D′ + √(D′² + 3AD′)),   κ_axis = (1 + ρ*)(A − D′ρ*²),
/// κ = κ_axis·(1 + γ^{3/2}·(0.3861 + 0.0259γ))
/// ```
///
/// # Why
///
/// Below the slip scale (s = |v_Px| + |v_Py| + a|ω| < δ) the wrapper scales the core by s/δ,
/// so F = −(fN/δ)·s·P(v, aω) with P the core's (−F_x, −F_y)/(fN): homogeneous of degree one,
/// its Jacobian K = s·∂P/∂v + P·σᵀ (σ = the signs of v_P, from ∂s/∂v) depends on the direction
/// of (v_P, aω) only. While the instantaneous centre lies inside the ellipse, P is the exact
/// quartic's gradient, so K is a polynomial matrix in (X₀, Y₀) = (−v_Py, v_Px)/(aω). At rest
/// with spin K = diag(A, B); without spin (pure translation) its eigenvalues are
/// |cos ψ| + |sin ψ| ≤ √2 (the ℓ¹ slip scale). Neither is the maximum: s grows with the slip
/// while the core's slope falls off slowly, and their product peaks in between — for a circle
/// with the IC at 0.66a on a diagonal (κ = 2.5135 = 2.13·A), moving onto the major axis as
/// e² → 1. On that axis (v_Px = 0) K is triangular and its first eigenvalue is
/// (1 + ρ)(A − D′ρ²) at |X₀| = ρ, maximal at ρ*: the closed form κ_axis, the exact sup in the
/// limit e² → 1 (≈ (32/27)·A once A ≫ B). The fitted factor 1 + γ^{3/2}·(0.3861 + 0.0259γ)
/// bounds the excess of the off-axis maximum (0 as e² → 1, 40.7 % at the circle). With the IC
/// outside the ellipse, and past the ramp (s ≥ δ: fN/s times the core's own stiffness, whose
/// sup is lower), the stiffness is smaller: checked on the whole direction sphere, for the
/// exact law and for `best` (`host-tests/stability.rs`; complex eigenvalue pairs, small, are
/// counted by Euler's |λ|²/Re λ). `best` is exact inside the ellipse, so its κ is the exact
/// law's.
///
/// # Domain and accuracy
///
/// Every valid e² (m₁ ∈ [m₁_min, 1]); finite and ≥ 2.51. Against the maximisation of
/// `tools/gen_best_stiffness.py` (mpmath; `tools/data/best_stiffness.csv`, m₁ from 1 to 1e-12):
/// never below it (`f64`; `f32` to rounding), at most 0.35 % above (conservative). Values:
/// 2.522 (circle; exact sup 2.5135), 2.694 (e² = 0.5), 3.492 (0.9), 5.187 (0.99), 7.131 (0.999),
/// 25.48 (m₁ = 1e-12). Cost: three square roots, four divisions (three in the quartic's
/// constants) and a few multiplications — construction or host use, not per step; not yet
/// measured on the Cortex-M4F.
pub fn ramp_stiffness<T: Real>(k: &Constants<T>) -> T {
    let q = Quartic::new(k);
    let a = q.a;
    // D′ = −k₂₂ = −2c₂₂ > 0 (c₂₂: the quartic's X₀²Y₀² coefficient), free of cancellation at
    // small m.
    let dp = -q.k22;
    let rho = a / (dp + (dp * dp + T::from_f64(3.0) * a * dp).sqrt());
    let axis = (T::ONE + rho) * (a - dp * rho * rho);
    let gamma = k.m1().sqrt();
    let fit = T::from_f64(0.3861) + T::from_f64(0.0259) * gamma;
    axis * (T::ONE + gamma * gamma.sqrt() * fit)
}

/// κ_T(e²): the largest torque stiffness of `best`'s ramped law in units of fN·a²/δ — the
/// supremum, over every slip direction and every spin ratio aω/δ, of −(δ/(fN·a²))·∂T_z/∂ω
/// with v_P held fixed. The stable explicit step for the spin
/// ([`Friction::stable_spin_step`](super::Friction::stable_spin_step) for `Best`) is
/// limit·Iδ/(κ_T·fN·a²).
///
/// # Formula
///
/// With the IC (X, Y) = (−v_Py, v_Px)/(aω) inside the ellipse (X² + Y²/m₁ ≤ 1) and the exact
/// quartic's pieces q₂ = (B/2)X² + (A/2)Y², q₄ = 3[c₄₀(X⁴ + Y⁴/m₁) + c₂₂X²Y²] (torque
/// T_z/(fNa) = −C + q₂ + q₄ for ω > 0):
///
/// ```text
/// k_T(X, Y) = C + q₂ + 3q₄ + (|X| + |Y|)·(2q₂ + 4q₄),     κ_T = max k_T over the ellipse
/// ```
///
/// maximised numerically over X = ρ cos θ, Y = γρ sin θ (ρ ∈ [0, 1], θ ∈ [0, π/2]): along
/// each ray k_T is a quintic in ρ with one maximum (golden-section search, 64 steps); over θ a
/// 65-point grid, then a golden-section search around its best point — a fixed amount of work.
///
/// # Why
///
/// Below the slip scale (s = |v_Px| + |v_Py| + a|ω| < δ) the wrapper gives
/// T_z = fN·a·(s/δ)·τ with τ the core's torque, homogeneous of degree 0 in (v_P, aω). So
/// −∂T_z/∂ω = (fN·a²/δ)·(−sgn ω·τ − s·∂τ/∂(aω)), a function of the slip direction only;
/// with ∂X/∂(aω) = −X/(aω) (and Y alike) and τ = −C + q₂ + q₄ (X·τ_X + Y·τ_Y = 2q₂ + 4q₄)
/// this is k_T. In pure spin k_T = C (the plateau −C·fNa ramped over a|ω| < δ: stiffness
/// C·fN·a²/δ); a slip inside the ramp makes s/|aω| = 1 + |X| + |Y| grow faster than the
/// core's torque falls, and the product peaks in between: κ_T ≈ 1.90–1.97·C (circle:
/// 1.1410 = 1.937·C with the IC at 0.82a on a diagonal). With the IC outside the ellipse, and
/// past the ramp (s ≥ δ: fN·a²/s times the core's own slope), the stiffness is smaller:
/// checked on the whole direction sphere for the exact law and for `best`
/// (`host-tests/stability.rs`). `best` is exact inside the ellipse, so its κ_T is the exact
/// law's. Not covered: the coupling with translation (F depends on ω and T_z on v_P; a body
/// whose v_P and ω both move has a 3 × 3 Jacobian whose largest eigenvalue depends on I/(ma²)).
///
/// # Domain and accuracy
///
/// Every valid e²; finite, ≥ C. Against the maximisation of `tools/gen_spin_stiffness.py`
/// (mpmath; `tools/data/spin_stiffness.csv`, m₁ from 1 to 1e-12): measured within 7.5e-15
/// (`f64`) and 1.9e-7 (`f32`) relative (asserted ≤ 1e-12 and ≤ 1e-6 by
/// `host-tests/stability.rs`). Below m₁ ≈ 1e-5 the maximiser lies on the ellipse and the sphere
/// check (e² ≤ 0.99) does not cover the outside there. Cost: ≈ 9,000 evaluations of a quintic
/// and 133 sine–cosines (host ≈ 26 µs, `f32` or `f64`) — construction or host use, not per
/// step; not measured on the Cortex-M4F.
pub fn spin_stiffness<T: Real>(k: &Constants<T>) -> T {
    /// Grid points over θ; golden-section steps over θ and over ρ.
    const GRID: usize = 64;
    const GOLDEN: usize = 64;
    let q = Quartic::new(k);
    let gamma = k.m1().sqrt();
    let (two, three, four) = (T::TWO, T::from_f64(3.0), T::from_f64(4.0));
    let g = T::from_f64(0.618_033_988_749_894_8);
    // Golden-section search for the maximum of a unimodal `f` on [lo, hi]: (argmax, max).
    let golden = |f: &dyn Fn(T) -> T, mut lo: T, mut hi: T| {
        let mut x1 = hi - g * (hi - lo);
        let mut x2 = lo + g * (hi - lo);
        let (mut f1, mut f2) = (f(x1), f(x2));
        for _ in 0..GOLDEN {
            if f1 < f2 {
                lo = x1;
                (x1, f1) = (x2, f2);
                x2 = lo + g * (hi - lo);
                f2 = f(x2);
            } else {
                hi = x2;
                (x2, f2) = (x1, f1);
                x1 = hi - g * (hi - lo);
                f1 = f(x1);
            }
        }
        // the ends too: the maximum may sit on them (ρ = 1, the ellipse)
        let (fl, fh) = (f(lo), f(hi));
        let mut best = if f1 < f2 { (x2, f2) } else { (x1, f1) };
        for c in [(lo, fl), (hi, fh)] {
            if c.1 > best.1 {
                best = c;
            }
        }
        best
    };
    // Max over ρ ∈ [0, 1] along the ray θ: k_T = C + ρ²(Q₂ + ρ(2LQ₂ + ρ(3Q₄ + 4LQ₄ρ))),
    // unimodal in ρ (its slope over ρ is concave with a positive start).
    let ray = |theta: T| {
        let (s, c) = theta.sin_cos();
        let (cx, cy) = (c, gamma * s);
        let (x2, y2) = (cx * cx, cy * cy);
        let q2 = q.hb * x2 + q.ha * y2;
        let q4 = x2 * (q.t40 * x2 + q.t22 * y2) + q.t40m * y2 * y2;
        let l = cx + cy;
        let (p3, p4, p5) = (two * l * q2, three * q4, four * l * q4);
        let f = |rho: T| q.c + rho * rho * (q2 + rho * (p3 + rho * (p4 + rho * p5)));
        golden(&f, T::ZERO, T::ONE).1
    };
    let n = T::from_usize(GRID);
    let step = T::FRAC_PI_2 / n;
    let mut best = (T::ZERO, ray(T::ZERO));
    for i in 1..=GRID {
        let theta = T::from_usize(i) * step;
        let v = ray(theta);
        if v > best.1 {
            best = (theta, v);
        }
    }
    let lo = larger(best.0 - step, T::ZERO);
    let hi = (best.0 + step).min(T::FRAC_PI_2);
    let refined = golden(&ray, lo, hi).1;
    larger(refined, best.1)
}

impl Best {
    /// Measured max error against the exact integrals, e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (`f64`; measured 1.8e-6, 7.4e-7): (force in fN, torque in fNa), asserted by
    /// `host-tests/friction_best.rs`.
    pub const ERROR: (f64, f64) = (2.0e-6, 1.0e-6);
}

impl FrictionLaw for Best {
    const NAME: &'static str = "best";
    type Branch = Branch;
    type Prepared<T: Real> = BestContact<T>;
    const RAMP_BELOW_DELTA: bool = true;

    /// κ = [`ramp_stiffness`]`(k)`.
    fn slip_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        Some(ramp_stiffness(k))
    }

    /// κ_T = [`spin_stiffness`]`(k)`.
    fn spin_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        Some(spin_stiffness(k))
    }

    /// The per-call form (e² may change every call): the fitted series summed at this e².
    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        Self::per_call::<Libm, T>(k, s)
    }

    /// Build the per-contact tables ([`BestContact::new`]).
    fn prepare<T: Real>(k: &Constants<T>) -> BestContact<T> {
        BestContact::new(k)
    }

    /// The per-contact form: [`BestContact::traction`].
    #[inline(always)]
    fn traction_prepared<T: Real>(p: &BestContact<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        p.traction(s)
    }
}

impl Best {
    fn per_call<B: Backend, T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        let q = Quartic::new(k);
        if let Some(r) = inside(&q, s) {
            return r;
        }
        let gamma = k.m1().sqrt();
        let g1 = T::ONE + gamma;
        let (c, sn, tau, one_minus) = confocal(k.m(), g1, s.x(), s.y(), s.w());
        let z = larger(one_minus, T::ZERO).sqrt();
        let co = Series::new::<B>(k, &q, gamma).at(z);
        let t = assemble(c, sn, tau, &co);
        let t = bounded(t);
        (t, Branch::Outside)
    }
}

/// [`Best`]'s per-call form with micromath's `ln` for the series' λ = 1 + log₁₀ m₁ (feature
/// `micromath`; `f32` only, libm for `f64`). The square roots stay [`Real::sqrt`] (the
/// confocal coordinates need them exact). [`FrictionLaw::prepare`] gives the [`Constants`]
/// unchanged: the per-contact form of `best` is [`BestContact`], which calls no `ln`.
///
/// Formula, domain, branches: as [`Best`]; `f64` is [`Best`]. Measured max error against the
/// exact integrals (`f32`, the 4,329 states of host-tests/micromath.rs, asserted there):
/// **2.6e-6 fN / 8.9e-7 fNa** ([`Best`]: 2.0e-6 / 8.8e-7 on the same set), so above
/// [`Best::ERROR`]'s force figure but far inside issue 5's 5e-4. Cost: M4F **1,297**
/// instructions on average (`f32`; [`Best`] per call 1,324), host ≈ 195 ns (as [`Best`] within
/// noise). Marginal: 2 % fewer instructions, only where e² changes every call.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BestMicromath;

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl FrictionLaw for BestMicromath {
    const NAME: &'static str = "best-micromath";
    type Branch = Branch;
    const RAMP_BELOW_DELTA: bool = true;

    /// κ = [`ramp_stiffness`]`(k)`.
    fn slip_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        Some(ramp_stiffness(k))
    }

    /// κ_T = [`spin_stiffness`]`(k)`.
    fn spin_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        Some(spin_stiffness(k))
    }
    super::law::constants_are_prepared!();

    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        Best::per_call::<crate::math::Micromath, T>(k, s)
    }
}

/// The `best` law for one contact shape (e² fixed): the quartic's constants and the seven
/// outside coefficients as 8 cubic pieces in z, built once by [`BestContact::new`]
/// (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BestContact<T> {
    quartic: Quartic<T>,
    m: T,
    g1: T,
    /// `pieces[i][j]`: cubic in r = 8z − i of coefficient j (monomial, r ∈ [0, 1]).
    pieces: [[[T; 4]; 7]; PIECES],
}

impl<T: Real> BestContact<T> {
    /// Measured max error against the exact integrals, e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (`f64`): (force in fN, torque in fNa). See `host-tests/friction_best.rs`.
    pub const ERROR: (f64, f64) = (5.5e-5, 4.5e-6);

    /// From the patch constants: sums the fitted series at this e² and interpolates them at
    /// the Chebyshev–Lobatto nodes r ∈ {0, 1/4, 3/4, 1} of each of 8 pieces. Total.
    pub fn new(k: &Constants<T>) -> Self {
        let quartic = Quartic::new(k);
        let gamma = k.m1().sqrt();
        let series = Series::new::<Libm>(k, &quartic, gamma);
        let mut pieces = [[[T::ZERO; 4]; 7]; PIECES];
        let n = T::from_usize(PIECES);
        let nodes = [0.0, 0.25, 0.75, 1.0];
        // Inverse Vandermonde of the nodes: monomial coefficients from node values.
        let inv: [[f64; 4]; 4] = [
            [1.0, 0.0, 0.0, 0.0],
            [-19.0 / 3.0, 8.0, -8.0 / 3.0, 1.0],
            [32.0 / 3.0, -56.0 / 3.0, 40.0 / 3.0, -16.0 / 3.0],
            [-16.0 / 3.0, 32.0 / 3.0, -32.0 / 3.0, 16.0 / 3.0],
        ];
        let half = series.at(T::HALF / n);
        for (i, piece) in pieces.iter_mut().enumerate() {
            let vals = nodes.map(|r| series.at((T::from_usize(i) + T::from_f64(r)) / n));
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
        BestContact {
            quartic,
            m: k.m(),
            g1: T::ONE + gamma,
            pieces,
        }
    }

    /// The dimensionless traction (F/(fN), T_z/(fNa)) and the branch for a slip state.
    /// Total: finite output for every state.
    #[inline(always)]
    pub fn traction(&self, s: &SlipState<T>) -> (Traction<T>, Branch) {
        if let Some(r) = inside(&self.quartic, s) {
            return r;
        }
        let (c, sn, tau, one_minus) = confocal(self.m, self.g1, s.x(), s.y(), s.w());
        let zn = larger(one_minus, T::ZERO).sqrt() * T::from_usize(PIECES);
        let i = zn.trunc_usize().min(PIECES - 1);
        let r = zn - T::from_usize(i);
        let piece = &self.pieces[i];
        let co = piece.map(|p| p[0] + r * (p[1] + r * (p[2] + r * p[3])));
        (bounded(assemble(c, sn, tau, &co)), Branch::Outside)
    }
}
