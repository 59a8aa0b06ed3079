//! Robustness checks over every public constructor and evaluation entry point, driven by an
//! arbitrary byte string. Shared by the cargo-fuzz targets (`fuzz/`, issue 8) and the
//! `robust` integration test (a seeded short run in `cargo test`).
//!
//! Each byte string decodes into inputs of both kinds: raw `f32`/`f64` bit patterns (NaN, ±∞,
//! subnormals, ±0, huge, tiny) and physical magnitudes 10^[−40, 40]. The oracles:
//!
//! - every constructor returns exactly the documented result: `Ok` for finite input in its
//!   domain, the documented `Error` variant otherwise (`NonFinite` for NaN/±∞);
//! - no per-step output is NaN for finite input (any magnitude);
//! - inside the physical box ([`Box`]) every output is finite, the normal force ≥ 0, friction
//!   bounded by fN and passive (F·v_P + T_z·ω ≤ 0 up to rounding).
//!
//! A failed check panics (a fuzzer crash).
#![allow(dead_code, clippy::neg_cmp_op_on_partial_ord, clippy::collapsible_if)]

use contensou::contact::{self, Contact, VaryingContact, Wrench};
use contensou::elliptic::{self, Agm, Integrals, Method, Parameter, Theta};
use contensou::friction::rolling;
use contensou::friction::{
    self, Best, Constants, Coulomb, Ellipsoid, Exact, Friction, FrictionLaw, Pade, Simplified,
    Slip, SlipState,
};
use contensou::geometry::{Curvatures, Principal, Race};
use contensou::normal::{
    CompressionDamping, Damping, Fitted, Hertz, HuntCrossley, Material, Modulus, NormalLaw, Patch,
    Undamped, Volumetric,
};
use contensou::shape::{self, Eccentricity, HamrockDowson, Linear, Newton, Ratio};
use contensou::{Error, Real};

/// A float type the decoder can build from raw bits.
pub trait Fz: Real + core::fmt::Debug {
    /// From the low bits of `u`.
    fn from_raw(u: u64) -> Self;
}
impl Fz for f32 {
    fn from_raw(u: u64) -> Self {
        f32::from_bits(u as u32)
    }
}
impl Fz for f64 {
    fn from_raw(u: u64) -> Self {
        f64::from_bits(u)
    }
}

/// Decodes inputs from the fuzzer's bytes (zeros once they run out).
pub struct Input<'a>(&'a [u8]);

impl<'a> Input<'a> {
    /// Over `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Input(data)
    }
    /// The next byte (0 past the end).
    pub fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }
    fn u64(&mut self) -> u64 {
        (0..8).fold(0, |acc, _| (acc << 8) | u64::from(self.byte()))
    }
    /// A value: raw bits, a special value, or a physical magnitude, by a tag byte.
    pub fn val<T: Fz>(&mut self) -> T {
        let tag = self.byte();
        let sign = if tag & 0x80 != 0 { -1.0 } else { 1.0 };
        match tag % 4 {
            0 => T::from_raw(self.u64()),
            1 => {
                const SPECIAL: [f64; 14] = [
                    0.0,
                    -0.0,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NAN,
                    1.0,
                    -1.0,
                    0.5,
                    1e-300,
                    5e-324,
                    1.1754943508222875e-38,
                    1e-45,
                    3.4028234663852886e38,
                    f64::MAX,
                ];
                let x = SPECIAL[usize::from(self.byte()) % SPECIAL.len()];
                T::from_f64(x)
            }
            _ => {
                let e = i32::from(self.byte() % 81) - 40;
                let mant = 1.0 + f64::from(self.byte()) / 256.0;
                T::from_f64(sign * mant * 10f64.powi(e))
            }
        }
    }
}

/// The physical box in which every output must be finite (SI): curvatures P, Q (1/m) in
/// [1e-6, 1e9], E* in [1e3, 1e13] Pa, h ≤ 1 m, |ḣ| ≤ 1e6 m/s, damping c_d ≤ 1e6 s/m,
/// d ≤ 1e12, f ≤ 10, δ ≤ 1e6 m/s, |v|, |ω| ≤ 1e12 (any tiny or subnormal value is inside).
pub struct Box;

impl Box {
    fn within<T: Real>(x: T, lo: f64, hi: f64) -> bool {
        let x = x.to_f64();
        x >= lo && x <= hi
    }
    fn small<T: Real>(x: T, hi: f64) -> bool {
        x.is_finite() && x.to_f64().abs() <= hi
    }
}

fn nan<T: Real>(x: T) -> bool {
    x.to_f64().is_nan()
}
fn fin<T: Real>(x: T, what: &str) {
    assert!(x.is_finite(), "{what} = {x:?} not finite", x = x.to_f64());
}
fn not_nan<T: Real>(x: T, what: &str) {
    assert!(!nan(x), "{what} is NaN");
}

/// What a constructor must return: `Ok` if `ok`, else the error `err`; NaN/±∞ inputs give
/// `NonFinite`.
fn expect<V: core::fmt::Debug>(
    r: &Result<V, Error>,
    finite: bool,
    ok: bool,
    err: Error,
    who: &str,
) {
    match (finite, r) {
        (false, Err(Error::NonFinite(_))) => {}
        (true, Ok(_)) if ok => {}
        (true, Err(e)) if !ok && *e == err => {}
        _ => panic!("{who}: got {r:?}, expected finite={finite} ok={ok} err={err:?}"),
    }
}

/// A damping law built from the coefficient `x`: refused below zero.
fn expect_damping<V: core::fmt::Debug, T: Real>(r: &Result<V, Error>, x: T, who: &str) {
    expect(r, x.is_finite(), x >= T::ZERO, Error::DampingNegative, who);
}

/// `f::<L, T>(args…)` for each sliding law, in the order the fuzz inputs are read.
macro_rules! every_law {
    ($f:ident::<_, $t:ty>($($arg:expr),*)) => {
        $f::<Simplified, $t>($($arg),*);
        $f::<Pade, $t>($($arg),*);
        $f::<Ellipsoid, $t>($($arg),*);
        $f::<Coulomb, $t>($($arg),*);
        $f::<Exact, $t>($($arg),*);
        $f::<Best, $t>($($arg),*);
    };
}

fn integrals_ok<T: Real>(i: &Integrals<T>, who: &str) {
    for (v, n) in [(i.k, "K"), (i.e, "E"), (i.b, "B"), (i.d, "D")] {
        fin(v, who);
        assert!(v > T::ZERO, "{who}: {n} = {} ≤ 0", v.to_f64());
    }
}

fn constants_ok<T: Real>(k: &Constants<T>, who: &str) {
    for v in [
        k.m(),
        k.m1(),
        k.gamma(),
        k.slope_x(),
        k.slope_y(),
        k.spin_torque(),
        k.knee_x(),
        k.knee_y(),
        k.knee_z_max(),
    ] {
        fin(v, who);
    }
}

