//! Rolling contact: every rolling law's error against Kalker's exact steady-rolling theory,
//! against cost, with the exact solver itself on the host chart.
//!
//! Charted error (the "at a glance" line, both Pareto charts, the first columns of the table):
//! the worst over the whole domain, the 500 points of the held-out set
//! `tools/data/rolling_ref_heldout.csv` (random shape a/b 1/20 … 20, skew of the rolling
//! direction to the patch axes, ν 0 … 0.5, creepage direction and magnitude; no law fitted on
//! them), of |ΔF| = |(ΔF_x, ΔF_y)| (fN) and |ΔM_z| (fNc), the laws' outputs read from
//! `tools/data/rolling_heldout_laws.csv` (written by `python3 tools/rolling_heldout.py` through
//! `contact_eval wrench`, i.e. the per-step wrench `contact::Rolling` in f64; `--check` in CI
//! keeps it what the laws give). The exact solver's own error is its estimate (the reference's
//! err_f, err_m columns).
//!
//! Second column, so nothing is lost: the 700 creep-curve points of
//! `tools/data/rolling_ref_quarter.csv` (aligned a/b ∈ {0.2 … 5}, ν = 0.25: the families
//! `table` was fitted to; ¼ and ¾ of each interval in ln q between `rolling_ref.csv`'s
//! magnitudes, not in `table`'s tables), evaluated here through `RollingContact::wrench` in f32
//! and f64 exactly as `python3 tools/fit_rolling_table.py --laws` does through
//! `contact_eval rolling` (a, b with c = √(ab) = 1, G = 1, f = 1, N = the row's load ratio,
//! V = 1).
//!
//! Cost: M4F instructions per call (`bench-results/qemu.csv`, stage `rolling`), host ns per
//! call (`bench-results/host-ns.csv`, stage `rolling`, from `benches/rolling.rs`), and for the
//! exact solver the host seconds per extrapolated value (`tools/data/rolling_ref_timing.csv`:
//! the mean solve time on its three grids summed, averaged over the five shapes at ν = 0.25).
//! The held-out set has f64 outputs only: an f32 point on the charts is f64's whole-domain error
//! at f32's cost (on the creep curves the two precisions' errors are compared in the text).

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

/// The held-out reference and the laws' outputs on it.
const HELDOUT_REF: &str = "tools/data/rolling_ref_heldout.csv";
const HELDOUT_LAWS: &str = "tools/data/rolling_heldout_laws.csv";

/// One creep-curve reference row: a/b, ν, load ratio, creepages ξ, η, cφ; F_x, F_y (fN), M_z
/// (fNc); the solver's own error estimates (fN, fNc).
struct Row {
    aob: f64,
    nu: f64,
    nl: f64,
    creep: [f64; 3],
    want: [f64; 3],
    est: [f64; 2],
}

/// The numeric columns after the first of a reference CSV's data rows.
fn numeric_rows(rel: &str) -> Option<Vec<Vec<f64>>> {
    let text = std::fs::read_to_string(repo(rel)).ok()?;
    let v = text
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with("family"))
        .filter_map(|l| {
            l.split(',')
                .skip(1)
                .map(|x| x.parse().ok())
                .collect::<Option<Vec<f64>>>()
        })
        .collect();
    Some(v)
}

