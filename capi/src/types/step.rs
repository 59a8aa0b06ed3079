//! The C types of the step-aware wrench (`contensou_contact_step_*`, `contensou_step_many_*`):
//! the columns of `contact_eval step` ([`contensou::step::contract`]) after the wrench's —
//! `dt`, W's upper triangle, the optional free end-of-step velocity — and, for several contacts
//! sharing bodies, their free end-of-step motion.

use contensou::step::contract::{FREE_INPUTS, STEP_INPUTS};

/// The most contacts one `contensou_step_many_*` call solves together (W of 32 × 32).
pub const CONTENSOU_STEP_MAX_CONTACTS: usize = 8;

/// W's upper triangle over u = (v_n, v_x, v_y, ω) (v_n = −ḣ; `w` = spin): the columns
/// `w_nn,w_nx,w_ny,w_nw,w_xx,w_xy,w_xw,w_yy,w_yw,w_ww` of `contact_eval step`. An impulse
/// Δt·(N, F_x, F_y, T_z) on body B changes its contact velocity u by Δt·W·(N, F_x, F_y, T_z).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_inverse_mass<T> {
    /// W_nn (1/kg).
    pub nn: T,
    /// W_nx.
    pub nx: T,
    /// W_ny.
    pub ny: T,
    /// W_nω.
    pub nw: T,
    /// W_xx.
    pub xx: T,
    /// W_xy.
    pub xy: T,
    /// W_xω.
    pub xw: T,
    /// W_yy.
    pub yy: T,
    /// W_yω.
    pub yw: T,
    /// W_ωω (1/(kg·m²)).
    pub ww: T,
}

impl<T: Copy> contensou_inverse_mass<T> {
    /// The ten entries in the contract's column order.
    pub(crate) fn upper(&self) -> [T; 10] {
        [
            self.nn, self.nx, self.ny, self.nw, self.xx, self.xy, self.xw, self.yy, self.yw,
            self.ww,
        ]
    }
}

/// A contact velocity u = (v_n, v_x, v_y, ω) of body B relative to A (v_n = −ḣ: separation
/// speed), contact frame: the free end-of-step velocity `un_free,ux_free,uy_free,uw_free` of
/// `contact_eval step` — what u would be at the end of the step without this contact.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_step_velocity<T> {
    /// v_n = −ḣ (m/s).
    pub vn: T,
    /// v_x (m/s).
    pub vx: T,
    /// v_y (m/s).
    pub vy: T,
    /// ω (rad/s).
    pub omega: T,
}

/// One contact's free end-of-step motion for `contensou_step_many_*`: its velocity u and its
/// approach h at the end of the step without the call's contacts (gravity and every other
/// force; h from the caller's prediction of the drifted pose, or h − Δt·v_n).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_step_free<T> {
    /// The free end-of-step velocity.
    pub u: contensou_step_velocity<T>,
    /// The free end-of-step approach h (m).
    pub h: T,
}

/// The step-aware wrench (N, F_x, F_y, T_z) on B from A, contact frame: the outputs
/// `N,Fx,Fy,Tz` of `contact_eval step`, to apply over the whole step.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_step_wrench<T> {
    /// N (N).
    pub n: T,
    /// F_x (N).
    pub fx: T,
    /// F_y (N).
    pub fy: T,
    /// T_z (N·m).
    pub tz: T,
}

/// `dt` (`contact_eval step`; after the rolling columns).
pub const CONTENSOU_COLUMN_DT: super::contensou_column = 16;
/// `w_nn`; `w_nx` … `w_ww` follow (17 … 26), in the order of [`contensou_inverse_mass`].
pub const CONTENSOU_COLUMN_W_NN: super::contensou_column = 17;
/// `W`: the inverse mass as a whole (not symmetric or not positive semidefinite; an entry of
/// the full matrix of `contensou_step_many_*` that is not finite).
pub const CONTENSOU_COLUMN_W: super::contensou_column = 27;
/// `un_free`; `ux_free`, `uy_free`, `uw_free` follow (29 … 31).
pub const CONTENSOU_COLUMN_UN_FREE: super::contensou_column = 28;
/// `h_free`: a contact's free end-of-step approach (`contensou_step_many_*`).
pub const CONTENSOU_COLUMN_H_FREE: super::contensou_column = 32;

/// The step columns' names by code from [`CONTENSOU_COLUMN_DT`]: `dt`, the ten `w_*`, `W`,
/// the four `u*_free`, `h_free`.
pub(crate) const STEP_COLUMNS: [&str; 17] = [
    STEP_INPUTS[0],
    STEP_INPUTS[1],
    STEP_INPUTS[2],
    STEP_INPUTS[3],
    STEP_INPUTS[4],
    STEP_INPUTS[5],
    STEP_INPUTS[6],
    STEP_INPUTS[7],
    STEP_INPUTS[8],
    STEP_INPUTS[9],
    STEP_INPUTS[10],
    "W",
    FREE_INPUTS[0],
    FREE_INPUTS[1],
    FREE_INPUTS[2],
    FREE_INPUTS[3],
    "h_free",
];
