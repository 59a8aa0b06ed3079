//! x86-64 lane vectors over `core::arch`: SSE2 (the x86-64 baseline: 4 × f32, 2 × f64) and
//! AVX2 (8 × f32, 4 × f64, detected at run time; AVX for the arithmetic, AVX2 for the
//! cross-lane table lookup `vpermps`), and the run-time detection.
//!
//! Only IEEE-exact instructions are used (`add/sub/mul/div/sqrt`, compares, bitwise
//! and/or/xor for signs and selects): no FMA, no approximate reciprocal, no `max` (whose
//! −0/+0 and NaN rules differ from [`crate::Real::max`]). Each lane therefore returns the
//! bits of the scalar operation.
//!
//! Safety: an AVX2 vector exists only inside the batch dispatch's `avx2_*` functions, entered
//! after [`level`] found AVX2 enabled by the CPU and the OS; SSE2 is part of x86-64. Loads and stores read and write
//! exactly `N` values from a slice of at least `N` (the callers pass `chunks_exact(N)`).
#![allow(unsafe_code)]

use core::arch::x86_64::*;
use core::ops::{Add, Div, Mul, Neg, Sub};
use core::sync::atomic::{AtomicU8, Ordering};

use super::lanes::{
    LAST_PIECE, Lanes, MAX_LANES, PIECE_TABLE, gather_by_lane, lookup_by_lane, piece_by_lane,
};

/// `impl Trait for Vector`, `fn method(self, o) = intrinsic(self, o)`, for each
/// `Trait method intrinsic`.
macro_rules! binary_ops {
    ($name:ident: $($trait:ident $method:ident $f:ident),*) => {$(
        impl $trait for $name {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                $name(unsafe { $f(self.0, o.0) })
            }
        }
    )*};
}

macro_rules! vector {
    (
        $name:ident, $mask:ident, $t:ty, $reg:ty, $n:literal, $feat:literal,
        add $add:ident, sub $sub:ident, mul $mul:ident, div $div:ident, sqrt $sqrt:ident,
        and $and:ident, andnot $andnot:ident, or $or:ident, xor $xor:ident,
        set1 $set1:ident, loadu $loadu:ident, storeu $storeu:ident, movemask $movemask:ident,
        ones $ones:expr,
        lt |$la:ident, $lb:ident| $lt:expr,
        le |$ea:ident, $eb:ident| $le:expr,
        eq |$qa:ident, $qb:ident| $eq:expr,
        nan |$na:ident| $nan:expr,
        select |$sm:ident, $sa:ident, $sb:ident| $select:expr,
        idx $idx:ty,
        piece |$pv:ident| $piece:expr,
        lookup |$tt:ident, $li:ident| $lookup:expr,
        gather |$gt:ident, $gi:ident| $gather:expr
    ) => {
        #[doc = concat!($n, " lanes of `", stringify!($t), "` (", $feat, ").")]
        #[derive(Clone, Copy, Debug)]
        pub struct $name($reg);

        #[doc = concat!("A per-lane mask of [`", stringify!($name), "`] (all bits set = true).")]
        #[derive(Clone, Copy, Debug)]
        pub struct $mask($reg);

        binary_ops!($name: Add add $add, Sub sub $sub, Mul mul $mul, Div div $div);
        impl Neg for $name {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                $name(unsafe { $xor(self.0, $set1(-0.0)) })
            }
        }

        impl Lanes for $name {
            type T = $t;
            type Mask = $mask;
            const N: usize = $n;

            #[inline(always)]
            fn splat(x: $t) -> Self {
                $name(unsafe { $set1(x) })
            }
            #[inline(always)]
            fn load(s: &[$t]) -> Self {
                debug_assert!(s.len() >= $n);
                $name(unsafe { $loadu(s.as_ptr()) })
            }
            #[inline(always)]
            fn store(self, s: &mut [$t]) {
                debug_assert!(s.len() >= $n);
                unsafe { $storeu(s.as_mut_ptr(), self.0) }
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $name(unsafe { $sqrt(self.0) })
            }
            #[inline(always)]
            fn abs(self) -> Self {
                $name(unsafe { $andnot($set1(-0.0), self.0) })
            }
            #[inline(always)]
            fn copysign(self, sign: Self) -> Self {
                unsafe {
                    let m = $set1(-0.0);
                    $name($or($andnot(m, self.0), $and(m, sign.0)))
                }
            }
            #[inline(always)]
            fn lt(self, o: Self) -> $mask {
                let ($la, $lb) = (self.0, o.0);
                $mask(unsafe { $lt })
            }
            #[inline(always)]
            fn le(self, o: Self) -> $mask {
                let ($ea, $eb) = (self.0, o.0);
                $mask(unsafe { $le })
            }
            #[inline(always)]
            fn eq(self, o: Self) -> $mask {
                let ($qa, $qb) = (self.0, o.0);
                $mask(unsafe { $eq })
            }
            #[inline(always)]
            fn is_nan(self) -> $mask {
                let $na = self.0;
                $mask(unsafe { $nan })
            }
            #[inline(always)]
            fn select(m: $mask, a: Self, b: Self) -> Self {
                let ($sm, $sa, $sb) = (m.0, a.0, b.0);
                $name(unsafe { $select })
            }
            #[inline(always)]
            fn and(m: $mask, n: $mask) -> $mask {
                $mask(unsafe { $and(m.0, n.0) })
            }
            #[inline(always)]
            fn or(m: $mask, n: $mask) -> $mask {
                $mask(unsafe { $or(m.0, n.0) })
            }
            #[inline(always)]
            fn not(m: $mask) -> $mask {
                $mask(unsafe { $xor(m.0, $ones) })
            }
            #[inline(always)]
            fn any(m: $mask) -> bool {
                unsafe { $movemask(m.0) != 0 }
            }
            type Idx = $idx;
            #[inline(always)]
            fn piece(self) -> ($idx, Self) {
                let $pv = self;
                #[allow(unused_unsafe)]
                unsafe {
                    $piece
                }
            }
            #[inline(always)]
            fn lookup($tt: &[$t; PIECE_TABLE], $li: $idx) -> Self {
                #[allow(unused_unsafe)]
                unsafe {
                    $lookup
                }
            }
            #[inline(always)]
            fn gather_f32($gt: &[f32], $gi: &[u32; MAX_LANES]) -> Self {
                #[allow(unused_unsafe)]
                unsafe {
                    $gather
                }
            }
        }
    };
}

