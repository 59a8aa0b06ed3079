//! NUL-terminated copies of the library's `&'static str` messages, made at compile time.

/// `s` followed by a NUL byte; `N` must be `s.len() + 1` (checked at compile time where used
/// through [`c_str!`]).
pub(crate) const fn nul_terminated<const N: usize>(s: &str) -> [u8; N] {
    let bytes = s.as_bytes();
    let mut out = [0u8; N];
    let mut i = 0;
    while i < bytes.len() {
        out[i] = bytes[i];
        i += 1;
    }
    out
}

/// A `&'static CStr` of a constant `&str` expression, built at compile time (a NUL inside the
/// string is a compile error, never a run-time panic).
macro_rules! c_str {
    ($s:expr) => {{
        const S: &str = $s;
        const B: [u8; S.len() + 1] = $crate::cstr::nul_terminated::<{ S.len() + 1 }>(S);
        const C: &core::ffi::CStr = match core::ffi::CStr::from_bytes_with_nul(&B) {
            Ok(c) => c,
            Err(_) => panic!("interior NUL in a message"),
        };
        C
    }};
}
pub(crate) use c_str;
