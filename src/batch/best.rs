//! `best` lane by lane: the inside quartic, the outside confocal map, the coefficient pieces
//! (per-contact form) or the per-step table, `assemble` and `bounded`
//! (src/friction/best.rs, best/contact.rs), every branch a select. Lanes inside and outside
//! are both evaluated only when the batch holds both; a lane's result is the scalar call's.

use super::lanes::{Lanes, MAX_LANES, PIECE_TABLE};
use super::laws::Shape;
use super::state::{State, Tr};
use crate::Real;
use crate::friction::best::{
    C40_SERIES, QuarticCoefficients as Quartic, VARYING_NS, VARYING_NZ, VARYING_S0, VARYING_TABLE,
};
use crate::friction::{BestContact, Constants};

/// The quartic's coefficients of a few contacts, lane by lane ([`Quartic::eval`] serves
/// scalars and lanes alike).
impl<V: Lanes> Quartic<V> {
    #[inline(always)]
    fn of(q: &[Quartic<V::T>]) -> Self {
        let lane = |f: fn(&Quartic<V::T>) -> V::T| {
            let mut a = [V::T::ZERO; MAX_LANES];
            for (x, q) in a.iter_mut().zip(q.iter().cycle()) {
                *x = f(q);
            }
            a
        };
        // every field, lane i from the contact i (cycling)
        macro_rules! by_lane {
            ($($field:ident),*) => {
                Quartic {
                    $($field: V::from_array(&lane(|q| q.$field)),)*
                }
            };
        }
        by_lane!(a, b, c, k22, k40, k40m, hb, ha, t40, t22, t40m, m1)
    }

    /// `Quartic::new` lane by lane (each lane's constants in `k`).
    #[inline(always)]
    fn from_shape(k: &Shape<V>) -> Self {
        let (m, m1, a, b) = (k.m, k.m1, k.a, k.b);
        let small = m.lt(splat::<V>(0.05));
        let mut series = splat(0.0);
        for &x in C40_SERIES.iter().rev() {
            series = series * m + splat(x);
        }
        let formula = -(b - m1 * a) / (splat::<V>(12.0) * m);
        let c40 = V::select(small, series, formula);
        let half = V::splat(V::T::HALF);
        let c22 = -half * (a + splat::<V>(12.0) * c40);
        let k40 = splat::<V>(4.0) * c40;
        let three = splat::<V>(3.0);
        let t40 = three * c40;
        let im1 = V::splat(V::T::ONE) / m1;
        Quartic {
            a,
            b,
            c: k.c,
            k22: V::splat(V::T::TWO) * c22,
            k40,
            k40m: k40 * im1,
            hb: half * b,
            ha: half * a,
            t40,
            t22: three * c22,
            t40m: t40 * im1,
            m1,
        }
    }

    /// `Quartic::boundary`: the coefficients at the ellipse (z = 0).
    #[inline(always)]
    fn lane_boundary(&self, gamma: V) -> [V; 7] {
        let (a, b, c, m1) = (self.a, self.b, self.c, self.m1);
        let half = V::splat(V::T::HALF);
        let two = V::splat(V::T::TWO);
        let one = V::splat(V::T::ONE);
        let c40 = V::splat(V::T::from_f64(0.25)) * self.k40;
        let c22 = half * self.k22;
        let three = V::splat(V::T::from_f64(3.0));
        [
            gamma * (a + self.k40),
            gamma * (self.k22 - self.k40),
            b + self.k22 * m1,
            self.k40 - self.k22 * m1,
            -c + half * a * m1 + three * c40 * m1,
            half * (b - a * m1) + three * m1 * (c22 - two * c40),
            three * (c40 * (one + m1) - c22 * m1),
        ]
    }
}

/// A constant in every lane.
#[inline(always)]
fn splat<V: Lanes>(x: f64) -> V {
    V::splat(V::T::from_f64(x))
}

/// The per-contact form splatted: quartic, m, 1 + γ, the number of pieces used and the pieces.
#[derive(Clone, Copy, Debug)]
pub struct Fixed<V: Lanes> {
    quartic: Quartic<V>,
    m: V,
    g1: V,
    /// The pieces used (8, or 12 for the thin patches), as `T`.
    nt: V,
    /// table[4j + k][i] = coefficient k of the cubic j on piece i (one 16-entry table per
    /// coefficient, the 12 stored pieces then zeros: a lane's piece is a cross-lane lookup).
    table: [[V::T; PIECE_TABLE]; 28],
}

impl<V: Lanes> Fixed<V> {
    #[inline(always)]
    pub(crate) fn new(p: &BestContact<V::T>) -> Self {
        let (q, m, g1, nt, pieces) = p.parts();
        let coefficient = |i: usize, jk: usize| {
            pieces
                .get(i)
                .and_then(|piece| piece.get(jk / 4))
                .and_then(|cubic| cubic.get(jk % 4))
                .copied()
                .unwrap_or(V::T::ZERO)
        };
        Fixed {
            quartic: Quartic::of(core::slice::from_ref(q)),
            m: V::splat(m),
            g1: V::splat(g1),
            nt: V::splat(nt),
            table: core::array::from_fn(|jk| core::array::from_fn(|i| coefficient(i, jk))),
        }
    }
}

