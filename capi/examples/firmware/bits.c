/* C firmware image `bits`: the host = MCU bit-identity check through the C API.
 * Evaluates the shared f32 test vectors (vectors.c) with contensou_contact_wrench_f32
 * for every law and form and streams, over semihosting, the same lines as the Rust twins
 * (vectors.rs): `CONFIG <law> <form>`, one line per state with the seven outputs
 * N Fx Fy Tz a b e2 as f32 bits in hex (`ERR <column>` if the C API refuses the state), and
 * `END <states>`. tools/host-mcu-bits.sh compares it with x86-64. */
#include "floatbits.h"
#include "semihost.h"
#include "vectors.h"

static const char *const law_names[] = {"best", "simplified", "pade", "ellipsoid", "coulomb"};
static const contensou_law laws[] = {CONTENSOU_LAW_BEST, CONTENSOU_LAW_SIMPLIFIED,
                                     CONTENSOU_LAW_PADE, CONTENSOU_LAW_ELLIPSOID,
                                     CONTENSOU_LAW_COULOMB};
static const char *const form_names[] = {"fixed", "varying"};
static const contensou_form forms[] = {CONTENSOU_FORM_FIXED, CONTENSOU_FORM_VARYING};

static void config(contensou_law law, const char *law_name, contensou_form form,
                   const char *form_name) {
    static contensou_contact_f32 contact; /* caller-owned storage, CONTENSOU_CONTACT_F32_SIZE bytes */
    bits_rng rng = {BITS_SEED};
    sh_puts("CONFIG ");
    sh_puts(law_name);
    sh_puts(" ");
    sh_puts(form_name);
    sh_puts("\n");
    for (int s = 0; s < BITS_SPECS; s++) {
        contensou_spec_f32 spec = bits_spec(&rng);
        contensou_column column;
        contensou_status built = contensou_contact_new_f32(&contact, &spec, law, form, &column);
        contensou_column built_column = column;
        for (int k = 0; k < BITS_STEPS; k++) {
            contensou_step_f32 step = bits_step(&rng);
            contensou_wrench_f32 w;
            contensou_status st = built;
            if (st == CONTENSOU_STATUS_OK) st = contensou_contact_wrench_f32(&contact, &step, &w, &column);
            else column = built_column;
            if (st != CONTENSOU_STATUS_OK) {
                sh_puts("ERR ");
                sh_puts(contensou_column_name(column));
                sh_puts("\n");
                continue;
            }
            const float out[7] = {w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2};
            for (int i = 0; i < 7; i++) {
                if (i) sh_puts(" ");
                sh_hex32(f32_bits(out[i]));
            }
            sh_puts("\n");
        }
    }
    sh_puts("END ");
    sh_u32(BITS_SPECS * BITS_STEPS);
    sh_puts("\n");
}

int main(void) {
    for (int l = 0; l < 5; l++)
        for (int f = 0; f < 2; f++) config(laws[l], law_names[l], forms[f], form_names[f]);
    return 0;
}
