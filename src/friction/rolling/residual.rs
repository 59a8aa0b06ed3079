//! The residual tables of the default rolling law (`Table`) for one contact shape:
//! the curves of the generated data (`table_data`) of the two tabulated shapes around a/b, mixed
//! on each look-up. Data for `RollingShape`, read by the law; see the law's module
//! docs for the formula, the error and the cost.

use super::table_data::{
    COARSE, Data, FINE, KNEE_START, KNEE_WIDTH, SCALE_COARSE, SCALE_FINE, SHAPES as DATA, Shape,
};
use crate::Real;

/// One residual curve of one contact: ln m of the first node, 1/Δ(ln m) (coarse spacing),
/// m₀⁻¹, m_N, and the residual at the nodes, `C` channels (F_x; F_y, M_z; or all three), read
/// from the generated data of the two tabulated shapes around a/b and mixed at the weight `u` on
/// each look-up (nothing copied: a curve is a few numbers and two references into flash).
/// With `N` = 29 + 3 · 8 (the curves with φ) the 8 coarse intervals of the knee window hold
/// three more nodes each.
///
/// A view made by [`Tables`] on each look-up (nothing stored per curve but its grid, and that
/// only per contact). Tables built per call ([`Tables::at_ln_once`]) store no grid (`inv_dx` =
/// 0 in the view, never the value of a stored grid): each look-up computes the grid it reads
/// with the same expressions, so the same values bit for bit, and the curves the law does not
/// read cost nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curve<T, const N: usize, const C: usize> {
    x0: T,
    inv_dx: T,
    inv_m0: T,
    m_last: T,
    lo: &'static Data<N, C>,
    hi: &'static Data<N, C>,
    u: T,
}

/// Where ln m falls on a curve: node index and fraction, or a tail factor.
#[derive(Clone, Copy)]
enum At<T> {
    Below(T),
    Between(usize, T),
    Above(T),
}

impl<T: Real, const N: usize, const C: usize> Curve<T, N, C> {
    /// The stored grid of this curve: x₀, 1/Δ, m₀⁻¹, m_N (two `exp`).
    #[inline(always)]
    fn stored_grid(&self) -> [T; 4] {
        let (x0, dx) = self.grid();
        [
            x0,
            T::ONE / dx,
            Self::tail_below(x0),
            Self::tail_above(x0, dx),
        ]
    }

    /// ln m₀ and Δ(ln m), linear in `u` between the two shapes' (rounded to `T`: in `f32`
    /// the data's own `f32` copies, the same values without a run-time conversion).
    #[inline(always)]
    fn grid(&self) -> (T, T) {
        let lerp = |p: T, q: T| p + self.u * (q - p);
        if T::MANTISSA_DIGITS > 24 {
            (
                lerp(T::from_f64(self.lo.0), T::from_f64(self.hi.0)),
                lerp(T::from_f64(self.lo.1), T::from_f64(self.hi.1)),
            )
        } else {
            (
                lerp(T::from_f32(self.lo.3), T::from_f32(self.hi.3)),
                lerp(T::from_f32(self.lo.4), T::from_f32(self.hi.4)),
            )
        }
    }

    /// m₀⁻¹ = e^{−x₀}.
    #[inline(always)]
    fn tail_below(x0: T) -> T {
        (-x0).exp()
    }

    /// m_N = e^{x₀ + (COARSE − 1)Δ}.
    #[inline(always)]
    fn tail_above(x0: T, dx: T) -> T {
        (x0 + T::from_usize(COARSE - 1) * dx).exp()
    }

    /// Its grid stored (built once per contact).
    #[inline(always)]
    fn stored(&self) -> bool {
        self.inv_dx != T::ZERO
    }

