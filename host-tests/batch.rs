//! The batch path (src/batch/) against the scalar call, bit for bit: every law × form ×
//! precision × vector level available on this machine, on 100,003 rows (not a multiple of any
//! lane count, so the scalar tail runs too) mixing ordinary states, the extremes of
//! host-tests/extremes.rs (subnormal approaches and spins, huge and tiny slip speeds, rest,
//! pure spin, pure translation), slips straddling the regularization speed δ, and slips on
//! both sides of `best`'s inside/outside switch (the ellipse x² + m₁y² = m₁w², as in
//! host-tests/best_switch) within a few ulps.

use contensou::Error;
use contensou::Real;
use contensou::batch::{
    self, BatchDamping, BatchLaw, BatchReal, CurvatureColumns, Level, RowError, Steps, Wrenches,
};
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::{Best, Coulomb, Ellipsoid, Friction, Pade, Simplified, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::{CompressionDamping, Hertz, HuntCrossley, Modulus, Undamped};
use contensou::shape::Newton;

/// 100,003 rows in release (the CI step `cargo test --release --test batch`); 10,007 in a debug
/// build (`cargo test`), where the vector intrinsics are not inlined.
const ROWS: usize = if cfg!(debug_assertions) {
    10_007
} else {
    100_003
};

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

impl Rng {
    fn pick<X: Copy>(&mut self, xs: &[X]) -> X {
        xs[(self.bits() % xs.len() as u64) as usize]
    }
    /// ± 10^[lo, hi], sometimes 0.
    fn magnitude(&mut self, lo: f64, hi: f64) -> f64 {
        if self.next() < 0.1 {
            return 0.0;
        }
        let s = if self.next() < 0.5 { -1.0 } else { 1.0 };
        s * 10f64.powf(lo + (hi - lo) * self.next())
    }
}

/// The input columns (f64; converted per precision) and a per-row scale a/√h hint.
struct Rows {
    p: Vec<f64>,
    q: Vec<f64>,
    h: Vec<f64>,
    hdot: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    omega: Vec<f64>,
}

/// `a` of the contact at h (the major semi-axis), to place slips relative to aω.
fn rows<T: Real>(a_of: impl Fn(f64, f64, f64) -> (f64, f64), fixed: (f64, f64)) -> Rows {
    let mut r = Rng(0x9e37_79b9_7f4a_7c15 ^ T::MANTISSA_DIGITS as u64);
    let (tiny_h, tiny_w, huge) = if T::MANTISSA_DIGITS > 24 {
        (1e-310, 1e-310, 1e300)
    } else {
        (1e-40, 1e-40, 1e30)
    };
    let mut out = Rows {
        p: vec![],
        q: vec![],
        h: vec![],
        hdot: vec![],
        vx: vec![],
        vy: vec![],
        omega: vec![],
    };
    for i in 0..ROWS {
        let (p, q) = if i % 3 == 0 {
            fixed
        } else {
            let q = 10f64.powf(1.0 + 2.0 * r.next());
            let g = if r.next() < 0.5 {
                r.pick(&[1.0, 1.001e-4, 0.5, 0.0274])
            } else {
                10f64.powf(-3.99 * r.next())
            };
            (q * g, q)
        };
        let h = match r.bits() % 10 {
            0 => -r.next() * 1e-6,
            1 => 0.0,
            2 => r.pick(&[tiny_h, 1e-15, 1e-12, huge]),
            _ => 10f64.powf(-9.0 + 5.0 * r.next()),
        };
        let m = r.magnitude(-6.0, 1.0);
        let hdot = r.pick(&[0.0, 0.0, m, -1e3, 1e3]);
        let (a, m1) = a_of(p, q, h);
        let kind = r.bits() % 8;
        let (vx, vy, omega) = match kind {
            // the inside/outside switch of `best`: ρ = 1 ± a few ulps on x² + m₁y² = m₁w²
            0 | 1 if a > 0.0 => {
                let omega = r.magnitude(-2.0, 3.0);
                let rho = 1.0 + r.pick(&[0.0, 1e-16, -1e-16, 6e-8, -6e-8, 1e-3, -1e-3]);
                let th = std::f64::consts::TAU * r.next();
                let aw = a * omega;
                (rho * aw * th.cos(), rho * aw * m1.sqrt() * th.sin(), omega)
            }
            // around δ = 1e-4 m/s
            2 => {
                let s = 1e-4 * (1.0 + r.pick(&[0.0, 1e-7, -1e-7, 0.5, -0.5, -0.999]));
                let th = std::f64::consts::TAU * r.next();
                (
                    s * th.cos() * 0.5,
                    s * th.sin() * 0.5,
                    if a > 0.0 {
                        0.5 * s / a * r.pick(&[0.0, 1.0, 0.1])
                    } else {
                        0.0
                    },
                )
            }
            // extremes
            3 => (
                r.pick(&[0.0, tiny_w, -tiny_w, huge, 1e-20]),
                r.pick(&[0.0, tiny_w, huge, -1e-20]),
                r.pick(&[0.0, tiny_w, -tiny_w, huge, 100.0, -3.0]),
            ),
            // rest, pure spin, pure translation
            4 => r.pick(&[
                (0.0, 0.0, 0.0),
                (0.0, 0.0, 50.0),
                (0.01, 0.0, 0.0),
                (0.0, -0.02, 0.0),
            ]),
            _ => (
                r.magnitude(-8.0, 1.0),
                r.magnitude(-8.0, 1.0),
                r.magnitude(-3.0, 4.0),
            ),
        };
        for (col, v) in [
            (&mut out.p, p),
            (&mut out.q, q),
            (&mut out.h, h),
            (&mut out.hdot, hdot),
            (&mut out.vx, vx),
            (&mut out.vy, vy),
            (&mut out.omega, omega),
        ] {
            col.push(v);
        }
    }
    out
}

fn cast<T: Real>(v: &[f64]) -> Vec<T> {
    v.iter().map(|&x| T::from_f64(x)).collect()
}

/// The step columns h, ḣ, v_x, v_y, ω as the batch path's [`Steps`].
fn steps_of<T>(c: &[Vec<T>; 5]) -> Steps<'_, T> {
    let [h, hdot, vx, vy, omega] = c;
    Steps {
        h,
        hdot,
        vx,
        vy,
        omega,
    }
}

