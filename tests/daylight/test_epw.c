/* The EPW reader (daylight/epw.h) on synthetic weather files:
 *  - a year read back: the site, 8760 rows in order, each hour's values as
 *    written (a value that encodes its row, month, day and hour), the
 *    file's missing marks read as missing, the year the sun is placed in;
 *  - a leap year of 8784 rows with 29 February;
 *  - every error named by its line and field with what was expected: a
 *    first line that is not LOCATION, a latitude out of range, no DATA
 *    PERIODS line, a field that is not a number, too few fields, a hour out
 *    of order, a missing or negative irradiance, 29 February in 8760 rows,
 *    too few and too many rows (the count said).
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "daylight/epw.h"
#include "daylight/epw_fixture.h"

/* Each hour's values encode where it is: dni = row index, dhi = month * 100 + day,
 * dew point = hour / 10, illuminances from them. */
static void coded(int row, int month, int day, int hour, void *user, epw_fixture_weather *w)
{
    (void)user;
    w->dew_point_c = hour / 10.0;
    w->direct_normal_w_m2 = row;
    w->diffuse_horizontal_w_m2 = month * 100 + day;
    w->global_horizontal_w_m2 = row % 7 == 3 ? 9999 : 0.75 * row; /* every 7th row's missing */
    w->global_horizontal_lx = 110.0 * row;
    w->direct_normal_lx = row % 11 == 5 ? 999999 : 100.0 * row;
    w->diffuse_horizontal_lx = 110.0 * (month * 100 + day);
    if (row == 4000) w->dew_point_c = 99.9;
}

static epw_fixture year_file(int rows, int year)
{
    epw_fixture f = {52.52, 13.4, 1.0, 34.0, rows, year, coded, NULL, 0, NULL};
    return f;
}

static int parse(const epw_fixture *f, cdl_epw *out, cdl_error *err)
{
    char *text = epw_fixture_text(f);
    cdl_status st = cdl_epw_parse(text, "w.epw", out, err);
    free(text);
    return st;
}

static void test_year(void)
{
    epw_fixture f = year_file(8760, 0);
    cdl_epw w;
    cdl_error err;
    CHECK_OK(parse(&f, &w, &err), &err);
    if (!w.hours) return;
    CHECK(w.count == 8760);
    CHECK(strcmp(w.city, "Testville") == 0 && strcmp(w.country, "Nowhere") == 0);
    CHECK(w.latitude_deg == 52.52 && w.longitude_deg == 13.4 && w.time_zone_h == 1.0 && w.elevation_m == 34.0);
    /* a typical year's months come from different years: a reference year */
    CHECK(w.year == 2019 && !w.year_from_file);
    CHECK(w.dew_point_missing == 1 && isnan(w.hours[4000].dew_point_c));
    int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    size_t r = 0;
    int in_order = 1, values = 1;
    for (int m = 1; m <= 12; ++m)
        for (int d = 1; d <= days[m - 1]; ++d)
            for (int h = 1; h <= 24; ++h, ++r) {
                const cdl_epw_hour *x = &w.hours[r];
                in_order &= x->month == m && x->day == d && x->hour == h && x->line == (int)r + 9;
                values &= x->direct_normal_w_m2 == (double)r && x->diffuse_horizontal_w_m2 == m * 100 + d &&
                          (r == 4000 || x->dew_point_c == h / 10.0) && x->diffuse_horizontal_lx == 110.0 * (m * 100 + d) &&
                          x->global_horizontal_lx == 110.0 * (double)r &&
                          (r % 7 == 3 ? isnan(x->global_horizontal_w_m2) : x->global_horizontal_w_m2 == 0.75 * (double)r) &&
                          (r % 11 == 5 ? isnan(x->direct_normal_lx) : x->direct_normal_lx == 100.0 * (double)r);
            }
    CHECK_MSG(in_order, "every row in its place, on its line");
    CHECK_MSG(values, "every value as written, the missing ones NAN");
    cdl_epw_release(&w);

    /* one year throughout, not leap: that year */
    f = year_file(8760, 2003);
    CHECK_OK(parse(&f, &w, &err), &err);
    CHECK(w.year == 2003 && w.year_from_file);
    cdl_epw_release(&w);
    /* a leap year's 8784 rows */
    f = year_file(8784, 2024);
    CHECK_OK(parse(&f, &w, &err), &err);
    CHECK(w.count == 8784 && w.year == 2024 && w.year_from_file);
    if (w.hours) CHECK(w.hours[59 * 24 - 1].month == 2 && w.hours[59 * 24].day == 29 && w.hours[8783].day == 31);
    cdl_epw_release(&w);
    /* 8760 rows labelled with a leap year: the reference year */
    f = year_file(8760, 2024);
    CHECK_OK(parse(&f, &w, &err), &err);
    CHECK(w.year == 2019 && !w.year_from_file);
    cdl_epw_release(&w);
}

