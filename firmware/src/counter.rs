//! Executed-instruction counter: the STM32 TIM2 of QEMU's `netduinoplus2` board.
//!
//! Under `-icount shift=0` QEMU advances virtual time by 1 ns per executed instruction, and TIM2
//! (a 32-bit timer) runs from a 1 GHz virtual clock, so with prescaler 0 its counter increases by
//! exactly one per executed instruction and repeated runs give identical counts. (The DWT cycle
//! counter is not implemented by QEMU 7.2: it reads 0.) On silicon TIM2 would count timer-clock
//! ticks instead; this module is for the QEMU rig only.

use core::ptr::{read_volatile, write_volatile};

const RCC_APB1ENR: *mut u32 = 0x4002_3840 as *mut u32;
const RCC_APB1ENR_TIM2EN: u32 = 1 << 0;

const TIM2: usize = 0x4000_0000;
const TIM2_CR1: *mut u32 = TIM2 as *mut u32;
const TIM2_EGR: *mut u32 = (TIM2 + 0x14) as *mut u32;
const TIM2_CNT: *const u32 = (TIM2 + 0x24) as *const u32;
const TIM2_PSC: *mut u32 = (TIM2 + 0x28) as *mut u32;
const TIM2_ARR: *mut u32 = (TIM2 + 0x2C) as *mut u32;

/// Enable the TIM2 clock, prescaler 0, auto-reload 0xFFFF_FFFF, start counting up.
pub fn init() {
    // SAFETY: fixed, aligned MMIO registers of the STM32F405 (RCC, TIM2); single-threaded
    // firmware before any measurement, nothing else owns these peripherals.
    unsafe {
        write_volatile(RCC_APB1ENR, read_volatile(RCC_APB1ENR) | RCC_APB1ENR_TIM2EN);
        write_volatile(TIM2_CR1, 0);
        write_volatile(TIM2_PSC, 0);
        write_volatile(TIM2_ARR, 0xFFFF_FFFF);
        write_volatile(TIM2_EGR, 1); // UG: load the prescaler now
        write_volatile(TIM2_CR1, 1); // CEN
    }
}

/// Current count (one tick per executed instruction under `-icount shift=0`).
#[inline(always)]
pub fn now() -> u32 {
    // SAFETY: aligned read of the TIM2 counter register, which has no read side effects.
    unsafe { read_volatile(TIM2_CNT) }
}
