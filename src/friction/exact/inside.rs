//! The exact traction while the instantaneous centre (IC) lies inside the ellipse: a quartic
//! polynomial in the IC position.
//!
//! # Formula
//!
//! With the IC at (X₀, Y₀) (units of a), m = e², m₁ = 1 − m and
//!
//! ```text
//! Ψ = C + (B/2)X₀² + (A/2)Y₀² + c₄₀(X₀⁴ + Y₀⁴/m₁) + c₂₂X₀²Y₀²
//! A = (3/2)D(m),  B = (3/2)B(m),  C = (3/8)E(m)              (paper (3.5))
//! c₄₀ = −[(2 − m)E − 2m₁K]/(8m²) = −(B(m) − m₁D(m))/(8m),  c₂₂ = −(A + 12c₄₀)/2
//! F_x = −∂Ψ/∂Y₀,  F_y = ∂Ψ/∂X₀,  T_z = −Ψ + X₀∂Ψ/∂X₀ + Y₀∂Ψ/∂Y₀
//! ```
//!
//! (B(m), D(m) the cancellation-free elliptic pair of [`crate::elliptic`]; the Hertz slope on
//! the minor axis is B = (3/2)(K + (E − K)/m) = (3/2)B(m).) This is the notes' "beyond the
//! paper" fact; it agrees with the independent brute-force reference
//! (`tools/gen_friction_ref.py`) to 1.4e-17 at every reference point with the IC inside,
//! e² ∈ {0, 0.3, 0.687, 0.9, 0.99, 0.9999}, including u = u_b(1 − 1e-6).
//!
//! # Small m
//!
//! c₄₀ → −3π/128 as m → 0 and both closed forms cancel there, so for m < ¼ it is summed from its
//! Maclaurin series: with a_k = [(2k−1)!!/(2k)!!]² (K = (π/2)Σa_k m^k),
//! c₄₀ = −(π/16)·Σ_{k≥2} d_k m^{k−2},  d_k = 4k·a_k/(1 − 2k) + (5 − 4k)·a_{k−1}/(3 − 2k),
//! 40 terms (truncation < 1e-25 at m = ¼).

use crate::elliptic::Integrals;

/// Quartic coefficients at one m.
#[derive(Clone, Copy, Debug)]
pub(super) struct Quartic {
    a: f64,
    b: f64,
    c: f64,
    c40: f64,
    c22: f64,
    m1: f64,
}

impl Quartic {
    pub(super) fn new(m: f64, m1: f64, i: &Integrals<f64>) -> Self {
        let a = 1.5 * i.d;
        let c40 = if m < 0.25 {
            c40_series(m)
        } else {
            -(i.b - m1 * i.d) / (8.0 * m)
        };
        Quartic {
            a,
            b: 1.5 * i.b,
            c: 0.375 * i.e,
            c40,
            c22: -0.5 * (a + 12.0 * c40),
            m1,
        }
    }

    /// (F_x, F_y, T_z) with the IC at (x0, y0), inside the ellipse (y0² ≤ m₁ keeps Y₀⁴/m₁ ≤ m₁).
    pub(super) fn traction(&self, x0: f64, y0: f64) -> (f64, f64, f64) {
        let (x2, y2) = (x0 * x0, y0 * y0);
        let y2m = y2 / self.m1; // ≤ 1 inside
        let fx = -y0 * (self.a + 4.0 * self.c40 * y2m + 2.0 * self.c22 * x2);
        let fy = x0 * (self.b + 4.0 * self.c40 * x2 + 2.0 * self.c22 * y2);
        let tz = -self.c
            + 0.5 * (self.b * x2 + self.a * y2)
            + 3.0 * (self.c40 * (x2 * x2 + y2 * y2m) + self.c22 * x2 * y2);
        (fx, fy, tz)
    }
}

/// c₄₀(m) from its Maclaurin series, for 0 ≤ m < ¼ (fixed 40 terms).
fn c40_series(m: f64) -> f64 {
    let mut a_prev = 0.25; // a₁
    let mut sum = 0.0;
    let mut pow = 1.0; // m^{k−2}
    for k in 2..42u32 {
        let kf = f64::from(k);
        let r = (2.0 * kf - 1.0) / (2.0 * kf);
        let a_k = a_prev * r * r;
        let d_k = 4.0 * kf * a_k / (1.0 - 2.0 * kf) + (5.0 - 4.0 * kf) * a_prev / (3.0 - 2.0 * kf);
        sum += d_k * pow;
        pow *= m;
        a_prev = a_k;
    }
    -core::f64::consts::PI / 16.0 * sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::elliptic::{Agm, Method, Parameter};

    #[test]
    fn c40_series_matches_closed_form_at_the_switch() {
        for m in [0.2, 0.25, 0.3] {
            let i = Agm::integrals(Parameter::new(m).unwrap());
            let direct = -(i.b - (1.0 - m) * i.d) / (8.0 * m);
            assert!((c40_series(m) - direct).abs() < 1e-15, "{m}");
        }
        assert!((c40_series(0.0) + 3.0 * core::f64::consts::PI / 128.0).abs() < 1e-17);
    }
}
