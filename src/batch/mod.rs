//! Many contacts per call: the wrench of N rows from structure-of-arrays columns, several
//! rows per instruction in SIMD lanes, every result bit for bit the scalar call's.
//!
//! [`Contact::wrench_many`] (a fixed contact: one geometry, N steps) and
//! [`VaryingContact::wrench_many`] (one contact, a curvature pair per row) take the input
//! columns `h, hdot, vx, vy, omega` ([`Steps`], plus `P, Q` for the varying form:
//! [`CurvatureColumns`]) and fill the output columns `N, Fx, Fy, Tz, a, b, e2` ([`Wrenches`]),
//! for every friction law ([`BatchLaw`]: `best`, `simplified`, `pade`, `ellipsoid`, `coulomb`)
//! and the damping laws [`Undamped`](crate::normal::Undamped),
//! [`HuntCrossley`](crate::normal::HuntCrossley) and
//! [`CompressionDamping`](crate::normal::CompressionDamping). No allocation; `no_std`.
//!
//! # Same answers
//!
//! Row i of the output is **bit for bit** `contact.wrench(h[i], hdot[i], Slip::new(vx[i],
//! vy[i], omega[i])?)` (or the varying contact's call at `Curvatures::ordered(P[i], Q[i])`):
//! each law's kernel (src/batch/laws.rs, best.rs) is its scalar code with every branch made a
//! select over the lanes (inside/outside the ellipse, the table pieces, the rest and ramp
//! cases, the plateau/hyperbola of the torque), the same IEEE operations in the same order,
//! no fused multiply-add, no approximate reciprocal. Checked over every law × form ×
//! precision × vector level on 10⁵+ rows with the extremes and the branch switches
//! (`host-tests/batch.rs`).
//!
//! # Validation
//!
//! Every column must have `h`'s length ([`Error::ColumnLengthMismatch`], naming the first
//! column that differs). A non-finite input stops the call at its row: rows before it are
//! written, the error ([`RowError`]) names the row and the column (`P`, `Q`, `h`, `hdot`,
//! `vx`, `vy`, `omega`: the order of [`crate::dynamic::INPUTS`]); curvatures are checked as
//! [`crate::dynamic`] checks them (ordered, P/Q ≥ 1e-4, never clamped).
//!
//! # Lanes
//!
//! On x86-64: AVX2 (8 × f32, 4 × f64) where the CPU and OS have it, detected at run time
//! (CPUID + XGETBV, no `std`), else SSE2 (4 × f32, 2 × f64, the x86-64 baseline), through
//! `core::arch`; elsewhere (thumbv7em included) one lane, the same kernels. The rows past the
//! last full vector go through the scalar call. [`level`] says which is used;
//! [`cap_level`] lowers it (tests, benchmarks).
//!
//! Why `core::arch` and not a portable-SIMD crate: `wide` picks its instructions at compile
//! time from the target features (a default x86-64 build gets SSE2 only, no run-time AVX);
//! `pulp` and `macerator` dispatch at run time, but this crate needs a handful of operations
//! (add, mul, div, sqrt, compares, selects, sign bits) whose exact IEEE semantics matter more
//! than breadth, and `pulp`'s `max`/`min` follow the instruction's NaN and ±0 rules (not
//! [`crate::Real::max`]'s), so every kernel would still wrap them; the crate would take a
//! dependency (and for `pulp`, `std` by default) for a 200-line module.
//!
//! # Example
//!
//! ```
//! use contensou::batch::{Steps, Wrenches};
//! use contensou::contact::Contact;
//! use contensou::friction::{Friction, Slip};
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::shape::Newton;
//!
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::new(40.0, 60.0)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::<f64>::new(0.1, 1e-4)?,
//! )?;
//! let h = [1e-6, 2e-6, -1e-6, 5e-7, 1e-6];
//! let (hdot, vx, vy, omega) = ([0.0; 5], [0.01; 5], [0.0, 0.01, 0.0, -0.02, 0.0], [50.0; 5]);
//! let mut out = [[0.0; 5]; 7];
//! let [n, fx, fy, tz, a, b, e2] = &mut out;
//! let steps = Steps { h: &h, hdot: &hdot, vx: &vx, vy: &vy, omega: &omega };
//! contact.wrench_many(&steps, &mut Wrenches { n, fx, fy, tz, a, b, e2 }).unwrap();
//! let one = contact.wrench(h[3], 0.0, Slip::new(vx[3], vy[3], omega[3])?);
//! assert_eq!((out[0][3], out[1][3], out[3][3]), (one.n, one.fx, one.tz)); // bit for bit
//! assert_eq!(out[0][2], 0.0); // apart
//! # Ok::<(), contensou::Error>(())
//! ```

