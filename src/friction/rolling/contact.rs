//! The per-contact data of the rolling laws ([`RollingContact`]: shape, elasticity, Kalker's
//! coefficients, the full-slip tables), the per-call patch ([`Patch`]), the law interface
//! ([`RollingLaw`]) and the dimensional result ([`Wrench`]).

use super::{Elasticity, Kalker, RollingSlip, Scaled};
use crate::elliptic::Parameter;
use crate::error::finite;
use crate::friction::{BestContact, Constants, Slip, SlipState};
use crate::{Error, Real};

/// Forces (N) and moment about the patch centre (N·m) on body B from body A, in the rolling
/// frame (x along the rolling direction, z the contact normal).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Wrench<T> {
    /// F_x (N)
    pub fx: T,
    /// F_y (N)
    pub fy: T,
    /// M_z (N·m)
    pub mz: T,
}

/// Dimensionless rolling traction on body B: F_x/(fN), F_y/(fN), M_z/(fNc), c = √(ab).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Creep<T> {
    /// F_x/(fN)
    pub fx: T,
    /// F_y/(fN)
    pub fy: T,
    /// M_z/(fNc)
    pub mz: T,
}

/// The patch of one call: semi-axes a (along the rolling direction) and b (m), normal force N
/// (N) and friction coefficient f. Validated: a, b > 0 ([`Error::LengthNotPositive`]),
/// f ≥ 0 ([`Error::FrictionCoefficientNegative`]), all finite ([`Error::NonFinite`]: `"a"`,
/// `"b"`, `"N"`, `"f"`); N ≤ 0 is no contact (zero wrench).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Patch<T> {
    pub(crate) c: T,
    pub(crate) fn_: T,
}

impl<T: Real> Patch<T> {
    /// See the [type docs](Self).
    pub fn new(a: T, b: T, n: T, f: T) -> Result<Self, Error> {
        let (a, b) = (finite(a, "a")?, finite(b, "b")?);
        let (n, f) = (finite(n, "N")?, finite(f, "f")?);
        if !(a > T::ZERO && b > T::ZERO) {
            return Err(Error::LengthNotPositive);
        }
        if f < T::ZERO {
            return Err(Error::FrictionCoefficientNegative);
        }
        Ok(Self {
            c: (a * b).sqrt(),
            fn_: f * n.max(T::ZERO),
        })
    }

    /// c = √(ab) (m)
    pub fn c(&self) -> T {
        self.c
    }
}

/// What a rolling law sees per call, all dimensionless: the load parameter κ = Gc²/(fN), the
/// slip in homogeneous form with ω̂ = cω/S, the creep shape, and the full-slip traction in the
/// direction of the slip (given by the caller: [`RollingContact`] from the aligned ellipse's
/// own `best`, [`crate::contact::Rolling`] from the contact's real patch).
#[derive(Debug)]
pub struct Input<'a, T> {
    /// The creep shape (Kalker's coefficients, `blend`'s constants, `table`'s residuals).
    pub contact: &'a RollingShape<T>,
    /// κ = Gc²/(fN) > 0 (the inverse of the load ratio fN/(Gc²)), within [ε², 1/ε²]
    /// (clamped there when G, c, f or N are extreme, so that no product overflows).
    pub kappa: T,
    /// v_x/S
    pub vx: T,
    /// v_y/S
    pub vy: T,
    /// cω/S
    pub w: T,
    /// |V|/S ∈ [0, 1]
    pub v: T,
    /// The full-slip traction F/(fN), M_z/(fNc) in the direction of (vx, vy, w), rolling frame
    /// (zero when the law does not read it: [`RollingLaw::FULL_SLIP`] false).
    pub full_slip: Creep<T>,
}

