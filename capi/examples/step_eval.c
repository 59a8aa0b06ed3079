/*
 * step_eval: the C twin of `contact_eval step` (the step-aware wrench's row contract,
 * contensou::step::contract) through contensou_contact_step_*.
 *
 *   step_eval [--law NAME] [--form fixed|varying] [--precision f32|f64] < in.csv > out.csv
 *
 * stdin: the header row P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega,dt,w_nn,w_nx,w_ny,w_nw,w_xx,
 * w_xy,w_xw,w_yy,w_yw,w_ww, then any of the optional columns G,nu,vrx,vry,un_free,ux_free,
 * uy_free,uw_free (each at most once, any order), then one row per step; stdout: the inputs
 * echoed, then N,Fx,Fy,Tz. A contact is built per row (contensou_contact_new_rolling_*: G, nu
 * NULL when absent); the rolling velocity is 0 when its columns are absent; the free velocity
 * is NULL when no free column is given, else each absent one is the start velocity's
 * (−hdot, vx, vy, omega), as the contract reads absent columns. Floats print with %.9g (f32)
 * or %.17g (f64). The first bad row stops the run: "step_eval: row K: column = value: message
 * (status code)" on stderr, exit 1 (the value "?" for the column W as a whole). Usage errors
 * exit 2. Defaults: best, fixed, f64 (as contact_eval).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contensou.h"
#include "csv_fields.h"

#define COLUMNS 22
#define OPTIONAL 8
#define MAX_FIELDS (COLUMNS + OPTIONAL)
static const char *const INPUT_NAMES =
    "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega,dt,w_nn,w_nx,w_ny,w_nw,w_xx,w_xy,w_xw,w_yy,w_yw,w_ww";
static const char *const OPTIONAL_NAMES[OPTIONAL] = {"G", "nu", "vrx", "vry", "un_free", "ux_free", "uy_free", "uw_free"};

/* One row in precision S (f32, f64; T its C type) on the storage c: builds the contact, then
 * the step-aware wrench into out. */
#define STEP_ROW(S, T, c)                                                                          \
    do {                                                                                           \
        contensou_spec_##S spec;                                                                   \
        contensou_step_##S step;                                                                   \
        contensou_rolling_step_##S roll;                                                           \
        contensou_inverse_mass_##S w;                                                              \
        contensou_step_velocity_##S u;                                                             \
        contensou_step_wrench_##S o = {0, 0, 0, 0};                                                \
        T g = (T)opt[0], nu = (T)opt[1];                                                           \
        CONTRACT_COLUMNS(T, spec, step, roll, v, opt);                                             \
        w.nn = (T)v[12]; w.nx = (T)v[13]; w.ny = (T)v[14]; w.nw = (T)v[15]; w.xx = (T)v[16];       \
        w.xy = (T)v[17]; w.xw = (T)v[18]; w.yy = (T)v[19]; w.yw = (T)v[20]; w.ww = (T)v[21];       \
        u.vn = (T)opt[4]; u.vx = (T)opt[5]; u.vy = (T)opt[6]; u.omega = (T)opt[7];                 \
        s = contensou_contact_new_rolling_##S(&c, &spec, field_of[0] >= 0 ? &g : NULL,             \
                                              field_of[1] >= 0 ? &nu : NULL, law, form, &column); \
        if (s == CONTENSOU_STATUS_OK)                                                              \
            s = contensou_contact_step_##S(&c, &step, &roll, (T)v[11], &w, has_free ? &u : NULL, &o, &column); \
        out[0] = o.n; out[1] = o.fx; out[2] = o.fy; out[3] = o.tz;                                 \
    } while (0)

static int usage(const char *why) { return usage_error("step_eval", "[--law NAME] [--form fixed|varying] [--precision f32|f64]", why); }

/* Fields are named by number in a parse error. */
static const char *field_number(int k, const void *ctx) {
    (void)k;
    (void)ctx;
    return NULL;
}

int main(int argc, char **argv) {
    contensou_law law = CONTENSOU_LAW_BEST;
    contensou_form form = CONTENSOU_FORM_FIXED;
    int f32 = 0, i, fields_per_row, has_free = 0;
    static char line[4096], header[4096];
    static contensou_contact_f32 c32; /* caller-owned storage: static, no allocation */
    static contensou_contact_f64 c64;
    int field_of[OPTIONAL];
    static csv_rows rows;
    double v[MAX_FIELDS];
    int got;

    {
        const char *why = contract_options(argc, argv, &law, &form, &f32);
        if (why) return usage(why);
    }
    if (!fgets(line, sizeof line, stdin)) return usage("missing header row");
    memcpy(header, trim(line), strlen(trim(line)) + 1);
    fields_per_row = optional_columns("step_eval", header, INPUT_NAMES, OPTIONAL_NAMES, OPTIONAL, field_of);
    if (fields_per_row < 0) return 1;
    for (i = 4; i < OPTIONAL; i++) has_free = has_free || field_of[i] >= 0;
    printf("%s,N,Fx,Fy,Tz\n", header);

    rows.program = "step_eval";
    rows.header = header;
    rows.expected = fields_per_row;
    rows.name = field_number;
    while ((got = next_row(&rows, v, f32)) > 0) {
        char **fields = rows.fields;
        double out[4] = {0, 0, 0, 0}, opt[OPTIONAL];
        contensou_column column = CONTENSOU_COLUMN_NONE;
        contensou_status s;
        int k, bad_field;
        for (k = 0; k < OPTIONAL; k++) opt[k] = field_of[k] >= 0 ? v[field_of[k]] : 0.0;
        /* Absent free columns: the start velocity's (−hdot, vx, vy, omega). */
        if (field_of[4] < 0) opt[4] = -v[7];
        for (k = 5; k < OPTIONAL; k++)
            if (field_of[k] < 0) opt[k] = v[8 + (k - 5)];
        if (f32) STEP_ROW(f32, float, c32);
        else STEP_ROW(f64, double, c64);
        if (s != CONTENSOU_STATUS_OK) {
            bad_field = column < 11 ? (int)column
                      : column >= CONTENSOU_COLUMN_G && column <= CONTENSOU_COLUMN_VRY ? field_of[column - CONTENSOU_COLUMN_G]
                      : column == CONTENSOU_COLUMN_DT ? 11
                      : column >= CONTENSOU_COLUMN_W_NN && column < CONTENSOU_COLUMN_W ? 12 + (int)(column - CONTENSOU_COLUMN_W_NN)
                      : column >= CONTENSOU_COLUMN_UN_FREE && column < CONTENSOU_COLUMN_H_FREE ? field_of[4 + column - CONTENSOU_COLUMN_UN_FREE]
                      : -1;
            fprintf(stderr, "step_eval: row %ld: %s = %s: %s (status %u)\n", rows.row, contensou_column_name(column),
                    bad_field >= 0 ? fields[bad_field] : "?", contensou_status_message(s), (unsigned)s);
            return 1;
        }
        print_row(v, fields_per_row, out, 4, f32);
    }
    if (got < 0) return 1;
    return fflush(stdout) == 0 ? 0 : 1;
}