mod best;
mod dyn_contact;
mod lanes;
mod laws;
mod normal;
mod state;
#[cfg(target_arch = "x86_64")]
mod x86;

use core::sync::atomic::{AtomicU8, Ordering};

use crate::contact::{Contact, VaryingContact};
use crate::dynamic::Output;
use crate::friction::{Best, Constants, Coulomb, Ellipsoid, FrictionLaw, Pade, Simplified, Slip};
use crate::geometry::Curvatures;
use crate::normal::{Hertz, Modulus};
use crate::shape::{self, Eccentricity, Ratio};
use crate::{Error, Real};
use lanes::{Lanes, MAX_LANES, One};
pub use normal::BatchDamping;
use state::{State, Tr, ramp, scaled};

/// The input columns of a batch (every slice the same length; see the [module docs](self)).
#[derive(Clone, Copy, Debug)]
pub struct Steps<'a, T> {
    /// Approach h (m; ≤ 0 apart).
    pub h: &'a [T],
    /// ḣ (m/s; > 0 compression).
    pub hdot: &'a [T],
    /// v_Px (m/s), along the major axis.
    pub vx: &'a [T],
    /// v_Py (m/s).
    pub vy: &'a [T],
    /// ω (rad/s) about the normal.
    pub omega: &'a [T],
}

/// The per-row curvatures of [`VaryingContact::wrench_many`]: P ≤ Q (1/m), as
/// [`Curvatures::ordered`].
#[derive(Clone, Copy, Debug)]
pub struct CurvatureColumns<'a, T> {
    /// P (1/m), 0 < P ≤ Q.
    pub p: &'a [T],
    /// Q (1/m).
    pub q: &'a [T],
}

/// The output columns (each as long as the inputs).
#[derive(Debug)]
pub struct Wrenches<'a, T> {
    /// N (N).
    pub n: &'a mut [T],
    /// F_x (N).
    pub fx: &'a mut [T],
    /// F_y (N).
    pub fy: &'a mut [T],
    /// T_z (N·m).
    pub tz: &'a mut [T],
    /// a (m).
    pub a: &'a mut [T],
    /// b (m).
    pub b: &'a mut [T],
    /// e² of the patch.
    pub e2: &'a mut [T],
}

/// A rejected batch: the row, the column and why (rows before `row` are written).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RowError {
    /// The first bad row (for [`Error::ColumnLengthMismatch`], the shorter length).
    pub row: usize,
    /// The column ([`crate::dynamic::INPUTS`] names, or an output name for a length).
    pub column: &'static str,
    /// Why.
    pub error: Error,
}

/// The vector level of the batch kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// One lane (every target without vectors, thumbv7em included).
    Scalar,
    /// x86-64 SSE2: 4 × f32, 2 × f64.
    Sse2,
    /// x86-64 AVX2: 8 × f32, 4 × f64.
    Avx2,
}

impl Level {
    /// `"scalar"`, `"sse2"`, `"avx2"`.
    pub fn name(self) -> &'static str {
        match self {
            Level::Scalar => "scalar",
            Level::Sse2 => "sse2",
            Level::Avx2 => "avx2",
        }
    }
}

static CAP: AtomicU8 = AtomicU8::new(u8::MAX);

/// The level the batch calls use: the best this CPU has, at most [`cap_level`]'s.
pub fn level() -> Level {
    let found = detected();
    match found.min(CAP.load(Ordering::Relaxed)) {
        0 => Level::Scalar,
        1 => Level::Sse2,
        _ => Level::Avx2,
    }
}