impl Rows {
    /// The step columns h, ḣ, v_x, v_y, ω in precision `T`.
    fn step_columns<T: Real>(&self) -> [Vec<T>; 5] {
        [&self.h, &self.hdot, &self.vx, &self.vy, &self.omega].map(|c| cast::<T>(c))
    }
}

/// The level cap is process-wide and the tests run on parallel threads: each level's batch call
/// holds this lock, so that it runs at the level it names.
static LEVEL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn levels() -> Vec<Level> {
    let best = {
        let _held = LEVEL.lock().unwrap_or_else(|e| e.into_inner());
        batch::cap_level(Level::Avx2);
        batch::level()
    };
    [Level::Scalar, Level::Sse2, Level::Avx2]
        .into_iter()
        .filter(|&l| l <= best)
        .collect()
}

fn bits<T: Real>(x: T) -> u64 {
    x.to_f64().to_bits()
}

/// Compares one batch output against the scalar rows; panics on the first differing bit.
fn compare<T: Real>(what: &str, out: &[Vec<T>; 7], scalar: &[[T; 7]]) {
    let names = ["N", "Fx", "Fy", "Tz", "a", "b", "e2"];
    for (i, row) in scalar.iter().enumerate() {
        for (c, name) in names.iter().enumerate() {
            let (b, s) = (out[c][i], row[c]);
            assert!(
                bits(b) == bits(s),
                "{what}: row {i} column {name}: batch {b:?} != scalar {s:?}"
            );
        }
    }
}

fn outputs<T: Real>(n: usize) -> [Vec<T>; 7] {
    core::array::from_fn(|_| vec![T::from_f64(-7.0); n])
}

fn wrenches<T>(o: &mut [Vec<T>; 7]) -> Wrenches<'_, T> {
    let [n, fx, fy, tz, a, b, e2] = o;
    Wrenches {
        n,
        fx,
        fy,
        tz,
        a,
        b,
        e2,
    }
}

