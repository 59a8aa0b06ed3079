//! Steady rolling with Coulomb friction on the discretised patch, by block Gauss–Seidel
//! (one 2×2 block per element, in the spirit of CONTACT's SteadyGS; sweep order below).
//!
//! Per element e, with the other tractions fixed, the slip is affine in its own traction:
//! s_e = s⁰ + D τ_e with D = diag(B_xx[e,e], B_yy[e,e]) (B_xy[e,e] = 0 by symmetry). Then
//! - adhesion if τ = −D⁻¹ s⁰ satisfies |τ| ≤ g_e (g_e the traction bound f·p);
//! - otherwise slip: τ = −g_e ŝ with s = λ ŝ, λ > 0, i.e. ŝ = (λI + g_e D)⁻¹ s⁰ with |ŝ| = 1,
//!   a monotone scalar equation in λ solved by Newton from λ = 0 (exact to round-off).

use crate::grid::Grid;
use crate::influence::SlipOperator;

/// Creepages in the crate's dimensionless frame (c = 1 m, G = 1 Pa): ξ, η, φ (1/m).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Creepage {
    pub xi: f64,
    pub eta: f64,
    pub phi: f64,
}

/// Totals on body B: Fx, Fy (N), Mz (N·m) about the patch centre.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Totals {
    pub fx: f64,
    pub fy: f64,
    pub mz: f64,
}

/// What the solver did.
#[derive(Clone, Copy, Debug, Default)]
pub struct Stats {
    pub sweeps: usize,
    pub slip_elements: usize,
    /// Last sweep's largest traction change, relative to the largest bound.
    pub residual: f64,
}

/// Solver settings.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Stop when a sweep changes no traction by more than `tol`·(max bound) with Coulomb, or
    /// `tol`·(max |traction|) in full adhesion.
    pub tol: f64,
    pub max_sweeps: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            tol: 1e-10,
            max_sweeps: 20_000,
        }
    }
}

/// Solves the steady-rolling problem on `grid` (with its slip operator `op`); `coulomb = false`
/// drops the traction bound (full adhesion: Kalker's linear theory).
pub fn solve(
    grid: &Grid,
    op: &SlipOperator,
    c: Creepage,
    coulomb: bool,
    set: Settings,
) -> (Totals, Stats) {
    let n = grid.len();
    let els = &grid.elements;
    // rigid slip w = (ξ − φy, η + φx)
    let mut sx: Vec<f64> = els.iter().map(|e| c.xi - c.phi * e.y).collect();
    let mut sy: Vec<f64> = els.iter().map(|e| c.eta + c.phi * e.x).collect();
    let mut tx = vec![0.0; n];
    let mut ty = vec![0.0; n];
    let gmax = els.iter().fold(0.0f64, |m, e| m.max(e.bound));
    let scale = if coulomb { gmax } else { 0.0 };
    let mut stats = Stats::default();
    for sweep in 1..=set.max_sweeps {
        let mut change = 0.0f64;
        let mut tmax = 0.0f64;
        // Index order = strip by strip, each from its trailing edge (i = 0) to its leading
        // edge. In this order plain Gauss–Seidel converges; measured on a/b = 1, ν = ¼: the
        // opposite order (leading edge first) diverges unless under-relaxed to ω = 0.4; this
        // order over-relaxed to ω = 1.3 diverges too.
        for e in 0..n {
            let (dx, dy) = (op.bxx[e * n + e], op.byy[e * n + e]);
            let (s0x, s0y) = (sx[e] - dx * tx[e], sy[e] - dy * ty[e]);
            let (mut nx, mut ny) = (-s0x / dx, -s0y / dy);
            if coulomb {
                let g = els[e].bound;
                if nx * nx + ny * ny > g * g {
                    (nx, ny) = slip_traction(s0x, s0y, g * dx, g * dy, g);
                }
            }
            let (ddx, ddy) = (nx - tx[e], ny - ty[e]);
            if ddx != 0.0 || ddy != 0.0 {
                let (cxx, cyy, cxy) = (
                    &op.bxx[e * n..(e + 1) * n],
                    &op.byy[e * n..(e + 1) * n],
                    &op.bxy[e * n..(e + 1) * n],
                );
                for r in 0..n {
                    sx[r] += cxx[r] * ddx + cxy[r] * ddy;
                    sy[r] += cxy[r] * ddx + cyy[r] * ddy;
                }
                tx[e] = nx;
                ty[e] = ny;
            }
            change = change.max(ddx.abs().max(ddy.abs()));
            tmax = tmax.max(nx.abs().max(ny.abs()));
        }
        stats.sweeps = sweep;
        let reference = if coulomb {
            scale
        } else {
            tmax.max(f64::MIN_POSITIVE)
        };
        stats.residual = change / reference;
        if stats.residual <= set.tol {
            break;
        }
    }
    let mut t = Totals::default();
    for (k, e) in els.iter().enumerate() {
        let area = 4.0 * e.hx * e.hy;
        let (mut fx, mut fy) = (tx[k], ty[k]);
        if coulomb && (fx * fx + fy * fy).sqrt() >= e.bound * (1.0 - 1e-12) {
            stats.slip_elements += 1;
            // blend weight: 1 where the elastic slip is negligible against the rigid slip's
            // variation across the element (full slip), 0 where it is not (partial slip)
            let (ex, ey) = (sx[k] - (c.xi - c.phi * e.y), sy[k] - (c.eta + c.phi * e.x));
            let spread = c.phi.abs() * e.hx.max(e.hy);
            let lam = if spread > 0.0 {
                (1.0 - (ex * ex + ey * ey).sqrt() / (BLEND * spread)).clamp(0.0, 1.0)
            } else {
                0.0
            };
            if lam > 0.0 {
                let (mx, my) = slip_element_mean(e.bound, sx[k], sy[k], c.phi, e.hx, e.hy);
                (fx, fy) = (fx + lam * (mx - fx), fy + lam * (my - fy));
            }
        }
        t.fx += fx * area;
        t.fy += fy * area;
        t.mz += (e.x * fy - e.y * fx) * area;
    }
    (t, stats)
}

