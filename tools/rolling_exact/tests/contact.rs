//! (c) CONTACT's printed exact results (E.A.H. Vollebregt & J.J. Kalker, CONTACT, open source,
//! github.com/eve70a/CONTACT; numbers quoted below with their source file, nothing else taken).
//!
//! Besides the printed results, the same cases were run with CONTACT itself on finer grids
//! (built by hand, see the constants below) and extrapolated: converged against converged.
//!
//! CONTACT's results are themselves discretised (first order in the element size, no
//! extrapolation). The check: CONTACT's printed value lies within the grid-error band this
//! solver shows at CONTACT's element count, i.e.
//! |CONTACT − extrapolated| ≤ |own grid with CONTACT's element counts − extrapolated| + 0.01,
//! and under an absolute cap (0.03 fN at 40 × 40 elements, 0.06 fN at 7 × 7). The two coarse
//! results are not expected to agree closely with each other: CONTACT's rectangular
//! potential-contact grid takes its contact area and pressure from its discrete normal problem,
//! this crate's strips are fitted to the Hertz ellipse.

use rolling_exact::grid::Grid;
use rolling_exact::influence::SlipOperator;
use rolling_exact::reference::{Patch, finest_k};
use rolling_exact::solver::{Creepage, Settings, solve};

/// This solver on an n × m grid (elements along x × y), totals ÷ fN, ÷ fNc.
fn on_grid(aob: f64, nu: f64, nl: f64, n: usize, m: usize, c: Creepage) -> (f64, f64, f64) {
    let g = Grid::new(aob.sqrt(), 1.0 / aob.sqrt(), m, n, nl);
    let op = SlipOperator::new(&g, nu);
    let (t, _) = solve(&g, &op, c, true, Settings::default());
    (t.fx / nl, t.fy / nl, t.mz / nl)
}

/// examples/fastsim.inp, first case (CONTACT's half-space solver, steady rolling): AA = 8 mm,
/// BB = 4 mm, FN = 82000 N, G = 82000 N/mm², ν = 0.28, f = 0.3, ξ = 0, η = −0.000625,
/// φ = 0.000625 /mm; 44 × 44 potential-contact grid, DX = 0.4 mm, DY = 0.2 mm (40 elements across
/// 2a and across 2b). examples/fastsim.ref_out, case 1: "FX/FSTAT/FN 0.000, FY/FSTAT/FN −0.6074",
/// "MZ −4.821E+04" (N·mm), CP (c) = 5.657 mm.
#[test]
fn fastsim_example_case_1() {
    let (g, f, n_load) = (82000.0, 0.3, 82000.0);
    let c = (8.0f64 * 4.0).sqrt();
    let nl = f * n_load / (g * c * c);
    let (eta, phi_c) = (-0.000625, 0.000625 * c);
    let fy_contact = -0.6074;
    let mz_contact = -4.821e4 / (f * n_load * c);
    let p = Patch::new(2.0, 0.28, nl, finest_k(2.0, 1024));
    let s = p.solve(0.0, eta, phi_c, true);
    let (_, fy40, mz40) = on_grid(
        2.0,
        0.28,
        nl,
        40,
        40,
        Creepage {
            xi: 0.0,
            eta,
            phi: phi_c,
        },
    );
    println!(
        "extrapolated fy {:.4} mz {:.4} (est {:.1e}, {:.1e}); 40x40 fy {fy40:.4} mz {mz40:.4}; CONTACT fy {fy_contact:.4} mz {mz_contact:.4}",
        s.totals.fy, s.totals.mz, s.err_f, s.err_m
    );
    assert!(s.totals.fx.abs() < 1e-9);
    for (ours, own_grid, contact) in [
        (s.totals.fy, fy40, fy_contact),
        (s.totals.mz, mz40, mz_contact),
    ] {
        let d = (ours - contact).abs();
        assert!(
            d <= (own_grid - ours).abs() + 0.01 && d <= 0.03,
            "{ours} vs CONTACT {contact} (own 40x40 {own_grid})"
        );
    }
    // CONTACT itself on finer grids (built by hand with gfortran in /tmp, nothing of it
    // committed): the same case 1 with MX = MY = 66, 88, 132 (DQ = DX) printed
    // FY/FSTAT/FN = −0.6137, −0.6167, −0.6195 and MZ = −4.795E+04, −4.783E+04, −4.771E+04
    // (44: −0.6074, −4.821E+04 as in ref_out); their F₀ + c₁h + c₂h² extrapolation:
    // Fy/(fN) = −0.6245, Mz/(fNc) = −0.3411 (4 printed digits: ±0.0005).
    let (fy_fine, mz_fine) = (-0.6245, -47470.0 / (f * n_load * c));
    println!("CONTACT extrapolated by hand: fy {fy_fine:.4} mz {mz_fine:.4}");
    assert!(
        (s.totals.fy - fy_fine).abs() <= 0.003,
        "fy {} vs {fy_fine}",
        s.totals.fy
    );
    assert!(
        (s.totals.mz - mz_fine).abs() <= 0.003,
        "mz {} vs {mz_fine}",
        s.totals.mz
    );
}

