/*
 * The CSV reading shared by the C twins (wrench_eval.c, rolling_eval.c, step_eval.c): one row
 * of comma-separated numbers, as contact_eval reads them; a header's optional columns; with
 * contensou.h, the contract twins' options. Header-only (static functions).
 */
#ifndef CONTENSOU_CSV_FIELDS_H
#define CONTENSOU_CSV_FIELDS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A usage error of `program` (taking `options`, reading stdin, writing stdout): `why`, then the
 * usage line, on stderr; the exit code 2. */
static int usage_error(const char *program, const char *options, const char *why) {
    fprintf(stderr, "%s: %s\nusage: %s %s < in.csv > out.csv\n", program, why, program, options);
    return 2;
}

/* Strips leading and trailing blanks in place. */
static char *trim(char *s) {
    char *end;
    while (*s == ' ' || *s == '\t' || *s == '\r') s++;
    end = s + strlen(s);
    while (end > s && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r' || end[-1] == '\n')) *--end = '\0';
    return s;
}

/* Splits a row into trimmed fields (the first `max` kept in `fields`); returns the number of
 * fields found. */
static int split(char *line, char **fields, int max) {
    int n = 0;
    char *p = line;
    for (;;) {
        char *comma = strchr(p, ',');
        if (comma) *comma = '\0';
        if (n < max) fields[n] = trim(p);
        n++;
        if (!comma) return n;
        p = comma + 1;
    }
}

/* A field as a number: NULL if it parses (the whole field), else why not (as contact_eval:
 * NaN is refused). */
static const char *parse(const char *field, double *out, int f32) {
    char *end;
    if (*field == '\0') return "not a number";
    if (f32) *out = strtof(field, &end); else *out = strtod(field, &end);
    if (*end != '\0') return "not a number";
    return *out == *out ? NULL : "not a number (NaN)";
}

/* The name of field k of a row for a message (`ctx`: the twin's), or NULL for "field k+1". */
typedef const char *(*field_name_fn)(int k, const void *ctx);

/* The rows after the header on stdin, read as contact_eval reads them. */
typedef struct {
    const char *program; /* the twin, named in every message */
    const char *header;  /* named in a field-count message */
    int expected;        /* fields per row */
    field_name_fn name;  /* names field k in a parse message */
    const void *ctx;     /* name's */
    long row;            /* rows read, blank ones included (row K is line K + 1) */
    char line[4096];     /* the row as read */
    char copy[4096];     /* the row split in place: `fields` point into it */
    char *fields[64];    /* the row's trimmed fields */
} csv_rows;

/* The next row (blank lines skipped) into `v` (room for `expected` values), each field parsed
 * in the run's precision: 1 for a row, 0 at the end of the input, −1 after a message on stderr
 * naming the program, the row and why (another field count, or a field that is not a
 * number). */
static int next_row(csv_rows *r, double *v, int f32) {
    while (fgets(r->line, sizeof r->line, stdin)) {
        int n, k;
        r->row++;
        if (*trim(r->line) == '\0') continue;
        memcpy(r->copy, r->line, sizeof r->line);
        n = split(r->copy, r->fields, 64);
        if (n != r->expected) {
            fprintf(stderr, "%s: row %ld: fields = %d: expected %d (%s)\n", r->program, r->row, n, r->expected,
                    r->header);
            return -1;
        }
        for (k = 0; k < n; k++) {
            const char *why = parse(r->fields[k], &v[k], f32);
            if (why) {
                const char *field = r->name(k, r->ctx);
                if (field) fprintf(stderr, "%s: row %ld: %s = %s: %s\n", r->program, r->row, field, r->fields[k], why);
                else fprintf(stderr, "%s: row %ld: field %d = %s: %s\n", r->program, r->row, k + 1, r->fields[k], why);
                return -1;
            }
        }
        return 1;
    }
    return 0;
}

/* A row's `n` inputs `v` then its `outputs` results `out`, comma-separated: %.9g (f32) or
 * %.17g (f64), so that they read back to the same bits. */
static void print_row(const double *v, int n, const double *out, int outputs, int f32) {
    int k;
    for (k = 0; k < n; k++) printf(f32 ? "%.9g," : "%.17g,", v[k]);
    for (k = 0; k < outputs; k++) printf(f32 ? "%.9g%s" : "%.17g%s", out[k], k + 1 < outputs ? "," : "\n");
}

#ifdef CONTENSOU_H
/* The options of the wrench contract's twins (wrench_eval, step_eval): --law (a law of the
 * contract: not full-slip or linear), --form, --precision; NULL, or why they are wrong. */
static inline const char *contract_options(int argc, char **argv, contensou_law *law, contensou_form *form, int *f32) {
    int i;
    for (i = 1; i < argc; i += 2) {
        const char *opt = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!val) return "option without a value";
        if (strcmp(opt, "--law") == 0) {
            if (contensou_law_from_name(val, law) != CONTENSOU_STATUS_OK || *law == CONTENSOU_LAW_FULL_SLIP ||
                *law == CONTENSOU_LAW_LINEAR)
                return "--law: unknown law";
        } else if (strcmp(opt, "--form") == 0) {
            if (contensou_form_from_name(val, form) != CONTENSOU_STATUS_OK) return "--form: must be fixed or varying";
        } else if (strcmp(opt, "--precision") == 0) {
            if (strcmp(val, "f32") == 0) *f32 = 1;
            else if (strcmp(val, "f64") == 0) *f32 = 0;
            else return "--precision: must be f32 or f64";
        } else {
            return "unknown option";
        }
    }
    return NULL;
}

