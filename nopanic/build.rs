//! Puts a `memory.x` on the linker search path (cortex-m-rt's `link.x` includes it): the
//! repository's top-level layout (the firmware's STM32F405) with a larger flash region. This
//! image is only linked, never run (the proof is that it links), and its probes — every
//! public entry point in f32 and f64, the wrench's Jacobian over every law included — pass
//! the 1 MiB of the real part.

use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let src = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"))
        .join("../memory.x");
    let layout = fs::read_to_string(&src).expect("read ../memory.x");
    let layout = layout.replace("LENGTH = 1024K", "LENGTH = 4096K");
    assert!(
        layout.contains("LENGTH = 4096K"),
        "../memory.x: flash region not found"
    );
    fs::write(out.join("memory.x"), layout).expect("write memory.x into OUT_DIR");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed={}", src.display());
    println!("cargo:rerun-if-changed=build.rs");
}
