//! Richardson extrapolation over three grids, with a check that the grids are in the
//! asymptotic range.
//!
//! The discretisation error of the totals behaves like c₁h + c₂h² + … (first-order upwind slip
//! derivative, piecewise-constant tractions; measured on the linear coefficients over seven
//! grids, see README.md). Three grids with h ∝ 1/k determine F₀ + c₁h + c₂h²; the error
//! estimate is the difference between that and the two-grid linear extrapolation of the two
//! finest grids.
//!
//! Not every total converges smoothly: where the slip field's instantaneous centre lies inside
//! the patch, or the stick/slip boundary crosses elements, the sequence can oscillate by a
//! fraction of the last change. The extrapolation is used only when the two successive
//! changes d₁ (coarse → middle) and d₂ (middle → fine) have the same sign and a ratio
//! d₁/d₂ ∈ [1.4, 4.5] (order p = 1 gives 2, p = 2 gives 2.86 for k/2, 3k/4, k); otherwise the
//! finest grid's value is reported with the error estimate max(|d₁|, |d₂|).

/// How a value was obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// F₀ of F₀ + c₁h + c₂h² through the three grids.
    Extrapolated,
    /// The finest grid (changes not in the asymptotic range, or below round-off).
    Finest,
}

/// (value, error estimate, kind) from values `v` on grids with sizes `h` (any order).
pub fn richardson(h: [f64; 3], v: [f64; 3]) -> (f64, f64, Kind) {
    let mut idx = [0, 1, 2];
    idx.sort_by(|&a, &b| h[b].total_cmp(&h[a])); // coarse → fine
    let (h, v) = (idx.map(|i| h[i]), idx.map(|i| v[i]));
    let (d1, d2) = (v[1] - v[0], v[2] - v[1]);
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
    let ratio = d1 / d2;
    let asymptotic = d1 * d2 > 0.0 && (1.4..=4.5).contains(&ratio) && d2.abs() > 1e-11 * scale;
    if !asymptotic {
        return (v[2], d1.abs().max(d2.abs()), Kind::Finest);
    }
    // Lagrange polynomial through (h_i, v_i) evaluated at h = 0.
    let mut f0 = 0.0;
    for i in 0..3 {
        let mut w = 1.0;
        for j in 0..3 {
            if j != i {
                w *= h[j] / (h[j] - h[i]);
            }
        }
        f0 += w * v[i];
    }
    // two finest grids, linear in h
    let lin = (h[1] * v[2] - h[2] * v[1]) / (h[1] - h[2]);
    (f0, (f0 - lin).abs(), Kind::Extrapolated)
}

#[cfg(test)]
mod tests {
    use super::{Kind, richardson};

    #[test]
    fn exact_for_quadratics() {
        let f = |h: f64| 1.5 - 0.7 * h + 2.0 * h * h;
        let h = [1.0 / 16.0, 1.0 / 24.0, 1.0 / 32.0];
        let (v, e, k) = richardson(h, h.map(f));
        assert_eq!(k, Kind::Extrapolated);
        assert!((v - 1.5).abs() < 1e-12, "{v}");
        // the linear two-grid value misses the h² term: error estimate = 2 h2 h3
        assert!((e - 2.0 * h[1] * h[2]).abs() < 1e-12, "{e}");
    }

    #[test]
    fn oscillating_sequence_falls_back_to_the_finest_grid() {
        let h = [1.0 / 8.0, 1.0 / 12.0, 1.0 / 16.0];
        let (v, e, k) = richardson(h, [-0.1685, -0.1731, -0.1726]);
        assert_eq!(k, Kind::Finest);
        assert_eq!(v, -0.1726);
        assert!((e - 0.0046).abs() < 1e-12, "{e}");
    }
}
