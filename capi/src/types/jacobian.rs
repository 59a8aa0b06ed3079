//! The C type of the wrench's Jacobian (`contensou_contact_jacobian_*`):
//! [`contensou::jacobian::Jacobian`], the columns of `contact_eval jacobian`.

/// The wrench (N, F_x, F_y, T_z) on body B of one step and its derivatives with respect to
/// the step's inputs q = (h, ḣ, v_x, v_y, ω) ([`contensou::jacobian::Jacobian`]): the outputs
/// `N,Fx,Fy,Tz,dN_dh,…,dTz_domega` of `contact_eval jacobian`, in that order (`d` row by
/// row). SI units: `d[0][0]` = ∂N/∂h in N/m, `d[3][4]` = ∂T_z/∂ω in N·m·s, ….
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_jacobian<T> {
    /// Normal force N (N): bit for bit `contensou_contact_wrench_*`'s.
    pub n: T,
    /// Friction force F_x (N).
    pub fx: T,
    /// Friction force F_y (N).
    pub fy: T,
    /// Drilling torque T_z (N·m).
    pub tz: T,
    /// `d[i][j]` = ∂wᵢ/∂qⱼ: rows i = (N, F_x, F_y, T_z), columns j = (h, ḣ, v_x, v_y, ω).
    pub d: [[T; 5]; 4],
}

impl<T: Copy> From<contensou::jacobian::Jacobian<T>> for contensou_jacobian<T> {
    fn from(j: contensou::jacobian::Jacobian<T>) -> Self {
        let [n, fx, fy, tz] = j.value;
        Self {
            n,
            fx,
            fy,
            tz,
            d: j.d,
        }
    }
}
