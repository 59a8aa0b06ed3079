/* The host = MCU test vectors, C twin of vectors.rs in this directory (see
 * there for the ranges): the same xorshift64 stream and the same draws in the same order, so
 * both generate the same f32 bits. */
#ifndef VECTORS_H
#define VECTORS_H

#include <stdint.h>

#include "contensou.h"

/* Contact specs per configuration, steps per spec: 10,240 states per (law, form). */
#define BITS_SPECS 1280
#define BITS_STEPS 8
/* Restarted for every configuration, so all see the same states. */
#define BITS_SEED 0x9E3779B97F4A7C15ull

typedef struct {
    uint64_t state;
} bits_rng;

contensou_spec_f32 bits_spec(bits_rng *rng);
contensou_step_f32 bits_step(bits_rng *rng);

#endif
