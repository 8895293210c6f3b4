/* solar_position.h - where the sun is, seen from a place on the Earth at a time.
 *
 * The NREL Solar Position Algorithm (SPA): I. Reda and A. Andreas, "Solar
 * Position Algorithm for Solar Radiation Applications", NREL/TP-560-34302,
 * 2003, revised 2008 (Solar Energy 76(5), 577-589, 2004). It follows the
 * Earth's heliocentric longitude, latitude and radius in the truncated
 * VSOP87 series of J. Meeus, "Astronomical Algorithms" (1998), adds
 * nutation, aberration and the observer's parallax, and gives the
 * topocentric zenith and azimuth angles to +-0.0003 degrees for the years
 * -2000 to 6000, refraction by the atmosphere included.
 *
 *   input            meaning                                        unit      default  range
 *   latitude_deg     geodetic latitude, north positive               degree    -        [-90, 90]
 *   longitude_deg    longitude, east positive                        degree    -        [-180, 180]
 *   elevation_m      height above sea level                          m         0        [-6500000, 1e7]
 *   pressure_mbar    mean local air pressure (refraction); 0: none   mbar      1013.25  [0, 5000]
 *   temperature_c    mean local air temperature (refraction)         degree C  12       (-273.15, 6000]
 *   delta_t_s        TT - UT1 (Delta T); NAN: estimated for the year s         NAN      [-8000, 8000]
 *   time             civil date and time with its UTC offset         -         -        years -2000..6000
 *                    (the Julian calendar before 1582-10-15, as the SPA)
 *
 * Outputs (cdl_solar_position): the topocentric zenith angle (90 degrees
 * minus the elevation, refraction included where the sun is above the
 * refracted horizon), the azimuth eastward from north (0 north, 90 east,
 * 180 south), the geocentric apparent declination and right ascension, the
 * equation of time (apparent minus mean solar time) and the Julian day.
 *
 * Delta T, when not given, is estimated from the polynomials of
 * F. Espenak and J. Meeus, "Five Millennium Canon of Solar Eclipses"
 * (NASA/TP-2006-214141), section 2.6, whose error since 1900 is a few
 * seconds; the sun's place moves by about 1.1e-5 degrees per second of
 * Delta T, so its effect is below 1e-4 degrees.
 *
 * Thread safety: pure functions. Errors: CDL_ERR_INPUT naming the input
 * ("latitude_deg: expected a number in [-90, 90], found 95").
 */
#ifndef CANDELA_LIGHTS_ENVIRONMENT_SOLAR_POSITION_H
#define CANDELA_LIGHTS_ENVIRONMENT_SOLAR_POSITION_H

#include "base/error.h"

/* A civil time with its offset from UTC (ISO 8601 with an offset). */
typedef struct cdl_civil_time {
    int year, month, day;                 /* Gregorian calendar (Julian before 1582-10-15); month 1..12 */
    int hour, minute;                     /* 0..24 (24:00:00 only), 0..59 */
    double second;                        /* [0, 61): a leap second may be 60.x */
    int utc_offset_min;                   /* local time minus UTC, minutes, [-18 h, +18 h] */
} cdl_civil_time;

typedef struct cdl_solar_site {
    double latitude_deg, longitude_deg;
    double elevation_m;
    double pressure_mbar;
    double temperature_c;
    double delta_t_s;                     /* NAN: estimated (cdl_solar_delta_t_estimate) */
} cdl_solar_site;
#define CDL_SOLAR_SITE_DEFAULT {0.0, 0.0, 0.0, 1013.25, 12.0, NAN}

typedef struct cdl_solar_position {
    double zenith_deg;                    /* topocentric, refraction included */
    double azimuth_deg;                   /* eastward from north, [0, 360) */
    double elevation_deg;                 /* 90 - zenith_deg */
    double declination_deg;               /* geocentric apparent declination */
    double right_ascension_deg;           /* geocentric apparent right ascension, [0, 360) */
    double topocentric_declination_deg;
    double hour_angle_deg;                /* topocentric local hour angle, [0, 360) */
    double equation_of_time_min;          /* apparent minus mean solar time, minutes */
    double julian_day;                    /* UT */
    double delta_t_s;                     /* the Delta T used */
    double refraction_deg;                /* the refraction added to the elevation (0: none) */
    /* intermediate values, as the SPA report tabulates them for its example */
    double heliocentric_longitude_deg;    /* the Earth's L, [0, 360) */
    double heliocentric_latitude_deg;     /* the Earth's B */
    double earth_sun_distance_au;         /* R */
    double nutation_longitude_deg;        /* Delta psi */
    double nutation_obliquity_deg;        /* Delta epsilon */
    double obliquity_deg;                 /* true obliquity of the ecliptic epsilon */
} cdl_solar_position;

/* Read an ISO 8601 date and time with its UTC offset:
 * YYYY-MM-DDThh:mm[:ss[.fff]] then Z, +hh, +hh:mm or +hhmm (or -); a space
 * may stand for the T. A time without an offset is refused (the sun's
 * place depends on the hour in UTC, and a local time is ambiguous). The
 * message names what was found ("expected a UTC offset (Z, +hh:mm or
 * -hh:mm) after the time, found none"), without any prefix: the caller
 * prefixes the argument or JSON path. */
cdl_status cdl_civil_time_parse(const char *text, cdl_civil_time *out, cdl_error *err);

/* Delta T = TT - UT1 in seconds estimated for a decimal year (Espenak and
 * Meeus 2006, above). */
double cdl_solar_delta_t_estimate(double year);

/* The sun's position at `site` and `time` by the SPA. Checks every input
 * (ranges above), CDL_ERR_INPUT with the field's name otherwise. */
cdl_status cdl_solar_position_compute(const cdl_solar_site *site, const cdl_civil_time *time,
                                      cdl_solar_position *out, cdl_error *err);

#endif
