//! Shared by `host-tests/stability.rs` and `examples/stability.rs`: the reference tables, the
//! large-u series and the block-under-friction integrator whose stable step is bisected.
#![allow(dead_code)]

use contensou::elliptic::Parameter;
use contensou::friction::{Best, BestContact, Constants, Explicit, Friction, FrictionLaw, Slip};

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

/// One step of `scheme` for the scalar ODE y' = acc(y).
pub fn step1(scheme: Explicit, h: f64, y: f64, acc: impl Fn(f64) -> f64) -> f64 {
    match scheme {
        Explicit::Euler => y + h * acc(y),
        Explicit::Rk4 => {
            let k1 = acc(y);
            let k2 = acc(y + 0.5 * h * k1);
            let k3 = acc(y + 0.5 * h * k2);
            let k4 = acc(y + h * k3);
            y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        }
    }
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
        let next = step1(scheme, h, v, acc);
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

// ---- the `best` law: 2-D block, fixed spin, held at a probe slip by a constant drive -----------

/// A block of mass `mass` sliding under `Friction<f64, Best>` (prepared for `k`) at normal
/// force `n`, with its spin held at a·ω = `aw` (a = 1 m, so ω = `aw` rad/s) and its in-plane
/// velocity integrated. A constant drive −F(v_eq) makes `v_eq` an equilibrium (v_eq = 0: no
/// drive, the block coming to rest).
pub struct BestBlock {
    pub law: Friction<f64, Best>,
    pub contact: BestContact<f64>,
    pub mass: f64,
    pub n: f64,
    pub aw: f64,
}

impl BestBlock {
    pub fn new(k: &Constants<f64>, f: f64, delta: f64, mass: f64, n: f64, aw: f64) -> Self {
        BestBlock {
            law: Friction::new(f, delta).unwrap(),
            contact: Best::prepare(k),
            mass,
            n,
            aw,
        }
    }

    /// The friction force on the block at velocity v.
    pub fn force(&self, v: [f64; 2]) -> [f64; 2] {
        let t = self.law.tangential_prepared(
            &self.contact,
            1.0,
            self.n,
            Slip::new(v[0], v[1], self.aw).unwrap(),
        );
        [t.fx, t.fy]
    }
}

impl Settles for BestBlock {
    type V = [f64; 2];

    /// Does `scheme` at step h keep a perturbation of the equilibrium `v_eq` bounded? The
    /// perturbation starts at `dv0` (|dv0| ≪ δ: the linearisation, unless v_eq = 0 without spin,
    /// where the law is homogeneous along the ray and `dv0` is the block's whole velocity);
    /// unstable if |v − v_eq| ever exceeds 10·|dv0|, stable if it does not within `steps`
    /// steps and ends below |dv0| (a growth by (1 + 2η) per step reaches 10 within 2,000 steps
    /// for η > 5.8e-4).
    fn settles(
        &self,
        v_eq: [f64; 2],
        dv0: [f64; 2],
        h: f64,
        scheme: Explicit,
        steps: usize,
    ) -> bool {
        let f_eq = self.force(v_eq);
        let inv_m = 1.0 / self.mass;
        let acc = |v: [f64; 2]| {
            let f = self.force(v);
            [(f[0] - f_eq[0]) * inv_m, (f[1] - f_eq[1]) * inv_m]
        };
        let axpy = |v: [f64; 2], a: f64, d: [f64; 2]| [v[0] + a * d[0], v[1] + a * d[1]];
        let size = |v: [f64; 2]| (v[0] - v_eq[0]).hypot(v[1] - v_eq[1]);
        let d0 = dv0[0].hypot(dv0[1]);
        let mut v = axpy(v_eq, 1.0, dv0);
        for _ in 0..steps {
            v = match scheme {
                Explicit::Euler => axpy(v, h, acc(v)),
                Explicit::Rk4 => {
                    let k1 = acc(v);
                    let k2 = acc(axpy(v, 0.5 * h, k1));
                    let k3 = acc(axpy(v, 0.5 * h, k2));
                    let k4 = acc(axpy(v, h, k3));
                    let s = [
                        k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0],
                        k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1],
                    ];
                    axpy(v, h / 6.0, s)
                }
            };
            let d = size(v);
            if d > 10.0 * d0 || d.is_nan() {
                return false;
            }
        }
        size(v) < d0
    }
}

