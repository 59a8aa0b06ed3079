//! Helper of `tests/compare.sh` (the C twin against the Rust contract, bit for bit):
//!
//! - `bits gen` prints the test rows (header + valid states: every patch shape, damping,
//!   friction and slip regime, contact loss, valid extremes; runs of rows that change only
//!   P, Q so that the C twin takes its `set_curvatures` path in the varying form);
//! - `bits bad` prints rows each ending in one bad row, `KIND<TAB>row`, for the error paths;
//! - `bits rolling-gen` prints rows of `contact_eval rolling` (header + valid states: shapes
//!   a/b from 0.012 to 86, every regime from pure rolling to full slip, V < 0, V = 0, N ≤ 0,
//!   f = 0, ν at both ends); `bits rolling-bad` the bad rows of its error paths (as `bad`);
//! - `bits wrench-rolling-gen` prints rows of the wrench contract with the optional rolling
//!   columns `G,nu,vrx,vry` (contact blocks, rolling velocities from 0 to past the slip);
//! - `bits step-gen` prints rows of `contact_eval step` with every optional column
//!   (`G,nu,vrx,vry,un_free,ux_free,uy_free,uw_free`): the wrench's states, steps from 10 µs
//!   to 10 ms, W of random rigid bodies (J M⁻¹ Jᵀ: PSD, some singular), free velocities
//!   around the start; `bits step-bad` the bad rows of its error paths (as `bad`);
//! - `bits check f32|f64 A.csv B.csv` parses every field of both outputs in that precision
//!   and requires the same bits (and the same header — the wrench contract's, its Jacobian's
//!   or `contact_eval rolling`'s — and row count).
use std::process::ExitCode;
use std::str::FromStr;

use contensou::dynamic::{INPUTS, OUTPUTS};
use contensou::jacobian::OUTPUTS as JACOBIAN_OUTPUTS;
use contensou::step::contract::{FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS};
use contensou::Real;

/// splitmix64: a fixed, portable stream.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Log-uniform in [lo, hi].
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
    fn signed(&mut self, lo: f64, hi: f64) -> f64 {
        let x = self.log(lo, hi);
        if self.next() & 1 == 0 {
            x
        } else {
            -x
        }
    }
    fn pick(&mut self, xs: &[f64]) -> f64 {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

/// One of the values, drawn after evaluating all of them (fixed stream consumption).
macro_rules! pick {
    ($rng:ident, $($x:expr),+) => {{
        let xs = [$($x),+];
        $rng.pick(&xs)
    }};
}

fn row(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:e}"))
        .collect::<Vec<_>>()
        .join(",")
}

