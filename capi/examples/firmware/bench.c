/* C firmware image `bench`: instructions per contensou_contact_wrench_f32 call on the
 * Cortex-M4F under QEMU (-icount shift=0, TIM2), measured as the Rust rig measures
 * (firmware/src/harness.rs): one call per input between two counter reads, the call made
 * through a function pointer read once from a volatile (the Rust rig's black_box), the
 * empty-region overhead subtracted, the per-call average over the input set rounded to the
 * nearest instruction. Prints `BENCH wrench c-fixed-best f32 insns=N` and
 * `BENCH wrench c-varying-best f32 insns=N` (tools/qemu-bench.sh puts them in qemu.csv), and
 * DETAIL lines (min/max/total).
 *
 * The work is that of the Rust rows wrench,fixed-best,f32 and wrench,table_each_step-best,f32
 * (firmware/src/bench_wrench.rs, benches/wrench_set.rs): the 209 bearing's inner-race contact
 * (ball 12.7 mm, groove radius 6.6 mm, pitch 65 mm), E* = 1.142857e11 Pa, f = 0.07, δ = 0,
 * law `best`, h = 5 µm, ḣ = 0, and the friction stage's 64 mixed slips (u log-uniform in
 * [0.01, 100], ψ uniform, same xorshift64 seed; v = u·a·ω, ω = 100 rad/s), computed here in
 * double with pow/sin/cos, which resolve to the Rust libm the Rust rig uses (build.sh); the
 * INPUTS line gives a FNV-1a hash of the slips' f32 bits, and the image fails unless it is
 * the Rust set's (RUST_SLIPS_FNV1A64, printed by firmware/src/bin/dispatch.rs). The C path has the C API's work
 * on top: pointer/alignment/initialisation checks, the finiteness checks of the step, the
 * law and form dispatch of contensou::dynamic, Hunt–Crossley with c_d = 0 in place of
 * Undamped, and the copy of the seven outputs. */
#include <math.h>

#include "contensou.h"
#include "counter.h"
#include "floatbits.h"
#include "semihost.h"

#define SET 64
/* FNV-1a 64 of the Rust rig's 64 slips' (vx, vy) f32 bits, little-endian bytes. */
#define RUST_SLIPS_FNV1A64 0x5661b63f35609537ull

typedef contensou_status (*wrench_fn)(const contensou_contact_f32 *, const contensou_step_f32 *,
                                      contensou_wrench_f32 *, contensou_column *);

static uint32_t overhead;
static int failures;

/* Two back-to-back counter reads. */
__attribute__((noinline)) static uint32_t empty_region(void) {
    uint32_t t0 = counter_now();
    uint32_t t1 = counter_now();
    return t1 - t0;
}

/* The friction stage's mixed set (benches/friction_set.rs): (u, ψ) per state. */
static void mixed_set(double u[SET], double psi[SET]) {
    uint64_t seed = 0x2545F4914F6CDD1Dull;
    for (int i = 0; i < SET; i++) {
        double unit[2];
        for (int k = 0; k < 2; k++) {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            unit[k] = (double)(seed >> 11) / (double)(1ull << 53);
        }
        u[i] = pow(10.0, -2.0 + 4.0 * unit[0]);
        psi[i] = 2.0 * 3.14159265358979323846 * unit[1];
    }
}

static void line(const char *kind, const char *method) {
    sh_puts(kind);
    sh_puts(" wrench ");
    sh_puts(method);
    sh_puts(" f32 ");
}

static void bench(const char *method, const contensou_contact_f32 *contact,
                  const contensou_step_f32 steps[SET]) {
    static wrench_fn volatile pointer = contensou_contact_wrench_f32;
    wrench_fn f = pointer;
    uint32_t total = 0, min = UINT32_MAX, max = 0;
    for (int i = 0; i < SET; i++) {
        contensou_wrench_f32 w;
        uint32_t t0 = counter_now();
        contensou_status st = f(contact, &steps[i], &w, 0);
        uint32_t t1 = counter_now();
        uint32_t n = t1 - t0 - overhead;
        failures += st != CONTENSOU_STATUS_OK || !(w.n > 0.0f);
        total += n;
        min = n < min ? n : min;
        max = n > max ? n : max;
    }
    line("BENCH", method);
    sh_puts("insns=");
    sh_u32((total + SET / 2) / SET);
    sh_puts("\n");
    line("DETAIL", method);
    sh_puts("inputs=64 min=");
    sh_u32(min);
    sh_puts(" max=");
    sh_u32(max);
    sh_puts(" total=");
    sh_u32(total);
    sh_puts("\n");
    /* One write per row, as the Rust rig prints: tools/cycle_model.py groups the measured
     * regions by the semihosting calls between them. */
    sh_flush();
}

int main(void) {
    static contensou_contact_f32 fixed, varying;
    contensou_curvatures_f32 curv;
    contensou_step_f32 steps[SET];
    contensou_wrench_f32 rest;
    double u[SET], psi[SET];

    counter_init();
    overhead = UINT32_MAX;
    for (int i = 0; i < 8; i++) {
        uint32_t n = empty_region();
        overhead = n < overhead ? n : overhead;
    }
    sh_puts("OVERHEAD c-firmware insns=");
    sh_u32(overhead);
    sh_puts("\n");

    /* As benches/wrench_set.rs: every constant rounded from double to float. */
    failures += contensou_curvatures_ball_race_f32((float)12.7e-3, (float)6.6e-3, (float)65e-3,
                                                   0.0f, CONTENSOU_RACE_INNER, &curv) != 0;
    const contensou_spec_f32 spec = {curv.p, curv.q, (float)1.142857e11, 0.0f, (float)0.07, 0.0f};
    failures += contensou_contact_new_f32(&fixed, &spec, CONTENSOU_LAW_BEST, CONTENSOU_FORM_FIXED, 0) != 0;
    failures += contensou_contact_new_f32(&varying, &spec, CONTENSOU_LAW_BEST, CONTENSOU_FORM_VARYING, 0) != 0;
    const float h = (float)5e-6;
    const contensou_step_f32 at_rest = {h, 0.0f, 0.0f, 0.0f, 0.0f};
    failures += contensou_contact_wrench_f32(&fixed, &at_rest, &rest, 0) != 0;
    mixed_set(u, psi);
    uint64_t hash = 0xcbf29ce484222325ull; /* FNV-1a over the f32 bits of (vx, vy) */
    for (int i = 0; i < SET; i++) {
        double v = u[i] * (double)rest.a * 100.0;
        steps[i] = (contensou_step_f32){h, 0.0f, (float)(v * cos(psi[i])), (float)(v * sin(psi[i])), 100.0f};
        const uint32_t words[2] = {f32_bits(steps[i].vx), f32_bits(steps[i].vy)};
        for (int k = 0; k < 2; k++)
            for (int b = 0; b < 4; b++) hash = (hash ^ ((words[k] >> (8 * b)) & 0xFF)) * 0x100000001b3ull;
    }
    failures += hash != RUST_SLIPS_FNV1A64;
    sh_puts("INPUTS wrench c f32 slips=64 fnv1a64=");
    sh_hex32((uint32_t)(hash >> 32));
    sh_hex32((uint32_t)hash);
    sh_puts("\n");

    bench("c-fixed-best", &fixed, steps);
    bench("c-varying-best", &varying, steps);
    return failures != 0;
}
