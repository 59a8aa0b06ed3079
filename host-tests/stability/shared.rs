//! Shared by `host-tests/stability.rs` and `examples/stability.rs`: the reference tables, the
//! large-u series and the block-under-friction integrator whose stable step is bisected.
#![allow(dead_code)]

use contensou::friction::{Constants, Explicit, Friction, FrictionLaw, Slip};

/// Relative error.
pub fn rel(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

fn parse(line: &str) -> Vec<f64> {
    line.split(',').map(|f| f.parse().unwrap()).collect()
}

/// (x, K, E, D) rows of `tools/data/stability_elliptic.csv` of one kind: `"m"` (x = m, small)
/// or `"m1"` (x = m₁ = 1 − m, near m = 1).
pub fn elliptic_rows(kind: &str) -> Vec<[f64; 4]> {
    include_str!("../../tools/data/stability_elliptic.csv")
        .lines()
        .skip(1)
        .filter_map(|l| l.strip_prefix(kind).and_then(|r| r.strip_prefix(',')))
        .map(|r| {
            let v = parse(r);
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// One row of `tools/data/stability_shape.csv`: g, c, m₁, K, E, B, D and a, b, N for P = g,
/// Q = 1, E* = 1, h = 1.
pub struct ShapeRow {
    pub g: f64,
    pub c: f64,
    pub m1: f64,
    pub a: f64,
    pub b: f64,
    pub n: f64,
}

pub fn shape_rows() -> Vec<ShapeRow> {
    include_str!("../../tools/data/stability_shape.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let v = parse(l);
            ShapeRow {
                g: v[0],
                c: v[1],
                m1: v[2],
                a: v[7],
                b: v[8],
                n: v[9],
            }
        })
        .collect()
}

/// The two-term large-u series of model.md §3 at (m = e², ψ, u): (F_x, F_y) = −w + F₂/u²,
/// T_z = T₁/u, in fN and fNa. Independent of the crate's own copy in `friction::exact`.
pub fn series(m: f64, psi: f64, u: f64) -> [f64; 3] {
    let (be, al) = psi.sin_cos();
    let p2 = 1.5 * al * al - 0.5;
    let f2x = 0.2 * (0.5 * al + m * (p2 * al - al));
    let f2y = 0.2 * (0.5 * be + m * p2 * be);
    [
        -al + f2x / (u * u),
        -be + f2y / (u * u),
        -0.2 * (1.0 - m * be * be) / u,
    ]
}

/// Does `scheme` at step h bring a block of mass `mass` (1-D, point contact, no spin, starting
/// at v₀ = δ/10, inside the law's ramp) to rest under the library's friction law? Unstable if
/// |v| ever exceeds 2v₀ or, with `sign_change`, if v ever changes sign (Euler's oscillation
/// onset); stable if after 2,000 steps |v| < v₀/2.
pub fn comes_to_rest<L: FrictionLaw>(
    law: &Friction<f64, L>,
    mass: f64,
    n: f64,
    h: f64,
    scheme: Explicit,
    sign_change: bool,
) -> bool {
    let k = Constants::circle();
    let acc = |v: f64| {
        law.tangential(&k, 0.0, n, Slip::new(v, 0.0, 0.0).unwrap())
            .fx
            / mass
    };
    let v0 = 0.1 * law.delta();
    let mut v = v0;
    for _ in 0..2000 {
        let next = match scheme {
            Explicit::Euler => v + h * acc(v),
            Explicit::Rk4 => {
                let k1 = acc(v);
                let k2 = acc(v + 0.5 * h * k1);
                let k3 = acc(v + 0.5 * h * k2);
                let k4 = acc(v + h * k3);
                v + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
            }
        };
        if (sign_change && next * v < 0.0) || next.abs() > 2.0 * v0 {
            return false;
        }
        v = next;
    }
    sign_change || v.abs() < 0.5 * v0
}

/// The largest step at which [`comes_to_rest`] holds, bisected (50 halvings) in
/// [h_est/10, 10·h_est] around `h_est`.
pub fn measured_step<L: FrictionLaw>(
    law: &Friction<f64, L>,
    mass: f64,
    n: f64,
    scheme: Explicit,
    sign_change: bool,
    h_est: f64,
) -> f64 {
    let (mut lo, mut hi) = (0.1 * h_est, 10.0 * h_est);
    for _ in 0..50 {
        let mid = 0.5 * (lo + hi);
        if comes_to_rest(law, mass, n, mid, scheme, sign_change) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}