fn generate() {
    let mut rng = Rng(15);
    println!("{}", INPUTS.join(","));
    // Hand-picked states: shapes, contact loss, zero slip/spin, δ = 0, f = 0, extremes.
    let fixed: [[f64; 11]; 12] = [
        [
            50.0, 50.0, 1.15e11, 0.0, 0.1, 1e-4, 1e-6, 0.0, 0.01, 0.0, 50.0,
        ],
        [
            2e-4 * 60.0,
            60.0,
            1.15e11,
            0.2,
            0.3,
            0.0,
            1e-6,
            0.1,
            0.0,
            0.0,
            0.0,
        ],
        [10.0, 50.0, 2e11, 0.0, 0.0, 1e-4, -1e-6, 0.0, 1.0, 1.0, 1.0],
        [10.0, 50.0, 2e11, 0.1, 0.1, 1e-4, 0.0, -0.5, 1.0, 1.0, 1.0],
        [1.0, 1.0, 1e7, 0.5, 1.0, 1.0, 1e-3, -1.0, 0.0, 0.0, 1e3],
        [
            30.0, 40.0, 1e30, 0.0, 0.1, 1e-4, 1e-30, 0.0, 1e-30, -1e-30, 1e-30,
        ],
        [
            30.0, 40.0, 1e3, 0.0, 0.1, 1e-4, 1e-2, 0.0, 1e30, -1e30, 1e30,
        ],
        [
            1e-20, 1e-17, 1.15e11, 0.0, 0.1, 1e-4, 1e-6, 0.0, 0.01, 0.0, 50.0,
        ],
        [
            1e20, 1e20, 1.15e11, 0.0, 0.1, 1e-4, 1e-12, 0.0, 0.01, 0.0, 50.0,
        ],
        [
            50.0, 50.0, 1.15e11, 0.0, 0.1, 1e-4, 1e-6, 1e3, 0.01, 0.0, 50.0,
        ],
        [
            50.0, 50.0, 1.15e11, 1e3, 0.1, 1e-4, 1e-6, -1e3, 0.0, 0.0, -50.0,
        ],
        [
            50.0, 50.0, 1.15e11, 0.0, 0.1, 1e-4, 1e-6, 0.0, -0.0, -0.0, -0.0,
        ],
    ];
    for v in &fixed {
        println!("{}", row(v));
    }
    // Random blocks: one contact spec, then 8 steps that also move P, Q (per-step update).
    for _ in 0..1250 {
        let estar = rng.log(1e6, 1e12);
        let cd = pick!(rng, 0.0, 0.0, rng.log(1e-3, 10.0));
        let f = pick!(rng, 0.0, rng.log(1e-3, 1.0), rng.log(1e-3, 1.0));
        let delta = pick!(rng, 0.0, rng.log(1e-6, 1e-1), rng.log(1e-6, 1e-1));
        for _ in 0..8 {
            let q = rng.log(1e-1, 1e4);
            let g = pick!(
                rng,
                1.0,
                rng.log(2e-4, 1.0),
                rng.log(2e-4, 1.0),
                rng.log(0.5, 1.0)
            );
            let h = pick!(rng, -1e-6, 0.0, rng.log(1e-12, 1e-3), rng.log(1e-9, 1e-4));
            let hdot = pick!(rng, 0.0, rng.signed(1e-6, 1.0));
            let vx = pick!(rng, 0.0, rng.signed(1e-9, 10.0), rng.signed(1e-6, 1.0));
            let vy = pick!(rng, 0.0, rng.signed(1e-9, 10.0), rng.signed(1e-6, 1.0));
            let omega = pick!(rng, 0.0, rng.signed(1e-3, 1e4), rng.signed(1e-1, 1e3));
            println!(
                "{}",
                row(&[g * q, q, estar, cd, f, delta, h, hdot, vx, vy, omega])
            );
        }
    }
}

/// The columns of `contact_eval rolling`.
const ROLLING_INPUTS: [&str; 10] = ["a", "b", "G", "nu", "f", "N", "V", "xi", "eta", "phi"];
const ROLLING_OUTPUTS: [&str; 3] = ["Fx", "Fy", "Mz"];

