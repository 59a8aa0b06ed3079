//! The linear theory over the whole domain (`friction::rolling::creep_matrix`) against the exact
//! theory's held-out creep matrices `tools/data/rolling_linear_check.csv` (tools/rolling_exact,
//! example `linear_table -- check`: 12 aligned patches, a/b log-uniform over [1/20, 20], and 28
//! patches rolled at random angles, r log-uniform over [1, 20], ν uniform over [0, ½]; none of
//! them a node of the tables), and its structure: the axes, the mirror image, totality.
use contensou::friction::rolling::{
    CreepMatrix, Kalker, SkewGrid, SkewRow, aligned_ellipse, creep_matrix,
};

#[path = "common/rng.rs"]
mod rng;

/// (own a/b, θ (rad) from the rolling direction to the patch's a axis, ν, K, max error estimate)
type Row = (f64, f64, f64, [[f64; 3]; 3], f64);

fn check_rows() -> Vec<Row> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tools/data/rolling_linear_check.csv"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with("a_over_b"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').take(21).map(|s| s.parse().unwrap()).collect();
            let k = [[v[3], v[4], v[5]], [v[6], v[7], v[8]], [v[9], v[10], v[11]]];
            let est = v[12..21].iter().copied().fold(0.0, f64::max);
            (v[0], v[1].to_radians(), v[2], k, est)
        })
        .collect()
}

/// The library's matrix for a reference row: the library frame has x along the major axis, the
/// rolling direction at −θ from it (θ: rolling direction → a axis).
fn library(r: f64, theta: f64, nu: f64) -> [[f64; 3]; 3] {
    let (r, psi) = if r >= 1.0 {
        (r, theta)
    } else {
        (1.0 / r, theta + std::f64::consts::FRAC_PI_2)
    };
    let (a, b) = (r.sqrt(), 1.0 / r.sqrt());
    CreepMatrix::<f64>::new(a, b, psi.cos(), -psi.sin(), nu).k
}

/// Relative deviations: the diagonal and K₂₃ (÷ themselves), the couplings K₁₂, K₁₃ (÷ the
/// geometric mean of their diagonal entries), with the reference's reciprocal pairs averaged.
fn deviations(got: &[[f64; 3]; 3], want: &[[f64; 3]; 3]) -> [f64; 6] {
    let k12 = 0.5 * (want[0][1] + want[1][0]);
    let k13 = 0.5 * (want[0][2] - want[2][0]);
    let k23 = 0.5 * (want[1][2] - want[2][1]);
    [
        got[0][0] / want[0][0] - 1.0,
        got[1][1] / want[1][1] - 1.0,
        got[1][2] / k23 - 1.0,
        got[2][2] / want[2][2] - 1.0,
        (got[0][1] - k12) / (want[0][0] * want[1][1]).sqrt(),
        (got[0][2] - k13) / (want[0][0] * want[2][2]).sqrt(),
    ]
}

/// Bounds for patches with r = max(a/b, b/a) ≤ 6.5: 1 % (C₁₁, C₂₂, C₂₃, the couplings), 4 % (C₃₃;
/// measured worst 3.3 % at a/b = 2.97 along the axis, 1.6 % skewed — the 2 % aim is not met
/// there). Measured worst: K₁₁ 0.36 %, K₂₂ 0.43 %, K₂₃ 0.51 %, K₁₂ 0.30 %, K₁₃ 0.75 %.
const BOUND: [f64; 6] = [0.01, 0.01, 0.01, 0.04, 0.01, 0.01];
/// Bounds for r > 6.5 (long patches: the reference's own C₃₃ error estimate is 1–7 %, and
/// near the minor axis at ν ≈ ½ the tables' ν and t interpolation): measured worst K₁₁ 0.56 %,
/// K₂₂ 0.68 %, K₂₃ 2.1 %, K₃₃ 4.7 %, K₁₂ 0.31 %, K₁₃ 4.3 % — the 1 % / 2 % aims are not met for
/// K₂₃, K₃₃, K₁₃ there.
const BOUND_LONG: [f64; 6] = [0.01, 0.01, 0.025, 0.05, 0.01, 0.05];
const NAMES: [&str; 6] = ["K11", "K22", "K23", "K33", "K12", "K13"];

