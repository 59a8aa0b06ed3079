/* Executed-instruction counter: TIM2 of QEMU's netduinoplus2, as in the Rust rig
 * (firmware/src/counter.rs). Under -icount shift=0 virtual time advances 1 ns per executed
 * instruction and TIM2 runs at 1 GHz of virtual time: with prescaler 0 it counts executed
 * instructions one for one (QEMU only; on silicon it counts timer-clock ticks). */
#ifndef COUNTER_H
#define COUNTER_H

#include <stdint.h>

#define TIM2_CNT (*(volatile uint32_t *)0x40000024u)

/* Enables TIM2's clock, prescaler 0, auto-reload 0xFFFF_FFFF, counting up. */
void counter_init(void);

/* The current count. */
static inline uint32_t counter_now(void) { return TIM2_CNT; }

#endif
