//! Friction laws: property tests over seeded random slip states (passivity, bounds, continuity
//! across every switch, symmetries, limits, f32 against f64) and the dimensional wrapper's
//! input handling.
//!
//! A cheap seeded generator (splitmix64) instead of proptest keeps ≥ 1e5 states per law and
//! precision fast in the debug profile.
#![allow(clippy::excessive_precision)]

use contensou::elliptic::Parameter;
use contensou::friction::{
    Constants, Coulomb, Ellipsoid, Friction, FrictionLaw, Pade, Simplified, Slip, SlipState,
    Traction,
};
use contensou::{Error, Real};

/// States per law and precision in the main property loop.
const STATES: usize = 100_000;
/// 1-D paths per law and precision searched for branch switches.
const PATHS: usize = 20_000;

#[path = "common/rng.rs"]
mod rng;
#[macro_use]
#[path = "common/each.rs"]
mod each;
use rng::SplitMix as Rng;

impl Rng {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp()
    }
    fn below(&mut self, n: u64) -> u64 {
        self.bits() % n
    }
}

/// Float stepping for the continuity checks.
trait Step: Real {
    fn up(self) -> Self;
    fn down(self) -> Self;
}
macro_rules! step_impl {
    ($($t:ty),*) => {$(
        impl Step for $t {
            fn up(self) -> Self {
                <$t>::from_bits(if self >= 0.0 {
                    self.to_bits() + 1
                } else {
                    self.to_bits() - 1
                })
            }
            fn down(self) -> Self {
                -(-self).up()
            }
        }
    )*};
}
step_impl!(f32, f64);

/// A random dimensionless slip (vx, vy, aω, δ) in f64, covering rest, pure translation, pure
/// spin, both spin signs, u over 1e-6 … 1e6, overall scales from `tiny` to `huge`.
fn random_slip(rng: &mut Rng, tiny: f64, huge: f64) -> [f64; 4] {
    let psi = rng.range(0.0, 2.0 * std::f64::consts::PI);
    let u = match rng.below(16) {
        0 => 0.0,
        1 => f64::INFINITY,
        _ => rng.log(1e-6, 1e6),
    };
    let scale = match rng.below(8) {
        0 => rng.log(tiny, huge),
        _ => rng.log(1e-3, 1e3),
    };
    let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
    let (v, aw) = if u.is_infinite() {
        (scale, 0.0)
    } else {
        (u * scale, sign * scale)
    };
    let delta = match rng.below(4) {
        0 => 0.0,
        _ => scale * rng.log(1e-4, 1e2),
    };
    if rng.below(200) == 0 {
        return [0.0, 0.0, 0.0, delta];
    }
    [v * psi.cos(), v * psi.sin(), aw, delta]
}

fn table<T: Real>() -> Vec<Constants<T>> {
    let mut v = vec![Constants::circle()];
    for i in 0..=33 {
        let m = 0.99 * i as f64 / 33.0;
        v.push(Constants::from_parameter(
            Parameter::new(T::from_f64(m)).unwrap(),
        ));
    }
    v.push(Constants::from_parameter(
        Parameter::from_complement(T::from_f64(1e-3)).unwrap(),
    ));
    v
}

fn state<T: Real>(s: [f64; 4]) -> SlipState<T> {
    SlipState::new(
        T::from_f64(s[0]),
        T::from_f64(s[1]),
        T::from_f64(s[2]),
        T::from_f64(s[3]),
    )
    .unwrap()
}

fn eval<T: Real, L: FrictionLaw>(k: &Constants<T>, s: [f64; 4]) -> Traction<T> {
    L::traction(k, &state::<T>(s)).0
}

fn diff<T: Real, U: Real>(a: Traction<T>, b: Traction<U>) -> f64 {
    let d = |p: T, q: U| (p.to_f64() - q.to_f64()).abs();
    d(a.fx, b.fx).max(d(a.fy, b.fy)).max(d(a.tz, b.tz))
}

fn eps<T: Real>() -> f64 {
    T::EPSILON.to_f64()
}

