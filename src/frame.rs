//! The contact frame in the world: from two bodies' motion to the [`Slip`] and ḣ that
//! [`Contact::wrench`](crate::contact::Contact::wrench) takes, and from the [`Wrench`] it returns
//! (contact frame) back to a world force and a torque about each body's centre of mass.
//!
//! # The frame
//!
//! The contact frame P x y z (crate conventions) is built from
//!
//! - the unit **normal** z, pointing from body A into body B (world vector);
//! - a **reference tangent** t₁ ⊥ z (world vector; e.g. body A's first principal direction, the
//!   direction [`Curvatures::from_bodies`] measures its angle from, or any fixed horizontal for
//!   a circular patch); t₂ = z × t₁ completes the right-handed tangent basis;
//! - the **major axis** as the angle φ from t₁ towards t₂ ([`MajorAxis`], held as cos φ and
//!   sin φ so that firmware needs no trigonometry per step):
//!
//! ```text
//! x = cos φ·t₁ + sin φ·t₂,    y = z × x = −sin φ·t₁ + cos φ·t₂.
//! ```
//!
//! With [`Curvatures`], t₁ is the direction its constructor measured from and φ its
//! [`Curvatures::major_angle`] ([`MajorAxis::of`]): the (x′, y′) of [`Curvatures::new`]
//! (φ = 0 or π/2, taken exactly), body A's first principal direction for
//! [`Curvatures::from_bodies`] (then measure its ω in the same sense, from t₁ towards t₂), the
//! rolling direction for [`Curvatures::ball_race`]. φ and φ + π give the same ellipse (the
//! frame turned by π about z, the same world loads).
//!
//! # Into the contact frame
//!
//! With v_rel the velocity of B's material point at P minus A's (world; [`point_velocity`]
//! gives each) and ω_rel = ω_B − ω_A (world):
//!
//! ```text
//! v_Px = v_rel·x,  v_Py = v_rel·y,  ω = ω_rel·z,  ḣ = −v_rel·z  (ḣ > 0: compression).
//! ```
//!
//! The rolling part of ω_rel (in the tangent plane) does not enter the friction model.
//!
//! # Back to the world
//!
//! N, F_x, F_y act at the patch centre P, T_z about the normal. On body B:
//!
//! ```text
//! F = F_x·x + F_y·y + N·z,    torque about a point C:  (P − C) × F + T_z·z,
//! ```
//!
//! and body A receives the opposite force and, about its own point C_A, (P − C_A) × (−F) − T_z·z
//! ([`ContactFrame::on_b`], [`ContactFrame::on_a`]; the conversions are the [`ContactFrame`]
//! trait's, for [`Frame`] and [`WorldAxes`]).
//!
//! # Where the curvatures cross (e² = 0)
//!
//! Where P = Q the patch is a circle and every tangent direction is a major axis; on either
//! side the major axis is the direction of the smaller curvature, so as the two curvatures
//! cross the axis **jumps by 90°**: [`Curvatures::new`] reports φ = 0 for p ≤ q and π/2 for
//! p > q, and [`Curvatures::from_bodies`] swaps the eigenvectors. The contact-frame quantities
//! (v_Px, v_Py, F_x, F_y) jump with the frame, but the world force and torque do not: at e² = 0
//! the friction is isotropic (a rotation of the slip about z rotates the force with it), and e²
//! tends to 0 from both sides, so the world wrench is continuous across the crossing. Measured
//! (`host-tests/frame.rs`, g = P/Q = 1 ∓ ε): the jump in the world force is
//! at most 0.52·ε·fN (default law; 0.50·ε·fN with `Simplified`), against a contact-frame jump of
//! order fN.
//!
//! # Cost
//!
//! [`Frame::new`]: a cross product and two scaled sums (18 multiplies, 9 additions; no division,
//! no root); [`Frame::from_reference`] adds the projection, a square root and a division. The
//! slip is two dot products (three with ḣ), the load on a body a 3 × 3 product, a cross product
//! and a scaled add. Measured on the Cortex-M4F (QEMU instructions per call, frame built in the
//! call, `bench-results/qemu.csv` stage `frame`): `Frame::new` + slip + ḣ **77** (`f32`; 4,490
//! `f64`, soft float), `Frame::new` + [`ContactFrame::on_b`] **68** (`f32`; 5,515 `f64`), against
//! 182 for the wrench itself ([`crate::contact::Contact::wrench`], `Best`). Where the contact
//! frame is the world frame (a floor under the body), [`WorldAxes`] does the same with no
//! arithmetic. No panic, no allocation; finite input gives a finite output.
//!
//! # Example
//!
//! ```
//! use contensou::contact::Contact;
//! use contensou::frame::{ContactFrame, Frame, MajorAxis, point_velocity};
//! use contensou::friction::Friction;
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::shape::Newton;
//!
//! // A 10 mm steel ball (B) on a steel floor (A, at rest), centre G at height R − h.
//! let (r, h) = (10e-3, 1e-6);
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::sphere_plane(r)?,
//!     Modulus::new(1.153846e11)?,
//!     Undamped,
//!     Friction::<f64>::new(0.1, 1e-6)?,
//! )?;
//! // Floor normal up (A → B), world x as the reference tangent; a circle's major axis is any.
//! let frame = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::ALONG);
//! let arm = [0.0, 0.0, -(r - h)]; // G → P
//! let (v, w) = ([1.0, 0.0, 0.0], [0.0, 0.0, 100.0]); // sliding along x, spinning about z
//! let v_rel = point_velocity(v, w, arm); // the floor's point P is at rest
//! let wrench = contact.wrench(h, frame.approach_rate(v_rel), frame.slip(v_rel, w)?);
//! let on_ball = frame.on_b(&wrench, arm); // force, and torque about G
//! assert!(on_ball.force[0] < 0.0 && on_ball.force[2] > 0.0); // friction opposes the slip
//! assert!(on_ball.torque[2] < 0.0 && on_ball.torque[1] > 0.0); // spin braked, rolling spun up
//! # Ok::<(), contensou::Error>(())
//! ```

