/* epw.c - EnergyPlus weather files (see the header). */
#include "daylight/epw.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "base/file_bytes.h"

/* Largest weather file read: a year of 35-field lines is about 1.3 MB. */
#define EPW_MAX_BYTES (64u * 1024u * 1024u)

/* Fields a data line must reach (the diffuse horizontal illuminance). */
#define EPW_FIELDS_NEEDED CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_ILLUMINANCE
#define EPW_MAX_FIELDS 40

/* The data dictionary's "missing" values. */
#define EPW_MISSING_DEW_POINT 99.9
#define EPW_MISSING_IRRADIANCE 9999.0
#define EPW_MISSING_ILLUMINANCE 999999.0

/* One line cut into fields (pointers into a copy of the line). */
typedef struct epw_line {
    char buf[1024];
    const char *field[EPW_MAX_FIELDS];
    int count;
    int number;          /* 1-based line number */
    int truncated;       /* longer than buf */
} epw_line;

/* The next line of `text` from *at into *line (CR and LF dropped); 0 at the end. */
static int next_line(const char **at, epw_line *line)
{
    const char *p = *at;
    if (!*p) return 0;
    size_t n = strcspn(p, "\n");
    const char *next = p[n] ? p + n + 1 : p + n;
    if (n > 0 && p[n - 1] == '\r') --n;
    line->truncated = n >= sizeof line->buf;
    if (line->truncated) n = sizeof line->buf - 1;
    memcpy(line->buf, p, n);
    line->buf[n] = '\0';
    line->count = 0;
    char *s = line->buf;
    for (;;) {
        if (line->count < EPW_MAX_FIELDS) line->field[line->count++] = s;
        char *comma = strchr(s, ',');
        if (!comma) break;
        *comma = '\0';
        s = comma + 1;
    }
    line->number++;
    *at = next;
    return 1;
}

/* Field k (1-based) as a number; 0 and the message when it is not one. */
static int field_number(const epw_line *line, int k, const char *what, const char *path, double *out, cdl_error *err)
{
    const char *s = line->field[k - 1];
    char *end = NULL;
    double v = strtod(s, &end);
    while (end && (*end == ' ' || *end == '\t')) ++end;
    if (!end || end == s || *end || !isfinite(v)) {
        cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: field %d (%s): expected a number, found '%s'", path, line->number,
                      k, what, s);
        return 0;
    }
    *out = v;
    return 1;
}

/* Field k as an integer in [lo, hi]. */
static int field_int(const epw_line *line, int k, const char *what, int lo, int hi, const char *path, int *out,
                     cdl_error *err)
{
    double v;
    if (!field_number(line, k, what, path, &v, err)) return 0;
    if (v != floor(v) || v < lo || v > hi) {
        cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: field %d (%s): expected an integer in [%d, %d], found '%s'", path,
                      line->number, k, what, lo, hi, line->field[k - 1]);
        return 0;
    }
    *out = (int)v;
    return 1;
}

/* The LOCATION line: the site. */
static cdl_status read_location(const epw_line *line, const char *path, cdl_epw *out, cdl_error *err)
{
    if (line->count < 10 || strcmp(line->field[0], "LOCATION") != 0)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:%d: expected the EPW header line "
                             "'LOCATION,City,State,Country,Source,WMO,Latitude,Longitude,TimeZone,Elevation'",
                             path, line->number);
    snprintf(out->city, sizeof out->city, "%s", line->field[1]);
    snprintf(out->country, sizeof out->country, "%s", line->field[3]);
    static const struct {
        int field;
        const char *what;
        double lo, hi;
        size_t offset;
    } site[] = {{7, "latitude, degrees north", -90.0, 90.0, offsetof(cdl_epw, latitude_deg)},
                {8, "longitude, degrees east", -180.0, 180.0, offsetof(cdl_epw, longitude_deg)},
                {9, "time zone, hours from UTC", -12.0, 14.0, offsetof(cdl_epw, time_zone_h)},
                {10, "elevation, m", -1000.0, 9999.0, offsetof(cdl_epw, elevation_m)}};
    for (size_t i = 0; i < sizeof site / sizeof site[0]; ++i) {
        double v;
        if (!field_number(line, site[i].field, site[i].what, path, &v, err)) return CDL_ERR_INPUT;
        if (v < site[i].lo || v > site[i].hi)
            return cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: field %d (%s): expected a number in [%g, %g], found %g",
                                 path, line->number, site[i].field, site[i].what, site[i].lo, site[i].hi, v);
        *(double *)((char *)out + site[i].offset) = v;
    }
    return CDL_OK;
}

