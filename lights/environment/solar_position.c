/* solar_position.c - the NREL Solar Position Algorithm (Reda and Andreas 2004).
 *
 * Equation numbers (3.x.y) are the sections of NREL/TP-560-34302 (revised
 * 2008); the periodic terms are in solar_position_terms.h. The steps:
 *   1. Julian day of the UT instant, Julian ephemeris day JDE = JD + Delta T
 *      / 86400, and the centuries JC, JCE and millennium JME from J2000.0;
 *   2. the Earth's heliocentric longitude L, latitude B and radius R
 *      (VSOP87 series in JME), the geocentric longitude Theta = L + 180 and
 *      latitude beta = -B;
 *   3. nutation in longitude and obliquity (IAU 1980, 63 terms), the true
 *      obliquity of the ecliptic, the aberration correction, the apparent
 *      longitude lambda;
 *   4. the apparent sidereal time at Greenwich, the geocentric right
 *      ascension alpha and declination delta;
 *   5. the observer's local hour angle, the parallax of the sun for the
 *      observer's place (topocentric alpha', delta', H');
 *   6. the topocentric elevation, refraction (Bennett's formula scaled by
 *      pressure and temperature), zenith and azimuth angles;
 *   7. the equation of time from the sun's mean longitude (A.1).
 */
#include "lights/environment/solar_position.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error_report.h"
#include "lights/environment/solar_position_terms.h"
#include "radiometry/constants.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* The SPA's sun radius and the refraction at the horizon, degrees (3.14):
 * the refraction correction applies while the sun's upper limb is above
 * the refracted horizon, e0 >= -(0.26667 + 0.5667). */
#define SPA_SUN_RADIUS_DEG 0.26667
#define SPA_HORIZON_REFRACTION_DEG 0.5667

static double deg(double rad) { return rad * CDL_RAD_TO_DEG; }
static double rad(double deg_) { return deg_ * CDL_DEG_TO_RAD; }

/* x reduced to [0, 360). */
static double limit_degrees(double x)
{
    double r = fmod(x, 360.0);
    return r < 0.0 ? r + 360.0 : r;
}

/* ---- time ------------------------------------------------------------------------ */

/* Leap years: the Gregorian rule from 1583, the Julian before (as the SPA's
 * Julian day). */
static int is_leap(int y)
{
    if (y < 1583) return y % 4 == 0;
    return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

static int days_in_month(int year, int month)
{
    static const int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month == 2) return is_leap(year) ? 29 : 28;
    return days[month - 1];
}

/* Read exactly `digits` decimal digits. */
static int read_digits(const char **s, int digits, int *out)
{
    int v = 0;
    for (int i = 0; i < digits; ++i) {
        if (!isdigit((unsigned char)(*s)[i])) return 0;
        v = 10 * v + ((*s)[i] - '0');
    }
    *s += digits;
    *out = v;
    return 1;
}

static cdl_status time_fail(cdl_error *err, const char *text, const char *expected)
{
    return cdl_error_set(err, CDL_ERR_INPUT, "'%s': expected %s", text, expected);
}

/* The UTC offset after the time: Z, +hh, +hh:mm or +hhmm (or -). */
static cdl_status parse_offset(const char *text, const char *s, int *offset_min, cdl_error *err)
{
    if (*s == '\0')
        return time_fail(err, text, "a UTC offset (Z, +hh:mm or -hh:mm) after the time, found none: a local time "
                                    "without its offset names no instant");
    if ((*s == 'Z' || *s == 'z') && s[1] == '\0') {
        *offset_min = 0;
        return CDL_OK;
    }
    if (*s != '+' && *s != '-') return time_fail(err, text, "a UTC offset (Z, +hh:mm or -hh:mm) after the time");
    int sign = *s == '-' ? -1 : 1, hh = 0, mm = 0;
    ++s;
    if (!read_digits(&s, 2, &hh)) return time_fail(err, text, "two digits of hours in the UTC offset");
    if (*s == ':') ++s;
    if (*s != '\0' && !read_digits(&s, 2, &mm)) return time_fail(err, text, "two digits of minutes in the UTC offset");
    if (*s != '\0') return time_fail(err, text, "nothing after the UTC offset");
    if (hh > 18 || mm > 59 || hh * 60 + mm > 18 * 60)
        return time_fail(err, text, "a UTC offset within +-18:00");
    *offset_min = sign * (60 * hh + mm);
    return CDL_OK;
}