/// A rolling law: dimensionless creep from the dimensionless input (V ≥ 0 after the mirror).
pub trait RollingLaw {
    /// The name `contact_eval rolling --law` takes.
    const NAME: &'static str;
    /// Whether the law reads [`Input::full_slip`] (the caller evaluates it only then).
    const FULL_SLIP: bool = true;
    /// F/(fN), M_z/(fNc) on body B.
    fn creep<T: Real>(input: &Input<'_, T>) -> Creep<T>;
}

/// The creep shape of one aligned ellipse a/b (a along the rolling direction) and ν: what the
/// rolling laws read besides the slip (Kalker's coefficients, `blend`'s per-shape constants,
/// `table`'s residual tables). Built in `f64` ([`RollingShape::new`]: tens of µs on a host).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollingShape<T> {
    /// √(a/b)
    pub(crate) rho: T,
    pub(crate) kalker: Kalker<T>,
    /// `blend`'s per-shape constants (σ, γ) (`Blend::shape`).
    pub(crate) blend: (T, T),
    /// The default law's residual tables for this shape (`table::Tables`).
    pub(crate) table: super::residual::Tables<T>,
    /// The couplings (K₁₂, K₁₃) of a patch rolled at an angle to its axes (zero along an axis;
    /// [`super::skew_linear`]): (F_x, F_y, M_z/c)/(Gc²) gains −(K₁₂η + K₁₃cφ, K₁₂ξ, −K₁₃ξ).
    pub(crate) coupling: (T, T),
}

impl<T: Copy> RollingShape<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> RollingShape<U> {
        RollingShape {
            rho: f(self.rho),
            kalker: self.kalker.map(f),
            blend: (f(self.blend.0), f(self.blend.1)),
            table: self.table.map(f),
            coupling: (f(self.coupling.0), f(self.coupling.1)),
        }
    }
}

impl<T: Real> RollingShape<T> {
    /// For a/b (a along the rolling direction), clamped to [0.01, 100] (NaN: 1), and ν ∈
    /// [0, 0.5] (an [`Elasticity`]'s). Total.
    pub fn new(a_over_b: T, nu: T) -> Self {
        let r = if a_over_b >= T::from_f64(0.01) {
            a_over_b.min(T::from_f64(100.0))
        } else if a_over_b < T::from_f64(0.01) {
            T::from_f64(0.01)
        } else {
            T::ONE
        };
        Self {
            rho: r.sqrt(),
            kalker: super::creep_matrix::aligned(r, nu),
            blend: super::fitted::blend_at(r),
            table: super::residual::Tables::new(r),
            coupling: (T::ZERO, T::ZERO),
        }
    }

    /// Kalker's coefficients of this shape (the exact theory's, [`super::creep_matrix::aligned`];
    /// for a skewed patch the diagonal of its creep matrix).
    pub fn kalker(&self) -> &Kalker<T> {
        &self.kalker
    }

    /// The couplings (K₁₂, K₁₃) of a patch rolled at an angle to its axes (zero along an axis).
    pub fn coupling(&self) -> (T, T) {
        self.coupling
    }
}

/// A rolling contact: the patch shape a/b (a along the rolling direction), the elasticity, and
/// what depends on them only, built once (the creep shape, the full-slip law's tables).
#[derive(Clone, Debug)]
pub struct RollingContact<T> {
    pub(crate) shape: RollingShape<T>,
    pub(crate) g: T,
    /// a_major/c: √(a/b) or √(b/a)
    pub(crate) major_over_c: T,
    /// a ≥ b: the library frame (x along the major axis) is the rolling frame; else it is
    /// turned by 90°.
    pub(crate) along_major: bool,
    pub(crate) best: BestContact<T>,
}

impl<T: Real> RollingContact<T> {
    /// From the semi-axis ratio a/b ∈ [0.01, 100] ([`Error::RollingAspectOutOfRange`];
    /// non-finite: [`Error::NonFinite`] `"a/b"`) and the elastic constants. Builds the Kalker
    /// coefficients ([`Kalker::new`]) and the per-contact tables of `best` for full slip.
    pub fn new(a_over_b: T, elasticity: Elasticity<T>) -> Result<Self, Error> {
        let r = finite(a_over_b, "a/b")?;
        if !(r >= T::from_f64(0.01) && r <= T::from_f64(100.0)) {
            return Err(Error::RollingAspectOutOfRange);
        }
        let along_major = r >= T::ONE;
        let minor_over_major = if along_major { T::ONE / r } else { r };
        let m = T::ONE - minor_over_major * minor_over_major;
        let k = Constants::from_parameter(Parameter::new(m)?);
        let shape = RollingShape::new(r, elasticity.nu());
        Ok(Self {
            major_over_c: if along_major {
                shape.rho
            } else {
                T::ONE / shape.rho
            },
            shape,
            g: elasticity.g(),
            along_major,
            best: BestContact::new(&k),
        })
    }

