/*
 * The C API's error paths from C (the ABI as the header declares it): storage in static memory
 * that no constructor initialised, NULL and misaligned pointers, out-of-range enum values,
 * the column of a rejected input, and an error that leaves a contact usable. Exit 0 if every
 * check holds; run by capi/build.sh.
 */
#include <stdio.h>
#include <string.h>

#include "contensou.h"

static contensou_contact_f32 never_initialised; /* static: zeroed */
static contensou_contact_f64 contact;
static contensou_rolling_f32 rolling_never_initialised; /* static: zeroed */
static contensou_rolling_f64 rolling;
static int failures = 0;

#define EXPECT(cond) do { if (!(cond)) { fprintf(stderr, "errors.c:%d: %s\n", __LINE__, #cond); failures++; } } while (0)

int main(void) {
    contensou_spec_f64 spec = {10.0, 50.0, 1.15e11, 0.1, 0.1, 1e-4};
    contensou_step_f64 step = {1e-6, 0.0, 0.01, 0.0, 50.0};
    contensou_step_f32 step32 = {1e-6f, 0.0f, 0.01f, 0.0f, 50.0f};
    contensou_wrench_f64 w;
    contensou_wrench_f32 w32;
    contensou_column column = 99;
    union { contensou_contact_f64 storage; unsigned char bytes[sizeof(contensou_contact_f64) + 8]; } raw;
    contensou_contact_f64 *misaligned = (contensou_contact_f64 *)(void *)(raw.bytes + 4);

    EXPECT(sizeof(contensou_contact_f32) == CONTENSOU_CONTACT_F32_SIZE);
    EXPECT(sizeof(contensou_contact_f64) == CONTENSOU_CONTACT_F64_SIZE);
    EXPECT(contensou_contact_wrench_f32(&never_initialised, &step32, &w32, NULL) == CONTENSOU_STATUS_NOT_INITIALIZED);
    EXPECT(contensou_contact_new_f64(NULL, &spec, CONTENSOU_LAW_BEST, CONTENSOU_FORM_FIXED, &column) == CONTENSOU_STATUS_NULL_POINTER);
    EXPECT(column == CONTENSOU_COLUMN_NONE);
    EXPECT(contensou_contact_new_f64(misaligned, &spec, CONTENSOU_LAW_BEST, CONTENSOU_FORM_FIXED, NULL) == CONTENSOU_STATUS_MISALIGNED);
    EXPECT(contensou_contact_new_f64(&contact, &spec, 42, CONTENSOU_FORM_FIXED, NULL) == CONTENSOU_STATUS_INVALID_LAW);
    EXPECT(contensou_contact_new_f64(&contact, &spec, CONTENSOU_LAW_FULL_SLIP, CONTENSOU_FORM_FIXED, NULL) == CONTENSOU_STATUS_INVALID_LAW);
    EXPECT(contensou_contact_new_f64(&contact, &spec, CONTENSOU_LAW_BEST, 7, NULL) == CONTENSOU_STATUS_INVALID_FORM);
    spec.p = 60.0;
    EXPECT(contensou_contact_new_f64(&contact, &spec, CONTENSOU_LAW_PADE, CONTENSOU_FORM_VARYING, &column) == CONTENSOU_STATUS_CURVATURES_NOT_ORDERED);
    EXPECT(column == CONTENSOU_COLUMN_P && strcmp(contensou_column_name(column), "P") == 0);
    spec.p = 10.0;
    EXPECT(contensou_contact_new_f64(&contact, &spec, CONTENSOU_LAW_PADE, CONTENSOU_FORM_VARYING, &column) == CONTENSOU_STATUS_OK);
    EXPECT(contensou_contact_set_curvatures_f64(&contact, 20.0, 0.0, &column) == CONTENSOU_STATUS_CURVATURES_NOT_ORDERED);
    EXPECT(contensou_contact_wrench_f64(&contact, &step, &w, &column) == CONTENSOU_STATUS_OK && w.n > 0.0 && w.tz < 0.0);
    step.omega = 1.0 / 0.0 * 0.0; /* NaN */
    EXPECT(contensou_contact_wrench_f64(&contact, &step, &w, &column) == CONTENSOU_STATUS_NON_FINITE);
    EXPECT(column == CONTENSOU_COLUMN_OMEGA);
    EXPECT(contensou_contact_wrench_f64(&contact, NULL, &w, NULL) == CONTENSOU_STATUS_NULL_POINTER);
    {
        /* The Jacobian: the wrench's errors and column; its wrench is the wrench's. */
        contensou_jacobian_f64 j;
        contensou_rolling_step_f64 roll = {2.0, 1.0 / 0.0};
        EXPECT(contensou_contact_jacobian_f64(&contact, &step, &j, &column) == CONTENSOU_STATUS_NON_FINITE);
        EXPECT(column == CONTENSOU_COLUMN_OMEGA);
        EXPECT(contensou_contact_jacobian_f32(&never_initialised, &step32, NULL, NULL) == CONTENSOU_STATUS_NOT_INITIALIZED);
        EXPECT(contensou_contact_jacobian_f64(&contact, NULL, &j, NULL) == CONTENSOU_STATUS_NULL_POINTER);
        step.omega = 50.0;
        EXPECT(contensou_contact_jacobian_f64(&contact, &step, NULL, &column) == CONTENSOU_STATUS_NULL_POINTER);
        EXPECT(contensou_contact_jacobian_f64(&contact, &step, &j, &column) == CONTENSOU_STATUS_OK);
        EXPECT(contensou_contact_wrench_f64(&contact, &step, &w, &column) == CONTENSOU_STATUS_OK);
        EXPECT(memcmp(&j.n, &w.n, sizeof w.n) == 0 && memcmp(&j.tz, &w.tz, sizeof w.tz) == 0 && j.d[0][0] > 0.0);
        EXPECT(contensou_contact_new_f64(&contact, &spec, CONTENSOU_LAW_TABLE, CONTENSOU_FORM_FIXED, &column) == CONTENSOU_STATUS_OK);
        EXPECT(contensou_contact_jacobian_rolling_f64(&contact, &step, &roll, &j, &column) == CONTENSOU_STATUS_NON_FINITE);
        EXPECT(column == CONTENSOU_COLUMN_VRY && strcmp(contensou_column_name(column), "vry") == 0);
        EXPECT(strcmp(contensou_status_message(CONTENSOU_STATUS_STEP_NOT_POSITIVE), "time step dt must be > 0 (s)") == 0);
    }
    EXPECT(strcmp(contensou_status_message(CONTENSOU_STATUS_DAMPING_NEGATIVE), "damping coefficient is negative") == 0);
    EXPECT(strcmp(contensou_status_message(4242), "unknown contensou_status code") == 0);

    /* The rolling evaluator: typed errors naming the column, NULL, zeroed storage. */
    {
        contensou_rolling_state_f64 st = {6e-3, 4e-3, 0.3, 8e4, 30.0, 1e-3, 0.0, 0.5};
        contensou_rolling_state_f32 st32 = {6e-3f, 4e-3f, 0.3f, 8e4f, 30.0f, 1e-3f, 0.0f, 0.5f};
        contensou_rolling_output_f64 out;
        contensou_rolling_output_f32 out32;
        contensou_rolling_column rc = 99;
        contensou_law law = 0;
        EXPECT(sizeof(contensou_rolling_f32) == CONTENSOU_ROLLING_F32_SIZE);
        EXPECT(sizeof(contensou_rolling_f64) == CONTENSOU_ROLLING_F64_SIZE);
        EXPECT(contensou_rolling_wrench_f32(&rolling_never_initialised, &st32, &out32, NULL) == CONTENSOU_STATUS_NOT_INITIALIZED);
        EXPECT(contensou_rolling_new_f64(NULL, 1.5, 8e10, 0.28, CONTENSOU_LAW_TABLE, &rc) == CONTENSOU_STATUS_NULL_POINTER);
        EXPECT(rc == CONTENSOU_ROLLING_COLUMN_NONE);
        EXPECT(contensou_rolling_new_f64(&rolling, 1.5, 8e10, 0.28, CONTENSOU_LAW_BEST, NULL) == CONTENSOU_STATUS_INVALID_LAW);
        EXPECT(contensou_rolling_new_f64(&rolling, 1.5, -1.0, 0.28, CONTENSOU_LAW_TABLE, &rc) == CONTENSOU_STATUS_SHEAR_MODULUS_NOT_POSITIVE);
        EXPECT(rc == CONTENSOU_ROLLING_COLUMN_G && strcmp(contensou_rolling_column_name(rc), "G") == 0);
        EXPECT(contensou_rolling_new_f64(&rolling, 1.5, 8e10, 0.6, CONTENSOU_LAW_TABLE, &rc) == CONTENSOU_STATUS_ROLLING_POISSON_RATIO_OUT_OF_RANGE);
        EXPECT(rc == CONTENSOU_ROLLING_COLUMN_NU);
        EXPECT(contensou_rolling_new_f64(&rolling, 200.0, 8e10, 0.28, CONTENSOU_LAW_TABLE, &rc) == CONTENSOU_STATUS_ROLLING_ASPECT_OUT_OF_RANGE);
        EXPECT(rc == CONTENSOU_ROLLING_COLUMN_A_OVER_B && strcmp(contensou_rolling_column_name(rc), "a/b") == 0);
        EXPECT(contensou_law_from_name("fastsim-16", &law) == CONTENSOU_STATUS_OK && law == CONTENSOU_LAW_FASTSIM_16);
        EXPECT(contensou_rolling_new_f64(&rolling, 1.5, 8e10, 0.28, law, &rc) == CONTENSOU_STATUS_OK);
        EXPECT(contensou_rolling_wrench_f64(&rolling, &st, &out, &rc) == CONTENSOU_STATUS_OK && out.fx < 0.0 && out.mz != 0.0);
        EXPECT(contensou_rolling_wrench_f64(&rolling, &st, NULL, &rc) == CONTENSOU_STATUS_NULL_POINTER);
        st.phi = 1.0 / 0.0; /* inf */
        EXPECT(contensou_rolling_wrench_f64(&rolling, &st, &out, &rc) == CONTENSOU_STATUS_NON_FINITE);
        EXPECT(rc == CONTENSOU_ROLLING_COLUMN_PHI);
    }
    if (failures) return 1;
    printf("errors.c: all checks hold\n");
    return 0;
}