/* The contract's columns in C type T (float or double; the cast is exact for double): the
 * contact spec from v[0..5], the step from v[6..10], the rolling velocity from opt[2], opt[3]. */
#define CONTRACT_COLUMNS(T, spec, step, roll, v, opt)                                              \
    do {                                                                                           \
        (spec).p = (T)(v)[0]; (spec).q = (T)(v)[1]; (spec).estar = (T)(v)[2];                      \
        (spec).cd = (T)(v)[3]; (spec).f = (T)(v)[4]; (spec).delta = (T)(v)[5];                     \
        (step).h = (T)(v)[6]; (step).hdot = (T)(v)[7]; (step).vx = (T)(v)[8];                      \
        (step).vy = (T)(v)[9]; (step).omega = (T)(v)[10];                                          \
        (roll).vrx = (T)(opt)[2]; (roll).vry = (T)(opt)[3];                                        \
    } while (0)
#endif

/* A header made of the `required` columns then any of the `count` optional `names` (each at
 * most once, any order): field_of[k] gets the field of names[k] (−1 if absent); the fields per
 * row, or −1 after a message on stderr naming `program`. */
static inline int optional_columns(const char *program, const char *header, const char *required, const char *const *names,
                                   int count, int *field_of) {
    size_t n = strlen(required);
    const char *rest = header + n;
    char copy[4096], *found[64];
    int extra, k, j, columns = 1;
    for (k = 0; k < count; k++) field_of[k] = -1;
    for (k = 0; required[k]; k++) columns += required[k] == ',';
    if (strncmp(header, required, n) != 0 || (*rest != '\0' && *rest != ',') || strlen(rest) >= sizeof copy) {
        fprintf(stderr, "%s: header = %s: must be `%s` then optional columns\n", program, header, required);
        return -1;
    }
    memcpy(copy, rest, strlen(rest) + 1);
    extra = *copy ? split(copy + 1, found, 64) : 0;
    if (extra > count) {
        fprintf(stderr, "%s: header = %s: too many columns\n", program, header);
        return -1;
    }
    for (j = 0; j < extra; j++) {
        for (k = 0; k < count && strcmp(found[j], names[k]) != 0; k++) {}
        if (k == count || field_of[k] >= 0) {
            fprintf(stderr, "%s: header = %s: `%s` is no optional column or repeats\n", program, header, found[j]);
            return -1;
        }
        field_of[k] = columns + j;
    }
    return columns + extra;
}

#endif
