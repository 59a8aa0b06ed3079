//! The inverse-mass matrix W from rigid bodies: masses, inertia tensors, centres, and each
//! contact's point and frame ([`crate::frame::Frame`]).
//!
//! # Formula
//!
//! Contact i touches body Aᵢ (below) and Bᵢ (above) at point Pᵢ with frame (xᵢ, yᵢ, zᵢ). For a
//! body b with inverse mass 1/m, world inverse inertia I⁻¹ and centre c, and the arm
//! r = P − c, the contact velocity rows are (linear | angular part):
//!
//! ```text
//! v_n: (z | r × z),   v_x: (x | r × x),   v_y: (y | r × y),   ω: (0 | z)
//! ```
//!
//! so that body b adds to the block W_ij (contact i's velocity from contact j's wrench)
//!
//! ```text
//! s_i·s_j·( (1/m)·Lᵢ·Lⱼᵀ + Aᵢ·I⁻¹·Aⱼᵀ ),     s = +1 where b is the contact's B, −1 where it is A,
//! ```
//!
//! Lᵢ, Aᵢ the 4 × 3 linear and angular parts at contact i. A fixed body ([`Body::fixed`])
//! adds nothing. The result goes through [`InverseMass::new`]'s checks.

use super::InverseMass;
use crate::error::finite;
use crate::frame::{Frame, Vector};
use crate::{Error, Real};

/// A rigid body's inverse mass and world inverse inertia about its centre of mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body<T> {
    inv_mass: T,
    inv_inertia: [[T; 3]; 3],
    centre: Vector<T>,
}

/// One contact between two of the bodies (indices into the slice given to
/// [`InverseMass::from_bodies`]; `None` for the fixed world), at `point` with `frame`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint<T> {
    /// Body A (below; the normal points from A into B), or `None` for the fixed world.
    pub a: Option<usize>,
    /// Body B (above), or `None` for the fixed world.
    pub b: Option<usize>,
    /// The contact point P (world, m).
    pub point: Vector<T>,
    /// The contact frame (x the major axis, z from A into B).
    pub frame: Frame<T>,
}

impl<T: Real> Body<T> {
    /// Mass (kg), inertia tensor about the centre in **world** axes (kg·m², symmetric positive
    /// definite), centre of mass (world, m). Errors: [`Error::NonFinite`] (`"mass"`,
    /// `"inertia"`, `"centre"`), [`Error::MassNotPositive`], [`Error::InertiaNotPositiveDefinite`]
    /// (not symmetric to 64 ε relative to its largest diagonal entry, or a leading minor ≤ 0).
    pub fn new(mass: T, inertia: [[T; 3]; 3], centre: Vector<T>) -> Result<Self, Error> {
        let inv_mass = inverse_mass(mass)?;
        for r in inertia {
            for v in r {
                finite(v, "inertia")?;
            }
        }
        for v in centre {
            finite(v, "centre")?;
        }
        Ok(Body {
            inv_mass,
            inv_inertia: inverse_spd(inertia)?,
            centre,
        })
    }

    /// Mass, principal moments (kg·m², each > 0) and the body's orientation `rotation`
    /// (columns: the principal axes in world coordinates, orthonormal), centre of mass:
    /// I⁻¹ = R·diag(1/Iₖ)·Rᵀ. Errors as [`Body::new`] (`"rotation"` for a non-finite entry;
    /// a moment ≤ 0 is [`Error::InertiaNotPositiveDefinite`]).
    pub fn principal(
        mass: T,
        moments: [T; 3],
        rotation: [[T; 3]; 3],
        centre: Vector<T>,
    ) -> Result<Self, Error> {
        let inv_mass = inverse_mass(mass)?;
        let mut inv = [T::ZERO; 3];
        for k in 0..3 {
            let m = finite(moments[k], "inertia")?;
            if !(m > T::ZERO) {
                return Err(Error::InertiaNotPositiveDefinite);
            }
            inv[k] = T::ONE / m;
        }
        for r in rotation {
            for v in r {
                finite(v, "rotation")?;
            }
        }
        for v in centre {
            finite(v, "centre")?;
        }
        let mut ii = [[T::ZERO; 3]; 3];
        for (r, row) in ii.iter_mut().enumerate() {
            for (c, e) in row.iter_mut().enumerate() {
                let mut s = T::ZERO;
                for k in 0..3 {
                    s += rotation[r][k] * inv[k] * rotation[c][k];
                }
                *e = s;
            }
        }
        Ok(Body {
            inv_mass,
            inv_inertia: ii,
            centre,
        })
    }

    /// A body held fixed (infinite mass and inertia): contributes nothing to W.
    pub fn fixed() -> Self {
        Body {
            inv_mass: T::ZERO,
            inv_inertia: [[T::ZERO; 3]; 3],
            centre: [T::ZERO; 3],
        }
    }

    /// 1/m (1/kg).
    pub fn inv_mass(&self) -> T {
        self.inv_mass
    }

    /// The world inverse inertia (1/(kg·m²)).
    pub fn inv_inertia(&self) -> [[T; 3]; 3] {
        self.inv_inertia
    }
}