/// Elliptic parameter, integrals by every method, friction constants, the exact traction.
pub fn elliptic<T: Fz>(inp: &mut Input<'_>) {
    let min = Parameter::<T>::min_complement();
    let (m, m1): (T, T) = (inp.val(), inp.val());
    let (r, rc) = (Parameter::new(m), Parameter::from_complement(m1));
    // m and m₁ = 1 − m, each within its domain
    for (got, x, in_domain, who) in [
        (&r, m, m >= T::ZERO && T::ONE - m >= min, "Parameter::new"),
        (
            &rc,
            m1,
            m1 >= min && m1 <= T::ONE,
            "Parameter::from_complement",
        ),
    ] {
        let err = Error::EllipticParameterOutOfDomain;
        expect(got, x.is_finite(), in_domain, err, who);
    }
    let (vx, vy, w): (T, T, T) = (inp.val(), inp.val(), inp.val());
    for p in [r, rc].into_iter().flatten() {
        integrals_ok(&Agm::integrals(p), "Agm");
        integrals_ok(&Theta::integrals(p), "Theta");
        integrals_ok(&elliptic::Table::integrals(p), "Table");
        let (k, e) = elliptic::paper_k_e(p);
        fin(k, "paper K");
        fin(e, "paper E");
        constants_ok(&Constants::new::<Agm>(p), "Constants::new::<Agm>");
        constants_ok(&Constants::new::<Theta>(p), "Constants::new::<Theta>");
        constants_ok(
            &Constants::new::<elliptic::Table>(p),
            "Constants::new::<Table>",
        );
        constants_ok(&Constants::from_parameter(p), "Constants::from_parameter");
        constants_ok(
            &Constants::from_integrals(p, &Agm::integrals(p)),
            "Constants::from_integrals",
        );
        let t = friction::exact::traction(p, vx, vy, w);
        for v in [t.fx, t.fy, t.tz] {
            fin(v, "exact::traction");
        }
        assert!(t.fx.hypot(t.fy).to_f64() <= 1.0 + 1e-6 && t.tz.abs().to_f64() <= 0.6);
    }
}

fn shape_ok<T: Real>(s: &shape::Shape<T>, who: &str) {
    fin(s.e2(), who);
    fin(s.m1(), who);
    assert!(
        // m₁ may exceed 1 by the table's fit error (≤ 5e-12 relative) near g = 1.
        s.e2() >= T::ZERO && s.m1() > T::ZERO && s.m1().to_f64() <= 1.0 + 1e-11,
        "{who}: e2/m1 range: e2 = {:?}, m1 = {:?}",
        s.e2().to_f64(),
        s.m1().to_f64()
    );
    integrals_ok(&s.integrals(), who);
    constants_ok(&Constants::from_shape(s), who);
}

/// Curvature ratio, every eccentricity method, every curvature constructor.
pub fn geometry<T: Fz>(inp: &mut Input<'_>) {
    let g: T = inp.val();
    let r = Ratio::new(g);
    let in_range = g >= T::from_f64(1e-4) && g <= T::ONE;
    expect(
        &r,
        g.is_finite(),
        in_range,
        Error::CurvatureRatioOutOfRange,
        "Ratio::new",
    );
    if let Ok(g) = r {
        shape_ok(&Newton::shape(g), "Newton");
        shape_ok(&Linear::shape(g), "Linear");
        shape_ok(&HamrockDowson::shape(g), "HamrockDowson");
        shape_ok(&shape::Table::shape(g), "Table");
        for (a, b) in [Newton::solve(g), Linear::solve(g), HamrockDowson::solve(g)] {
            fin(a, "solve");
            fin(b, "solve");
        }
    }
    shape_ok(&shape::Table::shape(Ratio::clamped(g)), "Table (clamped)");

    let (p, q): (T, T) = (inp.val(), inp.val());
    let c = Curvatures::new(p, q);
    expect(
        &c,
        p.is_finite() && q.is_finite(),
        p.min(q) > T::ZERO,
        Error::CurvatureNotPositive,
        "Curvatures::new",
    );
    if let Ok(c) = c {
        assert!(c.p() <= c.q() && c.p() > T::ZERO);
        let r = Ratio::of(&c);
        expect(
            &r,
            true,
            c.ratio() >= T::from_f64(1e-4),
            Error::CurvatureRatioOutOfRange,
            "Ratio::of",
        );
        not_nan(c.ratio(), "ratio");
        not_nan(c.gaussian_radius(), "gaussian_radius");
        if Box::within(c.p(), 1e-6, 1e9) && Box::within(c.q(), 1e-6, 1e9) {
            fin(c.gaussian_radius(), "gaussian_radius");
        }
    }
    // Constructors from radii and bodies: Ok values are validated curvatures.
    let (r1, r2, r3, ang): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let all_finite = r1.is_finite() && r2.is_finite();
    let results = [
        Curvatures::sphere_plane(r1),
        Curvatures::sphere_sphere(r1, r2),
        Curvatures::ball_race(r1, r2, r3, ang, Race::Inner),
        Curvatures::ball_race(r1, r2, r3, ang, Race::Outer),
        Curvatures::from_bodies(
            Principal { k1: r1, k2: r2 },
            Principal { k1: r3, k2: ang },
            r2,
        ),
    ];
    for c in results.iter().flatten() {
        assert!(
            c.p() > T::ZERO && c.p() <= c.q() && c.q().is_finite(),
            "curvatures {c:?}"
        );
        not_nan(c.major_angle(), "major_angle");
    }
    if all_finite && r1 > T::ZERO && Box::within(r1, 1e-9, 1e6) {
        assert!(results[0].is_ok(), "sphere_plane({:?})", r1.to_f64());
    }
    // Inputs are checked in order: the first bad one names the error.
    let first_bad = [r1, r2]
        .into_iter()
        .find(|r| !r.is_finite() || *r == T::ZERO);
    match first_bad {
        Some(r) if !r.is_finite() => assert!(matches!(results[1], Err(Error::NonFinite(_)))),
        Some(_) => assert_eq!(results[1].unwrap_err(), Error::LengthNotPositive),
        None => {}
    }
    let _ = Principal::sphere(r1);
}

fn patch_ok<T: Real>(p: &Patch<T>, boxed: bool, who: &str) {
    // Outside the box N, a or b may overflow to ∞ (a physical quantity beyond the float's
    // range); NaN is allowed only downstream of such an overflow.
    // Likewise for N, a or b underflowing to 0 at h > 0 (then p0 may be 0/0).
    let overflow = !(p.n.is_finite() && p.a.is_finite() && p.b.is_finite())
        || (p.h > T::ZERO && (p.n == T::ZERO || p.a == T::ZERO || p.b == T::ZERO));
    for v in [p.h, p.a, p.b, p.n, p.p0, p.e2, p.m1] {
        assert!(!nan(v) || overflow, "{who}: NaN in {p:?}");
        if boxed {
            fin(v, who);
        }
    }
    assert!(
        !(p.n < T::ZERO) && !(p.a < T::ZERO) && !(p.b < T::ZERO),
        "{who}: negative {p:?}"
    );
}