/// The four vectors, a column each — SSE2 `f32`, SSE2 `f64`, AVX2 `f32`, AVX2 `f64`: the type
/// row, a row per lane-wise instruction (its intrinsic for each type), and each type's
/// compares, selects and table lookups. `vector!` takes one column at a time.
macro_rules! vectors {
    (
        types: [$($head:tt),*];
        lanewise: { $($op:ident: [$($f:ident),*];)* }
        rest: [$($tail:tt),*];
    ) => {
        vectors!(@column [$($head),*] [$($tail),*] $($op: [$($f),*];)*);
    };
    (@column [] [] $($op:ident: [];)*) => {};
    (@column [$head:tt $(, $heads:tt)*] [$tail:tt $(, $tails:tt)*]
        $($op:ident: [$f:ident $(, $fs:ident)*];)*) => {
        vectors!(@one $head $tail $($op $f),*);
        vectors!(@column [$($heads),*] [$($tails),*] $($op: [$($fs),*];)*);
    };
    // SSE2: compare intrinsics per predicate, no blend (select by and/andnot/or), the table
    // lookups lane by lane.
    (@one $head:tt {
        sse($cast:ident, $lt:ident, $le:ident, $eq:ident, $unord:ident, $or:ident, $and:ident,
            $andnot:ident)
    } $($op:ident $f:ident),*) => {
        vectors!(@one $head {
            ones $cast(_mm_set1_epi32(-1)),
            lt |a, b| $lt(a, b),
            le |a, b| $le(a, b),
            eq |a, b| $eq(a, b),
            nan |a| $unord(a, a),
            select |m, a, b| $or($and(m, a), $andnot(m, b)),
            idx [u8; MAX_LANES],
            piece |v| piece_by_lane(v),
            lookup |t, i| lookup_by_lane(t, &i),
            gather |t, i| gather_by_lane(t, i)
        } $($op $f),*);
    };
    (@one ($($head:tt)*) {$($tail:tt)*} $($op:ident $f:ident),*) => {
        vector!($($head)*, $($op $f),*, $($tail)*);
    };
}