use crate::contact::Wrench;
use crate::friction::Slip;
use crate::geometry::Curvatures;
use crate::{Error, Real};

/// A world-frame 3-vector (SI units of whatever it holds).
pub type Vector<T> = [T; 3];

/// The direction of the contact ellipse's major axis in the tangent plane: cos φ and sin φ of
/// the angle φ from the reference tangent t₁ towards t₂ = z × t₁ (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MajorAxis<T> {
    cos: T,
    sin: T,
}

impl<T: Real> MajorAxis<T> {
    /// φ = 0: the major axis along the reference tangent (also any axis of a circular patch).
    pub const ALONG: Self = MajorAxis {
        cos: T::ONE,
        sin: T::ZERO,
    };

    /// φ = π/2: the major axis along t₂ = z × t₁, exactly (no rounding of cos π/2).
    pub const ACROSS: Self = MajorAxis {
        cos: T::ZERO,
        sin: T::ONE,
    };

    /// From cos φ and sin φ (e.g. from a per-step geometry computation; no trigonometry).
    /// The pair should be unit to rounding: it is not renormalised, and a pair of norm k
    /// scales the frame's x and y by k.
    #[inline(always)]
    pub fn from_cos_sin(cos: T, sin: T) -> Self {
        MajorAxis { cos, sin }
    }

    /// From the angle φ (rad): one `sin_cos`.
    #[inline]
    pub fn from_angle(phi: T) -> Self {
        let (sin, cos) = phi.sin_cos();
        MajorAxis { cos, sin }
    }

    /// The major axis of `curvatures`, [`Curvatures::major_angle`] from the frame its
    /// constructor measured in (body A's first principal direction, or the (x′, y′) of
    /// [`Curvatures::new`]), which is then the reference tangent. The two angles that
    /// [`Curvatures::new`] reports, 0 and π/2, give exactly [`MajorAxis::ALONG`] and
    /// [`MajorAxis::ACROSS`].
    #[inline]
    pub fn of(curvatures: &Curvatures<T>) -> Self {
        let phi = curvatures.major_angle();
        if phi == T::ZERO {
            Self::ALONG
        } else if phi == T::FRAC_PI_2 {
            Self::ACROSS
        } else {
            Self::from_angle(phi)
        }
    }

    /// cos φ.
    #[inline(always)]
    pub fn cos(&self) -> T {
        self.cos
    }

    /// sin φ.
    #[inline(always)]
    pub fn sin(&self) -> T {
        self.sin
    }
}

/// The contact frame's axes as world vectors (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<T> {
    x: Vector<T>,
    y: Vector<T>,
    z: Vector<T>,
}