/// Materials, moduli, damping laws and every normal law's patch.
pub fn normal<T: Fz>(inp: &mut Input<'_>) {
    let (e1, n1): (T, T) = (inp.val(), inp.val());
    let mat = Material::new(e1, n1);
    let fine = e1.is_finite() && n1.is_finite();
    match mat {
        _ if !fine => assert!(matches!(mat, Err(Error::NonFinite(_)))),
        _ if !(e1 > T::ZERO) => assert_eq!(mat, Err(Error::ModulusNotPositive)),
        _ if !(n1 > -T::ONE && n1 <= T::HALF) => {
            assert_eq!(mat, Err(Error::PoissonRatioOutOfRange))
        }
        _ => assert!(mat.is_ok()),
    }
    if let Ok(m) = mat {
        if let Ok(e) = Modulus::of(m, m) {
            assert!(e.get() > T::ZERO && e.get().is_finite());
        }
    }
    let es: T = inp.val();
    let e = Modulus::new(es);
    expect(
        &e,
        es.is_finite(),
        es > T::ZERO,
        Error::ModulusNotPositive,
        "Modulus::new",
    );
    let (cd, d): (T, T) = (inp.val(), inp.val());
    let hc = HuntCrossley::new(cd);
    expect_damping(&hc, cd, "HuntCrossley::new");
    let cdamp = CompressionDamping::new(d);
    expect_damping(&cdamp, d, "CompressionDamping::new");
    let (p, q, h, hdot): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let (Ok(c), Ok(e)) = (Curvatures::new(p, q), e) else {
        return;
    };
    if !(h.is_finite() && hdot.is_finite()) {
        return;
    }
    let boxed = Box::within(c.p(), 1e-6, 1e9)
        && Box::within(c.q(), 1e-6, 1e9)
        && Box::within(e.get(), 1e3, 1e13)
        && h.to_f64() <= 1.0
        && Box::small(hdot, 1e6)
        && hc.map_or(true, |_| cd.to_f64() <= 1e6)
        && cdamp.map_or(true, |_| d.to_f64() <= 1e12);
    let mut laws: [Option<Hertz<T>>; 5] = [
        Hertz::new::<Newton>(&c, e).ok(),
        Hertz::new::<Linear>(&c, e).ok(),
        Hertz::new::<HamrockDowson>(&c, e).ok(),
        Hertz::new::<shape::Table>(&c, e).ok(),
        Some(Hertz::from_shape(
            &c,
            &shape::Table::shape(Ratio::clamped(c.ratio())),
            e,
        )),
    ];
    if c.p() == c.q() {
        laws[0] = Some(Hertz::circular(c.p(), e));
    }
    let check = |law: &dyn Fn(T) -> Patch<T>, damped: &dyn Fn(T, T) -> [Patch<T>; 3], who: &str| {
        patch_ok(&law(h), boxed, who);
        for pt in damped(h, hdot) {
            patch_ok(&pt, boxed, who);
        }
    };
    macro_rules! law {
        ($l:expr, $who:expr) => {{
            let l = $l;
            check(
                &|h| l.patch(h),
                &|h, hd| {
                    [
                        l.damped_patch(h, hd, &Undamped),
                        hc.map_or(l.patch(h), |x| l.damped_patch(h, hd, &x)),
                        cdamp.map_or(l.patch(h), |x| l.damped_patch(h, hd, &x)),
                    ]
                },
                $who,
            );
            if l.stiffness().is_finite() {
                not_nan(l.energy(h), "energy");
                not_nan(l.approach(h), "approach");
            }
            if boxed {
                fin(l.stiffness(), "stiffness");
                fin(l.energy(h), "energy");
            }
        }};
    }
    for l in laws.into_iter().flatten() {
        law!(l, "Hertz");
    }
    law!(Volumetric::new(&c, e), "Volumetric");
    law!(Fitted::clamped(&c, e), "Fitted");
    if let Ok(f) = Fitted::new(&c, e) {
        law!(f, "Fitted::new");
    }
    let _ = (Undamped.force(h, h, hdot), hc.map(|x| x.force(h, h, hdot)));
}

/// What the laws derive (so that `Friction<T, L>` is `Copy`, `Debug`, `PartialEq`).
pub trait Law: FrictionLaw + Copy + core::fmt::Debug + PartialEq {}
impl<L: FrictionLaw + Copy + core::fmt::Debug + PartialEq> Law for L {}

/// F·v + T·ω ≤ 0 up to rounding.
fn passive<T: Real>(fx: T, fy: T, tz: T, vx: T, vy: T, om: T, who: &str) {
    let (fx, fy, tz, vx, vy, om) = (
        fx.to_f64(),
        fy.to_f64(),
        tz.to_f64(),
        vx.to_f64(),
        vy.to_f64(),
        om.to_f64(),
    );
    let p = fx * vx + fy * vy + tz * om;
    let scale = (fx * vx).abs() + (fy * vy).abs() + (tz * om).abs();
    assert!(
        p <= 1e-5 * scale || !p.is_finite() && scale.is_infinite(),
        "{who}: power {p} > 0 (scale {scale})"
    );
}

fn law_core<L: FrictionLaw, T: Fz>(k: &Constants<T>, s: &SlipState<T>) {
    let (t, _) = L::traction(k, s);
    for v in [t.fx, t.fy, t.tz] {
        fin(v, L::NAME);
    }
    assert!(
        t.fx.hypot(t.fy).to_f64() <= 1.0 + 1e-5,
        "{}: |F| > fN",
        L::NAME
    );
    // Exact: |T| ≤ (3/8)E(0) = 0.589; the approximations stay within their stated error.
    assert!(
        t.tz.abs().to_f64() <= 1.0,
        "{}: |T| too large: {t:?} at {s:?}, {k:?}",
        L::NAME
    );
    passive(t.fx, t.fy, t.tz, s.x(), s.y(), s.w(), L::NAME);
}

fn law_dimensional<L: Law, T: Fz>(
    inp: &mut Input<'_>,
    k: &Constants<T>,
    slip: Slip<T>,
    boxed: bool,
) {
    let (f, delta, a, n): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let fr = Friction::<T, L>::with_law(f, delta);
    let fine = f.is_finite() && delta.is_finite();
    match fr {
        _ if !fine => assert!(matches!(fr, Err(Error::NonFinite(_)))),
        _ if f < T::ZERO => assert_eq!(fr, Err(Error::FrictionCoefficientNegative)),
        _ if delta < T::ZERO => assert_eq!(fr, Err(Error::RegularizationSpeedNegative)),
        _ => assert!(fr.is_ok()),
    }
    let Ok(fr) = fr else { return };
    if !(a.is_finite() && n.is_finite()) {
        return;
    }
    let t = fr.tangential(k, a, n, slip);
    let boxed = boxed
        && f.to_f64() <= 10.0
        && delta.to_f64() <= 1e6
        && Box::small(a, 1e3)
        && Box::small(n, 1e20);
    let overflow = !(f * n * a).is_finite() || !(f * n).is_finite();
    for v in [t.fx, t.fy, t.tz] {
        assert!(!nan(v) || overflow, "{}: NaN {t:?}", L::NAME);
        if boxed {
            fin(v, L::NAME);
        }
    }
    if boxed {
        passive(
            t.fx,
            t.fy,
            t.tz,
            slip.vx(),
            slip.vy(),
            slip.omega(),
            L::NAME,
        );
    }
}