    #[inline(always)]
    fn at(&self, lnm: T, m: T, inv_m: T) -> At<T> {
        if self.stored() {
            Self::locate(
                self.x0,
                self.inv_dx,
                lnm,
                m,
                inv_m,
                || self.inv_m0,
                || self.m_last,
            )
        } else {
            let (x0, dx) = self.grid();
            Self::locate(
                x0,
                T::ONE / dx,
                lnm,
                m,
                inv_m,
                || Self::tail_below(x0),
                || Self::tail_above(x0, dx),
            )
        }
    }

    /// Where ln m falls on the grid (x₀, 1/Δ); the tails' factors from `inv_m0`, `m_last`.
    #[inline(always)]
    fn locate(
        x0: T,
        inv_dx: T,
        lnm: T,
        m: T,
        inv_m: T,
        inv_m0: impl Fn() -> T,
        m_last: impl Fn() -> T,
    ) -> At<T> {
        let u = (lnm - x0) * inv_dx;
        if u <= T::ZERO {
            At::Below((m * inv_m0()).sq())
        } else if u >= T::from_usize(COARSE - 1) {
            At::Above((m_last() * inv_m).sq())
        } else {
            // the knee window: four node intervals per coarse one
            let g = if N > COARSE {
                let k = (u - T::from_usize(KNEE_START))
                    .max(T::ZERO)
                    .min(T::from_usize(KNEE_WIDTH));
                u + T::from_f64(3.0) * k
            } else {
                u
            };
            let i = g.trunc_usize().min(N - 2);
            At::Between(i, g - T::from_usize(i))
        }
    }

    /// The residual (F_x, F_y, M_z) at ln m (channels the curve lacks: 0; two channels are
    /// F_y, M_z, one is F_x).
    #[inline(always)]
    pub(super) fn eval(&self, lnm: T, m: T, inv_m: T) -> [T; 3] {
        self.value(self.at(lnm, m, inv_m))
    }

    /// [`Self::eval`] at a place found by [`Self::at`] (on this curve or one on the same grid).
    /// Node k of a shape is its `i16` times the power of two `scale[k]` (exact in `T`); the two
    /// shapes' integers are mixed first, then scaled once.
    #[inline(always)]
    fn value(&self, at: At<T>) -> [T; 3] {
        let mut out = [T::ZERO; 3];
        let first = if C == 2 { 1 } else { 0 };
        let scale: &[f32] = if N == FINE {
            &SCALE_FINE
        } else {
            &SCALE_COARSE
        };
        let rows = self.lo.2.iter().zip(self.hi.2.iter());
        for (o, (a, b)) in out.iter_mut().skip(first).zip(rows) {
            let node = |k: usize| {
                let int = |row: &[i16; N]| T::from_f32(f32::from(row.get(k).copied().unwrap_or(0)));
                let (p, q) = (int(a), int(b));
                (p + self.u * (q - p)) * T::from_f32(scale.get(k).copied().unwrap_or(0.0))
            };
            *o = match at {
                At::Below(f) => node(0) * f,
                At::Above(f) => node(N - 1) * f,
                At::Between(i, t) => node(i) + t * (node(i + 1) - node(i)),
            };
        }
        out
    }
}

/// The residual curves of one contact shape: ξ; the η–φ plane at u = 0 (η), 1 (η with φ, same
/// sign), 1½, 2 (φ), 2½, 3 (η with φ, opposite signs), 3½; the ring (ξ at 45° to the plane) at
/// u = 0 (ξ with η), 1, 2, 3.
///
/// Held: the pair of tabulated shapes (`DATA[pair]`, `DATA[pair + 1]`), the weight between them
/// and, per contact, each curve's grid (x₀, 1/Δ, m₀⁻¹, m_N; curves in the order ξ, η, ξ with η,
/// the plane's six, the ring's three); the curves are views made on each look-up. Tables built
/// per call hold no grids (three words written, not twelve curves).
#[derive(Clone, Copy)]
pub struct Tables<T> {
    pair: usize,
    lo: &'static Shape,
    hi: &'static Shape,
    u: T,
    grids: Option<[[T; 4]; 12]>,
}

