/* epw_fixture.h - synthetic EnergyPlus weather files for the tests (no
 * third-party weather data in the tree).
 *
 * epw_fixture_text writes the eight header lines and one line per hour,
 * the weather of each hour from a callback, in the field layout of the EPW
 * data dictionary (35 fields; those Candela does not read hold plausible
 * constants). A test may replace any one line (1-based, header included)
 * by its own text to break the file where it wants.
 */
#ifndef CANDELA_TESTS_EPW_FIXTURE_H
#define CANDELA_TESTS_EPW_FIXTURE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One hour's weather as the file gives it. */
typedef struct epw_fixture_weather {
    double dew_point_c;
    double global_horizontal_w_m2, direct_normal_w_m2, diffuse_horizontal_w_m2;
    double global_horizontal_lx, direct_normal_lx, diffuse_horizontal_lx;
} epw_fixture_weather;

typedef void (*epw_fixture_fn)(int row, int month, int day, int hour, void *user, epw_fixture_weather *out);

typedef struct epw_fixture {
    double latitude_deg, longitude_deg, time_zone_h, elevation_m;
    int rows;                 /* 8760, 8784 (29 February included), or fewer / more to break the count */
    int year;                 /* every row's year; 0: the years of a typical year, changing by month */
    epw_fixture_fn weather;   /* NULL: a constant overcast-ish hour */
    void *user;
    int replace_line;         /* 0: none */
    const char *replacement;
} epw_fixture;

static inline int epw_fixture_month_days(int month, int leap)
{
    static const int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return days[month - 1] + (month == 2 && leap);
}

/* The file's text (the caller frees it). */
static inline char *epw_fixture_text(const epw_fixture *f)
{
    size_t cap = (size_t)(f->rows + 16) * 256, len = 0;
    char *text = malloc(cap);
    if (!text) return NULL;
    int line = 0;
#define EPW_FIXTURE_LINE(...)                                                                                         \
    do {                                                                                                               \
        ++line;                                                                                                        \
        if (line == f->replace_line)                                                                                   \
            len += (size_t)snprintf(text + len, cap - len, "%s\n", f->replacement);                                    \
        else                                                                                                           \
            len += (size_t)snprintf(text + len, cap - len, __VA_ARGS__);                                               \
    } while (0)
    EPW_FIXTURE_LINE("LOCATION,Testville,TS,Nowhere,Candela test,000000,%.4f,%.4f,%.1f,%.1f\n", f->latitude_deg,
                     f->longitude_deg, f->time_zone_h, f->elevation_m);
    EPW_FIXTURE_LINE("DESIGN CONDITIONS,0\n");
    EPW_FIXTURE_LINE("TYPICAL/EXTREME PERIODS,0\n");
    EPW_FIXTURE_LINE("GROUND TEMPERATURES,0\n");
    EPW_FIXTURE_LINE("HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\n");
    EPW_FIXTURE_LINE("COMMENTS 1,synthetic weather written by Candela's tests\n");
    EPW_FIXTURE_LINE("COMMENTS 2,\n");
    EPW_FIXTURE_LINE("DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31\n");
    int leap = f->rows >= 8784;
    int month = 1, day = 1, hour = 1;
    for (int r = 0; r < f->rows; ++r) {
        epw_fixture_weather w = {10.0, 200.0, 300.0, 100.0, 22000.0, 30000.0, 11000.0};
        if (f->weather) f->weather(r, month, day, hour, f->user, &w);
        int year = f->year ? f->year : 1990 + month;
        EPW_FIXTURE_LINE("%d,%d,%d,%d,60,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9,15.0,%.6g,60,101325,500,1300,"
                         "350,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,5000,180,2.0,5,5,20.0,77777,9,999999999,15,0.1,0,88,0.2,"
                         "0.0,1.0\n",
                         year, month, day, hour, w.dew_point_c, w.global_horizontal_w_m2, w.direct_normal_w_m2,
                         w.diffuse_horizontal_w_m2, w.global_horizontal_lx, w.direct_normal_lx,
                         w.diffuse_horizontal_lx);
        if (++hour > 24) {
            hour = 1;
            if (++day > epw_fixture_month_days(month, leap)) {
                day = 1;
                if (++month > 12) month = 1;
            }
        }
    }
#undef EPW_FIXTURE_LINE
    return text;
}

/* The same written to `path`; 0 on failure. */
static inline int epw_fixture_write(const epw_fixture *f, const char *path)
{
    char *text = epw_fixture_text(f);
    FILE *fp = text ? fopen(path, "w") : NULL;
    int ok = fp && fputs(text, fp) >= 0;
    if (fp) ok &= fclose(fp) == 0;
    free(text);
    return ok;
}

#endif
