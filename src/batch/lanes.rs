//! The lane vector the batch kernels are written over: a few contacts' values side by side,
//! with exactly the IEEE operations of [`Real`] (add, sub, mul, div, sqrt, sign-bit ops) and
//! masks in place of branches.
//!
//! One kernel, written once against [`Lanes`], runs as `One<T>` (one lane: the scalar
//! fallback on every target, thumbv7em included) or as an x86-64 vector ([`super::x86`]:
//! SSE2 4 × f32 / 2 × f64, AVX 8 × f32 / 4 × f64). Every operation is one correctly rounded
//! IEEE operation per lane (no fused multiply-add: Rust never contracts `a * b + c`), so a
//! lane computes the same bits as the scalar law it mirrors.

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::Real;

/// The widest vector, in lanes (AVX f32): the size of the per-lane scratch arrays.
pub(crate) const MAX_LANES: usize = 8;

/// The last cubic piece of `BestContact` (`PIECES − 1`): [`Lanes::piece`] clamps to it.
pub(crate) const LAST_PIECE: usize = crate::friction::best::CONTACT_PIECES - 1;
/// Entries of a [`Lanes::lookup`] table: the pieces padded to 16 (two 8-float or four
/// 4-double registers; the padding is never selected).
pub(crate) const PIECE_TABLE: usize = 16;
const _: () = assert!(LAST_PIECE < PIECE_TABLE);

/// A vector of `N` values of `T` (see the [module docs](self)). `Mask` is a per-lane
/// boolean; `select(m, a, b)` is `if m { a } else { b }` lane by lane.
pub trait Lanes:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The scalar type.
    type T: Real;
    /// A per-lane boolean.
    type Mask: Copy;
    /// Number of lanes (≤ [`MAX_LANES`]).
    const N: usize;

    /// Every lane `x`.
    fn splat(x: Self::T) -> Self;
    /// The first `N` values of `s` (`s.len() ≥ N`, checked by the callers' `chunks_exact`).
    fn load(s: &[Self::T]) -> Self;
    /// Into the first `N` values of `s` (`s.len() ≥ N`).
    fn store(self, s: &mut [Self::T]);
    /// IEEE square root, correctly rounded.
    fn sqrt(self) -> Self;
    /// |x| (clears the sign bit, as `libm::fabs`).
    fn abs(self) -> Self;
    /// |self| with the sign bit of `sign` (as `libm::copysign`).
    fn copysign(self, sign: Self) -> Self;
    /// self < o (false for NaN).
    fn lt(self, o: Self) -> Self::Mask;
    /// self ≤ o (false for NaN).
    fn le(self, o: Self) -> Self::Mask;
    /// self == o (false for NaN).
    fn eq(self, o: Self) -> Self::Mask;
    /// self ≠ self: NaN.
    fn is_nan(self) -> Self::Mask;
    /// Lane by lane `if m { a } else { b }`.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// m ∧ n.
    fn and(m: Self::Mask, n: Self::Mask) -> Self::Mask;
    /// m ∨ n.
    fn or(m: Self::Mask, n: Self::Mask) -> Self::Mask;
    /// ¬m.
    fn not(m: Self::Mask) -> Self::Mask;
    /// Some lane set.
    fn any(m: Self::Mask) -> bool;
    /// A per-lane index into a [`PIECE_TABLE`]-entry table (see [`Lanes::piece`]).
    type Idx: Copy;
    /// (i, r) with i = min(⌊self⌋, [`LAST_PIECE`]) (as the scalar
    /// `trunc_usize().min(PIECES − 1)` of `BestContact::traction`) and r = self − i, for lanes
    /// 0 ≤ self < 2³¹; any other lane gets some i in 0..=[`LAST_PIECE`].
    fn piece(self) -> (Self::Idx, Self);
    /// Lane l is `table[i_l]` (i from [`Lanes::piece`]).
    fn lookup(table: &[Self::T; PIECE_TABLE], i: Self::Idx) -> Self;
    /// Lane l is `table[idx[l]]` converted (exactly) to `T`. Every `idx[l]` (l < N) must be
    /// `< table.len()`; an index past the end gives 0 on the lane-by-lane path and is the
    /// caller's bug (the AVX2 gather reads it).
    fn gather_f32(table: &[f32], idx: &[u32; MAX_LANES]) -> Self;
    /// Lane `i` of the vector as a scalar array (`out[..N]`).
    fn to_array(self) -> [Self::T; MAX_LANES] {
        let mut out = [Self::T::ZERO; MAX_LANES];
        self.store(&mut out);
        out
    }
    /// From the first `N` values of `a`.
    fn from_array(a: &[Self::T; MAX_LANES]) -> Self {
        Self::load(a)
    }

    /// self > o.
    #[inline(always)]
    fn gt(self, o: Self) -> Self::Mask {
        o.lt(self)
    }
    /// self ≥ o.
    #[inline(always)]
    fn ge(self, o: Self) -> Self::Mask {
        o.le(self)
    }
    /// `larger(self, b)` of the friction laws: `if b > self { b } else { self }`.
    #[inline(always)]
    fn larger(self, b: Self) -> Self {
        Self::select(b.gt(self), b, self)
    }
    /// [`Real::max`]: `if o > self || self is NaN { o } else { self }` (keeps −0 against +0,
    /// unlike `maxps`).
    #[inline(always)]
    fn max_real(self, o: Self) -> Self {
        Self::select(Self::or(o.gt(self), self.is_nan()), o, self)
    }
    /// [`Real::min`]: `if o < self || self is NaN { o } else { self }`.
    #[inline(always)]
    fn min_real(self, o: Self) -> Self {
        Self::select(Self::or(o.lt(self), self.is_nan()), o, self)
    }
}

