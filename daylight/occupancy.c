/* occupancy.c - occupied hours from a daily range or a CSV file (see the header). */
#include "daylight/occupancy.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/file_bytes.h"

/* A schedule file: at most a few values per hour of a leap year. */
#define OCCUPANCY_MAX_BYTES (16u * 1024u * 1024u)

/* "A-B" as two whole hours; 0 when spec is not of that form. */
static int parse_range(const char *spec, int *a, int *b)
{
    char *end = NULL;
    if (!isdigit((unsigned char)spec[0])) return 0;
    long x = strtol(spec, &end, 10);
    if (*end != '-' || !isdigit((unsigned char)end[1])) return 0;
    long y = strtol(end + 1, &end, 10);
    if (*end) return 0;
    *a = x > 99 ? 99 : (int)x;
    *b = y > 99 ? 99 : (int)y;
    return 1;
}

/* The last comma-separated field of a line (trimmed) into *v; 0 when not a number. */
static int last_field(char *line, double *v)
{
    char *f = strrchr(line, ',');
    f = f ? f + 1 : line;
    while (*f == ' ' || *f == '\t') ++f;
    char *end = NULL;
    *v = strtod(f, &end);
    if (end == f) return 0;
    while (*end == ' ' || *end == '\t' || *end == '\r') ++end;
    return *end == '\0';
}

static cdl_status read_file(const char *path, const cdl_epw *epw, unsigned char *occupied, size_t *count,
                            cdl_error *err)
{
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "occupancy file", OCCUPANCY_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    size_t n = 0;
    int line_no = 0;
    for (char *line = text; st == CDL_OK && line && *line;) {
        char *next = strchr(line, '\n');
        if (next) *next++ = '\0';
        ++line_no;
        char *p = line;
        while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
        double v = 0.0;
        if (*p == '\0') {
            /* blank */
        } else if (!last_field(line, &v)) {
            if (line_no != 1)
                st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: expected 0 or 1 (occupied) as the line's last field, "
                                   "found '%.40s'", path, line_no, line);
        } else if (v != 0.0 && v != 1.0) {
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: expected 0 or 1 (occupied), found %g", path, line_no, v);
        } else {
            if (n < epw->count) occupied[n] = v == 1.0;
            ++n;
        }
        line = next;
    }
    free(text);
    if (st == CDL_OK && n != epw->count)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected %zu values (one per hour of the weather file), found %zu",
                           path, epw->count, n);
    *count = n;
    return st;
}

cdl_status cdl_occupancy_read(const char *spec, const cdl_epw *epw, unsigned char *occupied, char *described,
                              size_t described_size, cdl_error *err)
{
    int a, b;
    size_t hours = 0;
    if (parse_range(spec, &a, &b)) {
        if (!(a >= 0 && a < b && b <= 24))
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "occupancy '%s': expected a daily range A-B of whole hours, 0 <= A < B <= 24", spec);
        for (size_t h = 0; h < epw->count; ++h) {
            /* hour h of the file runs from hour - 1 to hour o'clock */
            int end = epw->hours[h].hour;
            occupied[h] = end - 1 >= a && end <= b;
            hours += occupied[h];
        }
        snprintf(described, described_size, "%02d:00-%02d:00 local standard time, every day (%zu hours)", a, b, hours);
        return CDL_OK;
    }
    cdl_status st = read_file(spec, epw, occupied, &hours, err);
    if (st != CDL_OK) return st;
    size_t on = 0;
    for (size_t h = 0; h < epw->count; ++h) on += occupied[h];
    snprintf(described, described_size, "the schedule %s (%zu hours)", spec, on);
    return CDL_OK;
}