vectors! {
    types: [
        (F32x4, M32x4, f32, __m128, 4, "SSE2"),
        (F64x2, M64x2, f64, __m128d, 2, "SSE2"),
        (F32x8, M32x8, f32, __m256, 8, "AVX2"),
        (F64x4, M64x4, f64, __m256d, 4, "AVX2")
    ];
    lanewise: {
        add: [_mm_add_ps, _mm_add_pd, _mm256_add_ps, _mm256_add_pd];
        sub: [_mm_sub_ps, _mm_sub_pd, _mm256_sub_ps, _mm256_sub_pd];
        mul: [_mm_mul_ps, _mm_mul_pd, _mm256_mul_ps, _mm256_mul_pd];
        div: [_mm_div_ps, _mm_div_pd, _mm256_div_ps, _mm256_div_pd];
        sqrt: [_mm_sqrt_ps, _mm_sqrt_pd, _mm256_sqrt_ps, _mm256_sqrt_pd];
        and: [_mm_and_ps, _mm_and_pd, _mm256_and_ps, _mm256_and_pd];
        andnot: [_mm_andnot_ps, _mm_andnot_pd, _mm256_andnot_ps, _mm256_andnot_pd];
        or: [_mm_or_ps, _mm_or_pd, _mm256_or_ps, _mm256_or_pd];
        xor: [_mm_xor_ps, _mm_xor_pd, _mm256_xor_ps, _mm256_xor_pd];
        set1: [_mm_set1_ps, _mm_set1_pd, _mm256_set1_ps, _mm256_set1_pd];
        loadu: [_mm_loadu_ps, _mm_loadu_pd, _mm256_loadu_ps, _mm256_loadu_pd];
        storeu: [_mm_storeu_ps, _mm_storeu_pd, _mm256_storeu_ps, _mm256_storeu_pd];
        movemask: [_mm_movemask_ps, _mm_movemask_pd, _mm256_movemask_ps, _mm256_movemask_pd];
    }
    rest: [
        {
            sse(_mm_castsi128_ps, _mm_cmplt_ps, _mm_cmple_ps, _mm_cmpeq_ps, _mm_cmpunord_ps, _mm_or_ps,
                _mm_and_ps, _mm_andnot_ps)
        },
        {
            sse(_mm_castsi128_pd, _mm_cmplt_pd, _mm_cmple_pd, _mm_cmpeq_pd, _mm_cmpunord_pd, _mm_or_pd,
                _mm_and_pd, _mm_andnot_pd)
        },
        {
            ones _mm256_castsi256_ps(_mm256_set1_epi32(-1)),
            lt |a, b| _mm256_cmp_ps::<_CMP_LT_OQ>(a, b),
            le |a, b| _mm256_cmp_ps::<_CMP_LE_OQ>(a, b),
            eq |a, b| _mm256_cmp_ps::<_CMP_EQ_OQ>(a, b),
            nan |a| _mm256_cmp_ps::<_CMP_UNORD_Q>(a, a),
            select |m, a, b| _mm256_blendv_ps(b, a, m),
            // (the index, whose low 3 bits pick within a half-table, the upper-half mask i > 7, and
            // whether any lane is there: wide contacts reach piece 8 only at u = ∞)
            idx (__m256i, __m256, bool),
            piece |v| {
                let i = _mm256_cvttps_epi32(v.0);
                let last = _mm256_set1_epi32(LAST_PIECE as i32);
                let i = _mm256_min_epi32(_mm256_max_epi32(i, _mm256_setzero_si256()), last);
                let upper = _mm256_castsi256_ps(_mm256_cmpgt_epi32(i, _mm256_set1_epi32(7)));
                let any = _mm256_movemask_ps(upper) != 0;
                ((i, upper, any), F32x8(_mm256_sub_ps(v.0, _mm256_cvtepi32_ps(i))))
            },
            lookup |t, i| {
                let lo = _mm256_permutevar8x32_ps(_mm256_loadu_ps(t.as_ptr()), i.0);
                if !i.2 {
                    return F32x8(lo);
                }
                let hi = _mm256_permutevar8x32_ps(_mm256_loadu_ps(t.as_ptr().add(8)), i.0);
                F32x8(_mm256_blendv_ps(lo, hi, i.1))
            },
            gather |t, i| F32x8(_mm256_i32gather_ps::<4>(t.as_ptr(), _mm256_loadu_si256(i.as_ptr().cast())))
        },
        {
            ones _mm256_castsi256_pd(_mm256_set1_epi32(-1)),
            lt |a, b| _mm256_cmp_pd::<_CMP_LT_OQ>(a, b),
            le |a, b| _mm256_cmp_pd::<_CMP_LE_OQ>(a, b),
            eq |a, b| _mm256_cmp_pd::<_CMP_EQ_OQ>(a, b),
            nan |a| _mm256_cmp_pd::<_CMP_UNORD_Q>(a, a),
            select |m, a, b| _mm256_blendv_pd(b, a, m),
            // (the 32-bit word pairs of each lane's double within a quarter-table, the masks of
            // bit 2 (odd quarter) and of i > 7 (the third quarter), and whether any lane is there)
            idx (__m256i, __m256d, __m256d, bool),
            piece |v| {
                let i = _mm256_cvttpd_epi32(v.0);
                let last = _mm_set1_epi32(LAST_PIECE as i32);
                let i = _mm_min_epi32(_mm_max_epi32(i, _mm_setzero_si128()), last);
                let r = F64x4(_mm256_sub_pd(v.0, _mm256_cvtepi32_pd(i)));
                let j = _mm256_slli_epi64::<1>(_mm256_cvtepi32_epi64(_mm_and_si128(i, _mm_set1_epi32(3))));
                let pairs = _mm256_or_si256(j, _mm256_slli_epi64::<32>(_mm256_add_epi64(j, _mm256_set1_epi64x(1))));
                let four = _mm_set1_epi32(4);
                let odd = _mm_cmpeq_epi32(_mm_and_si128(i, four), four);
                let odd = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(odd));
                let upper = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm_cmpgt_epi32(i, _mm_set1_epi32(7))));
                let any = _mm256_movemask_pd(upper) != 0;
                ((pairs, odd, upper, any), r)
            },
            lookup |t, i| {
                let quarter = |k: usize| {
                    let q = _mm256_castpd_ps(_mm256_loadu_pd(t.as_ptr().add(4 * k)));
                    _mm256_castps_pd(_mm256_permutevar8x32_ps(q, i.0))
                };
                // i ≤ LAST_PIECE = 11: the fourth quarter (12…15, padding) is never selected
                const { assert!(LAST_PIECE < 12) };
                let lo = _mm256_blendv_pd(quarter(0), quarter(1), i.1);
                if !i.3 {
                    return F64x4(lo);
                }
                F64x4(_mm256_blendv_pd(lo, quarter(2), i.2))
            },
            gather |t, i| F64x4(_mm256_cvtps_pd(_mm_i32gather_ps::<4>(t.as_ptr(), _mm_loadu_si128(i.as_ptr().cast()))))
        }
    ];
}

