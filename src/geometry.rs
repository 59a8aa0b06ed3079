//! Contact geometry: the two bodies' principal curvatures at the contact point → the relative
//! surface z = P x² + Q y² (0 < P ≤ Q) and the direction of the contact ellipse's major axis.
//!
//! # Formula
//!
//! Each body's surface near the contact point is z = ½(κ₁ξ² + κ₂η²) in its own principal
//! frame (ξ, η), with **signed** curvatures: positive where the surface bulges towards the other
//! body (a ball), negative where it is hollow (a raceway groove across its section, a cup),
//! zero for a plane. Body B's first principal direction makes the angle ω with body A's. In A's
//! principal frame the gap between the surfaces is the quadratic form
//!
//! ```text
//! M = ½·diag(κ₁ᴬ, κ₂ᴬ) + ½·R(ω) diag(κ₁ᴮ, κ₂ᴮ) R(ω)ᵀ,
//! P + Q = ½(κ₁ᴬ + κ₂ᴬ + κ₁ᴮ + κ₂ᴮ),   Q = tr M/2 + √((M₁₁ − M₂₂)²/4 + M₁₂²),   P = det M / Q
//! ```
//!
//! (P from det M / Q, not tr M/2 − √…, so that a conforming contact — P ≪ Q, e.g. a ball in a
//! groove — keeps P to a few ulps). The contact frame's x axis (major semi-axis a) is the
//! eigenvector of M for P (crate conventions).
//!
//! # Cost
//!
//! Construction only: one `hypot`, one `atan2`, one `sin_cos` and a division.

use crate::error::finite;
use crate::{Error, Real};

/// Principal curvatures κ₁, κ₂ (1/m) of one body's surface at the contact point, **signed**:
/// positive for a surface convex towards the other body, negative for a concave one (a groove,
/// a cup), zero for a plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Principal<T> {
    /// Curvature along the body's first principal direction.
    pub k1: T,
    /// Curvature along the second principal direction (perpendicular to the first).
    pub k2: T,
}

impl<T: Real> Principal<T> {
    /// A sphere of radius `r` (m): κ₁ = κ₂ = 1/r. A negative `r` is a concave spherical cup.
    pub fn sphere(r: T) -> Result<Self, Error> {
        let k = curvature_of_radius(r, "radius")?;
        Ok(Principal { k1: k, k2: k })
    }

    /// A plane: κ₁ = κ₂ = 0.
    pub fn plane() -> Self {
        Principal {
            k1: T::ZERO,
            k2: T::ZERO,
        }
    }
}

/// x > 0 (false for NaN).
#[inline(always)]
pub(crate) fn positive<T: Real>(x: T) -> bool {
    x > T::ZERO
}

/// 1/r for a signed radius; [`Error::LengthNotPositive`] for r = 0, [`Error::NonFinite`].
fn curvature_of_radius<T: Real>(r: T, name: &'static str) -> Result<T, Error> {
    let r = finite(r, name)?;
    if r == T::ZERO {
        return Err(Error::LengthNotPositive);
    }
    Ok(T::ONE / r)
}

/// `Ok(x)` if x is finite and > 0, else [`Error::LengthNotPositive`] / [`Error::NonFinite`].
fn positive_length<T: Real>(x: T, name: &'static str) -> Result<T, Error> {
    let x = finite(x, name)?;
    if x > T::ZERO {
        Ok(x)
    } else {
        Err(Error::LengthNotPositive)
    }
}

/// Which raceway of a ball bearing the ball touches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Race {
    /// The inner ring's raceway (convex along the rolling direction).
    Inner,
    /// The outer ring's raceway (concave along the rolling direction).
    Outer,
}

