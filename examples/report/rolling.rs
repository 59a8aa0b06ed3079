//! Rolling contact: every rolling law's error against the exact steady-rolling
//! reference on its held-out points, against cost, with the exact solver itself on the host
//! chart.
//!
//! Errors: the 700 creep-curve points of `tools/data/rolling_ref_quarter.csv` (¼ and ¾ of each
//! interval in ln q between `rolling_ref.csv`'s magnitudes: held out from `table`'s tables, no
//! law fitted on them), evaluated here through `RollingContact::wrench` exactly as
//! `python3 tools/fit_rolling_table.py --laws` does through `contact_eval rolling` (a, b with
//! c = √(ab) = 1, G = 1, f = 1, N = the row's load ratio, V = 1): max |ΔF| (fN) and max |ΔM_z|
//! (fNc). The exact solver's own error is its estimate (the CSV's err_f, err_m columns).
//!
//! Cost: M4F instructions per call (`bench-results/qemu.csv`, stage `rolling`), host ns per
//! call (`bench-results/host-ns.csv`, stage `rolling`, from `benches/rolling.rs`), and for the
//! exact solver the host seconds per extrapolated value (`tools/data/rolling_ref_timing.csv`:
//! the mean solve time on its three grids summed, averaged over the five shapes at ν = 0.25).

use std::fmt::Write as _;
use std::path::Path;

use contensou::Real;
use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
};

use crate::Keyed;
use crate::inputs::repo;
use crate::plot::{self, Axis};

/// One reference row: a/b, ν, load ratio, creepages ξ, η, cφ; F_x, F_y (fN), M_z (fNc); the
/// solver's own error estimates (fN, fNc).
struct Row {
    aob: f64,
    nu: f64,
    nl: f64,
    creep: [f64; 3],
    want: [f64; 3],
    est: [f64; 2],
}

fn rows(rel: &str) -> Option<Vec<Row>> {
    let text = std::fs::read_to_string(repo(rel)).ok()?;
    let v = text
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with("family"))
        .filter_map(|l| {
            let f: Vec<f64> = l
                .split(',')
                .skip(1)
                .map(|x| x.parse().ok())
                .collect::<Option<_>>()?;
            let [aob, nu, nl, xi, eta, phic, fx, fy, mz, ef, em] = f[..] else {
                return None;
            };
            Some(Row {
                aob,
                nu,
                nl,
                creep: [xi, eta, phic],
                want: [fx, fy, mz],
                est: [ef, em],
            })
        })
        .collect();
    Some(v)
}

/// Max |ΔF| (fN) and |ΔM_z| (fNc) of law `L` in precision `T` over the rows.
fn errors<L: RollingLaw, T: Real>(rows: &[Row]) -> [f64; 2] {
    let x = T::from_f64;
    let mut worst = [0.0f64; 2];
    for r in rows {
        let (a, b) = (r.aob.sqrt(), 1.0 / r.aob.sqrt());
        let w = Elasticity::new(x(1.0), x(r.nu))
            .and_then(|el| RollingContact::new(x(a) / x(b), el))
            .and_then(|c| {
                let p = Patch::new(x(a), x(b), x(r.nl), x(1.0))?;
                let s = RollingSlip::from_creepages(
                    x(r.creep[0]),
                    x(r.creep[1]),
                    x(r.creep[2]),
                    x(1.0),
                )?;
                Ok(c.wrench::<L>(&p, &s))
            });
        let Ok(w) = w else {
            return [f64::NAN; 2];
        };
        let g = |v: T| v.to_f64() / r.nl;
        let df = (g(w.fx) - r.want[0]).hypot(g(w.fy) - r.want[1]);
        let dm = (g(w.mz) - r.want[2]).abs();
        worst = [worst[0].max(df), worst[1].max(dm)];
    }
    worst
}

/// One method × precision: its errors and costs.
struct Point {
    law: &'static str,
    precision: &'static str,
    err: [f64; 2],
    insns: Option<f64>,
    ns: Option<f64>,
}

impl Point {
    fn label(&self) -> String {
        format!("{} {}", self.law, self.precision)
    }
    /// The charted error: the larger of the two, to the three digits the table prints (so
    /// f32 and f64 of one law tie, and the dearer one is off the front).
    fn worst(&self) -> f64 {
        three_digits(self.err[0].max(self.err[1]))
    }
}

fn three_digits(x: f64) -> f64 {
    format!("{x:.2e}").parse().unwrap_or(x)
}

/// The exact solver's cost: host ns per extrapolated value (three grids), mean over the shapes
/// of the creep-curve set (ν = 0.25), and the range over the shapes.
fn exact_ns() -> Option<(f64, f64, f64)> {
    let text = std::fs::read_to_string(repo("tools/data/rolling_ref_timing.csv")).ok()?;
    let mut per_shape: Vec<(f64, f64)> = Vec::new();
    for l in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<f64> = l.split(',').filter_map(|x| x.parse().ok()).collect();
        // a_over_b,nu,nl,k,elements,build_s,cases,solve_s_mean,solve_s_max,sweeps_mean
        if let [aob, nu, _, _, _, _, _, mean, ..] = f[..]
            && nu == 0.25
        {
            match per_shape.iter_mut().find(|s| s.0 == aob) {
                Some(s) => s.1 += mean,
                None => per_shape.push((aob, mean)),
            }
        }
    }
    if per_shape.is_empty() {
        return None;
    }
    let ns: Vec<f64> = per_shape.iter().map(|s| s.1 * 1e9).collect();
    let mean = ns.iter().sum::<f64>() / ns.len() as f64;
    let lo = ns.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ns.iter().copied().fold(0.0, f64::max);
    Some((mean, lo, hi))
}