fn rows(rel: &str) -> Option<Vec<Row>> {
    let v = numeric_rows(rel)?
        .into_iter()
        .filter_map(|f| {
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

/// One held-out reference row (`rolling_ref_heldout.csv`: a/b, θ, ν, nl, ξ, η, φc, F_x, F_y,
/// M_z, err_f, err_m, converged, seconds): the exact wrench in the rolling frame (fN, fNc), the
/// solver's own error estimates, and its seconds for the point.
struct Held {
    want: [f64; 3],
    est: [f64; 2],
    converged: bool,
    seconds: f64,
}

fn heldout_ref() -> Option<Vec<Held>> {
    let v = numeric_rows(HELDOUT_REF)?
        .into_iter()
        .filter_map(|f| {
            let [_, _, _, _, _, _, _, fx, fy, mz, ef, em, converged, seconds] = f[..] else {
                return None;
            };
            Some(Held {
                want: [fx, fy, mz],
                est: [ef, em],
                converged: converged == 1.0,
                seconds,
            })
        })
        .collect();
    Some(v)
}

/// The laws' outputs on the held-out set (`rolling_heldout_laws.csv`): per law name, its
/// (F_x/fN, F_y/fN, M_z/(fNc)) per point, in the reference's row order.
fn heldout_laws() -> Option<Vec<(String, Vec<[f64; 3]>)>> {
    let text = std::fs::read_to_string(repo(HELDOUT_LAWS)).ok()?;
    let mut lines = text
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'));
    let head: Vec<&str> = lines.next()?.split(',').collect();
    let data: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().ok()).collect::<Option<_>>())
        .collect::<Option<_>>()?;
    let col = |name: String| head.iter().position(|h| *h == name);
    let mut out = Vec::new();
    for h in &head {
        let Some(law) = h.strip_suffix("_fx") else {
            continue;
        };
        let (x, y, z) = (
            col(format!("{law}_fx"))?,
            col(format!("{law}_fy"))?,
            col(format!("{law}_mz"))?,
        );
        let got = data
            .iter()
            .map(|r| Some([*r.get(x)?, *r.get(y)?, *r.get(z)?]))
            .collect::<Option<_>>()?;
        out.push((law.to_string(), got));
    }
    Some(out)
}

/// Whole-domain errors of one law: worst and median |ΔF| (fN), worst and median |ΔM_z| (fNc).
#[derive(Clone, Copy)]
struct Whole {
    worst: [f64; 2],
    median: [f64; 2],
}

fn whole(reference: &[Held], got: &[[f64; 3]]) -> Whole {
    let (df, dm): (Vec<f64>, Vec<f64>) = reference
        .iter()
        .zip(got)
        .map(|(r, g)| {
            (
                (g[0] - r.want[0]).hypot(g[1] - r.want[1]),
                (g[2] - r.want[2]).abs(),
            )
        })
        .unzip();
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    Whole {
        worst: [max(&df), max(&dm)],
        median: [crate::median(df), crate::median(dm)],
    }
}

/// The held-out set: the reference and every law's whole-domain errors, or why it is absent.
struct Heldout {
    reference: Vec<Held>,
    laws: Vec<(String, Whole)>,
}

fn heldout() -> Result<Heldout, String> {
    let reference = heldout_ref().ok_or(format!("No `{HELDOUT_REF}`"))?;
    let laws = heldout_laws().ok_or(format!("No `{HELDOUT_LAWS}` (or it does not parse)"))?;
    if reference.is_empty() {
        return Err(format!("No rows in `{HELDOUT_REF}`"));
    }
    let mut out = Vec::new();
    for (law, got) in laws {
        if got.len() != reference.len() {
            return Err(format!(
                "`{HELDOUT_LAWS}` has {} rows, `{HELDOUT_REF}` {} (re-run `python3 \
                 tools/rolling_heldout.py`)",
                got.len(),
                reference.len()
            ));
        }
        let w = whole(&reference, &got);
        out.push((law, w));
    }
    Ok(Heldout {
        reference,
        laws: out,
    })
}

/// Max |ΔF| (fN) and |ΔM_z| (fNc) of law `L` in precision `T` over the creep-curve rows.
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

/// One method: its whole-domain errors (f64), its creep-curve errors per precision, its costs.
struct Method {
    law: &'static str,
    whole: Option<Whole>,
    /// [f32, f64] max |ΔF|, |ΔM_z| on the creep curves
    curves: Option<[[f64; 2]; 2]>,
    insns: [Option<f64>; 2],
    ns: [Option<f64>; 2],
}

const PRECISIONS: [&str; 2] = ["f32", "f64"];

/// The charted error: the larger of the two, to the three digits the table prints.
fn charted(err: [f64; 2]) -> f64 {
    three_digits(err[0].max(err[1]))
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

/// "a / b" to three decimals.
fn pair(v: [f64; 2]) -> String {
    format!("{:.3} / {:.3}", v[0], v[1])
}

/// Writes the section (table + two charts) into `md`, the charts into `dir`; returns the
/// "at a glance" line (the Pareto front on M4F instructions against the worst error over the
/// whole held-out set) if there is one.
pub fn section(md: &mut String, dir: &Path, host: &Keyed, qemu: &Keyed) -> Option<String> {
    md.push_str("### Rolling contact: Kalker's creep laws against the exact theory\n\n");
    let held = heldout();
    let quarter = rows("tools/data/rolling_ref_quarter.csv");
    match &held {
        Ok(h) => {
            let _ = writeln!(
                md,
                "Error (the first columns, both charts and the \"at a glance\" line): the worst \
                 over the {} points of the held-out set over the whole domain (`{HELDOUT_REF}`: \
                 shape a/b log-uniform in [1/20, 20], one point in three with an axis along the \
                 rolling direction and the others skewed at any angle, ν ∈ [0, 0.5], creepage \
                 direction uniform over (ξ, η, cφ) and magnitude log-uniform over three decades; \
                 {} not converged; no law fitted on them) of |ΔF| = |(ΔF_x, ΔF_y)| (fN) and \
                 |ΔM_z| (fNc, c = √(ab)) against Kalker's exact steady-rolling theory \
                 (`tools/rolling_exact`). The laws' outputs are read from `{HELDOUT_LAWS}`, which \
                 `python3 tools/rolling_heldout.py` writes through `contact_eval wrench` (the \
                 per-step wrench `contact::Rolling`, which also takes a rolling direction off the \
                 patch axes; `full-slip` there is `best`) **in f64 only**, and which CI's \
                 `--check` keeps what the laws give now; the tables per family (direction, \
                 skew, shape, ν, magnitude) are in `bench-results/rolling-heldout.md`.\n",
                h.reference.len(),
                h.reference.iter().filter(|r| !r.converged).count(),
            );
        }
        Err(why) => {
            let _ = writeln!(
                md,
                "{why}: the whole-domain figures, the charts and the \"at a glance\" line are \
                 left out.\n"
            );
        }
    }
    let key = |law: &str, p: &str| ("rolling".to_string(), law.to_string(), p.to_string());
    let get = |t: &Keyed, law: &str, p: &str| t.as_ref().and_then(|t| t.get(&key(law, p)).copied());
    let mut methods: Vec<Method> = Vec::new();
    macro_rules! law {
        ($l:ty, $name:expr) => {
            methods.push(Method {
                law: $name,
                whole: held.as_ref().ok().and_then(|h| {
                    h.laws
                        .iter()
                        .find(|(l, _)| l.as_str() == $name)
                        .map(|(_, w)| *w)
                }),
                curves: quarter
                    .as_ref()
                    .map(|q| [errors::<$l, f32>(q), errors::<$l, f64>(q)]),
                insns: PRECISIONS.map(|p| get(qemu, $name, p)),
                ns: PRECISIONS.map(|p| get(host, $name, p)),
            });
        };
    }
    law!(Table, Table::NAME);
    law!(Blend, Blend::NAME);
    law!(Fastsim, Fastsim::NAME);
    law!(FastsimGrid<16, 16>, "fastsim-16");
    law!(FullSlip, FullSlip::NAME);
    let exact = exact_ns();

    match &quarter {
        Some(q) => {
            // how far f32 and f64 differ where both are measured
            let gap = methods
                .iter()
                .filter_map(|m| m.curves)
                .fold([0.0f64; 2], |g, [a, b]| {
                    [g[0].max((a[0] - b[0]).abs()), g[1].max((a[1] - b[1]).abs())]
                });
            let _ = writeln!(
                md,
                "Second column, **on the creep curves `table` was fitted to**: the max over the \
                 {} creep-curve points of `tools/data/rolling_ref_quarter.csv` (pure ξ, η, φ, η \
                 with φ, ξ with η; aligned, a/b ∈ {{0.2, 0.5, 1, 2, 5}}, ν = 0.25; ¼ and ¾ of \
                 each interval between `rolling_ref.csv`'s magnitudes: not in `table`'s tables, \
                 but on the families it was fitted to), measured here through \
                 `RollingContact::wrench` in f32 and f64 (as `python3 tools/fit_rolling_table.py \
                 --laws`); there the two precisions' worst errors differ by at most {:.1e} fN / \
                 {:.1e} fNc (the f64 figure is printed).\n",
                q.len(),
                gap[0],
                gap[1]
            );
        }
        None => md.push_str(
            "No `tools/data/rolling_ref_quarter.csv`: the creep-curve column is left out.\n\n",
        ),
    }
    md.push_str(
        "Cost: M4F instructions (QEMU stage `rolling`: the law alone, `RollingContact::wrench`, \
         64 creep-curve states along an axis; the per-step wrench costs more off the axes, \
         `wrench-skewed` in `bench-results/qemu.csv`), host ns (`benches/rolling.rs`, same \
         states; stage `rolling` of `bench-results/host-ns.csv`). The exact solver: its own \
         error estimate (the reference CSVs' err_f, err_m) and its host time per extrapolated \
         value (three grids, `tools/data/rolling_ref_timing.csv`, mean over the five creep-curve \
         shapes; a loaded machine, so an upper figure). Charts: the larger of the two worst \
         whole-domain errors; as the held-out set has f64 outputs only, an **f32 point is f64's \
         whole-domain error at f32's cost** (an f64 point is measured in full); the red line \
         joins the Pareto front.\n\n",
    );

    md.push_str(
        "| method | whole domain: worst \\|ΔF\\| (fN) | worst \\|ΔM_z\\| (fNc) | median \\|ΔF\\| / \
         \\|ΔM_z\\| | on the creep curves `table` was fitted to: max \\|ΔF\\| / \\|ΔM_z\\| | \
         M4F insns f32 | M4F insns f64 | host ns f32 | host ns f64 |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let opt = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:.0}"));
    for m in &methods {
        let (wf, wm, med) = m.whole.map_or(("—".into(), "—".into(), "—".into()), |w| {
            (
                format!("{:.3}", w.worst[0]),
                format!("{:.3}", w.worst[1]),
                format!("{:.4} / {:.4}", w.median[0], w.median[1]),
            )
        });
        let curves = m.curves.map_or("—".into(), |[_, c64]| pair(c64));
        let _ = writeln!(
            md,
            "| {} | {wf} | {wm} | {med} | {curves} | {} | {} | {} | {} |",
            m.law,
            opt(m.insns[0]),
            opt(m.insns[1]),
            opt(m.ns[0]),
            opt(m.ns[1])
        );
    }
    let est = |it: &mut dyn Iterator<Item = [f64; 2]>| {
        it.fold([0.0f64; 2], |w, e| [w[0].max(e[0]), w[1].max(e[1])])
    };
    let held_est = held
        .as_ref()
        .ok()
        .map(|h| est(&mut h.reference.iter().map(|r| r.est)));
    let curve_est = quarter.as_ref().map(|q| est(&mut q.iter().map(|r| r.est)));
    if exact.is_some() || held_est.is_some() {
        let (wf, wm, med) = match &held {
            Ok(h) => {
                let col = |j: usize| crate::median(h.reference.iter().map(|r| r.est[j]).collect());
                let w = held_est.unwrap_or_default();
                (
                    format!("{:.4} (own estimate)", w[0]),
                    format!("{:.4} (own estimate)", w[1]),
                    format!("{:.1e} / {:.1e} (own estimate)", col(0), col(1)),
                )
            }
            Err(_) => ("—".into(), "—".into(), "—".into()),
        };
        let curves = curve_est.map_or("—".into(), |e| {
            format!("{:.4} / {:.4} (own estimate)", e[0], e[1])
        });
        let ns = match (exact, &held) {
            (Some((mean, lo, hi)), Ok(h)) => format!(
                "{mean:.2e} ({lo:.1e} … {hi:.1e} over the creep-curve shapes; the held-out \
                 set's own solves, 1,024 elements on the finest grid: {:.1e} per point, the mean \
                 of its `seconds`)",
                1e9 * h.reference.iter().map(|r| r.seconds).sum::<f64>() / h.reference.len() as f64
            ),
            (Some((mean, lo, hi)), Err(_)) => {
                format!("{mean:.2e} ({lo:.1e} … {hi:.1e} over the creep-curve shapes)")
            }
            (None, _) => "—".into(),
        };
        let _ = writeln!(
            md,
            "| exact (tools/rolling_exact, 3 grids + extrapolation) | {wf} | {wm} | {med} | \
             {curves} | — | — | — | {ns} |"
        );
    }
    md.push('\n');

    let Ok(h) = &held else {
        return None;
    };
    let mut insn_pts: Vec<(String, f64, f64)> = Vec::new();
    let mut ns_pts: Vec<(String, f64, f64)> = Vec::new();
    for m in &methods {
        let Some(w) = m.whole else { continue };
        for (i, p) in PRECISIONS.iter().enumerate() {
            let label = format!("{} {p}", m.law);
            if let Some(c) = m.insns[i] {
                insn_pts.push((label.clone(), c, charted(w.worst)));
            }
            if let Some(c) = m.ns[i] {
                ns_pts.push((label, c, charted(w.worst)));
            }
        }
    }
    if let (Some((mean, _, _)), Some(e)) = (exact, held_est) {
        ns_pts.push(("exact f64".into(), mean, e[0].max(e[1])));
    }
    let y = Axis {
        title: "worst error, whole-domain held-out set (|ΔF| in fN, |ΔM_z| in fNc)",
        log: true,
    };
    let charts = [
        (
            "pareto-rolling-m4f.png",
            format!(
                "Rolling laws, {} held-out points over the whole domain: worst error against \
                 M4F instructions",
                h.reference.len()
            ),
            "Cortex-M4F instructions per call (QEMU; f32 points: f64's error)",
            &insn_pts,
        ),
        (
            "pareto-rolling-host.png",
            format!(
                "Rolling laws and the exact solver, {} held-out points: worst error against \
                 host time",
                h.reference.len()
            ),
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
            &title,
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
    if front.is_empty() {
        return None;
    }
    let line = front
        .iter()
        .map(|(l, c, e)| format!("{l} ({c:.0}, {})", crate::e(*e)))
        .collect::<Vec<_>>()
        .join("; ");
    let _ = writeln!(
        md,
        "Pareto front on M4F instructions (worst whole-domain error), cheapest first: {line}.\n"
    );
    Some(line)
}