/// Lowers (or, with [`Level::Avx2`], restores) the level for every later batch call of the
/// process: for tests and benchmarks comparing the levels. Results do not change with it.
pub fn cap_level(cap: Level) {
    CAP.store(cap as u8, Ordering::Relaxed);
}

#[cfg(target_arch = "x86_64")]
fn detected() -> u8 {
    x86::level()
}

#[cfg(not(target_arch = "x86_64"))]
fn detected() -> u8 {
    0
}

mod sealed {
    /// Only this crate implements the batch traits.
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
    impl Sealed for crate::friction::Best {}
    impl Sealed for crate::friction::Simplified {}
    impl Sealed for crate::friction::Pade {}
    impl Sealed for crate::friction::Ellipsoid {}
    impl Sealed for crate::friction::Coulomb {}
    impl Sealed for crate::normal::Undamped {}
    impl<T> Sealed for crate::normal::HuntCrossley<T> {}
    impl<T> Sealed for crate::normal::CompressionDamping<T> {}
}

/// A kernel over the lanes of one precision: runs full vectors from row 0 and returns the
/// first row it did not do (the end of the last full vector, or the start of a vector holding
/// an input the scalar path must report).
pub trait Kernel<T> {
    /// Run with lanes `V`.
    fn run<V: Lanes<T = T>>(self) -> usize;
}

/// `f32` or `f64`: the precisions with lane vectors.
pub trait BatchReal: Real + sealed::Sealed {
    /// Runs `k` at the current [`level`].
    #[doc(hidden)]
    fn dispatch<K: Kernel<Self>>(k: K) -> usize;
}

macro_rules! batch_real {
    ($t:ty, $sse:ident, $avx:ident, $avx_fn:ident) => {
        impl BatchReal for $t {
            #[inline]
            fn dispatch<K: Kernel<$t>>(k: K) -> usize {
                match level() {
                    Level::Scalar => k.run::<One<$t>>(),
                    #[cfg(target_arch = "x86_64")]
                    Level::Sse2 => k.run::<x86::$sse>(),
                    #[cfg(target_arch = "x86_64")]
                    // SAFETY: `level` returns Avx2 only when CPUID and XGETBV found AVX2.
                    #[allow(unsafe_code)]
                    Level::Avx2 => unsafe { $avx_fn(k) },
                    #[cfg(not(target_arch = "x86_64"))]
                    _ => k.run::<One<$t>>(),
                }
            }
        }

        /// The kernel compiled for AVX2.
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2")]
        fn $avx_fn<K: Kernel<$t>>(k: K) -> usize {
            k.run::<x86::$avx>()
        }
    };
}
batch_real!(f32, F32x4, F32x8, avx_f32);
batch_real!(f64, F64x2, F64x4, avx_f64);

/// A friction law with a lane form. Implemented for [`Best`], [`Simplified`], [`Pade`],
/// [`Ellipsoid`] and [`Coulomb`].
pub trait BatchLaw: FrictionLaw + sealed::Sealed {
    /// The per-contact form splatted over the lanes.
    #[doc(hidden)]
    type Fixed<V: Lanes>: Copy;
    /// Splat the per-contact form.
    #[doc(hidden)]
    fn fixed<V: Lanes>(p: &Self::Prepared<V::T>) -> Self::Fixed<V>;
    /// The core with the per-contact form (`traction_prepared`).
    #[doc(hidden)]
    fn traction_fixed<V: Lanes>(p: &Self::Fixed<V>, s: &State<V>) -> Tr<V>;
    /// The core with each lane's constants (`traction`; `k` has `V::N` rows).
    #[doc(hidden)]
    fn traction_varying<V: Lanes>(k: &[Constants<V::T>], s: &State<V>) -> Tr<V>;
}