/// A sample of the 3,220-case table (src/test_table.f90; results testbank/test_table_mx11.ref_fx):
/// G = 82000, ν = 0.28, f = 0.3, FN = G (mm², N), CONTACT's half-space solver on 11 × 11
/// elements with SCALE = 11/7, i.e. 7 elements across 2a and 7 across 2b. Case parameters
/// (a/b, spin, angle°, magnitude) → ξ = mag·f·cos(angle)·cp/ρ, η = mag·f·sin(angle)·cp/ρ,
/// φ = f·spin/ρ, with ρ, cp as printed in the same file (a/b 0.2: 1772, 8.944; 0.5: 2075,
/// 8.485; 1: 2700, 9.000; 2: 2075, 8.485; 5: 1772, 8.944); results Fx/(fFN), Fy/(fFN), Mz/(fFN·cp).
const TESTBANK: [(f64, f64, f64, f64, [f64; 3]); 11] = [
    // (a/b, spin, angle°, magnitude, [Fx, Fy, Mz]) — line of ref_fx after the 5 header lines
    (1.0, 0.0, 0.0, 0.5, [-0.500932, 0.0, 0.0]), // case 1363
    (1.0, 0.0, 0.0, 1.1, [-0.865046, 0.0, 0.0]), // case 1366
    (1.0, 0.0, 0.0, 3.0, [-0.999628, 0.0, 0.0]), // case 1371
    (1.0, 1.0, 90.0, 0.5, [0.0, -0.741178, -0.167823]), // case 1754
    (1.0, 0.5, 30.0, 1.4, [-0.796759, -0.561810, -0.048001]), // case 1551
    (0.2, 2.0, 0.0, 0.0, [0.0, -0.255064, -0.814366]), // case 553
    (0.2, 1.0, 60.0, 0.9, [-0.241313, -0.661155, -0.590127]), // case 445
    (5.0, 0.5, -60.0, 1.4, [-0.646357, 0.714191, -0.189809]), // case 2770
    (5.0, 2.0, 90.0, 0.3, [0.0, -0.463774, -0.702930]), // case 3201
    (0.5, 0.5, -30.0, 2.0, [-0.906787, 0.396710, -0.038684]), // case 863
    (2.0, 1.0, -90.0, 0.7, [0.0, 0.080507, -0.447708]), // case 2261
];

/// The same cases (but the third, which is at full slip) run with CONTACT itself on finer grids
/// (built by hand with gfortran in /tmp, nothing of it committed; input as examples/fastsim.inp
/// case 1 with the table's AA, BB, FN, creepages and ν, MX = MY = 44, 66, 88 at SCALE 1.1, DQ = DX),
/// totals as printed (4 digits) and extrapolated F₀ + c₁h + c₂h² over the three grids.
/// E.g. the first: FX/FSTAT/FN = −0.4850, −0.4814, −0.4799 → −0.4766.
const TESTBANK_CONTACT_FINE: [Option<[f64; 3]>; 11] = [
    Some([-0.4766, 0.0, 0.0]),
    Some([-0.8212, 0.0, 0.0]),
    None,
    Some([0.0, -0.7233, -0.1422]),
    Some([-0.7712, -0.5428, -0.0341]),
    Some([0.0, -0.2514, -0.8113]),
    Some([-0.2384, -0.6409, -0.5736]),
    Some([-0.6501, 0.6932, -0.2199]),
    Some([0.0, -0.5164, -0.6595]),
    Some([-0.8899, 0.3858, -0.0497]),
    Some([0.0, 0.0509, -0.4095]),
];