/// Slip, slip state, friction coefficients and every friction law (core and dimensional).
pub fn friction<T: Fz>(inp: &mut Input<'_>) {
    let (vx, vy, om, delta): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let fine = vx.is_finite() && vy.is_finite() && om.is_finite();
    let slip = Slip::new(vx, vy, om);
    expect(&slip, fine, true, Error::NonFinite(""), "Slip::new");
    let s = SlipState::new(vx, vy, om, delta);
    expect(
        &s,
        fine && delta.is_finite(),
        true,
        Error::NonFinite(""),
        "SlipState::new",
    );
    let (psi, u): (T, T) = (inp.val(), inp.val());
    let sp = SlipState::from_polar(psi, u);
    assert_eq!(
        sp.is_ok(),
        psi.is_finite() && !nan(u),
        "from_polar({:?}, {:?})",
        psi.to_f64(),
        u.to_f64()
    );
    let m1: T = inp.val();
    let k = Parameter::from_complement(m1).map_or(Constants::circle(), Constants::from_parameter);
    let a: T = inp.val();
    let states = [
        s.ok(),
        sp.ok(),
        slip.map(|sl| SlipState::from_slip(sl, a, delta)).ok(),
    ];
    for st in states.into_iter().flatten() {
        // The documented invariant is |x|, |y|, |w| ≤ 1; the multiply by 1/s can round 2 ulp over.
        for v in [st.x(), st.y(), st.w()] {
            assert!(
                v.abs() <= T::ONE + T::from_f64(4.0) * T::EPSILON,
                "slip state {st:?}"
            );
        }
        assert!(st.d() > T::ZERO, "slip state d");
        every_law!(law_core::<_, T>(&k, &st));
    }
    let Ok(slip) = slip else { return };
    let boxed = Box::small(vx, 1e12) && Box::small(vy, 1e12) && Box::small(om, 1e12);
    every_law!(law_dimensional::<_, T>(inp, &k, slip, boxed));
}

fn wrench_ok<T: Real, B: core::fmt::Debug>(
    w: &Wrench<T, B>,
    f: T,
    boxed: bool,
    slip: &Slip<T>,
    who: &str,
) {
    patch_ok(&w.patch, boxed, who);
    // fN and fNa (the scales of F and T) overflowing to ∞ is the same case.
    let overflow = !(w.n * w.patch.a * f).is_finite() || !(w.n * f).is_finite();
    for v in [w.n, w.fx, w.fy, w.tz] {
        assert!(!nan(v) || overflow, "{who}: NaN in {w:?} at {slip:?}");
        if boxed {
            fin(v, who);
        }
    }
    if boxed {
        passive(w.fx, w.fy, w.tz, slip.vx(), slip.vy(), slip.omega(), who);
    }
}

fn contact_law<L: Law, T: Fz>(inp: &mut Input<'_>, c: &Curvatures<T>, e: Modulus<T>, boxed: bool) {
    let [f, delta, h, hdot, vx, vy, om, cd]: [T; 8] = core::array::from_fn(|_| inp.val());
    let (Ok(fr), Ok(slip), Ok(hc)) = (
        Friction::<T, L>::with_law(f, delta),
        Slip::new(vx, vy, om),
        HuntCrossley::new(cd),
    ) else {
        return;
    };
    let Some(boxed) = step_box(boxed, f, h, hdot) else {
        return;
    };
    let boxed = boxed
        && delta.to_f64() <= 1e6
        && cd.to_f64() <= 1e6
        && Box::small(vx, 1e12)
        && Box::small(vy, 1e12)
        && Box::small(om, 1e12);
    if let Ok(contact) = Contact::hertz::<Newton>(c, e, hc, fr) {
        wrench_ok(&contact.wrench(h, hdot, slip), f, boxed, &slip, L::NAME);
    }
    let varying = VaryingContact::new(e, Undamped, fr);
    wrench_ok(&varying.wrench(c, h, hdot, slip), f, boxed, &slip, L::NAME);
    let fitted = Contact::from_parts(
        Fitted::clamped(c, e),
        Undamped,
        fr,
        Constants::from_shape(&shape::Table::shape(Ratio::clamped(c.ratio()))),
    );
    wrench_ok(&fitted.wrench(h, hdot, slip), f, boxed, &slip, L::NAME);
}

/// A step's h, ḣ: `None` if not finite (nothing to check), else whether the step stays in the
/// box (f ≤ 10, h ≤ 1 m, |ḣ| ≤ 1e6 m/s) given the contact's `boxed`.
fn step_box<T: Real>(boxed: bool, f: T, h: T, hdot: T) -> Option<bool> {
    (h.is_finite() && hdot.is_finite())
        .then(|| boxed && f.to_f64() <= 10.0 && h.to_f64() <= 1.0 && Box::small(hdot, 1e6))
}

/// `Contact::wrench` and `VaryingContact::wrench` with every friction law.
pub fn wrench<T: Fz>(inp: &mut Input<'_>) {
    let (p, q, es): (T, T, T) = (inp.val(), inp.val(), inp.val());
    let (Ok(c), Ok(e)) = (Curvatures::new(p, q), Modulus::new(es)) else {
        return;
    };
    let boxed = Box::within(c.p(), 1e-6, 1e9)
        && Box::within(c.q(), 1e-6, 1e9)
        && Box::within(e.get(), 1e3, 1e13);
    every_law!(contact_law::<_, T>(inp, &c, e, boxed));
}

/// Everything, in `f32` then `f64`, the first byte choosing the area (for a single target).
pub fn all(data: &[u8]) {
    let mut inp = Input::new(data);
    let area = inp.byte();
    match area % 5 {
        0 => elliptic::<f32>(&mut inp),
        1 => geometry::<f32>(&mut inp),
        2 => normal::<f32>(&mut inp),
        3 => friction::<f32>(&mut inp),
        _ => wrench::<f32>(&mut inp),
    }
    match area / 5 % 5 {
        0 => elliptic::<f64>(&mut inp),
        1 => geometry::<f64>(&mut inp),
        2 => normal::<f64>(&mut inp),
        3 => friction::<f64>(&mut inp),
        _ => wrench::<f64>(&mut inp),
    }
}

/// The outputs of one rolling law on one patch and slip (issue 20 item 7): never NaN unless
/// fN·c overflowed; inside the physical box finite, |F| ≤ fN (1 + 1e-5) (`bounded`: not for
/// the unsaturated `linear`), and passive: F·v + M_z·ω ≤ 1e-5·fN·S with
/// S = max(|V|, |v_x| + |v_y| + c|ω|).
fn rolling_law<L: rolling::RollingLaw, T: Fz>(
    contact: &rolling::RollingContact<T>,
    patch: &rolling::Patch<T>,
    slip: &rolling::RollingSlip<T>,
    scale: (T, T, T),
    g: T,
    boxed: bool,
    bounded: bool,
) {
    let (fn_, c, s) = (scale.0.to_f64(), scale.1.to_f64(), scale.2.to_f64());
    let r = contact.kalker();
    let w = contact.wrench::<L>(patch, slip);
    let overflow = !(fn_ * c).is_finite() || !c.is_finite() || c == 0.0;
    for v in [w.fx, w.fy, w.mz] {
        assert!(
            !nan(v) || overflow,
            "{}: NaN in {w:?} at {slip:?}, {patch:?}, a/b = {r:?}, G = {g:?}",
            L::NAME
        );
        if boxed && bounded {
            fin(v, L::NAME);
        }
    }
    if !(boxed && bounded) {
        return;
    }
    let (fx, fy, mz) = (w.fx.to_f64(), w.fy.to_f64(), w.mz.to_f64());
    // plus a few of the smallest subnormals: the output's rounding when fN is subnormal
    let tiny = 4.0 * T::MIN_POSITIVE.to_f64() * T::EPSILON.to_f64();
    let (vx, vy, om) = (
        slip.vx().to_f64(),
        slip.vy().to_f64(),
        slip.omega().to_f64(),
    );
    assert!(
        fx.hypot(fy) <= fn_ * (1.0 + 1e-5) + tiny,
        "{}: |F| = {} > fN = {fn_} at {slip:?}, {patch:?}, a/b = {r:?}, G = {g:?}",
        L::NAME,
        fx.hypot(fy)
    );
    let p = fx * vx + fy * vy + mz * om;
    assert!(
        p <= 1e-5 * fn_ * s + tiny * (vx.abs() + vy.abs() + om.abs()),
        "{}: power {p} > 0 (fN·S = {}) at {slip:?}, {patch:?}, a/b = {r:?}, G = {g:?}: {w:?}",
        L::NAME,
        fn_ * s
    );
}

