//! The speed-against-accuracy report: every method × precision of every stage measured here
//! against the committed mpmath references (tools/data/), joined with the recorded host ns
//! (bench-results/host-ns.csv), QEMU instructions (bench-results/qemu.csv) and flash bytes
//! (bench-results/flash.csv), charted, and written to `docs/report.md` + `docs/report/*.png`.
//!
//! ```text
//! cargo run --release --example report                 # writes docs/
//! cargo run --release --example report -- --out DIR    # writes DIR/report.md, DIR/report/
//! ```
//!
//! `tools/report.sh` re-runs the benches first. Methods: `registry.rs` (one line each).
//! Inputs that are absent (flash.csv, scenes.csv, stability charts) print as "—" or are
//! left out with a note.

mod friction_maps;
mod inputs;
mod measure;
mod plot;
mod registry;
mod rolling;

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use plot::Axis;
use registry::{Method, SECTIONS, Section};

/// Measured errors of one method: per component (max, median), and the row count.
struct Measured {
    m: Method,
    max: Vec<f64>,
    median: Vec<f64>,
    rows: usize,
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn measure(m: Method, refs: &measure::Refs) -> Measured {
    let errs = (m.errors)(refs);
    let k = m.section.components.len();
    // NaN: the point is outside this component's range (not counted)
    let col = |j: usize| {
        errs.iter()
            .filter_map(|e| e.get(j).copied().filter(|v| !v.is_nan()))
            .collect::<Vec<_>>()
    };
    Measured {
        m,
        max: (0..k)
            .map(|j| col(j).into_iter().fold(f64::NAN, f64::max))
            .collect(),
        median: (0..k).map(|j| median(col(j))).collect(),
        rows: errs.len(),
    }
}

type Keyed = Option<HashMap<(String, String, String), f64>>;
/// key → [lo, mid, hi] Cortex-M4F cycles per call (bench-results/cycles.csv).
type Cycles = Option<HashMap<(String, String, String), [f64; 3]>>;

fn lookup(t: &Keyed, m: &Method) -> Option<f64> {
    t.as_ref()?
        .get(&(m.stage.into(), m.method.into(), m.precision.into()))
        .copied()
}

fn e(v: f64) -> String {
    if v.is_nan() {
        "—".into()
    } else if v == 0.0 {
        "0".into()
    } else {
        format!("{v:.1e}")
    }
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("—".into(), |v| format!("{v:.digits$}"))
}

struct Out {
    dir: PathBuf,
    md: String,
}

impl Out {
    fn img(&mut self, alt: &str, file: &str) {
        let _ = writeln!(self.md, "![{alt}](report/{file})\n");
    }
}

/// The chart's points of a section: (method precision, QEMU instructions, max error over the
/// charted components); rows without a QEMU count are left out.
fn chart_points(s: &Section, rows: &[&Measured], qemu: &Keyed) -> Vec<(String, f64, f64)> {
    rows.iter()
        .filter_map(|r| {
            let insns = lookup(qemu, &r.m)?;
            // a zero error (exact on every reference point) is drawn at the chart's floor
            let err = s
                .chart
                .iter()
                .filter_map(|&j| r.max.get(j))
                .fold(0.0, |a: f64, &b| a.max(b))
                .max(1e-17);
            Some((format!("{} {}", r.m.method, r.m.precision), insns, err))
        })
        .collect()
}

/// The Pareto front of chart points (no other point is both cheaper and more accurate), by
/// rising cost.
fn pareto_front(pts: &[(String, f64, f64)]) -> Vec<&(String, f64, f64)> {
    let mut front: Vec<&(String, f64, f64)> = pts
        .iter()
        .filter(|p| {
            !pts.iter()
                .any(|q| q.1 <= p.1 && q.2 <= p.2 && (q.1 < p.1 || q.2 < p.2))
        })
        .collect();
    front.sort_by(|a, b| a.1.total_cmp(&b.1));
    front
}

/// "At a glance": per stage, the methods on the Pareto front with their cost and error.
fn glance(md: &mut String, measured: &[Measured], qemu: &Keyed, rolling: Option<&str>) {
    md.push_str(
        "\n## At a glance: the Pareto front of each stage\n\n\
         The methods no other method beats on both M4F instructions and max error (computed \
         from the tables below; pick the first one whose error your scene tolerates — or let \
         [`contensou::select`](#scenes-the-cheapest-adequate-model-per-scene) pick it):\n\n\
         | stage | Pareto front: method precision (instructions, max error), cheapest first |\n\
         |---|---|\n",
    );
    for s in &SECTIONS {
        let rows: Vec<&Measured> = measured.iter().filter(|r| r.m.section.id == s.id).collect();
        let pts = chart_points(s, &rows, qemu);
        let front: Vec<String> = pareto_front(&pts)
            .iter()
            .map(|(label, insns, err)| format!("{label} ({insns:.0}, {})", e(*err)))
            .collect();
        if !front.is_empty() {
            let _ = writeln!(md, "| {} | {} |", s.title, front.join("; "));
        }
    }
    if let Some(front) = rolling {
        let _ = writeln!(
            md,
            "| Rolling contact (worst over the whole-domain held-out set; f64 error, also for \
             f32) | {front} |"
        );
    }
    md.push('\n');
}

fn section(
    out: &mut Out,
    s: &Section,
    rows: &[&Measured],
    host: &Keyed,
    qemu: &Keyed,
    cycles: &Cycles,
    flash: &Keyed,
) {
    let md = &mut out.md;
    let _ = writeln!(md, "### {}\n", s.title);
    let _ = writeln!(md, "Error: {}.\n", s.how);
    let mut head = String::from("| method | precision | points |");
    for c in s.components {
        let _ = write!(head, " max {c} | median {c} |");
    }
    head.push_str(" host ns | QEMU insns | µs at 168 MHz | flash bytes |");
    let _ = writeln!(md, "{head}");
    let _ = writeln!(md, "|{}", "---|".repeat(7 + 2 * s.components.len()));
    for r in rows {
        let mut line = format!("| {} | {} | {} |", r.m.method, r.m.precision, r.rows);
        for (a, b) in r.max.iter().zip(&r.median) {
            let _ = write!(line, " {} | {} |", e(*a), e(*b));
        }
        let us = cycles
            .as_ref()
            .and_then(|t| t.get(&(r.m.stage.into(), r.m.method.into(), r.m.precision.into())))
            .map_or("—".into(), |&c| inputs::micros(c));
        let _ = write!(
            line,
            " {} | {} | {} | {} |",
            opt(lookup(host, &r.m), 1),
            opt(lookup(qemu, &r.m), 0),
            us,
            opt(lookup(flash, &r.m), 0)
        );
        let _ = writeln!(md, "{line}");
    }
    md.push('\n');
    let pts = chart_points(s, rows, qemu);
    if pts.is_empty() {
        return;
    }
    let file = format!("pareto-{}.png", s.id);
    let r = plot::pareto(
        &out.dir.join(&file),
        &format!("{}: max error against QEMU instructions per call", s.title),
        Axis {
            title: "Cortex-M4F instructions per call (QEMU)",
            log: true,
        },
        Axis {
            title: &format!(
                "max error ({})",
                s.chart
                    .iter()
                    .filter_map(|&j| s.components.get(j).copied())
                    .collect::<Vec<_>>()
                    .join("; ")
            ),
            log: true,
        },
        &pts,
    );
    match r {
        Ok(()) => out.img(&format!("{}: error against instructions", s.title), &file),
        Err(err) => eprintln!("report: {file}: {err}"),
    }
    let missing: Vec<String> = rows
        .iter()
        .filter(|r| lookup(qemu, &r.m).is_none())
        .map(|r| format!("{} {}", r.m.method, r.m.precision))
        .collect();
    if !missing.is_empty() {
        let _ = writeln!(
            out.md,
            "Not on the chart (no QEMU row): {}.\n",
            missing.join(", ")
        );
    }
}

const INTRO: &str = "# Speed against accuracy

Generated by `tools/report.sh` (benches, then `cargo run --release --example report`); do not
edit by hand. Every error below is measured by the report itself, calling the library against
the committed mpmath references in `tools/data/` (never against the code under test); the cost
columns are joined from the recorded benchmark files by `stage,method,precision`.

How to read the cost columns:

- **host ns**: criterion on the machine that ran `tools/report.sh` (`bench-results/host-ns.csv`,
  fastest sample per benchmark, divided by the calls per iteration). The machine (2 cores) is
  shared and loaded: two back-to-back runs agreed within 5 % on 36 of 40 rows and differed by
  up to 42 % on the others, so compare orders of magnitude, not single figures. Host time is
  not the MCU cost.
- **QEMU insns**: executed Cortex-M4F instructions per call under QEMU (`-icount`,
  `bench-results/qemu.csv`), deterministic. These are *instructions, not cycles*: QEMU models no
  pipeline, wait states or FPU latencies (a `vsqrt.f32` or `vdiv.f32` costs 14 cycles on the
  M4F but counts 1 here). Each figure includes the call itself: the floor is `core,call,f32` =
  8 instructions for an empty call. f64 runs in software on the M4F (no double FPU), hence its
  10–100× counts.
- **µs at 168 MHz**: Cortex-M4F cycles per call at 168 MHz, estimated from the executed
  instruction mix of the same QEMU run (`bench-results/cycles.csv`, `tools/cycle_model.py`:
  the TRM's cycle table, VDIV/VSQRT 14, VMLA 3, loads 2 or 1 pipelined, taken branches 1 + P);
  the figure is P = 2, the range P = 1…3. Zero flash wait states assumed (the STM32F4's ART
  accelerator hides most of its 5 at 168 MHz in loops, not on cold code).
- **flash bytes**: from `bench-results/flash.csv` when present (`—` otherwise).
- Error charts: one point per method × precision with a QEMU row; log–log; the red line joins
  the Pareto front (no other point is both cheaper and more accurate). An error of exactly 0 is
  drawn at 1e-17.
";

fn main() {
    let mut args = std::env::args().skip(1);
    let mut out_dir = inputs::repo("docs");
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => match args.next() {
                Some(d) => out_dir = PathBuf::from(d),
                None => {
                    eprintln!("--out needs a directory");
                    std::process::exit(2);
                }
            },
            _ => {
                eprintln!(
                    "usage: report [--out DIR]   (writes DIR/report.md and DIR/report/*.png)"
                );
                std::process::exit(2);
            }
        }
    }
    let start = Instant::now();
    plot::register();
    let img_dir = out_dir.join("report");
    if let Err(err) = std::fs::create_dir_all(&img_dir) {
        eprintln!("report: {}: {err}", img_dir.display());
        std::process::exit(1);
    }
    // generated images only (the stability CSVs under report/stability/ stay)
    if let Ok(entries) = std::fs::read_dir(&img_dir) {
        for p in entries.filter_map(|e| e.ok().map(|e| e.path())) {
            if p.extension().is_some_and(|x| x == "png") {
                let _ = std::fs::remove_file(p);
            }
        }
    }
    let mut out = Out {
        dir: img_dir,
        md: INTRO.to_string(),
    };

