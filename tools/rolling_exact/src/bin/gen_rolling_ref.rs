//! Writes tools/data/rolling_ref.csv (format: ROLLING.md) and a per-case timing file.
//!
//! `cargo run --release --bin gen_rolling_ref -- [--target N] [--out PATH] [--shapes 0.2,1] [--no-contact]`
//! (run from tools/rolling_exact; defaults: about 1024 elements on the finest grid, the
//! repository's tools/data/rolling_ref.csv, all five shapes, plus CONTACT's published cases).

use rolling_exact::cases::{self, Case};
use rolling_exact::reference::{Patch, csv_file, finest_k};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Instant;

fn main() {
    let mut target = 1024usize;
    let mut out = String::from("../data/rolling_ref.csv");
    let mut shapes: Vec<f64> = cases::SHAPES.to_vec();
    let mut contact = true;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--target" => {
                target = args
                    .next()
                    .and_then(|s| s.parse().ok())
                    .expect("--target N")
            }
            "--out" => out = args.next().expect("--out PATH"),
            "--shapes" => {
                shapes = args
                    .next()
                    .expect("--shapes list")
                    .split(',')
                    .map(|s| s.parse().expect("a/b"))
                    .collect()
            }
            "--no-contact" => contact = false,
            _ => panic!("unknown argument {a}"),
        }
    }
    let started = Instant::now();
    let mut rows = String::new();
    let mut timing = String::from(
        "a_over_b,nu,nl,k,elements,build_s,cases,solve_s_mean,solve_s_max,sweeps_mean\n",
    );
    let mut grids = String::new();
    // group the cases by (a/b, ν, nl): one set of influence coefficients each
    let mut groups: BTreeMap<(u64, u64, u64), Vec<Case>> = BTreeMap::new();
    let all = shapes.iter().flat_map(|&aob| cases::for_shape(aob));
    let all: Vec<Case> = if contact {
        all.chain(cases::contact()).collect()
    } else {
        all.collect()
    };
    for c in all {
        groups
            .entry((c.aob.to_bits(), c.nu.to_bits(), c.nl.to_bits()))
            .or_default()
            .push(c);
    }
    for ((aob, nu, nl), list) in groups {
        let (aob, nu, nl) = (f64::from_bits(aob), f64::from_bits(nu), f64::from_bits(nl));
        let k = finest_k(aob, target);
        let patch = Patch::new(aob, nu, nl, k);
        let mut stat = [(0.0f64, 0.0f64, 0usize); 3];
        for c in &list {
            let s = patch.solve(c.xi, c.eta, c.phi_c, c.coulomb);
            assert!(s.converged, "not converged: {c:?}");
            for (i, l) in s.levels.iter().enumerate() {
                stat[i].0 += l.2;
                stat[i].1 = stat[i].1.max(l.2);
                stat[i].2 += l.1.sweeps;
            }
            let row = patch.csv_row(c.family, [c.xi, c.eta, c.phi_c], &s);
            writeln!(rows, "{row}").unwrap();
        }
        for (i, l) in patch.levels.iter().enumerate() {
            let n = list.len() as f64;
            writeln!(
                timing,
                "{aob},{nu},{nl},{},{},{:.4},{},{:.5},{:.5},{:.1}",
                l.k,
                l.grid.len(),
                l.build_s,
                list.len(),
                stat[i].0 / n,
                stat[i].1,
                stat[i].2 as f64 / n
            )
            .unwrap();
        }
        writeln!(grids, "{}", patch.grids_comment()).unwrap();
        eprintln!(
            "a/b {aob} nu {nu} nl {nl}: {} cases, {:.1} s so far",
            list.len(),
            started.elapsed().as_secs_f64()
        );
    }
    let mut text = String::new();
    text.push_str(
        "# Exact steady-rolling reference (Kalker's exact half-space theory), written by\n",
    );
    text.push_str("# tools/rolling_exact (cargo run --release --bin gen_rolling_ref); method: tools/rolling_exact/README.md.\n");
    text.push_str("# Dimensionless: c = sqrt(ab) = 1, G = 1, f = 1, N = nl; fx, fy = F/(fN), mz = Mz/(fNc), forces on body B,\n");
    text.push_str("# Kalker's convention (rolling along +x, leading edge +a, creepages = slip of B relative to A / V).\n");
    text.push_str("# Each row: Richardson extrapolation F0 + c1 h + c2 h^2 over three grids (h = 1/k, k elements along the\n");
    text.push_str("# shorter axis, square elements); err_f, err_m = |3-grid - 2-grid (finest pair, linear)| extrapolation.\n");
    text.push_str("# linear: full adhesion (no traction bound), creepage 1e-3 of saturation: C11 = -fx*nl/xi etc.\n");
    text.push_str("# fullslip: normalised creepage 1e4 (elastic correction O(1e-4)).\n");
    text.push_str("# contact_example, contact_testbank: CONTACT's published cases (nu = 0.28; tools/rolling_exact/src/cases.rs).\n");
    let seconds = started.elapsed().as_secs_f64();
    std::fs::write(&out, csv_file(&text, &grids, seconds, &rows)).expect("write csv");
    let tpath = out.replace(".csv", "_timing.csv");
    std::fs::write(&tpath, timing).expect("write timing");
    eprintln!(
        "wrote {out} and {tpath} in {:.1} s",
        started.elapsed().as_secs_f64()
    );
}
