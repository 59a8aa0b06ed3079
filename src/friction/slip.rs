//! The slip state: the validated dimensional input and the friction core's homogeneous form.
//!
//! Every law here is homogeneous of degree 0 in (v_Px, v_Py, aω) — only the direction of that
//! triple matters — except for the regularization speed δ, which is measured in the same unit.
//! The core therefore takes the triple divided by its size,
//!
//! ```text
//! (x, y, w) = (v_Px, v_Py, aω)/s,   d = δ/s,   s = |v_Px| + |v_Py| + a|ω|
//! ```
//!
//! (the ℓ¹ norm: two additions instead of two compare-and-selects; where s would be subnormal
//! or overflow, the largest magnitude instead), so that every component lies in [−1, 1] and
//! max(|x|, |y|, |w|) ≥ 1/3 (or everything is 0: no slip). This never overflows or underflows
//! where it matters, unlike u = v/(aω) (∞ at ω = 0, 0/0 at rest, denormal at tiny speeds). In the core's terms u = √(x² + y²)/|w|, cos ψ = x/√(x² + y²), sin ψ = y/√(x² + y²).

use super::larger;
use crate::error::finite;
use crate::{Error, Real};

/// A validated slip: v_P = (`vx`, `vy`) (m/s), the velocity of body B relative to body A at the
/// patch centre in the contact frame, and `omega` (rad/s), the relative spin about the normal z.
///
/// [`Slip::new`] rejects NaN and ±∞ and [`Slip::or_rest`] replaces them by the rest slip, so
/// every `Slip` is finite and the per-step friction call that takes it is total. From two bodies' world velocities:
/// [`crate::frame::ContactFrame::slip`].
///
/// # Example
///
/// ```
/// use contensou::Error;
/// use contensou::friction::Slip;
///
/// // B slides over A at 2 cm/s along the major axis and spins at 10 rad/s about the normal.
/// let slip = Slip::new(0.02, 0.0, 10.0)?;
/// assert_eq!((slip.vx(), slip.vy(), slip.omega()), (0.02, 0.0, 10.0));
/// // A diverged state is refused, naming the input.
/// assert_eq!(Slip::new(f64::NAN, 0.0, 0.0), Err(Error::NonFinite("v_Px")));
/// assert_eq!(Slip::<f32>::default().omega(), 0.0); // rest
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Slip<T> {
    vx: T,
    vy: T,
    omega: T,
}

impl<T: Real> Slip<T> {
    /// From v_P = (vx, vy) in m/s and ω in rad/s. Errors: [`Error::NonFinite`] naming `"v_Px"`,
    /// `"v_Py"` or `"omega"` if that input is NaN or ±∞. Any finite values are accepted,
    /// including zero and subnormal ones.
    #[inline]
    pub fn new(vx: T, vy: T, omega: T) -> Result<Self, Error> {
        Ok(Slip {
            vx: finite(vx, "v_Px")?,
            vy: finite(vy, "v_Py")?,
            omega: finite(omega, "omega")?,
        })
    }
    /// The slip (vx, vy, ω) if all three are finite, else the rest slip ([`Slip::default`],
    /// all zero): for per-step loops whose inputs are finite unless the whole state is lost
    /// (a scene's right-hand side). One finiteness test, on vx + vy + ω — finite exactly when no
    /// input is NaN or ±∞, unless finite inputs overflow the sum (|values| ≈ `T::MAX`), which
    /// also gives the rest slip — where [`Slip::new`] tests each input (on the M4F ≈4
    /// instructions each).
    #[inline(always)]
    pub fn or_rest(vx: T, vy: T, omega: T) -> Self {
        if (vx + vy + omega).is_finite() {
            Slip { vx, vy, omega }
        } else {
            Slip::default()
        }
    }

    /// The slip from the components of one already validated ([`Slip::new`]: each finite),
    /// carried into another [`Real`] (the Jacobian's dual numbers): no test. Unlike
    /// [`Slip::or_rest`] it keeps finite components whose sum overflows (|v| near `T::MAX`),
    /// as the validated slip does.
    #[inline(always)]
    pub(crate) fn from_valid(vx: T, vy: T, omega: T) -> Self {
        Slip { vx, vy, omega }
    }