cdl_status cdl_civil_time_parse(const char *text, cdl_civil_time *out, cdl_error *err)
{
    if (!text) return cdl_error_set(err, CDL_ERR_INPUT, "expected an ISO 8601 time, found nothing");
    const char *s = text;
    cdl_civil_time t;
    memset(&t, 0, sizeof t);
    int sign = 1;
    if (*s == '-' || *s == '+') {
        sign = *s == '-' ? -1 : 1;
        ++s;
    }
    if (!read_digits(&s, 4, &t.year) || *s++ != '-' || !read_digits(&s, 2, &t.month) || *s++ != '-' ||
        !read_digits(&s, 2, &t.day))
        return time_fail(err, text, "an ISO 8601 date and time, YYYY-MM-DDThh:mm:ss+hh:mm");
    t.year *= sign;
    if (*s != 'T' && *s != 't' && *s != ' ')
        return time_fail(err, text, "a time after the date (YYYY-MM-DDThh:mm:ss+hh:mm)");
    ++s;
    if (!read_digits(&s, 2, &t.hour) || *s++ != ':' || !read_digits(&s, 2, &t.minute))
        return time_fail(err, text, "hh:mm after the T");
    if (*s == ':') {
        ++s;
        int whole = 0;
        if (!read_digits(&s, 2, &whole)) return time_fail(err, text, "two digits of seconds after hh:mm:");
        t.second = whole;
        if (*s == '.' || *s == ',') {
            ++s;
            double scale = 0.1;
            if (!isdigit((unsigned char)*s)) return time_fail(err, text, "digits after the decimal point");
            while (isdigit((unsigned char)*s)) {
                t.second += scale * (*s - '0');
                scale *= 0.1;
                ++s;
            }
        }
    }
    cdl_status st = parse_offset(text, s, &t.utc_offset_min, err);
    if (st != CDL_OK) return st;
    if (t.month < 1 || t.month > 12) return time_fail(err, text, "a month 01..12");
    if (t.day < 1 || t.day > days_in_month(t.year, t.month)) return time_fail(err, text, "a day that month has");
    if (t.hour > 24 || (t.hour == 24 && (t.minute != 0 || t.second != 0.0)))
        return time_fail(err, text, "an hour 00..23 (or 24:00:00)");
    if (t.minute > 59) return time_fail(err, text, "minutes 00..59");
    if (!(t.second < 61.0)) return time_fail(err, text, "seconds below 61 (60 for a leap second)");
    *out = t;
    return CDL_OK;
}

double cdl_solar_delta_t_estimate(double y)
{
    /* Espenak and Meeus (NASA/TP-2006-214141, 2.6), the polynomials from
     * 1900 on; the long-term parabola -20 + 32 u^2 elsewhere. */
    double t;
    if (y < 1900.0 || y >= 2150.0) {
        double u = (y - 1820.0) / 100.0;
        return -20.0 + 32.0 * u * u;
    }
    if (y < 1920.0) {
        t = y - 1900.0;
        return -2.79 + t * (1.494119 + t * (-0.0598939 + t * (0.0061966 - 0.000197 * t)));
    }
    if (y < 1941.0) {
        t = y - 1920.0;
        return 21.20 + t * (0.84493 + t * (-0.076100 + 0.0020936 * t));
    }
    if (y < 1961.0) {
        t = y - 1950.0;
        return 29.07 + 0.407 * t - t * t / 233.0 + t * t * t / 2547.0;
    }
    if (y < 1986.0) {
        t = y - 1975.0;
        return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
    }
    if (y < 2005.0) {
        t = y - 2000.0;
        return 63.86 + t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + 0.00002373599 * t))));
    }
    if (y < 2050.0) {
        t = y - 2000.0;
        return 62.92 + 0.32217 * t + 0.005589 * t * t;
    }
    double u = (y - 1820.0) / 100.0;
    return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - y);
}

/* Julian day of a UT instant (3.1.1, after Meeus chapter 7): the Julian
 * calendar before 1582-10-15, the Gregorian from then on. `day` carries
 * the fraction of the day. */
