//! `on_plane(body, tangent)`: the one-contact inverse mass W of `body` (as body B, index 0)
//! touching the fixed plane z = 0 at the origin: normal +z, first tangent `tangent` (a unit
//! vector in the plane). A test crate includes it with `#[path = "common/on_plane.rs"] mod
//! on_plane;`.

use contensou::frame::{Frame, MajorAxis};
use contensou::step::{Body, ContactPoint, InverseMass};

/// W of `body` resting on the plane z = 0 at the origin (module docs).
pub fn on_plane(body: Body<f64>, tangent: [f64; 3]) -> InverseMass<f64, 1> {
    let frame = Frame::new([0.0, 0.0, 1.0], tangent, MajorAxis::from_cos_sin(1.0, 0.0));
    let cp = ContactPoint {
        a: None,
        b: Some(0),
        point: [0.0; 3],
        frame,
    };
    InverseMass::<f64, 1>::from_bodies(&[body], &[cp]).unwrap()
}