/// Every rolling law (issue 20): `Elasticity::new`/`dissimilar`, `RollingContact::new`,
/// `Patch::new`, `RollingSlip::new`/`from_creepages` return the documented result; then every
/// law's `wrench` on the accepted inputs ([`rolling_law`]). Physical box: G ∈ [1e3, 1e13] Pa,
/// a, b ∈ [1e-9, 1e3] m, N ≤ 1e20 N, f ≤ 10, |v_x|, |v_y|, |V| ≤ 1e12 m/s, |ω| ≤ 1e12 rad/s.
pub fn rolling<T: Fz>(inp: &mut Input<'_>) {
    let (g, nu, g2, nu2): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let valid = |g: T, nu: T| g > T::ZERO && nu >= T::ZERO && nu <= T::HALF;
    let first = |g: T| {
        if !(g > T::ZERO) {
            Error::ShearModulusNotPositive
        } else {
            Error::RollingPoissonRatioOutOfRange
        }
    };
    let el = rolling::Elasticity::new(g, nu);
    expect(
        &el,
        g.is_finite() && nu.is_finite(),
        valid(g, nu),
        first(g),
        "Elasticity::new",
    );
    let dis = rolling::Elasticity::dissimilar(g, nu, g2, nu2);
    match (&el, rolling::Elasticity::new(g2, nu2), &dis) {
        // Two valid bodies always combine: G between G₁ and G₂, ν ∈ [0, 0.5].
        (Ok(_), Ok(_), Ok(e)) => {
            let (lo, hi) = (g.min(g2).to_f64(), g.max(g2).to_f64());
            let gd = e.g().to_f64();
            assert!(
                gd >= lo * (1.0 - 1e-6) && gd <= hi && e.g().is_finite(),
                "dissimilar({g:?}, {g2:?}): G = {gd}"
            );
            assert!(e.nu() >= T::ZERO && e.nu() <= T::HALF, "dissimilar ν {e:?}");
        }
        (Ok(_), b2, d) => assert_eq!(b2.map(|_| ()), d.map(|_| ()), "dissimilar"),
        (Err(e1), _, d) => assert_eq!(Err(*e1), d.map(|_| ()), "dissimilar"),
    }

    let (r, a, b, n, f): (T, T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val(), inp.val());
    let patch = rolling::Patch::new(a, b, n, f);
    let fine = [a, b, n, f].iter().all(|x| x.is_finite());
    let (ok, err) = if !(a > T::ZERO && b > T::ZERO) {
        (false, Error::LengthNotPositive)
    } else if f < T::ZERO {
        (false, Error::FrictionCoefficientNegative)
    } else {
        (true, Error::LengthNotPositive)
    };
    expect(&patch, fine, ok, err, "Patch::new");
    // The contact's a/b: the patch's own (byte odd) or independent.
    let r = if inp.byte() & 1 == 1 && fine {
        a / b
    } else {
        r
    };
    let Ok(el) = el else { return };
    let contact = rolling::RollingContact::new(r, el);
    let in_range = r >= T::from_f64(0.01) && r <= T::from_f64(100.0);
    expect(
        &contact,
        r.is_finite(),
        in_range,
        Error::RollingAspectOutOfRange,
        "RollingContact::new",
    );
    let (vx, vy, om, v): (T, T, T, T) = (inp.val(), inp.val(), inp.val(), inp.val());
    let slip = rolling::RollingSlip::new(vx, vy, om, v);
    let all_fine = [vx, vy, om, v].iter().all(|x| x.is_finite());
    expect(
        &slip,
        all_fine,
        true,
        Error::NonFinite(""),
        "RollingSlip::new",
    );
    if let Ok(s) = slip {
        match s.creepages() {
            None => assert!(v == T::ZERO),
            Some((x, y, p)) => {
                for c in [x, y, p] {
                    not_nan(c, "creepages");
                }
            }
        }
    }
    let crp = rolling::RollingSlip::from_creepages(vx, vy, om, v);
    let prod_fine = [vx * v, vy * v, om * v, v].iter().all(|x| x.is_finite());
    expect(
        &crp,
        prod_fine,
        true,
        Error::NonFinite(""),
        "RollingSlip::from_creepages",
    );
    let (Ok(contact), Ok(patch)) = (contact, patch) else {
        return;
    };
    let fn_ = f * n.max(T::ZERO);
    let c = patch.c();
    let boxed = Box::within(el.g(), 1e3, 1e13)
        && Box::within(a, 1e-9, 1e3)
        && Box::within(b, 1e-9, 1e3)
        && n.to_f64() <= 1e20
        && f.to_f64() <= 10.0;
    for s in [slip.ok(), crp.ok()].into_iter().flatten() {
        let boxed = boxed
            && Box::small(s.vx(), 1e12)
            && Box::small(s.vy(), 1e12)
            && Box::small(s.omega(), 1e12)
            && Box::small(s.v(), 1e12);
        let sum = s.vx().abs().to_f64() + s.vy().abs().to_f64() + (c * s.omega()).abs().to_f64();
        let scale = (fn_, c, T::from_f64(sum.max(s.v().abs().to_f64())));
        let (ct, p) = (&contact, &patch);
        rolling_law::<rolling::Table, T>(ct, p, &s, scale, el.g(), boxed, true);
        rolling_law::<rolling::Blend, T>(ct, p, &s, scale, el.g(), boxed, true);
        rolling_law::<rolling::Fastsim, T>(ct, p, &s, scale, el.g(), boxed, true);
        rolling_law::<rolling::FastsimGrid<16, 16>, T>(ct, p, &s, scale, el.g(), boxed, true);
        rolling_law::<rolling::FullSlip, T>(ct, p, &s, scale, el.g(), boxed, true);
        rolling_law::<rolling::Linear, T>(ct, p, &s, scale, el.g(), boxed, false);
    }
}