/// `inside`: the traction of the lanes inside the ellipse (rest included), and that mask.
#[inline(always)]
fn inside<V: Lanes>(q: &Quartic<V>, s: &State<V>) -> (Tr<V>, V::Mask) {
    let zero = V::splat(V::T::ZERO);
    let (x, y, w) = (s.x, s.y, s.w);
    let is_inside = V::not((x * x + q.m1 * y * y).gt(q.m1 * w * w));
    if !V::any(is_inside) {
        return (Tr::zero(), is_inside);
    }
    let iw = V::splat(V::T::ONE) / w.abs();
    let (fx, fy, tz) = q.eval(y * iw, x * iw);
    let t = Tr {
        fx: -fx,
        fy: -fy,
        tz: tz * (w * iw),
    };
    (Tr::select(w.eq(zero), Tr::zero(), t), is_inside)
}

/// `confocal`: (cos ν, sin ν, τ, 1 − |τ|).
#[inline(always)]
fn confocal<V: Lanes>(m: V, g1: V, x: V, y: V, w: V) -> (V, V, V, V) {
    let zero = V::splat(V::T::ZERO);
    let half = V::splat(V::T::HALF);
    let two = V::splat(V::T::TWO);
    let one = V::splat(V::T::ONE);
    let p = x * x + y * y;
    let w2 = w * w;
    let mw2 = m * w2;
    let dlt = p - mw2;
    let mx2w2 = mw2 * x * x;
    let r = (dlt * dlt + V::splat(V::T::from_f64(4.0)) * mx2w2).sqrt();
    let a2 = half * (p + mw2 + r);
    let positive = dlt.ge(zero);
    let b2 = half * (dlt + r);
    // The cancellation-free form, where some lane has Δ < 0 (its division only then).
    let b2 = if V::any(V::not(positive)) {
        V::select(positive, b2, two * mx2w2 / (r - dlt))
    } else {
        b2
    };
    let (ac, bc) = (a2.sqrt(), b2.sqrt().larger(V::splat(V::T::MIN_POSITIVE)));
    let tau = g1 * w / (ac + bc);
    (x / bc, y / ac, tau, one - tau.abs())
}

/// `assemble` then `bounded`.
#[inline(always)]
fn assemble<V: Lanes>(c: V, sn: V, tau: V, k: &[V; 7]) -> Tr<V> {
    let zero = V::splat(V::T::ZERO);
    let one = V::splat(V::T::ONE);
    let q = sn * sn;
    let t = k[4] + q * (k[5] + k[6] * q);
    let fx = -c * (k[0] + k[1] * q);
    let fy = -sn * (k[2] + k[3] * q);
    let tz = tau * V::select(t.lt(zero), t, zero);
    let f2 = fx * fx + fy * fy;
    let over = f2.gt(one);
    if !V::any(over) {
        return Tr { fx, fy, tz };
    }
    let r = one / f2.sqrt();
    Tr {
        fx: V::select(over, fx * r, fx),
        fy: V::select(over, fy * r, fy),
        tz,
    }
}

/// Coefficient j on each lane's piece i at r: c₀ + r(c₁ + r(c₂ + r c₃)).
#[inline(always)]
fn cubic<V: Lanes>(table: &[[V::T; PIECE_TABLE]; 28], j: usize, i: V::Idx, r: V) -> V {
    let c = |k: usize| table.get(4 * j + k).unwrap_or(&table[0]);
    let (c0, c1, c2, c3) = (
        V::lookup(c(0), i),
        V::lookup(c(1), i),
        V::lookup(c(2), i),
        V::lookup(c(3), i),
    );
    c0 + r * (c1 + r * (c2 + r * c3))
}

/// `BestContact::traction`.
#[inline(always)]
pub(crate) fn fixed<V: Lanes>(p: &Fixed<V>, s: &State<V>) -> Tr<V> {
    let (ins, is_inside) = inside(&p.quartic, s);
    if !V::any(V::not(is_inside)) {
        return ins;
    }
    let zero = V::splat(V::T::ZERO);
    let (c, sn, tau, one_minus) = confocal(p.m, p.g1, s.x, s.y, s.w);
    let zn = one_minus.larger(zero).sqrt() * p.nt;
    // The piece of each lane: i = min(⌊zn⌋, 11), r = zn − i (with 8 pieces z = 1 lands on the
    // constant piece 8); the cubic's coefficients looked up.
    let (i, r) = zn.piece();
    let k = [
        cubic(&p.table, 0, i, r),
        cubic(&p.table, 1, i, r),
        cubic(&p.table, 2, i, r),
        cubic(&p.table, 3, i, r),
        cubic(&p.table, 4, i, r),
        cubic(&p.table, 5, i, r),
        cubic(&p.table, 6, i, r),
    ];
    let out = assemble(c, sn, tau, &k);
    Tr::select(is_inside, ins, out)
}