    /// v_Px (m/s)
    #[inline(always)]
    pub fn vx(&self) -> T {
        self.vx
    }
    /// v_Py (m/s)
    #[inline(always)]
    pub fn vy(&self) -> T {
        self.vy
    }
    /// ω (rad/s)
    #[inline(always)]
    pub fn omega(&self) -> T {
        self.omega
    }
}

/// s = |vx| + |vy| + |aw| (≥ 0, or +∞ if |aw| overflowed).
#[inline(always)]
fn l1<T: Real>(vx: T, vy: T, aw: T) -> T {
    vx.abs() + vy.abs() + aw.abs()
}

/// The slip in the friction core's homogeneous form (see the [module docs](self)):
/// (x, y, w) = (v_Px, v_Py, aω)/s and d = δ/s with s = |v_Px| + |v_Py| + a|ω|.
///
/// Invariants: x, y, w lie in [−1, 1] with max(|x|, |y|, |w|) ≥ 1/3, or all three are 0 (no
/// slip); d ≥ `T::MIN_POSITIVE` (the smallest normal number), possibly +∞
/// (δ > 0 at a vanishing slip speed). The floor means δ = 0 acts as a regularization width of
/// 1e-38·s (`f32`) or 2e-308·s (`f64`), far below rounding; it spares the laws a test for
/// 0/0 at rest.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlipState<T> {
    x: T,
    y: T,
    w: T,
    d: T,
}

impl<T: Real> SlipState<T> {
    /// From a validated slip, the major semi-axis `a` (m) and the regularization speed `delta`
    /// (m/s). `a` is read as 0 (point contact) unless it is > 0, `delta` as 0 (no
    /// regularization) unless it is > 0; a·ω overflowing to ±∞ is read as pure spin. Total.
    #[inline]
    pub fn from_slip(slip: Slip<T>, a: T, delta: T) -> Self {
        Self::from_clamped(slip, a.max(T::ZERO), delta.max(T::ZERO))
    }

    /// [`SlipState::from_slip`] for a ≥ 0 and δ ≥ 0 already checked.
    #[inline(always)]
    pub(crate) fn from_clamped(slip: Slip<T>, a: T, delta: T) -> Self {
        Self::normalised(slip.vx, slip.vy, a * slip.omega, delta)
    }

    /// The per-step path in two halves, for a ≥ 0 already checked: (aω, s) first, so that the
    /// wrapper can gate its ramp on s against δ before the division; then
    /// [`SlipState::from_scale`].
    #[inline(always)]
    pub(crate) fn scale_of(slip: Slip<T>, a: T) -> (T, T) {
        let aw = a * slip.omega;
        (aw, l1(slip.vx, slip.vy, aw))
    }

    /// The state from (aω, s) = [`SlipState::scale_of`]`(slip, a)` and δ ≥ 0: the same as
    /// [`SlipState::from_clamped`]`(slip, a, delta)`.
    #[inline(always)]
    pub(crate) fn from_scale(slip: Slip<T>, aw: T, s: T, delta: T) -> Self {
        Self::divided(slip.vx, slip.vy, aw, s, delta)
    }

    /// The dimensionless state of the paper's figures: v_P = u·aω·(cos ψ, sin ψ) with ω > 0 and
    /// δ → 0 (no regularization). `u = +∞` is pure translation; a negative `u` means the
    /// direction ψ + π. Errors: [`Error::NonFinite`] (`"psi"` or `"u"`) if ψ is not finite or u
    /// is NaN. Costs a sine and a cosine: for tests, tools and the evaluator, not for the hot path.
    pub fn from_polar(psi: T, u: T) -> Result<Self, Error> {
        let psi = finite(psi, "psi")?;
        if !(u.is_finite() || u.abs() > T::ONE) {
            return Err(Error::NonFinite("u"));
        }
        let (s, c) = psi.sin_cos();
        Ok(if u.abs() <= T::ONE {
            Self::normalised(u * c, u * s, T::ONE, T::ZERO)
        } else {
            // 1/u is 0 for u = ±∞: pure translation.
            let sign = T::ONE.copysign(u);
            Self::normalised(sign * c, sign * s, T::ONE / u.abs(), T::ZERO)
        })
    }

