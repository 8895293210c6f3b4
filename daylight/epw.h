/* epw.h - EnergyPlus weather files (EPW): the site and the hourly weather
 * an annual daylight study needs.
 *
 * The format (EnergyPlus "Auxiliary Programs", Weather Converter, "EnergyPlus
 * Weather File (EPW) Data Dictionary"): comma-separated text, eight header
 * lines, then one line per hour of one year, 8760 of them (8784 in a leap
 * year). The first header line is
 *     LOCATION,City,State,Country,Source,WMO,Latitude,Longitude,TimeZone,Elevation
 * latitude north positive, longitude east positive (degrees), the time zone
 * in hours from UTC (standard time, -5 for US Eastern), elevation in metres.
 * The data follow the header line that begins "DATA PERIODS". Each data
 * line holds 35 fields; those read here (numbered from 1):
 *     1 year, 2 month, 3 day, 4 hour (1..24: the hour that ENDS at hour:00
 *     local standard time; daylight saving is never applied), 5 minute,
 *     8 dew point (C; 99.9 missing),
 *     14 global horizontal, 15 direct normal, 16 diffuse horizontal
 *        irradiance (W h/m^2 over the hour = the hour's mean W/m^2; 9999 missing),
 *     17 global horizontal, 18 direct normal, 19 diffuse horizontal
 *        illuminance (lx, the hour's mean; 999999 missing).
 * Irradiances and illuminances are means over the hour, so the sun of hour h
 * is placed at its middle, h - 0.5 (as Radiance's epw2wea writes it).
 *
 * What is refused (CDL_ERR_INPUT, the message naming the file, the line and
 * the field with what was expected): a first line that is not LOCATION, a
 * latitude, longitude, time zone or elevation out of range, no DATA PERIODS
 * line, a data line with fewer than 19 fields or a field that is not a
 * number, a month, day or hour out of range or out of order (each line must
 * be the hour after the one before, from 1 January hour 1), a missing or
 * negative direct normal or diffuse horizontal irradiance, and a row count
 * other than 8760 or 8784 (the message gives the count found). A missing dew
 * point is kept as NAN (the caller picks a default and says so); missing
 * illuminances are NAN.
 *
 * Thread safety: pure; no global state. Ownership: *out's arrays are the
 * caller's, freed by cdl_epw_release.
 */
#ifndef CANDELA_DAYLIGHT_EPW_H
#define CANDELA_DAYLIGHT_EPW_H

#include <stddef.h>

#include "base/error.h"

/* Rows of a year. */
#define CDL_EPW_HOURS 8760
#define CDL_EPW_HOURS_LEAP 8784

/* The fields of a data line used here, numbered from 1 as the data
 * dictionary numbers them. */
#define CDL_EPW_FIELD_YEAR 1
#define CDL_EPW_FIELD_MONTH 2
#define CDL_EPW_FIELD_DAY 3
#define CDL_EPW_FIELD_HOUR 4
#define CDL_EPW_FIELD_DEW_POINT 8
#define CDL_EPW_FIELD_GLOBAL_HORIZONTAL_IRRADIANCE 14
#define CDL_EPW_FIELD_DIRECT_NORMAL_IRRADIANCE 15
#define CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_IRRADIANCE 16
#define CDL_EPW_FIELD_GLOBAL_HORIZONTAL_ILLUMINANCE 17
#define CDL_EPW_FIELD_DIRECT_NORMAL_ILLUMINANCE 18
#define CDL_EPW_FIELD_DIFFUSE_HORIZONTAL_ILLUMINANCE 19

typedef struct cdl_epw_hour {
    int year, month, day, hour;             /* as given; hour 1..24 ends at hour:00 local standard time */
    double dew_point_c;                     /* NAN when missing */
    double global_horizontal_w_m2;          /* NAN when missing */
    double direct_normal_w_m2;              /* >= 0 */
    double diffuse_horizontal_w_m2;         /* >= 0 */
    double global_horizontal_lx, direct_normal_lx, diffuse_horizontal_lx; /* NAN when missing */
    int line;                               /* its line in the file (1-based), for messages */
} cdl_epw_hour;

typedef struct cdl_epw {
    char city[64], country[16];             /* LOCATION fields 2 and 4 (truncated) */
    double latitude_deg;                    /* [-90, 90], north positive */
    double longitude_deg;                   /* [-180, 180], east positive */
    double time_zone_h;                     /* [-12, 14], hours from UTC (standard time) */
    double elevation_m;                     /* [-1000, 9999] */
    cdl_epw_hour *hours;                    /* count rows, 1 January hour 1 first */
    size_t count;                           /* CDL_EPW_HOURS or CDL_EPW_HOURS_LEAP */
    int year;                               /* the year the sun is placed in: the rows' own when
                                             * they all give one that fits the count, else 2019
                                             * (8760 rows) or 2020 (8784) */
    int year_from_file;                     /* 1: that year is the rows' own */
    size_t dew_point_missing;               /* rows without a dew point */
} cdl_epw;

/* Read the EPW file at `path` (whole, at most 64 MB). */
cdl_status cdl_epw_read(const char *path, cdl_epw *out, cdl_error *err);

/* The same from text (NUL-terminated); `path` names it in messages. */
cdl_status cdl_epw_parse(const char *text, const char *path, cdl_epw *out, cdl_error *err);

/* Free what *epw holds and zero it (a zeroed one is fine). */
void cdl_epw_release(cdl_epw *epw);

#endif