fn rho_cp(aob: f64) -> (f64, f64) {
    match aob {
        0.2 | 5.0 => (1772.0, 8.944),
        0.5 | 2.0 => (2075.0, 8.485),
        _ => (2700.0, 9.000),
    }
}

/// Finest grids of about 256 elements (CI).
#[test]
fn testbank_sample_small_grids() {
    testbank(256, 0.02);
}

/// The generator's grids.
#[test]
#[ignore = "generator grids, ~30 s in release"]
fn testbank_sample_generator_grids() {
    testbank(1024, 0.006);
}

/// `fine_bound`: against CONTACT's own extrapolated values (fN, fNc).
fn testbank(target: usize, fine_bound: f64) {
    let f = 0.3;
    let mut worst = (0.0f64, 0.0f64);
    let mut worst_fine = 0.0f64;
    for (&(aob, spin, angle, mag, contact), fine) in TESTBANK.iter().zip(TESTBANK_CONTACT_FINE) {
        let (rho, cp) = rho_cp(aob);
        let nl = f / (cp * cp);
        let ang = angle.to_radians();
        let (xi, eta, phi_c) = (
            mag * f * ang.cos() * cp / rho,
            mag * f * ang.sin() * cp / rho,
            f * spin * cp / rho,
        );
        let p = Patch::new(aob, 0.28, nl, finest_k(aob, target));
        let s = p.solve(xi, eta, phi_c, true);
        let ours = [s.totals.fx, s.totals.fy, s.totals.mz];
        let coarse = on_grid(
            aob,
            0.28,
            nl,
            7,
            7,
            Creepage {
                xi,
                eta,
                phi: phi_c,
            },
        );
        let coarse = [coarse.0, coarse.1, coarse.2];
        let d = |v: [f64; 3], w: [f64; 3]| (0..3).map(|i| (v[i] - w[i]).abs()).fold(0.0, f64::max);
        let (de, dc) = (d(ours, contact), d(ours, coarse));
        if let Some(fine) = fine {
            // converged against converged: the two extrapolations agree to their own accuracy
            let df = d(ours, fine);
            println!("  vs CONTACT extrapolated from 44/66/88 grids {fine:?}: {df:.4}");
            worst_fine = worst_fine.max(df);
            assert!(
                df <= fine_bound,
                "a/b {aob} spin {spin} ang {angle} mag {mag}: {ours:?} vs CONTACT fine {fine:?}"
            );
        }
        for i in 0..3 {
            let band = (coarse[i] - ours[i]).abs() + 0.01;
            assert!(
                (ours[i] - contact[i]).abs() <= band,
                "a/b {aob} spin {spin} ang {angle} mag {mag}, component {i}: {} vs CONTACT {} (band {band})",
                ours[i],
                contact[i]
            );
        }
        println!(
            "a/b {aob} spin {spin} ang {angle} mag {mag}: CONTACT {contact:?} extrapolated [{:+.4} {:+.4} {:+.4}] (est {:.1e}) 7x7 [{:+.4} {:+.4} {:+.4}] |CONTACT - extrapolated| {de:.4}, |own 7x7 - extrapolated| {dc:.4}",
            ours[0],
            ours[1],
            ours[2],
            s.err_f.max(s.err_m),
            coarse[0],
            coarse[1],
            coarse[2]
        );
        worst = (worst.0.max(de), worst.1.max(dc));
    }
    println!(
        "worst: |CONTACT - extrapolated| {:.4} fN, |own 7x7 - extrapolated| {:.4} fN",
        worst.0, worst.1
    );
    assert!(
        worst.0 <= 0.06,
        "extrapolated vs CONTACT (7x7 elements) {}",
        worst.0
    );
}
