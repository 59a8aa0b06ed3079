//! `table`: the default rolling law — [`super::Blend`] plus a compact per-shape table of its
//! residual against the exact steady-rolling reference, over the normalised creepage, with
//! both limits built in.
//!
//! # Formula
//!
//! l = κ·(C₁₁ξ, C₂₂η, C₂₃cφ) (Kalker's linear forces in fN, κ = Gc²/(fN), the shape's exact
//! coefficients — for a skewed patch its creep matrix's diagonal), m = |l|, d = l/m;
//! W_b the `blend` wrench (F_x, F_y, M_z/c)/(fN). Then W = W_b + R, R the exact reference's
//! residual against `blend` interpolated over the direction d and the magnitude m:
//!
//! - symmetry: F_x is odd in ξ and (F_y, M_z) odd in (η, φ) (the y-reflection and the reversal
//!   of all creepages are exact symmetries of the steady rolling problem), so with s_x = sgn d_x,
//!   s_y = sgn d_φ the direction is reduced to d_x ≥ 0, d_φ ≥ 0 and
//!   R = (s_x·R'_x, s_y·R'_y, s_y·R'_m);
//! - direction: u = 2 − 2d_y/(|d_y| + d_φ) ∈ [0, 4] around the η–φ half plane (0: η, 1: η with
//!   φ of the same sign at equal linear shares, 2: φ, 3: opposite signs, 4: −η), v = 2d_x² ∈
//!   [0, 2] towards ξ (0: the plane, 1: 45°, 2: ξ), P the plane's curves at u = 0, 1, 1½, 2,
//!   2½, 3, 3½, 4 (F_y, M_z), Q the ring's (ξ at 45° to the plane) at u = 0, 1, 2, 3, 4 (F_x,
//!   F_y, M_z), X the ξ curve (F_x), each piecewise linear in u between its curves (u = 4: the
//!   u = 0 curve mirrored). Between the families each channel moves at the order its symmetry
//!   gives: for v ≤ 1 (off the plane) R'_x = √2·d_x·Q_x (F_x is odd in ξ: linear in d_x) and
//!   R'_{y,m} = (1 − v)·P + v·Q (even in ξ: in d_x²); beyond (towards ξ) R'_x = (2 − v)·Q_x +
//!   (v − 1)·X_x (even in (η, φ): in |d_⊥|², d_⊥ = (d_y, d_φ)) and R'_{y,m} = √(2 − v)·Q = √2·|d_⊥|·Q
//!   (odd in (η, φ), 0 on the ξ curve: linear in |d_⊥|). Both weights are 1 on the ring. (With
//!   v for every channel, the spin moment of a mostly longitudinal creepage with some spin grew
//!   as d_φ² instead of d_φ off the ξ curve: 0.256 fNc off at a/b = 16.5, 0.146 now.)
//! - magnitude: each curve piecewise linear in ln m between its nodes, ∝ (m/m₀)² below the
//!   first and ∝ (m_N/m)² above the last: 29 nodes uniform in ln m from 1e-3 of saturation to
//!   full slip (`tools/data/rolling_ref.csv`'s 15 magnitudes per creep curve and their
//!   midpoints, `rolling_ref_mid.csv`, `rolling_ref_dir.csv`); on the curves with φ the knee
//!   of the spin force (coarse intervals 12 to 20, m ≈ 0.25 … 4.7) is cut in four: nodes at its
//!   ¼, ½, ¾ points at a/b = 2 and 5 (`rolling_ref_knee.csv` and the quarter files), at the ½
//!   points at a/b = 1, linear between coarse nodes elsewhere (and on the curves at u = 1½,
//!   2½, 3½);
//!
//! then a positive power removed along (ξ, η, cφ) and |F| ≤ fN by scaling, as in `blend`. The
//! curves at u = 1½, 2½, 3½ exist at a/b = 2 and 5 (`rolling_ref_plane.csv`, m ≥ 0.12); below
//! that and at the other shapes they hold their neighbours' mean (the law without them). Per
//! shape a/b ∈ {1/20, 0.2, 0.5, 1, 2, 5, 20} (ν = 0.25; the two ends of the domain from
//! `rolling_ref_ends.csv`: the nine curves laid out with the exact linear coefficients, on the
//! held-out set's grids, no knee or ½-direction nodes), node by node linear in ln(a/b) between
//! them (built once per contact, [`Tables::new`]), the end shapes outside; `blend`'s constants
//! are its end values beyond [0.2, 5] (its own rule). Data: `table_data.rs`,
//! written by `python3 tools/fit_rolling_table.py --write` (nothing fitted: the node values are
//! the reference's residuals; `--check` in CI): each node value an `i16` times a power of two
//! per node index (the smallest with every shape's, curve's and channel's |residual| at that
//! node ≤ 32,767 of it: exact in `f32` and `f64`, within 3.0e-5 fN / fNc of the residual at
//! every node (7.6e-6 before the shapes 1/20 and 20, whose residuals are larger), and relatively as fine near the linear limit as at the knee, where the
//! residuals are 1e4 times larger); the two shapes' integers are mixed, then scaled.
//!
//! - m → 0: the correction is O(m²) (the residual of `blend` is O(m²) too): the linear
//!   theory, its coefficients and couplings exactly (as `blend`).
//! - V → 0: m → ∞, the correction O(1/m²) → 0: W = `blend`'s = the full slip of `best` exactly.
//! - Passive (the projection), |F| ≤ fN (the scaling), continuous (each piece is; u, v and the
//!   signs are continuous away from rest, or R is even where they jump: at d_φ = 0 u = 0 and
//!   u = 4 hold mirror curves, at d_x = 0 the ring and ξ weigh 0; the correction vanishes at
//!   rest).
//!
//! # Domain and special cases
//!
//! Every input, as `blend`: rest → 0; N ≤ 0 or f = 0 → 0; V = 0 → full slip (the correction is
//! skipped: its limit there is 0); V < 0 by the mirror ([`super::RollingSlip`]). a/b outside
//! [1/20, 20]: the end shape's tables (unmeasured there: the held-out set spans 1/20 to 20); ν ≠ 0.25:
//! the same residuals with ν's own coefficients.
//!
//! # Example
//!
//! ```
//! use contensou::friction::rolling::{Elasticity, Patch, RollingContact, RollingSlip, Table};
//!
//! let contact = RollingContact::new(5.0_f32, Elasticity::new(80e9, 0.25)?)?; // once
//! let patch = Patch::new(10e-3, 2e-3, 10e3, 0.3)?;
//! // pure spin near the knee of the spin force (φ·c ≈ 1.6e-3, V = 20 m/s)
//! let w = contact.wrench::<Table>(&patch, &RollingSlip::from_creepages(0.0, 0.0, 0.36, 20.0)?);
//! assert!(w.fy < 0.0 && w.mz < 0.0 && w.fy.abs() <= 0.3 * 10e3);
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Error (against the exact reference, `host-tests/rolling_ref.rs`)
//!
//! On its nodes the law is the reference within 0.0017 fN / 0.0021 fNc (the curves were laid
//! out with Table E3's coefficients, on which the nodes sat exactly; the law reads the exact
//! theory's, which moves the combined curves' points slightly off their direction nodes and
//! the ½-direction curves off φ's magnitude grid). Held out
//! (never used to build the tables; same solver, `tools/rolling_exact`, examples `midpoints`
//! and `directions`): the geometric midpoints between the 29 node magnitudes of every curve
//! outside the knee window (`rolling_ref_quarter.csv`, `rolling_ref_dir_quarter.csv`), inside it
//! the ⅛/⅝ points at a/b = 2, 5 (`rolling_ref_knee_held.csv`) and ¼/¾ points at a/b = 1
//! (`rolling_ref_half_held.csv`) — 1,052 points, **0.026 fN / 0.012 fNc at worst**
//! (0.0256 / 0.0120 with the exact coefficients; the per-family figures below are Table E3's)
//! ([`Table::REF_ERROR_HELD_OUT`]): pure ξ 0.006 fN; pure η 0.013 / 0.010; pure φ 0.009 /
//! 0.009; ξ with η 0.010 / 0.005; η with φ 0.026 / 0.012; η against φ 0.020 / 0.007; ξ with η
//! and φ (the ring) 0.025 / 0.012: the aim (0.03 fN, 0.05 fNc) holds on every creep-curve
//! family; the knee of pure spin 0.004 fN at a/b = 5, 0.002 at a/b = 2. Before the knee
//! window and the direction curves: 0.045 / 0.033 on the first five families (the knee of pure
//! spin at a/b = 5; 0.027 at a/b = 2), and on the new families up to 0.50 / 0.37 (ξ with φ). On the same held-out points `blend` is 0.495 / 0.489, FASTSIM 32 × 32 0.119 / 0.063.
//!
//! Off the curves: 30 random directions and magnitudes (`rolling_ref_dir_random.csv`, q from
//! 0.01 to 10): 0.064 / 0.055 ([`Table::REF_ERROR_DIRECTIONS`]; 0.067 / 0.057 with every
//! channel weighted by v between the families, 0.061 / 0.057 with Table E3's
//! coefficients, before the direction curves 0.111 / 0.168, `blend` 0.101 / 0.244, FASTSIM
//! 0.098 / 0.103) — the residual of `blend` is not linear between the direction curves (its
//! spin moment's saturation varies sharply with the φ share), so the aim is met on the curves,
//! not between them. CONTACT's published cases (combined creepages of both signs, ν = 0.28,
//! own load ratios): 0.101 / 0.054 (0.107 / 0.054 with every channel weighted by v, 0.108 /
//! 0.133 with Table E3's coefficients, before the
//! direction curves 0.186 / 0.178; `blend` 0.169 / 0.244, FASTSIM 0.090 / 0.070);
//! `examples/fastsim.inp` (a/b = 2, η against large spin) 0.004 / 0.003. ν ≠ 0.25: the same
//! residuals with ν's own coefficients (the exact reference at ν = 0.25 and 0.28 differs by
//! ≤ 0.006 fN / 0.003 fNc on two of CONTACT's cases at the same normalised creepages).
//!
//! **Over the whole domain** (the held-out set `tools/data/rolling_ref_heldout.csv`: 500 points
//! at random patch shapes a/b 0.05–20, skews, ν, directions and magnitudes; through the
//! per-step wrench, `tools/rolling_heldout.py`, `bench-results/rolling-heldout.md`): **0.148 fN
//! / 0.334 fNc at worst**, median 0.0115 / 0.0057, 95 % 0.067 / 0.060, worse than FASTSIM
//! 32 × 32 on 166 of the 500 points (0.159 / 0.334, 0.0118 / 0.0062, 0.072 / 0.067 and 165
//! with every channel weighted by v between the direction families; 0.158 / 0.405, 0.0133 /
//! 0.0074, 0.081 / 0.087 and 201 with the tables at a/b 0.2 … 5 only, their end shapes kept
//! beyond; 0.433 / 0.952 before the
//! exact linear theory for any rolling direction and the spin in `blend`'s translational
//! saturation; FASTSIM 32 × 32 0.281 / 1.002). The shapes 1/20 and 20 cut the errors of the
//! wide and long patches along the rolling direction: a/b 0.05–0.1 median 0.031 / 0.024 →
//! 0.011 / 0.004, worst 0.147 / 0.115 → 0.112 / 0.066; 10–20 median M_z 0.070 → 0.014 (F
//! 0.032 → 0.040), worst M_z 0.405 → 0.256, and the channel orders (above) to 0.146. The worst
//! points left are a skewed long patch (a/b 14.9 at 165° from the rolling direction) with η
//! and φ, 0.334 fNc (the aligned-ellipse rule for the nonlinear part), and wide or long
//! patches with combined creepage, up to 0.15 fN / 0.15 fNc.
//!
//! Precision: f32 within 3.5e-7 fN / 4.8e-7 fNc of f64 (asserted 4e-6). Linear limit:
//! 1.8e-5 relative at 1e-6 of saturation; full slip: `best`'s 2.9e-5 fN, 2.0e-6 fNc
//! (`host-tests/rolling.rs`). Limits, passivity (1e5 random states), continuity along creep
//! curves and across directions, the V < 0 mirror: `host-tests/rolling.rs`.
//!
//! # References
//!
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990): the exact theory the
//! reference solves (`tools/rolling_exact`, its README) and the linear coefficients
//! ([`super::Kalker`]).
//!
//! # Cost
//!
//! `blend`'s call plus a square root, two divisions, one `ln` and 1 to 4 curve look-ups (1 to 3
//! channels each). M4F, f32, the dimensional call (firmware stage `rolling`, 64 creep states on
//! a spiral of directions): 1,020 instructions on average (`blend` 442; f64: 41,220 (also with five shapes); 1,037 with libm's `logf` for ln m instead of [`crate::real::ln_f32_hot`]; 1,030 before each channel's own order between the direction families; 1,020 while the tables held twelve curve views, 951 with
//! the nodes in `f32` — the `i16` nodes cost two conversions and a scaling per node read and
//! save 13 KB of flash; 919 before the spin entered `blend`'s translational saturation and the
//! couplings, 895 before a curve could be built per call without its grid; before the
//! direction curves 759; 787 while each contact held its own mixed copy of the nodes); two
//! neighbouring curves on the same magnitudes share one node search. Per contact the pair of
//! fitted shapes (references to their nodes in flash), the weight between them and each of
//! the 12 curves' grid (4 numbers), mixed at the weight on each look-up (a
//! [`super::RollingShape`] is 264 bytes in f32 on x86-64, 528 while the tables held a view per
//! curve; a mixed copy was 5.3 KB, and the per-call shape of a skewed rolling velocity built
//! it each call; a per-call shape holds no grids). Flash:
//! the generated data, 7 shapes × 1,287 `i16` + 82 `f32` scales + 84 curve grids (20.4 KB;
//! 14.5 KB with five shapes, 27.3 KB with five and `f32` nodes); the size probe
//! (`tools/flash-bench.sh --stage rolling`: a contact built and called) measures `table`
//! 63.5 KB in f32 (63.4 KB before the channel orders, 57.5 KB with five shapes), 9.0 KB over `blend` (54.4 KB; every rolling
//! law's probe holds the tables, since [`super::RollingContact::new`] builds them whatever the
//! law). Before: 77.6 KB (the `f32` nodes, and Table E3's interpolation
//! linked for the coefficients' growth beyond a/b ∈ [1/20, 20], 8 KB, now restated without
//! it: [`super::creep_matrix::aligned`]).

