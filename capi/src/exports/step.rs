//! The step-aware wrench ([`contensou::step`]): the wrench to apply over a whole time step Δt so
//! that a semi-implicit Euler step with it is the linearly implicit (backward Euler) step of
//! the contact, projected (N ≥ 0, friction inside the law's full-slip set, no energy injected
//! by friction). One contact with the columns of `contact_eval step`, bit for bit; several
//! contacts sharing bodies (W with its cross blocks, an active set) in one solve.

#[cfg(doc)]
use super::{contensou_contact_new_f32, contensou_contact_wrench_rolling_f32};
use crate::shell;
use crate::status::contensou_status;
use crate::types::*;

twins! {
    /// One contact's step-aware wrench: bit for bit `contact_eval step` on the row made of the
    /// contact's columns (`storage`, built by [`contensou_contact_new_f32`] or its rolling
    /// variant), the start `step` (`h,hdot,vx,vy,omega`), `rolling` (`vrx,vry`, read by the
    /// rolling laws; NULL: 0), `dt` (s, > 0), `w` (W's upper triangle `w_nn … w_ww`: symmetric
    /// positive semidefinite by construction, checked within the library's tolerance) and
    /// `u_free` (`un_free,ux_free,uy_free,uw_free`: the end-of-step velocity without this
    /// contact; NULL: the start velocity (−ḣ, v_x, v_y, ω), as the contract's absent columns).
    /// The free end approach is h − Δt·u_free,n. Writes N, F_x, F_y, T_z on B into `*out`.
    ///
    /// Errors: the start step as [`contensou_contact_wrench_rolling_f32`] (its columns), `dt`
    /// ≤ 0 or not finite (`STEP_NOT_POSITIVE` / `NON_FINITE`, `CONTENSOU_COLUMN_DT`), a W entry
    /// not finite (`NON_FINITE`, its column `CONTENSOU_COLUMN_W_NN` + i), W not symmetric or not
    /// positive semidefinite (`INVERSE_MASS_NOT_*`, `CONTENSOU_COLUMN_W`), a free velocity not
    /// finite (`CONTENSOU_COLUMN_UN_FREE` + i). Fixed cost (the library's step_wrench: at most
    /// a fixed number of wrench and Jacobian evaluations and 4 × 4 solves).
    ///
    /// # Safety
    /// `storage`, `step`, `w` NULL or readable; `rolling`, `u_free` NULL or readable; `out`,
    /// `column` NULL or writable.
    fn contensou_contact_step_f32, contensou_contact_step_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        step: *const contensou_step<f32> | *const contensou_step<f64>,
        rolling: *const contensou_rolling_step<f32> | *const contensou_rolling_step<f64>,
        dt: f32 | f64,
        w: *const contensou_inverse_mass<f32> | *const contensou_inverse_mass<f64>,
        u_free: *const contensou_step_velocity<f32> | *const contensou_step_velocity<f64>,
        out: *mut contensou_step_wrench<f32> | *mut contensou_step_wrench<f64>,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_step(storage, step, rolling, dt, w, u_free, out, column) }
    }
}

twins! {
    /// The step-aware wrenches of `k` ∈ 1 … `CONTENSOU_STEP_MAX_CONTACTS` (8) contacts that
    /// share bodies, in one solve (`contensou::step::step_wrenches`): `contacts[i]` (each built
    /// by [`contensou_contact_new_f32`] or its rolling variant; one may appear twice), their
    /// start `steps[i]`, rolling velocities `rolling[i]` (NULL: 0 for all), the step `dt`, `w`
    /// the contacts' inverse mass over (u₀, …, u_{k−1}), u_i = (v_n, v_x, v_y, ω) of contact i:
    /// 4k × 4k values row-major, the cross blocks W_ij (an impulse on contact j's B changes
    /// u_i), and `free[i]` the end-of-step velocity and approach of contact i without the k
    /// contacts (NULL: each contact's start velocity, approach h + Δt·ḣ). Contacts whose
    /// solved normal force would pull are dropped from the solve (an active set), not clamped
    /// afterwards. k = 1 with `free[0].h` = h − Δt·v_n is [`contensou_contact_step_f32`]'s
    /// value bit for bit.
    ///
    /// Errors: `k` = 0 or > 8: `CONTACT_COUNT_OUT_OF_RANGE`; else as
    /// [`contensou_contact_step_f32`] (the columns of its row; a W entry not finite:
    /// `CONTENSOU_COLUMN_W`; a free approach not finite: `CONTENSOU_COLUMN_H_FREE`), the
    /// contact it is about in `*index` (k for an error of no contact and on success); nothing
    /// is written to `out` then. `index`, `column` may be NULL. Fixed cost per k (W's solve
    /// grows as (4k)³).
    ///
    /// # Safety
    /// `contacts`, `steps`, `free` NULL or holding `k` readable values (each contact pointer
    /// NULL or readable); `rolling` NULL or holding `k` values; `w` NULL or holding 16·k²
    /// values; `out` NULL or holding `k` writable values, not overlapping the inputs; `index`,
    /// `column` NULL or writable.
    fn contensou_step_many_f32, contensou_step_many_f64(
        contacts: *const *const contensou_contact_f32 | *const *const contensou_contact_f64,
        k: usize | usize,
        steps: *const contensou_step<f32> | *const contensou_step<f64>,
        rolling: *const contensou_rolling_step<f32> | *const contensou_rolling_step<f64>,
        dt: f32 | f64,
        w: *const f32 | *const f64,
        free: *const contensou_step_free<f32> | *const contensou_step_free<f64>,
        out: *mut contensou_step_wrench<f32> | *mut contensou_step_wrench<f64>,
        index: *mut usize | *mut usize,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::step_many(contacts, k, steps, rolling, dt, w, free, out, index, column) }
    }
}