impl BestBlock {
    /// Largest eigenvalue (Euler's |λ|²/Re λ for a complex pair) of the stiffness −∂F/∂v at v,
    /// by one-sided differences (towards larger |v_x|, |v_y|), in units of fN/δ.
    pub fn stiffness(&self, v: [f64; 2]) -> f64 {
        let h = 1e-7 * self.law.delta();
        let f0 = self.force(v);
        let sx = if v[0] < 0.0 { -h } else { h };
        let sy = if v[1] < 0.0 { -h } else { h };
        let fx = self.force([v[0] + sx, v[1]]);
        let fy = self.force([v[0], v[1] + sy]);
        let k = [
            [-(fx[0] - f0[0]) / sx, -(fy[0] - f0[0]) / sy],
            [-(fx[1] - f0[1]) / sx, -(fy[1] - f0[1]) / sy],
        ];
        eig_euler(k) * self.law.delta() / (self.law.coefficient() * self.n)
    }
}

/// A body held at an equilibrium velocity by a constant drive ([`BestBlock`], [`SpinBody`]):
/// does a perturbation decay under an explicit scheme, and up to which step.
pub trait Settles {
    /// The integrated velocity: (v_x, v_y) of the block, ω of the spinning body.
    type V: Copy;

    /// Does `scheme` at step h bring a perturbation `d0` of the equilibrium `eq` back (each
    /// body's rule in its impl)?
    fn settles(&self, eq: Self::V, d0: Self::V, h: f64, scheme: Explicit, steps: usize) -> bool;

    /// The largest step at which [`Settles::settles`] holds, bisected (`halvings` times) in
    /// [lo, hi].
    fn measured_step(
        &self,
        eq: Self::V,
        d0: Self::V,
        scheme: Explicit,
        steps: usize,
        range: (f64, f64),
        halvings: usize,
    ) -> f64 {
        bisect(range, halvings, |h| self.settles(eq, d0, h, scheme, steps))
    }
}