macro_rules! constants_law {
    ($law:ty, |$k:ident, $s:ident| $body:expr) => {
        impl BatchLaw for $law {
            type Fixed<V: Lanes> = laws::Shape<V>;
            #[inline(always)]
            fn fixed<V: Lanes>(p: &Constants<V::T>) -> laws::Shape<V> {
                laws::Shape::splat(p)
            }
            #[inline(always)]
            fn traction_fixed<V: Lanes>($k: &laws::Shape<V>, $s: &State<V>) -> Tr<V> {
                $body
            }
            #[inline(always)]
            fn traction_varying<V: Lanes>(k: &[Constants<V::T>], $s: &State<V>) -> Tr<V> {
                let $k = &laws::Shape::<V>::of_lanes(k);
                $body
            }
        }
    };
}
constants_law!(Simplified, |k, s| laws::simplified(k, s));
constants_law!(Pade, |k, s| laws::pade(k, s));
constants_law!(Ellipsoid, |k, s| laws::ellipsoid(k, s));
constants_law!(Coulomb, |_k, s| laws::coulomb(s));

impl BatchLaw for Best {
    type Fixed<V: Lanes> = best::Fixed<V>;
    #[inline(always)]
    fn fixed<V: Lanes>(p: &crate::friction::BestContact<V::T>) -> best::Fixed<V> {
        best::Fixed::new(p)
    }
    #[inline(always)]
    fn traction_fixed<V: Lanes>(p: &best::Fixed<V>, s: &State<V>) -> Tr<V> {
        best::fixed(p, s)
    }
    #[inline(always)]
    fn traction_varying<V: Lanes>(k: &[Constants<V::T>], s: &State<V>) -> Tr<V> {
        best::varying(k, s)
    }
}

/// The names of the step columns, in contract order.
const STEP_COLUMNS: [&str; 5] = ["h", "hdot", "vx", "vy", "omega"];
/// The names of the output columns.
const OUTPUT_COLUMNS: [&str; 7] = ["N", "Fx", "Fy", "Tz", "a", "b", "e2"];

/// Every column as long as `h`.
fn check_lengths<T>(
    curvatures: Option<&CurvatureColumns<'_, T>>,
    steps: &Steps<'_, T>,
    out: &Wrenches<'_, T>,
) -> Result<usize, RowError> {
    let n = steps.h.len();
    let inputs = [steps.h, steps.hdot, steps.vx, steps.vy, steps.omega];
    let outputs = [
        out.n.len(),
        out.fx.len(),
        out.fy.len(),
        out.tz.len(),
        out.a.len(),
        out.b.len(),
        out.e2.len(),
    ];
    // curvatures absent: their lengths read as n (no error)
    let curv = curvatures.map_or([("P", n), ("Q", n)], |c| {
        [("P", c.p.len()), ("Q", c.q.len())]
    });
    let ins = [
        (STEP_COLUMNS[0], inputs[0].len()),
        (STEP_COLUMNS[1], inputs[1].len()),
        (STEP_COLUMNS[2], inputs[2].len()),
        (STEP_COLUMNS[3], inputs[3].len()),
        (STEP_COLUMNS[4], inputs[4].len()),
    ];
    let outs: [(&'static str, usize); 7] = core::array::from_fn(|k| {
        (
            OUTPUT_COLUMNS.get(k).copied().unwrap_or(""),
            outputs.get(k).copied().unwrap_or(n),
        )
    });
    // slices, not chained array iterators: no bounds-check panic path at any opt-level
    for list in [&curv[..], &ins[..], &outs[..]] {
        for &(column, len) in list {
            if len != n {
                return Err(RowError {
                    row: len.min(n),
                    column,
                    error: Error::ColumnLengthMismatch,
                });
            }
        }
    }
    Ok(n)
}

/// Row i's step columns, validated as [`crate::dynamic::DynContact::wrench`] does.
#[inline]
fn step_row<T: Real>(steps: &Steps<'_, T>, i: usize) -> Result<(T, T, Slip<T>), RowError> {
    let get = |c: &[T]| c.get(i).copied().unwrap_or(T::ZERO);
    let values = [
        get(steps.h),
        get(steps.hdot),
        get(steps.vx),
        get(steps.vy),
        get(steps.omega),
    ];
    for (column, v) in STEP_COLUMNS.into_iter().zip(values) {
        if !v.is_finite() {
            return Err(RowError {
                row: i,
                column,
                error: Error::NonFinite(column),
            });
        }
    }
    let [h, hdot, vx, vy, omega] = values;
    let slip = Slip::new(vx, vy, omega).map_err(|error| RowError {
        row: i,
        column: "vx",
        error,
    })?;
    Ok((h, hdot, slip))
}

