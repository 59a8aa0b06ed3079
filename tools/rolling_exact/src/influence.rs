//! Half-space influence coefficients for uniform tangential traction on a rectangle and the
//! discrete steady-rolling slip operator built from them.
//!
//! Boussinesq–Cerruti (Johnson, *Contact Mechanics*, eq. 3.86; Love 1929): a tangential point
//! force Q_x on the surface of a half-space (shear modulus G, Poisson ratio ν) displaces the
//! surface by u_x = Q_x/(2πG)·[(1−ν)/r + ν x²/r³], u_y = Q_x/(2πG)·ν x y/r³. For two
//! quasi-identical bodies the traction acts with opposite signs on the two, so the relative
//! displacement u = u⁽ᴮ⁾ − u⁽ᴬ⁾ doubles: the factor is 1/(πG) with 1/G = ½(1/G₁ + 1/G₂).
//!
//! Integrated over a rectangle [x₁, x₂] × [y₁, y₂] (relative coordinates X = x_P − x', Y = y_P − y'),
//! with F evaluated at the corners, S[F] = F(X₂,Y₂) − F(X₁,Y₂) − F(X₂,Y₁) + F(X₁,Y₁):
//!   ∬ x²/r³ = S[y·asinh(x/|y|)],  ∬ y²/r³ = S[x·asinh(y/|x|)],  ∬ 1/r = their sum,  ∬ xy/r³ = S[−r]
//! (Love's closed forms; the y·ln|y| terms dropped from y·ln(x + r) cancel in S).

use crate::grid::Grid;

/// v·asinh(u/|v|), 0 on v = 0 (its limit).
fn t(u: f64, v: f64) -> f64 {
    if v == 0.0 {
        0.0
    } else {
        v * (u / v.abs()).asinh()
    }
}

/// (I_xx, I_yy, I_xy) = ∬ (x²/r³, y²/r³, xy/r³) over the rectangle centred (cx, cy) with half
/// widths (hx, hy), seen from the point (px, py).
pub fn rectangle(px: f64, py: f64, cx: f64, cy: f64, hx: f64, hy: f64) -> (f64, f64, f64) {
    let xs = [px - cx - hx, px - cx + hx];
    let ys = [py - cy - hy, py - cy + hy];
    let (mut ixx, mut iyy, mut ixy) = (0.0, 0.0, 0.0);
    for (ix, &x) in xs.iter().enumerate() {
        for (iy, &y) in ys.iter().enumerate() {
            // S[·]: + at (X₂,Y₂) and (X₁,Y₁), − at the mixed corners
            let sgn = if ix == iy { 1.0 } else { -1.0 };
            ixx += sgn * t(x, y);
            iyy += sgn * t(y, x);
            ixy -= sgn * x.hypot(y);
        }
    }
    (ixx, iyy, ixy)
}

/// Influence (A_xx, A_yy, A_xy) of unit uniform traction on element `k` on the relative
/// displacement at point (px, py), for G = 1 (scale by 1/G).
pub fn displacement(g: &Grid, nu: f64, k: usize, px: f64, py: f64) -> (f64, f64, f64) {
    let e = &g.elements[k];
    let (ixx, iyy, ixy) = rectangle(px, py, e.x, e.y, e.hx, e.hy);
    let i1 = ixx + iyy;
    let c = 1.0 / std::f64::consts::PI;
    (
        c * ((1.0 - nu) * i1 + nu * ixx),
        c * ((1.0 - nu) * i1 + nu * iyy),
        c * nu * ixy,
    )
}

/// The slip operator of steady rolling, s = w + B τ with
/// B = (A(element) − A(upstream point))/Δx: the upwind form of s = w − ∂u/∂x (material flows
/// towards −x, so the derivative takes the upstream neighbour at +x). Stored by source column
/// (column k contiguous) for the Gauss–Seidel updates.
pub struct SlipOperator {
    pub n: usize,
    /// B_xx, B_yy, B_xy (= B_yx), column-major: entry (row e, column k) at k·n + e.
    pub bxx: Vec<f64>,
    pub byy: Vec<f64>,
    pub bxy: Vec<f64>,
}

impl SlipOperator {
    /// Builds B for the grid (G = 1).
    pub fn new(g: &Grid, nu: f64) -> Self {
        let n = g.len();
        let np = n + g.m;
        let (mut bxx, mut byy, mut bxy) = (vec![0.0; n * n], vec![0.0; n * n], vec![0.0; n * n]);
        let mut col = vec![(0.0, 0.0, 0.0); np];
        for k in 0..n {
            for (p, c) in col.iter_mut().enumerate() {
                let (px, py) = g.point(p);
                *c = displacement(g, nu, k, px, py);
            }
            for e in 0..n {
                let up = g.upstream(e);
                let inv = 1.0 / (2.0 * g.elements[e].hx);
                bxx[k * n + e] = (col[e].0 - col[up].0) * inv;
                byy[k * n + e] = (col[e].1 - col[up].1) * inv;
                bxy[k * n + e] = (col[e].2 - col[up].2) * inv;
            }
        }
        SlipOperator { n, bxx, byy, bxy }
    }
}