/// A validated relative surface z = P x² + Q y², 0 < P ≤ Q (1/m), with the direction of the
/// contact ellipse's major axis.
///
/// # Example
///
/// ```
/// use contensou::geometry::{Curvatures, Principal, Race};
/// use std::f64::consts::FRAC_PI_2;
///
/// // Coefficients in some frame (x′, y′), in either order: p > q is swapped, and the major
/// // axis (the smaller coefficient's direction) is then y′, at π/2.
/// let c = Curvatures::new(80.0, 20.0)?;
/// assert_eq!((c.p(), c.q(), c.major_angle()), (20.0, 80.0, FRAC_PI_2));
/// assert_eq!(c.ratio(), 0.25);
///
/// // A ball of radius 10 mm on a plane: P = Q = 1/(2R), a circle.
/// let ball = Curvatures::sphere_plane(10e-3)?;
/// assert_eq!((ball.p(), ball.q()), (50.0, 50.0));
///
/// // Two crossed cylinders of radius 10 mm and 20 mm (body B's axis at 90° to body A's).
/// let cyl = |r: f64| Principal { k1: 1.0 / r, k2: 0.0 };
/// let crossed = Curvatures::from_bodies(cyl(10e-3), cyl(20e-3), FRAC_PI_2)?;
/// assert!((crossed.p() - 25.0).abs() < 1e-12 && (crossed.q() - 50.0).abs() < 1e-12);
///
/// // A ball in a bearing's inner-race groove: the ellipse is long across the groove.
/// let race = Curvatures::ball_race(12.7e-3, 6.6e-3, 65e-3, 0.0, Race::Inner)?;
/// assert!(race.ratio() < 0.1 && (race.major_angle() - FRAC_PI_2).abs() < 1e-12);
/// assert!(Curvatures::new(0.0, 50.0).is_err()); // a plane on a plane: no Hertz contact
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curvatures<T> {
    p: T,
    q: T,
    major_angle: T,
}

impl<T: Real> Curvatures<T> {
    /// From the coefficients of z = p x'² + q y'² in some frame (x', y'), in either order.
    /// If p > q they are swapped and [`major_angle`](Self::major_angle) is π/2.
    ///
    /// Errors: [`Error::NonFinite`]; [`Error::CurvatureNotPositive`] if min(p, q) ≤ 0.
    pub fn new(p: T, q: T) -> Result<Self, Error> {
        let (p, q) = (finite(p, "P")?, finite(q, "Q")?);
        let (p, q, major_angle) = if p <= q {
            (p, q, T::ZERO)
        } else {
            (q, p, T::FRAC_PI_2)
        };
        if p > T::ZERO {
            Ok(Curvatures { p, q, major_angle })
        } else {
            Err(Error::CurvatureNotPositive)
        }
    }

    /// From the coefficients of z = p x² + q y² in a frame whose x must already be the major
    /// axis (0 < p ≤ q): nothing is swapped, [`major_angle`](Self::major_angle) is 0. This is
    /// the form of the wrench contract (`P,Q,…` columns; [`crate::dynamic`]).
    ///
    /// Errors: [`Error::NonFinite`]; [`Error::CurvaturesNotOrdered`] if p > q;
    /// [`Error::CurvatureNotPositive`] if p ≤ 0.
    pub fn ordered(p: T, q: T) -> Result<Self, Error> {
        let (p, q) = (finite(p, "P")?, finite(q, "Q")?);
        if p > q {
            return Err(Error::CurvaturesNotOrdered);
        }
        Self::new(p, q)
    }

    /// From two bodies' principal curvatures and the angle `omega` (rad) from body A's first
    /// principal direction to body B's. See the module docs for the formula.
    ///
    /// Errors: [`Error::NonFinite`] for any non-finite input; [`Error::CurvatureNotPositive`]
    /// if the bodies are not locally convex towards each other (P ≤ 0: no Hertz contact).
    pub fn from_bodies(a: Principal<T>, b: Principal<T>, omega: T) -> Result<Self, Error> {
        let (ka1, ka2) = (finite(a.k1, "body A k1")?, finite(a.k2, "body A k2")?);
        let (kb1, kb2) = (finite(b.k1, "body B k1")?, finite(b.k2, "body B k2")?);
        let omega = finite(omega, "omega")?;
        let (s, c) = omega.sin_cos();
        let half = T::HALF;
        let mxx = half * (ka1 + kb1 * c * c + kb2 * s * s);
        let myy = half * (ka2 + kb1 * s * s + kb2 * c * c);
        let mxy = half * (kb1 - kb2) * s * c;
        let d = half * (mxx - myy);
        let r = d.hypot(mxy);
        let q = half * (mxx + myy) + r;
        if !positive(q) {
            return Err(Error::CurvatureNotPositive);
        }
        let p = (mxx * myy - mxy * mxy) / q;
        if !positive(p) || !p.is_finite() {
            return Err(Error::CurvatureNotPositive);
        }
        // Eigenvector of the larger eigenvalue Q at φ = ½·atan2(2M₁₂, M₁₁ − M₂₂); the major
        // axis (eigenvalue P) is perpendicular to it. A circle (r = 0) reports 0.
        let major_angle = if r > T::ZERO {
            let phi = half * mxy.atan2(d);
            if phi > T::ZERO {
                phi - T::FRAC_PI_2
            } else {
                phi + T::FRAC_PI_2
            }
        } else {
            T::ZERO
        };
        Ok(Curvatures {
            p: p.min(q),
            q,
            major_angle,
        })
    }