/// One rolling wrench (issue 20, `contact::Rolling`): no NaN unless N·a·f or N·f overflowed;
/// in the box finite, |F| ≤ fN (1 + 1e-5) and F·v + T_z·ω ≤ 1e-5·fN·S, S = max(|V|, |v_x| +
/// |v_y| + c|ω|) (plus a few of the smallest subnormals), v the slip, V the rolling velocity.
fn rolling_wrench_ok<T: Real>(
    w: &Wrench<T, ()>,
    f: T,
    boxed: bool,
    slip: &Slip<T>,
    v: &rolling::RollingVelocity<T>,
    who: &str,
) {
    patch_ok(&w.patch, boxed, who);
    // as for the sliding wrench, plus the patch's c² = ab (the laws' length scale) over- or
    // underflowing
    let ab = w.patch.a * w.patch.b;
    let overflow = !(w.n * w.patch.a * f).is_finite()
        || !(w.n * f).is_finite()
        || !ab.is_finite()
        || (ab == T::ZERO && w.patch.a > T::ZERO);
    for x in [w.n, w.fx, w.fy, w.tz] {
        assert!(
            !nan(x) || overflow,
            "{who}: NaN in {w:?} at {slip:?}, {v:?}"
        );
        if boxed {
            fin(x, who);
        }
    }
    if !boxed {
        return;
    }
    let fn_ = (f * w.n.max(T::ZERO)).to_f64();
    let c = (w.patch.a * w.patch.b).sqrt().to_f64();
    let (fx, fy, tz) = (w.fx.to_f64(), w.fy.to_f64(), w.tz.to_f64());
    let (vx, vy, om) = (
        slip.vx().to_f64(),
        slip.vy().to_f64(),
        slip.omega().to_f64(),
    );
    let speed = v.vx().to_f64().hypot(v.vy().to_f64());
    let s = speed.max(vx.abs() + vy.abs() + c * om.abs());
    let tiny = 4.0 * T::MIN_POSITIVE.to_f64() * T::EPSILON.to_f64();
    assert!(
        fx.hypot(fy) <= fn_ * (1.0 + 1e-5) + tiny,
        "{who}: |F| = {} > fN = {fn_} in {w:?} at {slip:?}, {v:?}",
        fx.hypot(fy)
    );
    let p = fx * vx + fy * vy + tz * om;
    assert!(
        p <= 1e-5 * fn_ * s + tiny * (vx.abs() + vy.abs() + om.abs()),
        "{who}: power {p} > 0 (fN·S = {}) in {w:?} at {slip:?}, {v:?}",
        fn_ * s
    );
}

fn rolling_contact_law<L: rolling::RollingLaw, T: Fz>(
    inp: &mut Input<'_>,
    c: &Curvatures<T>,
    e: Modulus<T>,
    el: rolling::Elasticity<T>,
    boxed: bool,
) {
    let [f, h, hdot, vx, vy, om, vrx, vry]: [T; 8] = core::array::from_fn(|_| inp.val());
    let v = rolling::RollingVelocity::new(vrx, vry);
    match (vrx.is_finite(), vry.is_finite(), &v) {
        (true, true, Ok(_)) => {}
        (false, _, Err(Error::NonFinite("V_x"))) => {}
        (true, false, Err(Error::NonFinite("V_y"))) => {}
        _ => panic!("RollingVelocity::new({vrx:?}, {vry:?}) = {v:?}"),
    }
    let (Ok(fr), Ok(slip), Ok(v)) = (
        Friction::<T, Best>::with_law(f, T::ZERO),
        Slip::new(vx, vy, om),
        v,
    ) else {
        return;
    };
    let Some(boxed) = step_box(boxed, f, h, hdot) else {
        return;
    };
    let boxed = boxed && [vx, vy, om, vrx, vry].iter().all(|x| Box::small(*x, 1e12));
    if let Ok(contact) = Contact::hertz::<Newton>(c, e, Undamped, fr) {
        let r = contact::Rolling::<T, _, L>::new(contact, el);
        let r = r.unwrap_or_else(|err| panic!("Rolling::new: {err:?}"));
        rolling_wrench_ok(&r.wrench(h, hdot, slip, v), f, boxed, &slip, &v, L::NAME);
    }
    let varying = VaryingContact::new(e, Undamped, fr);
    let r = contact::Rolling::<T, _, L>::new(varying, el);
    let r = r.unwrap_or_else(|err| panic!("Rolling::new (varying): {err:?}"));
    rolling_wrench_ok(&r.wrench(c, h, hdot, slip, v), f, boxed, &slip, &v, L::NAME);
}

/// `contact::Rolling` (fixed `Contact` and `VaryingContact`, friction `Best`) with every
/// rolling law, `RollingVelocity::new` (issue 20). Box: the `wrench` box, G ∈ [1e3, 1e13] Pa,
/// |V_x|, |V_y| ≤ 1e12 m/s.
pub fn rolling_wrench<T: Fz>(inp: &mut Input<'_>) {
    let (p, q, es, g, nu): (T, T, T, T, T) =
        (inp.val(), inp.val(), inp.val(), inp.val(), inp.val());
    let (Ok(c), Ok(e), Ok(el)) = (
        Curvatures::new(p, q),
        Modulus::new(es),
        rolling::Elasticity::new(g, nu),
    ) else {
        return;
    };
    let boxed = Box::within(c.p(), 1e-6, 1e9)
        && Box::within(c.q(), 1e-6, 1e9)
        && Box::within(e.get(), 1e3, 1e13)
        && Box::within(el.g(), 1e3, 1e13);
    rolling_contact_law::<rolling::Table, T>(inp, &c, e, el, boxed);
    rolling_contact_law::<rolling::Blend, T>(inp, &c, e, el, boxed);
    rolling_contact_law::<rolling::Fastsim, T>(inp, &c, e, el, boxed);
    rolling_contact_law::<rolling::FastsimGrid<16, 16>, T>(inp, &c, e, el, boxed);
}