fn rolling_generate() {
    let mut rng = Rng(20);
    println!("{}", ROLLING_INPUTS.join(","));
    let fixed: [[f64; 10]; 10] = [
        [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-3, 0.0, 0.0],
        [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 0.0, 1e-3, 2e-3, 5.0],
        [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, -30.0, 1e-3, 2e-3, 5.0],
        [4e-3, 6e-3, 8e10, 0.0, 0.3, 8e4, 30.0, 0.0, 0.0, 0.0],
        [4e-3, 6e-3, 8e10, 0.5, 0.0, 8e4, 30.0, 0.1, 0.0, 0.0],
        [8e-3, 4e-3, 8.2e10, 0.28, 0.3, -1.0, 1.0, 0.1, 0.1, 10.0],
        [8e-3, 4e-3, 8.2e10, 0.28, 0.3, 0.0, 1.0, 0.1, 0.1, 10.0],
        [8e-3, 4e-3, 8.2e10, 0.28, 0.3, 1e5, 1.0, 0.0, 0.0, 240.0],
        [1e-2, 1e-4, 1e9, 0.3, 1.0, 1e3, 1e-3, -1e-6, 1e-6, -1e-3],
        [1e-4, 1e-2, 1e9, 0.3, 1.0, 1e3, 1e3, 1e30, -1e30, 1e30],
    ];
    for v in &fixed {
        println!("{}", row(v));
    }
    // Random blocks: one contact (a/b, G, ν), then 6 states (the size c and the slip vary).
    for _ in 0..250 {
        let ratio = rng.log(0.012, 60.0);
        let g = rng.log(1e6, 1e11);
        let nu = pick!(rng, 0.0, 0.5, rng.unit() * 0.5, rng.unit() * 0.5);
        for k in 0..6 {
            let c = rng.log(1e-4, 1e-2);
            let (a, b) = if k == 5 {
                (c * 1.2 * ratio.sqrt(), c / (1.2 * ratio.sqrt())) // a/b not the contact's
            } else {
                (c * ratio.sqrt(), c / ratio.sqrt())
            };
            let f = pick!(rng, 0.0, rng.log(1e-2, 1.0), rng.log(1e-2, 1.0));
            let n = pick!(rng, -1.0, 0.0, rng.log(1e-2, 1e6), rng.log(1e-2, 1e6));
            let v = pick!(
                rng,
                0.0,
                rng.signed(1e-3, 1e2),
                rng.signed(1e-3, 1e2),
                rng.log(1e-3, 1e2)
            );
            // creepages from 1e-3 of saturation (≈ fN/(Gc²)) to far past it
            let sat = (f.max(1e-2) * n.abs().max(1.0) / (g * c * c)).max(1e-9);
            let xi = pick!(rng, 0.0, rng.signed(1e-3 * sat, 1e2 * sat));
            let eta = pick!(rng, 0.0, rng.signed(1e-3 * sat, 1e2 * sat));
            let phi = pick!(rng, 0.0, rng.signed(1e-3 * sat / c, 1e2 * sat / c));
            println!("{}", row(&[a, b, g, nu, f, n, v, xi, eta, phi]));
        }
    }
}

/// A contact block of the rolling rows: `[E*, c_d, f, δ, G, ν]`, δ one of 0, a log-uniform
/// draw and `more_deltas`.
fn rolling_block(rng: &mut Rng, more_deltas: &[f64]) -> [f64; 6] {
    let estar = rng.log(1e8, 1e12);
    let cd = pick!(rng, 0.0, rng.log(1e-3, 10.0));
    let f = pick!(rng, 0.0, rng.log(1e-2, 1.0), rng.log(1e-2, 1.0));
    let deltas = [&[0.0, rng.log(1e-6, 1e-2)], more_deltas].concat();
    let delta = rng.pick(&deltas);
    let g = estar * pick!(rng, 0.7, rng.log(0.1, 1.0));
    let nu = pick!(rng, 0.0, 0.5, rng.unit() * 0.5);
    [estar, cd, f, delta, g, nu]
}

/// A state of a rolling block: `[P, Q, h, ḣ, v_x, v_y, ω, v_rx, v_ry]`; h and ω drawn
/// log-uniformly below `h_top` and `omega_top` (two ranges each), the rolling velocity from 0
/// to well past the slip.
fn rolling_state(rng: &mut Rng, h_top: [f64; 2], omega_top: [f64; 2]) -> [f64; 9] {
    let q = rng.log(1e-1, 1e4);
    let ratio = pick!(rng, 1.0, rng.log(2e-4, 1.0), rng.log(0.05, 1.0));
    let h = pick!(
        rng,
        -1e-6,
        rng.log(1e-12, h_top[0]),
        rng.log(1e-9, h_top[1])
    );
    let hdot = pick!(rng, 0.0, rng.signed(1e-6, 1.0));
    let vx = pick!(rng, 0.0, rng.signed(1e-7, 1.0), rng.signed(1e-5, 1e-1));
    let vy = pick!(rng, 0.0, rng.signed(1e-7, 1.0), rng.signed(1e-5, 1e-1));
    let omega = pick!(
        rng,
        0.0,
        rng.signed(1e-3, omega_top[0]),
        rng.signed(1e-1, omega_top[1])
    );
    let vrx = pick!(rng, 0.0, rng.signed(1e-4, 30.0), rng.signed(1e-2, 10.0));
    let vry = pick!(rng, 0.0, 0.0, rng.signed(1e-4, 30.0));
    [ratio * q, q, h, hdot, vx, vy, omega, vrx, vry]
}

