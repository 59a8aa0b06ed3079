//! FASTSIM (Kalker 1982) with the elliptic (Hertz) traction bound, on a fixed Chebyshev grid.
//!
//! # Formula
//!
//! Kalker's simplified theory: the surface displacement difference is u = L·p, with one
//! flexibility per creepage chosen so that the linear theory comes out for ξ, η and the spin
//! force: L₁ = 8a/(3C₁₁G), L₂ = 8a/(3C₂₂G), L₃ = πa√(a/b)/(4C₂₃G). Material enters the patch at
//! the leading edge x = +a(y) traction-free and moves towards −x; along each strip the traction
//! p = (p_x, p_y) is marched over the nodes x_k (from +a(y) to −a(y)): the trial
//! q = p_k − Δx·(ξ/L₁ − φy/L₃, η/L₂ + φx̄/L₃) (x̄ the interval's midpoint) is kept where
//! |q| ≤ f·p_H(x, y) (adhesion; p_H the Hertz pressure — the elliptic bound, not Kalker's
//! parabolic one), else the node slips and takes the bound f·p_H in the direction
//! d = q̃ − (f·p_H/|q|)(q̃ − q), where q̃ is the trial with one common flexibility
//! L̄ = 2/(1/L₁ + 1/L₂) for every creepage. d = q at the onset of slip (continuity), and
//! d → −(ξ − φy, η + φx) as the creepage → ∞ or V → 0: the traction then opposes the rigid
//! slip everywhere, i.e. the Contensou–Erismann integrals over the Hertz pressure (the original
//! FASTSIM, which scales q radially, would saturate along the weighted creepage instead).
//!
//! Grid: strips at y = b cos ϑ_j, ϑ_j = (j + ½)π/N_y (midpoint rule in ϑ), nodes at
//! x = a(y) cos θ_k, θ_k = kπ/(N_x − 1) (trapezoid rule in θ). On this grid the Hertz bound is
//! a product of sines (no square root), and the full-slip integrand sin²ϑ·sin²θ·(direction) is
//! integrated spectrally where the direction is smooth. Every component is homogeneous in
//! (v_x, v_y, cω, V) ([`super::Scaled`]): V = 0 needs no division.
//!
//! # Domain and special cases
//!
//! Every input; rest → zero; V = 0 → full slip on the grid; V < 0 by the mirror
//! ([`super::RollingSlip`]). Fixed cost: N_x·N_y nodes, no data-dependent loop.
//!
//! # Error
//!
//! Measured (`host-tests/rolling.rs`, f64, a/b ∈ {0.2, 0.5, 1, 2, 5}):
//! - linear limit (creepage at 1e-6 of saturation, ν ∈ {0, 0.25, 0.5}): F_x, F_y within
//!   8.6e-4 (relative) of −Gc²C₁₁ξ, −Gc²C₂₂η, −Gc³C₂₃φ on the 32 × 32 grid (the trapezoid
//!   rule's O(h²) on the adhesion traction). FASTSIM's linear M_z is the simplified theory's,
//!   not Kalker's: η → M_z goes through L₂ (Kalker: C₂₃), φ → M_z through L₃ — its known
//!   weakness on the spin moment.
//! - full slip (V = 0, 840 directions of (v_x, v_y, cω) per shape): 7.4e-3 fN on F and
//!   5.3e-3 fNc on M_z against the exact integrals on 32 × 32, 2.7e-2 / 2.0e-2 on 16 × 16
//!   (O(h²): the slip direction turns fast near the instantaneous centre when it lies in the
//!   patch).
//! - passivity: the simplified theory's quadratic form can be indefinite for long patches
//!   (a/b ≈ 90: power +2e-6·fN|v| before the fix), because its η → M_z and φ → F_y couplings
//!   use different flexibilities; a positive power P = F·v + M_zω is removed by
//!   W ← W − P·u/|u|², u = (v_x, v_y, cω) (continuous; only states with P > 0 change). Then
//!   passive and |F| ≤ fN on 1e5 random states.
//! - against the exact steady-rolling reference: `host-tests/rolling_ref.rs`.
//!
//! # Cost
//!
//! Per node ≈ 30 arithmetic instructions in adhesion, plus two square roots and two divisions
//! when slipping; N_x·N_y nodes (1,024 on 32 × 32, 256 on 16 × 16). M4F, f32, the dimensional
//! call (firmware stage `rolling`, 64 creep-curve states): 44,340 instructions on 32 × 32,
//! 11,221 on 16 × 16 (9,418 … 15,662). Not an MCU per-step law at these grids; the default law
//! [`super::Table`] is.

use super::contact::{Creep, Input, RollingLaw};
use crate::Real;

/// FASTSIM on an `NX` × `NY` grid (see the [module docs](self)); `NX` ≥ 3, `NY` ≥ 1.
#[derive(Clone, Copy, Debug, Default)]
pub struct FastsimGrid<const NX: usize, const NY: usize>;

/// FASTSIM on the 32 × 32 grid (the module's figures; [`FastsimGrid`]`<16, 16>` is 4× cheaper
/// and 4× less accurate at full slip).
pub type Fastsim = FastsimGrid<32, 32>;

/// Taylor series of (sin x, cos x) for |x| ≤ π, to f64 rounding (const-evaluable).
const fn sin_cos(x: f64) -> (f64, f64) {
    let (mut s, mut c) = (0.0, 0.0);
    let (mut ts, mut tc) = (x, 1.0);
    let mut n = 0;
    while n < 25 {
        s += ts;
        c += tc;
        let k = (2 * n + 1) as f64;
        tc *= -x * x / (k * (k + 1.0));
        ts *= -x * x / ((k + 1.0) * (k + 2.0));
        n += 1;
    }
    (s, c)
}

