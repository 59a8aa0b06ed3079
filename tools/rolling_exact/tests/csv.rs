//! The committed reference file tools/data/rolling_ref.csv (ROLLING.md format): header, the
//! linear family against Table E3 (≤ 1 %), the full-slip family against
//! `contensou::friction::exact` (≤ 1e-3 fN, fNc), and physics every row must obey: |F| ≤ fN
//! (Coulomb), dissipation F·v + Mz·ω ≤ 0 (passivity), creep curves monotone in magnitude
//! (|F| for ξ, η and ξ with η; |Mz| for φ).

use contensou::elliptic::Parameter;
use contensou::friction::exact::traction;
use rolling_exact::kalker::coefficients_nu;

struct Row {
    family: String,
    v: [f64; 11],
}

fn rows() -> Vec<Row> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../data/rolling_ref.csv");
    let text = std::fs::read_to_string(path).expect("tools/data/rolling_ref.csv");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next(),
        Some("family,a_over_b,nu,nl,xi,eta,phi_c,fx,fy,mz,err_f,err_m")
    );
    lines
        .map(|l| {
            let mut it = l.split(',');
            let family = it.next().unwrap().to_string();
            let v: Vec<f64> = it.map(|s| s.parse().expect("number")).collect();
            Row {
                family,
                v: v.try_into().expect("11 numbers"),
            }
        })
        .collect()
}

#[test]
fn every_row_is_bounded_and_passive() {
    let rows = rows();
    assert!(rows.len() >= 445, "{} rows", rows.len());
    for r in &rows {
        let [_, _, _, xi, eta, phi, fx, fy, mz, ef, em] = r.v;
        assert!(r.v.iter().all(|x| x.is_finite()));
        assert!(
            fx.hypot(fy) <= 1.0 + 1e-9,
            "{} {:?}: |F| > fN",
            r.family,
            r.v
        );
        let power = fx * xi + fy * eta + mz * phi;
        let scale = (fx.abs() + fy.abs()) * xi.abs().max(eta.abs()) + mz.abs() * phi.abs();
        assert!(
            power <= 1e-9 * scale,
            "{} {:?}: power {power:e} > 0",
            r.family,
            r.v
        );
        assert!(
            ef >= 0.0 && em >= 0.0 && ef < 0.02 && em < 0.02,
            "{} {:?}: error estimate",
            r.family,
            r.v
        );
    }
}

#[test]
fn creep_curves_are_monotone() {
    let rows = rows();
    let mut pairs = 0;
    for fam in ["xi", "eta", "phi", "combined"] {
        let curve: Vec<&Row> = rows.iter().filter(|r| r.family == fam).collect();
        for w in curve.windows(2) {
            let (a, b) = (&w[0].v, &w[1].v);
            let same = a[0] == b[0]
                && a[1] == b[1]
                && a[3].signum() == b[3].signum()
                && a[5].signum() == b[5].signum();
            let ratio_a = (a[3], a[4], a[5]);
            let grows =
                a[3].abs() <= b[3].abs() && a[4].abs() <= b[4].abs() && a[5].abs() <= b[5].abs();
            // η with φ: Mz = Gc³C23η − Gc⁴C33φ is a difference and may change sign; skipped
            let eta_phi = fam == "combined" && a[5] != 0.0;
            if same && grows && ratio_a != (b[3], b[4], b[5]) && !eta_phi {
                let (fa, fb) = (a[6].hypot(a[7]), b[6].hypot(b[7]));
                // |F| grows with the creepage without spin; with spin the lateral force peaks
                // and falls towards the full-slip value, so the check is on |Mz|
                let (ga, gb) = if a[5] != 0.0 {
                    (a[8].abs(), b[8].abs())
                } else {
                    (fa, fb)
                };
                assert!(gb >= ga - 1e-6, "{fam}: {:?} -> {:?}", a, b);
                pairs += 1;
            }
        }
    }
    // 5 shapes × 14 steps × (ξ, η, φ, ξ with η)
    assert_eq!(pairs, 280);
}

