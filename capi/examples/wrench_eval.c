/*
 * wrench_eval: the C twin of `contact_eval wrench` (the wrench contract of contensou::dynamic)
 * and, with the first argument `jacobian`, of `contact_eval jacobian`.
 *
 *   wrench_eval [jacobian]
 *               [--law best|simplified|pade|ellipsoid|coulomb|table|blend|fastsim|fastsim-16]
 *               [--form fixed|varying] [--precision f32|f64] < in.csv > out.csv
 *
 * stdin: the header row P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega, then any of the optional
 * rolling columns G,nu,vrx,vry (each at most once, any order), then one state per row; stdout:
 * the inputs echoed, then N,Fx,Fy,Tz,a,b,e2 (`jacobian`: N,Fx,Fy,Tz,dN_dh,...,dTz_domega). Without
 * optional columns the calls are contensou_contact_new_* / _wrench_* (_jacobian_*); with them,
 * contensou_contact_new_rolling_* (G, nu; NULL when absent) and
 * contensou_contact_wrench_rolling_* (_jacobian_rolling_*; vrx, vry; 0 when absent). Floats print with %.9g (f32) or %.17g (f64), so
 * they read back to the same bits. Blank lines are skipped (row K is line K + 1). The first bad
 * row stops the run: "wrench_eval: row K: column = value: message (status code NAME)" on
 * stderr, exit 1. Usage errors exit 2. Defaults: best, fixed, f64 (as contact_eval).
 *
 * A contact is built per row; in the varying form, a row that only changes P, Q updates the
 * previous contact with contensou_contact_set_curvatures_* (the per-step path) instead.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contensou.h"
#include "csv_fields.h"

#define COLUMNS 11
#define OPTIONAL 4
#define MAX_FIELDS (COLUMNS + OPTIONAL)
#define MAX_OUTPUTS 24
static const char *const INPUT_NAMES = "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega";
static const char *const OUTPUT_NAMES = "N,Fx,Fy,Tz,a,b,e2";
static const char *const JACOBIAN_NAMES =
    "N,Fx,Fy,Tz,dN_dh,dN_dhdot,dN_dvx,dN_dvy,dN_domega,dFx_dh,dFx_dhdot,dFx_dvx,dFx_dvy,dFx_domega,"
    "dFy_dh,dFy_dhdot,dFy_dvx,dFy_dvy,dFy_domega,dTz_dh,dTz_dhdot,dTz_dvx,dTz_dvy,dTz_domega";

/* The outputs of a Jacobian (contensou_jacobian_f32 / _f64): the wrench, then d row by row. */
#define JACOBIAN_OUT(out, j)                                                  \
    do {                                                                      \
        int r_, c_;                                                           \
        (out)[0] = (j).n; (out)[1] = (j).fx; (out)[2] = (j).fy; (out)[3] = (j).tz; \
        for (r_ = 0; r_ < 4; r_++)                                            \
            for (c_ = 0; c_ < 5; c_++) (out)[4 + 5 * r_ + c_] = (j).d[r_][c_];  \
    } while (0)
/* The optional columns, in contensou_column order from CONTENSOU_COLUMN_G. */
static const char *const OPTIONAL_NAMES[OPTIONAL] = {"G", "nu", "vrx", "vry"};

/* One row in precision S (f32, f64; T its C type) on the storage c: builds the contact (or, in
 * the varying form, updates its curvatures), then its wrench or Jacobian into out. */
#define WRENCH_ROW(S, T, c)                                                                        \
    do {                                                                                           \
        contensou_spec_##S spec;                                                                   \
        contensou_step_##S step;                                                                   \
        contensou_rolling_step_##S roll;                                                           \
        contensou_wrench_##S w = {0, 0, 0, 0, 0, 0, 0};                                            \
        T g = (T)opt[0], nu = (T)opt[1];                                                           \
        CONTRACT_COLUMNS(T, spec, step, roll, v, opt);                                             \
        if (same_but_curvatures) s = contensou_contact_set_curvatures_##S(&c, spec.p, spec.q, &column); \
        else if (has_contact_option)                                                               \
            s = contensou_contact_new_rolling_##S(&c, &spec, field_of[0] >= 0 ? &g : NULL,         \
                                                  field_of[1] >= 0 ? &nu : NULL, law, form, &column); \
        else s = contensou_contact_new_##S(&c, &spec, law, form, &column);                        \
        if (s == CONTENSOU_STATUS_OK && jacobian) {                                                \
            contensou_jacobian_##S j;                                                              \
            memset(&j, 0, sizeof j);                                                               \
            s = has_step_option ? contensou_contact_jacobian_rolling_##S(&c, &step, &roll, &j, &column) \
                                : contensou_contact_jacobian_##S(&c, &step, &j, &column);         \
            JACOBIAN_OUT(out, j);                                                                  \
        } else {                                                                                   \
            if (s == CONTENSOU_STATUS_OK)                                                          \
                s = has_step_option ? contensou_contact_wrench_rolling_##S(&c, &step, &roll, &w, &column) \
                                    : contensou_contact_wrench_##S(&c, &step, &w, &column);       \
            out[0] = w.n; out[1] = w.fx; out[2] = w.fy; out[3] = w.tz;                             \
            out[4] = w.a; out[5] = w.b; out[6] = w.e2;                                             \
        }                                                                                          \
    } while (0)