static double julian_day(int year, int month, double day)
{
    int y = year, m = month;
    if (m < 3) {
        y -= 1;
        m += 12;
    }
    double jd = floor(365.25 * (y + 4716.0)) + floor(30.6001 * (m + 1)) + day - 1524.5;
    if (jd > 2299160.0) {
        double a = floor(y / 100.0);
        jd += 2.0 - a + floor(a / 4.0);
    }
    return jd;
}

/* ---- the sun -------------------------------------------------------------------------- */

/* sum of A cos(B + C x) over a series of terms */
static double series(const spa_term *t, size_t n, double x)
{
    double s = 0.0;
    for (size_t i = 0; i < n; ++i) s += t[i].a * cos(t[i].b + t[i].c * x);
    return s;
}

/* (S0 + S1 x + S2 x^2 + ...) / 1e8 by Horner's rule (3.2.1-3.2.6). */
static double power_series(const double *s, int count, double x)
{
    double v = 0.0;
    for (int i = count - 1; i >= 0; --i) v = v * x + s[i];
    return v / 1e8;
}

/* Nutation in longitude and obliquity, degrees (3.4). */
static void nutation(double jce, double *dpsi, double *deps)
{
    double x[5];
    /* the mean elongation of the moon from the sun, the mean anomalies of
     * the sun and the moon, the moon's argument of latitude and the
     * longitude of its ascending node, degrees (3.4.1-3.4.5) */
    x[0] = 297.85036 + jce * (445267.111480 + jce * (-0.0019142 + jce / 189474.0));
    x[1] = 357.52772 + jce * (35999.050340 + jce * (-0.0001603 - jce / 300000.0));
    x[2] = 134.96298 + jce * (477198.867398 + jce * (0.0086972 + jce / 56250.0));
    x[3] = 93.27191 + jce * (483202.017538 + jce * (-0.0036825 + jce / 327270.0));
    x[4] = 125.04452 + jce * (-1934.136261 + jce * (0.0020708 + jce / 450000.0));
    double sp = 0.0, se = 0.0;
    for (size_t i = 0; i < COUNT(spa_nutation); ++i) {
        const spa_nutation_term *t = &spa_nutation[i];
        double arg = 0.0;
        for (int j = 0; j < 5; ++j) arg += x[j] * t->y[j];
        arg = rad(arg);
        sp += (t->a + t->b * jce) * sin(arg);
        se += (t->c + t->d * jce) * cos(arg);
    }
    /* 0.0001 arcsecond units to degrees */
    *dpsi = sp / 36000000.0;
    *deps = se / 36000000.0;
}

/* Mean obliquity of the ecliptic, arcseconds, U = JME / 10 (3.5.1: Laskar's
 * polynomial as Meeus gives it, eq. 22.3). */
static double mean_obliquity_arcsec(double jme)
{
    static const double c[11] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                 -39.05,    7.12,     27.87, 5.79,    2.45};
    double u = jme / 10.0, v = 0.0;
    for (int i = 10; i >= 0; --i) v = v * u + c[i];
    return v;
}

static cdl_status check_range(cdl_error *err, const char *name, double v, double lo, double hi, const char *unit)
{
    if (isfinite(v) && v >= lo && v <= hi) return CDL_OK;
    return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a number in [%g, %g] %s, found %g", name, lo, hi, unit, v);
}

