// The per-step call of a `contensou::select` scene, shared verbatim (`include!`) by the QEMU
// stage `bench_scene.rs` and the size probe `bin/probe.rs`: both contact forms behind one
// signature, and the constructor input of each geometry kind.

use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::friction::FrictionLaw;
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, Undamped};

/// One step of either contact form: (curvatures of this step, h, slip) → wrench (ḣ = 0).
trait SceneStep<T: Real> {
    type Branch;
    fn step(&self, curv: &Curvatures<T>, h: T, slip: Slip<T>) -> Wrench<T, Self::Branch>;
}

impl<T: Real, L: FrictionLaw> SceneStep<T> for Contact<T, Hertz<T>, Undamped, L> {
    type Branch = L::Branch;
    #[inline(always)]
    fn step(&self, _: &Curvatures<T>, h: T, slip: Slip<T>) -> Wrench<T, L::Branch> {
        self.wrench(h, T::ZERO, slip)
    }
}

impl<T: Real, L: FrictionLaw> SceneStep<T> for VaryingContact<T, Undamped, L> {
    type Branch = L::Branch;
    #[inline(always)]
    fn step(&self, curv: &Curvatures<T>, h: T, slip: Slip<T>) -> Wrench<T, L::Branch> {
        self.wrench(curv, h, T::ZERO, slip)
    }
}

/// The constructor input of a geometry kind: the curvatures for a fixed contact, `()` for a
/// varying one.
trait FromCurvatures<T> {
    fn of(curv: &Curvatures<T>) -> Self;
}

impl<T: Copy> FromCurvatures<T> for Curvatures<T> {
    fn of(curv: &Curvatures<T>) -> Self {
        *curv
    }
}

impl<T> FromCurvatures<T> for () {
    fn of(_: &Curvatures<T>) -> Self {}
}