// By hand: `lo` and `hi` are `DATA[pair]` and `DATA[pair + 1]` (the data type has no `Debug`,
// `PartialEq`).
impl<T: PartialEq> PartialEq for Tables<T> {
    fn eq(&self, other: &Self) -> bool {
        self.pair == other.pair && self.u == other.u && self.grids == other.grids
    }
}

impl<T: core::fmt::Debug> core::fmt::Debug for Tables<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Tables")
            .field("pair", &self.pair)
            .field("u", &self.u)
            .field("grids", &self.grids)
            .finish()
    }
}

impl<T: Copy> Tables<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> Tables<U> {
        Tables {
            pair: self.pair,
            lo: self.lo,
            hi: self.hi,
            u: f(self.u),
            grids: self.grids.map(|g| g.map(|c| c.map(f))),
        }
    }
}

/// Per family of curves (the plane, the ring): `$curves(j, …)`, node `j` (0: the end curve
/// `$end`, `$last`: it mirrored, between: the family's curve `$get(j − 1)`), and
/// `$name(j, t, …)`, the nodes `j` and `j + 1` mixed at `t` ∈ [0, 1) with one look-up for
/// both where they share their grid (`$shared`). Written once, expanded per family: one
/// generic function over both measured 863 against 787 M4F instructions per call, with the
/// nodes copied per contact.
macro_rules! mix {
    ($(
        $(#[$mix_doc:meta])* $name:ident: $shared:ident;
        $(#[$node_doc:meta])* $curves:ident: $end:ident, $get:ident, $last:literal;
    )*) => {$(
        $(#[$mix_doc])*
        #[inline(always)]
        pub(super) fn $name(&self, j: usize, t: T, lnm: T, m: T, inv_m: T) -> [T; 3] {
            if t > T::ZERO
                && j >= 1
                && $shared.get(self.pair).and_then(|s| s.get(j - 1)) == Some(&true)
            {
                let (a, b) = (self.$get(j - 1), self.$get(j));
                let at = a.at(lnm, m, inv_m);
                return lerp(a.value(at), b.value(at), t);
            }
            let a = self.$curves(j, lnm, m, inv_m);
            if t > T::ZERO {
                lerp(a, self.$curves(j + 1, lnm, m, inv_m), t)
            } else {
                a
            }
        }

        $(#[$node_doc])*
        #[inline(always)]
        fn $curves(&self, j: usize, lnm: T, m: T, inv_m: T) -> [T; 3] {
            match j {
                0 => self.$end().eval(lnm, m, inv_m),
                $last => mirror(self.$end().eval(lnm, m, inv_m)),
                _ => self.$get(j - 1).eval(lnm, m, inv_m),
            }
        }
    )*};
}

impl<T: Real> Tables<T> {
    /// For a/b: the generated tables linear in ln(a/b) between the tabulated shapes, the end
    /// shapes outside [1/20, 20] ([`Self::at_ln`] at x = ln(a/b)).
    pub fn new(a_over_b: T) -> Self {
        Self::at_ln(T::from_f64(libm::log(super::within(
            a_over_b.to_f64(),
            0.05,
            20.0,
        ))))
    }

    mix! {
        /// The plane's nodes `j` and `j + 1` mixed at `t` ∈ [0, 1).
        plane_mix: SHARED_PLANE;
        /// The η–φ plane at node `j` ∈ 0..=7 (u = 0, 1, 1½, … 3½, 4; 7: η mirrored).
        plane: eta, plane_curve, 7;
        /// The ring's nodes `j` and `j + 1` mixed at `t` ∈ [0, 1).
        ring_mix: SHARED_RING;
        /// The ring at node `j` ∈ 0..=4 of u (4: ξ with η mirrored).
        ring: xieta, ring_curve, 4;
    }
}

/// The y-reflection: (F_x, −F_y, −M_z).
#[inline(always)]
fn mirror<T: Real>(w: [T; 3]) -> [T; 3] {
    [w[0], -w[1], -w[2]]
}

/// a + t(b − a), channel by channel.
#[inline(always)]
pub(super) fn lerp<T: Real>(a: [T; 3], b: [T; 3], t: T) -> [T; 3] {
    [
        a[0] + t * (b[0] - a[0]),
        a[1] + t * (b[1] - a[1]),
        a[2] + t * (b[2] - a[2]),
    ]
}

impl<T: Real> Tables<T> {
    /// The tables for a/b = e^x (a contact's, or a per-call shape's: `crate::contact::Rolling`
    /// with a skewed rolling velocity or a varying contact): the tabulated shapes around x and
    /// the weight between them (linear in ln(a/b), the end shapes outside [1/20, 20]) and each
    /// curve's grid (two `exp` per curve, 24 in all), no node copied.
    pub fn at_ln(x: T) -> Self {
        Self::build(x, false)
    }

    /// [`Self::at_ln`] for tables used by one look-up (a per-call shape): the pair and the
    /// weight only (no grid, no `exp` here); a look-up computes the grid it reads, in a tail
    /// its curve's one factor (the same values bit for bit).
    pub fn at_ln_once(x: T) -> Self {
        Self::build(x, true)
    }

    /// [`Self::at_ln_once`] from the tabulated shapes `i`, `i + 1` and the weight `u`
    /// ([`super::fitted::between`], shared with `blend`'s constants of the same shape).
    #[inline(always)]
    pub(super) fn between_once(at: (usize, T)) -> Self {
        Self::from_pair(at, true)
    }

    #[inline(always)]
    fn build(x: T, once: bool) -> Self {
        Self::from_pair(super::fitted::between(x), once)
    }

    #[inline(always)]
    fn from_pair((i, u): (usize, T), once: bool) -> Self {
        let pair = i.min(DATA.len() - 2);
        let mut tables = Self {
            pair,
            // `get`: no bounds-check panic path at any opt-level (pair ≤ len − 2)
            lo: DATA.get(pair).unwrap_or(&DATA[0]),
            hi: DATA.get(pair + 1).unwrap_or(&DATA[1]),
            u,
            grids: None,
        };
        if !once {
            let mut grids = [[T::ZERO; 4]; 12];
            let [xi, eta, xieta, plane @ .., r0, r1, r2] = &mut grids;
            *xi = tables.xi().stored_grid();
            *eta = tables.eta().stored_grid();
            *xieta = tables.xieta().stored_grid();
            for (k, g) in plane.iter_mut().enumerate() {
                *g = tables.plane_curve(k).stored_grid();
            }
            for (k, g) in [r0, r1, r2].into_iter().enumerate() {
                *g = tables.ring_curve(k).stored_grid();
            }
            tables.grids = Some(grids);
        }
        tables
    }

    /// The view of curve `k` (the order of `grids`) of the data `pick` selects.
    #[inline(always)]
    fn curve<const N: usize, const C: usize>(
        &self,
        k: usize,
        pick: impl Fn(&'static Shape) -> &'static Data<N, C>,
    ) -> Curve<T, N, C> {
        let [x0, inv_dx, inv_m0, m_last] = match &self.grids {
            Some(g) => g.get(k).copied().unwrap_or([T::ZERO; 4]),
            None => [T::ZERO; 4],
        };
        Curve {
            x0,
            inv_dx,
            inv_m0,
            m_last,
            lo: pick(self.lo),
            hi: pick(self.hi),
            u: self.u,
        }
    }

    /// ξ (F_x).
    #[inline(always)]
    pub(super) fn xi(&self) -> Curve<T, COARSE, 1> {
        self.curve(0, |s| &s.xi)
    }

    /// η (F_y, M_z).
    #[inline(always)]
    fn eta(&self) -> Curve<T, COARSE, 2> {
        self.curve(1, |s| &s.eta)
    }

    /// ξ with η.
    #[inline(always)]
    fn xieta(&self) -> Curve<T, COARSE, 3> {
        self.curve(2, |s| &s.xieta)
    }

    /// The plane's curve `k` ∈ 0..6 (u = 1, 1½, 2, 2½, 3, 3½; the last beyond).
    #[inline(always)]
    fn plane_curve(&self, k: usize) -> Curve<T, FINE, 2> {
        let k = k.min(5);
        self.curve(3 + k, move |s| s.plane.get(k).unwrap_or(&s.plane[0]))
    }

    /// The ring's curve `k` ∈ 0..3 (u = 1, 2, 3; the last beyond).
    #[inline(always)]
    fn ring_curve(&self, k: usize) -> Curve<T, FINE, 3> {
        let k = k.min(2);
        self.curve(9 + k, move |s| s.ring.get(k).unwrap_or(&s.ring[0]))
    }
}

/// The same grid in ln m (x₀ and Δ bit for bit) at both tabulated shapes of a pair.
const fn same_grid<const N: usize, const C: usize>(
    a: [&Data<N, C>; 2],
    b: [&Data<N, C>; 2],
) -> bool {
    same_data_grid(a[0], b[0]) && same_data_grid(a[1], b[1])
}

/// x₀ and Δ bit for bit.
const fn same_data_grid<const N: usize, const C: usize>(p: &Data<N, C>, q: &Data<N, C>) -> bool {
    p.0.to_bits() == q.0.to_bits() && p.1.to_bits() == q.1.to_bits()
}

/// The pairs of neighbouring tabulated shapes.
const PAIRS: usize = DATA.len() - 1;

/// Per pair of tabulated shapes (i, i + 1): whether plane[k] and plane[k + 1] share their grid
/// (then curves between the pair's shapes do at every weight: one node search for both).
/// From the data at compile time, not per call.
const SHARED_PLANE: [[bool; 5]; PAIRS] = {
    let mut out = [[false; 5]; PAIRS];
    let mut i = 0;
    while i < PAIRS {
        let (lo, hi) = (&DATA[i], &DATA[i + 1]);
        let mut k = 0;
        while k < 5 {
            out[i][k] = same_grid(
                [&lo.plane[k], &hi.plane[k]],
                [&lo.plane[k + 1], &hi.plane[k + 1]],
            );
            k += 1;
        }
        i += 1;
    }
    out
};

/// The same for ring[k] and ring[k + 1].
const SHARED_RING: [[bool; 2]; PAIRS] = {
    let mut out = [[false; 2]; PAIRS];
    let mut i = 0;
    while i < PAIRS {
        let (lo, hi) = (&DATA[i], &DATA[i + 1]);
        let mut k = 0;
        while k < 2 {
            out[i][k] = same_grid(
                [&lo.ring[k], &hi.ring[k]],
                [&lo.ring[k + 1], &hi.ring[k + 1]],
            );
            k += 1;
        }
        i += 1;
    }
    out
};

#[cfg(test)]
mod tests {
    use super::DATA;

    /// The data's `f32` copies of ln m₀ and Δ(ln m) are the `f64` values rounded to `f32`, so
    /// an `f32` look-up reads the same grid either way.
    #[test]
    fn f32_copies_are_the_rounded_values() {
        let mut n = 0;
        let mut check = |x0: f64, dx: f64, x0_32: f32, dx_32: f32| {
            assert_eq!((x0 as f32).to_bits(), x0_32.to_bits(), "x0 {x0}");
            assert_eq!((dx as f32).to_bits(), dx_32.to_bits(), "dx {dx}");
            n += 1;
        };
        for s in DATA.iter() {
            check(s.xi.0, s.xi.1, s.xi.3, s.xi.4);
            check(s.eta.0, s.eta.1, s.eta.3, s.eta.4);
            check(s.xieta.0, s.xieta.1, s.xieta.3, s.xieta.4);
            for c in &s.plane {
                check(c.0, c.1, c.3, c.4);
            }
            for c in &s.ring {
                check(c.0, c.1, c.3, c.4);
            }
        }
        assert_eq!(n, DATA.len() * 12);
    }
}