fn inverse_mass<T: Real>(mass: T) -> Result<T, Error> {
    let m = finite(mass, "mass")?;
    if !(m > T::ZERO) {
        return Err(Error::MassNotPositive);
    }
    let inv = T::ONE / m;
    if inv.is_finite() {
        Ok(inv)
    } else {
        Err(Error::MassNotPositive)
    }
}

/// The inverse of a symmetric positive definite 3 × 3 (Sylvester's criterion on the leading
/// minors, then the adjugate over the determinant), else [`Error::InertiaNotPositiveDefinite`].
fn inverse_spd<T: Real>(a: [[T; 3]; 3]) -> Result<[[T; 3]; 3], Error> {
    let [[a00, a01, a02], [a10, a11, a12], [a20, a21, a22]] = a;
    let scale = a00.abs().max(a11.abs()).max(a22.abs());
    let tol = T::EPSILON * T::from_f64(64.0) * scale;
    if (a01 - a10).abs() > tol || (a02 - a20).abs() > tol || (a12 - a21).abs() > tol {
        return Err(Error::InertiaNotPositiveDefinite);
    }
    let (b01, b02, b12) = (
        (a01 + a10) * T::HALF,
        (a02 + a20) * T::HALF,
        (a12 + a21) * T::HALF,
    );
    // cofactors of the symmetric matrix
    let c00 = a11 * a22 - b12 * b12;
    let c01 = b02 * b12 - b01 * a22;
    let c02 = b01 * b12 - a11 * b02;
    let c11 = a00 * a22 - b02 * b02;
    let c12 = b01 * b02 - a00 * b12;
    let c22 = a00 * a11 - b01 * b01;
    let det = a00 * c00 + b01 * c01 + b02 * c02;
    if !(a00 > T::ZERO && c22 > T::ZERO && det > T::ZERO) {
        return Err(Error::InertiaNotPositiveDefinite);
    }
    let inv = [
        [c00 / det, c01 / det, c02 / det],
        [c01 / det, c11 / det, c12 / det],
        [c02 / det, c12 / det, c22 / det],
    ];
    if inv.iter().flatten().all(|v| v.is_finite()) {
        Ok(inv)
    } else {
        Err(Error::InertiaNotPositiveDefinite)
    }
}

fn cross<T: Real>(a: Vector<T>, b: Vector<T>) -> Vector<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot<T: Real>(a: Vector<T>, b: Vector<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub<T: Real>(a: Vector<T>, b: Vector<T>) -> Vector<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The 4 linear and angular rows of a contact for a body with arm r.
fn rows<T: Real>(frame: &Frame<T>, r: Vector<T>) -> ([Vector<T>; 4], [Vector<T>; 4]) {
    let (x, y, z) = (frame.x(), frame.y(), frame.z());
    (
        [z, x, y, [T::ZERO; 3]],
        [cross(r, z), cross(r, x), cross(r, y), z],
    )
}

fn mat_vec<T: Real>(m: &[[T; 3]; 3], v: Vector<T>) -> Vector<T> {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}

impl<T: Real, const K: usize> InverseMass<T, K> {
    /// W for K contacts among rigid `bodies` (see the [module docs](self)): one or two moving
    /// bodies per contact, the cross blocks wherever contacts share a body. Errors:
    /// [`Error::BodyIndexInvalid`] (an index beyond `bodies`, or A = B), [`Error::NonFinite`]
    /// `"point"`, then [`InverseMass::new`]'s.
    pub fn from_bodies(bodies: &[Body<T>], contacts: &[ContactPoint<T>; K]) -> Result<Self, Error> {
        for c in contacts {
            for v in c.point {
                finite(v, "point")?;
            }
            if c.a.is_some() && c.a == c.b {
                return Err(Error::BodyIndexInvalid);
            }
            for ix in [c.a, c.b].into_iter().flatten() {
                if ix >= bodies.len() {
                    return Err(Error::BodyIndexInvalid);
                }
            }
        }
        let mut blocks = [[[[T::ZERO; 4]; 4]; K]; K];
        for (bi, body) in bodies.iter().enumerate() {
            // Each contact's role for this body: +1 (B), −1 (A), 0 (none).
            let role = |c: &ContactPoint<T>| -> T {
                if c.b == Some(bi) {
                    T::ONE
                } else if c.a == Some(bi) {
                    -T::ONE
                } else {
                    T::ZERO
                }
            };
            for (ci, row) in contacts.iter().zip(blocks.iter_mut()) {
                let si = role(ci);
                if si == T::ZERO {
                    continue;
                }
                let (li, ai) = rows(&ci.frame, sub(ci.point, body.centre));
                for (cj, block) in contacts.iter().zip(row.iter_mut()) {
                    let sj = role(cj);
                    if sj == T::ZERO {
                        continue;
                    }
                    let (lj, aj) = rows(&cj.frame, sub(cj.point, body.centre));
                    for ((la, aa), brow) in li.iter().zip(&ai).zip(block.iter_mut()) {
                        for ((lb, ab), e) in lj.iter().zip(&aj).zip(brow.iter_mut()) {
                            let lin = body.inv_mass * dot(*la, *lb);
                            let ang = dot(*aa, mat_vec(&body.inv_inertia, *ab));
                            *e += si * sj * (lin + ang);
                        }
                    }
                }
            }
        }
        InverseMass::new(blocks)
    }
}
