//! One patch shape (a/b, ν) on three grids and the extrapolated steady-rolling totals.
//!
//! Dimensionless frame (ROLLING.md): c = √(ab) = 1, G = 1, f = 1, N = nl; forces are reported
//! divided by f·N, the moment by f·N·c.

use crate::extrapolate::richardson;
use crate::grid::Grid;
use crate::influence::SlipOperator;
use crate::solver::{Creepage, Settings, Stats, Totals, solve};
use std::time::Instant;

/// The sheared-grid parameters (a, b, s) of a patch a₀/b₀ = `aob` (c = √(a₀b₀) = 1) turned by
/// `theta` from x: (x − s y)²/a² + y²/b² ≤ 1 (see [`crate::grid`]). At θ = 0 exactly
/// (√aob, 1/√aob, 0), the grid of the aligned solver bit for bit.
pub fn skew(aob: f64, theta: f64) -> (f64, f64, f64) {
    let a0 = aob.sqrt();
    let b0 = 1.0 / a0;
    if theta == 0.0 {
        return (a0, b0, 0.0);
    }
    let (sn, cs) = theta.sin_cos();
    let big_a = cs * cs / (a0 * a0) + sn * sn / (b0 * b0);
    let big_b = sn * cs * (1.0 / (a0 * a0) - 1.0 / (b0 * b0));
    let a = 1.0 / big_a.sqrt();
    (a, a0 * b0 / a, -big_b / big_a)
}

