//! # Guide: a contact in your own loop
//!
//! What you need to wire [`Contact`] into your own integrator: which body is which, the contact
//! frame, the approach h and its rate ḣ, the slip and spin from the two bodies' states, where
//! the normal force, the friction force and the drilling torque act, and how they become a
//! force and a torque about each body's centre of mass. The [`frame`] module does the
//! geometry; `examples/ball_on_plane.rs` is the worked example, tested against the analytic
//! solution (`host-tests/ball_on_plane.rs`). This page holds documentation only.
//!
//! ## 1. Bodies A and B
//!
//! Every force and torque the library returns is the one **on body B from body A** (crate
//! conventions). Call the body "below" A (a floor, a raceway, the fixed part) and the other B;
//! A receives the opposite force. Swapping them flips every sign, so pick once and stay with it.
//!
//! ## 2. The contact frame
//!
//! P x y z: origin at the patch centre P; **z the common normal, from A into B**; x along the
//! **major** semi-axis a of the contact ellipse, y = z × x along the minor one. Everything
//! [`Contact::wrench`] takes (slip) and returns ([`Wrench`]) is in this frame.
//!
//! - The major axis is the direction of the smaller coefficient of the relative surface
//!   z = P x² + Q y² (0 < P ≤ Q). [`Curvatures`] reports where it lies:
//!   [`Curvatures::major_angle`] from the frame its constructor used (body A's first principal
//!   direction for [`Curvatures::from_bodies`]; the (x′, y′) of [`Curvatures::new`], which swaps
//!   p and q, and reports π/2, when p > q).
//! - [`frame::Frame`] builds the frame in the world from the unit normal, that reference tangent
//!   and the angle ([`frame::MajorAxis`], cos/sin, so firmware needs no trigonometry).
//! - A circle (sphere on plane, sphere on sphere) has every tangent as a major axis: any
//!   tangent will do, e.g. the world x projected on the tangent plane
//!   ([`frame::Frame::from_reference`]). A floor whose normal is the world +z (and a circle,
//!   or a major axis along world x) needs no frame arithmetic at all: [`frame::WorldAxes`].
//! - The conversions are the methods of the [`frame::ContactFrame`] trait (import it).
//! - Where the curvatures cross (P = Q, e² = 0) the major axis jumps by 90°; the world force
//!   does not (see [`frame`], "Where the curvatures cross"): convert back to the world with the
//!   same frame you used for the slip, and nothing jumps.
//!
//! ## 3. The approach h and its rate ḣ
//!
//! h (m) is the overlap of the undeformed surfaces along the normal: h > 0 in contact, h ≤ 0
//! apart (the wrench is then zero, not an error). For a sphere of radius R on a plane,
//! h = R − (height of its centre above the plane); for two spheres, h = R_A + R_B − |G_B − G_A|.
//!
//! **ḣ = dh/dt > 0 is compression** (the bodies move into each other): with v_rel the velocity
//! of B's material point at P minus A's, ḣ = −v_rel·z ([`frame::Frame::approach_rate`]).
//! Only the damping laws read it ([`normal::Damping`]: [`normal::HuntCrossley`],
//! [`normal::CompressionDamping`]); [`normal::Undamped`] ignores it.
//!
//! ## 4. Slip and spin from the bodies' states
//!
//! With each body's centre of mass G, its velocity v and angular velocity ω (world vectors):
//!
//! ```text
//! v_rel = (v_B + ω_B × (P − G_B)) − (v_A + ω_A × (P − G_A))      frame::point_velocity
//! v_P   = (v_rel·x, v_rel·y),    ω = (ω_B − ω_A)·z                 Frame::slip
//! ```
//!
//! v_P is the slip of B over A at the patch centre, ω the relative spin about the normal (the
//! drilling). The relative rolling (ω_rel in the tangent plane) does not enter the friction
//! model. [`friction::Slip::new`] rejects a NaN or ∞ (a diverged state); the per-step call
//! itself is total.
//!
//! ## 5. Where N, F and T_z act
//!
//! N (along +z), F = (F_x, F_y) act **at the patch centre P**; T_z is a pure couple about z (the
//! integral of the friction traction's moment about P over the patch). In the world, on B:
//!
//! ```text
//! F_B = F_x·x + F_y·y + N·z
//! τ_B = (P − G_B) × F_B + T_z·z            about B's centre of mass G_B
//! F_A = −F_B,  τ_A = (P − G_A) × F_A − T_z·z   about A's centre of mass G_A
//! ```
//!
//! [`frame::Frame::on_b`] and [`frame::Frame::on_a`] return exactly these
//! ([`frame::Load`]). Add them to the bodies' other forces; integrate.
//!
//! ## 6. One step
//!
//! A ball (B) on a fixed plane (A): build the contact once, then per step compute h, the slip,
//! the wrench and the load.
//!
//! ```
//! use contensou::contact::Contact;
//! use contensou::frame::{ContactFrame, Frame, MajorAxis, point_velocity};
//! use contensou::friction::Friction;
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Material, Modulus, NormalLaw, Undamped};
//! use contensou::shape::Newton;
//!
//! let (r, mass) = (10e-3, 32.67e-3);
//! let steel = Material::new(2.1e11, 0.3)?;
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::sphere_plane(r)?,
//!     Modulus::of(steel, steel)?,
//!     Undamped,
//!     Friction::<f64>::new(0.1, 1e-4)?, // the default law, `Best`
//! )?;
//! let h0 = contact.normal().approach(mass * 9.81); // resting: N = mg
//! let plane = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::ALONG);
//! let (g, v, w) = ([0.0, 0.0, r - h0], [1.0, 0.0, 0.0], [0.0, 0.0, 100.0]);
//!
//! // Per step:
//! let h = r - g[2];
//! let arm = [0.0, 0.0, -g[2]]; // P − G: P is the plane's point under the centre
//! let v_rel = point_velocity(v, w, arm); // the plane is at rest
//! let wrench = contact.wrench(h, plane.approach_rate(v_rel), plane.slip(v_rel, w)?);
//! let on_ball = plane.on_b(&wrench, arm);
//! assert!((on_ball.force[2] / (mass * 9.81) - 1.0).abs() < 1e-9); // N = mg
//! assert!(on_ball.force[0] < 0.0); // friction opposes the slip
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! `examples/ball_on_plane.rs` runs this loop with semi-implicit Euler from a 1 m/s slide and a
//! 100 rad/s spin: pure rolling at t = 0.29132 s against (2/7)·v₀/(f g) = 0.29125 s (+0.025 %),
//! at 0.71456 m/s against (5/7)·v₀ = 0.71429 m/s (+0.039 %), then the spin decays at
//! 0.397511 rad/s² against (3π/16)·f·N·a/I = 0.397511 rad/s² (1.3e-9 relative).
//!
//! ## 7. The time step
//!
//! The friction law is regularized near rest (a ramp of width δ, the regularization speed of
//! [`friction::Friction::new`]), and the ramp is stiff: an explicit step must stay below
//! [`Contact::stable_step`] for the slip and [`Contact::stable_spin_step`] for the spin.
//! Their mass and inertia are the **effective** ones at the contact point: for a solid ball
//! rolling on its surface 2m/7 (a force at P moves the slip through both translation and
//! rotation), not m; about the normal, the ball's own I (both bodies free: 1/(1/I_A + 1/I_B)).
//! The normal contact is an oscillator too: ω_n² = (dN/dh)/m_eff with dN/dh = (3/2)·N/h
//! (Hertz); explicit and semi-implicit Euler need a step below 2/ω_n, and resolving the contact
//! takes a few tens of steps per period 2π/ω_n.
//!
//! ## 8. Fixed or varying geometry; damping
//!
//! - [`Contact`]: the curvatures never change (a ball on a plane, a ball in a given raceway):
//!   everything but h is precomputed. [`VaryingContact`]: the curvatures change every step (a
//!   contact point wandering over a non-spherical body): pass this step's [`Curvatures`] to
//!   [`VaryingContact::wrench`], and build this step's frame from its major axis.
//! - Impacts: [`normal::HuntCrossley`]'s c_d sets the restitution, e ≈ 1 − c_d·v for a
//!   small impact speed v (its docs give the derivation and the measured accuracy).
//!
//! [`Contact`]: crate::contact::Contact
//! [`Contact::wrench`]: crate::contact::Contact::wrench
//! [`Contact::stable_step`]: crate::contact::Contact::stable_step
//! [`Contact::stable_spin_step`]: crate::contact::Contact::stable_spin_step
//! [`VaryingContact`]: crate::contact::VaryingContact
//! [`VaryingContact::wrench`]: crate::contact::VaryingContact::wrench
//! [`Wrench`]: crate::contact::Wrench
//! [`Curvatures`]: crate::geometry::Curvatures
//! [`Curvatures::major_angle`]: crate::geometry::Curvatures::major_angle
//! [`Curvatures::new`]: crate::geometry::Curvatures::new
//! [`Curvatures::from_bodies`]: crate::geometry::Curvatures::from_bodies
//! [`frame`]: crate::frame
//! [`frame::Frame`]: crate::frame::Frame
//! [`frame::MajorAxis`]: crate::frame::MajorAxis
//! [`frame::Load`]: crate::frame::Load
//! [`frame::WorldAxes`]: crate::frame::WorldAxes
//! [`frame::ContactFrame`]: crate::frame::ContactFrame
//! [`frame::Frame::from_reference`]: crate::frame::Frame::from_reference
//! [`frame::Frame::approach_rate`]: crate::frame::ContactFrame::approach_rate
//! [`frame::Frame::on_b`]: crate::frame::ContactFrame::on_b
//! [`frame::Frame::on_a`]: crate::frame::ContactFrame::on_a
//! [`friction::Slip::new`]: crate::friction::Slip::new
//! [`friction::Friction::new`]: crate::friction::Friction::new
//! [`normal::Damping`]: crate::normal::Damping
//! [`normal::HuntCrossley`]: crate::normal::HuntCrossley
//! [`normal::CompressionDamping`]: crate::normal::CompressionDamping
//! [`normal::Undamped`]: crate::normal::Undamped