/// Writes row i of the outputs.
#[inline]
pub(crate) fn put<T: Copy>(out: &mut Wrenches<'_, T>, i: usize, row: impl Into<Output<T>>) {
    let row = row.into().to_array();
    let cols = [
        &mut *out.n,
        &mut *out.fx,
        &mut *out.fy,
        &mut *out.tz,
        &mut *out.a,
        &mut *out.b,
        &mut *out.e2,
    ];
    for (col, v) in cols.into_iter().zip(row) {
        if let Some(x) = col.get_mut(i) {
            *x = v;
        }
    }
}

/// The vector of rows `r..r + N` of a column (`None` past the end).
#[inline(always)]
fn load<V: Lanes>(col: &[V::T], r: usize) -> Option<V> {
    col.get(r..r.checked_add(V::N)?).map(V::load)
}

/// Stores a vector at rows `r..r + N`.
#[inline(always)]
fn store<V: Lanes>(v: V, col: &mut [V::T], r: usize) {
    if let Some(s) = r.checked_add(V::N).and_then(|e| col.get_mut(r..e)) {
        v.store(s);
    }
}

/// Loads the five step columns at row r, if they are all there and finite.
#[inline(always)]
fn load_steps<V: Lanes>(steps: &Steps<'_, V::T>, r: usize) -> Option<[V; 5]> {
    let v = [
        load::<V>(steps.h, r)?,
        load::<V>(steps.hdot, r)?,
        load::<V>(steps.vx, r)?,
        load::<V>(steps.vy, r)?,
        load::<V>(steps.omega, r)?,
    ];
    let max = V::splat(V::T::MAX);
    let finite = v.iter().fold(None, |acc: Option<V::Mask>, x| {
        let f = x.abs().le(max);
        Some(acc.map_or(f, |a| V::and(a, f)))
    })?;
    (!V::any(V::not(finite))).then_some(v)
}

/// Stores the seven outputs at row r.
#[inline(always)]
fn store_outputs<V: Lanes>(out: &mut Wrenches<'_, V::T>, r: usize, values: [V; 7]) {
    let [n, fx, fy, tz, a, b, e2] = values;
    store(n, out.n, r);
    store(fx, out.fx, r);
    store(fy, out.fy, r);
    store(tz, out.tz, r);
    store(a, out.a, r);
    store(b, out.b, r);
    store(e2, out.e2, r);
}

/// The dimensional friction (F_x, F_y, T_z) = fN·(F̂_x, F̂_y, a·T̂_z).
#[inline(always)]
fn dimensional<V: Lanes>(fn_: V, a: V, t: Tr<V>) -> (V, V, V) {
    (fn_ * t.fx, fn_ * t.fy, fn_ * (a * t.tz))
}

/// The fixed-form kernel.
struct FixedKernel<'c, 'o, 'i, T: Real, D, L: FrictionLaw> {
    contact: &'c Contact<T, Hertz<T>, D, L>,
    steps: &'c Steps<'i, T>,
    out: &'c mut Wrenches<'o, T>,
}

impl<T: BatchReal, D: BatchDamping<T>, L: BatchLaw> Kernel<T> for FixedKernel<'_, '_, '_, T, D, L> {
    #[inline(always)]
    fn run<V: Lanes<T = T>>(self) -> usize {
        let c = self.contact;
        let hertz = normal::HertzLanes::<V>::splat(c.normal());
        let law = L::fixed::<V>(c.prepared());
        let f = V::splat(c.friction().coefficient());
        let delta = V::splat(c.friction().delta());
        let damping = c.damping();
        let mut r = 0;
        while let Some([h, hdot, vx, vy, omega]) = load_steps::<V>(self.steps, r) {
            let (a, b, n) = hertz.patch(damping, h, hdot);
            let sc = scaled([f, delta], a, n, [vx, vy, omega]);
            let t = L::traction_fixed(&law, &sc.state);
            let fn_ = ramp(L::RAMP_BELOW_DELTA, &sc, delta, &t);
            let (fx, fy, tz) = dimensional(fn_, a, t);
            store_outputs(self.out, r, [n, fx, fy, tz, a, b, hertz.e2]);
            r += V::N;
        }
        r
    }
}