/// The checks `check` makes on each row of `family`, summed.
fn checks_of(family: &str, check: impl Fn([f64; 11]) -> usize) -> usize {
    rows()
        .iter()
        .filter(|r| r.family == family)
        .map(|r| check(r.v))
        .sum()
}

#[test]
fn linear_family_matches_table_e3() {
    let n = checks_of("linear", |[aob, nu, nl, xi, eta, phi, fx, fy, mz, _, _]| {
        let (c11, c22, c23) = coefficients_nu(aob, nu).expect("table row");
        let checks: Vec<(f64, f64)> = if xi != 0.0 {
            vec![(-fx * nl / xi, c11)]
        } else if eta != 0.0 {
            vec![(-fy * nl / eta, c22), (mz * nl / eta, c23)]
        } else {
            vec![(-fy * nl / phi, c23)]
        };
        for &(got, want) in &checks {
            assert!(
                (got / want - 1.0).abs() <= 0.01,
                "a/b {aob} nu {nu}: {got} vs {want}"
            );
        }
        checks.len()
    });
    assert_eq!(n, 60);
}

#[test]
fn fullslip_family_matches_exact_integrals() {
    let n = checks_of("fullslip", |[aob, _, _, xi, eta, phi, fx, fy, mz, _, _]| {
        let (a, b) = (aob.sqrt(), 1.0 / aob.sqrt());
        let (ex, ey, em) = if a >= b {
            let t = traction(
                Parameter::from_complement((b / a).powi(2)).unwrap(),
                xi,
                eta,
                a * phi,
            );
            (t.fx, t.fy, t.tz * a)
        } else {
            let t = traction(
                Parameter::from_complement((a / b).powi(2)).unwrap(),
                eta,
                -xi,
                b * phi,
            );
            (-t.fy, t.fx, t.tz * b)
        };
        let (df, dm) = ((fx - ex).abs().max((fy - ey).abs()), (mz - em).abs());
        assert!(
            df <= 1e-3 && dm <= 1e-3,
            "a/b {aob} ({xi},{eta},{phi}): dF {df:e} dM {dm:e}"
        );
        1
    });
    assert_eq!(n, 25);
}

/// The writer of the generators (`Patch::grids_comment`, `Patch::csv_row`, `csv_file`: the
/// binary gen_rolling_ref, the examples midpoints and directions) writes every row of every
/// committed reference file in that file's exact text: each row re-written from its own values
/// is the same line, and the columns line is `CSV_COLUMNS`.
#[test]
fn the_writer_writes_the_committed_rows() {
    use rolling_exact::reference::{CSV_COLUMNS, Patch, Solution};
    use rolling_exact::solver::Totals;
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../data");
    let files = [
        "rolling_ref.csv",
        "rolling_ref_mid.csv",
        "rolling_ref_quarter.csv",
        "rolling_ref_dir.csv",
        "rolling_ref_dir_quarter.csv",
    ];
    for name in files {
        let text = std::fs::read_to_string(format!("{dir}/{name}")).expect(name);
        let mut lines = text.lines().filter(|l| !l.starts_with('#'));
        assert_eq!(lines.next(), Some(CSV_COLUMNS), "{name}");
        let mut n = 0;
        for line in lines {
            let mut it = line.split(',');
            let family = it.next().unwrap();
            let v: Vec<f64> = it.map(|s| s.parse().expect("number")).collect();
            let patch = Patch {
                aob: v[0],
                theta: 0.0,
                aligned: (0.0, 0.0, 0.0),
                nu: v[1],
                nl: v[2],
                levels: Vec::new(),
            };
            let sol = Solution {
                converged: true,
                totals: Totals {
                    fx: v[6],
                    fy: v[7],
                    mz: v[8],
                },
                err_f: v[9],
                err_m: v[10],
                levels: Vec::new(),
            };
            assert_eq!(
                patch.csv_row(family, [v[3], v[4], v[5]], &sol),
                line,
                "{name}"
            );
            n += 1;
        }
        assert!(n > 0, "{name}: no rows");
    }
}
