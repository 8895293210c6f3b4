/* The sun's position by the SPA (solar_position.h):
 *  - the SPA report's worked example (NREL/TP-560-34302, Table A5.1:
 *    Golden, Colorado, 17 October 2003 12:30:30 local time at UTC-7),
 *    every tabulated step to the digits the report prints, the zenith
 *    and azimuth to 1e-4 degrees;
 *  - hourly over a year at three latitudes (60 N, the equator, 35 S) and
 *    two years, against the low-precision formulas of the Astronomical
 *    Almanac (section C, "Sun, low precision": apparent right ascension and
 *    declination to 0.01 degrees between 1950 and 2050), written apart
 *    below, with its own sidereal time (Michalsky, Solar Energy 40(3),
 *    1988, eq. for GMST) and without refraction;
 *  - ISO 8601 times and their errors, out-of-range inputs.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "lights/environment/solar_position.h"
#include "radiometry/constants.h"
#include "radiometry/vec3.h"

static void test_worked_example(void)
{
    cdl_error err;
    cdl_civil_time t;
    CHECK_OK(cdl_civil_time_parse("2003-10-17T12:30:30-07:00", &t, &err), &err);
    cdl_solar_site site = CDL_SOLAR_SITE_DEFAULT;
    site.latitude_deg = 39.742476;
    site.longitude_deg = -105.1786;
    site.elevation_m = 1830.14;
    site.pressure_mbar = 820.0;
    site.temperature_c = 11.0;
    site.delta_t_s = 67.0;
    cdl_solar_position s;
    CHECK_OK(cdl_solar_position_compute(&site, &t, &s, &err), &err);
    /* Table A5.1, each to half a unit of the last digit it prints. */
    CHECK_ABS(s.julian_day, 2452930.312847, 0.5e-6);
    CHECK_ABS(s.heliocentric_longitude_deg, 24.0182616917, 0.5e-10);
    CHECK_ABS(s.heliocentric_latitude_deg, -0.0001011219, 0.5e-10);
    CHECK_ABS(s.earth_sun_distance_au, 0.9965422974, 0.5e-10);
    CHECK_ABS(s.nutation_longitude_deg, -0.00399840, 0.5e-8);
    CHECK_ABS(s.nutation_obliquity_deg, 0.00166657, 0.5e-8);
    CHECK_ABS(s.obliquity_deg, 23.440465, 0.5e-6);
    CHECK_ABS(s.right_ascension_deg, 202.22741, 0.5e-5);
    CHECK_ABS(s.declination_deg, -9.31434, 0.5e-5);
    CHECK_ABS(s.topocentric_declination_deg, -9.316179, 0.5e-6);
    /* H' = H - Delta alpha, with the example's H = 11.105902 (as NREL's
     * spa_tester prints it) and Delta alpha = -0.000369: 11.106271 to the
     * two roundings, a millionth */
    CHECK_ABS(s.hour_angle_deg, 11.105902 + 0.000369, 1e-6);
    CHECK_ABS(s.refraction_deg, 0.016332, 0.5e-6);
    /* The bound, 1e-4 degrees (the report prints 50.11162 and 194.34024). */
    CHECK_ABS(s.zenith_deg, 50.11162, 1e-4);
    CHECK_ABS(s.azimuth_deg, 194.34024, 1e-4);
    CHECK_ABS(s.elevation_deg + s.zenith_deg, 90.0, 1e-12);
    /* The equation of time that day: about +14.6 minutes (the sun ahead of
     * mean time in mid-October; the almanac check below holds it to 0.1
     * minute all year). */
    CHECK(s.equation_of_time_min > 14.0 && s.equation_of_time_min < 15.2);
    /* The same instant written in UTC, and in another offset. */
    cdl_civil_time u;
    cdl_solar_position su;
    CHECK_OK(cdl_civil_time_parse("2003-10-17T19:30:30Z", &u, &err), &err);
    CHECK_OK(cdl_solar_position_compute(&site, &u, &su, &err), &err);
    CHECK_ABS(su.zenith_deg, s.zenith_deg, 1e-9);
    CHECK_OK(cdl_civil_time_parse("2003-10-18 01:00:30+0530", &u, &err), &err);
    CHECK_OK(cdl_solar_position_compute(&site, &u, &su, &err), &err);
    CHECK_ABS(su.azimuth_deg, s.azimuth_deg, 1e-9);
}

/* ---- the Astronomical Almanac's low-precision sun, independently ---------- */

/* Julian day of a UTC instant (Gregorian; Fliegel and Van Flandern's
 * integer day number, CACM 11, 1968), not the SPA's Meeus form. */
