//! Host side of the host = MCU bit-identity check.
//!
//! - `host_mcu_bits` evaluates the shared f32 test vectors (`capi/examples/firmware/vectors.rs`:
//!   10,240 states, every law and form) through `contensou::dynamic` and prints one line of
//!   output bits per state (the format of the MCU images).
//! - `host_mcu_bits FILE…` compares each FILE (an MCU image's semihosting output) with that
//!   stream: per law and form, the states compared, the first differing state and the largest
//!   difference in ulps over the seven outputs. Exit status 1 unless every file is bit-identical.
//!
//! `tools/host-mcu-bits.sh` runs the images under QEMU and calls this.

use contensou::dynamic::{DynContact, Form, Law, Spec, Step};
use std::io::Write;

include!("../capi/examples/firmware/vectors.rs");

/// `core::fmt::Write` over any `std::io::Write`.
struct Out<W: Write>(W);

impl<W: Write> core::fmt::Write for Out<W> {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        self.0.write_all(s.as_bytes()).map_err(|_| core::fmt::Error)
    }
}

/// f32 bits → a monotonic integer (adjacent floats differ by 1; +0 and −0 both 0).
fn ordered(bits: u32) -> i64 {
    let magnitude = i64::from(bits & 0x7FFF_FFFF);
    if bits >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    }
}

/// Distance in ulps between two lines of output bits (`u64::MAX` if one is not seven words).
fn ulps(host: &str, mcu: &str) -> u64 {
    let words = |s: &str| -> Option<Vec<u32>> {
        s.split_whitespace()
            .map(|w| u32::from_str_radix(w, 16).ok())
            .collect()
    };
    match (words(host), words(mcu)) {
        (Some(h), Some(m)) if h.len() == 7 && m.len() == 7 => h
            .iter()
            .zip(&m)
            .map(|(&a, &b)| ordered(a).abs_diff(ordered(b)))
            .max()
            .unwrap_or(0),
        _ => u64::MAX,
    }
}

/// Compares `mcu` with `host` config by config; prints a summary; true if bit-identical.
fn compare(name: &str, host: &str, mcu: &str) -> bool {
    let (host, mcu): (Vec<&str>, Vec<&str>) = (host.lines().collect(), mcu.lines().collect());
    let mut identical = host.len() == mcu.len();
    if !identical {
        println!("{name}: {} lines, host {} lines", mcu.len(), host.len());
    }
    let mut config = "";
    let (mut states, mut first, mut worst) = (0usize, None, 0u64);
    for (i, h) in host.iter().enumerate() {
        let m = mcu.get(i).copied().unwrap_or("");
        if let Some(c) = h.strip_prefix("CONFIG ") {
            (config, states, first, worst) = (c, 0, None, 0);
        } else if h.starts_with("END") {
            let verdict = match first {
                None if h == &m => "bit-identical".to_string(),
                None => format!("differs at the END line: {m:?}"),
                Some(k) => format!("DIFFERS: first at state {k}, max {worst} ulp"),
            };
            println!("{name}: {config:<18} {states:>6} states  {verdict}");
            identical &= first.is_none() && h == &m;
        } else {
            if h != &m {
                first.get_or_insert(states);
                worst = worst.max(ulps(h, m));
            }
            states += 1;
        }
    }
    identical
}

fn main() {
    let mut host = Out(Vec::new());
    if bits_all(&mut host).is_err() {
        eprintln!("host_mcu_bits: formatting failed");
        std::process::exit(1);
    }
    let host = String::from_utf8(host.0).unwrap_or_default();
    let files: Vec<String> = std::env::args().skip(1).collect();
    if files.is_empty() {
        if std::io::stdout().lock().write_all(host.as_bytes()).is_err() {
            eprintln!("host_mcu_bits: cannot write to stdout");
            std::process::exit(1);
        }
        return;
    }
    let mut all = true;
    for file in &files {
        match std::fs::read_to_string(file) {
            Ok(mcu) => all &= compare(file, &host, &mcu.replace('\r', "")),
            Err(e) => {
                eprintln!("host_mcu_bits: {file}: {e}");
                all = false;
            }
        }
    }
    std::process::exit(if all { 0 } else { 1 });
}