/// `dynamic::DynContact::new_rolling` + `wrench_rolling` with every rolling law and both forms
/// (issue 20): the optional columns' errors name the column (`nu` first, then `G`; `vrx`, `vry`
/// after the step's own columns); accepted inputs give the `rolling_wrench` oracles.
pub fn dynamic_rolling<T: Fz>(inp: &mut Input<'_>) {
    use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
    let [p, q, estar, cd, f, delta, g, nu]: [T; 8] = core::array::from_fn(|_| inp.val());
    let pick = inp.byte();
    let law = Law::ROLLING[usize::from(pick % 4)];
    let form = Form::ALL[usize::from(pick / 4 % 2)];
    let rs = RollingSpec {
        g: (pick & 0x10 != 0).then_some(g),
        nu: (pick & 0x20 != 0).then_some(nu),
    };
    let spec = Spec {
        p,
        q,
        estar,
        cd,
        f,
        delta,
    };
    let sliding = DynContact::new(&spec, Law::Best, form);
    let rolling = DynContact::new_rolling(&spec, &rs, law, form);
    let Ok(_) = sliding else {
        // the contract's own columns are checked first, as for the sliding laws
        assert_eq!(rolling.err(), sliding.err(), "new_rolling vs new");
        return;
    };
    let nu_v = rs.nu.unwrap_or(T::from_f64(0.3));
    let expected = if !nu_v.is_finite() {
        Some(("nu", Error::NonFinite("nu")))
    } else if !(nu_v >= T::ZERO && nu_v <= T::HALF) {
        Some(("nu", Error::RollingPoissonRatioOutOfRange))
    } else {
        match rs.g {
            Some(g) if !g.is_finite() => Some(("G", Error::NonFinite("G"))),
            Some(g) if g <= T::ZERO => Some(("G", Error::ShearModulusNotPositive)),
            Some(_) => None,
            // E*·(1 − ν) underflowing to 0 for a subnormal E*
            None if estar * (T::ONE - nu_v) <= T::ZERO => {
                Some(("estar", Error::ShearModulusNotPositive))
            }
            None => None,
        }
    };
    let got = rolling.as_ref().err().map(|e| (e.column, e.error));
    assert_eq!(got, expected, "new_rolling({rs:?})");
    let Ok(contact) = rolling else { return };
    let [h, hdot, vx, vy, om, vrx, vry]: [T; 7] = core::array::from_fn(|_| inp.val());
    let step = Step {
        h,
        hdot,
        vx,
        vy,
        omega: om,
    };
    let out = contact.wrench_rolling(&step, &RollingStep { vrx, vry });
    let first_bad = [
        ("h", h),
        ("hdot", hdot),
        ("vx", vx),
        ("vy", vy),
        ("omega", om),
    ]
    .into_iter()
    .chain([("vrx", vrx), ("vry", vry)])
    .find(|(_, x)| !x.is_finite());
    let w = match (first_bad, out) {
        (Some((col, _)), Err(e)) => {
            assert_eq!(e.column, col, "wrench_rolling: {e:?}");
            assert!(matches!(e.error, Error::NonFinite(_)), "{e:?}");
            return;
        }
        (None, Ok(w)) => w,
        (bad, out) => panic!("wrench_rolling: {bad:?} gave {out:?}"),
    };
    let el = contact.rolling_spec().elasticity(estar).unwrap();
    let boxed = Box::within(p.min(q), 1e-6, 1e9)
        && Box::within(p.max(q), 1e-6, 1e9)
        && Box::within(estar, 1e3, 1e13)
        && Box::within(el.g(), 1e3, 1e13)
        && cd.to_f64() <= 1e6;
    let Some(boxed) = step_box(boxed, f, h, hdot) else {
        return;
    };
    let boxed = boxed && [vx, vy, om, vrx, vry].iter().all(|x| Box::small(*x, 1e12));
    let ab = w.a * w.b;
    let overflow = !(w.n * w.a * f).is_finite()
        || !(w.n * f).is_finite()
        || !ab.is_finite()
        || (ab == T::ZERO && w.a > T::ZERO);
    for x in [w.n, w.fx, w.fy, w.tz] {
        assert!(
            !nan(x) || overflow,
            "{}: NaN in {w:?} at {step:?}",
            law.name()
        );
        if boxed {
            fin(x, law.name());
        }
    }
    if !boxed {
        return;
    }
    let fn_ = (f * w.n.max(T::ZERO)).to_f64();
    let c = ab.sqrt().to_f64();
    let (fx, fy, tz) = (w.fx.to_f64(), w.fy.to_f64(), w.tz.to_f64());
    let (vx, vy, om) = (vx.to_f64(), vy.to_f64(), om.to_f64());
    let s = vrx
        .to_f64()
        .hypot(vry.to_f64())
        .max(vx.abs() + vy.abs() + c * om.abs());
    let tiny = 4.0 * T::MIN_POSITIVE.to_f64() * T::EPSILON.to_f64();
    assert!(
        fx.hypot(fy) <= fn_ * (1.0 + 1e-5) + tiny,
        "{}: |F| > fN in {w:?}",
        law.name()
    );
    let pw = fx * vx + fy * vy + tz * om;
    assert!(
        pw <= 1e-5 * fn_ * s + tiny * (vx.abs() + vy.abs() + om.abs()),
        "{}: power {pw} > 0 in {w:?} at {step:?}",
        law.name()
    );
}

/// A run-time contact of the contract from the fuzzer's bytes (any law, either form, the
/// optional rolling columns), its start step and rolling columns; `None` when the contract
/// refuses the contact (its errors are `dynamic_rolling`'s to check). Also whether the
/// contact and step lie in the physical box.
#[allow(clippy::type_complexity)]
fn contract_row<T: Fz>(
    inp: &mut Input<'_>,
) -> Option<(
    contensou::dynamic::DynContact<T>,
    contensou::dynamic::Step<T>,
    contensou::dynamic::RollingStep<T>,
    bool,
)> {
    use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
    let [p, q, estar, cd, f, delta]: [T; 6] = core::array::from_fn(|_| inp.val());
    let pick = inp.byte();
    let law = Law::ALL[usize::from(pick) % Law::ALL.len()];
    let form = Form::ALL[usize::from(pick / 16 % 2)];
    let spec = Spec {
        p,
        q,
        estar,
        cd,
        f,
        delta,
    };
    let contact = if law.is_rolling() {
        DynContact::new_rolling(&spec, &RollingSpec::default(), law, form)
    } else {
        DynContact::new(&spec, law, form)
    }
    .ok()?;
    let [h, hdot, vx, vy, omega, vrx, vry]: [T; 7] = core::array::from_fn(|_| inp.val());
    let step = Step {
        h,
        hdot,
        vx,
        vy,
        omega,
    };
    let rolling = RollingStep { vrx, vry };
    let boxed = Box::within(p.min(q), 1e-6, 1e9)
        && Box::within(p.max(q), 1e-6, 1e9)
        && Box::within(estar, 1e3, 1e13)
        && cd.to_f64() <= 1e6
        && delta.to_f64() <= 1e6
        && step_box(true, f, h, hdot).unwrap_or(false)
        && [vx, vy, omega, vrx, vry]
            .iter()
            .all(|x| Box::small(*x, 1e6));
    Some((contact, step, rolling, boxed))
}

/// The wrench's Jacobian through the run-time contract (`DynContact::jacobian_rolling`, every
/// law and form): a non-finite step column is refused naming the same column as the wrench;
/// otherwise every derivative is finite (saturated at ±MAX, never NaN: the documented rule)
/// and the value is the wrench bit for bit (NaN only where the wrench itself is).
pub fn jacobian<T: Fz>(inp: &mut Input<'_>) {
    let Some((contact, step, rolling, boxed)) = contract_row::<T>(inp) else {
        return;
    };
    let j = contact.jacobian_rolling(&step, &rolling);
    let w = contact.wrench_rolling(&step, &rolling);
    let (j, w) = match (j, w) {
        (Err(a), Err(b)) => {
            assert_eq!(a, b, "jacobian vs wrench refusal");
            return;
        }
        (Ok(j), Ok(w)) => (j, w),
        (j, w) => panic!("jacobian {j:?} vs wrench {w:?}"),
    };
    let name = contact.law().name();
    for (i, x) in j.d.iter().flatten().enumerate() {
        assert!(
            x.is_finite(),
            "{name}: derivative {i} = {:?} at {step:?}",
            x.to_f64()
        );
    }
    for (got, want) in j.value.iter().zip([w.n, w.fx, w.fy, w.tz]) {
        assert!(
            got.to_f64().to_bits() == want.to_f64().to_bits(),
            "{name}: value {:?} vs wrench {:?} at {step:?}",
            got.to_f64(),
            want.to_f64()
        );
        if boxed {
            fin(*got, name);
        }
    }
}