/// [`Lanes::piece`] lane by lane through arrays (the lane types without a table instruction).
#[inline(always)]
pub(crate) fn piece_by_lane<V: Lanes>(v: V) -> ([u8; MAX_LANES], V) {
    let a = v.to_array();
    let mut i = [0u8; MAX_LANES];
    let mut r = [V::T::ZERO; MAX_LANES];
    for ((&x, i), r) in a.iter().zip(i.iter_mut()).zip(r.iter_mut()).take(V::N) {
        let k = x.trunc_usize().min(LAST_PIECE);
        *i = k as u8;
        *r = x - V::T::from_usize(k);
    }
    (i, V::from_array(&r))
}

/// [`Lanes::lookup`] lane by lane through arrays.
#[inline(always)]
pub(crate) fn lookup_by_lane<V: Lanes>(table: &[V::T; PIECE_TABLE], i: &[u8; MAX_LANES]) -> V {
    V::from_array(&i.map(|k| table[usize::from(k) % PIECE_TABLE]))
}

/// [`Lanes::gather_f32`] lane by lane.
#[inline(always)]
pub(crate) fn gather_by_lane<V: Lanes>(table: &[f32], idx: &[u32; MAX_LANES]) -> V {
    let mut a = [V::T::ZERO; MAX_LANES];
    for (x, &i) in a.iter_mut().zip(idx.iter()).take(V::N) {
        let v = table.get(i as usize).copied().unwrap_or(0.0);
        *x = V::T::from_f64(f64::from(v));
    }
    V::from_array(&a)
}

/// One lane: the scalar fallback (every target without a vector implementation, and the tail
/// rows of a batch are evaluated by the scalar call itself).
#[derive(Clone, Copy, Debug)]
pub struct One<T>(pub(crate) T);

macro_rules! one_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<T: Real> $tr for One<T> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                One(self.0 $op o.0)
            }
        }
    };
}
one_op!(Add, add, +);
one_op!(Sub, sub, -);
one_op!(Mul, mul, *);
one_op!(Div, div, /);

impl<T: Real> Neg for One<T> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        One(-self.0)
    }
}

impl<T: Real> Lanes for One<T> {
    type T = T;
    type Mask = bool;
    const N: usize = 1;

    #[inline(always)]
    fn splat(x: T) -> Self {
        One(x)
    }
    #[inline(always)]
    fn load(s: &[T]) -> Self {
        One(s.first().copied().unwrap_or(T::ZERO))
    }
    #[inline(always)]
    fn store(self, s: &mut [T]) {
        if let Some(x) = s.first_mut() {
            *x = self.0;
        }
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        One(self.0.sqrt())
    }
    #[inline(always)]
    fn abs(self) -> Self {
        One(self.0.abs())
    }
    #[inline(always)]
    fn copysign(self, sign: Self) -> Self {
        One(self.0.copysign(sign.0))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> bool {
        self.0 < o.0
    }
    #[inline(always)]
    fn le(self, o: Self) -> bool {
        self.0 <= o.0
    }
    #[inline(always)]
    fn eq(self, o: Self) -> bool {
        self.0 == o.0
    }
    #[inline(always)]
    #[allow(clippy::eq_op)]
    fn is_nan(self) -> bool {
        self.0 != self.0
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m { a } else { b }
    }
    #[inline(always)]
    fn and(m: bool, n: bool) -> bool {
        m & n
    }
    #[inline(always)]
    fn or(m: bool, n: bool) -> bool {
        m | n
    }
    #[inline(always)]
    fn not(m: bool) -> bool {
        !m
    }
    #[inline(always)]
    fn any(m: bool) -> bool {
        m
    }
    type Idx = [u8; MAX_LANES];
    #[inline(always)]
    fn piece(self) -> (Self::Idx, Self) {
        piece_by_lane(self)
    }
    #[inline(always)]
    fn lookup(table: &[T; PIECE_TABLE], i: Self::Idx) -> Self {
        lookup_by_lane(table, &i)
    }
    #[inline(always)]
    fn gather_f32(table: &[f32], idx: &[u32; MAX_LANES]) -> Self {
        gather_by_lane(table, idx)
    }
}
