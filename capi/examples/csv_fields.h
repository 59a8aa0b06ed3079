/*
 * The CSV reading shared by the C twins (wrench_eval.c, rolling_eval.c): one row of
 * comma-separated numbers, as contact_eval reads them. Header-only (static functions).
 */
#ifndef CONTENSOU_CSV_FIELDS_H
#define CONTENSOU_CSV_FIELDS_H

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

#endif
