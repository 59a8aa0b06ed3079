//! The residual tables of the default rolling law (`Table`) for one contact shape:
//! the curves of the generated data (`table_data`) of the two fitted shapes around a/b, mixed
//! on each look-up. Data for `RollingShape`, read by the law; see the law's module
//! docs for the formula, the error and the cost.

use super::table_data::{
    COARSE, Data, FINE, KNEE_START, KNEE_WIDTH, SCALE_COARSE, SCALE_FINE, SHAPES as DATA,
};
use crate::Real;

/// One residual curve of one contact: ln m of the first node, 1/Δ(ln m) (coarse spacing),
/// m₀⁻¹, m_N, and the residual at the nodes, `C` channels (F_x; F_y, M_z; or all three), read
/// from the generated data of the two fitted shapes around a/b and mixed at the weight `u` on
/// each look-up (nothing copied: a curve is a few numbers and two references into flash).
/// With `N` = 29 + 3 · 8 (the curves with φ) the 8 coarse intervals of the knee window hold
/// three more nodes each.
///
/// A curve built per call ([`Tables::at_ln_once`]) stores no grid (`inv_dx` = 0, never the
/// value of a stored grid): each look-up computes the grid it reads with the same expressions,
/// so the same values bit for bit, and the curves the law does not read cost nothing.
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

impl<T: Copy, const N: usize, const C: usize> Curve<T, N, C> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Curve<U, N, C> {
        Curve {
            x0: f(self.x0),
            inv_dx: f(self.inv_dx),
            inv_m0: f(self.inv_m0),
            m_last: f(self.m_last),
            lo: self.lo,
            hi: self.hi,
            u: f(self.u),
        }
    }
}

