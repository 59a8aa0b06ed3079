//! The methods the report measures: one line per (stage, method, precision).
//!
//! `stage`, `method` and `precision` are the join key of `bench-results/qemu.csv`,
//! `host-ns.csv` and `flash.csv`; `section` is the report section (and chart) the row belongs
//! to. Adding a method is one line here (behind its feature if it has one), e.g.
//!
//! ```text
//! #[cfg(feature = "micromath")]
//! m!("elliptic", "agm-micromath", ELLIPTIC, elliptic::<f32, AgmMicromath>),
//! ```

use contensou::elliptic::{Agm, Table as KeTable, Theta};
use contensou::friction::{Best, Coulomb, Ellipsoid, Exact, Pade, Simplified};
use contensou::shape::{HamrockDowson, Linear, Newton, Table};

use crate::measure::{
    Refs, elliptic, hertz_fitted, hertz_newton, hertz_table_each_step, hertz_volumetric,
    law_per_call, law_prepared, shape, wrench_fixed, wrench_varying,
};

/// A report section: one table and one error-against-instructions chart.
#[derive(Clone, Copy, Debug)]
pub struct Section {
    /// File-name stem of the chart.
    pub id: &'static str,
    /// Heading.
    pub title: &'static str,
    /// What each error component is, in the order the error functions return them.
    pub components: &'static [&'static str],
    /// The components whose max is the chart's error.
    pub chart: &'static [usize],
    /// How the errors are measured (one sentence for the report).
    pub how: &'static str,
}

pub const ELLIPTIC: Section = Section {
    id: "elliptic",
    title: "Complete elliptic integrals K, E, B, D",
    components: &["K, E, B, D (rel.)"],
    chart: &[0],
    how: "max relative error of K, E, B and D against `tools/data/elliptic_ref.csv` \
          (mpmath); f32: the rows whose m (m ≤ ½) or m₁ (m > ½) is exact in f32 and inside \
          the f32 domain (m₁ ≥ 2⁻²⁴)",
};

pub const ECCENTRICITY: Section = Section {
    id: "eccentricity",
    title: "Eccentricity from the curvature ratio g (shape methods)",
    components: &["N (rel.)", "a, b (rel.)", "c = e² (abs.)"],
    chart: &[0, 1],
    how: "`Hertz::new::<M>` (shape solved once) on every row of `tools/data/hertz_ref.csv` \
          (mpmath; g from 1e-4 to 1): relative error of N and of a, b, absolute error of \
          c = e². QEMU counts are the shape construction alone (`M::shape(g)`)",
};

pub const NORMAL: Section = Section {
    id: "normal",
    title: "Normal force per step",
    components: &["N (rel.)", "a, b (rel.)"],
    chart: &[0, 1],
    how: "the patch (a, b, N) at every row of `tools/data/hertz_ref.csv` (mpmath): relative \
          error of N and of a, b. `per_step`: geometry solved once (Newton), the step only; \
          `table_each_step`: e² by table from g every step; `fitted_each_step`: the fitted law \
          from g every step; `volumetric`: the eccentricity-free volumetric law from the \
          curvatures every step",
};

pub const FRICTION: Section = Section {
    id: "friction",
    title: "Friction laws (dimensionless core)",
    components: &[
        "ΔF/(fN), accepted e²",
        "ΔT_z/(fNa), accepted e²",
        "ΔF/(fN), all e²",
        "ΔT_z/(fNa), all e²",
    ],
    chart: &[0, 1],
    how: "every row of `tools/data/friction_ref.csv` and `friction_ref_random.csv` (mpmath \
          integrals; e² from 0 to 1 − 1.5e-12, u from 0 to ∞): |ΔF| = |(ΔF_x, ΔF_y)| in fN and |ΔT_z| \
          in fNa (ΔF, ΔT_z in the tables), over the e² the contract accepts, up to 0.999982985551773 at P/Q = 1e-4 (`best`'s exact-grade \
          domain; the chart) \
          and over every row (e² up to 1 − 1.5e-12). Laws in their per-contact form (`prepare` once per e²); `best-varying` is \
          `Best`'s per-step form (its coefficients from the flash table with e² interpolated, \
          every call: what `VaryingContact` calls). f32 skips the rows whose e² rounds \
          to 1 in f32 (outside its domain). `exact` is the library's reference \
          quadrature, computed in f64 for both precisions (closed form inside the ellipse, \
          64–192-node Gauss–Legendre outside: a reference path, not for the hot path)",
};

pub const WRENCH: Section = Section {
    id: "wrench",
    title: "Full wrench per step (Hertz + friction, bearing 209)",
    components: &["N (rel.)", "ΔF/(fN)", "ΔT_z/(fNa)"],
    chart: &[0, 1, 2],
    how: "the 209 bearing's inner and outer race rows of `tools/data/hertz_ref.csv` (mpmath \
          N, a, e²) × the 64 slips of the benches' mixed set (u log-uniform in [0.01, 100], \
          ψ uniform, ω = 100 rad/s, f = 0.07): the reference wrench is the mpmath patch with \
          the library's exact friction quadrature (5e-15 against mpmath) in f64. `fixed`: \
          `Contact` (geometry solved once, Newton); `table_each_step`: `VaryingContact` (e² \
          by table every step); `-best`: the `best` law, else `simplified`",
};

