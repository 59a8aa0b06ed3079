//! The exact traction while the instantaneous centre (IC) lies outside the ellipse: polar
//! coordinates about the IC, closed-form radial integrals, Gauss–Legendre over the ray angle.
//!
//! # Formula
//!
//! Stretch y by 1/γ (γ = √m₁): the patch becomes the unit disk, the IC the point
//! IC′ = (X₀, Y₀/γ) at distance R = 1/r > 1 from the centre, and rays from the IC stay rays.
//! Parametrise them by their stretched angle φ = φ_c + β, φ_c the direction from IC′ to the
//! centre, |β| ≤ b = asin r. Along a ray the slip direction is constant — the physical ray
//! direction d = (cos φ, γ sin φ)/n turned by +90°, n(φ) = √(cos²φ + m₁ sin²φ) — and the chord
//! through the disk has midpoint distance s_m = R cos β from IC′ and half-length h with
//! h² = 1 − S², S = R sin β. The radial integrals of the Hertz weight √(h² − (s − s_m)²) against
//! s and s² are (π/2)s_m h² and (π/2)s_m²h² + (π/8)h⁴, so (forces in fN, torque in fNa)
//!
//! ```text
//! F   = −(3/4)·R ∫ (−γ sin φ, cos φ)/n · cos β·(1 − S²) dβ
//! T_z = (3/4)·m·R ∫ S·cos β·(1 − S²)·sin φ cos φ/n dβ − (3/16) ∫ n·(1 − S²)² dβ
//! ```
//!
//! (the torque's first term is the moment of the chord midpoint, M_mid·d = −m S sin φ cos φ/n:
//! every term is O(1), so there is no cancellation as u → ∞ where T_z = O(1/u)).
//!
//! The integrands are trigonometric polynomials in β times n^{±1}: entire except the branch
//! points of n at φ = ±π/2 ± i·atanh γ, which come close to the real axis in thin ellipses.
//! The β-range is split at 0 and at the branch point's real part when inside; on each panel that
//! has a branch point within one panel width, β = q + g·sinh t (q its real part,
//! g = min(atanh γ, 1)) spreads the nodes around it, then 32-point Gauss–Legendre in t
//! (otherwise directly in β). At most 3 panels: 96 nodes (192 when γ < 0.01, where each sinh
//! panel is split in two in t). Each node's φ is carried as its offset δ from the branch point
//! it is mapped around (φ = ∓π/2 + δ), so n keeps full relative accuracy even where it is ≈ γ
//! (m₁ = 1e-12: without that, 3e-11 errors).
//!
//! # Accuracy
//!
//! Max abs error 5e-15 against the reference (e² up to 1 − 1.5e-12, u from just outside the
//! boundary to 1e3). In a Python mirror of this code: 24 nodes per panel would still give 6e-13,
//! 20 give 4e-10; for m₁ down to 1e-12 the rule agrees with a 300-node one to 5e-14.

use super::gauss::{NODES, WEIGHTS};
use core::f64::consts::PI;

