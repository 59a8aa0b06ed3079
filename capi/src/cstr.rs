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

/// The summed lengths of `names` with a NUL each: the length of [`nul_joined`]'s buffer.
pub(crate) const fn nul_joined_len(names: &[&str]) -> usize {
    let mut total = 0;
    let mut k = 0;
    while k < names.len() {
        total += names[k].len() + 1;
        k += 1;
    }
    total
}

/// `names` one after the other, each followed by a NUL; `N` must be
/// [`nul_joined_len`]`(names)` (checked at compile time where used through [`c_strs!`]).
pub(crate) const fn nul_joined<const N: usize>(names: &[&str]) -> [u8; N] {
    let mut out = [0u8; N];
    let mut at = 0;
    let mut k = 0;
    while k < names.len() {
        let bytes = names[k].as_bytes();
        let mut i = 0;
        while i < bytes.len() {
            out[at + i] = bytes[i];
            i += 1;
        }
        at += bytes.len() + 1;
        k += 1;
    }
    out
}

/// The `K` NUL-terminated strings of a [`nul_joined`] buffer, in order (a missing NUL or one
/// inside a name is a compile error where used through [`c_strs!`]).
pub(crate) const fn split_nul_joined<const K: usize>(
    mut bytes: &'static [u8],
) -> [&'static core::ffi::CStr; K] {
    let mut out = [c_str!(""); K];
    let mut k = 0;
    while k < K {
        let mut end = 0;
        while bytes[end] != 0 {
            end += 1;
        }
        let (head, rest) = bytes.split_at(end + 1);
        out[k] = match core::ffi::CStr::from_bytes_with_nul(head) {
            Ok(c) => c,
            Err(_) => panic!("interior NUL in a name"),
        };
        bytes = rest;
        k += 1;
    }
    out
}

/// The `&'static CStr`s of a constant array of `K` `&str`s, built at compile time.
macro_rules! c_strs {
    ($names:expr; $k:literal) => {{
        const NAMES: [&str; $k] = $names;
        const LEN: usize = $crate::cstr::nul_joined_len(&NAMES);
        const B: [u8; LEN] = $crate::cstr::nul_joined::<LEN>(&NAMES);
        const C: [&core::ffi::CStr; $k] = $crate::cstr::split_nul_joined::<$k>(&B);
        C
    }};
}
pub(crate) use c_strs;
