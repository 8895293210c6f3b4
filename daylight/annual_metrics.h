/* annual_metrics.h - climate-based daylight metrics from a year of hourly
 * illuminance (not public).
 *
 * Per point, over the occupied hours of the schedule (occupancy.h):
 *   DA300      daylight autonomy: the share of occupied hours with E >= 300 lx
 *              (Reinhart and Walkenhorst, Energy and Buildings 33(7), 2001;
 *              IES LM-83-12, 2.2);
 *   UDI        useful daylight illuminance (Nabil and Mardaljevic, Lighting
 *              Research and Technology 37(1), 2005; the 3000 lx upper bound
 *              of Mardaljevic et al. 2012): the share of occupied hours with
 *              100 <= E <= 3000 lx; "fell short" below 100 lx, "exceeded"
 *              above 3000 lx (the three sum to 100 %);
 *   ASE hours  the occupied hours whose direct sunlight alone (no sky, no
 *              interreflection: LM-83-12, 2.3) is >= 1000 lx;
 *   EN 17037   the share of the daylight hours (below) with E >= 300 lx.
 * Per grid (each point weighted by the area it stands for; 1 each for a
 * points grid):
 *   sDA300/50%      the share of the grid whose DA300 >= 50 % (LM-83-12);
 *   ASE1000,250h    the share of the grid with more than 250 ASE hours;
 *   UDI (and the other two) averaged;
 *   EN 17037:2018 daylight provision (A.3, the hourly method): an hour
 *   counts for a level's target when the share of the grid at or above the
 *   target illuminance E_T is at least 50 %, and for its minimum when the
 *   share at or above E_TM is at least 95 %; the level is met when both
 *   count in at least half of the daylight hours. Levels: minimum (E_T 300,
 *   E_TM 100 lx), medium (500, 300), high (750, 500). The daylight hours
 *   are the half of the year's hours (4380 of 8760) with the greatest
 *   diffuse horizontal illuminance in the weather file (ties in file order),
 *   as the standard's climate-based method reads "daylight hours".
 * All shares are percentages. Exact comparisons on the float values, with
 * the thresholds as written (>= 300 is met by 300 itself).
 *
 * Thread safety: pure.
 */
#ifndef CANDELA_DAYLIGHT_ANNUAL_METRICS_H
#define CANDELA_DAYLIGHT_ANNUAL_METRICS_H

#include <stddef.h>

#include "base/error.h"

#define CDL_DA_LX 300.0
#define CDL_UDI_LOW_LX 100.0
#define CDL_UDI_HIGH_LX 3000.0
#define CDL_ASE_LX 1000.0
#define CDL_ASE_HOURS 250.0
#define CDL_SDA_SHARE 50.0
#define CDL_EN17037_LEVELS 3

/* EN 17037:2018 Table A.1: target and minimum target illuminance per level. */
typedef struct cdl_en17037_level {
    const char *name;                     /* "minimum", "medium", "high" */
    double target_lx, minimum_lx;
} cdl_en17037_level;
extern const cdl_en17037_level cdl_en17037_levels[CDL_EN17037_LEVELS];

/* One year at one grid: E[row * points + i] (lx), the direct sun alone likewise
 * (NULL: no sun, every ASE count 0), and per hour whether it is occupied and
 * whether it is a daylight hour. */
typedef struct cdl_annual_input {
    size_t hours, points;
    const float *E;                       /* rows of `points` values: row_of_hour[h] (or h) for hour h */
    const float *E_sun;
    const int *row_of_hour;               /* per hour its row of E and E_sun, -1 for an hour of 0 lx; NULL: row h */
    const unsigned char *occupied;
    const unsigned char *daylight;
    const double *weights;                /* per point (area), or NULL: 1 each */
} cdl_annual_input;

typedef struct cdl_point_metrics {
    double DA300;                         /* % of occupied hours */
    double UDI_fell_short, UDI, UDI_exceeded; /* % of occupied hours */
    double ASE_hours;                     /* occupied hours */
    double EN17037_target;                /* % of daylight hours with E >= 300 lx */
} cdl_point_metrics;

typedef struct cdl_grid_annual_metrics {
    double sDA300;                        /* % of the grid */
    double ASE1000;                       /* % of the grid */
    double UDI_fell_short, UDI, UDI_exceeded; /* grid means, % */
    double DA300_mean;
    size_t occupied_hours, daylight_hours;
    /* EN 17037: per level, the % of daylight hours that count for its target and for its minimum, and whether met */
    double en_target_hours[CDL_EN17037_LEVELS], en_minimum_hours[CDL_EN17037_LEVELS];
    int en_met[CDL_EN17037_LEVELS];
    const char *en_level;                 /* the highest level met, or "none" */
} cdl_grid_annual_metrics;

/* The metrics of every point (out[points]) and of the grid.
 * CDL_ERR_INPUT when no hour is occupied or no hour is a daylight hour;
 * CDL_ERR_INTERNAL when out of memory. */
cdl_status cdl_annual_metrics_compute(const cdl_annual_input *in, cdl_point_metrics *points,
                                      cdl_grid_annual_metrics *grid, cdl_error *err);

/* The daylight hours: daylight[h] = 1 for the half of the hours (rounded
 * down) with the greatest diffuse_lx[h], ties to the earlier hour. */
cdl_status cdl_annual_daylight_hours(const double *diffuse_lx, size_t hours, unsigned char *daylight,
                                     cdl_error *err);

#endif
