//! Every exported C function. Each is a one-line call of its generic body in the private
//! `shell` module, once per precision (`_f32`: `float`, `_f64`: `double`), each pair written
//! once by `twins!`: cbindgen reads the macro-expanded crate (`[parse.expand]` in
//! cbindgen.toml, a nightly `rustc -Zunpretty=expanded`), so the header is as before.
//!
//! Pointers: every pointer parameter may be anything a C caller passes. NULL gives
//! [`contensou_status::NullPointer`], a misaligned one [`contensou_status::Misaligned`];
//! otherwise it must point to valid memory of its type (C's usual contract). On any error
//! nothing is written except `*column` (which may itself be NULL: then it is not written).

use core::ffi::c_char;

use contensou::dynamic::{Form, Law};
use contensou::geometry::Curvatures;

use crate::shell;
use crate::status::contensou_status;
use crate::types::*;

/// The `_f32` function as written and its `_f64` twin: the same parameters with the `double`
/// types given after `|`, the same body; the twin's docs refer to the `_f32` one.
macro_rules! twins {
    (
        $(#[doc = $doc:literal])*
        fn $f32:ident, $f64:ident($($arg:ident: $t32:ty | $t64:ty),* $(,)?) -> $ret:ty $body:block
    ) => {
        twins! {
            $(#[doc = $doc])*
            fn $f32, $f64($($arg: $t32 | $t64),*) -> $ret $body
            twin safety: concat!(" As [`", stringify!($f32), "`].")
        }
    };
    (
        $(#[doc = $doc:literal])*
        fn $f32:ident, $f64:ident($($arg:ident: $t32:ty | $t64:ty),* $(,)?) -> $ret:ty $body:block
        twin safety: $safety:expr
    ) => {
        $(#[doc = $doc])*
        #[no_mangle]
        pub unsafe extern "C" fn $f32($($arg: $t32),*) -> $ret $body

        #[doc = concat!(" [`", stringify!($f32), "`] in `double`.")]
        #[doc = ""]
        #[doc = " # Safety"]
        #[doc = $safety]
        #[no_mangle]
        pub unsafe extern "C" fn $f64($($arg: $t64),*) -> $ret $body
    };
}

/// A geometry helper, `Curvatures::$new` of the `float` (`double`) arguments, as twins writing
/// `*out`.
macro_rules! curvatures_twins {
    (
        $(#[doc = $doc:literal])*
        fn $f32:ident, $f64:ident = $new:ident($($arg:ident),*)
    ) => {
        twins! {
            $(#[doc = $doc])*
            ///
            /// # Safety
            /// `out` is NULL or writable.
            fn $f32, $f64(
                $($arg: f32 | f64,)*
                out: *mut contensou_curvatures<f32> | *mut contensou_curvatures<f64>,
            ) -> contensou_status {
                unsafe { shell::curvatures(out, || Ok(Curvatures::$new($($arg),*)?)) }
            }
            twin safety: " `out` is NULL or writable."
        }
    };
}

mod jacobian;
mod rolling;
mod step;
pub use jacobian::*;
pub use rolling::*;
pub use step::*;

/// The message of a status code: a static NUL-terminated string (also for unknown codes).
#[no_mangle]
pub extern "C" fn contensou_status_message(status: u32) -> *const c_char {
    contensou_status::message_ptr(status)
}

/// The name of a contract column (`"P"`, …, `"omega"`): a static NUL-terminated string, `""`
/// for `CONTENSOU_COLUMN_NONE` and unknown values.
#[no_mangle]
pub extern "C" fn contensou_column_name(column: contensou_column) -> *const c_char {
    shell::column_name(column)
}

/// The law of a name (`"best"`, `"simplified"`, `"pade"`, `"ellipsoid"`, `"coulomb"`; the
/// rolling laws `"table"`, `"blend"`, `"fastsim"`, `"fastsim-16"`, `"full-slip"`, `"linear"`;
/// `"rolling"` names the default rolling law, today `"table"`).
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `law` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn contensou_law_from_name(
    name: *const c_char,
    law: *mut contensou_law,
) -> contensou_status {
    let parse = |n: &str| {
        Law::from_name(n)
            .map(shell::law_code)
            .or_else(|| shell::rolling_law_of(n))
    };
    unsafe { shell::from_name(name, law, parse, |code| code) }
}

/// The form of a name (`"fixed"`, `"varying"`).
///
/// # Safety
/// `name` is NULL or a NUL-terminated string; `form` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn contensou_form_from_name(
    name: *const c_char,
    form: *mut contensou_form,
) -> contensou_status {
    unsafe { shell::from_name(name, form, Form::from_name, shell::form_code) }
}

curvatures_twins! {
    /// Curvatures from z = p x'² + q y'² in any order: P = min, Q = max, `major_angle` 0 or π/2.
    fn contensou_curvatures_new_f32, contensou_curvatures_new_f64 = new(p, q)
}

curvatures_twins! {
    /// Sphere of radius `r` (m) on a plane: P = Q = 1/(2r).
    fn contensou_curvatures_sphere_plane_f32, contensou_curvatures_sphere_plane_f64 = sphere_plane(r)
}

curvatures_twins! {
    /// Two spheres of signed radii (m; negative = concave cup): P = Q = ½(1/r_a + 1/r_b).
    fn contensou_curvatures_sphere_sphere_f32, contensou_curvatures_sphere_sphere_f64 = sphere_sphere(r_a, r_b)
}

twins! {
    /// A ball of diameter D in a raceway groove of radius r_g, pitch diameter d_m, contact angle
    /// α (rad), inner or outer race: P ≤ Q in contract order, and the major axis's angle from the
    /// rolling direction (π/2 for a conforming groove: the ellipse is long across the groove).
    ///
    /// # Safety
    /// `out` is NULL or writable.
    fn contensou_curvatures_ball_race_f32, contensou_curvatures_ball_race_f64(
        ball_diameter: f32 | f64,
        groove_radius: f32 | f64,
        pitch_diameter: f32 | f64,
        contact_angle: f32 | f64,
        race: contensou_race | contensou_race,
        out: *mut contensou_curvatures<f32> | *mut contensou_curvatures<f64>,
    ) -> contensou_status {
        unsafe {
            shell::curvatures(out, || {
                let race = shell::race(race)?;
                Ok(Curvatures::ball_race(
                    ball_diameter,
                    groove_radius,
                    pitch_diameter,
                    contact_angle,
                    race,
                )?)
            })
        }
    }
    twin safety: " `out` is NULL or writable."
}

twins! {
    /// E* of two materials (Young's modulus E > 0 in Pa, Poisson's ratio ν ∈ (−1, 0.5]):
    /// 1/E* = (1 − ν_a²)/E_a + (1 − ν_b²)/E_b.
    ///
    /// # Safety
    /// `estar` is NULL or writable.
    fn contensou_modulus_of_f32, contensou_modulus_of_f64(
        young_a: f32 | f64,
        poisson_a: f32 | f64,
        young_b: f32 | f64,
        poisson_b: f32 | f64,
        estar: *mut f32 | *mut f64,
    ) -> contensou_status {
        unsafe { shell::modulus_of(young_a, poisson_a, young_b, poisson_b, estar) }
    }
    twin safety: " `estar` is NULL or writable."
}

twins! {
    /// Validates `spec` and builds a contact of that law and form into `storage` (the storage is
    /// not read; on error it is left unchanged). The column of a rejected input goes to
    /// `*column` (`CONTENSOU_COLUMN_NONE` on success or for errors of no column; `column` may be
    /// NULL). Cost: `fixed` solves the eccentricity (and `best` fills its tables) here.
    ///
    /// # Safety
    /// `storage` is NULL or writable; `spec` NULL or readable; `column` NULL or writable.
    fn contensou_contact_new_f32, contensou_contact_new_f64(
        storage: *mut contensou_contact_f32 | *mut contensou_contact_f64,
        spec: *const contensou_spec<f32> | *const contensou_spec<f64>,
        law: contensou_law | contensou_law,
        form: contensou_form | contensou_form,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_new(storage, spec, law, form, column) }
    }
}

twins! {
    /// New curvatures P ≤ Q for a contact (validated as in construction; on error the contact is
    /// unchanged). `varying` form: the per-step update (no solve); `fixed`: the contact is rebuilt
    /// (construction cost).
    ///
    /// # Safety
    /// `storage` is NULL or an initialised, writable contact; `column` NULL or writable.
    fn contensou_contact_set_curvatures_f32, contensou_contact_set_curvatures_f64(
        storage: *mut contensou_contact_f32 | *mut contensou_contact_f64,
        p: f32 | f64,
        q: f32 | f64,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_set_curvatures(storage, p, q, column) }
    }
}

twins! {
    /// One step: validates `step` (finite values; the column of a NaN/±∞ goes to `*column`) and
    /// writes the wrench into `*out`. Fixed cost; bit for bit the Rust contract's value.
    ///
    /// # Safety
    /// `storage` is NULL or readable; `step` NULL or readable; `out`, `column` NULL or writable.
    fn contensou_contact_wrench_f32, contensou_contact_wrench_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        step: *const contensou_step<f32> | *const contensou_step<f64>,
        out: *mut contensou_wrench<f32> | *mut contensou_wrench<f64>,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_wrench(storage, step, out, column) }
    }
}

twins! {
    /// Many steps of one contact over caller arrays (structure of arrays): row i of the seven
    /// output arrays is bit for bit what [`contensou_contact_wrench_f32`] gives for row i of the
    /// five step arrays, several rows per instruction (SIMD lanes: AVX2 or SSE2 on x86-64,
    /// detected at run time; one lane elsewhere). `rows` = 0 writes nothing and succeeds.
    ///
    /// On a non-finite input the call stops at that row: rows before it are written, `*row` gets
    /// its index and `*column` its column (`CONTENSOU_COLUMN_H` … `_OMEGA`); on success `*row` =
    /// `rows`. `row` and `column` may be NULL. A NULL or misaligned array (for `rows` > 0) is
    /// refused before anything is written; so is a `rows` larger than any array can be
    /// (> PTRDIFF_MAX / sizeof(float): `NullPointer`).
    ///
    /// # Safety
    /// `storage` is NULL or readable; `steps`, `out` NULL or readable, their arrays NULL or
    /// holding `rows` values (the output arrays writable, distinct, not overlapping the inputs);
    /// `row`, `column` NULL or writable.
    fn contensou_contact_wrench_many_f32, contensou_contact_wrench_many_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        rows: usize | usize,
        steps: *const contensou_step_columns<f32> | *const contensou_step_columns<f64>,
        out: *const contensou_wrench_columns<f32> | *const contensou_wrench_columns<f64>,
        row: *mut usize | *mut usize,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_wrench_many(storage, rows, steps, out, row, column) }
    }
}