    /// From raw components in any common velocity unit: v_P = (vx, vy), the spin speed aω and
    /// δ. Errors: [`Error::NonFinite`] (`"v_Px"`, `"v_Py"`, `"a_omega"` or `"delta"`) for NaN or
    /// ±∞; a negative δ is read as 0.
    pub fn new(vx: T, vy: T, a_omega: T, delta: T) -> Result<Self, Error> {
        let vx = finite(vx, "v_Px")?;
        let vy = finite(vy, "v_Py")?;
        let aw = finite(a_omega, "a_omega")?;
        let delta = finite(delta, "delta")?;
        Ok(Self::normalised(vx, vy, aw, delta.max(T::ZERO)))
    }

    /// Divide by s = |vx| + |vy| + |aw|. vx, vy finite, aw finite or ±∞ (an overflowed
    /// product of finite a and ω), δ ≥ 0 finite.
    #[inline(always)]
    fn normalised(vx: T, vy: T, aw: T, delta: T) -> Self {
        Self::divided(vx, vy, aw, l1(vx, vy, aw), delta)
    }

    /// [`SlipState::normalised`] with s = |vx| + |vy| + |aw| given.
    #[inline(always)]
    fn divided(vx: T, vy: T, aw: T, s: T, delta: T) -> Self {
        // MIN_POSITIVE ≤ s ≤ MAX (s is ≥ 0 or +∞), one integer test on the bits.
        if s.is_positive_normal() {
            // 1/s is finite for every normal s.
            let inv = T::ONE / s;
            SlipState {
                x: vx * inv,
                y: vy * inv,
                w: aw * inv,
                d: larger(delta * inv, T::MIN_POSITIVE),
            }
        } else {
            Self::unusual(vx, vy, aw, delta)
        }
    }

    /// s subnormal, zero or overflowing: divide by the largest magnitude instead.
    #[cold]
    #[inline(never)]
    fn unusual(vx: T, vy: T, aw: T, delta: T) -> Self {
        let m = larger(larger(vx.abs(), vy.abs()), aw.abs());
        if !aw.is_finite() {
            // Only |aω| overflowing gets here: pure spin.
            SlipState {
                x: T::ZERO,
                y: T::ZERO,
                w: T::ONE.copysign(aw),
                d: T::MIN_POSITIVE,
            }
        } else if m > T::ZERO {
            SlipState {
                x: vx / m,
                y: vy / m,
                w: aw / m,
                d: larger(delta / m, T::MIN_POSITIVE),
            }
        } else {
            SlipState {
                x: T::ZERO,
                y: T::ZERO,
                w: T::ZERO,
                d: T::MIN_POSITIVE,
            }
        }
    }

    /// v_Px/s
    #[inline(always)]
    pub fn x(&self) -> T {
        self.x
    }
    /// v_Py/s
    #[inline(always)]
    pub fn y(&self) -> T {
        self.y
    }
    /// aω/s (carries the sign of ω)
    #[inline(always)]
    pub fn w(&self) -> T {
        self.w
    }
    /// max(δ/s, `T::MIN_POSITIVE`) (> 0, may be +∞)
    #[inline(always)]
    pub fn d(&self) -> T {
        self.d
    }
    /// No slip at all: v_P = 0 and ω = 0.
    #[inline(always)]
    pub fn is_rest(&self) -> bool {
        self.x == T::ZERO && self.y == T::ZERO && self.w == T::ZERO
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn or_rest_keeps_finite_slips_and_rests_otherwise() {
        let s = Slip::or_rest(0.25f32, -3.0, 1e30);
        assert_eq!(s, Slip::new(0.25, -3.0, 1e30).unwrap());
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert_eq!(Slip::or_rest(bad, 1.0, 2.0), Slip::default());
            assert_eq!(Slip::or_rest(1.0, bad, 2.0), Slip::default());
            assert_eq!(Slip::or_rest(1.0, 2.0, bad), Slip::default());
        }
        // +∞ and −∞ together: their sum is NaN.
        assert_eq!(
            Slip::or_rest(f64::INFINITY, f64::NEG_INFINITY, 0.0),
            Slip::default()
        );
        // Finite inputs whose sum overflows: the documented rest slip.
        assert_eq!(Slip::or_rest(f32::MAX, f32::MAX, 0.0), Slip::default());
    }
}