static int is_leap(int year)
{
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

/* Days of a month; February 29 days (the row count decides the year). */
static int month_days(int month)
{
    static const int days[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return days[month - 1];
}

/* Is (m, d, h) the hour after (pm, pd, ph)? (The first row: 1 January hour 1.) */
static int follows(int pm, int pd, int ph, int m, int d, int h)
{
    if (pm == 0) return m == 1 && d == 1 && h == 1;
    if (ph < 24) return m == pm && d == pd && h == ph + 1;
    if (h != 1) return 0;
    if (pm == 2 && pd == 28) return m == 2 ? d == 29 : m == 3 && d == 1;
    if (pd < month_days(pm)) return m == pm && d == pd + 1;
    return m == pm + 1 && d == 1;
}

/* A radiation or illuminance field: NAN when it holds the missing value. */
static int field_weather(const epw_line *line, int k, const char *what, double missing, const char *path,
                         double *out, cdl_error *err)
{
    if (!field_number(line, k, what, path, out, err)) return 0;
    if (*out >= missing) *out = NAN;
    return 1;
}

/* One data line into *row; `prev` is the row before (NULL for the first). */
static cdl_status read_row(const epw_line *line, const char *path, const cdl_epw_hour *prev, cdl_epw_hour *row,
                           cdl_error *err)
{
    if (line->count < EPW_FIELDS_NEEDED)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: expected at least %d comma-separated fields, found %d", path,
                             line->number, EPW_FIELDS_NEEDED, line->count);
    row->line = line->number;
    if (!field_int(line, CDL_EPW_FIELD_YEAR, "year", -9999, 9999, path, &row->year, err) ||
        !field_int(line, CDL_EPW_FIELD_MONTH, "month", 1, 12, path, &row->month, err) ||
        !field_int(line, CDL_EPW_FIELD_DAY, "day", 1, month_days(row->month), path, &row->day, err) ||
        !field_int(line, CDL_EPW_FIELD_HOUR, "hour", 1, 24, path, &row->hour, err))
        return CDL_ERR_INPUT;
    if (!follows(prev ? prev->month : 0, prev ? prev->day : 0, prev ? prev->hour : 0, row->month, row->day,
                 row->hour)) {
        if (!prev)
            return cdl_error_set(err, CDL_ERR_INPUT,
                                 "%s:%d: expected the first hour of the year (month 1, day 1, hour 1), found month %d, "
                                 "day %d, hour %d",
                                 path, line->number, row->month, row->day, row->hour);
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "%s:%d: expected the hour after month %d, day %d, hour %d, found month %d, day %d, hour %d",
                             path, line->number, prev->month, prev->day, prev->hour, row->month, row->day, row->hour);
    }
    if (!field_weather(line, CDL_EPW_FIELD_DEW_POINT, "dew point, C", EPW_MISSING_DEW_POINT, path, &row->dew_point_c,
                       err) ||
        !field_weather(line, CDL_EPW_FIELD_GLOBAL_HORIZONTAL_IRRADIANCE, "global horizontal irradiance, W h/m2",
                       EPW_MISSING_IRRADIANCE, path, &row->global_horizontal_w_m2, err) ||
        !field_weather(line, CDL_EPW_FIELD_DIRECT_NORMAL_IRRADIANCE, "direct normal irradiance, W h/m2",
                       EPW_MISSING_IRRADIANCE, path, &row->direct_normal_w_m2, err) ||
        !field_weather(line, CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_IRRADIANCE, "diffuse horizontal irradiance, W h/m2",
                       EPW_MISSING_IRRADIANCE, path, &row->diffuse_horizontal_w_m2, err) ||
        !field_weather(line, CDL_EPW_FIELD_GLOBAL_HORIZONTAL_ILLUMINANCE, "global horizontal illuminance, lx",
                       EPW_MISSING_ILLUMINANCE, path, &row->global_horizontal_lx, err) ||
        !field_weather(line, CDL_EPW_FIELD_DIRECT_NORMAL_ILLUMINANCE, "direct normal illuminance, lx",
                       EPW_MISSING_ILLUMINANCE, path, &row->direct_normal_lx, err) ||
        !field_weather(line, CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_ILLUMINANCE, "diffuse horizontal illuminance, lx",
                       EPW_MISSING_ILLUMINANCE, path, &row->diffuse_horizontal_lx, err))
        return CDL_ERR_INPUT;
    /* the two the skies are made from: present and not negative */
    static const struct {
        int field;
        const char *what;
        size_t offset;
    } needed[] = {
        {CDL_EPW_FIELD_DIRECT_NORMAL_IRRADIANCE, "direct normal irradiance", offsetof(cdl_epw_hour, direct_normal_w_m2)},
        {CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_IRRADIANCE, "diffuse horizontal irradiance",
         offsetof(cdl_epw_hour, diffuse_horizontal_w_m2)}};
    for (size_t i = 0; i < sizeof needed / sizeof needed[0]; ++i) {
        double v = *(const double *)((const char *)row + needed[i].offset);
        if (!(v >= 0.0))
            return cdl_error_set(err, CDL_ERR_INPUT, "%s:%d: field %d (%s, W h/m2): expected a value >= 0, found '%s'%s",
                                 path, line->number, needed[i].field, needed[i].what, line->field[needed[i].field - 1],
                                 isnan(v) ? " (the file's mark of a missing value)" : "");
    }
    return CDL_OK;
}

