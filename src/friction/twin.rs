//! A friction law and its micromath twin from one core: the law's module writes its core once,
//! `traction::<B: Backend, T>(k, s)` generic over the square root's [`Backend`](crate::math),
//! and [`libm_and_micromath!`] implements [`FrictionLaw`](super::FrictionLaw) for the law
//! (libm) and, with the feature `micromath`, for its twin (micromath's √; `f64` stays libm).
//! Both share the branch type and the ramps; the twin's name is the law's with
//! `-micromath`. The core is `#[inline(always)]`: each law's code is what it would be written
//! out by hand.

/// Declares the twin `$twin` (with its docs, under the feature `micromath`) and implements
/// `FrictionLaw` for `$law` (backend `Libm`) and `$twin` (backend `Micromath`), both calling
/// the module's `traction::<B, T>(k, s)`, with `maximally_dissipative` as
/// [`FrictionLaw::MAXIMALLY_DISSIPATIVE`](super::FrictionLaw::MAXIMALLY_DISSIPATIVE);
/// optionally the ramps κ, κ_T (each with its doc line) for a law that has them.
macro_rules! libm_and_micromath {
    (
        $law:ident: $name:literal, $branch:ty, maximally_dissipative $md:literal,
        $(slip_ramp #[doc = $slip_doc:literal] $slip:expr,
          spin_ramp #[doc = $spin_doc:literal] $spin:expr,)?
        $(#[$twin_doc:meta])*
        twin $twin:ident
    ) => {
        $(#[$twin_doc])*
        #[cfg(feature = "micromath")]
        #[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
        pub struct $twin;

        $crate::friction::twin::libm_and_micromath!(@impl $law, $name, $branch, $md,
            $crate::math::Libm $(, $slip_doc $slip, $spin_doc $spin)?);
        #[cfg(feature = "micromath")]
        #[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
        $crate::friction::twin::libm_and_micromath!(@impl $twin, concat!($name, "-micromath"),
            $branch, $md, $crate::math::Micromath $(, $slip_doc $slip, $spin_doc $spin)?);
    };
    (@impl $law:ident, $name:expr, $branch:ty, $md:literal, $backend:ty
        $(, $slip_doc:literal $slip:expr, $spin_doc:literal $spin:expr)?) => {
        impl $crate::friction::FrictionLaw for $law {
            const NAME: &'static str = $name;
            type Branch = $branch;
            const MAXIMALLY_DISSIPATIVE: bool = $md;
            $crate::friction::law::constants_are_prepared!();
            $(
                #[doc = $slip_doc]
                fn slip_ramp<T: $crate::Real>(_k: &$crate::friction::Constants<T>) -> Option<T> {
                    Some($slip)
                }

                #[doc = $spin_doc]
                fn spin_ramp<T: $crate::Real>(_k: &$crate::friction::Constants<T>) -> Option<T> {
                    Some($spin)
                }
            )?

            #[inline]
            fn traction<T: $crate::Real>(
                k: &$crate::friction::Constants<T>,
                s: &$crate::friction::SlipState<T>,
            ) -> ($crate::friction::Traction<T>, $branch) {
                traction::<$backend, T>(k, s)
            }
        }
    };
}
pub(crate) use libm_and_micromath;