use super::blend::{bounded, creep as blend_creep};
use super::contact::{Creep, Input, RollingLaw, passive};
use super::residual::lerp;
pub use super::residual::{Curve, Tables};
use crate::Real;

/// The default rolling law (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default)]
pub struct Table;

impl Table {
    /// Measured max error against the exact reference's creep curves on the points held out of
    /// the tables (|ΔF| in fN, |ΔM_z| in fNc; see the module docs), asserted by
    /// `host-tests/rolling_ref.rs` with a small margin (measured 0.0256, 0.0120).
    pub const REF_ERROR_HELD_OUT: (f64, f64) = (0.028, 0.014);
    /// The same off the curves, at the 30 random directions and magnitudes of
    /// `tools/data/rolling_ref_dir_random.csv` (measured 0.0635, 0.0554).
    pub const REF_ERROR_DIRECTIONS: (f64, f64) = (0.07, 0.06);
}

impl RollingLaw for Table {
    const NAME: &'static str = "table";

    #[inline]
    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        let w = blend_creep(i);
        let k = &i.contact.kalker;
        // l·v: the linear forces times v = V/S (no division yet)
        let lx = i.kappa * k.c11 * i.vx;
        let ly = i.kappa * k.c22 * i.vy;
        let lp = i.kappa * k.c23 * i.w;
        let lv = (lx * lx + ly * ly + lp * lp).sqrt();
        // rest, V = 0 (full slip: the correction's limit is 0) or an overflow: blend alone
        if !(lv > T::ZERO && i.v > T::ZERO && lv.is_finite()) {
            return w;
        }
        let m = lv / i.v;
        if !m.is_finite() {
            return w;
        }
        let r = T::ONE / lv;
        let (dx, dy, dp) = (lx * r, ly * r, lp * r);
        let inv_m = i.v * r;
        let lnm = m.ln_hot();
        let tb = &i.contact.table;
        // the symmetries: F_x odd in ξ, (F_y, M_z) odd in (η, φ) — d_x ≥ 0, d_φ ≥ 0
        let sy = T::ONE.copysign(dp);
        let (dy, dp) = (dy * sy, dp * sy);
        // u around the η–φ half plane (0: η … 2: φ … 4: −η), v = 2d_x² towards ξ
        let s1 = dy.abs() + dp;
        let u = if s1 > T::ZERO {
            T::TWO - T::TWO * dy / s1
        } else {
            T::ZERO
        };
        let v = T::TWO * dx * dx;
        let around = |ring: bool| {
            // node units: u for the ring; for the plane u up to 1, then 2u − 1 (nodes every ½)
            let (x, last) = if ring || u < T::ONE {
                (u, 3)
            } else {
                (T::TWO * u - T::ONE, 6)
            };
            let j = x.trunc_usize().min(last);
            let t = x - T::from_usize(j);
            if ring {
                tb.ring_mix(j, t, lnm, m, inv_m)
            } else {
                tb.plane_mix(j, t, lnm, m, inv_m)
            }
        };
        // Each channel leaves a family of curves at the order its symmetry gives: F_x (odd in
        // ξ) off the η–φ plane as d_x, the ring's weight √2·d_x; F_y, M_z (even in ξ) as d_x²,
        // the weight v. Towards ξ, F_x (even in (η, φ)) as |d_⊥|², the ξ curve's weight v − 1;
        // F_y, M_z (odd in (η, φ); 0 on the ξ curve) as |d_⊥|, the ring's weight
        // √2·|d_⊥| = √(2 − v).
        let c = if v <= T::ONE {
            let p = around(false);
            // on the plane itself (d_x = 0) the ring weighs nothing, but its F_x sets ∂F_x/∂ξ
            // there (√2·|d_x|·Q_x with the sign put back: slope √2·Q_x): looked up at d_x = 0
            // only for a Jacobian's dual numbers, with the same value as without (+ p's F_x,
            // +0; F_y, M_z p's while v = 0, also where 2d_x² underflows)
            if dx != T::ZERO || T::DERIVATIVES {
                let q = around(true);
                let w = if v > T::ZERO { lerp(p, q, v) } else { p };
                [
                    T::from_f64(core::f64::consts::SQRT_2) * dx.abs() * q[0] + p[0],
                    w[1],
                    w[2],
                ]
            } else {
                p
            }
        } else {
            let q = around(true);
            let x = tb.xi().eval(lnm, m, inv_m);
            let w = (T::TWO - v).max(T::ZERO).sqrt();
            [q[0] + (v - T::ONE) * (x[0] - q[0]), w * q[1], w * q[2]]
        };
        let out = Creep {
            fx: w.fx + T::ONE.copysign(dx) * c[0],
            fy: w.fy + sy * c[1],
            mz: w.mz + sy * c[2],
        };
        bounded(passive(out, i.vx, i.vy, i.w))
    }
}