/// Rows of the wrench contract with the optional rolling columns `G,nu,vrx,vry`: contact
/// blocks (a spec, G, ν) then steps with a rolling velocity from 0 to well past the slip.
fn wrench_rolling_generate() {
    let mut rng = Rng(21);
    println!("{},G,nu,vrx,vry", INPUTS.join(","));
    for _ in 0..200 {
        let [estar, cd, f, delta, g, nu] = rolling_block(&mut rng, &[]);
        for _ in 0..8 {
            let [p, q, h, hdot, vx, vy, omega, vrx, vry] =
                rolling_state(&mut rng, [1e-3, 1e-4], [1e4, 1e3]);
            let v = [
                p, q, estar, cd, f, delta, h, hdot, vx, vy, omega, g, nu, vrx, vry,
            ];
            println!("{}", row(&v));
        }
    }
}

/// W = J M⁻¹ Jᵀ of one random rigid body (mass m, principal inertia I, arm r from its centre
/// of mass to the contact point, contact frame = body axes): u = (v + ω × r)·(n, x, y), ω·n.
fn body_w(rng: &mut Rng) -> [f64; 10] {
    let m = rng.log(1e-3, 10.0);
    let i = [
        m * rng.log(1e-6, 1e-2),
        m * rng.log(1e-6, 1e-2),
        m * rng.log(1e-6, 1e-2),
    ];
    let r = [
        rng.signed(1e-4, 0.1),
        rng.signed(1e-4, 0.1),
        -rng.log(1e-4, 0.1),
    ];
    // Rows of J over (v, ω): n = z, x, y directions, and the spin about z.
    let dir = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let mut j = [[0.0f64; 6]; 4];
    for (k, d) in dir.iter().enumerate() {
        // (v + ω × r)·d = v·d + ω·(r × d)
        let c = [
            r[1] * d[2] - r[2] * d[1],
            r[2] * d[0] - r[0] * d[2],
            r[0] * d[1] - r[1] * d[0],
        ];
        j[k] = [d[0], d[1], d[2], c[0], c[1], c[2]];
    }
    j[3] = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    let inv = [
        1.0 / m,
        1.0 / m,
        1.0 / m,
        1.0 / i[0],
        1.0 / i[1],
        1.0 / i[2],
    ];
    let mut w = [0.0; 10];
    let mut n = 0;
    for a in 0..4 {
        for b in a..4 {
            w[n] = (0..6).map(|c| j[a][c] * inv[c] * j[b][c]).sum();
            n += 1;
        }
    }
    w
}

/// Rows of `contact_eval step` with every optional column.
fn step_generate() {
    let mut rng = Rng(27);
    println!(
        "{},{},G,nu,vrx,vry,{}",
        INPUTS.join(","),
        STEP_INPUTS.join(","),
        FREE_INPUTS.join(",")
    );
    for _ in 0..60 {
        let [estar, cd, f, delta, g, nu] = rolling_block(&mut rng, &[1e-4]);
        for _ in 0..5 {
            let [p, q, h, hdot, vx, vy, omega, vrx, vry] =
                rolling_state(&mut rng, [1e-4, 1e-5], [1e3, 1e2]);
            let dt = pick!(rng, 1e-3, 2e-3, rng.log(1e-5, 1e-2));
            let mut w = body_w(&mut rng);
            if rng.next() & 3 == 0 {
                // A body that cannot spin about the normal: W singular (its spin row zero).
                for k in [3, 6, 8, 9] {
                    w[k] = 0.0;
                }
            }
            // The free velocity: the start's plus what gravity or a push adds over the step.
            let un = -hdot + pick!(rng, 0.0, -9.81 * dt, rng.signed(1e-4, 1.0));
            let ux = vx + pick!(rng, 0.0, rng.signed(1e-5, 1.0));
            let uy = vy + pick!(rng, 0.0, rng.signed(1e-5, 1.0));
            let uw = omega + pick!(rng, 0.0, rng.signed(1e-3, 10.0));
            let mut v = vec![p, q, estar, cd, f, delta, h, hdot, vx, vy, omega, dt];
            v.extend_from_slice(&w);
            v.extend_from_slice(&[g, nu, vrx, vry, un, ux, uy, uw]);
            println!("{}", row(&v));
        }
    }
}