    /// Kalker's coefficients of this contact.
    pub fn kalker(&self) -> &Kalker<T> {
        &self.shape.kalker
    }

    /// The creep shape of this contact.
    pub fn shape(&self) -> &RollingShape<T> {
        &self.shape
    }

    /// The wrench on body B by the law `L` for one patch and slip state. Total: rest, N ≤ 0
    /// or f = 0 give zero; V = 0 gives full slip.
    #[inline]
    pub fn wrench<L: RollingLaw>(&self, patch: &Patch<T>, slip: &RollingSlip<T>) -> Wrench<T> {
        let s = slip.scaled(patch.c);
        let cr = self.creep::<L>(patch, &s);
        Wrench {
            fx: cr.fx * patch.fn_,
            fy: cr.fy * patch.fn_,
            mz: cr.mz * patch.fn_ * patch.c,
        }
    }

    /// The dimensionless creep by the law `L` (mirror for V < 0 applied).
    #[inline]
    pub fn creep<L: RollingLaw>(&self, patch: &Patch<T>, s: &Scaled<T>) -> Creep<T> {
        if patch.fn_ <= T::ZERO {
            return Creep::default();
        }
        let kappa = self.g * patch.c * patch.c / patch.fn_;
        let w = patch.c * s.omega;
        let input = Input {
            contact: &self.shape,
            kappa: load_parameter(kappa),
            vx: s.vx,
            vy: s.vy,
            w,
            v: s.v,
            full_slip: if L::FULL_SLIP {
                self.full_slip(s.vx, s.vy, w)
            } else {
                Creep::default()
            },
        };
        let mut cr = L::creep(&input);
        if s.mirrored {
            cr.fx = -cr.fx;
            cr.mz = -cr.mz;
        }
        cr
    }

    /// Full slip (the Contensou–Erismann integrals by `best`'s per-contact form) for the
    /// direction of (v_x, v_y, cω) in the rolling frame.
    #[inline(always)]
    pub fn full_slip(&self, vx: T, vy: T, w: T) -> Creep<T> {
        // library frame: x along the major axis; a < b turns the frame by 90°:
        // x' = y, y' = −x (ω unchanged).
        let (lx, ly) = if self.along_major {
            (vx, vy)
        } else {
            (vy, -vx)
        };
        let st = SlipState::from_slip(Slip::or_rest(lx, ly, w), self.major_over_c, T::ZERO);
        let (t, _) = self.best.traction(&st);
        let (fx, fy) = if self.along_major {
            (t.fx, t.fy)
        } else {
            (-t.fy, t.fx)
        };
        Creep {
            fx,
            fy,
            mz: t.tz * self.major_over_c,
        }
    }
}

/// κ = Gc²/(fN) as the laws read it ([`Input::kappa`]): at most 1/ε² (f32: 7e13, f64:
/// 2e31; ∞ and NaN too). A larger κ only moves the end of the linear range to creepages below
/// ε²/C, under the rounding of the velocities they come from (and needs a patch 1/ε² times
/// smaller than the bodies' radii: nothing Hertzian); the clamp keeps κ·C and its square finite
/// in every law (a fuzz finding: NaN from every law at G near the float's maximum, or
/// a tiny N in f32, with the old clamp κ ≤ T::MAX). Every caller building an [`Input`] uses it.
///
/// And at least ε² (f32: 1.4e-14, f64: 4.9e-32): κ ≳ 1/f for any Hertzian contact (fN/(Gc²)
/// is of the order of f·p₀/G, and p₀/G ≪ 1), so a κ below ε² needs a pressure 1/ε² times the
/// shear modulus; the floor keeps FASTSIM's squared increments (κ·C·ΔX)² from underflowing to
/// an adhesion test 0 ≤ 0 at V = 0 (fuzz finding: an infinite force at f32 κ = 6e-24).
#[inline(always)]
pub(crate) fn load_parameter<T: Real>(kappa: T) -> T {
    let min = T::EPSILON * T::EPSILON;
    let max = T::ONE / min;
    if kappa < max { kappa.max(min) } else { max }
}

