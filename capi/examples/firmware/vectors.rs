// The host = MCU test vectors, Rust twin of `vectors.c` in this directory:
// the same xorshift64 stream and the same draws in the same order, so both produce the same
// f32 bits. Shared verbatim (`include!`) by the host side `examples/host_mcu_bits.rs` and the
// Rust MCU image `firmware/src/bin/bits.rs`; the C image uses `vectors.c`.
// `tools/host-mcu-bits.sh` compares the streams line by line.
//
// Every value is built from random bits (sign, exponent, 23-bit significand), never through a
// libm call, so C (newlib) and Rust (libm) generate the same numbers. Ranges (all valid
// contract inputs, extremes included):
//   Q  2^-8 .. 2^24 1/m; g = P/Q: 1 (1/8), 1.0001e-4 (1/8), else 2^-13 .. 1; P = Q·g
//   E* 2^17 .. 2^40 Pa; c_d 0 (1/2) or 2^-10 .. 2^3 s/m; f 0 (1/8) or uniform [0, 1);
//   δ 0 (1/4) or 2^-24 .. 2^-2 m/s
//   h  0 (1/16), −(2^-40 .. 2^-10) (1/16), subnormal (1/16), else 2^-40 .. 2^-8 m
//   ḣ  0 (1/4) or ±2^-12 .. 2^2 m/s
//   slip: zero (1/8), only v_y (1/8), only v_x (1/8), else both; each ±2^-30 .. 2^5 m/s
//   ω  0 (1/8), huge ±2^10 .. 2^24 (1/8), tiny ±2^-40 .. 2^-20 (1/8), else ±2^-8 .. 2^8 rad/s

/// Contact specs per configuration; each is evaluated at `BITS_STEPS` steps.
const BITS_SPECS: usize = 1280;
/// Steps per spec: `BITS_SPECS · BITS_STEPS` = 10,240 states per (law, form).
const BITS_STEPS: usize = 8;
/// The xorshift64 seed (restarted for every configuration, so all see the same states).
const BITS_SEED: u64 = 0x9E37_79B9_7F4A_7C15;

/// xorshift64 (Marsaglia 13/7/17).
struct BitsRng(u64);

impl BitsRng {
    /// The next 32 random bits (the high half of the next state).
    fn bits(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        (x >> 32) as u32
    }

    /// Uniform in 0..n (n small: the modulo bias is irrelevant here).
    fn below(&mut self, n: u32) -> u32 {
        self.bits() % n
    }

    /// 2^e·(1 + m·2^-23), e uniform in lo..hi, m 23 random bits.
    fn log_uniform(&mut self, lo: i32, hi: i32) -> f32 {
        let e = lo + self.below((hi - lo) as u32) as i32;
        let m = self.bits() >> 9;
        f32::from_bits((((e + 127) as u32) << 23) | m)
    }

    /// ±`log_uniform(lo, hi)`, the sign drawn first.
    fn signed(&mut self, lo: i32, hi: i32) -> f32 {
        let negative = self.bits() & 1 == 1;
        let x = self.log_uniform(lo, hi);
        if negative { -x } else { x }
    }

    fn spec(&mut self) -> Spec<f32> {
        let q = self.log_uniform(-8, 24);
        let g = match self.below(8) {
            0 => 1.0,
            1 => 1.0001e-4,
            _ => self.log_uniform(-13, 0),
        };
        let estar = self.log_uniform(17, 40);
        let cd = if self.below(2) == 0 {
            0.0
        } else {
            self.log_uniform(-10, 3)
        };
        let f = if self.below(8) == 0 {
            0.0
        } else {
            (self.bits() >> 8) as f32 * (1.0 / 16_777_216.0)
        };
        let delta = if self.below(4) == 0 {
            0.0
        } else {
            self.log_uniform(-24, -2)
        };
        Spec {
            p: q * g,
            q,
            estar,
            cd,
            f,
            delta,
        }
    }

    fn step(&mut self) -> Step<f32> {
        let h = match self.below(16) {
            0 => 0.0,
            1 => -self.log_uniform(-40, -10),
            2 => f32::from_bits(self.bits() & 0x007F_FFFF),
            _ => self.log_uniform(-40, -8),
        };
        let hdot = if self.below(4) == 0 {
            0.0
        } else {
            self.signed(-12, 2)
        };
        let (vx, vy) = match self.below(8) {
            0 => (0.0, 0.0),
            1 => (0.0, self.signed(-30, 5)),
            2 => (self.signed(-30, 5), 0.0),
            _ => {
                let vx = self.signed(-30, 5);
                (vx, self.signed(-30, 5))
            }
        };
        let omega = match self.below(8) {
            0 => 0.0,
            1 => self.signed(10, 24),
            2 => self.signed(-40, -20),
            _ => self.signed(-8, 8),
        };
        Step {
            h,
            hdot,
            vx,
            vy,
            omega,
        }
    }
}

/// Evaluates every state for `law` and `form` and writes `CONFIG <law> <form>`, one line per
/// state (the seven outputs N Fx Fy Tz a b e2 as `%08x` f32 bits; `ERR <column>` if the
/// contract rejects the state), and `END <states>`.
fn bits_config<W: core::fmt::Write>(out: &mut W, law: Law, form: Form) -> core::fmt::Result {
    writeln!(out, "CONFIG {} {}", law.name(), form.name())?;
    let mut rng = BitsRng(BITS_SEED);
    for _ in 0..BITS_SPECS {
        let spec = rng.spec();
        let contact = DynContact::new(&spec, law, form);
        for _ in 0..BITS_STEPS {
            let step = rng.step();
            match contact
                .as_ref()
                .map_err(|e| *e)
                .and_then(|c| c.wrench(&step))
            {
                Ok(w) => {
                    let [n, fx, fy, tz, a, b, e2] = w.to_array().map(f32::to_bits);
                    writeln!(
                        out,
                        "{n:08x} {fx:08x} {fy:08x} {tz:08x} {a:08x} {b:08x} {e2:08x}"
                    )?;
                }
                Err(e) => writeln!(out, "ERR {}", e.column)?,
            }
        }
    }
    writeln!(out, "END {}", BITS_SPECS * BITS_STEPS)
}

/// Every sliding law and form, in `Law::SLIDING` × `Form::ALL` order (the laws of the C twin
/// `bits.c`; the rolling laws are not in this stream: FASTSIM's grids would take the QEMU run
/// past its time limit, and their host = MCU identity is not checked here).
fn bits_all<W: core::fmt::Write>(out: &mut W) -> core::fmt::Result {
    for law in Law::SLIDING {
        for form in Form::ALL {
            bits_config(out, law, form)?;
        }
    }
    Ok(())
}