/// The vector level found on this CPU: 1 = SSE2 (always on x86-64), 2 = AVX2 (CPU and OS).
/// Detected once (CPUID + XGETBV, no `std`), cached.
pub(crate) fn level() -> u8 {
    static LEVEL: AtomicU8 = AtomicU8::new(0);
    let cached = LEVEL.load(Ordering::Relaxed);
    if cached != 0 {
        return cached;
    }
    let found = if avx_enabled() { 2 } else { 1 };
    LEVEL.store(found, Ordering::Relaxed);
    found
}

/// CPUID.1:ECX.AVX[28] and OSXSAVE[27], CPUID.7.0:EBX.AVX2[5], and XCR0 saving the XMM and
/// YMM state (bits 1, 2).
fn avx_enabled() -> bool {
    // SAFETY: CPUID exists on every x86-64 CPU; XGETBV is executed only when OSXSAVE says the
    // OS enabled it.
    unsafe {
        let ecx = __cpuid(1).ecx;
        let (osxsave, avx) = (ecx & (1 << 27) != 0, ecx & (1 << 28) != 0);
        let avx2 = __cpuid(0).eax >= 7 && __cpuid_count(7, 0).ebx & (1 << 5) != 0;
        osxsave && avx && avx2 && xcr0() & 0b110 == 0b110
    }
}

#[target_feature(enable = "xsave")]
unsafe fn xcr0() -> u64 {
    // SAFETY: the caller checked OSXSAVE.
    unsafe { _xgetbv(0) }
}