static double almanac_julian_day(int y, int m, int d, double hours_utc)
{
    long a = (14 - m) / 12, yy = y + 4800 - a, mm = m + 12 * a - 3;
    long jdn = d + (153 * mm + 2) / 5 + 365 * yy + yy / 4 - yy / 100 + yy / 400 - 32045;
    return (double)jdn - 0.5 + hours_utc / 24.0;
}

typedef struct almanac_sun {
    cdl_vec3 dir;              /* towards the sun: x east, y north, z up */
    double declination_deg;
    double eot_min;
} almanac_sun;

static void almanac(double jd, double lat_deg, double lon_deg, almanac_sun *out)
{
    double n = jd - 2451545.0;
    double L = fmod(280.460 + 0.9856474 * n, 360.0);
    double g = fmod(357.528 + 0.9856003 * n, 360.0) * CDL_DEG_TO_RAD;
    double lambda = (L + 1.915 * sin(g) + 0.020 * sin(2.0 * g)) * CDL_DEG_TO_RAD;
    double eps = (23.439 - 0.0000004 * n) * CDL_DEG_TO_RAD;
    double ra = atan2(cos(eps) * sin(lambda), cos(lambda));
    double dec = asin(sin(eps) * sin(lambda));
    /* Greenwich mean sidereal time, hours: 6.697375 + 0.0657098242 n + UT */
    double ut = fmod(jd + 0.5, 1.0) * 24.0;
    double n0 = n - ut / 24.0;
    double gmst = fmod(6.697375 + 0.0657098242 * n0 + 1.00273790935 * ut, 24.0);
    double ha = (gmst * 15.0 + lon_deg) * CDL_DEG_TO_RAD - ra;
    double phi = lat_deg * CDL_DEG_TO_RAD;
    /* east, north, up components of the direction at hour angle ha */
    out->dir = cdl_vec3_make(-cos(dec) * sin(ha), sin(dec) * cos(phi) - cos(dec) * cos(ha) * sin(phi),
                             sin(dec) * sin(phi) + cos(dec) * cos(ha) * cos(phi));
    out->declination_deg = dec * CDL_RAD_TO_DEG;
    /* mean longitude less right ascension, 4 minutes a degree */
    double e = fmod(L - ra * CDL_RAD_TO_DEG + 720.0, 360.0);
    if (e > 180.0) e -= 360.0;
    out->eot_min = 4.0 * e;
}

static cdl_vec3 spa_direction(const cdl_solar_position *s)
{
    double z = s->zenith_deg * CDL_DEG_TO_RAD, a = s->azimuth_deg * CDL_DEG_TO_RAD;
    return cdl_vec3_make(sin(z) * sin(a), sin(z) * cos(a), cos(z));
}

static void test_year_against_almanac(void)
{
    const double lat[3] = {60.0, 0.0, -35.0}, lon[3] = {10.75, -78.5, 149.1};
    const int years[2] = {2003, 2024};
    double worst_angle = 0.0, worst_dec = 0.0, worst_eot = 0.0;
    int compared = 0;
    for (int yi = 0; yi < 2; ++yi)
        for (int site_i = 0; site_i < 3; ++site_i)
            for (int doy = 0; doy < 365; doy += 3)
                for (int hour = 0; hour < 24; ++hour) {
                    /* the day of the year as a date */
                    int m = 1, d = doy + 1;
                    static const int mdays[12] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
                    while (d > mdays[m - 1] - (m == 2 && years[yi] % 4 != 0)) {
                        d -= mdays[m - 1] - (m == 2 && years[yi] % 4 != 0);
                        ++m;
                    }
                    cdl_civil_time t = {years[yi], m, d, hour, 17, 0.0, 0};
                    cdl_solar_site site = CDL_SOLAR_SITE_DEFAULT;
                    site.latitude_deg = lat[site_i];
                    site.longitude_deg = lon[site_i];
                    site.pressure_mbar = 0.0; /* no refraction: the almanac has none */
                    cdl_solar_position s;
                    cdl_error err;
                    if (cdl_solar_position_compute(&site, &t, &s, &err) != CDL_OK) {
                        CHECK_MSG(0, "%s", err.message);
                        continue;
                    }
                    CHECK(s.refraction_deg == 0.0);
                    almanac_sun a;
                    almanac(almanac_julian_day(years[yi], m, d, hour + 17.0 / 60.0), lat[site_i], lon[site_i], &a);
                    cdl_vec3 w = spa_direction(&s);
                    double c = fmin(1.0, cdl_vec3_dot(w, cdl_vec3_normalize(a.dir)));
                    double angle = acos(c) * CDL_RAD_TO_DEG;
                    worst_angle = fmax(worst_angle, angle);
                    worst_dec = fmax(worst_dec, fabs(s.declination_deg - a.declination_deg));
                    worst_eot = fmax(worst_eot, fabs(s.equation_of_time_min - a.eot_min));
                    ++compared;
                }
    fprintf(stderr, "almanac: %d instants, worst separation %.5f deg, declination %.5f deg, EoT %.4f min\n", compared,
            worst_angle, worst_dec, worst_eot);
    CHECK(compared == 2 * 3 * 122 * 24);
    /* The almanac's right ascension and declination are good to 0.01
     * degrees each (so 0.0141 degrees together at most); its sidereal time
     * to about 0.1 s (0.0004 degrees); the SPA's place is topocentric, off
     * the geocentric one by at most the solar parallax, 8.8" = 0.0024
     * degrees: 0.017 in all, checked to 0.02. */
    CHECK(worst_angle < 0.02);
    /* declination: the almanac's 0.01 degrees */
    CHECK(worst_dec < 0.01);
    /* equation of time: 0.01 degrees of right ascension and of mean
     * longitude are 0.04 minutes each; checked to 0.1 minute */
    CHECK(worst_eot < 0.1);
}