    let refs = measure::Refs::load();
    let measured: Vec<Measured> = registry::methods()
        .into_iter()
        .map(|m| measure(m, &refs))
        .collect();
    eprintln!(
        "report: errors measured in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    let host = inputs::keyed("bench-results/host-ns.csv");
    let qemu = inputs::keyed("bench-results/qemu.csv");
    let flash = inputs::keyed("bench-results/flash.csv");
    let cycles = inputs::cycles();
    let mut missing = Vec::new();
    for (t, f) in [
        (&host, "host-ns.csv"),
        (&qemu, "qemu.csv"),
        (&flash, "flash.csv"),
    ] {
        if t.is_none() {
            missing.push(format!("`bench-results/{f}`"));
        }
    }
    if cycles.is_none() {
        missing.push("`bench-results/cycles.csv`".into());
    }
    if !missing.is_empty() {
        let _ = writeln!(
            out.md,
            "\nNot recorded yet (shown as —): {}.",
            missing.join(", ")
        );
    }

    let mut rolling_md = String::new();
    let rolling_front = rolling::section(&mut rolling_md, &out.dir, &host, &qemu);
    glance(&mut out.md, &measured, &qemu, rolling_front.as_deref());
    out.md.push_str("\n## Error against cost, per stage\n\n");
    for s in &SECTIONS {
        let rows: Vec<&Measured> = measured.iter().filter(|r| r.m.section.id == s.id).collect();
        section(&mut out, s, &rows, &host, &qemu, &cycles, &flash);
    }
    out.md.push_str(&rolling_md);

    out.md.push_str(FRICTION_MAPS);
    let t = Instant::now();
    match friction_maps::all_maps(&out.dir) {
        Ok(maps) => {
            for m in maps {
                let _ = writeln!(
                    out.md,
                    "**{}** (max over the grid: force {}, torque {}):\n",
                    m.law,
                    e(m.max_force),
                    e(m.max_torque)
                );
                for file in &m.files {
                    out.img(&format!("{} error map", m.law), file);
                }
            }
        }
        Err(err) => eprintln!("report: friction maps: {err}"),
    }
    out.md.push_str(FRICTION_CURVES);
    match friction_maps::curves(&out.dir) {
        Ok(files) => {
            for file in files {
                out.img("model curves at e = 0.81, ψ = π/4", &file);
            }
        }
        Err(err) => eprintln!("report: friction curves: {err}"),
    }
    eprintln!(
        "report: friction maps and curves in {:.1} s",
        t.elapsed().as_secs_f64()
    );

    out.md.push_str("## Stability\n\n");
    let charts = inputs::stability(&out.dir);
    if charts.is_empty() {
        out.md.push_str(
            "No stability data yet (`cargo run --release --example stability` writes \
             `docs/report/stability/*.csv`).\n\n",
        );
    }
    for (title, file) in charts {
        let _ = writeln!(out.md, "#### {title}\n");
        out.img(&title, &file);
    }
    if let Ok(table) = std::fs::read_to_string(inputs::repo("docs/report/stability.md")) {
        out.md.push_str(&table);
        out.md.push('\n');
    }

    out.md.push_str(
        "\n## Scenes: the cheapest adequate model per scene\n\n\
         What `contensou::select` resolves each declared scene to (`Scene<patch, geometry, \
         motion, budget, precision>`), chosen at compile time so only that configuration's \
         code is linked: per step cost, flash and measured error against the exact model.\n\n",
    );
    match inputs::scenes() {
        Some(t) => out.md.push_str(&t),
        None => out
            .md
            .push_str("No scene table yet (`bench-results/scenes.csv`).\n"),
    }

    out.md.push_str(
        "\n## From Python: throughput, and the library's contact inside MuJoCo\n\n\
         The Python package's figures (`python/bench.py` → `bench-results/python.md`) and the \
         MuJoCo comparison (`python/examples/mujoco_report.py` → `docs/mujoco.md`), included \
         here as recorded (their headings one level down).\n\n",
    );
    for rel in ["bench-results/python.md", "docs/mujoco.md"] {
        match std::fs::read_to_string(inputs::repo(rel)) {
            Ok(text) => {
                for line in text.lines() {
                    if line.starts_with('#') {
                        out.md.push('#');
                    }
                    out.md.push_str(line);
                    out.md.push('\n');
                }
                out.md.push('\n');
            }
            Err(_) => {
                let _ = writeln!(out.md, "No `{rel}` yet.\n");
            }
        }
    }

    let path = out_dir.join("report.md");
    if let Err(err) = std::fs::write(&path, &out.md) {
        eprintln!("report: {}: {err}", path.display());
        std::process::exit(1);
    }
    eprintln!(
        "report: wrote {} in {:.1} s",
        path.display(),
        start.elapsed().as_secs_f64()
    );
}

const FRICTION_MAPS: &str = "
## Friction: where each law errs, over (u, ψ)

Error of the law (f64, per-contact form) against the library's exact integrals
(`friction::Exact`, 5e-15 against mpmath) on a 128 × 64 grid of cell centres: u = v/(aω)
log-spaced over [1e-2, 1e2], ψ over [0, π/2] (the symmetries ψ → −ψ, ψ → π − ψ cover the rest),
for e² ∈ {0, 0.5, 0.9, 0.99, 0.999, 0.9999}. Force: |ΔF|/(fN); torque: |ΔT_z|/(fNa). Shared logarithmic colour
scale per image (at most 12 decades; values below its floor take the floor colour).

";

const FRICTION_CURVES: &str = "
## Friction: the exact and model curves at e = 0.81, ψ = π/4

F_x/(fN), F_y/(fN) and T_z/(fNa) against u for the exact integrals and every law (f64,
per-contact form): the paper's Figs. 3.4–3.6, here on a logarithmic u axis.

";