/// A force and a torque on one body, world frame (N, N·m).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Load<T> {
    /// The force (N), acting at the patch centre P.
    pub force: Vector<T>,
    /// The torque (N·m) about the point the arm was measured from (e.g. the centre of mass).
    pub torque: Vector<T>,
}

impl<T: Real> Frame<T> {
    /// From the unit `normal` z (A → B) and a unit `tangent` t₁ ⊥ z, both world vectors,
    /// taken as they are (no renormalisation: that is [`Frame::from_reference`]), and the
    /// major axis. An orthonormal input gives an orthonormal, right-handed frame to rounding.
    #[inline]
    pub fn new(normal: Vector<T>, tangent: Vector<T>, major: MajorAxis<T>) -> Self {
        let t2 = cross(normal, tangent);
        let (c, s) = (major.cos, major.sin);
        let x = add(scale(tangent, c), scale(t2, s));
        let y = add(scale(tangent, -s), scale(t2, c));
        Frame { x, y, z: normal }
    }

    /// As [`Frame::new`] but from any `reference` vector (world or a body's axis mapped to the
    /// world): its part in the tangent plane, normalised, is t₁. The `normal` must still be
    /// unit. If that part vanishes (reference along the normal, or zero), t₁ is the world
    /// axis least aligned with the normal, projected: the frame is then orthonormal but its
    /// orientation about z arbitrary (fine for a circular patch only).
    #[inline]
    pub fn from_reference(normal: Vector<T>, reference: Vector<T>, major: MajorAxis<T>) -> Self {
        let t = tangent_part(normal, reference);
        let t = match normalised(t) {
            Some(t) => t,
            None => {
                let [ax, ay, az] = normal.map(T::abs);
                let axis = if ax <= ay && ax <= az {
                    [T::ONE, T::ZERO, T::ZERO]
                } else if ay <= az {
                    [T::ZERO, T::ONE, T::ZERO]
                } else {
                    [T::ZERO, T::ZERO, T::ONE]
                };
                // At least √(2/3) of a unit axis survives the projection.
                normalised(tangent_part(normal, axis)).unwrap_or(axis)
            }
        };
        Self::new(normal, t, major)
    }

    /// The major axis x (world).
    #[inline(always)]
    pub fn x(&self) -> Vector<T> {
        self.x
    }

    /// The minor axis y = z × x (world).
    #[inline(always)]
    pub fn y(&self) -> Vector<T> {
        self.y
    }

    /// The normal z, from A into B (world).
    #[inline(always)]
    pub fn z(&self) -> Vector<T> {
        self.z
    }
}

/// The conversions every contact frame offers: [`Frame`] (any orientation) and [`WorldAxes`]
/// (the world axes themselves) implement the four primitives, and the slip, ḣ and the loads
/// follow from them once, here.
pub trait ContactFrame<T: Real> {
    /// A world vector's components in the contact frame (along x, y, z).
    fn to_contact(&self, v: Vector<T>) -> Vector<T>;

    /// A contact-frame vector (components along x, y, z) in the world.
    fn to_world(&self, c: Vector<T>) -> Vector<T>;

    /// The normal component v·z of a world vector.
    fn normal_part(&self, v: Vector<T>) -> T;

    /// The world vector s·z.
    fn along_normal(&self, s: T) -> Vector<T>;

    /// The slip from the relative velocity at P, `v_rel` = v_B(P) − v_A(P), and the relative
    /// angular velocity `w_rel` = ω_B − ω_A (world vectors): v_P = (v_rel·x, v_rel·y),
    /// ω = w_rel·z. Errors: [`Error::NonFinite`] (from [`Slip::new`]) if a component is not
    /// finite.
    #[inline(always)]
    fn slip(&self, v_rel: Vector<T>, w_rel: Vector<T>) -> Result<Slip<T>, Error> {
        let [vx, vy, _] = self.to_contact(v_rel);
        Slip::new(vx, vy, self.normal_part(w_rel))
    }

    /// ḣ = −v_rel·z, the rate of the approach (ḣ > 0: the bodies move into each other,
    /// compression), from the same `v_rel` as [`ContactFrame::slip`].
    #[inline(always)]
    fn approach_rate(&self, v_rel: Vector<T>) -> T {
        -self.normal_part(v_rel)
    }

