//! Stage `frame`: `contensou::frame` per step, the geometry around a `Contact::wrench` call.
//!
//! - `slip`: `Frame::new` (unit normal, unit tangent, major axis as cos/sin) then `Frame::slip`
//!   and `Frame::approach_rate` from world v_rel, ω_rel.
//! - `load`: `Frame::new` then `Frame::on_b` (world force and torque about a point) from a
//!   wrench.
//!
//! Inputs: 16 frames (normals and tangents rotated about a tilted axis, major axis at 16
//! angles), world velocities and arms of order 1; a wrench of a 10 mm ball at 1 µm.

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, Wrench};
use contensou::frame::{ContactFrame, Frame, MajorAxis, Vector};
use contensou::friction::{Best, Friction, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::{Modulus, Undamped};

const N: usize = 16;

/// Normal, tangent, (cos, sin) of the major axis, and a world vector pair.
type SlipInput<T> = (Vector<T>, Vector<T>, (T, T), Vector<T>, Vector<T>);

#[inline(never)]
fn slip<T: Real>((n, t, (c, s), v, w): SlipInput<T>) -> (Result<Slip<T>, contensou::Error>, T) {
    let frame = Frame::new(n, t, MajorAxis::from_cos_sin(c, s));
    (frame.slip(v, w), frame.approach_rate(v))
}

type LoadInput<'a, T> = (
    Vector<T>,
    Vector<T>,
    (T, T),
    &'a Wrench<T, contensou::friction::best::Branch>,
    Vector<T>,
);

#[inline(never)]
fn load<T: Real>((n, t, (c, s), w, arm): LoadInput<'_, T>) -> contensou::frame::Load<T> {
    let frame = Frame::new(n, t, MajorAxis::from_cos_sin(c, s));
    frame.on_b(w, arm)
}

/// The i-th frame: normal (sin θ cos φ, sin θ sin φ, cos θ) and its tangent ∂/∂θ, orthonormal.
fn frame_inputs<T: Real>(i: usize) -> (Vector<T>, Vector<T>, (T, T)) {
    let c = T::from_f64;
    let theta = 0.3 + 0.1 * i as f64;
    let phi = 0.7 * i as f64;
    let (st, ct) = (libm::sin(theta), libm::cos(theta));
    let (sp, cp) = (libm::sin(phi), libm::cos(phi));
    let psi = core::f64::consts::PI * i as f64 / N as f64;
    (
        [c(st * cp), c(st * sp), c(ct)],
        [c(ct * cp), c(ct * sp), c(-st)],
        (c(libm::cos(psi)), c(libm::sin(psi))),
    )
}

fn stage<T: Real>(r: &Runner) {
    let c = T::from_f64;
    let inputs: [SlipInput<T>; N] = core::array::from_fn(|i| {
        let (n, t, axis) = frame_inputs::<T>(i);
        let k = i as f64;
        (
            n,
            t,
            axis,
            [c(0.3 - 0.05 * k), c(0.2), c(0.01 * k)],
            [c(1.0), c(-2.0 + 0.3 * k), c(50.0)],
        )
    });
    r.bench("frame", "slip", T::NAME, &inputs, slip::<T>);

    let Ok(contact) = Curvatures::sphere_plane(c(10e-3)).and_then(|curv| {
        Contact::circular(
            &curv,
            Modulus::new(c(1.15e11))?,
            Undamped,
            Friction::<T, Best>::with_law(c(0.1), c(1e-4))?,
        )
    }) else {
        return;
    };
    let w = contact.wrench(
        c(1e-6),
        T::ZERO,
        Slip::new(c(0.01), c(0.002), c(30.0)).unwrap_or_default(),
    );
    let inputs: [LoadInput<'_, T>; N] = core::array::from_fn(|i| {
        let (n, t, axis) = frame_inputs::<T>(i);
        (n, t, axis, &w, [c(0.001 * i as f64), c(-0.002), c(-0.01)])
    });
    r.bench("frame", "load", T::NAME, &inputs, load::<T>);
}

pub fn run(r: &Runner) {
    stage::<f32>(r);
    stage::<f64>(r);
}