/* The file broken as f says is refused, the message holding `expect`. */
static void refused(const char *what, const epw_fixture *f, const char *expect)
{
    cdl_epw w;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = parse(f, &w, &err);
    CHECK_MSG(st == CDL_ERR_INPUT, "%s: status %d", what, (int)st);
    CHECK_MSG(strstr(err.message, expect) != NULL, "%s: expected \"%s\" in: %s", what, expect, err.message);
    CHECK(w.hours == NULL && w.count == 0);
    fprintf(stderr, "%s: %s\n", what, err.message);
}

#define GOOD_ROW "1999,1,1,%d,60,x,15,10,60,101325,500,1300,350,200,300,100,22000,30000,11000,5000"

static void test_errors(void)
{
    epw_fixture f = year_file(8760, 0);
    f.replace_line = 1;
    f.replacement = "PLACE,Testville";
    refused("not LOCATION", &f, "w.epw:1: expected the EPW header line 'LOCATION,City");
    f.replacement = "LOCATION,Testville,TS,Nowhere,x,0,95,13.4,1,34";
    refused("latitude", &f, "w.epw:1: field 7 (latitude, degrees north): expected a number in [-90, 90], found 95");
    f.replacement = "LOCATION,Testville,TS,Nowhere,x,0,52,13.4,one,34";
    refused("time zone", &f, "w.epw:1: field 9 (time zone, hours from UTC): expected a number, found 'one'");
    f.replace_line = 8;
    f.replacement = "COMMENTS 3,";
    refused("no DATA PERIODS", &f, "w.epw: expected the EPW header line 'DATA PERIODS,...'");

    char row[512];
    f.replacement = row;
    f.replace_line = 9 + 30; /* the 31st hour: 2 January, hour 7 */
    snprintf(row, sizeof row, "1999,1,2,7,60,x,15,10,60,101325,500,1300,350,200,3o0,100,22000,30000,11000,5000");
    refused("not a number", &f, "w.epw:39: field 15 (direct normal irradiance, W h/m2): expected a number, found '3o0'");
    snprintf(row, sizeof row, "1999,1,2,7,60,x,15,10,60");
    refused("too few fields", &f, "w.epw:39: expected at least 19 comma-separated fields, found 9");
    snprintf(row, sizeof row, "1999,1,2,8,60,x,15,10,60,101325,500,1300,350,200,300,100,22000,30000,11000,5000");
    refused("out of order", &f, "w.epw:39: expected the hour after month 1, day 2, hour 6, found month 1, day 2, hour 8");
    snprintf(row, sizeof row, "1999,1,2,25,60,x,15,10,60,101325,500,1300,350,200,300,100,22000,30000,11000,5000");
    refused("hour 25", &f, "w.epw:39: field 4 (hour): expected an integer in [1, 24], found '25'");
    snprintf(row, sizeof row, "1999,1,2,7,60,x,15,10,60,101325,500,1300,350,200,9999,100,22000,30000,11000,5000");
    refused("missing irradiance", &f,
            "w.epw:39: field 15 (direct normal irradiance, W h/m2): expected a value >= 0, found '9999' (the file's "
            "mark of a missing value)");
    snprintf(row, sizeof row, "1999,1,2,7,60,x,15,10,60,101325,500,1300,350,200,300,-4,22000,30000,11000,5000");
    refused("negative irradiance", &f,
            "w.epw:39: field 16 (diffuse horizontal irradiance, W h/m2): expected a value >= 0, found '-4'");
    f.replace_line = 9;
    snprintf(row, sizeof row, GOOD_ROW, 2);
    refused("first hour", &f, "w.epw:9: expected the first hour of the year (month 1, day 1, hour 1), found month 1, day 1, hour 2");

    f = year_file(8759, 0);
    refused("a row short", &f, "w.epw: expected 8760 or 8784 hourly rows (a year), found 8759");
    f = year_file(8700, 0);
    refused("short", &f, "w.epw: expected 8760 or 8784 hourly rows (a year), found 8700");
    f = year_file(8784 + 30, 2024);
    refused("long", &f, "w.epw: expected 8760 or 8784 hourly rows (a year), found 8814");
    /* 29 February in a year of 8760 rows: it ends on 30 December */
    f = year_file(8784, 2024);
    char *text = epw_fixture_text(&f);
    /* drop the last 24 lines */
    size_t len = strlen(text);
    for (int k = 0; k < 25; ++k)
        while (len > 0 && text[--len] != '\n') continue;
    text[len + 1] = '\0';
    cdl_epw w;
    cdl_error err;
    CHECK(cdl_epw_parse(text, "w.epw", &w, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "w.epw:8768: expected the year's last hour (month 12, day 31, hour 24) on the last of "
                                  "8760 rows, found month 12, day 30, hour 24"),
              "%s", err.message);
    free(text);

    CHECK(cdl_epw_read(CANDELA_TEST_TMPDIR "/no_such.epw", &w, &err) == CDL_ERR_INPUT);
    CHECK_MSG(strstr(err.message, "no_such.epw") && strstr(err.message, "weather file"), "%s", err.message);
}

int main(void)
{
    test_year();
    test_errors();
    return check_finish();
}