impl<T: BatchReal, D: BatchDamping<T>, L: BatchLaw> Contact<T, Hertz<T>, D, L> {
    /// The wrench of every row of `steps` into `out` (see the [module docs](self)): row i is
    /// bit for bit `self.wrench(h[i], hdot[i], Slip::new(vx[i], vy[i], omega[i])?)`.
    ///
    /// Errors: [`Error::ColumnLengthMismatch`] (nothing written); [`Error::NonFinite`] at
    /// the first row with a NaN or ±∞ input, naming its column (rows before it written).
    pub fn wrench_many(
        &self,
        steps: &Steps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        let n = check_lengths(None, steps, out)?;
        let done = T::dispatch(FixedKernel {
            contact: self,
            steps,
            out: &mut *out,
        });
        for i in done..n {
            let (h, hdot, slip) = step_row(steps, i)?;
            let w = self.wrench(h, hdot, slip);
            put(out, i, w);
        }
        Ok(())
    }
}

/// One row's curvatures, validated as [`crate::dynamic`] validates them.
#[inline]
fn curvature_row<T: Real>(
    c: &CurvatureColumns<'_, T>,
    i: usize,
) -> Result<Curvatures<T>, RowError> {
    let get = |c: &[T]| c.get(i).copied().unwrap_or(T::ZERO);
    crate::dynamic::curvatures_of(get(c.p), get(c.q)).map_err(|e| RowError {
        row: i,
        column: e.column,
        error: e.error,
    })
}

/// Where a varying contact's rows take their curvatures from.
#[derive(Clone, Copy)]
enum Source<'c, 'i, T> {
    /// One pair per row.
    Columns(&'c CurvatureColumns<'i, T>),
    /// The same curvatures on every row.
    One(&'c Curvatures<T>),
}

/// The per-row work of `VaryingContact::wrench` before the patch: the shape by table, the
/// Hertz coefficients and the friction constants.
#[inline(always)]
fn varying_shape<T: Real>(curv: &Curvatures<T>, estar: Modulus<T>) -> ([T; 4], Constants<T>) {
    let shape = shape::Table::shape(Ratio::clamped(curv.ratio()));
    let hertz = Hertz::from_shape(curv, &shape, estar);
    (normal::coefficients(&hertz), Constants::from_shape(&shape))
}

/// Lane l of the per-lane Hertz coefficients and constants.
#[inline(always)]
fn set_lane<T: Real>(
    coef: &mut [[T; MAX_LANES]; 4],
    k: &mut [Constants<T>; MAX_LANES],
    l: usize,
    (c, kl): ([T; 4], Constants<T>),
) {
    for (col, v) in coef.iter_mut().zip(c) {
        if let Some(x) = col.get_mut(l) {
            *x = v;
        }
    }
    if let Some(x) = k.get_mut(l) {
        *x = kl;
    }
}

/// The varying-form kernel.
struct VaryingKernel<'c, 'o, 'i, T: Real, D, L> {
    contact: &'c VaryingContact<T, D, L>,
    curvatures: Source<'c, 'i, T>,
    steps: &'c Steps<'i, T>,
    out: &'c mut Wrenches<'o, T>,
}

