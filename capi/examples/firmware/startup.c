/* Minimal Cortex-M4F startup for the C firmware images: the vector table, Reset_Handler
 * (copy .data, zero .bss, enable the FPU, run main, exit QEMU with main's status), and one
 * handler for every fault or interrupt (exit with status 1: a fault must not hang CI).
 * Symbols come from link.ld. */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[], _estack[];
extern int main(void);

void Reset_Handler(void);
void Default_Handler(void);

/* CPACR: full access to the coprocessors CP10 and CP11 (the FPU). */
#define CPACR (*(volatile uint32_t *)0xE000ED88u)

/* Initial stack pointer, then the 15 system exceptions (reset first); no device interrupt is
 * enabled, so the table stops there. (A union: ISO C has no object-to-function pointer cast.) */
typedef union {
    uint32_t *stack;
    void (*handler)(void);
} vector;

#define D {.handler = Default_Handler}
__attribute__((section(".vectors"), used)) static const vector vectors[16] = {
    {.stack = _estack}, {.handler = Reset_Handler}, D, D, D, D, D, D, D, D, D, D, D, D, D, D,
};
#undef D

/* Word loops through volatile pointers: the compiler must not turn them into memcpy/memset
 * calls (there is no C library here) nor use FPU registers before the FPU is on. */
void Reset_Handler(void) {
    volatile uint32_t *src = _sidata;
    for (volatile uint32_t *dst = _sdata; dst < _edata;) *dst++ = *src++;
    for (volatile uint32_t *dst = _sbss; dst < _ebss;) *dst++ = 0;
    CPACR |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    sh_exit(main());
}

void Default_Handler(void) { sh_exit(1); }