impl<T: Real, const N: usize, const C: usize> Curve<T, N, C> {
    /// The curve for a/b between the shapes `lo` and `hi` at the weight `u` ∈ [0, 1]: ln m₀ and
    /// Δ(ln m) linear in `u` (rounded to `T`), two `exp`; `once`: no grid stored (see the type
    /// docs).
    #[inline(always)]
    fn between(lo: &'static Data<N, C>, hi: &'static Data<N, C>, u: T, once: bool) -> Self {
        let mut c = Self {
            x0: T::ZERO,
            inv_dx: T::ZERO,
            inv_m0: T::ZERO,
            m_last: T::ZERO,
            lo,
            hi,
            u,
        };
        if !once {
            let (x0, dx) = c.grid();
            c.x0 = x0;
            c.inv_dx = T::ONE / dx;
            c.inv_m0 = Self::tail_below(x0);
            c.m_last = Self::tail_above(x0, dx);
        }
        c
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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tables<T> {
    pub(super) xi: Curve<T, COARSE, 1>,
    eta: Curve<T, COARSE, 2>,
    xieta: Curve<T, COARSE, 3>,
    plane: [Curve<T, FINE, 2>; 6],
    ring: [Curve<T, FINE, 3>; 3],
    /// plane[k] and plane[k + 1] (ring[k], ring[k + 1]) share their grid: one look-up for both.
    plane_shared: [bool; 5],
    ring_shared: [bool; 2],
}

impl<T: Copy> Tables<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> Tables<U> {
        Tables {
            xi: self.xi.map(f),
            eta: self.eta.map(f),
            xieta: self.xieta.map(f),
            plane: self.plane.map(|c| c.map(f)),
            ring: self.ring.map(|c| c.map(f)),
            plane_shared: self.plane_shared,
            ring_shared: self.ring_shared,
        }
    }
}

/// Per family of curves (the plane, the ring): `$curves(j, …)`, node `j` (0: the end curve
/// `$end`, `$last`: it mirrored, between: `$curves[j − 1]`, at most index `$top`), and
/// `$name(j, t, …)`, the nodes `j` and `j + 1` mixed at `t` ∈ [0, 1) with one look-up for
/// both where they share their grid (`$shared`). Written once, expanded per family: one
/// generic function over both measured 863 against 787 M4F instructions per call, with the
/// nodes copied per contact.
macro_rules! mix {
    ($(
        $(#[$mix_doc:meta])* $name:ident: $shared:ident;
        $(#[$node_doc:meta])* $curves:ident: $end:ident, $last:literal, $top:literal;
    )*) => {$(
        $(#[$mix_doc])*
        #[inline(always)]
        pub(super) fn $name(&self, j: usize, t: T, lnm: T, m: T, inv_m: T) -> [T; 3] {
            if t > T::ZERO
                && j >= 1
                && self.$shared.get(j - 1) == Some(&true)
                && let (Some(a), Some(b)) = (self.$curves.get(j - 1), self.$curves.get(j))
            {
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
                0 => self.$end.eval(lnm, m, inv_m),
                $last => mirror(self.$end.eval(lnm, m, inv_m)),
                _ => self.$curves[(j - 1).min($top)].eval(lnm, m, inv_m),
            }
        }
    )*};
}

impl<T: Real> Tables<T> {
    /// For a/b: the generated tables linear in ln(a/b) between the fitted shapes, the end
    /// shapes outside [0.2, 5] ([`Self::at_ln`] at x = ln(a/b)).
    pub fn new(a_over_b: T) -> Self {
        Self::at_ln(T::from_f64(libm::log(super::within(
            a_over_b.to_f64(),
            0.2,
            5.0,
        ))))
    }

    mix! {
        /// The plane's nodes `j` and `j + 1` mixed at `t` ∈ [0, 1).
        plane_mix: plane_shared;
        /// The η–φ plane at node `j` ∈ 0..=7 (u = 0, 1, 1½, … 3½, 4; 7: η mirrored).
        plane: eta, 7, 5;
        /// The ring's nodes `j` and `j + 1` mixed at `t` ∈ [0, 1).
        ring_mix: ring_shared;
        /// The ring at node `j` ∈ 0..=4 of u (4: ξ with η mirrored).
        ring: xieta, 4, 2;
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
    /// with a skewed rolling velocity or a varying contact): the fitted shapes around x and
    /// the weight between them (linear in ln(a/b), the end shapes outside [0.2, 5]); per curve
    /// two `exp` (24 in all), no node copied.
    pub fn at_ln(x: T) -> Self {
        Self::build(x, false)
    }

    /// [`Self::at_ln`] for tables used by one look-up (a per-call shape): no `exp` here; a
    /// look-up in a tail computes its curve's one factor (the same values bit for bit).
    pub fn at_ln_once(x: T) -> Self {
        Self::build(x, true)
    }

    #[inline(always)]
    fn build(x: T, once: bool) -> Self {
        let (i, u) = super::fitted::between(x);
        let (lo, hi) = (&DATA[i.min(3)], &DATA[i.min(3) + 1]);
        let p = |k: usize| Curve::between(&lo.plane[k], &hi.plane[k], u, once);
        let plane: [Curve<T, FINE, 2>; 6] = [p(0), p(1), p(2), p(3), p(4), p(5)];
        let r = |k: usize| Curve::between(&lo.ring[k], &hi.ring[k], u, once);
        let ring: [Curve<T, FINE, 3>; 3] = [r(0), r(1), r(2)];
        Self {
            xi: Curve::between(&lo.xi, &hi.xi, u, once),
            eta: Curve::between(&lo.eta, &hi.eta, u, once),
            xieta: Curve::between(&lo.xieta, &hi.xieta, u, once),
            plane_shared: SHARED_PLANE[i.min(3)],
            ring_shared: SHARED_RING[i.min(3)],
            plane,
            ring,
        }
    }
}

/// The same grid in ln m (x₀ and Δ bit for bit) at both fitted shapes of a pair.
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

/// Per pair of fitted shapes (i, i + 1): whether plane[k] and plane[k + 1] share their grid
/// (then curves between the pair's shapes do at every weight: one node search for both).
/// From the data at compile time, not per call.
const SHARED_PLANE: [[bool; 5]; 4] = {
    let mut out = [[false; 5]; 4];
    let mut i = 0;
    while i < 4 {
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
const SHARED_RING: [[bool; 2]; 4] = {
    let mut out = [[false; 2]; 4];
    let mut i = 0;
    while i < 4 {
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
        assert_eq!(n, 5 * 12);
    }
}
