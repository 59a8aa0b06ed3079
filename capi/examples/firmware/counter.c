/* See counter.h; the registers of firmware/src/counter.rs. */
#include "counter.h"

#define RCC_APB1ENR (*(volatile uint32_t *)0x40023840u)
#define TIM2_CR1 (*(volatile uint32_t *)0x40000000u)
#define TIM2_EGR (*(volatile uint32_t *)0x40000014u)
#define TIM2_PSC (*(volatile uint32_t *)0x40000028u)
#define TIM2_ARR (*(volatile uint32_t *)0x4000002Cu)

void counter_init(void) {
    RCC_APB1ENR |= 1u; /* TIM2EN */
    TIM2_CR1 = 0;
    TIM2_PSC = 0;
    TIM2_ARR = 0xFFFFFFFFu;
    TIM2_EGR = 1; /* UG: load the prescaler now */
    TIM2_CR1 = 1; /* CEN */
}
