//! `defmt::Format` for the types firmware logs (feature `defmt`): the error, the patch, the
//! dimensionless traction, the tangential result, the wrench and the rolling wrench (branches
//! are left out: they are diagnostics with a `Debug` form on host).

use defmt::{Format, Formatter, write};

use crate::Error;
use crate::contact::Wrench;
use crate::friction::{Tangential, Traction};
use crate::normal::Patch;

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl Format for Error {
    fn format(&self, f: Formatter<'_>) {
        match self {
            Error::NonFinite(what) => write!(f, "{=str} must be finite", what),
            other => write!(f, "{=str}", other.as_str()),
        }
    }
}

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<T: Format> Format for Patch<T> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Patch {{ h: {}, a: {}, b: {}, n: {}, p0: {}, e2: {} }}",
            self.h, self.a, self.b, self.n, self.p0, self.e2
        )
    }
}

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<T: Format> Format for Traction<T> {
    fn format(&self, f: Formatter<'_>) {
        forces(f, "Traction", &self.fx, &self.fy, &self.tz)
    }
}

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<T: Format, B> Format for Tangential<T, B> {
    fn format(&self, f: Formatter<'_>) {
        forces(f, "Tangential", &self.fx, &self.fy, &self.tz)
    }
}

/// `name { fx: …, fy: …, tz: … }`: the traction and the tangential result.
fn forces<T: Format>(f: Formatter<'_>, name: &str, fx: &T, fy: &T, tz: &T) {
    write!(f, "{=str} {{ fx: {}, fy: {}, tz: {} }}", name, fx, fy, tz)
}

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<T: Format, B> Format for Wrench<T, B> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Wrench {{ n: {}, fx: {}, fy: {}, tz: {}, a: {}, b: {} }}",
            self.n, self.fx, self.fy, self.tz, self.patch.a, self.patch.b
        )
    }
}

#[cfg_attr(docsrs, doc(cfg(feature = "defmt")))]
impl<T: Format> Format for crate::friction::rolling::Wrench<T> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "RollingWrench {{ fx: {}, fy: {}, mz: {} }}",
            self.fx, self.fy, self.mz
        )
    }
}