#[test]
fn held_out_matrices() {
    let rows = check_rows();
    assert_eq!(rows.len(), 40);
    let mut worst = [0.0f64; 6];
    let mut fails = Vec::new();
    for (r, th, nu, want, est) in &rows {
        let got = library(*r, *th, *nu);
        let d = deviations(&got, want);
        println!(
            "a/b {r:.4} θ {:6.2}° ν {nu:.3}: {} (ref est {est:.1e})",
            th.to_degrees(),
            (0..6)
                .map(|i| format!("{} {:+.4}", NAMES[i], d[i]))
                .collect::<Vec<_>>()
                .join(" ")
        );
        let bound = if r.max(1.0 / r) <= 6.5 {
            BOUND
        } else {
            BOUND_LONG
        };
        for i in 0..6 {
            worst[i] = worst[i].max(d[i].abs());
            if d[i].abs() > bound[i] {
                fails.push(format!("a/b {r} θ {th} ν {nu}: {} {:+.4}", NAMES[i], d[i]));
            }
        }
    }
    println!("worst {worst:?}");
    assert!(fails.is_empty(), "{fails:#?}");
}

#[test]
fn along_the_axes_the_aligned_coefficients() {
    for (r, nu) in [
        (1.0, 0.3),
        (2.5, 0.0),
        (7.0, 0.45),
        (20.0, 0.25),
        (60.0, 0.3),
    ] {
        let (a, b) = (f64::sqrt(r), 1.0 / f64::sqrt(r));
        for (cx, sx, ratio) in [(1.0, 0.0, r), (0.0, 1.0, 1.0 / r), (-2.0, 0.0, r)] {
            let k = CreepMatrix::<f64>::new(a, b, cx, sx, nu).k;
            let c = creep_matrix::aligned(ratio, nu);
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs().max(1e-300);
            assert!(
                close(k[0][0], c.c11) && close(k[1][1], c.c22),
                "{k:?} {c:?}"
            );
            assert!(
                close(k[1][2], c.c23) && close(-k[2][1], c.c23),
                "{k:?} {c:?}"
            );
            assert!(close(k[2][2], c.c33), "{k:?} {c:?}");
            assert!(k[0][1].abs() + k[0][2].abs() + k[1][0].abs() + k[2][0].abs() < 1e-12);
        }
    }
}

#[test]
fn mirror_image_flips_the_couplings() {
    let (a, b) = (2.0, 0.5);
    let k = CreepMatrix::<f64>::new(a, b, 0.8, 0.6, 0.3).k;
    let m = CreepMatrix::<f64>::new(a, b, 0.8, -0.6, 0.3).k;
    for i in 0..3 {
        for j in 0..3 {
            let s = if (i == 0) != (j == 0) { -1.0 } else { 1.0 };
            assert!((k[i][j] - s * m[i][j]).abs() < 1e-12, "{k:?} {m:?}");
        }
    }
    assert!(k[0][1].abs() > 0.05, "{k:?}");
}

/// Finite for any valid input, f64 and f32 (shape, direction, ν over their domains).
#[test]
fn total() {
    let mut rng = rng::Lcg(1);
    let mut u = || rng.next();
    for _ in 0..20_000 {
        let r = 100f64.powf(u());
        let b = 1e-3 * 1e6f64.powf(u());
        let (cx, sx) = (2.0 * u() - 1.0, 2.0 * u() - 1.0);
        let nu = 0.5 * u();
        let k = CreepMatrix::<f64>::new(r * b, b, cx, sx, nu).k;
        assert!(
            k.iter().flatten().all(|v| v.is_finite()),
            "{r} {b} {cx} {sx} {nu}: {k:?}"
        );
        assert!(k[0][0] > 0.0 && k[1][1] > 0.0 && k[2][2] > 0.0, "{k:?}");
        let k =
            CreepMatrix::<f32>::new((r * b) as f32, b as f32, cx as f32, sx as f32, nu as f32).k;
        assert!(k.iter().flatten().all(|v| v.is_finite()));
        let c = creep_matrix::aligned(1.0 / (r * r), nu);
        assert!(c.c11.is_finite() && c.c33 > 0.0);
    }
    let k = CreepMatrix::<f64>::new(1.0, 1.0, 0.0, 0.0, 0.0).k;
    assert!(k.iter().flatten().all(|v| v.is_finite()));
}