/// The sections in report order.
pub const SECTIONS: [Section; 5] = [ELLIPTIC, ECCENTRICITY, NORMAL, FRICTION, WRENCH];

/// Errors of one method at every reference point: one vector of components per point.
pub type ErrorFn = fn(&Refs) -> Vec<Vec<f64>>;

/// One measured method.
#[derive(Clone, Copy)]
pub struct Method {
    pub stage: &'static str,
    pub method: &'static str,
    pub precision: &'static str,
    pub section: Section,
    pub errors: ErrorFn,
}

/// `m!(stage, method, section, errors::<precision, …>)`: the precision is the error
/// function's first type argument.
macro_rules! m {
    ($stage:literal, $method:literal, $section:expr, $f:ident::<$t:ident $(, $p:ty)*>) => {
        Method {
            stage: $stage,
            method: $method,
            precision: stringify!($t),
            section: $section,
            errors: $f::<$t $(, $p)*>,
        }
    };
}

/// `methods! { stage, method, section, errors::<precision, …>; … }`: a table of `m!` rows.
#[cfg(feature = "micromath")]
macro_rules! methods {
    ($($stage:literal, $method:literal, $section:expr, $f:ident::<$t:ident $(, $p:ty)*>;)*) => {
        vec![$(m!($stage, $method, $section, $f::<$t $(, $p)*>),)*]
    };
}

/// `both! { stage, method, section, errors[::<…>]; … }`: each method in f32 and in f64, as
/// `m!` with the precision inserted as `errors`'s first type argument, in order.
macro_rules! both {
    ($($stage:literal, $method:literal, $section:expr, $f:ident $(::<$($p:ty),*>)?;)*) => {
        vec![$(
            m!($stage, $method, $section, $f::<f32 $($(, $p)*)?>),
            m!($stage, $method, $section, $f::<f64 $($(, $p)*)?>),
        )*]
    };
}

/// Every method × precision the report measures.
pub fn methods() -> Vec<Method> {
    #[allow(unused_mut)]
    let mut all = both! {
        "elliptic", "agm", ELLIPTIC, elliptic::<Agm>;
        "elliptic", "theta", ELLIPTIC, elliptic::<Theta>;
        "elliptic", "table", ELLIPTIC, elliptic::<KeTable>;
        "hertz", "shape_newton", ECCENTRICITY, shape::<Newton>;
        "hertz", "shape_table", ECCENTRICITY, shape::<Table>;
        "hertz", "shape_linear", ECCENTRICITY, shape::<Linear>;
        "hertz", "shape_hamrock-dowson", ECCENTRICITY, shape::<HamrockDowson>;
        "hertz", "per_step", NORMAL, hertz_newton;
        "hertz", "table_each_step", NORMAL, hertz_table_each_step;
        "hertz", "fitted_each_step", NORMAL, hertz_fitted;
        "hertz", "volumetric", NORMAL, hertz_volumetric;
        "friction", "simplified", FRICTION, law_prepared::<Simplified>;
        "friction", "pade", FRICTION, law_prepared::<Pade>;
        "friction", "ellipsoid", FRICTION, law_prepared::<Ellipsoid>;
        "friction", "coulomb", FRICTION, law_prepared::<Coulomb>;
        "friction", "best", FRICTION, law_prepared::<Best>;
        "friction", "best-varying", FRICTION, law_per_call::<Best>;
        "friction", "exact", FRICTION, law_prepared::<Exact>;
        "wrench", "fixed", WRENCH, wrench_fixed::<Simplified>;
        "wrench", "table_each_step", WRENCH, wrench_varying::<Simplified>;
        "wrench", "fixed-best", WRENCH, wrench_fixed::<Best>;
        "wrench", "table_each_step-best", WRENCH, wrench_varying::<Best>;
    };
    #[cfg(feature = "micromath")]
    all.extend(micromath());
    all
}

/// The micromath twins (feature `micromath`; f32 only: their f64 is the libm method).
#[cfg(feature = "micromath")]
fn micromath() -> Vec<Method> {
    use contensou::elliptic::ThetaMicromath;
    use contensou::friction::{
        BestMicromath, CoulombMicromath, EllipsoidMicromath, SimplifiedMicromath,
    };
    use contensou::shape::HamrockDowsonMicromath;

    use crate::measure::hertz_newton_micromath;
    methods! {
        "elliptic", "theta-micromath", ELLIPTIC, elliptic::<f32, ThetaMicromath>;
        "hertz", "shape_hamrock-dowson-micromath", ECCENTRICITY, shape::<f32, HamrockDowsonMicromath>;
        "hertz", "per_step-micromath", NORMAL, hertz_newton_micromath::<f32>;
        "friction", "simplified-micromath", FRICTION, law_prepared::<f32, SimplifiedMicromath>;
        "friction", "ellipsoid-micromath", FRICTION, law_prepared::<f32, EllipsoidMicromath>;
        "friction", "coulomb-micromath", FRICTION, law_prepared::<f32, CoulombMicromath>;
        "friction", "best-micromath", FRICTION, law_per_call::<f32, BestMicromath>;
    }
}