/// The step-aware wrench through the run-time contract (`step::contract::step_row`): Δt, W's
/// upper triangle (raw, or built positive semidefinite as L·Lᵀ), optional free velocities.
/// Errors as documented, naming the column (`dt`: `NonFinite`, `StepNotPositive`; a W entry:
/// `NonFinite`; W: `InverseMassNotPositiveSemidefinite`, never for an L·Lᵀ within the box); accepted
/// rows never give NaN, and inside the box the wrench is finite, N ≥ 0 and friction injects no
/// power over the step (F·v⁺ ≤ 0 and T_z·ω⁺ ≤ 0 up to rounding, u⁺ = u_free + Δt·W·w; for a
/// rolling law, whose creep force and spin moment are one law, their sum ≤ 0).
#[allow(clippy::needless_range_loop)]
pub fn step<T: Fz>(inp: &mut Input<'_>) {
    use contensou::step::contract::step_row;
    let Some((contact, step, rolling, boxed)) = contract_row::<T>(inp) else {
        return;
    };
    let dt: T = inp.val();
    let how = inp.byte();
    let raw: [T; 10] = core::array::from_fn(|_| inp.val());
    // W's upper triangle, row-major over (n, x, y, w): the raw entries, or L·Lᵀ with L the
    // lower triangle of the same entries (positive semidefinite by construction).
    let built = how & 1 != 0;
    let w_upper = if built {
        let mut l = [[T::ZERO; 4]; 4];
        let mut k = 0;
        for (r, row) in l.iter_mut().enumerate() {
            for x in row.iter_mut().take(r + 1) {
                *x = raw[k];
                k += 1;
            }
        }
        let mut u = [T::ZERO; 10];
        let mut k = 0;
        for r in 0..4 {
            for c in r..4 {
                u[k] = (0..4).fold(T::ZERO, |acc, m| acc + l[r][m] * l[c][m]);
                k += 1;
            }
        }
        u
    } else {
        raw
    };
    let free: [Option<T>; 4] = core::array::from_fn(|k| {
        let v = inp.val();
        (how & (2 << k) != 0).then_some(v)
    });
    let got = step_row(&contact, &step, &rolling, dt, w_upper, free);
    let name = contact.law().name();
    // the start state first, as the wrench refuses it
    if let Err(e) = contact.wrench_rolling(&step, &rolling) {
        assert_eq!(got, Err(e), "{name}: step_row vs the wrench's refusal");
        return;
    }
    let w_box = w_upper.iter().all(|x| Box::small(*x, 1e12))
        && built
        // L's entries 0 or of moderate size: L·Lᵀ then has no underflowed entry (a product
        // of tiny entries rounding to 0 can make it indefinite in floating point)
        && raw
            .iter()
            .all(|x| *x == T::ZERO || Box::within(x.abs(), 1e-6, 1e6))
        // and L of full rank, its diagonal ≥ 0.1 of its largest entry: a rank-deficient W
        // whose dependent row repeats an ill-conditioned combination of the others can be
        // refused by its own rounding (the pivot floor 256 ε is absolute; documented)
        && {
            let big = raw.iter().fold(0.0f64, |m, x| m.max(x.to_f64().abs()));
            [0usize, 2, 5, 9]
                .iter()
                .all(|&k| raw[k].to_f64().abs() >= 0.1 * big)
        };
    let out = if !dt.is_finite() {
        assert_eq!(
            got.map_err(|e| (e.column, e.error)),
            Err(("dt", Error::NonFinite("dt")))
        );
        return;
    } else if !(dt > T::ZERO) {
        assert_eq!(
            got.map_err(|e| (e.column, e.error)),
            Err(("dt", Error::StepNotPositive))
        );
        return;
    } else if let Some(k) = w_upper.iter().position(|x| !x.is_finite()) {
        let e = got.expect_err("a non-finite W entry");
        assert_eq!(
            e.column,
            contensou::step::contract::STEP_INPUTS[k + 1],
            "{e:?}"
        );
        assert!(matches!(e.error, Error::NonFinite(_)), "{e:?}");
        return;
    } else {
        match got {
            Ok(o) => o,
            Err(e) if e.column == "W" => {
                // the upper triangle is symmetric by construction: never `NotSymmetric` (an
                // L·Lᵀ whose diagonal underflowed to 0 is, as rounded, not PSD)
                assert_eq!(e.error, Error::InverseMassNotPositiveSemidefinite, "{e:?}");
                assert!(!w_box, "{name}: L·Lᵀ refused: {e:?} for {w_upper:?}");
                return;
            }
            Err(e) => {
                // a free velocity that is not finite, by its column
                let k = contensou::step::contract::FREE_INPUTS
                    .iter()
                    .position(|c| *c == e.column)
                    .unwrap_or_else(|| panic!("{name}: unexpected refusal {e:?}"));
                // or h_free = h − Δt·un_free overflowing for finite inputs
                assert!(
                    free[k].is_some_and(|x| !x.is_finite())
                        || (k == 0 && e.error == Error::NonFinite("h_free")),
                    "{e:?}"
                );
                return;
            }
        }
    };
    for x in out {
        not_nan(x, name);
    }
    let free_box = free.iter().flatten().all(|x| Box::small(*x, 1e6));
    if !(boxed && w_box && free_box && dt.to_f64() <= 1.0) {
        return;
    }
    for x in out {
        fin(x, name);
    }
    assert!(out[0] >= T::ZERO, "{name}: N = {:?}", out[0].to_f64());
    // u⁺ = u_free + Δt·W·w (in f64)
    let u0 = [-step.hdot, step.vx, step.vy, step.omega];
    let u: [f64; 4] = core::array::from_fn(|k| free[k].unwrap_or(u0[k]).to_f64());
    let mut wm = [[0.0; 4]; 4];
    let mut k = 0;
    for r in 0..4 {
        for c in r..4 {
            wm[r][c] = w_upper[k].to_f64();
            wm[c][r] = wm[r][c];
            k += 1;
        }
    }
    let o: [f64; 4] = out.map(|x| x.to_f64());
    let dt = dt.to_f64();
    let du: [f64; 4] = core::array::from_fn(|r| dt * (0..4).map(|c| wm[r][c] * o[c]).sum::<f64>());
    let up: [f64; 4] = core::array::from_fn(|r| u[r] + du[r]);
    let eps = T::EPSILON.to_f64();
    let tiny = 4.0 * T::MIN_POSITIVE.to_f64();
    let fmag = o[1].hypot(o[2]);
    let fp = o[1] * up[1] + o[2] * up[2];
    let fscale = fmag * (u[1].hypot(u[2]) + du[1].hypot(du[2]));
    let tp = o[3] * up[3];
    let tscale = o[3].abs() * (u[3].abs() + du[3].abs());
    if contact.law().is_rolling() {
        // A rolling contact's creep force and spin moment are one law (its power gate is their
        // sum, the step's docs): the spin moment alone may do positive work while the pair
        // dissipates, e.g. `fastsim-16` at W = 0: F·v = −9,137 W, T_z·ω = +29 W.
        assert!(
            fp + tp <= 1e3 * eps * (fscale + tscale) + tiny,
            "{name}: F·v⁺ + T·ω⁺ = {:e} (scale {:e}): {o:?} at {step:?}, dt {dt}, W {wm:?}, u {u:?}",
            fp + tp,
            fscale + tscale
        );
        return;
    }
    assert!(
        fp <= 1e3 * eps * fscale + tiny,
        "{name}: F·v⁺ = {fp:e} (scale {fscale:e}): {o:?} at {step:?}, dt {dt}, W {wm:?}, u {u:?}"
    );
    assert!(
        tp <= 1e3 * eps * tscale + tiny,
        "{name}: T·ω⁺ = {tp:e} (scale {tscale:e}): {o:?} at {step:?}, dt {dt}, W {wm:?}, u {u:?}"
    );
}