/// n/m of the grids for the aligned ratio r: square elements (n/m = r) while r ∈ [1/5, 5],
/// beyond that n/m = 5·√(r/5) (1/r alike): elements elongated along the long axis, so that the
/// short axis keeps more elements for the same total (used for the shapes beyond [1/5, 5]).
pub fn elements_ratio(r: f64) -> f64 {
    if r > 5.0 {
        5.0 * (r / 5.0).sqrt()
    } else if r < 0.2 {
        1.0 / elements_ratio(1.0 / r)
    } else {
        r
    }
}

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
    /// The patch's own semi-axis ratio a₀/b₀ (a₀ at `theta` from the rolling direction).
    pub aob: f64,
    /// Angle (rad) from the rolling direction x to the patch's a₀ axis (0 for [`Patch::new`]).
    pub theta: f64,
    /// The sheared grid's (a, b, s): a along x, b across, shear s (see [`skew`]).
    pub aligned: (f64, f64, f64),
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
        Self::skewed(aob, 0.0, nu, nl, k)
    }

    /// A patch with semi-axis ratio a₀/b₀ = `aob` (c = 1) whose a₀ axis is turned by `theta`
    /// (rad) from the rolling direction; the grids are those of the aligned ellipse [`skew`]
    /// (k elements along its shorter axis) sheared along x. `theta = 0` is [`Patch::new`].
    pub fn skewed(aob: f64, theta: f64, nu: f64, nl: f64, k: usize) -> Self {
        let (a, b, _) = skew(aob, theta);
        // θ = 0: a/b itself (the aligned solver's element counts exactly)
        let nm = if theta == 0.0 { aob } else { a / b };
        Self::skewed_on(aob, theta, nu, nl, k, nm)
    }

    /// [`Patch::skewed`] with `nm` = n/m, the ratio of the elements per strip (along x) to the
    /// strips (along y), instead of a/b (square elements): for very long or very narrow
    /// patches, elements elongated along the long axis (k along the shorter direction).
    pub fn skewed_on(aob: f64, theta: f64, nu: f64, nl: f64, k: usize, nm: f64) -> Self {
        let (a, b, s) = skew(aob, theta);
        let aob_grid = nm;
        let levels = [k / 2, 3 * k / 4, k]
            .into_iter()
            .map(|k| {
                let t = Instant::now();
                let (n, m) = if aob_grid >= 1.0 {
                    (((k as f64) * aob_grid).round() as usize, k)
                } else {
                    (k, ((k as f64) / aob_grid).round() as usize)
                };
                let grid = Grid::sheared(a, b, s, m, n, nl);
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
            theta,
            aligned: (a, b, s),
            nu,
            nl,
            levels,
        }
    }

    /// [`Patch::skewed_on`] on the held-out set's grids: `elements` on the finest, n/m from
    /// [`elements_ratio`] of the aligned ellipse's a/b (elements elongated along the long axis
    /// beyond [1/5, 5]).
    pub fn heldout_grids(aob: f64, theta: f64, nu: f64, nl: f64, elements: usize) -> Self {
        let (a, b, _) = skew(aob, theta);
        let nm = elements_ratio(a / b);
        Self::skewed_on(aob, theta, nu, nl, finest_k(nm, elements), nm)
    }

    /// The three grids, coarse to fine, as `NxM` (elements along x by along y).
    pub fn grid_dims(&self) -> Vec<String> {
        self.levels
            .iter()
            .map(|l| format!("{}x{}", l.grid.n, l.grid.m))
            .collect()
    }

    /// The comment line of a reference file naming this patch's grids:
    /// `# a/b = …, nu = …, nl = …: grids (x by y elements) n×m, …`.
    pub fn grids_comment(&self) -> String {
        let dims = self.grid_dims();
        format!(
            "# a/b = {}, nu = {}, nl = {}: grids (x by y elements) {}",
            self.aob,
            self.nu,
            self.nl,
            dims.join(", ")
        )
    }

    /// The reference row (columns [`CSV_COLUMNS`]) of `family` at the creepages (ξ, η, cφ)
    /// solved as `sol`.
    pub fn csv_row(&self, family: &str, [xi, eta, phi_c]: [f64; 3], sol: &Solution) -> String {
        let (aob, nu, nl, t) = (self.aob, self.nu, self.nl, &sol.totals);
        format!(
            "{family},{aob},{nu},{nl},{xi:e},{eta:e},{phi_c:e},{:.10e},{:.10e},{:.10e},{:.3e},{:.3e}",
            t.fx, t.fy, t.mz, sol.err_f, sol.err_m
        )
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

/// One case of a skewed patch (a₀/b₀ = `aob`, c = 1, its a₀ axis at `theta` rad from the rolling
/// direction x), solved on the three grids with `elements` on the finest, as one CSV row of the
/// held-out file's format: `family,a_over_b,theta_deg,nu,nl,xi,eta,phi_c,fx,fy,mz,err_f,err_m,converged,seconds`.
pub fn skewed_row(
    family: &str,
    aob: f64,
    theta: f64,
    nu: f64,
    nl: f64,
    creepage: [f64; 3],
    elements: usize,
) -> String {
    let [xi, eta, phi_c] = creepage;
    let t = Instant::now();
    let patch = Patch::heldout_grids(aob, theta, nu, nl, elements);
    let sol = patch.solve(xi, eta, phi_c, true);
    format!(
        "{family},{aob:.6},{:.4},{nu:.4},{nl},{xi:e},{eta:e},{phi_c:e},{:.10e},{:.10e},{:.10e},{:.3e},{:.3e},{},{:.2}",
        theta.to_degrees(),
        sol.totals.fx,
        sol.totals.fy,
        sol.totals.mz,
        sol.err_f,
        sol.err_m,
        u8::from(sol.converged),
        t.elapsed().as_secs_f64()
    )
}

/// The columns of a reference file (tools/data/rolling_ref.csv's).
pub const CSV_COLUMNS: &str = "family,a_over_b,nu,nl,xi,eta,phi_c,fx,fy,mz,err_f,err_m";

/// A reference file: the `header` comment lines, the patches' grid comments `grids`, the
/// generator's time, the columns and the `rows`.
pub fn csv_file(header: &str, grids: &str, seconds: f64, rows: &str) -> String {
    format!("{header}{grids}# total generator time {seconds:.1} s\n{CSV_COLUMNS}\n{rows}")
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

/// Kalker's linear creep matrix of a patch (full adhesion, G = 1, c = 1): K with
/// (F_x, F_y, M_z/c)/(Gc²) = −K·(ξ, η, cφ) (forces on body B). For a patch aligned with the
/// rolling direction K = [[C₁₁, 0, 0], [0, C₂₂, C₂₃], [0, −C₂₃, C₃₃]]; a skewed patch couples
/// every entry. Column j from the unit creepage j, extrapolated over the three grids.
pub struct CreepMatrix {
    /// K[row][column], rows (F_x, F_y, M_z), columns (ξ, η, cφ).
    pub k: [[f64; 3]; 3],
    /// The extrapolation's error estimate per entry.
    pub err: [[f64; 3]; 3],
}

impl Patch {
    /// The linear creep matrix ([`CreepMatrix`]) of this patch (three full-adhesion solves on
    /// each grid; the load ratio does not enter).
    pub fn creep_matrix(&self) -> CreepMatrix {
        let mut k = [[0.0; 3]; 3];
        let mut err = [[0.0; 3]; 3];
        for j in 0..3 {
            let mut c = [0.0; 3];
            c[j] = 1.0;
            let s = self.solve(c[0], c[1], c[2], false);
            // totals are ÷ nl (= fN/(Gc²)): back to ÷ Gc²
            let t = [s.totals.fx, s.totals.fy, s.totals.mz];
            let e = [s.err_f, s.err_f, s.err_m];
            for i in 0..3 {
                k[i][j] = -t[i] * self.nl;
                err[i][j] = e[i] * self.nl;
            }
        }
        CreepMatrix { k, err }
    }
}
