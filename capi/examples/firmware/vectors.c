/* See vectors.h. Every draw is a separate statement: C leaves the evaluation order of function
 * arguments and initialisers unspecified, and the Rust twin draws left to right. */
#include "vectors.h"

#include "floatbits.h"

/* xorshift64 (Marsaglia 13/7/17): the next 32 random bits (the high half of the state). */
static uint32_t bits(bits_rng *r) {
    uint64_t x = r->state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    r->state = x;
    return (uint32_t)(x >> 32);
}

static uint32_t below(bits_rng *r, uint32_t n) { return bits(r) % n; }

/* 2^e·(1 + m·2^-23), e uniform in lo..hi, m 23 random bits. */
static float log_uniform(bits_rng *r, int32_t lo, int32_t hi) {
    int32_t e = lo + (int32_t)below(r, (uint32_t)(hi - lo));
    uint32_t m = bits(r) >> 9;
    return f32_from_bits(((uint32_t)(e + 127) << 23) | m);
}

/* ±log_uniform(lo, hi), the sign drawn first. */
static float signed_log_uniform(bits_rng *r, int32_t lo, int32_t hi) {
    int negative = (bits(r) & 1u) == 1u;
    float x = log_uniform(r, lo, hi);
    return negative ? -x : x;
}

contensou_spec_f32 bits_spec(bits_rng *r) {
    contensou_spec_f32 s;
    float g;
    s.q = log_uniform(r, -8, 24);
    switch (below(r, 8)) {
    case 0: g = 1.0f; break;
    case 1: g = 1.0001e-4f; break;
    default: g = log_uniform(r, -13, 0); break;
    }
    s.estar = log_uniform(r, 17, 40);
    s.cd = below(r, 2) == 0 ? 0.0f : log_uniform(r, -10, 3);
    s.f = below(r, 8) == 0 ? 0.0f : (float)(bits(r) >> 8) * (1.0f / 16777216.0f);
    s.delta = below(r, 4) == 0 ? 0.0f : log_uniform(r, -24, -2);
    s.p = s.q * g;
    return s;
}

contensou_step_f32 bits_step(bits_rng *r) {
    contensou_step_f32 s;
    switch (below(r, 16)) {
    case 0: s.h = 0.0f; break;
    case 1: s.h = -log_uniform(r, -40, -10); break;
    case 2: s.h = f32_from_bits(bits(r) & 0x007FFFFFu); break;
    default: s.h = log_uniform(r, -40, -8); break;
    }
    s.hdot = below(r, 4) == 0 ? 0.0f : signed_log_uniform(r, -12, 2);
    switch (below(r, 8)) {
    case 0: s.vx = 0.0f; s.vy = 0.0f; break;
    case 1: s.vx = 0.0f; s.vy = signed_log_uniform(r, -30, 5); break;
    case 2: s.vx = signed_log_uniform(r, -30, 5); s.vy = 0.0f; break;
    default:
        s.vx = signed_log_uniform(r, -30, 5);
        s.vy = signed_log_uniform(r, -30, 5);
        break;
    }
    switch (below(r, 8)) {
    case 0: s.omega = 0.0f; break;
    case 1: s.omega = signed_log_uniform(r, 10, 24); break;
    case 2: s.omega = signed_log_uniform(r, -40, -20); break;
    default: s.omega = signed_log_uniform(r, -8, 8); break;
    }
    return s;
}