fn fixed_case<T: Real + BatchReal, D: BatchDamping<T> + Copy, L: BatchLaw>(
    name: &str,
    p: f64,
    q: f64,
    damping: D,
    delta: f64,
) -> usize {
    let curv = Curvatures::ordered(T::from_f64(p), T::from_f64(q)).unwrap();
    let c: Contact<T, Hertz<T>, D, L> = Contact::hertz::<Newton>(
        &curv,
        Modulus::new(T::from_f64(1.15e11)).unwrap(),
        damping,
        Friction::with_law(T::from_f64(0.3), T::from_f64(delta)).unwrap(),
    )
    .unwrap();
    let (a1, m1) = {
        let w = c.wrench(T::ONE, T::ZERO, Slip::default());
        (w.patch.a.to_f64(), w.patch.m1.to_f64())
    };
    let r = rows::<T>(
        |_, _, h| (if h > 0.0 { a1 * h.sqrt() } else { 0.0 }, m1),
        (p, q),
    );
    let cols = r.step_columns::<T>();
    let [h, hdot, vx, vy, omega] = &cols;
    let mut branches = std::collections::BTreeMap::<String, usize>::new();
    let scalar: Vec<[T; 7]> = (0..ROWS)
        .map(|i| {
            let w = c.wrench(h[i], hdot[i], Slip::new(vx[i], vy[i], omega[i]).unwrap());
            if w.n > T::ZERO {
                *branches.entry(format!("{:?}", w.branch)).or_default() += 1;
            }
            [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
        })
        .collect();
    // The rows reach every branch of the law in contact, each on ≥ 0.1 % of the rows.
    let least = if L::NAME == "simplified" {
        2
    } else {
        ROWS / 1000
    };
    let wanted = match L::NAME {
        "best" | "coulomb" => 3,
        "simplified" => 5,
        _ => 2,
    };
    let common = branches.values().filter(|&&n| n >= least).count();
    assert!(
        common >= wanted,
        "{name} P={p} Q={q} δ={delta}: branches {branches:?}"
    );
    let steps = steps_of(&cols);
    for level in levels() {
        let _held = LEVEL.lock().unwrap_or_else(|e| e.into_inner());
        batch::cap_level(level);
        assert_eq!(batch::level(), level);
        let mut out = outputs::<T>(ROWS);
        c.wrench_many(&steps, &mut wrenches(&mut out)).unwrap();
        compare(
            &format!("fixed {name} {} {:?} P={p} Q={q} δ={delta}", T::NAME, level),
            &out,
            &scalar,
        );
    }
    ROWS
}

fn varying_case<T: Real + BatchReal, L: BatchLaw>(name: &str, delta: f64) -> usize {
    let c: VaryingContact<T, HuntCrossley<T>, L> = VaryingContact::new(
        Modulus::new(T::from_f64(1.15e11)).unwrap(),
        HuntCrossley::new(T::from_f64(0.5)).unwrap(),
        Friction::with_law(T::from_f64(0.3), T::from_f64(delta)).unwrap(),
    );
    let r = rows::<T>(
        |p, q, h| {
            let curv = Curvatures::ordered(T::from_f64(p), T::from_f64(q)).unwrap();
            let w = c.wrench(&curv, T::from_f64(h), T::ZERO, Slip::default());
            (w.patch.a.to_f64(), w.patch.m1.to_f64())
        },
        (40.0, 60.0),
    );
    let (p, q) = (cast::<T>(&r.p), cast::<T>(&r.q));
    let cols = r.step_columns::<T>();
    let [h, hdot, vx, vy, omega] = &cols;
    let scalar: Vec<[T; 7]> = (0..ROWS)
        .map(|i| {
            let curv = Curvatures::ordered(p[i], q[i]).unwrap();
            let w = c.wrench(
                &curv,
                h[i],
                hdot[i],
                Slip::new(vx[i], vy[i], omega[i]).unwrap(),
            );
            [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
        })
        .collect();
    let steps = steps_of(&cols);
    let curvatures = CurvatureColumns { p: &p, q: &q };
    for level in levels() {
        let _held = LEVEL.lock().unwrap_or_else(|e| e.into_inner());
        batch::cap_level(level);
        assert_eq!(batch::level(), level);
        let mut out = outputs::<T>(ROWS);
        c.wrench_many(&curvatures, &steps, &mut wrenches(&mut out))
            .unwrap();
        compare(
            &format!("varying {name} {} {:?} δ={delta}", T::NAME, level),
            &out,
            &scalar,
        );
    }
    ROWS
}

fn every_law<T: Real + BatchReal>() {
    let hc = HuntCrossley::new(T::from_f64(0.5)).unwrap();
    let mut rows = 0;
    macro_rules! law {
        ($l:ty) => {
            for (p, q) in [(40.0, 40.0), (40.0, 60.0), (1.0, 100.0)] {
                for delta in [0.0, 1e-4] {
                    rows += fixed_case::<T, _, $l>(stringify!($l), p, q, hc, delta);
                }
            }
            rows += fixed_case::<T, _, $l>(stringify!($l), 40.0, 60.0, Undamped, 1e-4);
            rows += fixed_case::<T, _, $l>(
                stringify!($l),
                40.0,
                60.0,
                CompressionDamping::new(T::from_f64(1e3)).unwrap(),
                1e-4,
            );
            for delta in [0.0, 1e-4] {
                rows += varying_case::<T, $l>(stringify!($l), delta);
            }
        };
    }
    law!(Best);
    // BestContact's thin series and 12 pieces (m₁ < 0.01; P/Q = 0.01 above is one too): a
    // patch near the contract's end (P/Q = 1e-4, m₁ ≈ 2e-5)
    rows += fixed_case::<T, _, Best>("Best", 1.0, 9000.0, hc, 1e-4);
    law!(Simplified);
    law!(Pade);
    law!(Ellipsoid);
    law!(Coulomb);
    assert!(rows >= 5 * 10 * ROWS);
}

#[test]
fn batch_equals_scalar_f32() {
    every_law::<f32>();
}

#[test]
fn batch_equals_scalar_f64() {
    every_law::<f64>();
}

#[test]
fn the_first_bad_row_is_reported_and_rows_before_it_written() {
    let c = VaryingContact::new(
        Modulus::new(1.15e11).unwrap(),
        Undamped,
        Friction::<f64>::new(0.1, 1e-4).unwrap(),
    );
    let n = 37;
    let ones = vec![1e-6; n];
    let q = vec![60.0; n];
    let mut p = vec![40.0; n];
    p[30] = 70.0; // P > Q
    let mut omega = vec![3.0; n];
    omega[21] = f64::NAN;
    let mut fixed_omega = omega.clone();
    fixed_omega[21] = 3.0;
    // The call on columns P (with its bad row 30), `omega` and the outputs `out`.
    let call = |omega: &[f64], out: &mut [Vec<f64>; 7]| {
        let (h, curvatures) = (&ones[..], CurvatureColumns { p: &p, q: &q });
        let steps = Steps {
            h,
            hdot: h,
            vx: h,
            vy: h,
            omega,
        };
        c.wrench_many(&curvatures, &steps, &mut wrenches(out))
            .unwrap_err()
    };
    for level in levels() {
        let _held = LEVEL.lock().unwrap_or_else(|e| e.into_inner());
        batch::cap_level(level);
        assert_eq!(batch::level(), level);
        let mut out = outputs::<f64>(n);
        let e = call(&omega, &mut out);
        let nan = RowError {
            row: 21,
            column: "omega",
            error: Error::NonFinite("omega"),
        };
        assert_eq!(e, nan);
        assert!(out[0][..21].iter().all(|&x| x > 0.0), "{level:?}");
        assert_eq!(out[0][21], -7.0);
        let e = call(&fixed_omega, &mut out);
        assert_eq!(
            (e.row, e.column, e.error),
            (30, "P", Error::CurvaturesNotOrdered)
        );
        // a short output column: nothing written
        let mut short = outputs::<f64>(n);
        short[5].pop();
        let e = call(&fixed_omega, &mut short);
        assert_eq!(
            (e.row, e.column, e.error),
            (n - 1, "b", Error::ColumnLengthMismatch)
        );
        assert!(short[0].iter().all(|&x| x == -7.0));
    }
}

/// `DynContact::wrench_many` (the shells' path) against `DynContact::wrench`, every law and
/// form (the varying form at the contact's own curvatures: `wrench_many_at`).
fn dynamic_case<T: Real + BatchReal>() {
    use contensou::dynamic::{DynContact, Form, Law, Spec, Step};
    let spec = Spec {
        p: T::from_f64(40.0),
        q: T::from_f64(60.0),
        estar: T::from_f64(1.15e11),
        cd: T::from_f64(0.5),
        f: T::from_f64(0.3),
        delta: T::from_f64(1e-4),
    };
    for law in Law::ALL {
        for form in Form::ALL {
            let c = DynContact::new(&spec, law, form).unwrap();
            let a1 = c
                .wrench(&Step {
                    h: T::ONE,
                    ..Default::default()
                })
                .unwrap()
                .a
                .to_f64();
            let r = rows::<T>(
                |_, _, h| (if h > 0.0 { a1 * h.sqrt() } else { 0.0 }, 0.6),
                (40.0, 60.0),
            );
            let cols = [&r.h, &r.hdot, &r.vx, &r.vy, &r.omega].map(|c| cast::<T>(c));
            let [h, hdot, vx, vy, omega] = &cols;
            let scalar: Vec<[T; 7]> = (0..ROWS)
                .map(|i| {
                    let s = Step {
                        h: h[i],
                        hdot: hdot[i],
                        vx: vx[i],
                        vy: vy[i],
                        omega: omega[i],
                    };
                    c.wrench(&s).unwrap().to_array()
                })
                .collect();
            let steps = Steps {
                h,
                hdot,
                vx,
                vy,
                omega,
            };
            let mut out = outputs::<T>(ROWS);
            {
                let _held = LEVEL.lock().unwrap_or_else(|e| e.into_inner());
                batch::cap_level(Level::Avx2);
                c.wrench_many(&steps, &mut wrenches(&mut out)).unwrap();
            }
            compare(
                &format!("dynamic {} {} {}", law.name(), form.name(), T::NAME),
                &out,
                &scalar,
            );
        }
    }
}

#[test]
fn dynamic_batch_equals_dynamic_rows() {
    dynamic_case::<f32>();
    dynamic_case::<f64>();
}