impl<T: BatchReal, D: BatchDamping<T>, L: BatchLaw> Kernel<T>
    for VaryingKernel<'_, '_, '_, T, D, L>
{
    #[inline(always)]
    fn run<V: Lanes<T = T>>(self) -> usize {
        let (estar, damping, friction) = self.contact.parts();
        let f = V::splat(friction.coefficient());
        let delta = V::splat(friction.delta());
        // Per row (scalar, as VaryingContact::wrench): the shape by table, Hertz, constants;
        // once for a single pair.
        let mut coef = [[T::ZERO; MAX_LANES]; 4];
        let mut k = [Constants::circle(); MAX_LANES];

        if let Source::One(curv) = self.curvatures {
            let one = varying_shape(curv, estar);
            for l in 0..V::N {
                set_lane(&mut coef, &mut k, l, one);
            }
        }
        let mut r = 0;
        'rows: while let Some([h, hdot, vx, vy, omega]) = load_steps::<V>(self.steps, r) {
            if let Source::Columns(columns) = self.curvatures {
                for l in 0..V::N {
                    let Ok(curv) = curvature_row(columns, r + l) else {
                        break 'rows;
                    };
                    set_lane(&mut coef, &mut k, l, varying_shape(&curv, estar));
                }
            }
            let hertz = normal::HertzLanes::<V>::of(&coef);
            let (a, b, n) = hertz.patch(damping, h, hdot);
            let rows = k.get(..V::N).unwrap_or(&[]);
            let sc = scaled([f, delta], a, n, [vx, vy, omega]);
            let t = L::traction_varying(rows, &sc.state);
            let fn_ = ramp(L::RAMP_BELOW_DELTA, &sc, delta, &t);
            let (fx, fy, tz) = dimensional(fn_, a, t);
            store_outputs(self.out, r, [n, fx, fy, tz, a, b, hertz.e2]);
            r += V::N;
        }
        r
    }
}

impl<T: BatchReal, D: BatchDamping<T>, L: BatchLaw> VaryingContact<T, D, L> {
    /// The wrench of every row into `out`, row i at the curvatures (`P[i]`, `Q[i]`) (see the
    /// [module docs](self)): bit for bit `self.wrench(&Curvatures::ordered(P[i], Q[i])?,
    /// h[i], hdot[i], Slip::new(vx[i], vy[i], omega[i])?)`.
    ///
    /// Errors: [`Error::ColumnLengthMismatch`] (nothing written); at the first bad row (rows
    /// before it written), the curvatures' errors as [`crate::dynamic::DynContact::new`]
    /// reports them (`P`/`Q`: [`Error::NonFinite`], [`Error::CurvaturesNotOrdered`],
    /// [`Error::CurvatureNotPositive`], [`Error::CurvatureRatioOutOfRange`]) and
    /// [`Error::NonFinite`] naming a step column.
    pub fn wrench_many(
        &self,
        curvatures: &CurvatureColumns<'_, T>,
        steps: &Steps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        self.many(Source::Columns(curvatures), steps, out)
    }

    /// [`VaryingContact::wrench_many`] with the same curvatures on every row (the shape
    /// solved once): row i is bit for bit `self.wrench(curvatures, h[i], hdot[i], slip_i)`.
    /// Errors as [`Contact::wrench_many`].
    pub fn wrench_many_at(
        &self,
        curvatures: &Curvatures<T>,
        steps: &Steps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        self.many(Source::One(curvatures), steps, out)
    }

    /// The kernel over the rows it takes, then the scalar call over the rest (the first bad
    /// row's curvatures, then its step columns, reported).
    fn many(
        &self,
        curvatures: Source<'_, '_, T>,
        steps: &Steps<'_, T>,
        out: &mut Wrenches<'_, T>,
    ) -> Result<(), RowError> {
        let columns = match curvatures {
            Source::Columns(c) => Some(c),
            Source::One(_) => None,
        };
        let n = check_lengths(columns, steps, out)?;
        let done = T::dispatch(VaryingKernel {
            contact: self,
            curvatures,
            steps,
            out: &mut *out,
        });
        for i in done..n {
            let curv = match curvatures {
                Source::Columns(c) => curvature_row(c, i)?,
                Source::One(c) => *c,
            };
            let (h, hdot, slip) = step_row(steps, i)?;
            put(out, i, self.wrench(&curv, h, hdot, slip));
        }
        Ok(())
    }
}