/// Passivity, |F| ≤ 1, |T| ≤ C, finiteness, bit-exact symmetries; returns the worst
/// f32-vs-f64 difference.
fn properties<L: FrictionLaw>(seed: u64, torque_free: bool) -> f64 {
    let mut rng = Rng(seed);
    let k64 = table::<f64>();
    let k32 = table::<f32>();
    let mut worst32 = 0.0f64;
    for _ in 0..STATES {
        let i = rng.below(k64.len() as u64) as usize;
        let s = random_slip(&mut rng, 1e-30, 1e30);
        check::<f64, L>(&k64[i], s, torque_free);
        let s32 = random_slip(&mut rng, 1e-40, 1e30);
        check::<f32, L>(&k32[i], s32, torque_free);
        // f32 against f64 on the same (f32-representable) state, ordinary scales.
        let s = s.map(|c| c as f32 as f64);
        if s.iter()
            .all(|c| c.abs() < 1e30 && (*c == 0.0 || c.abs() > 1e-30))
        {
            let t32 = eval::<f32, L>(&k32[i], s);
            let t64 = eval::<f64, L>(&k64[i], s);
            worst32 = worst32.max(diff(t32, t64));
        }
    }
    worst32
}

fn check<T: Real, L: FrictionLaw>(k: &Constants<T>, s: [f64; 4], torque_free: bool) -> Traction<T> {
    let st = state::<T>(s);
    let (t, _) = L::traction(k, &st);
    let ctx = || format!("{} {} s = {s:?} m = {} → {t:?}", L::NAME, T::NAME, k.m());
    assert!(
        t.fx.is_finite() && t.fy.is_finite() && t.tz.is_finite(),
        "{}",
        ctx()
    );
    // Passivity, in the state's own units: F·v_P + T_z·aω ≤ 0 exactly (each term ≤ 0).
    let power = t.fx * st.x() + t.fy * st.y() + t.tz * st.w();
    assert!(power <= T::ZERO, "power {power}: {}", ctx());
    assert!(
        t.fx * st.x() <= T::ZERO && t.fy * st.y() <= T::ZERO,
        "{}",
        ctx()
    );
    assert!(t.tz * st.w() <= T::ZERO, "{}", ctx());
    let f = (t.fx.to_f64()).hypot(t.fy.to_f64());
    assert!(f <= 1.0 + 4.0 * eps::<T>(), "|F| = {f}: {}", ctx());
    let c = k.spin_torque().to_f64();
    assert!(
        t.tz.to_f64().abs() <= c * (1.0 + 4.0 * eps::<T>()),
        "{}",
        ctx()
    );
    if torque_free {
        assert_eq!(t.tz, T::ZERO, "{}", ctx());
    }
    // Symmetries. ψ → −ψ: (Fx, −Fy, Tz); ψ → ψ + π: (−Fx, −Fy, Tz); ω → −ω: (Fx, Fy, −Tz);
    // ψ → π − ψ: (−Fx, Fy, Tz).
    let [vx, vy, aw, d] = s;
    let same = |a: Traction<T>, b: Traction<T>, what: &str| {
        assert!(a == b, "{what}: {a:?} vs {b:?}: {}", ctx());
    };
    let m = |x: T| -x;
    same(
        eval::<T, L>(k, [vx, -vy, aw, d]),
        Traction {
            fx: t.fx,
            fy: m(t.fy),
            tz: t.tz,
        },
        "psi -> -psi",
    );
    same(
        eval::<T, L>(k, [-vx, -vy, aw, d]),
        Traction {
            fx: m(t.fx),
            fy: m(t.fy),
            tz: t.tz,
        },
        "psi -> psi + pi",
    );
    same(
        eval::<T, L>(k, [vx, vy, -aw, d]),
        Traction {
            fx: t.fx,
            fy: t.fy,
            tz: m(t.tz),
        },
        "omega -> -omega",
    );
    same(
        eval::<T, L>(k, [-vx, vy, aw, d]),
        Traction {
            fx: m(t.fx),
            fy: t.fy,
            tz: t.tz,
        },
        "psi -> pi - psi",
    );
    t
}

macro_rules! property_test {
    ($name:ident, $law:ty, $seed:expr, $torque_free:expr, $tol32:expr) => {
        #[test]
        fn $name() {
            let worst = properties::<$law>($seed, $torque_free);
            assert!(
                worst <= $tol32,
                "{}: f32 vs f64 differ by {worst:e}",
                <$law>::NAME
            );
            eprintln!("{}: f32 vs f64 max difference {worst:.2e}", <$law>::NAME);
        }
    };
}