/// Sub-points per direction for the mean traction of a slip element.
const SUB: usize = 5;

/// Weight of the sub-element mean against the centre's direction: 1 − |elastic slip|/(BLEND·|φ|·
/// half width), clamped to [0, 1] (so the totals stay continuous in the creepages).
const BLEND: f64 = 0.2;

/// Mean traction over a slip element: −g ŝ averaged over SUB×SUB midpoints, with the slip
/// varying inside the element as the rigid slip does, s(x) = s_e + φ·(−(y − y_e), x − x_e)
/// (the elastic part taken constant: used only where it is small, see BLEND). This is the element's quadrature of −g·s/|s|: with the
/// direction only at the centre, the element holding the instantaneous centre of rotation
/// errs by up to g·area (O(h²), erratic in h, which spoils the extrapolation at full slip).
fn slip_element_mean(g: f64, sx: f64, sy: f64, phi: f64, hx: f64, hy: f64) -> (f64, f64) {
    let (mut ax, mut ay) = (0.0, 0.0);
    for iy in 0..SUB {
        let dy = hy * ((2 * iy + 1) as f64 / SUB as f64 - 1.0);
        for ix in 0..SUB {
            let dx = hx * ((2 * ix + 1) as f64 / SUB as f64 - 1.0);
            let (ux, uy) = (sx - phi * dy, sy + phi * dx);
            let r = (ux * ux + uy * uy).sqrt();
            if r > 0.0 {
                ax += ux / r;
                ay += uy / r;
            }
        }
    }
    let w = g / (SUB * SUB) as f64;
    (-w * ax, -w * ay)
}

/// Slip branch: τ = −g ŝ, ŝ = s⁰/(λ + d), |ŝ| = 1 (d = g·D), λ ≥ 0 by Newton from λ = 0.
fn slip_traction(s0x: f64, s0y: f64, dx: f64, dy: f64, g: f64) -> (f64, f64) {
    let mut lam = 0.0;
    for _ in 0..100 {
        let (ux, uy) = (s0x / (lam + dx), s0y / (lam + dy));
        let q = ux * ux + uy * uy - 1.0;
        let dq = -2.0 * (ux * ux / (lam + dx) + uy * uy / (lam + dy));
        let step = -q / dq;
        lam += step;
        if step.abs() <= 1e-15 * (lam + dx.min(dy)) {
            break;
        }
    }
    let (ux, uy) = (s0x / (lam + dx), s0y / (lam + dy));
    let r = (ux * ux + uy * uy).sqrt();
    (-g * ux / r, -g * uy / r)
}
