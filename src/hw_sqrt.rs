//! Single-precision square root that executes the FPU's `vsqrt.f32` on ARM `eabihf` targets.
//!
//! This is the crate's only `unsafe`-adjacent code. Why it exists: on `thumbv7em-none-eabihf`
//! `libm::sqrtf` is a software routine (≈50 executed instructions), `f32::sqrt` is not available
//! in `core` on stable Rust, and stable `asm!` rejects FPU register operands on that target. A
//! two-instruction naked function sidesteps all three: under the hard-float ABI the argument
//! and the result travel in `s0`, so the body is `vsqrt.f32 s0, s0; bx lr`.
//!
//! Soundness: the function reads only `s0` and writes only `s0` (caller-saved under AAPCS-VFP),
//! touches no memory and no stack, and returns with `bx lr`; it is a plain safe
//! `extern "C" fn(f32) -> f32`. Correctly rounded per IEEE 754, like `libm::sqrtf`.
//!
//! On every other target this is `libm::sqrtf`.
//!
//! Cost on the Cortex-M4F (QEMU, `tools/qemu-bench.sh`, rows `core vsqrt` / `core libm`):
//! 11 executed instructions per call vs 56 for `libm::sqrtf`, both including the benchmark's
//! 8-instruction call floor (row `core call`); the shim itself is `bl` + `vsqrt.f32` + `bx lr`.
//! Being a call, it clobbers the caller-saved FPU registers s0–s15 (the compiler keeps live
//! values in s16–s31).
//! `bench-results/vsqrt-disasm.txt` shows the disassembly; the script fails without `vsqrt.f32`.

#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
mod imp {
    /// `vsqrt.f32 s0, s0`.
    #[unsafe(naked)]
    pub extern "C" fn sqrtf(x: f32) -> f32 {
        core::arch::naked_asm!(".fpu fpv4-sp-d16", "vsqrt.f32 s0, s0", "bx lr")
    }
}

#[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
mod imp {
    #[inline(always)]
    pub fn sqrtf(x: f32) -> f32 {
        libm::sqrtf(x)
    }
}

pub(crate) use imp::sqrtf;
