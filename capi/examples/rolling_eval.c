/*
 * rolling_eval: the C twin of `contact_eval rolling` (Kalker's rolling contact).
 *
 *   rolling_eval [--law table|blend|fastsim|fastsim-16|full-slip|linear] [--precision f32|f64]
 *                < in.csv > out.csv
 *
 * stdin: the header row a,b,G,nu,f,N,V,xi,eta,phi then one state per row; stdout: the inputs
 * echoed, then Fx,Fy,Mz. Floats print with %.9g (f32) or %.17g (f64), so they read back to the
 * same bits. Blank lines are skipped (row K is line K + 1). The first bad row stops the run:
 * "rolling_eval: row K: column = value: message (status code)" on stderr, exit 1. Usage
 * errors exit 2. Defaults: table, f64 (as contact_eval).
 *
 * A rolling contact (shape a/b, G, nu) is built for a row whose a/b, G or nu differ from the
 * previous row's; otherwise the previous contact is evaluated again.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contensou.h"
#include "csv_fields.h"

#define COLUMNS 10
#define OUTPUTS 3
static const char *const INPUT_NAMES = "a,b,G,nu,f,N,V,xi,eta,phi";
static const char *const OUTPUT_NAMES = "Fx,Fy,Mz";

static int usage(const char *why) { return usage_error("rolling_eval", "[--law NAME] [--precision f32|f64]", why); }

static int fail_row(long row, contensou_rolling_column column, char *fields[COLUMNS], contensou_status s) {
    const char *value = column < COLUMNS ? fields[column] : "";
    fprintf(stderr, "rolling_eval: row %ld: %s = %s: %s (status %u)\n", row,
            contensou_rolling_column_name(column), value, contensou_status_message(s), (unsigned)s);
    return 1;
}

/* The name of field k: its rolling column. */
static const char *field_name(int k, const void *ctx) {
    (void)ctx;
    return contensou_rolling_column_name((contensou_rolling_column)k);
}

int main(int argc, char **argv) {
    contensou_law law = CONTENSOU_LAW_TABLE;
    int f32 = 0, i;
    static char line[4096];
    static contensou_rolling_f32 c32; /* caller-owned storage: static, no allocation */
    static contensou_rolling_f64 c64;
    double prev[COLUMNS];
    int have_prev = 0;
    static csv_rows rows;
    double v[COLUMNS];
    int got;

    for (i = 1; i < argc; i += 2) {
        const char *opt = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!val) return usage("option without a value");
        if (strcmp(opt, "--law") == 0) {
            if (contensou_law_from_name(val, &law) != CONTENSOU_STATUS_OK || law < CONTENSOU_LAW_TABLE)
                return usage("--law: unknown rolling law");
        } else if (strcmp(opt, "--precision") == 0) {
            if (strcmp(val, "f32") == 0) f32 = 1;
            else if (strcmp(val, "f64") == 0) f32 = 0;
            else return usage("--precision: must be f32 or f64");
        } else {
            return usage("unknown option");
        }
    }

    if (!fgets(line, sizeof line, stdin)) return usage("missing header row");
    if (strcmp(trim(line), INPUT_NAMES) != 0) {
        fprintf(stderr, "rolling_eval: header = %s: must be `%s`\n", trim(line), INPUT_NAMES);
        return 1;
    }
    printf("%s,%s\n", INPUT_NAMES, OUTPUT_NAMES);

    rows.program = "rolling_eval";
    rows.header = INPUT_NAMES;
    rows.expected = COLUMNS;
    rows.name = field_name;
    while ((got = next_row(&rows, v, f32)) > 0) {
        long row = rows.row;
        char **fields = rows.fields;
        double out[OUTPUTS];
        contensou_rolling_column column = CONTENSOU_ROLLING_COLUMN_NONE;
        contensou_status s = CONTENSOU_STATUS_OK;
        int same_contact;
        /* a, b, G, nu the previous row's: the same contact (same a/b, G, nu bits) */
        same_contact = have_prev && memcmp(v, prev, 4 * sizeof v[0]) == 0;
        have_prev = 0;
        if (f32) {
            contensou_rolling_state_f32 st;
            contensou_rolling_output_f32 w;
            float a = (float)v[0], b = (float)v[1];
            st.a = a; st.b = b; st.f = (float)v[4]; st.n = (float)v[5]; st.v = (float)v[6];
            st.xi = (float)v[7]; st.eta = (float)v[8]; st.phi = (float)v[9];
            if (!same_contact) s = contensou_rolling_new_f32(&c32, a / b, (float)v[2], (float)v[3], law, &column);
            if (s == CONTENSOU_STATUS_OK) s = contensou_rolling_wrench_f32(&c32, &st, &w, &column);
            if (s != CONTENSOU_STATUS_OK) return fail_row(row, column, fields, s);
            out[0] = w.fx; out[1] = w.fy; out[2] = w.mz;
        } else {
            contensou_rolling_state_f64 st;
            contensou_rolling_output_f64 w;
            st.a = v[0]; st.b = v[1]; st.f = v[4]; st.n = v[5]; st.v = v[6];
            st.xi = v[7]; st.eta = v[8]; st.phi = v[9];
            if (!same_contact) s = contensou_rolling_new_f64(&c64, v[0] / v[1], v[2], v[3], law, &column);
            if (s == CONTENSOU_STATUS_OK) s = contensou_rolling_wrench_f64(&c64, &st, &w, &column);
            if (s != CONTENSOU_STATUS_OK) return fail_row(row, column, fields, s);
            out[0] = w.fx; out[1] = w.fy; out[2] = w.mz;
        }
        memcpy(prev, v, sizeof v);
        have_prev = 1;
        print_row(v, COLUMNS, out, OUTPUTS, f32);
    }
    if (got < 0) return 1;
    return fflush(stdout) == 0 ? 0 : 1;
}
