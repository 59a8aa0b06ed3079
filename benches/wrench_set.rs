// The wrench benchmarks' fixed scene, shared verbatim (`include!`, after `friction_set.rs`) by
// the host bench `benches/wrench.rs` and the QEMU stage `firmware/src/bench_wrench.rs`.

/// The 209 bearing's inner-race contact (ball Ø 12.7 mm, groove radius 6.6 mm, pitch Ø 65 mm),
/// steel on steel (E* = 1.142857e11 Pa), f = 0.07 with no regularization, approach h = 5 µm
/// (a ≈ 1.1 mm): the fixed contact, the varying one, h, and the mixed set as slips
/// (v = u·a·ω, ω = 100 rad/s).
#[allow(clippy::type_complexity)]
fn wrench_scene<T: Real, L: FrictionLaw>() -> (
    Curvatures<T>,
    Contact<T, Hertz<T>, Undamped, L>,
    VaryingContact<T, Undamped, L>,
    T,
    [Slip<T>; SET],
) {
    let curv = Curvatures::<T>::ball_race(
        T::from_f64(12.7e-3),
        T::from_f64(6.6e-3),
        T::from_f64(65e-3),
        T::ZERO,
        Race::Inner,
    )
    .expect("valid bearing geometry");
    let estar = Modulus::new(T::from_f64(1.142857e11)).expect("positive modulus");
    let friction = Friction::<T, L>::with_law(T::from_f64(0.07), T::ZERO).expect("valid f");
    let contact =
        Contact::hertz::<Newton>(&curv, estar, Undamped, friction).expect("g in the domain");
    let varying = VaryingContact::new(estar, Undamped, friction);
    let h = T::from_f64(5e-6);
    let a = contact.wrench(h, T::ZERO, Slip::default()).patch.a.to_f64();
    let pairs = mixed_set();
    let slips = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let v = u * a * 100.0;
        Slip::new(
            T::from_f64(v * libm::cos(psi)),
            T::from_f64(v * libm::sin(psi)),
            T::from_f64(100.0),
        )
        .expect("finite slip")
    });
    (curv, contact, varying, h, slips)
}
