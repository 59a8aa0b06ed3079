//! The held-out test set of the rolling laws over the whole domain: `POINTS` cases drawn at
//! random (seeded, reproducible) over the patch shape, the skew angle of the rolling
//! direction to the patch axes, ν, the direction of the creepages and their magnitude — on no
//! creep curve of the other reference files and not used to fit anything.
//!
//! `nice cargo run --release --example heldout -- [OUT [FIRST [LAST [SEED [ELEMENTS]]]]]` (from
//! tools/rolling_exact; default `../data/rolling_ref_heldout.csv`, points FIRST..LAST of the
//! sequence, to split the work; concatenate the rows). Another SEED draws a TRAINING set from
//! the same distribution (family `train`; the surrogate prototype's, tools/fit_rolling_surrogate.py):
//! never fit on the held-out seed. ELEMENTS: on the finest grid (default 1,024, the held-out set's).
//!
//! Draws per point (splitmix64, seed `SEED`, in this order):
//! - a₀/b₀ log-uniform in [1/20, 20] (c = √(a₀b₀) = 1; a₀ may be the shorter semi-axis);
//! - skew: one point in three aligned (θ = 0: a₀ along the rolling direction; with a₀/b₀ on
//!   both sides of 1 this covers both axes), the others θ uniform in [0°, 180°) (the angle from
//!   the rolling direction x to the a₀ axis, counter-clockwise; θ and 180° − θ are mirror
//!   images);
//! - ν uniform in [0, 0.5];
//! - direction d uniform on the unit sphere and magnitude q log-uniform in [0.01, 10], placed
//!   as the other files place them: ξ = 3·nl·q·d₁/C₁₁, η = 3·nl·q·d₂/C₂₂, φc = 3·nl·q·d₃/C₂₃
//!   with Kalker's coefficients of the aligned ellipse ([`rolling_exact::reference::skew`];
//!   the library's `Kalker`, used only to place the cases), nl = 0.01.
//!
//! Grids: the aligned ellipse's, sheared (`Patch::skewed_on`), ≈ 1,024 elements on the finest;
//! square elements while the aligned ratio r is within [1/5, 5], beyond that n/m = 5·√(r/5)
//! (1/r alike): elements elongated along the long axis, so that the short axis keeps ≥ 8
//! elements on the finest grid. Columns: as rolling_ref.csv with `theta_deg` after
//! `a_over_b`, then `converged` (every grid's Gauss–Seidel met its tolerance) and the seconds.
use contensou::friction::rolling::Kalker;
use rolling_exact::cases::uniform;
use rolling_exact::reference::{skew, skewed_row};
use std::time::Instant;

/// Points in the committed file.
pub const POINTS: usize = 500;
/// The generator's seed.
pub const SEED: u64 = 29;
/// Load ratio fN/(Gc²).
const NL: f64 = 0.01;

/// One drawn case: (a₀/b₀, θ (rad), ν, ξ, η, φc).
pub fn draw(state: &mut u64) -> (f64, f64, f64, f64, f64, f64) {
    let aob = (20f64.ln() * (2.0 * uniform(state) - 1.0)).exp();
    let aligned = uniform(state) < 1.0 / 3.0;
    let t = uniform(state);
    let theta = if aligned {
        0.0
    } else {
        std::f64::consts::PI * t
    };
    let nu = 0.5 * uniform(state);
    let z = 2.0 * uniform(state) - 1.0;
    let az = std::f64::consts::TAU * uniform(state);
    let w = (1.0 - z * z).sqrt();
    let d = [z, w * az.cos(), w * az.sin()];
    let q = 0.01 * 1000f64.powf(uniform(state));
    let (a, b, _) = skew(aob, theta);
    let k = Kalker::<f64>::new(a / b, nu);
    let s = 3.0 * NL * q;
    (
        aob,
        theta,
        nu,
        s * d[0] / k.c11,
        s * d[1] / k.c22,
        s * d[2] / k.c23,
    )
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = args
        .first()
        .map(String::as_str)
        .unwrap_or("../data/rolling_ref_heldout.csv");
    let first: usize = args.get(1).map_or(0, |s| s.parse().expect("FIRST"));
    let last: usize = args.get(2).map_or(POINTS, |s| s.parse().expect("LAST"));
    let seed: u64 = args.get(3).map_or(SEED, |s| s.parse().expect("SEED"));
    let family = if seed == SEED { "heldout" } else { "train" };
    // elements on the finest grid (the held-out set's 1,024; fewer for a cheaper training set)
    let elements: usize = args.get(4).map_or(1024, |s| s.parse().expect("ELEMENTS"));
    let started = Instant::now();
    let mut line = rolling_exact::line_writer(out);
    if first == 0 {
        line(
            "# Exact steady-rolling reference: the held-out set over the whole domain, tools/rolling_exact/examples/heldout.rs",
        );
        line(&format!(
            "# ({} points drawn with seed {seed}; see there). Method, extrapolation, error columns and units as rolling_ref.csv;",
            last - first
        ));
        line(
            "# theta_deg: angle from the rolling direction x to the patch's a axis (a/b = a_over_b, c = 1).",
        );
        line("family,a_over_b,theta_deg,nu,nl,xi,eta,phi_c,fx,fy,mz,err_f,err_m,converged,seconds");
    }
    let mut state = seed;
    for i in 0..last {
        let (aob, theta, nu, xi, eta, phi_c) = draw(&mut state);
        if i < first {
            continue;
        }
        line(&skewed_row(
            family,
            aob,
            theta,
            nu,
            NL,
            [xi, eta, phi_c],
            elements,
        ));
    }
    eprintln!("wrote {out} in {:.1} s", started.elapsed().as_secs_f64());
}