/* The year the sun is placed in (the header's `year`). */
static void choose_year(cdl_epw *out)
{
    int one = out->hours[0].year;
    for (size_t i = 1; i < out->count && one; ++i)
        if (out->hours[i].year != one) one = 0;
    int leap = out->count == CDL_EPW_HOURS_LEAP;
    out->year_from_file = one > 0 && is_leap(one) == leap;
    out->year = out->year_from_file ? one : leap ? 2020 : 2019;
}

/* Skip the header lines up to and with DATA PERIODS; 0 and the message when none. */
static int skip_header(const char **at, epw_line *line, const char *path, cdl_error *err)
{
    while (next_line(at, line))
        if (strcmp(line->field[0], "DATA PERIODS") == 0) return 1;
    cdl_error_set(err, CDL_ERR_INPUT, "%s: expected the EPW header line 'DATA PERIODS,...' before the hourly data", path);
    return 0;
}

cdl_status cdl_epw_parse(const char *text, const char *path, cdl_epw *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    const char *at = text;
    epw_line *line = malloc(sizeof *line);
    out->hours = malloc(CDL_EPW_HOURS_LEAP * sizeof *out->hours);
    if (!line || !out->hours) {
        free(line);
        cdl_epw_release(out);
        return cdl_error_out_of_memory(err);
    }
    line->number = 0;
    cdl_status st = CDL_OK;
    if (!next_line(&at, line)) st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected an EPW weather file, found it empty", path);
    if (st == CDL_OK) st = read_location(line, path, out, err);
    if (st == CDL_OK && !skip_header(&at, line, path, err)) st = CDL_ERR_INPUT;
    size_t rows = 0;
    while (st == CDL_OK && next_line(&at, line)) {
        if (line->count == 1 && line->field[0][0] == '\0') continue; /* a blank line (the last one) */
        if (rows == CDL_EPW_HOURS_LEAP) {
            /* count the rest for the message */
            size_t more = 1;
            while (next_line(&at, line))
                if (!(line->count == 1 && line->field[0][0] == '\0')) ++more;
            st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected %d or %d hourly rows (a year), found %zu", path,
                               CDL_EPW_HOURS, CDL_EPW_HOURS_LEAP, rows + more);
            break;
        }
        st = read_row(line, path, rows ? &out->hours[rows - 1] : NULL, &out->hours[rows], err);
        if (st == CDL_OK) rows++;
    }
    if (st == CDL_OK && rows != CDL_EPW_HOURS && rows != CDL_EPW_HOURS_LEAP)
        st = cdl_error_set(err, CDL_ERR_INPUT, "%s: expected %d or %d hourly rows (a year), found %zu", path,
                           CDL_EPW_HOURS, CDL_EPW_HOURS_LEAP, rows);
    /* the year ends on 31 December, hour 24 (8760 rows holding 29 February
     * end a day early: follows() lets either through) */
    if (st == CDL_OK) {
        const cdl_epw_hour *last = &out->hours[rows - 1];
        if (last->month != 12 || last->day != 31 || last->hour != 24)
            st = cdl_error_set(err, CDL_ERR_INPUT,
                               "%s:%d: expected the year's last hour (month 12, day 31, hour 24) on the last of %zu "
                               "rows, found month %d, day %d, hour %d",
                               path, last->line, rows, last->month, last->day, last->hour);
    }
    free(line);
    if (st != CDL_OK) {
        cdl_epw_release(out);
        return st;
    }
    out->count = rows;
    for (size_t i = 0; i < rows; ++i) out->dew_point_missing += isnan(out->hours[i].dew_point_c);
    choose_year(out);
    return CDL_OK;
}

cdl_status cdl_epw_read(const char *path, cdl_epw *out, cdl_error *err)
{
    memset(out, 0, sizeof *out);
    char *text = NULL;
    size_t size = 0;
    cdl_status st = cdl_file_read_bytes(path, "weather file", EPW_MAX_BYTES, &text, &size, err);
    if (st != CDL_OK) return st;
    if (strlen(text) != size) {
        free(text);
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected an EPW weather file (text), found a NUL byte", path);
    }
    st = cdl_epw_parse(text, path, out, err);
    free(text);
    return st;
}

void cdl_epw_release(cdl_epw *epw)
{
    if (!epw) return;
    free(epw->hours);
    memset(epw, 0, sizeof *epw);
}
