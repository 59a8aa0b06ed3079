//! Host = MCU bit-identity check, Rust MCU side (issue 15 item 5): evaluates the shared f32 test
//! vectors (`capi/examples/firmware/vectors.rs`: 10,240 states, every law, both forms) through
//! `contensou::dynamic` on the Cortex-M4F and streams one line of output bits per state over
//! semihosting; `tools/host-mcu-bits.sh` compares it with `examples/host_mcu_bits.rs` on the
//! host. Not a benchmark: no counter, and its output is large (≈6 MB), so it is run apart from
//! `tools/qemu-bench.sh`.
#![no_std]
#![no_main]

use contensou::dynamic::{DynContact, Form, Law, Spec, Step};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hio};
use panic_semihosting as _;

include!("../../../capi/examples/firmware/vectors.rs");

/// `core::fmt::Write` into a 4 KiB buffer flushed to the host's stdout with one semihosting
/// `SYS_WRITE` per fill (one trap per line would dominate the run time).
struct Buffered {
    host: hio::HostStream,
    buf: heapless::Vec<u8, 4096>,
}

impl Buffered {
    fn flush(&mut self) -> core::fmt::Result {
        let r = self.host.write_all(&self.buf);
        self.buf.clear();
        r.map_err(|()| core::fmt::Error)
    }
}

impl core::fmt::Write for Buffered {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        for &byte in s.as_bytes() {
            if self.buf.is_full() {
                self.flush()?;
            }
            self.buf.push(byte).map_err(|_| core::fmt::Error)?;
        }
        Ok(())
    }
}

#[entry]
fn main() -> ! {
    let ok = match hio::hstdout() {
        Ok(host) => {
            let mut out = Buffered {
                host,
                buf: heapless::Vec::new(),
            };
            bits_all(&mut out).is_ok() && out.flush().is_ok()
        }
        Err(()) => false,
    };
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    #[allow(clippy::empty_loop)]
    loop {}
}