/// [cos, sin] of N angles: θ_k = kπ/(N − 1) (`ends`) or (k + ½)π/N.
const fn angles<const N: usize>(ends: bool) -> [[f64; N]; 2] {
    let mut t = [[0.0; N]; 2];
    let mut k = 0;
    while k < N {
        let th = if ends {
            k as f64 * core::f64::consts::PI / (N - 1) as f64
        } else {
            (k as f64 + 0.5) * core::f64::consts::PI / N as f64
        };
        let (s, c) = sin_cos(th);
        t[0][k] = c;
        t[1][k] = if s > 0.0 { s } else { 0.0 };
        k += 1;
    }
    t
}

const fn narrow<const N: usize>(t: [[f64; N]; 2]) -> [[f32; N]; 2] {
    let mut o = [[0.0f32; N]; 2];
    let mut k = 0;
    while k < N {
        o[0][k] = t[0][k] as f32;
        o[1][k] = t[1][k] as f32;
        k += 1;
    }
    o
}

impl<const NX: usize, const NY: usize> FastsimGrid<NX, NY> {
    const X64: [[f64; NX]; 2] = angles::<NX>(true);
    const X32: [[f32; NX]; 2] = narrow(Self::X64);
    const Y64: [[f64; NY]; 2] = angles::<NY>(false);
    const Y32: [[f32; NY]; 2] = narrow(Self::Y64);
}

impl<const NX: usize, const NY: usize> RollingLaw for FastsimGrid<NX, NY> {
    const NAME: &'static str = "fastsim";
    const FULL_SLIP: bool = false;

    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        let [cx, sx] = T::of_precision(&Self::X32, &Self::X64);
        let [cy, sy] = T::of_precision(&Self::Y32, &Self::Y64);
        let k = &i.contact.kalker;
        let rho = i.contact.rho; // √(a/b)
        let irho = T::ONE / rho;
        // increments per unit ΔX (X = x/a, Y = y/b), traction in units of f·p₀:
        // a/(L f p₀) = (π/4)·C·κ, spin: (8/3)C₂₃κ·(b/a)·Y·ŵ and (8/3)C₂₃κ·X·ŵ
        let quarter_pi = T::FRAC_PI_4;
        let k1 = quarter_pi * k.c11 * i.kappa;
        let k2 = quarter_pi * k.c22 * i.kappa;
        let k3 = T::from_f64(8.0 / 3.0) * k.c23 * i.kappa;
        let kb = T::HALF * (k1 + k2);
        let (vx, vy, w, v) = (i.vx, i.vy, i.w, i.v);
        // per-creepage pieces: adhesion increment (a) and common-flexibility increment (b)
        let ax0 = k1 * vx;
        let ax1 = k3 * w * irho * irho; // × Y
        let ay0 = k2 * vy;
        let ay1 = k3 * w; // × X̄
        let bx0 = kb * vx;
        let bx1 = kb * w * irho; // × Y
        let by0 = kb * vy;
        let by1 = kb * w * rho; // × X̄
        let inv_v = T::ONE / v.max(T::MIN_POSITIVE);
        let (mut fx, mut fy, mut mz) = (T::ZERO, T::ZERO, T::ZERO);
        for j in 0..NY {
            let (yy, sj) = (T::from_base(cy[j]), T::from_base(sy[j]));
            let (dx0, dy0) = (ax0 - ax1 * yy, ay0);
            let (ex0, ey0) = (bx0 - bx1 * yy, by0);
            let (mut px, mut py) = (T::ZERO, T::ZERO);
            let (mut sfx, mut sfy, mut smz) = (T::ZERO, T::ZERO, T::ZERO);
            let mut xprev = sj;
            for kk in 1..NX {
                let x = sj * T::from_base(cx[kk]);
                let dxx = xprev - x;
                let xm = T::HALF * (xprev + x);
                xprev = x;
                let qx = v * px - dxx * dx0;
                let qy = v * py - dxx * (dy0 + ay1 * xm);
                let g = sj * T::from_base(sx[kk]);
                let bound = v * g;
                let q2 = qx * qx + qy * qy;
                if q2 <= bound * bound {
                    px = qx * inv_v;
                    py = qy * inv_v;
                } else {
                    let tx = v * px - dxx * ex0;
                    let ty = v * py - dxx * (ey0 + by1 * x);
                    let r = bound / q2.sqrt();
                    let (ddx, ddy) = (tx - r * (tx - qx), ty - r * (ty - qy));
                    let d = (ddx * ddx + ddy * ddy).sqrt();
                    let s = if d > T::ZERO { g / d } else { T::ZERO };
                    px = ddx * s;
                    py = ddy * s;
                }
                let wk = T::from_base(sx[kk]);
                sfx += wk * px;
                sfy += wk * py;
                smz += wk * (rho * x * py - irho * yy * px);
            }
            let ws = sj * sj;
            fx += ws * sfx;
            fy += ws * sfy;
            mz += ws * smz;
        }
        // (3/(2π))·Δθ·Δϑ
        let scale = T::from_f64(
            3.0 / (2.0 * core::f64::consts::PI) * core::f64::consts::PI / (NX - 1) as f64
                * core::f64::consts::PI
                / NY as f64,
        );
        super::contact::passive(
            Creep {
                fx: fx * scale,
                fy: fy * scale,
                mz: mz * scale,
            },
            vx,
            vy,
            w,
        )
    }
}
