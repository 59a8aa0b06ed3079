//! Robustness (issue 8): the fuzz checks of `robust/checks.rs` (shared with the cargo-fuzz
//! targets in `fuzz/`) on proptest's random byte strings — a short run for `cargo test`; the
//! long runs are cargo-fuzz's (`bench-results/fuzz.md`).
#![allow(clippy::excessive_precision)]

#[path = "robust/checks.rs"]
mod checks;

use checks::Input;
use proptest::prelude::*;

/// Byte strings per check and precision pair (each decodes to dozens of inputs).
const CASES: u32 = 10_000;

fn run(check: fn(&mut Input<'_>)) {
    let config = ProptestConfig {
        cases: CASES,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    proptest!(config, |(data in prop::collection::vec(any::<u8>(), 0..400))| {
        check(&mut Input::new(&data));
    });
}

/// One test per area, each in `f32` then `f64` on the same bytes.
macro_rules! areas {
    ($($area:ident),*) => {$(
        #[test]
        fn $area() {
            run(|i| {
                checks::$area::<f32>(i);
                checks::$area::<f64>(i)
            });
        }
    )*};
}

areas!(
    elliptic,
    geometry,
    normal,
    friction,
    wrench,
    rolling,
    rolling_wrench,
    dynamic_rolling,
    jacobian,
    step
);

/// The rolling fuzz target's findings (issue 20), each once, deterministic: every output
/// finite where the library used to return NaN (or a wrong error).
mod rolling_findings {
    use contensou::Real;
    use contensou::contact::Contact;
    use contensou::contact::Rolling;
    use contensou::dynamic::Output;
    use contensou::friction::rolling::row::RowLaw;
    use contensou::friction::rolling::{
        Blend, Elasticity, Fastsim, FastsimGrid, Patch, RollingContact, RollingLaw, RollingSlip,
        RollingVelocity, Table, Wrench,
    };
    use contensou::friction::{Best, Friction, Slip};
    use contensou::geometry::Curvatures;
    use contensou::normal::{Hertz, Modulus, Undamped};
    use contensou::shape::Newton;

    /// Every rolling law but the unsaturated reference `linear` (the last of `RowLaw::ALL`).
    fn all<T: Real>(c: &RollingContact<T>, p: &Patch<T>, s: &RollingSlip<T>) -> [Wrench<T>; 5] {
        core::array::from_fn(|k| RowLaw::ALL[k].wrench(c, p, s))
    }

    type Fixed = contensou::contact::Contact<f32, Hertz<f32>, Undamped, Best>;

    /// `contact::Rolling`'s wrench at (h, ḣ = 0, slip, v) by each rolling law of the wrench
    /// contract on a `best` contact (f = 0.3, δ = 0, E* = 1e11 Pa, Newton's shape) of
    /// curvatures (P, Q), each with a positive normal force, finite components and
    /// |F| ≤ fN (1 + 1e-5).
    fn rolling_wrenches(
        (p, q): (f32, f32),
        el: Elasticity<f32>,
        h: f32,
        slip: Slip<f32>,
        v: RollingVelocity<f32>,
    ) -> [Output<f32>; 4] {
        fn one<L: RollingLaw>(
            c: Fixed,
            el: Elasticity<f32>,
            h: f32,
            s: Slip<f32>,
            v: RollingVelocity<f32>,
        ) -> Output<f32> {
            let w = Output::from(Rolling::<_, _, L>::new(c, el).unwrap().wrench(h, 0.0, s, v));
            assert!(
                w.n > 0.0 && w.fx.is_finite() && w.fy.is_finite() && w.tz.is_finite(),
                "{w:?}"
            );
            assert!(w.fx.hypot(w.fy) <= 0.3 * w.n * (1.0 + 1e-5), "{w:?}");
            w
        }
        let contact = Contact::hertz::<Newton>(
            &Curvatures::new(p, q).unwrap(),
            Modulus::new(1e11).unwrap(),
            Undamped,
            Friction::<f32, Best>::with_law(0.3, 0.0).unwrap(),
        )
        .unwrap();
        [
            one::<Table>(contact, el, h, slip, v),
            one::<Blend>(contact, el, h, slip, v),
            one::<Fastsim>(contact, el, h, slip, v),
            one::<FastsimGrid<16, 16>>(contact, el, h, slip, v),
        ]
    }

    fn finite<T: Real>(ws: &[Wrench<T>]) {
        for w in ws {
            assert!(
                w.fx.is_finite() && w.fy.is_finite() && w.mz.is_finite(),
                "{:?}",
                (w.fx.to_f64(), w.fy.to_f64(), w.mz.to_f64())
            );
        }
    }

    /// `blend`/`table`: M_z = S(d/m)·M_fs squared d and m: a spin of 1e-27 rad/s at a
    /// saturated ξ underflowed to 0/0 = NaN in f32. Now M_z is tiny, F_x full slip.
    #[test]
    fn tiny_spin_at_saturated_creep() {
        let c = RollingContact::new(2.0f32, Elasticity::new(8e10, 0.3).unwrap()).unwrap();
        let p = Patch::new(1e-3, 1e-3, 1.0, 0.3).unwrap();
        let s = RollingSlip::new(1e-3f32, 0.0, 1e-27, 1.0).unwrap();
        let ws = all(&c, &p, &s);
        finite(&ws);
        for w in &ws[..2] {
            assert!((w.fx + 0.3).abs() < 1e-6 && w.mz.abs() < 1e-20, "{w:?}");
        }
    }

    /// A subnormal rolling speed (V = 1e-310 m/s, pure spin): (a/v)·κ overflowed, ∞·0 = NaN
    /// in `blend`/`table`'s M_z. Now the full-slip pure spin moment, as `full-slip` gives.
    #[test]
    fn subnormal_rolling_speed() {
        let c = RollingContact::new(2.0f64, Elasticity::new(8e10, 0.3).unwrap()).unwrap();
        let p = Patch::new(1e-3, 1e-3, 1e3, 0.3).unwrap();
        let s = RollingSlip::new(0.0, 0.0, 1.0, 1e-310).unwrap();
        let ws = all(&c, &p, &s);
        finite(&ws);
        let fs = ws[4].mz;
        for w in &ws[..2] {
            assert!((w.mz - fs).abs() <= 1e-9 * fs.abs(), "{w:?} vs {fs}");
        }
        // f32: V/S subnormal
        let c = RollingContact::new(2.0f32, Elasticity::new(8e10, 0.3).unwrap()).unwrap();
        let p = Patch::new(1e-3, 1e-3, 1e3, 0.3).unwrap();
        finite(&all(
            &c,
            &p,
            &RollingSlip::new(1.0f32, 0.0, 0.0, 1e-40).unwrap(),
        ));
    }

    /// A subnormal slip sum S (f32 v_x = −1e-40 at V = 0): 1/S overflowed in
    /// `RollingSlip::scaled` (0·∞ = NaN in v_y). Now full slip along −x.
    #[test]
    fn subnormal_slip() {
        let c = RollingContact::new(1.0f32, Elasticity::new(1e9, 0.3).unwrap()).unwrap();
        let p = Patch::new(0.5, 0.5, 1e-16, 0.28).unwrap();
        let s = RollingSlip::new(-1e-40f32, 0.0, 0.0, 0.0).unwrap();
        let sc = s.scaled(0.5);
        assert_eq!((sc.vx, sc.vy, sc.omega, sc.v), (-1.0, 0.0, 0.0, 0.0));
        let ws = all(&c, &p, &s);
        finite(&ws);
        let fn_ = 0.28f32 * 1e-16;
        for w in &ws {
            assert!((w.fx - fn_).abs() < 1e-3 * fn_ && w.fy == 0.0, "{w:?}");
        }
    }

    /// κ = Gc²/(fN) overflowing (G near the float's maximum, or a tiny load in f32): κ·C
    /// overflowed to ∞ and 0·∞ gave NaN in every law. κ is clamped to 1/ε².
    #[test]
    fn huge_load_parameter() {
        let c = RollingContact::new(21.0f64, Elasticity::new(f64::MAX, 0.3).unwrap()).unwrap();
        let p = Patch::new(1e-10, 2e-11, 8.4e-86, 1.0).unwrap();
        let s = RollingSlip::new(-1.4e28, 4.9e-9, 1.25e104, 6.27e271).unwrap();
        finite(&all(&c, &p, &s));
        let c = RollingContact::new(2.0f32, Elasticity::new(8e10, 0.3).unwrap()).unwrap();
        let p = Patch::new(1e-3, 1e-3, 1e-30, 0.3).unwrap();
        let ws = all(&c, &p, &RollingSlip::new(1e-3f32, 0.0, 1.0, 1.0).unwrap());
        finite(&ws);
        for w in &ws {
            assert!(w.fx.hypot(w.fy) <= 0.3e-30 * (1.0 + 1e-5), "{w:?}");
        }
    }

    /// `Elasticity::dissimilar` of two valid bodies near the float's maximum: 1/G₁ + 1/G₂
    /// rounded to G = ∞ and the call returned `ShearModulusNotPositive`.
    #[test]
    fn dissimilar_extremes() {
        let e = Elasticity::dissimilar(f32::MAX, 0.3, f32::MAX, 0.3).unwrap();
        assert_eq!((e.g(), e.nu()), (f32::MAX, 0.3));
        let e = Elasticity::dissimilar(1e-45f32, 0.5, 1e30, 0.0).unwrap();
        assert!(
            e.g() > 0.0 && e.g() <= 2.0 * 1e-45f32 && e.nu() == 0.5,
            "{e:?}"
        );
        // the ordinary case is unchanged (1/G = ½(1/G₁ + 1/G₂))
        let e = Elasticity::dissimilar(80e9f64, 0.3, 1e6, 0.5).unwrap();
        assert!((e.g() / (2.0 / (1.0 / 80e9 + 1.0 / 1e6)) - 1.0).abs() < 1e-15);
    }

    /// The passivity projection W − P·u/|u|² with |u|² underflowing (f64: v_y/V = 5e-169,
    /// cω/V = 1e-167, κ = 2e24): P/0 = ∞ and NaN in FASTSIM. u is now scaled first.
    #[test]
    fn passivity_projection_of_a_tiny_slip() {
        let c = RollingContact::new(40.0f64, Elasticity::new(1.00390625e23, 0.0).unwrap()).unwrap();
        let p = Patch::new(2.4 * 40f64.sqrt(), 2.4 / 40f64.sqrt(), 0.25, 1.0).unwrap();
        let s = RollingSlip::new(
            0.0,
            -1.6835937500000002e-28,
            -1.68359375e-27,
            -3.4534724410691748e140,
        )
        .unwrap();
        let ws = all(&c, &p, &s);
        finite(&ws);
        for w in &ws {
            assert!(w.fx.hypot(w.fy) <= 0.25, "{w:?}");
        }
    }

    /// `contact::Rolling` (issue 20 round 2): κ = Gc²/(fN) overflowing (f32, G = 3e38 Pa,
    /// h = 1e-30 m on a 1 mm sphere: N ≈ 4e-36 N, κ ≈ 2e41) gave NaN through the old clamp
    /// κ ≤ T::MAX; it now shares `RollingContact`'s clamp (κ ≤ 1/ε²).
    #[test]
    fn rolling_wrench_at_a_tiny_load() {
        let el = Elasticity::new(3e38f32, 0.3).unwrap();
        let v = RollingVelocity::new(1.0f32, 0.0).unwrap();
        let slip = Slip::new(1e-3f32, 0.0, 1.0).unwrap();
        // finite, N > 0, |F| ≤ fN: checked per law by `rolling_wrenches`
        rolling_wrenches((1000.0, 1000.0), el, 1e-30, slip, v);
    }

    /// `contact::Rolling` with a slip whose magnitude overflows f32 (v = (f32::MAX, −1.77e38),
    /// V at 45°): the rotation into the rolling frame gave v_y = −∞ and ∞/∞ = NaN in
    /// `RollingSlip::scaled`. Now the limit direction: full slip, finite.
    #[test]
    fn rolling_wrench_of_an_overflowing_slip() {
        let el = Elasticity::new(8e10f32, 0.3).unwrap();
        let v = RollingVelocity::new(1.0f32, 1.0).unwrap();
        let slip = Slip::new(f32::MAX, -1.7698068e38, 1.0).unwrap();
        for w in rolling_wrenches((10.0, 200.0), el, 1e-5, slip, v) {
            // opposing the slip
            assert!(w.fx < 0.0 && w.fy > 0.0, "{w:?}");
        }
    }

    /// FASTSIM at V = 0 with a tiny κ (f32 G = 0.11 Pa under N = 5.6e24 N: κ = 6e-24): its
    /// squared increments underflowed, the adhesion test read 0 ≤ 0 and the traction became
    /// q/MIN_POSITIVE: F_x = ∞, F_y = NaN. κ is now at least ε².
    #[test]
    fn fastsim_at_a_tiny_load_parameter() {
        use contensou::contact::VaryingContact;
        let c = Curvatures::new(1.1523438e-5f32, 0.14335938).unwrap();
        let contact = VaryingContact::new(
            Modulus::new(1.90625e23f32).unwrap(),
            Undamped,
            Friction::<f32, Best>::with_law(0.5, 0.0).unwrap(),
        );
        let el = Elasticity::new(0.10976563f32, 0.115234375).unwrap();
        let slip = Slip::new(-0.046852607f32, 0.0, 0.0).unwrap();
        macro_rules! law {
            ($l:ty) => {{
                let r = Rolling::<_, _, $l>::new(contact, el).unwrap();
                let w = r.wrench(&c, 0.5, 1e-45, slip, RollingVelocity::ZERO);
                assert!(
                    w.fx.is_finite() && w.fy.is_finite() && w.tz.is_finite(),
                    "{w:?}"
                );
                // full slip along +x (opposing v_x < 0): |F| = fN to FASTSIM's grid error
                assert!(w.fx > 0.0 && w.fx <= 0.5 * w.n * (1.0 + 1e-5), "{w:?}");
                assert!(w.fx >= 0.5 * w.n * 0.9, "{w:?}");
            }};
        }
        law!(Table);
        law!(Blend);
        law!(Fastsim);
        law!(FastsimGrid<16, 16>);
    }

    /// `RollingSlip::creepages` at a subnormal V: 1/V overflowed and 0·∞ gave NaN.
    #[test]
    fn creepages_at_subnormal_speed() {
        let s = RollingSlip::new(0.0f64, 1e-300, 0.0, 1e-310).unwrap();
        let (x, y, p) = s.creepages().unwrap();
        assert_eq!((x, p), (0.0, 0.0));
        assert!((y - 1e10).abs() < 1e-3 * 1e10);
    }
}

/// The `jacobian` and `step` fuzz targets' findings, replayed byte for byte through the
/// shared checks (f32 then f64 on the same bytes, as the targets run them).
mod jacobian_step_findings {
    use super::checks::{self, Input};

    /// One `step` finding: its bytes through the shared check, f32 then f64 on the same
    /// bytes, as the fuzz target runs them.
    fn replay_step(data: &[u8]) {
        let mut i = Input::new(data);
        checks::step::<f32>(&mut i);
        checks::step::<f64>(&mut i);
    }

    /// One `jacobian` finding: its bytes through the shared check, f32 then f64 on the same
    /// bytes, as the fuzz target runs them.
    fn replay_jacobian(data: &[u8]) {
        let mut i = Input::new(data);
        checks::jacobian::<f32>(&mut i);
        checks::jacobian::<f64>(&mut i);
    }

    /// `blend` at v_x = v_y = f32::MAX (out of the box, barely in contact: N ≈ 1e-24 N): the
    /// Jacobian's value was 0, the wrench's F −8.7e-25 — the dual pass read the slip through
    /// `Slip::or_rest`, which gives rest where finite components overflow their sum.
    #[test]
    fn blend_value_at_a_huge_slip() {
        let data = [
            0x21, 0x21, 0x01, 0x2f, 0x21, 0x21, 0x41, 0xbd, 0xf1, 0xbd, 0xb5, 0x3d, 0xb1, 0x72,
            0x18, 0xe5, 0x0a, 0x1d, 0x38, 0xb1, 0xec, 0x2d, 0xec, 0xec, 0xec, 0xf1,
        ];
        replay_jacobian(&data);
    }

    /// `table` with a slip across the rolling direction but for v_x ≈ 1e-35 (f32): 2d_x²
    /// underflowed to 0 while d_x did not, and the dual pass (which looks the ring up at d_x = 0
    /// for ∂F_x/∂ξ) added √2·|d_x|·Q_x where the plain wrench skipped it: value −5.57e-36 vs
    /// −5.52e-36. Both now branch on d_x, not v.
    #[test]
    fn table_value_where_v_underflows() {
        let data = [
            0x15, 0x5b, 0x05, 0x05, 0x05, 0x67, 0x05, 0x27, 0x05, 0x15, 0xf5, 0xfa, 0x05, 0x05,
            0x15, 0x27, 0x05, 0xf7, 0x1e, 0x05, 0x5b, 0x05, 0x69, 0x5b, 0x05, 0x7a, 0x05, 0x69,
            0x0a, 0x05, 0xae, 0x40, 0x25,
        ];
        replay_jacobian(&data);
    }

    /// W = L·Lᵀ whose diagonal underflowed: refused as not positive semidefinite (was: not
    /// symmetric).
    #[test]
    fn step_w_from_tiny_factors() {
        let a = [
            0xfd, 0x3f, 0xfd, 0x3d, 0xc1, 0xc1, 0xc1, 0x3d, 0xfd, 0x3f, 0xfd, 0x3d, 0xc1, 0xc1,
            0xc1, 0xc9, 0xc1, 0xc1, 0x3d, 0x3d, 0x68, 0xc1, 0xc9, 0x7d, 0x3d, 0x89, 0x89, 0x3d,
            0xc1, 0xc1, 0xc1, 0xc9, 0x32,
        ];
        let b = [
            0xfd, 0x3d, 0xfd, 0x3d, 0xc1, 0x23, 0xc5, 0xc1, 0x3d, 0x3d, 0xf5, 0xcf, 0xc2, 0xfd,
            0xd0, 0xfd, 0x3d, 0xc1, 0x23, 0xc5, 0xc1, 0x3d, 0x3d, 0xf5, 0xcf, 0xc2, 0xfd, 0xd0,
            0x3d, 0xb4, 0xb4,
        ];
        // a rank-deficient f64 W = L·Lᵀ with a nearly repeated row (|L_21| ≈ 33 in the
        // scaled factorisation): pivot −2.1e-13 against the fixed floor 5.7e-14 — refused as
        // not positive semidefinite, documented (the check's box now needs L of full rank)
        let c = [
            0xfd, 0x3d, 0xfd, 0x3d, 0xfd, 0xb5, 0x3d, 0xdd, 0x3d, 0x3d, 0x70, 0xdd, 0xb5, 0x3d,
            0x3d, 0x3d, 0x70, 0xc1, 0xc1, 0xad, 0xad, 0xad, 0xad, 0xad, 0x3f, 0x86, 0x23, 0x2a,
            0xad, 0xad, 0xad, 0xc1, 0xc1, 0xc1, 0xc1, 0xad, 0xad, 0x01, 0x00, 0x00, 0x52, 0x52,
            0x52, 0xc0, 0x7e, 0x23, 0x2a, 0xad, 0xad, 0xad, 0xad, 0xad, 0xad, 0xad, 0x3d, 0x3d,
            0x3d, 0x3d, 0xad, 0xad, 0xad, 0xad, 0x23, 0x3f, 0xc8, 0x0f, 0x79, 0xad, 0xad, 0xad,
            0xc9,
        ];
        for data in [&a[..], &b[..], &c[..]] {
            replay_step(data);
        }
    }

    /// The normal re-solve at h = f32::MAX with E* ≈ 1e-38 and Δt ≈ 1.7e-14 (out of the box):
    /// N(h) = (h₀ − h)/c overflowed (c ≈ 7e-29) and the friction's scaling by it gave N = NaN;
    /// N̄ is now kept there.
    #[test]
    fn step_normal_resolve_overflow() {
        let data = [
            0xf5, 0xf5, 0xf5, 0xf5, 0xf5, 0x26, 0xf5, 0xf5, 0x0a, 0xf5, 0x42, 0x05, 0x07, 0x01,
            0x29, 0x52, 0x4f, 0x52, 0x72, 0x11, 0x52, 0x52, 0xf5, 0xf5, 0x8b, 0x8b, 0x8b, 0x8b,
            0x8b, 0x8b, 0x69, 0x3f, 0x12, 0x6b, 0xb1, 0x05, 0xf5, 0x69, 0x7f, 0x69, 0x69, 0x69,
            0x69,
        ];
        replay_step(&data);
    }

    /// `fastsim-16` out of the box (h ≈ 1.6e21, Δt = 1): the re-solved N (3.2e19) scaled a
    /// friction already at 1e21 / 1e31 by N's ratio past f32's range, and the next round read
    /// infinities as NaN; a re-solve or a friction update whose sums are not finite is now not
    /// taken (the step keeps what it had).
    #[test]
    fn step_friction_scaled_past_the_range() {
        let data = [
            0xad, 0x15, 0x15, 0x15, 0x05, 0x15, 0x15, 0xa1, 0x15, 0x15, 0x21, 0x63, 0xa1, 0x26,
            0x3d, 0xa1, 0x3d, 0xa1, 0xb1, 0xa1, 0xad, 0x15, 0xa1, 0x15, 0x15, 0x3d, 0xa1, 0xb1,
            0xa1, 0xad, 0x15, 0xa1, 0x15, 0x15, 0x15, 0xa1, 0xad, 0x15,
        ];
        replay_step(&data);
    }

    /// `fastsim-16` at W = 0 (the plain wrench): F·v = −9,137 W and T_z·ω = +29 W — the check
    /// asked each part to dissipate; a rolling law's pair is one law, checked on its sum.
    #[test]
    fn step_rolling_power_as_a_pair() {
        let data = [
            0x15, 0x40, 0xa1, 0xa1, 0x15, 0x5b, 0x67, 0xc7, 0x3f, 0x29, 0x51, 0xd7, 0x51, 0xff,
            0x15, 0xa1, 0xa1, 0xa1, 0xa1, 0x2b, 0x2b, 0x2b, 0x2b, 0x2b, 0xa1, 0xa1, 0xa1, 0x3d,
            0xb1, 0xa1, 0xa1, 0x3d, 0x3d, 0x3d, 0x3d, 0x3d, 0x31, 0xa1, 0xa1, 0xa1, 0xa1, 0xa1,
            0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x45, 0xcd, 0xa1, 0xa1,
        ];
        replay_step(&data);
    }

    /// `coulomb` in f32 where the linear solve failed (the plain-wrench fallback, N̄ = 9.3e7 N)
    /// and the normal re-solve brought N down to 8 N: u⁺ updated increment by increment was off
    /// by ulp(1.9e8) ≈ 16 m/s, and the final power check passed F_y = −4 N against a true
    /// v_y⁺ = −3 m/s (F·v⁺ = +12 W); u⁺ is now recomputed from the final wrench.
    #[test]
    fn step_end_velocity_after_cancellation() {
        let data = [
            0x61, 0xe5, 0xe5, 0xe5, 0x2b, 0x2f, 0x65, 0xe5, 0x59, 0xe5, 0xe5, 0xe5, 0xe5, 0xe5,
            0xe5, 0x59, 0x59, 0x59, 0x59, 0x59, 0x59, 0x75, 0x75, 0x75, 0x75, 0x75, 0x75, 0x75,
            0x75, 0x75, 0x75, 0x75, 0x75, 0x75, 0x59, 0x59, 0x59, 0x75, 0x75, 0x75, 0x75, 0x75,
            0x75, 0x5f, 0x75, 0x0e, 0x9a, 0x26, 0x1a, 0x1a, 0x24, 0xe5, 0xe5, 0xe5, 0x00, 0x1c,
        ];
        replay_step(&data);
    }
}
