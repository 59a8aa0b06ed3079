//! Richardson extrapolation over three grids.
//!
//! The discretisation error of the totals behaves like c₁h + c₂h² + … (first-order upwind slip
//! derivative, piecewise-constant tractions; measured on the linear coefficients, see
//! README.md). Three grids with h ∝ 1/k determine F₀ + c₁h + c₂h²; the error estimate is the
//! difference between that and the two-grid linear extrapolation of the two finest grids.

/// (extrapolated value, error estimate) from values `v` on grids with sizes `h` (any order).
pub fn richardson(h: [f64; 3], v: [f64; 3]) -> (f64, f64) {
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
    let mut idx = [0, 1, 2];
    idx.sort_by(|&a, &b| h[a].total_cmp(&h[b]));
    let (h1, h2) = (h[idx[0]], h[idx[1]]);
    let (v1, v2) = (v[idx[0]], v[idx[1]]);
    let lin = (h2 * v1 - h1 * v2) / (h2 - h1);
    (f0, (f0 - lin).abs())
}

#[cfg(test)]
mod tests {
    use super::richardson;

    #[test]
    fn exact_for_quadratics() {
        let f = |h: f64| 1.5 - 0.7 * h + 2.0 * h * h;
        let h = [1.0 / 16.0, 1.0 / 24.0, 1.0 / 32.0];
        let (v, e) = richardson(h, h.map(f));
        assert!((v - 1.5).abs() < 1e-12, "{v}");
        // the linear two-grid value misses the h² term: error estimate = 2 h1 h2
        assert!((e - 2.0 * h[1] * h[2]).abs() < 1e-12, "{e}");
    }
}
