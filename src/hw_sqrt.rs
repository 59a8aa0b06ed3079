//! Single-precision square root that executes the FPU's `vsqrt.f32` on ARM `eabihf` targets.
//!
//! This is the crate's only `unsafe`-adjacent code. Why it exists: on `thumbv7em-none-eabihf`
//! `libm::sqrtf` is a software routine (≈50 executed instructions), `f32::sqrt` is not available
//! in `core` on stable Rust, and stable `asm!` rejects FPU register operands on that target
//! (`sreg` needs the unstable `vfp2` target feature). It does accept an FPU register as a
//! clobber, so the value travels through a core register:
//! `vmov s0, r` / `vsqrt.f32 s0, s0` / `vmov r, s0`, declaring only `s0` clobbered.
//!
//! The block is `pure, nomem, nostack`: it inlines (no `bl`/`bx`), clobbers one FPU register
//! instead of the s0–s15 a call clobbers (so callers keep their values in registers instead of
//! spilling d8–d15 with VPUSH/VPOP), and a root whose result is unused is removed. Correctly
//! rounded per IEEE 754, like `libm::sqrtf`; the same instruction as the out-of-line shim it
//! replaces, so results are bit-identical.
//!
//! On every other target this is `libm::sqrtf`.
//!
//! Cost on the Cortex-M4F (QEMU, `tools/qemu-bench.sh`, rows `core vsqrt` / `core libm`; cycles
//! from `bench-results/cycles.csv`): the `core vsqrt` row is 13 instructions, 34 cycles (the
//! shim: 11 and 34; `libm::sqrtf` 60 and 77), the root itself 3 instructions (2 `vmov`,
//! `vsqrt.f32`: 1 + 14 + 1 cycles). Inlined in real code it saves more: `hertz per_step` 79 → 66
//! cycles, the tippe-top RK4 step (with its other changes) 4,880 → 4,524.
//! `bench-results/vsqrt-disasm.txt` shows the disassembly; the script fails without `vsqrt.f32`.

#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
mod imp {
    /// `vsqrt.f32` through s0 (see the module docs).
    #[inline(always)]
    pub fn sqrtf(x: f32) -> f32 {
        let y: u32;
        // SAFETY: register-only arithmetic: reads the input register, writes the output
        // register and s0 (declared clobbered); no memory, no stack, no condition flags
        // (vsqrt.f32 sets only FPSCR's cumulative exception bits).
        unsafe {
            core::arch::asm!(
                "vmov s0, {x}",
                "vsqrt.f32 s0, s0",
                "vmov {y}, s0",
                x = in(reg) x.to_bits(),
                y = lateout(reg) y,
                out("s0") _,
                options(pure, nomem, nostack, preserves_flags),
            );
        }
        f32::from_bits(y)
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