static cdl_status check_inputs(const cdl_solar_site *s, const cdl_civil_time *t, cdl_error *err)
{
    cdl_status st;
    if ((st = check_range(err, "latitude_deg", s->latitude_deg, -90.0, 90.0, "degrees")) != CDL_OK ||
        (st = check_range(err, "longitude_deg", s->longitude_deg, -180.0, 180.0, "degrees")) != CDL_OK ||
        (st = check_range(err, "elevation_m", s->elevation_m, -6500000.0, 1e7, "m")) != CDL_OK ||
        (st = check_range(err, "pressure_mbar", s->pressure_mbar, 0.0, 5000.0, "mbar")) != CDL_OK ||
        (st = check_range(err, "temperature_c", s->temperature_c, -273.0, 6000.0, "degrees C")) != CDL_OK)
        return st;
    if (!isnan(s->delta_t_s) && (st = check_range(err, "delta_t_s", s->delta_t_s, -8000.0, 8000.0, "s")) != CDL_OK)
        return st;
    if (t->year < -2000 || t->year > 6000)
        return cdl_error_set(err, CDL_ERR_INPUT, "time: expected a year in [-2000, 6000] (the SPA's range), found %d",
                             t->year);
    if (t->month < 1 || t->month > 12 || t->day < 1 || t->day > days_in_month(t->year, t->month) || t->hour < 0 ||
        t->hour > 24 || t->minute < 0 || t->minute > 59 || !(t->second >= 0.0 && t->second < 61.0) ||
        abs(t->utc_offset_min) > 18 * 60)
        return cdl_error_set(err, CDL_ERR_INPUT,
                             "time: expected a valid date and time, found %04d-%02d-%02d %02d:%02d:%g (offset %d min)",
                             t->year, t->month, t->day, t->hour, t->minute, t->second, t->utc_offset_min);
    return CDL_OK;
}

/* The geocentric apparent sun at JD (UT) with Delta T: right ascension,
 * declination, the apparent sidereal time at Greenwich and the distance,
 * and the equation of time (3.1-3.9, A.1). */
typedef struct geocentric_sun {
    double alpha, delta;                  /* degrees */
    double nu;                            /* apparent sidereal time at Greenwich, degrees */
    double L, B, R;                       /* the Earth's heliocentric longitude and latitude (degrees), AU */
    double eot_min;
    double dpsi, deps, epsilon;           /* degrees, for tests of the steps */
} geocentric_sun;

static void geocentric(double jd, double delta_t, geocentric_sun *g)
{
    double jde = jd + delta_t / 86400.0;
    double jc = (jd - 2451545.0) / 36525.0, jce = (jde - 2451545.0) / 36525.0, jme = jce / 10.0;
    /* 3.2: the Earth's heliocentric longitude, latitude and radius */
    double l[6] = {series(spa_L0, COUNT(spa_L0), jme), series(spa_L1, COUNT(spa_L1), jme),
                   series(spa_L2, COUNT(spa_L2), jme), series(spa_L3, COUNT(spa_L3), jme),
                   series(spa_L4, COUNT(spa_L4), jme), series(spa_L5, COUNT(spa_L5), jme)};
    double b[2] = {series(spa_B0, COUNT(spa_B0), jme), series(spa_B1, COUNT(spa_B1), jme)};
    double r[5] = {series(spa_R0, COUNT(spa_R0), jme), series(spa_R1, COUNT(spa_R1), jme),
                   series(spa_R2, COUNT(spa_R2), jme), series(spa_R3, COUNT(spa_R3), jme),
                   series(spa_R4, COUNT(spa_R4), jme)};
    double L = g->L = limit_degrees(deg(power_series(l, 6, jme)));
    double B = g->B = deg(power_series(b, 2, jme));
    g->R = power_series(r, 5, jme);
    /* 3.3: geocentric longitude and latitude */
    double theta = limit_degrees(L + 180.0), beta = -B;
    /* 3.4-3.5: nutation and the true obliquity */
    nutation(jce, &g->dpsi, &g->deps);
    g->epsilon = mean_obliquity_arcsec(jme) / 3600.0 + g->deps;
    /* 3.6-3.7: aberration, -20.4898" / R, and the apparent longitude */
    double lambda = theta + g->dpsi - 20.4898 / (3600.0 * g->R);
    /* 3.8: apparent sidereal time at Greenwich (Meeus eq. 12.4, then the
     * equation of the equinoxes) */
    double nu0 = limit_degrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) + jc * jc * (0.000387933 - jc / 38710000.0));
    double eps = rad(g->epsilon);
    g->nu = nu0 + g->dpsi * cos(eps);
    /* 3.9-3.10: right ascension and declination */
    double lam = rad(lambda), bet = rad(beta);
    g->alpha = limit_degrees(deg(atan2(sin(lam) * cos(eps) - tan(bet) * sin(eps), cos(lam))));
    g->delta = deg(asin(sin(bet) * cos(eps) + cos(bet) * sin(eps) * sin(lam)));
    /* A.1: the equation of time from the sun's mean longitude M (Meeus eq.
     * 28.2), E = M - 0.0057183 - alpha + dpsi cos(epsilon), 4 minutes a degree */
    double M = limit_degrees(280.4664567 +
                             jme * (360007.6982779 + jme * (0.03032028 + jme * (1.0 / 49931.0 + jme * (-1.0 / 15300.0 - jme / 2000000.0)))));
    double E = M - 0.0057183 - g->alpha + g->dpsi * cos(eps);
    E = limit_degrees(E);
    if (E > 180.0) E -= 360.0;
    g->eot_min = 4.0 * E;
}