/// For each `(kind, line)` of `cases`: a file of rows `kind<TAB>row` — valid rows (`good`;
/// an empty line too), then the bad `line`, then a valid one — for an error path.
fn print_bad<L: std::fmt::Display>(good: &str, cases: impl IntoIterator<Item = (&'static str, L)>) {
    for (kind, line) in cases {
        println!("{kind}\t{good}\n{kind}\t\n{kind}\t{good}\n{kind}\t{line}\n{kind}\t{good}");
    }
}

/// Valid step rows, then one bad row (`kind<TAB>line`), for the step's error paths.
fn step_bad() {
    let c = "50,50,1.15e11,0,0.1,1e-4,7.6e-8,0,0.5,0,0";
    let w = "30.609,0,0,0,107.13,0,0,107.13,0,7.6522e5";
    let good = format!("{c},1e-3,{w}");
    let cases = [
        ("dt-zero", format!("{c},0,{w}")),
        ("dt-neg", format!("{c},-1e-3,{w}")),
        ("dt-inf", format!("{c},inf,{w}")),
        (
            "w-inf",
            format!("{c},1e-3,30.609,0,0,0,inf,0,0,107.13,0,7.6522e5"),
        ),
        (
            "w-not-psd",
            format!("{c},1e-3,30.609,0,0,0,-107.13,0,0,107.13,0,7.6522e5"),
        ),
        ("w-coupled", format!("{c},1e-3,1,5,0,0,1,0,0,1,0,1")),
        (
            "h-inf",
            format!("50,50,1.15e11,0,0.1,1e-4,inf,0,0.5,0,0,1e-3,{w}"),
        ),
        (
            "p-gt-q",
            format!("60,50,1.15e11,0,0.1,1e-4,7.6e-8,0,0.5,0,0,1e-3,{w}"),
        ),
    ];
    print_bad(&good, cases);
}

/// Valid rows, then one bad row (`kind<TAB>line`), for the rolling error paths.
fn rolling_bad() {
    let good = "6e-3,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0,1";
    let cases = [
        ("g-neg", "6e-3,4e-3,-8e10,0.28,0.3,8e4,30,1e-3,0,1"),
        ("g-inf", "6e-3,4e-3,inf,0.28,0.3,8e4,30,1e-3,0,1"),
        ("nu-big", "6e-3,4e-3,8e10,0.6,0.3,8e4,30,1e-3,0,1"),
        ("nu-neg", "6e-3,4e-3,8e10,-0.1,0.3,8e4,30,1e-3,0,1"),
        ("ratio", "6e-3,4e-5,8e10,0.28,0.3,8e4,30,1e-3,0,1"),
        ("f-neg", "6e-3,4e-3,8e10,0.28,-0.3,8e4,30,1e-3,0,1"),
        ("n-inf", "6e-3,4e-3,8e10,0.28,0.3,inf,30,1e-3,0,1"),
        ("xi-inf", "6e-3,4e-3,8e10,0.28,0.3,8e4,30,inf,0,1"),
        ("phi-inf", "6e-3,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0,-inf"),
        ("text", "6e-3,4e-3,8e10,0.28,0.3,8e4,30,abc,0,1"),
        ("fields", "6e-3,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0"),
    ];
    print_bad(good, cases);
}

/// Files with valid rows, then one bad row (`kind<TAB>line`), for the error paths.
fn bad() {
    let good = "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50";
    let cases = [
        ("p-gt-q", "60,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("p-zero", "0,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("ratio", "1e-5,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("q-inf", "50,inf,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("estar-neg", "50,50,-1,0,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("cd-neg", "50,50,1.15e11,-1,0.1,1e-4,1e-6,0,0.01,0,50"),
        ("f-neg", "50,50,1.15e11,0,-0.1,1e-4,1e-6,0,0.01,0,50"),
        ("delta-neg", "50,50,1.15e11,0,0.1,-1e-4,1e-6,0,0.01,0,50"),
        ("h-inf", "50,50,1.15e11,0,0.1,1e-4,inf,0,0.01,0,50"),
        ("omega-inf", "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,-inf"),
        ("vx-overflow", "50,50,1.15e11,0,0.1,1e-4,1e-6,0,1e400,0,50"),
        ("nan", "50,50,1.15e11,0,0.1,1e-4,NaN,0,0.01,0,50"),
        ("text", "50,50,1.15e11,0,0.1,1e-4,abc,0,0.01,0,50"),
        ("empty", "50,50,1.15e11,0,0.1,,1e-6,0,0.01,0,50"),
        ("fields", "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0"),
    ];
    print_bad(good, cases);
}

fn parse_all<T: FromStr + Real>(line: &str) -> Result<Vec<u64>, String> {
    line.split(',')
        .map(|f| {
            f.trim()
                .parse::<T>()
                .map(|x| x.to_f64().to_bits())
                .map_err(|_| format!("not a number: {f:?}"))
        })
        .collect()
}

fn check<T: FromStr + Real>(a: &str, b: &str) -> ExitCode {
    let (a, b) = match (std::fs::read_to_string(a), std::fs::read_to_string(b)) {
        (Ok(a), Ok(b)) => (a, b),
        _ => {
            eprintln!("bits check: cannot read the files");
            return ExitCode::from(2);
        }
    };
    let (la, lb): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    let header = format!("{},{}", INPUTS.join(","), OUTPUTS.join(","));
    let rolling = format!("{},{}", ROLLING_INPUTS.join(","), ROLLING_OUTPUTS.join(","));
    let first = la.first().copied().unwrap_or_default();
    // the wrench contract (and its Jacobian's, `contact_eval jacobian`) may add optional
    // rolling columns between its inputs and outputs
    let optional = first.starts_with(INPUTS.join(",").as_str())
        && (first.ends_with(OUTPUTS.join(",").as_str())
            || first.ends_with(JACOBIAN_OUTPUTS.join(",").as_str()));
    // the step contract: the wrench's inputs, the step's, optional ones, then N,Fx,Fy,Tz
    let step = first.starts_with(&format!("{},{}", INPUTS.join(","), STEP_INPUTS.join(",")))
        && first.ends_with(STEP_OUTPUTS.join(",").as_str());
    let optional = optional || step;
    if !(first == header || first == rolling || optional) || lb.first() != Some(&first) {
        eprintln!("bits check: header differs from `{header}` or `{rolling}`");
        return ExitCode::from(1);
    }
    let fields = first.split(',').count();
    if la.len() != lb.len() {
        eprintln!("bits check: {} rows against {}", la.len() - 1, lb.len() - 1);
        return ExitCode::from(1);
    }
    let mut bad = 0;
    for (k, (x, y)) in la.iter().zip(&lb).enumerate().skip(1) {
        match (parse_all::<T>(x), parse_all::<T>(y)) {
            (Ok(u), Ok(v)) if u == v && u.len() == fields => {}
            _ => {
                bad += 1;
                if bad <= 5 {
                    eprintln!("bits check: row {k} differs:\n  {x}\n  {y}");
                }
            }
        }
    }
    if bad > 0 {
        eprintln!("bits check: {bad} of {} rows differ", la.len() - 1);
        return ExitCode::from(1);
    }
    println!("{}", la.len() - 1);
    ExitCode::SUCCESS
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("gen") => generate(),
        Some("bad") => bad(),
        Some("rolling-gen") => rolling_generate(),
        Some("rolling-bad") => rolling_bad(),
        Some("wrench-rolling-gen") => wrench_rolling_generate(),
        Some("step-gen") => step_generate(),
        Some("step-bad") => step_bad(),
        Some("check") if args.len() == 4 => {
            return match args[1].as_str() {
                "f32" => check::<f32>(&args[2], &args[3]),
                _ => check::<f64>(&args[2], &args[3]),
            };
        }
        _ => {
            eprintln!("usage: bits gen | bad | rolling-gen | rolling-bad | wrench-rolling-gen | step-gen | step-bad | check f32|f64 A B");
            return ExitCode::from(2);
        }
    }
    ExitCode::SUCCESS
}