/// `Best::traction` (the per-step form: `per_call` with the per-step table) for a few
/// contacts, each with its own constants `k` (`V::N` rows).
#[inline(always)]
pub(crate) fn varying<V: Lanes>(k: &[Constants<V::T>], s: &State<V>) -> Tr<V> {
    let shape = Shape::<V>::of_lanes(k);
    let q = Quartic::from_shape(&shape);
    let (ins, is_inside) = inside(&q, s);
    if !V::any(V::not(is_inside)) {
        return ins;
    }
    let zero = V::splat(V::T::ZERO);
    let one = V::splat(V::T::ONE);
    let gamma = q.m1.sqrt();
    let g1 = one + gamma;
    let (c, sn, tau, one_minus) = confocal(shape.m, g1, s.x, s.y, s.w);
    let z = one_minus.larger(zero).sqrt();
    // The ends of `coefficients`: the quartic's boundary values and the limits at z = 1.
    let ends0 = q.lane_boundary(gamma);
    let g4 = V::splat(V::T::from_f64(0.4));
    let ends1 = [
        one,
        zero,
        one,
        zero,
        -g4 / (one + gamma),
        g4 * (one - gamma),
        zero,
    ];
    let k = coefficients(gamma, z, &ends0, &ends1);
    let out = assemble(c, sn, tau, &k);
    Tr::select(is_inside, ins, out)
}

/// `best::varying::coefficients` lane by lane: the per-step table's three-node stencil in
/// s = m₁^⅛ = √√γ (weights w) and cubic piece in z, gathered per lane, plus the ends.
#[inline(always)]
fn coefficients<V: Lanes>(gamma: V, z: V, ends0: &[V; 7], ends1: &[V; 7]) -> [V; 7] {
    let table = VARYING_TABLE.as_flattened().as_flattened().as_flattened();
    let (one, two, half) = (
        V::splat(V::T::ONE),
        V::splat(V::T::TWO),
        V::splat(V::T::HALF),
    );
    let scale = V::splat(V::T::from_f64(VARYING_NS as f64 / (1.0 - VARYING_S0)));
    let x = ((gamma.sqrt().sqrt() - V::splat(V::T::from_f64(VARYING_S0))) * scale)
        .max_real(V::splat(V::T::ZERO))
        .min_real(V::splat(V::T::from_usize(VARYING_NS)));
    let zn = z * V::splat(V::T::from_usize(VARYING_NZ));
    // Per lane: the stencil's first node j0, the piece i, and the table offset of (j0, i).
    let (xs, zs) = (x.to_array(), zn.to_array());
    let (mut j0s, mut is) = ([V::T::ZERO; MAX_LANES], [V::T::ZERO; MAX_LANES]);
    let mut base = [0u32; MAX_LANES];
    for l in 0..V::N {
        let (Some(&x), Some(&zn)) = (xs.get(l), zs.get(l)) else {
            break;
        };
        let j0 = x.trunc_usize().min(VARYING_NS - 1).min(VARYING_NS - 2);
        let i = zn.trunc_usize().min(VARYING_NZ - 1);
        if let (Some(a), Some(b), Some(o)) = (j0s.get_mut(l), is.get_mut(l), base.get_mut(l)) {
            (*a, *b) = (V::T::from_usize(j0), V::T::from_usize(i));
            *o = ((j0 * VARYING_NZ + i) * 28) as u32;
        }
    }
    let t = x - V::from_array(&j0s);
    let (t1, t2) = (t - one, t - two);
    let w = [half * t1 * t2, -t * t2, half * t * t1];
    let r = zn - V::from_array(&is);
    let mut v = [V::splat(V::T::ZERO); 7];
    for (node, &wk) in w.iter().enumerate() {
        for (jj, vj) in v.iter_mut().enumerate() {
            let at = |c: usize| {
                let off = ((node * VARYING_NZ * 7 + jj) * 4 + c) as u32;
                base.map(|b| b + off)
            };
            let (c0, c1, c2, c3) = (
                V::gather_f32(table, &at(0)),
                V::gather_f32(table, &at(1)),
                V::gather_f32(table, &at(2)),
                V::gather_f32(table, &at(3)),
            );
            *vj = *vj + wk * (c0 + r * (c1 + r * (c2 + r * c3)));
        }
    }
    let z2 = z * z;
    let mut out = v;
    for ((o, &e0), &e1) in out.iter_mut().zip(ends0).zip(ends1) {
        *o = *o + e0 + (e1 - e0) * z2;
    }
    out
}
