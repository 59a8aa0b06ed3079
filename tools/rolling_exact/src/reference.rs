//! One patch shape (a/b, ν) on three grids and the extrapolated steady-rolling totals.
//!
//! Dimensionless frame (ROLLING.md): c = √(ab) = 1, G = 1, f = 1, N = nl; forces are reported
//! divided by f·N, the moment by f·N·c.

use crate::extrapolate::richardson;
use crate::grid::Grid;
use crate::influence::SlipOperator;
use crate::solver::{Creepage, Settings, Stats, Totals, solve};
use std::time::Instant;

/// One grid of the extrapolation.
pub struct Level {
    /// Elements along the shorter semi-axis' direction (h ∝ 1/k).
    pub k: usize,
    pub grid: Grid,
    pub op: SlipOperator,
    /// Seconds to build the influence coefficients.
    pub build_s: f64,
}

/// A Hertz patch a/b with Poisson ratio ν and load ratio nl = fN/(Gc²), on three grids.
pub struct Patch {
    pub aob: f64,
    pub nu: f64,
    pub nl: f64,
    pub levels: Vec<Level>,
}

/// The finest grid's `k` for about `target` elements with square elements (n/m = a/b).
pub fn finest_k(aob: f64, target: usize) -> usize {
    let ratio = if aob >= 1.0 { aob } else { 1.0 / aob };
    let k = (target as f64 / ratio).sqrt();
    (((k / 4.0).round() as usize).max(1)) * 4
}

impl Patch {
    /// Grids k/2, 3k/4, k elements along the shorter axis (k a multiple of 4); square
    /// elements: n = k·a/b (a ≥ b) along x, m = k·b/a (a < b) along y.
    pub fn new(aob: f64, nu: f64, nl: f64, k: usize) -> Self {
        let a = aob.sqrt();
        let b = 1.0 / a;
        let levels = [k / 2, 3 * k / 4, k]
            .into_iter()
            .map(|k| {
                let t = Instant::now();
                let (n, m) = if aob >= 1.0 {
                    (((k as f64) * aob).round() as usize, k)
                } else {
                    (k, ((k as f64) / aob).round() as usize)
                };
                let grid = Grid::new(a, b, m, n, nl);
                let op = SlipOperator::new(&grid, nu);
                Level {
                    k,
                    grid,
                    op,
                    build_s: t.elapsed().as_secs_f64(),
                }
            })
            .collect();
        Patch {
            aob,
            nu,
            nl,
            levels,
        }
    }

    /// Solves one case on the three grids and extrapolates. `phi_c` = φ·c; `coulomb = false`:
    /// full adhesion (linear theory).
    pub fn solve(&self, xi: f64, eta: f64, phi_c: f64, coulomb: bool) -> Solution {
        let c = Creepage {
            xi,
            eta,
            phi: phi_c,
        };
        let mut per = Vec::new();
        for l in &self.levels {
            let t = Instant::now();
            let (tot, st) = solve(&l.grid, &l.op, c, coulomb, Settings::default());
            let s = t.elapsed().as_secs_f64();
            let tot = Totals {
                fx: tot.fx / self.nl,
                fy: tot.fy / self.nl,
                mz: tot.mz / self.nl,
            };
            per.push((tot, st, s));
        }
        let h = [0, 1, 2].map(|i| 1.0 / self.levels[i].k as f64);
        let (fx, ex, _) = richardson(h, [0, 1, 2].map(|i| per[i].0.fx));
        let (fy, ey, _) = richardson(h, [0, 1, 2].map(|i| per[i].0.fy));
        let (mz, em, _) = richardson(h, [0, 1, 2].map(|i| per[i].0.mz));
        let tol = Settings::default().tol;
        Solution {
            converged: per.iter().all(|l| l.1.residual <= tol),
            totals: Totals { fx, fy, mz },
            err_f: ex.max(ey),
            err_m: em,
            levels: per,
        }
    }
}

/// Extrapolated totals (÷ fN, ÷ fNc), their error estimates and the per-grid results.
pub struct Solution {
    /// Every grid's Gauss–Seidel met its tolerance (else it stopped at the sweep limit).
    pub converged: bool,
    pub totals: Totals,
    pub err_f: f64,
    pub err_m: f64,
    /// Per grid (coarse to fine): totals (÷ fN), solver statistics, seconds.
    pub levels: Vec<(Totals, Stats, f64)>,
}