/// The closing note's figures: the coefficients at a/b = 0.05, 0.1, 0.14, 20 (ν = 0.3) from the
/// exact theory, next to Table E3's interpolation ([`Kalker::new`]) that `blend` and `table`
/// use; at a/b = 0.1 the latter's C₃₃ is ≈ 16 % too large.
#[test]
fn coefficients_at_the_ends() {
    for r in [0.05, 0.1, 0.14, 20.0] {
        let c = creep_matrix::aligned(r, 0.3);
        let k = Kalker::<f64>::new(r, 0.3);
        println!(
            "a/b {r}: C11 {:.4} ({:.4}) C22 {:.4} ({:.4}) C23 {:.4} ({:.4}) C33 {:.4} ({:.4})",
            c.c11, k.c11, c.c22, k.c22, c.c23, k.c23, c.c33, k.c33
        );
        // Table E3 and the exact theory agree on the force coefficients within a few %
        assert!((c.c11 / k.c11 - 1.0).abs() < 0.05 && (c.c22 / k.c22 - 1.0).abs() < 0.05);
    }
    // the exact C₃₃ ≈ 8.06 at a/b ≈ 0.11 (the 209 bearing's patch, ν = 0.3), and
    // Table E3's interpolation 16 % above at 0.1
    let c = creep_matrix::aligned(0.1, 0.3).c33;
    assert!(Kalker::<f64>::new(0.1, 0.3).c33 / c > 1.10, "{c}");
}

/// The per-call skew ratios ([`SkewRow`]: a fixed contact, 17 nodes in t, linear between
/// them; [`SkewGrid`]: a varying one, the table's 7 × 9 nodes, bilinear) against the exact
/// reference's held-out matrices, with the bounds of `held_out_matrices` (the table's own,
/// cubic Hermite in both: [`CreepMatrix::new`]). Measured worst (row / grid): printed; the
/// grid's bilinear interpolation in (ln r, t) costs accuracy near the major axis of long
/// patches at large ν (K₃₃).
#[test]
fn skew_ratios_per_call_against_the_reference() {
    let rows = check_rows();
    let (mut row_worst, mut grid_worst) = ([0.0f64; 6], [0.0f64; 6]);
    let mut fails = Vec::new();
    for (r0, th, nu, want, _) in &rows {
        let (r, psi) = if *r0 >= 1.0 {
            (*r0, *th)
        } else {
            (1.0 / r0, th + std::f64::consts::FRAC_PI_2)
        };
        let (a, b) = (r.sqrt(), 1.0 / r.sqrt());
        let (cx, sx) = (psi.cos(), -psi.sin());
        let (ar, br) = aligned_ellipse(a, b, cx, sx);
        let ln_q = (ar / br).ln();
        let kalker = creep_matrix::aligned(ar / br, *nu);
        let bound = if r <= 6.5 { BOUND } else { BOUND_LONG };
        for (name, ratios, worst, slack) in [
            ("row", SkewRow::new(r, *nu).at(ln_q), &mut row_worst, 1.0),
            (
                "grid",
                SkewGrid::new(*nu).at(r.ln(), ln_q),
                &mut grid_worst,
                GRID_SLACK,
            ),
        ] {
            let d = deviations(&skewed_matrix(&kalker, ratios, cx, sx), want);
            for i in 0..6 {
                worst[i] = worst[i].max(d[i].abs());
                if d[i].abs() > slack * bound[i] {
                    fails.push(format!(
                        "{name}: a/b {r0} θ {th} ν {nu}: {} {:+.4}",
                        NAMES[i], d[i]
                    ));
                }
            }
        }
    }
    println!("skew ratios per call, worst per entry: row {row_worst:.4?}, grid {grid_worst:.4?}");
    assert!(fails.is_empty(), "{fails:#?}");
}

/// How much looser than the table's Hermite the grid's bilinear interpolation may be.
const GRID_SLACK: f64 = 2.0;

/// K from the aligned coefficients and the six ratios (the library's `skewed`, restated).
fn skewed_matrix(k: &Kalker<f64>, ratios: [f64; 6], cx: f64, sx: f64) -> [[f64; 3]; 3] {
    let [r11, r22, r33, r23, q12, q13] = ratios;
    let s = -cx * sx;
    let (k11, k22, k33, k23) = (r11 * k.c11, r22 * k.c22, r33 * k.c33, r23 * k.c23);
    let k12 = s * q12 * (k.c11 * k.c22).sqrt();
    let k13 = s * q13 * (k.c11 * k.c33).sqrt();
    [[k11, k12, k13], [k12, k22, k23], [-k13, -k23, k33]]
}