/// (F_x, F_y, T_z) for the IC outside: `vx, vy ≥ 0`, `w = aω > 0`, vy² + vx²/m₁ > w².
pub(super) fn traction(m: f64, m1: f64, vx: f64, vy: f64, w: f64) -> (f64, f64, f64) {
    let gamma = libm::sqrt(m1);
    let r = w / libm::sqrt(vy * vy + vx * vx / m1); // 1/R ∈ (0, 1)
    let b = libm::asin(r.min(1.0));
    let g = if gamma < 0.76 {
        libm::atanh(gamma)
    } else {
        1.0
    };
    // Branch points' real parts in β: φ = −π/2 at q1 ∈ [−π/2, 0], φ = +π/2 at q2 = q1 + π.
    // q1 = −π/2 − φ_c = −atan2(γ v_y, v_x), formed without cancellation; every node's φ is
    // carried as its offset δ from one of them, so n(φ) keeps its relative accuracy near them.
    let q1 = -libm::atan2(gamma * vy, vx);
    let q2 = q1 + PI;
    let split = q1 > -b && q1 < 0.0;
    let panels = [
        (-b, if split { q1 } else { 0.0 }),
        (if split { q1 } else { 0.0 }, 0.0),
        (0.0, b),
    ];
    let ray = Ray { r, m1, gamma };
    let mut acc = Sums::default();
    for (lo, hi) in panels {
        if hi > lo {
            let near = |q: f64| (lo - q).max(q - hi).max(0.0);
            let upper = near(q2) < near(q1);
            let (q, d) = if upper {
                (q2, near(q2))
            } else {
                (q1, near(q1))
            };
            if d > hi - lo {
                acc.panel(Map::Linear { lo, hi, q }, upper, &ray);
            } else {
                let (t0, t1) = (libm::asinh((lo - q) / g), libm::asinh((hi - q) / g));
                if gamma < 0.01 {
                    // e² > 0.9999: split in two in t (one 32-point rule loses accuracy there:
                    // 6e-10 at m₁ = 1e-12, 5e-14 with the split)
                    let tm = 0.5 * (t0 + t1);
                    acc.panel(Map::Sinh { q, g, t0, t1: tm }, upper, &ray);
                    acc.panel(Map::Sinh { q, g, t0: tm, t1 }, upper, &ray);
                } else {
                    acc.panel(Map::Sinh { q, g, t0, t1 }, upper, &ray);
                }
            }
        }
    }
    let fx = -0.75 / r * acc.fx;
    let fy = -0.75 / r * acc.fy;
    let tz = 0.75 * m / r * acc.t1 - 0.1875 * acc.t2;
    (fx, fy, tz)
}

/// Panel map from the Gauss–Legendre variable to β, around the branch point at β = q.
#[derive(Clone, Copy)]
enum Map {
    Linear { lo: f64, hi: f64, q: f64 },
    Sinh { q: f64, g: f64, t0: f64, t1: f64 },
}

impl Map {
    /// (β, δ = β − q, weight) for node `x` ∈ (−1, 1) with Gauss weight `w`.
    fn node(self, x: f64, w: f64) -> (f64, f64, f64) {
        match self {
            Map::Linear { lo, hi, q } => {
                let h = 0.5 * (hi - lo);
                let beta = lo + h * (1.0 + x);
                (beta, beta - q, h * w)
            }
            Map::Sinh { q, g, t0, t1 } => {
                let h = 0.5 * (t1 - t0);
                let t = t0 + h * (1.0 + x);
                let delta = g * libm::sinh(t);
                (q + delta, delta, h * w * g * libm::cosh(t))
            }
        }
    }
}

/// What the integrand needs besides the node: r = 1/R, m₁ and γ = √m₁.
struct Ray {
    r: f64,
    m1: f64,
    gamma: f64,
}

/// Running sums of the four integrals.
#[derive(Default)]
struct Sums {
    fx: f64,
    fy: f64,
    t1: f64,
    t2: f64,
}

impl Sums {
    /// Adds one 32-point Gauss–Legendre panel; `upper`: the map's centre is φ = +π/2 (else −π/2).
    fn panel(&mut self, map: Map, upper: bool, ray: &Ray) {
        for (&x, &wx) in NODES.iter().zip(WEIGHTS.iter()) {
            for xs in [-x, x] {
                let (beta, delta, wt) = map.node(xs, wx);
                let (sd, cd) = libm::sincos(delta);
                // φ = ∓π/2 + δ
                let (sp, cp) = if upper { (cd, -sd) } else { (-cd, sd) };
                self.add(beta, sp, cp, wt, ray);
            }
        }
    }

    fn add(&mut self, beta: f64, sp: f64, cp: f64, wt: f64, ray: &Ray) {
        let (sb, cb) = libm::sincos(beta);
        let s = sb / ray.r;
        let h2 = 1.0 - s * s;
        let n = libm::sqrt(cp * cp + ray.m1 * sp * sp);
        let k = wt * cb * h2 / n;
        self.fx -= k * ray.gamma * sp;
        self.fy += k * cp;
        self.t1 += k * s * sp * cp;
        self.t2 += wt * n * h2 * h2;
    }
}