property_test!(simplified_properties, Simplified, 1, false, 2e-6);
property_test!(pade_properties, Pade, 2, false, 2e-6);
property_test!(ellipsoid_properties, Ellipsoid, 3, false, 2e-6);
property_test!(coulomb_properties, Coulomb, 4, true, 2e-6);

/// One crossing of a branch switch: the component varied, the two adjacent floats and the
/// branches on either side.
struct Crossing<B> {
    jump: f64,
    lo: B,
    hi: B,
}

/// Scan random 1-D paths (one component of the state varied log-uniformly, the others fixed),
/// bisect every branch change down to two adjacent floats, and return the crossings.
fn crossings<T: Real + Step, L: FrictionLaw>(seed: u64) -> Vec<Crossing<L::Branch>> {
    let mut rng = Rng(seed);
    let ks = table::<T>();
    let mut out = Vec::new();
    const POINTS: usize = 48;
    for _ in 0..PATHS {
        let k = &ks[rng.below(ks.len() as u64) as usize];
        let psi = rng.range(0.0, 2.0 * std::f64::consts::PI);
        let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
        let u = rng.log(1e-3, 1e2);
        let delta = if rng.below(3) == 0 {
            0.0
        } else {
            rng.log(1e-3, 1e1)
        };
        let base = [u * psi.cos(), u * psi.sin(), sign, delta];
        // Vary v_Px, aω or δ (the δ path only when δ > 0 makes sense; aω keeps its sign).
        let j = [0usize, 2, 3][rng.below(3) as usize];
        let (lo, hi) = (1e-3f64, 1e2f64);
        let value = |t: f64| -> T {
            let t = T::from_f64(t);
            if j == 2 {
                t * T::from_f64(sign)
            } else if j == 0 && base[0] < 0.0 {
                -t
            } else {
                t
            }
        };
        let at = |t: T| -> (Traction<T>, L::Branch) {
            let mut s = base.map(T::from_f64);
            s[j] = t;
            L::traction(k, &SlipState::new(s[0], s[1], s[2], s[3]).unwrap())
        };
        let mut prev_t = value(lo);
        let mut prev = at(prev_t);
        for i in 1..POINTS {
            let t = value((lo.ln() + (hi.ln() - lo.ln()) * i as f64 / (POINTS - 1) as f64).exp());
            let cur = at(t);
            if cur.1 != prev.1 {
                // Bisect [prev_t, t] (same sign) to adjacent floats.
                let (mut a, mut b) = (prev_t, t);
                let (ba, bb) = (prev.1, cur.1);
                let mut guard = 0;
                loop {
                    let next = if a < b { a.up() } else { a.down() };
                    if next == b || guard > 200 {
                        break;
                    }
                    guard += 1;
                    let mid = T::from_f64(0.5 * (a.to_f64() + b.to_f64()));
                    let mid = if mid == a { next } else { mid };
                    if at(mid).1 == ba {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                let (ta, tb) = (at(a), at(b));
                // Several switches may fall in one interval: record the last one found.
                out.push(Crossing {
                    jump: diff(ta.0, tb.0),
                    lo: ta.1,
                    hi: tb.1,
                });
                let _ = bb;
            }
            prev = cur;
            prev_t = t;
        }
    }
    out
}

fn continuity<T: Real + Step, L: FrictionLaw>(
    seed: u64,
    tol_ulps: f64,
) -> Vec<Crossing<L::Branch>> {
    let c = crossings::<T, L>(seed);
    let worst = c.iter().map(|c| c.jump).fold(0.0, f64::max);
    eprintln!(
        "{} {}: {} switch crossings, largest jump {:.1} ulp(1)",
        L::NAME,
        T::NAME,
        c.len(),
        worst / eps::<T>()
    );
    for x in &c {
        assert!(
            x.jump <= tol_ulps * eps::<T>(),
            "{} {}: jump {:e} across {:?} → {:?}",
            L::NAME,
            T::NAME,
            x.jump,
            x.lo,
            x.hi
        );
    }
    c
}

#[test]
fn simplified_is_continuous_across_every_switch() {
    use contensou::friction::simplified::{TorqueZone, Zone};
    for (f32_run, c) in [
        (false, continuity::<f64, Simplified>(11, 8.0)),
        (true, continuity::<f32, Simplified>(12, 8.0)),
    ] {
        // Every kind of switch must have been crossed (both axes, torque, spin regularization).
        let seen = |f: &dyn Fn(&Crossing<contensou::friction::simplified::Branch>) -> bool| {
            c.iter().filter(|x| f(x)).count()
        };
        for (a, b) in [
            (Zone::Sliding, Zone::Spin),
            (Zone::Sliding, Zone::Regularized),
            (Zone::Spin, Zone::Regularized),
        ] {
            let pair = |p: Zone, q: Zone| (p == a && q == b) || (p == b && q == a);
            assert!(
                seen(&|x| pair(x.lo.x, x.hi.x)) > 0,
                "x {a:?}/{b:?} f32={f32_run}"
            );
            assert!(
                seen(&|x| pair(x.lo.y, x.hi.y)) > 0,
                "y {a:?}/{b:?} f32={f32_run}"
            );
        }
        assert!(
            seen(&|x| x.lo.tz != x.hi.tz
                && (x.lo.tz == TorqueZone::Plateau || x.hi.tz == TorqueZone::Plateau))
                > 0
        );
        assert!(seen(&|x| x.lo.tz_regularized != x.hi.tz_regularized) > 0);
    }
}

#[test]
fn coulomb_is_continuous_across_its_switch() {
    for c in [
        continuity::<f64, Coulomb>(13, 8.0),
        continuity::<f32, Coulomb>(14, 8.0),
    ] {
        assert!(!c.is_empty());
    }
}

#[test]
fn smooth_laws_have_no_switch() {
    assert!(crossings::<f64, Pade>(15).is_empty());
    assert!(crossings::<f32, Ellipsoid>(16).is_empty());
}

/// ω → 0 and v → 0 limits: approached at distance ε, against the exact pure-translation
/// (F = −v̂, T = 0) and pure-spin (F = 0, T = −C sgn ω) values (δ = 0). `slope` bounds the
/// law's |dT/du| at u = 0 (Padé: C²/|T₁| ≤ 5C²/m₁; the others have a flat torque there).
fn limits<T: Real, L: FrictionLaw>(
    eps_path: f64,
    spin_free: bool,
    slope: fn(&Constants<T>) -> f64,
) {
    let mut rng = Rng(21);
    let ks = table::<T>();
    let tol = 10.0 * eps_path + 16.0 * eps::<T>();
    for _ in 0..20_000 {
        let k = &ks[rng.below(ks.len() as u64) as usize];
        let psi = rng.range(0.0, 2.0 * std::f64::consts::PI);
        let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
        let (c, s) = (psi.cos(), psi.sin());
        let translation = Traction {
            fx: T::from_f64(-c),
            fy: T::from_f64(-s),
            tz: T::ZERO,
        };
        let near = eval::<T, L>(k, [c, s, sign * eps_path, 0.0]);
        assert!(
            diff(near, translation) <= tol,
            "{} ω → 0: {near:?}",
            L::NAME
        );
        if !spin_free {
            let spin = Traction {
                fx: T::ZERO,
                fy: T::ZERO,
                tz: -k.spin_torque() * T::from_f64(sign),
            };
            let near = eval::<T, L>(k, [eps_path * c, eps_path * s, sign, 0.0]);
            assert!(
                diff(near, spin) <= tol + eps_path * slope(k),
                "{} v → 0: {near:?} vs {spin:?}",
                L::NAME
            );
            assert!(diff(eval::<T, L>(k, [0.0, 0.0, sign, 0.0]), spin) <= 16.0 * eps::<T>());
        }
        assert!(diff(eval::<T, L>(k, [c, s, 0.0, 0.0]), translation) <= 16.0 * eps::<T>());
    }
}

#[test]
fn limits_of_pure_translation_and_pure_spin() {
    fn flat<T: Real>(_: &Constants<T>) -> f64 {
        0.0
    }
    fn pade<T: Real>(k: &Constants<T>) -> f64 {
        5.0 * k.spin_torque().to_f64().powi(2) / k.m1().to_f64()
    }
    limits::<f64, Simplified>(1e-7, false, flat);
    limits::<f32, Simplified>(1e-4, false, flat);
    limits::<f64, Pade>(1e-7, false, pade);
    limits::<f32, Pade>(1e-4, false, pade);
    limits::<f64, Ellipsoid>(1e-7, false, flat);
    limits::<f32, Ellipsoid>(1e-4, false, flat);
    limits::<f64, Coulomb>(1e-7, true, flat);
    limits::<f32, Coulomb>(1e-4, true, flat);
    // Regularized Coulomb: F → 0 as v → 0 when δ > 0.
    let k = Constants::<f64>::circle();
    let t = eval::<f64, Coulomb>(&k, [1e-9, -2e-9, 1.0, 1e-3]);
    assert!(t.fx.hypot(t.fy) <= 3e-6);
}

/// Closed-form spot values of the simplified model (paper §3) at m = 0: A = B = 3π/8,
/// C = 3π/16, T₁ = −1/5, u_z* = 1/(5C).
#[test]
fn simplified_spot_values() {
    let k = Constants::<f64>::circle();
    let a = 3.0 * std::f64::consts::PI / 8.0;
    let c = a / 2.0;
    let at = |psi: f64, u: f64| Simplified::traction(&k, &SlipState::from_polar(psi, u).unwrap()).0;
    let t = at(0.3, 0.5);
    assert!((t.fx + 0.3f64.cos() * (a * 0.5).min(1.0)).abs() < 1e-15);
    assert!((t.fy + 0.3f64.sin() * (a * 0.5).min(1.0)).abs() < 1e-15);
    assert!((t.tz + 0.2 / 0.5).abs() < 1e-15); // u = 0.5 > u_z* = 0.34: hyperbola
    let t = at(1.0, 0.2);
    assert!((t.tz + c).abs() < 1e-15); // plateau
    assert!((t.fx + 1.0f64.cos() * a * 0.2).abs() < 1e-15);
    // Ellipse, ψ = π/2: T₁ = −(1 − m)/5.
    let p = Parameter::new(0.8f64).unwrap();
    let k = Constants::from_parameter(p);
    let t = Simplified::traction(
        &k,
        &SlipState::from_polar(std::f64::consts::FRAC_PI_2, 3.0).unwrap(),
    )
    .0;
    assert!((t.tz + 0.2 * 0.2 / 3.0).abs() < 1e-15);
    assert!((t.fy + 1.0).abs() < 1e-15 && t.fx.abs() < 1e-15);
}

#[test]
fn dimensional_wrapper_validates_and_scales() {
    assert_eq!(
        Friction::<f64, Simplified>::with_law(-0.1, 0.0).unwrap_err(),
        Error::FrictionCoefficientNegative
    );
    assert_eq!(
        Friction::<f64, Simplified>::with_law(f64::NAN, 0.0).unwrap_err(),
        Error::NonFinite("f")
    );
    assert_eq!(
        Friction::<f32, Pade>::with_law(f32::INFINITY, 0.0).unwrap_err(),
        Error::NonFinite("f")
    );
    assert_eq!(
        Friction::<f64, Coulomb>::with_law(0.3, -1e-3).unwrap_err(),
        Error::RegularizationSpeedNegative
    );
    assert_eq!(
        Friction::<f64, Coulomb>::with_law(0.3, f64::NAN).unwrap_err(),
        Error::NonFinite("delta")
    );
    assert_eq!(
        Slip::new(f64::NAN, 0.0, 0.0).unwrap_err(),
        Error::NonFinite("v_Px")
    );
    assert_eq!(
        Slip::new(0.0, f32::NEG_INFINITY, 0.0).unwrap_err(),
        Error::NonFinite("v_Py")
    );
    assert_eq!(
        Slip::new(0.0, 0.0, f64::INFINITY).unwrap_err(),
        Error::NonFinite("omega")
    );
    assert!(SlipState::<f64>::from_polar(f64::NAN, 1.0).is_err());
    assert!(SlipState::<f64>::from_polar(0.0, f64::NAN).is_err());

    let k = Constants::from_parameter(Parameter::new(0.5f64).unwrap());
    let law = Friction::<f64, Simplified>::with_law(0.3, 1e-4).unwrap();
    let slip = Slip::new(1e-3, -2e-3, 40.0).unwrap();
    for n in [0.0, -1.0, f64::NAN] {
        let w = law.tangential(&k, 1e-4, n, slip);
        assert!(w.fx == 0.0 && w.fy == 0.0 && w.tz == 0.0, "{w:?}");
    }
    let (a, n) = (1e-4, 2.0);
    let w = law.tangential(&k, a, n, slip);
    let (t, b) = Simplified::traction(&k, &SlipState::new(1e-3, -2e-3, a * 40.0, 1e-4).unwrap());
    assert_eq!(b, w.branch);
    assert!((w.fx - 0.6 * t.fx).abs() < 1e-15 && (w.fy - 0.6 * t.fy).abs() < 1e-15);
    assert!((w.tz - 0.6 * a * t.tz).abs() < 1e-19);
    // a ≤ 0: point contact, no torque.
    assert_eq!(law.tangential(&k, 0.0, n, slip).tz, 0.0);
}

/// Extreme dimensional inputs: tiny, subnormal, huge, aω overflowing: finite, passive, bounded.
fn extremes<T: Real, L: FrictionLaw>() {
    let mut rng = Rng(31);
    let ks = table::<T>();
    let big = if T::MANTISSA_DIGITS > 24 { 300.0 } else { 37.0 };
    let pick = |rng: &mut Rng| -> T {
        let x = match rng.below(6) {
            0 => 0.0,
            1 => T::MIN_POSITIVE.to_f64() * rng.unit(),
            _ => 10f64.powf(rng.range(-big, big)),
        };
        T::from_f64(if rng.below(2) == 0 { x } else { -x })
    };
    for _ in 0..20_000 {
        let k = &ks[rng.below(ks.len() as u64) as usize];
        let (vx, vy, om) = (pick(&mut rng), pick(&mut rng), pick(&mut rng));
        let a = pick(&mut rng).abs().min(T::from_f64(1e3));
        let n = T::from_f64(rng.log(1e-9, 1e3));
        let delta = pick(&mut rng).abs();
        let law = Friction::<T, L>::with_law(T::from_f64(0.4), delta).unwrap();
        let w = law.tangential(k, a, n, Slip::new(vx, vy, om).unwrap());
        let ctx = format!(
            "{} {}: v=({vx},{vy}) ω={om} a={a} N={n} δ={delta}: {w:?}",
            L::NAME,
            T::NAME
        );
        assert!(
            w.fx.is_finite() && w.fy.is_finite() && w.tz.is_finite(),
            "{ctx}"
        );
        let fnn = 0.4 * n.to_f64();
        assert!(
            w.fx.to_f64().hypot(w.fy.to_f64()) <= fnn * (1.0 + 8.0 * eps::<T>()),
            "{ctx}"
        );
        assert!(
            w.fx * vx <= T::ZERO && w.fy * vy <= T::ZERO && w.tz * om <= T::ZERO,
            "{ctx}"
        );
    }
}

#[test]
fn extreme_inputs_stay_finite_passive_and_bounded() {
    each!(extremes, [f64, f32], [Simplified, Pade, Ellipsoid, Coulomb]);
}

/// The exact integrals as a law: passive (to rounding), |F| ≤ 1, symmetric, on random states
/// (fewer than for the fast laws: µs per call, tens of µs in the debug profile).
#[test]
fn exact_is_passive_bounded_and_symmetric() {
    use contensou::friction::Exact;
    let mut rng = Rng(41);
    let ks = table::<f64>();
    for _ in 0..20_000 {
        let k = &ks[rng.below(ks.len() as u64) as usize];
        let s = random_slip(&mut rng, 1e-30, 1e30);
        let st = state::<f64>(s);
        let t = Exact::traction(k, &st).0;
        let ctx = format!("s = {s:?} m = {} → {t:?}", k.m());
        assert!(
            t.fx.is_finite() && t.fy.is_finite() && t.tz.is_finite(),
            "{ctx}"
        );
        let power = t.fx * st.x() + t.fy * st.y() + t.tz * st.w();
        assert!(power <= 1e-15, "power {power}: {ctx}");
        assert!(t.fx.hypot(t.fy) <= 1.0 + 1e-14, "{ctx}");
        let [vx, vy, aw, d] = s;
        let close = |a: Traction<f64>, b: Traction<f64>, what: &str| {
            assert!(diff(a, b) <= 1e-14, "{what}: {a:?} vs {b:?}: {ctx}");
        };
        let t2 = |fx: f64, fy: f64, tz: f64| Traction { fx, fy, tz };
        close(
            eval::<f64, Exact>(k, [vx, -vy, aw, d]),
            t2(t.fx, -t.fy, t.tz),
            "psi -> -psi",
        );
        close(
            eval::<f64, Exact>(k, [-vx, -vy, aw, d]),
            t2(-t.fx, -t.fy, t.tz),
            "psi -> psi + pi",
        );
        close(
            eval::<f64, Exact>(k, [vx, vy, -aw, d]),
            t2(t.fx, t.fy, -t.tz),
            "omega -> -omega",
        );
    }
}

/// Max (|ΔF|, |ΔT_z|) of law `L` in precision `T` against `reference` (exact, f64) on `grid`.
fn max_error<T: Real, L: FrictionLaw>(grid: &[(f64, f64, f64, Traction<f64>)]) -> (f64, f64) {
    let (mut ef, mut et) = (0.0f64, 0.0f64);
    let mut k: Option<(f64, Constants<T>)> = None;
    for &(m, psi, u, r) in grid {
        let kk = match k {
            Some((km, kk)) if km == m => kk,
            _ => Constants::from_parameter(Parameter::new(T::from_f64(m)).unwrap()),
        };
        k = Some((m, kk));
        let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
        let t = L::traction(&kk, &s).0;
        ef = ef.max((t.fx.to_f64() - r.fx).hypot(t.fy.to_f64() - r.fy));
        et = et.max((t.tz.to_f64() - r.tz).abs());
    }
    (ef, et)
}

/// Each law's max error against the exact integrals stays within its documented figure
/// (measured by `cargo bench --bench friction` on a denser grid, e² ∈ [0, 0.99]; here a
/// sparser grid through the same worst points, so a regression fails).
#[test]
fn max_error_against_exact_within_documented_bounds() {
    use contensou::friction::Exact;
    let mut grid = Vec::new();
    for m in [0.0, 0.5, 0.9, 0.99] {
        let k = Constants::<f64>::from_parameter(Parameter::new(m).unwrap());
        for j in 0..=16 {
            let psi = std::f64::consts::FRAC_PI_2 * j as f64 / 16.0;
            let (s, c) = psi.sin_cos();
            let mut us = vec![0.0, f64::INFINITY];
            us.extend((0..=320).map(|n| 10f64.powf(-4.0 + n as f64 / 40.0)));
            us.extend([
                k.knee_x(),
                k.knee_y(),
                (1.0 - m * s * s) / (5.0 * k.spin_torque()),
                1.0 / (s * s + c * c / k.m1()).sqrt(),
            ]);
            for u in us {
                let st = SlipState::from_polar(psi, u).unwrap();
                grid.push((m, psi, u, Exact::traction(&k, &st).0));
            }
        }
    }
    // (law, measured (force fN, torque fNa), bound asserted)
    let check = |name: &str, got: (f64, f64), doc: (f64, f64), bound: (f64, f64)| {
        eprintln!(
            "{name}: max error {:.4} fN, {:.4} fNa (documented {doc:?})",
            got.0, got.1
        );
        assert!(
            got.0 <= bound.0 && got.1 <= bound.1,
            "{name}: {got:?} > {bound:?}"
        );
        assert!(
            got.0 <= doc.0 + 1e-4 && got.1 <= doc.1 + 1e-4,
            "{name}: {got:?} > {doc:?}"
        );
    };
    // Each law in f64 and f32: its documented error and the bound asserted.
    macro_rules! laws {
        ($($law:ident: $bound:expr;)*) => {$(
            for (precision, got) in [
                ("f64", max_error::<f64, $law>(&grid)),
                ("f32", max_error::<f32, $law>(&grid)),
            ] {
                check(&format!("{} {precision}", $law::NAME), got, $law::ERROR, $bound);
            }
        )*};
    }
    laws! {
        Simplified: (0.393, 0.355);
        Pade: (0.410, 0.355);
        Ellipsoid: (0.228, 0.134);
        Coulomb: (1.0, 0.590);
    }
    // The exact law in f32 is the rounded f64 one.
    let (ef, et) = max_error::<f32, Exact>(&grid);
    assert!(ef <= 2e-7 && et <= 2e-7, "exact f32: {ef:e} {et:e}");
}
