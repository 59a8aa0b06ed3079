/* The bits of an IEEE 754 single and back (a union: defined behaviour in C99). */
#ifndef FLOATBITS_H
#define FLOATBITS_H

#include <stdint.h>

typedef union {
    float f;
    uint32_t u;
} floatbits;

static inline uint32_t f32_bits(float x) {
    floatbits v;
    v.f = x;
    return v.u;
}

static inline float f32_from_bits(uint32_t b) {
    floatbits v;
    v.u = b;
    return v.f;
}

#endif