/// Writes the section (table + two charts) into `md`, the charts into `dir`; returns the
/// "at a glance" line (the Pareto front on M4F instructions) if there is one.
pub fn section(md: &mut String, dir: &Path, host: &Keyed, qemu: &Keyed) -> Option<String> {
    md.push_str("### Rolling contact: Kalker's creep laws against the exact theory\n\n");
    let Some(quarter) = rows("tools/data/rolling_ref_quarter.csv") else {
        md.push_str("No `tools/data/rolling_ref_quarter.csv`: section left out.\n\n");
        return None;
    };
    let _ = writeln!(
        md,
        "Error: max over the {} held-out creep-curve points of \
         `tools/data/rolling_ref_quarter.csv` (pure ξ, η, φ, η with φ, ξ with η; a/b ∈ {{0.2, \
         0.5, 1, 2, 5}}, ν = 0.25; ¼ and ¾ of each interval between `rolling_ref.csv`'s \
         magnitudes: not in `table`'s tables, no law fitted on them) of |ΔF| (fN) and |ΔM_z| \
         (fNc, c = √(ab)) against the exact steady-rolling reference (`tools/rolling_exact`), \
         measured here through `RollingContact::wrench` (as `python3 tools/fit_rolling_table.py \
         --laws`). Cost: M4F instructions (QEMU stage `rolling`, 64 creep-curve states), host ns \
         (`benches/rolling.rs`, same states; stage `rolling` of `bench-results/host-ns.csv`). \
         The exact solver: its own error estimate (err_f, err_m of the CSV) and its host time \
         per extrapolated value (three grids, `tools/data/rolling_ref_timing.csv`, mean over \
         the five shapes; a loaded machine, so an upper figure). Charts: the larger of the two \
         errors.\n",
        quarter.len()
    );
    let key = |law: &str, p: &str| ("rolling".to_string(), law.to_string(), p.to_string());
    let get = |t: &Keyed, law: &str, p: &str| t.as_ref().and_then(|t| t.get(&key(law, p)).copied());
    let mut pts: Vec<Point> = Vec::new();
    macro_rules! law {
        ($l:ty, $name:expr) => {
            for (p, err) in [
                ("f32", errors::<$l, f32>(&quarter)),
                ("f64", errors::<$l, f64>(&quarter)),
            ] {
                pts.push(Point {
                    law: $name,
                    precision: p,
                    err,
                    insns: get(qemu, $name, p),
                    ns: get(host, $name, p),
                });
            }
        };
    }
    law!(Table, Table::NAME);
    law!(Blend, Blend::NAME);
    law!(Fastsim, Fastsim::NAME);
    law!(FastsimGrid<16, 16>, "fastsim-16");
    law!(FullSlip, FullSlip::NAME);
    let exact_err = quarter
        .iter()
        .fold([0.0f64; 2], |w, r| [w[0].max(r.est[0]), w[1].max(r.est[1])]);
    let exact = exact_ns();

    md.push_str(
        "| method | precision | max \\|ΔF\\| (fN) | max \\|ΔM_z\\| (fNc) | M4F insns | host ns |\n\
         |---|---|---|---|---|---|\n",
    );
    let opt = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:.0}"));
    for p in &pts {
        let _ = writeln!(
            md,
            "| {} | {} | {:.3} | {:.3} | {} | {} |",
            p.law,
            p.precision,
            p.err[0],
            p.err[1],
            opt(p.insns),
            opt(p.ns)
        );
    }
    if let Some((mean, lo, hi)) = exact {
        let _ = writeln!(
            md,
            "| exact (tools/rolling_exact, 3 grids + extrapolation) | f64 | {:.4} (own estimate) | \
             {:.4} (own estimate) | — | {:.2e} ({:.1e} … {:.1e} over the shapes) |",
            exact_err[0], exact_err[1], mean, lo, hi
        );
    }
    md.push('\n');

    let insn_pts: Vec<(String, f64, f64)> = pts
        .iter()
        .filter_map(|p| Some((p.label(), p.insns?, p.worst())))
        .collect();
    let mut ns_pts: Vec<(String, f64, f64)> = pts
        .iter()
        .filter_map(|p| Some((p.label(), p.ns?, p.worst())))
        .collect();
    if let Some((mean, _, _)) = exact {
        ns_pts.push(("exact f64".into(), mean, exact_err[0].max(exact_err[1])));
    }
    let y = Axis {
        title: "max error on held-out points (|ΔF| in fN, |ΔM_z| in fNc)",
        log: true,
    };
    let charts = [
        (
            "pareto-rolling-m4f.png",
            "Rolling laws: error against Cortex-M4F instructions per call (QEMU)",
            "Cortex-M4F instructions per call (QEMU)",
            &insn_pts,
        ),
        (
            "pareto-rolling-host.png",
            "Rolling laws and the exact solver: error against host time per call",
            "host ns per call (criterion; exact solver: per extrapolated value)",
            &ns_pts,
        ),
    ];
    for (file, title, x, pts) in charts {
        if pts.is_empty() {
            let _ = writeln!(md, "Chart `{file}` left out: no cost rows recorded.\n");
            continue;
        }
        let r = plot::pareto(
            &dir.join(file),
            title,
            Axis {
                title: x,
                log: true,
            },
            y,
            pts,
        );
        match r {
            Ok(()) => {
                let _ = writeln!(md, "![{title}](report/{file})\n");
            }
            Err(err) => eprintln!("report: {file}: {err}"),
        }
    }
    let front = crate::pareto_front(&insn_pts);
    (!front.is_empty()).then(|| {
        front
            .iter()
            .map(|(l, c, e)| format!("{l} ({c:.0}, {})", crate::e(*e)))
            .collect::<Vec<_>>()
            .join("; ")
    })
}
