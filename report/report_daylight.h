/* report_daylight.h - the report of an annual daylight study (`candela
 * annual`'s folder: its summary.json holds "annual").
 *
 * In the order a reviewer reads it: the cover (scene, weather and site,
 * sky model and patches, occupancy, daylight hours, the coefficients' target
 * and seed, the time each step took); the daylight summary, a row per grid
 * (sDA300/50 %, ASE1000,250h, the mean DA300, UDI and its fell-short and
 * exceeded shares, EN 17037's level, the coefficients' stated error); EN
 * 17037's daylight provision per grid and level; the maps NAME.png of each
 * metric written by the study; the method (each metric's definition, how
 * the hours were made, what the stated error holds and what is left out).
 * The numbers are summary.json's, unchanged. Not public.
 */
#ifndef CANDELA_REPORT_DAYLIGHT_H
#define CANDELA_REPORT_DAYLIGHT_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "base/error.h"
#include "report/report_document.h"

/* A picture of the folder, drawn as a figure. */
typedef struct cdl_report_image cdl_report_image;
void cdl_report_images_release(cdl_report_image **images, size_t count);

/* 1 when summary (a folder's summary.json) is an annual study's. */
int cdl_report_is_annual(const cJSON *summary);

/* The document of the annual study in out_dir whose summary.json is
 * `summary` (borrowed); title NULL for "Daylight report: SCENE". */
cdl_status cdl_report_daylight_build(const char *out_dir, const cJSON *summary, const char *title,
                                     cdl_report_document **out, cdl_error *err);

#endif
