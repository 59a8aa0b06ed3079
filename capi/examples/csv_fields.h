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

/* Row number `row` in `line` (stripped in place) read into `v`: its fields split from `copy`
 * (a copy of the `size` bytes of `line`) into `fields` (the first `max` kept). 0 for a blank
 * line (skipped), 1 for a row of `expected` numbers, −1 after a message on stderr naming
 * `program`, the row and why: another field count (the header `header` named), or a field
 * that is not a number (named by `name`). */
static int read_row(const char *program, long row, char *line, char *copy, size_t size, char **fields, int max,
                    int expected, const char *header, double *v, int f32, field_name_fn name, const void *ctx) {
    int n, k;
    if (*trim(line) == '\0') return 0;
    memcpy(copy, line, size);
    n = split(copy, fields, max);
    if (n != expected) {
        fprintf(stderr, "%s: row %ld: fields = %d: expected %d (%s)\n", program, row, n, expected, header);
        return -1;
    }
    for (k = 0; k < expected; k++) {
        const char *why = parse(fields[k], &v[k], f32);
        if (why) {
            const char *field = name(k, ctx);
            if (field) fprintf(stderr, "%s: row %ld: %s = %s: %s\n", program, row, field, fields[k], why);
            else fprintf(stderr, "%s: row %ld: field %d = %s: %s\n", program, row, k + 1, fields[k], why);
            return -1;
        }
    }
    return 1;
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