/// The largest step in [lo, hi] at which `stable` holds, bisected `halvings` times (stable at
/// `lo` and unstable at `hi` assumed): the returned step is below the threshold by at most
/// (hi − lo)/2^halvings.
pub fn bisect((mut lo, mut hi): (f64, f64), halvings: usize, stable: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..halvings {
        let mid = 0.5 * (lo + hi);
        if stable(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The exact law's dissipation per unit fN, p = −(F·v_P + T_z·ω)/(fN), at (v_Px, v_Py, aω)
/// (the `best` ramp's variable; degree one).
pub fn dissipation(p: Parameter<f64>, v: [f64; 3]) -> f64 {
    let t = contensou::friction::exact::traction(p, v[0], v[1], v[2]);
    -(t.fx * v[0] + t.fy * v[1] + t.tz * v[2])
}

/// The first octant of the direction sphere |v_x| + |v_y| + a|ω| = `scale` on an
/// (n + 1) × (n + 1) grid: (v_x, v_y, aω), all ≥ 0.
pub fn octant(n: usize, scale: f64) -> impl Iterator<Item = (f64, f64, f64)> {
    (0..=n).flat_map(move |i| {
        let w = i as f64 / n as f64;
        (0..=n).map(move |j| {
            let t = j as f64 / n as f64;
            (
                scale * (1.0 - w) * t,
                scale * (1.0 - w) * (1.0 - t),
                scale * w,
            )
        })
    })
}

/// Largest real eigenvalue of a 2×2 matrix, or |λ|²/Re λ (Euler's bound) for a complex pair.
pub fn eig_euler(k: [[f64; 2]; 2]) -> f64 {
    let tr = k[0][0] + k[1][1];
    let det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
    let disc = 0.25 * tr * tr - det;
    if disc >= 0.0 {
        0.5 * tr + disc.sqrt()
    } else {
        (0.25 * tr * tr - disc) / (0.5 * tr)
    }
}

/// One case of the `best` stability map: e², slip direction ψ, spin ratio aω/δ.
pub struct BestCase {
    pub e2: f64,
    pub psi: f64,
    pub spin: f64,
}

/// The probe slips of a case along the ray ψ (a = 1, δ given): rest, and `probes − 1` speeds
/// spread over the ramp (s < δ) when aω < δ, else over |v_P| ≤ 2aω; without spin rest only.
pub fn probe_speeds(case: &BestCase, delta: f64, probes: usize) -> Vec<f64> {
    if case.spin == 0.0 {
        // no spin: the ramped law is homogeneous of degree one, its Jacobian constant on the ray
        return vec![0.0];
    }
    let aw = case.spin * delta;
    let phi = case.psi.cos().abs() + case.psi.sin().abs();
    let top = if aw < delta {
        0.995 * (delta - aw) / phi
    } else {
        2.0 * aw
    };
    (0..probes)
        .map(|j| top * j as f64 / (probes - 1).max(1) as f64)
        .collect()
}

/// Measured stable step of a case for `scheme`: the smallest over the probe slips (`probes`,
/// plus `extra` probe velocities), each bisected in [h*/2, 16·h*] (`halvings`) with `steps`
/// steps per trial; a 1e-6·δ perturbation at ψ + 1 rad (generic: not an eigenvector of the
/// stiffness at rest), or along ψ without spin. Returns (measured step, h* = `stable_step`, the stiffness in fN/δ
/// predicted at the probe that set the measured step: the Jacobian's largest eigenvalue, or
/// 8/3 without spin, where the ramped law is F = −(8/3)·fN·v_P/δ, with a double eigenvalue that
/// differences resolve poorly).
#[allow(clippy::too_many_arguments)]
pub fn best_case_step(
    case: &BestCase,
    extra: &[[f64; 2]],
    f: f64,
    delta: f64,
    mass: f64,
    n: f64,
    scheme: Explicit,
    probes: usize,
    steps: usize,
    halvings: usize,
) -> (f64, f64, f64) {
    let k = Constants::from_parameter(Parameter::new(case.e2).unwrap());
    let block = BestBlock::new(&k, f, delta, mass, n, case.spin * delta);
    let h_star = block.law.stable_step(&k, mass, n, scheme);
    let (s, c) = case.psi.sin_cos();
    // without spin at rest the perturbation is the block's whole velocity: along ψ
    let turn = if case.spin == 0.0 { 0.0 } else { 1.0 };
    let (s1, c1) = (case.psi + turn).sin_cos();
    let dv0 = [1e-6 * delta * c1, 1e-6 * delta * s1];
    let mut v_eqs: Vec<[f64; 2]> = probe_speeds(case, delta, probes)
        .into_iter()
        .map(|r| [r * c, r * s])
        .collect();
    v_eqs.extend_from_slice(extra);
    let mut best = (f64::INFINITY, h_star, 0.0);
    for v_eq in v_eqs {
        let h = block.measured_step(
            v_eq,
            dv0,
            scheme,
            steps,
            (0.5 * h_star, 16.0 * h_star),
            halvings,
        );
        if h < best.0 {
            let lam = if case.spin == 0.0 {
                // F = −(8/3)·fN·v_P/δ: the ramp by the dissipation p = |v_P| is linear here
                8.0 / 3.0
            } else {
                block.stiffness(v_eq)
            };
            best = (h, h_star, lam);
        }
    }
    best
}

/// The stiffest slip of the derivation at one e² (`tools/data/best_stiffness.csv`, the row with
/// m₁ within 1e-9 of `m1`): (κ, v_P/(aω)) — the maximiser in units of the spin speed.
pub fn best_stiffness_row(m1: f64) -> Option<(f64, [f64; 2])> {
    include_str!("../../tools/data/best_stiffness.csv")
        .lines()
        .skip(1)
        .map(parse)
        .find(|v| (v[0] - m1).abs() <= 1e-9)
        .map(|v| (v[3], [v[4], v[5]]))
}

/// Every row of `tools/data/best_stiffness.csv`: (m₁, A, B, κ).
pub fn best_stiffness_rows() -> Vec<[f64; 4]> {
    include_str!("../../tools/data/best_stiffness.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let v = parse(l);
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

// ---- the spin about the normal: ω integrated, v_P held, ω held at a probe by a drive ---------

/// A body spinning under `Friction<f64, L>` (prepared for its patch) with v_P held fixed and ω
/// integrated: I·ω' = T_z(v_P, ω) − T_z(v_P, ω_eq), so that ω_eq is an equilibrium (ω_eq = 0
/// with v_P = 0: no drive, the spin coming to rest).
pub struct SpinBody<L: FrictionLaw> {
    pub law: Friction<f64, L>,
    pub prepared: L::Prepared<f64>,
    pub a: f64,
    pub inertia: f64,
    pub n: f64,
    pub v: [f64; 2],
}

impl<L: FrictionLaw> SpinBody<L> {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        k: &Constants<f64>,
        f: f64,
        delta: f64,
        a: f64,
        inertia: f64,
        n: f64,
        v: [f64; 2],
    ) -> Self {
        SpinBody {
            law: Friction::with_law(f, delta).unwrap(),
            prepared: L::prepare(k),
            a,
            inertia,
            n,
            v,
        }
    }

    /// The drilling torque at spin ω.
    pub fn torque(&self, omega: f64) -> f64 {
        self.law
            .tangential_prepared(
                &self.prepared,
                self.a,
                self.n,
                Slip::new(self.v[0], self.v[1], omega).unwrap(),
            )
            .tz
    }
}

impl<L: FrictionLaw> Settles for SpinBody<L> {
    type V = f64;

    /// Does `scheme` at step h bring a perturbation `dw0` of the equilibrium `w_eq` back? Unstable
    /// if |ω − ω_eq| ever exceeds 10·|dw0|, stable if it does not within `steps` steps and ends
    /// below |dw0|.
    fn settles(&self, w_eq: f64, dw0: f64, h: f64, scheme: Explicit, steps: usize) -> bool {
        let t_eq = self.torque(w_eq);
        let inv_i = 1.0 / self.inertia;
        let acc = |w: f64| (self.torque(w) - t_eq) * inv_i;
        let mut w = w_eq + dw0;
        for _ in 0..steps {
            w = step1(scheme, h, w, acc);
            let d = (w - w_eq).abs();
            if d > 10.0 * dw0.abs() || d.is_nan() {
                return false;
            }
        }
        (w - w_eq).abs() < dw0.abs()
    }
}

impl<L: FrictionLaw> SpinBody<L> {
    /// −∂T_z/∂ω at ω by a one-sided difference (towards larger |ω|), in units of fN·a²/δ.
    pub fn stiffness(&self, omega: f64) -> f64 {
        let h = 1e-7 * self.law.delta() / self.a;
        let h = if omega < 0.0 { -h } else { h };
        let k = -(self.torque(omega + h) - self.torque(omega)) / h;
        k * self.law.delta() / (self.law.coefficient() * self.n * self.a * self.a)
    }
}

/// The stiffest slip of the torque's derivation at one e² (`tools/data/spin_stiffness.csv`,
/// the row with m₁ within 1e-9 of `m1`): (κ_T, C, (X, Y)) — the IC of the maximiser in units of a.
pub fn spin_stiffness_row(m1: f64) -> Option<(f64, f64, [f64; 2])> {
    spin_stiffness_rows()
        .into_iter()
        .find(|v| (v[0] - m1).abs() <= 1e-9)
        .map(|v| (v[2], v[1], [v[3], v[4]]))
}

/// Every row of `tools/data/spin_stiffness.csv`: (m₁, C, κ_T, X, Y).
pub fn spin_stiffness_rows() -> Vec<[f64; 5]> {
    include_str!("../../tools/data/spin_stiffness.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let v = parse(l);
            [v[0], v[1], v[2], v[3], v[4]]
        })
        .collect()
}

/// One probe of the spin map: the held slip v_P and the equilibrium spin ω_eq (a = 1 m).
pub struct SpinProbe {
    pub name: &'static str,
    pub v: [f64; 2],
    pub omega: f64,
}

/// The spin probes of a law at one e² (δ given, a = 1): pure spin from rest, a generic slip,
/// and the derivation's stiffest slip — for `simplified` just below the switch from its
/// hyperbola to its plateau (a|ω| = 0.999·5Cv, v_P = (δ/2, 0)), for `best` the maximiser of
/// `tools/data/spin_stiffness.csv` scaled into the ramp (its dissipation p = 3δ/16, half the
/// ramp's width).
pub fn spin_probes(best: bool, e2: f64, m1: f64, delta: f64) -> Vec<SpinProbe> {
    let k = Constants::from_parameter(Parameter::new(e2).unwrap());
    let generic = SpinProbe {
        name: "generic",
        v: [0.2 * delta, 0.1 * delta],
        omega: 0.3 * delta,
    };
    let stiffest = if best {
        let (_, _, [x, y]) = spin_stiffness_row(m1).unwrap();
        // the ramp's dissipation p = aω·Ψ(X, Y) (exact law at aω = 1) set to half the ramp's
        // width, 3δ/16
        let p = dissipation(Parameter::new(e2).unwrap(), [y, -x, 1.0]);
        let w = 0.1875 * delta / p;
        // IC (X, Y) = (−v_Py, v_Px)/(aω)
        SpinProbe {
            name: "stiffest",
            v: [y * w, -x * w],
            omega: w,
        }
    } else {
        let v = 0.5 * delta;
        SpinProbe {
            name: "stiffest",
            v: [v, 0.0],
            omega: 0.999 * 5.0 * k.spin_torque() * v,
        }
    };
    vec![
        SpinProbe {
            name: "pure spin",
            v: [0.0, 0.0],
            omega: 0.0,
        },
        generic,
        stiffest,
    ]
}

/// Measured stable step of a spin probe (a = 1 m) for `scheme`, bisected in [h*/2, 16·h*]
/// (`halvings`, `steps` steps per trial, perturbation 1e-6·δ/a): (measured, stiffness at the
/// probe in fN·a²/δ).
#[allow(clippy::too_many_arguments)]
pub fn spin_probe_step<L: FrictionLaw>(
    probe: &SpinProbe,
    k: &Constants<f64>,
    (f, delta, inertia, n): (f64, f64, f64, f64),
    h_star: f64,
    scheme: Explicit,
    steps: usize,
    halvings: usize,
) -> (f64, f64) {
    let body = SpinBody::<L>::new(k, f, delta, 1.0, inertia, n, probe.v);
    let h = body.measured_step(
        probe.omega,
        1e-6 * delta,
        scheme,
        steps,
        (0.5 * h_star, 16.0 * h_star),
        halvings,
    );
    (h, body.stiffness(probe.omega))
}
