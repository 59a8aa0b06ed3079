//! How the batch path scales: contacts per second against rows (10³ … 10⁷) for the scalar
//! loop and `wrench_many`, and across threads when the caller splits the arrays (the core
//! stays single-threaded; `std::thread::scope`, one chunk per thread). `best`, fixed, the
//! contract's contact (Hunt–Crossley c_d = 0.5 s/m, f = 0.3, δ = 1e-4 m/s, P = 40, Q = 60).
//!
//! `cargo run --release --example batch_scaling` (run by tools/batch-bench.sh) writes
//! bench-results/batch-scaling.csv and docs/report/batch/scaling.png. Wall-clock time,
//! minimum over repeats (≥ 2, filling 0.25 s).

#[path = "report/plot.rs"]
#[allow(dead_code)]
mod plot;

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use contensou::Real;
use contensou::batch::{self, BatchReal, Steps, Wrenches};
use contensou::contact::Contact;
use contensou::friction::{Best, Friction, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, HuntCrossley, Modulus};
use contensou::shape::Newton;

type Fixed<T> = Contact<T, Hertz<T>, HuntCrossley<T>, Best>;

fn contact<T: Real>() -> Fixed<T> {
    Contact::hertz::<Newton>(
        &Curvatures::ordered(T::from_f64(40.0), T::from_f64(60.0)).unwrap(),
        Modulus::new(T::from_f64(1.15e11)).unwrap(),
        HuntCrossley::new(T::from_f64(0.5)).unwrap(),
        Friction::with_law(T::from_f64(0.3), T::from_f64(1e-4)).unwrap(),
    )
    .unwrap()
}

include!("../benches/batch_set.rs");

/// Minimum wall time of `f` over ≥ 2 repeats filling 0.25 s.
fn time(mut f: impl FnMut()) -> f64 {
    let (mut best, mut spent, mut reps) = (f64::INFINITY, 0.0, 0);
    while reps < 2 || spent < 0.25 {
        let t = Instant::now();
        f();
        let dt = t.elapsed().as_secs_f64();
        best = best.min(dt);
        spent += dt;
        reps += 1;
    }
    best
}

/// `wrench_many` of the step columns `[h, hdot, vx, vy, omega]` into the output columns
/// `[N, Fx, Fy, Tz, a, b, e2]`.
fn wrench_cols<T: BatchReal>(c: &Fixed<T>, cols: [&[T]; 5], out: [&mut [T]; 7]) {
    let [h, hdot, vx, vy, omega] = cols;
    let [n, fx, fy, tz, a, b, e2] = out;
    let steps = Steps {
        h,
        hdot,
        vx,
        vy,
        omega,
    };
    let mut wrenches = Wrenches {
        n,
        fx,
        fy,
        tz,
        a,
        b,
        e2,
    };
    c.wrench_many(&steps, &mut wrenches).unwrap();
}

/// Rows of `cols` split in `k` chunks over `k` threads (k = 1: on this thread).
fn threaded<T: BatchReal + Send + Sync>(
    c: &Fixed<T>,
    cols: &[Vec<T>; 5],
    out: &mut [Vec<T>; 7],
    k: usize,
) {
    let n = cols[0].len();
    if k == 1 {
        wrench_cols(
            c,
            cols.each_ref().map(|c| &c[..]),
            out.each_mut().map(|c| &mut c[..]),
        );
        return;
    }
    let mut outs: Vec<[&mut [T]; 7]> = Vec::new();
    let mut rest: [&mut [T]; 7] = out.each_mut().map(|c| &mut c[..]);
    for i in 0..k {
        let len = (i + 1) * n / k - i * n / k;
        let (head, tail): (Vec<_>, Vec<_>) = rest.map(|c| c.split_at_mut(len)).into_iter().unzip();
        outs.push(head.try_into().unwrap());
        rest = tail.try_into().unwrap();
    }
    std::thread::scope(|s| {
        for (i, o) in outs.into_iter().enumerate() {
            let r = i * n / k..(i + 1) * n / k;
            s.spawn(move || wrench_cols(c, cols.each_ref().map(|c| &c[r.clone()]), o));
        }
    });
}

fn measure<T: BatchReal + Send + Sync>(csv: &mut String, series: &mut Vec<plot::Series>) {
    let c = contact::<T>();
    let sizes = [1_000usize, 10_000, 100_000, 1_000_000, 10_000_000];
    let [_, _, all @ ..] = columns::<T>(*sizes.last().unwrap());
    let (mut scalar_pts, mut batch_pts, mut two_pts) = (vec![], vec![], vec![]);
    for &n in &sizes {
        let cols: [Vec<T>; 5] = all.each_ref().map(|c| c[..n].to_vec());
        let mut out: [Vec<T>; 7] = std::array::from_fn(|_| vec![T::ZERO; n]);
        let ts = time(|| {
            for i in 0..n {
                let w = c.wrench(
                    cols[0][i],
                    cols[1][i],
                    Slip::new(cols[2][i], cols[3][i], cols[4][i]).unwrap(),
                );
                let row = [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2];
                for (o, v) in out.iter_mut().zip(row) {
                    o[i] = v;
                }
            }
            black_box(&mut out);
        });
        let tb = time(|| {
            threaded(&c, &cols, &mut out, 1);
            black_box(&mut out);
        });
        let t2 = time(|| {
            threaded(&c, &cols, &mut out, 2);
            black_box(&mut out);
        });
        for (path, threads, t, pts) in [
            ("scalar", 1, ts, &mut scalar_pts),
            ("batch", 1, tb, &mut batch_pts),
            ("batch", 2, t2, &mut two_pts),
        ] {
            let _ = writeln!(
                csv,
                "{},{path},{threads},{n},{:.2},{:.4e}",
                T::NAME,
                t / n as f64 * 1e9,
                n as f64 / t
            );
            pts.push((n as f64, n as f64 / t));
        }
        eprintln!(
            "{} {n}: scalar {:.1} ns, batch {:.1} ns, batch ×2 threads {:.1} ns",
            T::NAME,
            ts / n as f64 * 1e9,
            tb / n as f64 * 1e9,
            t2 / n as f64 * 1e9
        );
    }
    series.push((format!("{} scalar loop", T::NAME), scalar_pts));
    series.push((format!("{} batch", T::NAME), batch_pts));
    series.push((format!("{} batch, 2 threads", T::NAME), two_pts));
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut csv = String::from("precision,path,threads,rows,ns_per_contact,contacts_per_s\n");
    let mut series = Vec::new();
    measure::<f32>(&mut csv, &mut series);
    measure::<f64>(&mut csv, &mut series);
    std::fs::write(root.join("bench-results/batch-scaling.csv"), csv)?;
    let dir = root.join("docs/report/batch");
    std::fs::create_dir_all(&dir)?;
    plot::register();
    plot::lines(
        &dir.join("scaling.png"),
        &format!(
            "best, fixed: contacts/s against rows (level {}, {} threads available)",
            batch::level().name(),
            std::thread::available_parallelism().map_or(1, |n| n.get())
        ),
        plot::Axis {
            title: "rows per call",
            log: true,
        },
        plot::Axis {
            title: "contacts per second",
            log: true,
        },
        &series,
        false,
    )?;
    Ok(())
}