static void test_times(void)
{
    cdl_civil_time t;
    cdl_error err;
    CHECK_OK(cdl_civil_time_parse("2021-06-21T04:05:06.25+02:30", &t, &err), &err);
    CHECK(t.year == 2021 && t.month == 6 && t.day == 21 && t.hour == 4 && t.minute == 5);
    CHECK_ABS(t.second, 6.25, 1e-12);
    CHECK(t.utc_offset_min == 150);
    CHECK_OK(cdl_civil_time_parse("2021-06-21T04:05-03", &t, &err), &err);
    CHECK(t.utc_offset_min == -180 && t.second == 0.0);
    CHECK_OK(cdl_civil_time_parse("2024-02-29T24:00:00Z", &t, &err), &err);
    /* no offset: refused, saying so */
    CHECK(cdl_civil_time_parse("2003-10-17T12:30:30", &t, &err) == CDL_ERR_INPUT);
    CHECK(strstr(err.message, "UTC offset") && strstr(err.message, "found none"));
    const char *bad[] = {"2003-13-01T00:00Z", "2003-02-29T00:00Z", "2003-10-17", "2003-10-17T25:00Z",
                         "2003-10-17T12:60Z", "2003-10-17T12:30:30+19:00", "2003-10-17T12:30:30 CET",
                         "17/10/2003 12:30", "2003-10-17T12:30:30.+01:00", "", "2003-10-17T12:30:30+01:00x"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        CHECK_MSG(cdl_civil_time_parse(bad[i], &t, &err) == CDL_ERR_INPUT, "'%s' accepted", bad[i]);
        CHECK_MSG(strstr(err.message, "expected") != NULL, "'%s': %s", bad[i], err.message);
    }
    /* inputs out of range name the input */
    CHECK_OK(cdl_civil_time_parse("2003-10-17T12:30:30-07:00", &t, &err), &err);
    cdl_solar_site site = CDL_SOLAR_SITE_DEFAULT;
    cdl_solar_position s;
    site.latitude_deg = 91.0;
    CHECK(cdl_solar_position_compute(&site, &t, &s, &err) == CDL_ERR_INPUT && strstr(err.message, "latitude_deg"));
    site.latitude_deg = NAN;
    CHECK(cdl_solar_position_compute(&site, &t, &s, &err) == CDL_ERR_INPUT && strstr(err.message, "latitude_deg"));
    site.latitude_deg = 0.0;
    site.longitude_deg = -181.0;
    CHECK(cdl_solar_position_compute(&site, &t, &s, &err) == CDL_ERR_INPUT && strstr(err.message, "longitude_deg"));
    site.longitude_deg = 0.0;
    site.pressure_mbar = -1.0;
    CHECK(cdl_solar_position_compute(&site, &t, &s, &err) == CDL_ERR_INPUT && strstr(err.message, "pressure_mbar"));
    site.pressure_mbar = 1013.25;
    site.delta_t_s = 1e5;
    CHECK(cdl_solar_position_compute(&site, &t, &s, &err) == CDL_ERR_INPUT && strstr(err.message, "delta_t_s"));
    /* Delta T estimates (Espenak and Meeus): about 64 s in 2003 (measured
     * 64.5 s), 32 s in 1950 (measured 29.1 s): within 4 s */
    CHECK_ABS(cdl_solar_delta_t_estimate(2003.5), 64.5, 4.0);
    CHECK_ABS(cdl_solar_delta_t_estimate(1950.0), 29.1, 4.0);
}

int main(void)
{
    test_worked_example();
    test_year_against_almanac();
    test_times();
    return check_finish();
}