cdl_status cdl_solar_position_compute(const cdl_solar_site *site, const cdl_civil_time *time,
                                      cdl_solar_position *out, cdl_error *err)
{
    cdl_status st = check_inputs(site, time, err);
    if (st != CDL_OK) return st;
    double day = time->day + (time->hour + (time->minute + time->second / 60.0 - time->utc_offset_min) / 60.0) / 24.0;
    double jd = julian_day(time->year, time->month, day);
    double delta_t = isnan(site->delta_t_s) ? cdl_solar_delta_t_estimate(time->year + (time->month - 0.5) / 12.0)
                                            : site->delta_t_s;
    geocentric_sun g;
    geocentric(jd, delta_t, &g);
    /* 3.11: the observer's local hour angle */
    double H = limit_degrees(g.nu + site->longitude_deg - g.alpha);
    /* 3.12: parallax. xi the sun's equatorial horizontal parallax (8.794"
     * at 1 AU); u, x, y the observer's place on the Earth's ellipsoid
     * (flattening 1 - 0.99664719, equatorial radius 6378140 m). */
    double xi = rad(8.794 / (3600.0 * g.R));
    double phi = rad(site->latitude_deg);
    double u = atan(0.99664719 * tan(phi));
    double x = cos(u) + site->elevation_m / 6378140.0 * cos(phi);
    double y = 0.99664719 * sin(u) + site->elevation_m / 6378140.0 * sin(phi);
    double Hr = rad(H), dr = rad(g.delta);
    double dalpha = atan2(-x * sin(xi) * sin(Hr), cos(dr) - x * sin(xi) * cos(Hr));
    double delta_p = atan2((sin(dr) - y * sin(xi)) * cos(dalpha), cos(dr) - x * sin(xi) * cos(Hr));
    double H_p = Hr - dalpha;
    /* 3.14: topocentric elevation without refraction, then refraction
     * (Bennett 1982 as Meeus eq. 16.4, scaled by P / 1010 and 283 / T) */
    double e0 = deg(asin(sin(phi) * sin(delta_p) + cos(phi) * cos(delta_p) * cos(H_p)));
    double de = 0.0;
    if (e0 >= -(SPA_SUN_RADIUS_DEG + SPA_HORIZON_REFRACTION_DEG))
        de = site->pressure_mbar / 1010.0 * 283.0 / (273.0 + site->temperature_c) * 1.02 /
             (60.0 * tan(rad(e0 + 10.3 / (e0 + 5.11))));
    double e = e0 + de;
    /* 3.15: the topocentric azimuth, astronomers' (westward from south)
     * Gamma, then navigators' (eastward from north) Gamma + 180 */
    double gamma = deg(atan2(sin(H_p), cos(H_p) * sin(phi) - tan(delta_p) * cos(phi)));
    memset(out, 0, sizeof *out);
    out->elevation_deg = e;
    out->zenith_deg = 90.0 - e;
    out->azimuth_deg = limit_degrees(gamma + 180.0);
    out->declination_deg = g.delta;
    out->right_ascension_deg = g.alpha;
    out->topocentric_declination_deg = deg(delta_p);
    out->hour_angle_deg = limit_degrees(deg(H_p));
    out->equation_of_time_min = g.eot_min;
    out->julian_day = jd;
    out->delta_t_s = delta_t;
    out->refraction_deg = de;
    out->heliocentric_longitude_deg = g.L;
    out->heliocentric_latitude_deg = g.B;
    out->earth_sun_distance_au = g.R;
    out->nutation_longitude_deg = g.dpsi;
    out->nutation_obliquity_deg = g.deps;
    out->obliquity_deg = g.epsilon;
    return CDL_OK;
}