    /// Sphere of radius `r` on a plane: P = Q = 1/(2r).
    ///
    /// Errors: [`Error::LengthNotPositive`] if r ≤ 0, [`Error::NonFinite`].
    pub fn sphere_plane(r: T) -> Result<Self, Error> {
        let r = positive_length(r, "radius")?;
        let p = T::HALF / r;
        Self::new(p, p)
    }

    /// Two spheres with **signed** radii (negative = concave: a ball inside a spherical cup,
    /// internal contact): P = Q = ½(1/r_a + 1/r_b).
    ///
    /// Errors: [`Error::LengthNotPositive`] for a zero radius, [`Error::CurvatureNotPositive`]
    /// if 1/r_a + 1/r_b ≤ 0 (the cup is smaller than the ball), [`Error::NonFinite`].
    pub fn sphere_sphere(r_a: T, r_b: T) -> Result<Self, Error> {
        let ka = curvature_of_radius(r_a, "radius A")?;
        let kb = curvature_of_radius(r_b, "radius B")?;
        let p = T::HALF * (ka + kb);
        Self::new(p, p)
    }

    /// A ball (body B) in a bearing raceway groove (body A; a torus), the standard
    /// deep-groove / angular-contact geometry. With γ = D cos α / d_m:
    ///
    /// ```text
    /// ball:        κ₁ = κ₂ = 2/D
    /// inner race:  κ₁ = +2 cos α/(d_m − D cos α)   (rolling direction),  κ₂ = −1/r_g
    /// outer race:  κ₁ = −2 cos α/(d_m + D cos α),                        κ₂ = −1/r_g
    /// ```
    ///
    /// `major_angle` is measured from the rolling direction: π/2 (the ellipse is long across
    /// the groove) whenever the groove conforms closely, which is the usual case.
    ///
    /// Errors: [`Error::LengthNotPositive`] if D, r_g or d_m ≤ 0; [`Error::NonFinite`];
    /// [`Error::CurvatureNotPositive`] if the ball does not fit the groove (r_g ≤ D/2) or
    /// the inner race would be concave (D cos α ≥ d_m).
    pub fn ball_race(
        ball_diameter: T,
        groove_radius: T,
        pitch_diameter: T,
        contact_angle: T,
        race: Race,
    ) -> Result<Self, Error> {
        let d = positive_length(ball_diameter, "ball diameter")?;
        let rg = positive_length(groove_radius, "groove radius")?;
        let dm = positive_length(pitch_diameter, "pitch diameter")?;
        let cos_a = finite(contact_angle, "contact angle")?.cos();
        let dc = d * cos_a;
        let rolling = match race {
            Race::Inner => {
                if !positive(dm - dc) {
                    return Err(Error::CurvatureNotPositive);
                }
                T::TWO * cos_a / (dm - dc)
            }
            Race::Outer => -T::TWO * cos_a / (dm + dc),
        };
        let race_body = Principal {
            k1: rolling,
            k2: -T::ONE / rg,
        };
        let ball = Principal {
            k1: T::TWO / d,
            k2: T::TWO / d,
        };
        Self::from_bodies(race_body, ball, T::ZERO)
    }

    /// P, the smaller coefficient (1/m); the major axis lies along its direction.
    #[inline(always)]
    pub fn p(&self) -> T {
        self.p
    }

    /// Q, the larger coefficient (1/m).
    #[inline(always)]
    pub fn q(&self) -> T {
        self.q
    }

    /// g = P/Q ∈ (0, 1]: the only input the eccentricity depends on.
    #[inline(always)]
    pub fn ratio(&self) -> T {
        self.p / self.q
    }

    /// Angle (rad, in (−π/2, π/2]) from body A's first principal direction (or the frame of
    /// [`Curvatures::new`]) to the major axis x of the contact frame. 0 for a circle.
    #[inline(always)]
    pub fn major_angle(&self) -> T {
        self.major_angle
    }

    /// Gaussian radius R_e = 1/(2√(PQ)) (m): the radius of the sphere-on-plane contact with
    /// the same Gaussian curvature 4PQ of the relative surface.
    #[inline(always)]
    pub fn gaussian_radius(&self) -> T {
        T::HALF / (self.p * self.q).sqrt()
    }
}
