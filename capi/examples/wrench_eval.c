/*
 * wrench_eval: the C twin of `contact_eval wrench` (the wrench contract of contensou::dynamic).
 *
 *   wrench_eval [--law best|simplified|pade|ellipsoid|coulomb] [--form fixed|varying]
 *               [--precision f32|f64] < in.csv > out.csv
 *
 * stdin: the header row P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega then one state per row; stdout:
 * the inputs echoed, then N,Fx,Fy,Tz,a,b,e2. Floats print with %.9g (f32) or %.17g (f64), so
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
#define OUTPUTS 7
static const char *const INPUT_NAMES = "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega";
static const char *const OUTPUT_NAMES = "N,Fx,Fy,Tz,a,b,e2";

static int usage(const char *why) {
    fprintf(stderr, "wrench_eval: %s\nusage: wrench_eval [--law NAME] [--form fixed|varying] "
                    "[--precision f32|f64] < in.csv > out.csv\n", why);
    return 2;
}

static int fail_row(long row, const char *column, const char *value, contensou_status s) {
    fprintf(stderr, "wrench_eval: row %ld: %s = %s: %s (status %u)\n", row, column, value,
            contensou_status_message(s), (unsigned)s);
    return 1;
}

int main(int argc, char **argv) {
    contensou_law law = CONTENSOU_LAW_BEST;
    contensou_form form = CONTENSOU_FORM_FIXED;
    int f32 = 0, i;
    static char line[4096];
    static contensou_contact_f32 c32; /* caller-owned storage: static, no allocation */
    static contensou_contact_f64 c64;
    double prev[COLUMNS];
    int have_prev = 0;
    long row = 0;

    for (i = 1; i < argc; i += 2) {
        const char *opt = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!val) return usage("option without a value");
        if (strcmp(opt, "--law") == 0) {
            if (contensou_law_from_name(val, &law) != CONTENSOU_STATUS_OK) return usage("--law: unknown law");
        } else if (strcmp(opt, "--form") == 0) {
            if (contensou_form_from_name(val, &form) != CONTENSOU_STATUS_OK) return usage("--form: must be fixed or varying");
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
        fprintf(stderr, "wrench_eval: header = %s: must be `%s`\n", trim(line), INPUT_NAMES);
        return 1;
    }
    printf("%s,%s\n", INPUT_NAMES, OUTPUT_NAMES);

    while (fgets(line, sizeof line, stdin)) {
        char copy[sizeof line];
        char *fields[COLUMNS];
        double v[COLUMNS], out[OUTPUTS];
        contensou_column column = CONTENSOU_COLUMN_NONE;
        contensou_status s;
        int n, k, same_but_curvatures;
        row++;
        if (*trim(line) == '\0') continue;
        memcpy(copy, line, sizeof line);
        n = split(copy, fields, COLUMNS);
        if (n != COLUMNS) {
            fprintf(stderr, "wrench_eval: row %ld: fields = %d: expected %d (%s)\n", row, n, COLUMNS, INPUT_NAMES);
            return 1;
        }
        for (k = 0; k < COLUMNS; k++) {
            const char *why = parse(fields[k], &v[k], f32);
            if (why) {
                fprintf(stderr, "wrench_eval: row %ld: %s = %s: %s\n", row,
                        contensou_column_name((contensou_column)k), fields[k], why);
                return 1;
            }
        }
        same_but_curvatures = have_prev && form == CONTENSOU_FORM_VARYING;
        for (k = CONTENSOU_COLUMN_ESTAR; k <= CONTENSOU_COLUMN_DELTA; k++)
            same_but_curvatures = same_but_curvatures && memcmp(&v[k], &prev[k], sizeof v[k]) == 0;
        have_prev = 0;
        if (f32) {
            contensou_spec_f32 spec;
            contensou_step_f32 step;
            contensou_wrench_f32 w;
            spec.p = (float)v[0]; spec.q = (float)v[1]; spec.estar = (float)v[2];
            spec.cd = (float)v[3]; spec.f = (float)v[4]; spec.delta = (float)v[5];
            step.h = (float)v[6]; step.hdot = (float)v[7]; step.vx = (float)v[8];
            step.vy = (float)v[9]; step.omega = (float)v[10];
            s = same_but_curvatures ? contensou_contact_set_curvatures_f32(&c32, spec.p, spec.q, &column)
                                    : contensou_contact_new_f32(&c32, &spec, law, form, &column);
            if (s == CONTENSOU_STATUS_OK) s = contensou_contact_wrench_f32(&c32, &step, &w, &column);
            if (s != CONTENSOU_STATUS_OK) return fail_row(row, contensou_column_name(column), fields[column < COLUMNS ? column : 0], s);
            out[0] = w.n; out[1] = w.fx; out[2] = w.fy; out[3] = w.tz; out[4] = w.a; out[5] = w.b; out[6] = w.e2;
        } else {
            contensou_spec_f64 spec;
            contensou_step_f64 step;
            contensou_wrench_f64 w;
            spec.p = v[0]; spec.q = v[1]; spec.estar = v[2]; spec.cd = v[3]; spec.f = v[4]; spec.delta = v[5];
            step.h = v[6]; step.hdot = v[7]; step.vx = v[8]; step.vy = v[9]; step.omega = v[10];
            s = same_but_curvatures ? contensou_contact_set_curvatures_f64(&c64, spec.p, spec.q, &column)
                                    : contensou_contact_new_f64(&c64, &spec, law, form, &column);
            if (s == CONTENSOU_STATUS_OK) s = contensou_contact_wrench_f64(&c64, &step, &w, &column);
            if (s != CONTENSOU_STATUS_OK) return fail_row(row, contensou_column_name(column), fields[column < COLUMNS ? column : 0], s);
            out[0] = w.n; out[1] = w.fx; out[2] = w.fy; out[3] = w.tz; out[4] = w.a; out[5] = w.b; out[6] = w.e2;
        }
        memcpy(prev, v, sizeof v);
        have_prev = 1;
        for (k = 0; k < COLUMNS; k++) printf(f32 ? "%.9g," : "%.17g,", v[k]);
        for (k = 0; k < OUTPUTS; k++) printf(f32 ? "%.9g%s" : "%.17g%s", out[k], k + 1 < OUTPUTS ? "," : "\n");
    }
    return fflush(stdout) == 0 ? 0 : 1;
}