    /// The wrench's force in the world: F = F_x·x + F_y·y + N·z, on body B.
    #[inline(always)]
    fn force<B>(&self, w: &Wrench<T, B>) -> Vector<T> {
        self.to_world([w.fx, w.fy, w.n])
    }

    /// The load on body B: the force F at P and the torque (P − C) × F + T_z·z about the point
    /// C with `arm` = P − C (world; e.g. C = B's centre of mass).
    #[inline(always)]
    fn on_b<B>(&self, w: &Wrench<T, B>, arm: Vector<T>) -> Load<T> {
        let force = self.force(w);
        Load {
            force,
            torque: add(cross(arm, force), self.along_normal(w.tz)),
        }
    }

    /// The load on body A (the reaction): −F at P and (P − C_A) × (−F) − T_z·z about the point
    /// C_A with `arm` = P − C_A (world; e.g. A's centre of mass).
    #[inline(always)]
    fn on_a<B>(&self, w: &Wrench<T, B>, arm: Vector<T>) -> Load<T> {
        let Load { force, torque } = self.on_b(w, arm);
        Load {
            force: force.map(|c| -c),
            torque: torque.map(|c| -c),
        }
    }
}

impl<T: Real> ContactFrame<T> for Frame<T> {
    #[inline(always)]
    fn to_contact(&self, v: Vector<T>) -> Vector<T> {
        [dot(v, self.x), dot(v, self.y), dot(v, self.z)]
    }

    #[inline(always)]
    fn to_world(&self, c: Vector<T>) -> Vector<T> {
        let [cx, cy, cz] = c;
        add(add(scale(self.x, cx), scale(self.y, cy)), scale(self.z, cz))
    }

    #[inline(always)]
    fn normal_part(&self, v: Vector<T>) -> T {
        dot(v, self.z)
    }

    #[inline(always)]
    fn along_normal(&self, s: T) -> Vector<T> {
        scale(self.z, s)
    }
}

/// The contact frame that **is** the world frame: normal z = world +z (body A a horizontal
/// floor below body B), major axis x = world x (or any, for a circular patch). The same
/// conversions as `Frame::new([0, 0, 1], [1, 0, 0], MajorAxis::ALONG)` with no arithmetic:
/// floats cannot drop a multiplication by 0 or 1 (NaN, ∞ and −0 forbid it), so the general
/// frame costs its dot products even there (measured: 68 more Cortex-M4F instructions per
/// sphere in the tippe top's step, f32). Equal results (`host-tests/frame.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WorldAxes;

impl<T: Real> ContactFrame<T> for WorldAxes {
    #[inline(always)]
    fn to_contact(&self, v: Vector<T>) -> Vector<T> {
        v
    }

    #[inline(always)]
    fn to_world(&self, c: Vector<T>) -> Vector<T> {
        c
    }

    #[inline(always)]
    fn normal_part(&self, v: Vector<T>) -> T {
        v[2]
    }

    #[inline(always)]
    fn along_normal(&self, s: T) -> Vector<T> {
        [T::ZERO, T::ZERO, s]
    }
}

/// The velocity of a body's material point at `arm` from its centre of mass: v + ω × arm
/// (world vectors; v the centre's velocity, ω the body's angular velocity).
#[inline(always)]
pub fn point_velocity<T: Real>(v: Vector<T>, w: Vector<T>, arm: Vector<T>) -> Vector<T> {
    add(v, cross(w, arm))
}

#[inline(always)]
fn dot<T: Real>(a: Vector<T>, b: Vector<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
fn cross<T: Real>(a: Vector<T>, b: Vector<T>) -> Vector<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline(always)]
fn add<T: Real>(a: Vector<T>, b: Vector<T>) -> Vector<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline(always)]
fn scale<T: Real>(a: Vector<T>, s: T) -> Vector<T> {
    a.map(|c| c * s)
}

/// r − (r·n)n.
#[inline(always)]
fn tangent_part<T: Real>(n: Vector<T>, r: Vector<T>) -> Vector<T> {
    add(r, scale(n, -dot(r, n)))
}

/// t/|t|, or `None` if |t|² is zero, subnormal or not finite.
#[inline(always)]
fn normalised<T: Real>(t: Vector<T>) -> Option<Vector<T>> {
    let n2 = dot(t, t);
    if n2.is_positive_normal() {
        Some(scale(t, T::ONE / n2.sqrt()))
    } else {
        None
    }
}