/// Full slip everywhere, whatever V (the sliding law of the library, `best`): the limit every
/// rolling law meets at large creepage and V → 0.
#[derive(Clone, Copy, Debug, Default)]
pub struct FullSlip;

impl RollingLaw for FullSlip {
    const NAME: &'static str = "full-slip";
    #[inline]
    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        i.full_slip
    }
}

/// Kalker's linear theory, unsaturated (|F| unbounded: a reference for small creepage, not a
/// friction law; V = 0 gives zero).
#[derive(Clone, Copy, Debug, Default)]
pub struct Linear;

impl Linear {
    /// F/(fN), M_z/(fNc) of the linear theory times V/S (the numerators of the creepage
    /// form): the creep is this divided by the scaled rolling speed v.
    #[inline(always)]
    pub(crate) fn numerators<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        let k = &i.contact.kalker;
        let q = i.kappa;
        let (k12, k13) = i.contact.coupling;
        Creep {
            fx: -q * (k.c11 * i.vx + k12 * i.vy + k13 * i.w),
            fy: -q * (k.c22 * i.vy + k.c23 * i.w + k12 * i.vx),
            mz: q * (k.c23 * i.vy - k.c33 * i.w + k13 * i.vx),
        }
    }
}

impl RollingLaw for Linear {
    const NAME: &'static str = "linear";
    const FULL_SLIP: bool = false;
    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        if i.v <= T::ZERO {
            return Creep::default();
        }
        let n = Self::numerators(i);
        let r = T::ONE / i.v;
        Creep {
            fx: n.fx * r,
            fy: n.fy * r,
            mz: n.mz * r,
        }
    }
}

/// Removes a positive power P = F·v + M_z·ω from a dimensionless wrench for the slip
/// direction u = (v_x, v_y, cω): W ← W − P·u/|u|² (only states with P > 0 change; continuous,
/// the correction vanishing as P → 0⁺). For laws whose cross terms are not exactly
/// antisymmetric (FASTSIM's simplified theory; `blend`'s channel weights).
#[inline(always)]
pub(crate) fn passive<T: Real>(c: Creep<T>, vx: T, vy: T, w: T) -> Creep<T> {
    let p = c.fx * vx + c.fy * vy + c.mz * w;
    if p > T::ZERO {
        let n2 = vx * vx + vy * vy + w * w;
        if n2 < T::MIN_POSITIVE {
            return passive_tiny(c, vx, vy, w);
        }
        let k = p / n2;
        Creep {
            fx: c.fx - k * vx,
            fy: c.fy - k * vy,
            mz: c.mz - k * w,
        }
    } else {
        c
    }
}

/// [`passive`] for a slip direction whose |u|² underflows (every component below ≈ 1e-19 in
/// f32, 1e-154 in f64: p/|u|² was ∞, a fuzz finding): u scaled by its largest
/// component first.
#[cold]
fn passive_tiny<T: Real>(c: Creep<T>, vx: T, vy: T, w: T) -> Creep<T> {
    let m = vx.abs().max(vy.abs()).max(w.abs());
    if m <= T::ZERO {
        return c;
    }
    let (ux, uy, uw) = (vx / m, vy / m, w / m);
    let p = c.fx * ux + c.fy * uy + c.mz * uw;
    if p <= T::ZERO {
        return c;
    }
    let k = p / (ux * ux + uy * uy + uw * uw);
    Creep {
        fx: c.fx - k * ux,
        fy: c.fy - k * uy,
        mz: c.mz - k * uw,
    }
}