static int usage(const char *why) { return usage_error("wrench_eval", "[jacobian] [--law NAME] [--form fixed|varying] [--precision f32|f64]", why); }

/* The name of field k: a contract column, or the optional column `field_of` puts there. */
static const char *field_name(int k, const void *field_of) {
    const char *name = k < COLUMNS ? contensou_column_name((contensou_column)k) : "";
    int j;
    for (j = 0; j < OPTIONAL; j++)
        if (((const int *)field_of)[j] == k) name = OPTIONAL_NAMES[j];
    return name;
}

static int fail_row(long row, const char *column, const char *value, contensou_status s) {
    fprintf(stderr, "wrench_eval: row %ld: %s = %s: %s (status %u)\n", row, column, value,
            contensou_status_message(s), (unsigned)s);
    return 1;
}

int main(int argc, char **argv) {
    contensou_law law = CONTENSOU_LAW_BEST;
    contensou_form form = CONTENSOU_FORM_FIXED;
    int f32 = 0, jacobian = argc > 1 && strcmp(argv[1], "jacobian") == 0;
    int outputs = jacobian ? MAX_OUTPUTS : 7;
    static char line[4096], header[4096];
    static contensou_contact_f32 c32; /* caller-owned storage: static, no allocation */
    static contensou_contact_f64 c64;
    double prev[MAX_FIELDS];
    int have_prev = 0, fields_per_row = COLUMNS, has_contact_option = 0, has_step_option = 0;
    /* field_of[k]: the field holding optional column k, or -1 */
    int field_of[OPTIONAL] = {-1, -1, -1, -1};
    static csv_rows rows;
    double v[MAX_FIELDS];
    int got;

    {
        /* `jacobian` takes argv[1]: the options start after it */
        const char *why = contract_options(argc - jacobian, argv + jacobian, &law, &form, &f32);
        if (why) return usage(why);
    }
    if (!fgets(line, sizeof line, stdin)) return usage("missing header row");
    memcpy(header, trim(line), strlen(trim(line)) + 1);
    fields_per_row = optional_columns("wrench_eval", header, INPUT_NAMES, OPTIONAL_NAMES, OPTIONAL, field_of);
    if (fields_per_row < 0) return 1;
    has_contact_option = field_of[0] >= 0 || field_of[1] >= 0;
    has_step_option = field_of[2] >= 0 || field_of[3] >= 0;
    printf("%s,%s\n", header, jacobian ? JACOBIAN_NAMES : OUTPUT_NAMES);

    rows.program = "wrench_eval";
    rows.header = header;
    rows.expected = fields_per_row;
    rows.name = field_name;
    rows.ctx = field_of;
    while ((got = next_row(&rows, v, f32)) > 0) {
        char **fields = rows.fields;
        double out[MAX_OUTPUTS], opt[OPTIONAL];
        contensou_column column = CONTENSOU_COLUMN_NONE;
        contensou_status s;
        int k, same_but_curvatures, bad_field;
        for (k = 0; k < OPTIONAL; k++) opt[k] = field_of[k] >= 0 ? v[field_of[k]] : 0.0;
        same_but_curvatures = have_prev && form == CONTENSOU_FORM_VARYING;
        for (k = CONTENSOU_COLUMN_ESTAR; k <= CONTENSOU_COLUMN_DELTA; k++)
            same_but_curvatures = same_but_curvatures && memcmp(&v[k], &prev[k], sizeof v[k]) == 0;
        for (k = 0; k < 2; k++)
            if (field_of[k] >= 0)
                same_but_curvatures = same_but_curvatures && memcmp(&v[field_of[k]], &prev[field_of[k]], sizeof v[0]) == 0;
        have_prev = 0;
        if (f32) WRENCH_ROW(f32, float, c32);
        else WRENCH_ROW(f64, double, c64);
        if (s != CONTENSOU_STATUS_OK) {
            bad_field = column < COLUMNS ? (int)column
                      : column >= CONTENSOU_COLUMN_G && column <= CONTENSOU_COLUMN_VRY ? field_of[column - CONTENSOU_COLUMN_G]
                      : -1;
            return fail_row(rows.row, contensou_column_name(column), bad_field >= 0 ? fields[bad_field] : fields[0], s);
        }
        memcpy(prev, v, sizeof v);
        have_prev = 1;
        print_row(v, fields_per_row, out, outputs, f32);
    }
    if (got < 0) return 1;
    return fflush(stdout) == 0 ? 0 : 1;
}
