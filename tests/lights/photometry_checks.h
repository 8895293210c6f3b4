/* photometry_checks.h - helpers shared by the photometry tests. */
#ifndef CANDELA_TESTS_PHOTOMETRY_CHECKS_H
#define CANDELA_TESTS_PHOTOMETRY_CHECKS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lights/photometry/photometry.h"

/* Read from a string (strict or not); NULL and a message in *err on failure. */
static inline cdl_photometry *pc_read_text(const char *name, const char *text, size_t len, int strict, cdl_error *err)
{
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    o.strict = strict;
    cdl_photometry *p = NULL;
    cdl_error_clear(err);
    cdl_photometry_read_memory(text, len, name, &o, &p, err);
    return p;
}

static inline cdl_photometry *pc_read_file(const char *path, int strict, cdl_error *err)
{
    cdl_photometry_read_options o = CDL_PHOTOMETRY_READ_OPTIONS_INIT;
    o.strict = strict;
    cdl_photometry *p = NULL;
    cdl_error_clear(err);
    cdl_photometry_read_file(path, &o, &p, err);
    return p;
}

/* The text of p written as EULUMDAT (ldt) or LM-63 `version`, line 11 `name`
 * (NULL: the writer's default); NULL and a failed check when the writer fails. */
static inline char *pc_write(const cdl_photometry *p, int ldt, int version, const char *name)
{
    cdl_photometry_write_options o = CDL_PHOTOMETRY_WRITE_OPTIONS_INIT;
    o.ies_version = version;
    o.file_name = name;
    char *text = NULL;
    size_t len;
    cdl_error err;
    cdl_status st = ldt ? cdl_photometry_format_ldt(p, &o, &text, &len, NULL, &err)
                        : cdl_photometry_format_ies(p, &o, &text, &len, NULL, &err);
    CHECK_MSG(st == CDL_OK, "%s: %s", name ? name : "", err.message);
    return text;
}

static inline int pc_has_warning(const cdl_photometry *p, const char *needle)
{
    for (size_t i = 0; i < cdl_photometry_warning_count(p); ++i)
        if (strstr(cdl_photometry_warning(p, i), needle)) return 1;
    return 0;
}

/* Largest |Ia - Ib| over a 2.5 x 2 degree grid of the sphere (frame C, gamma). */
static inline double pc_max_difference(const cdl_photometry *a, const cdl_photometry *b)
{
    double worst = 0.0;
    for (int i = 0; i < 144; ++i)
        for (int j = 0; j <= 90; ++j) {
            double c = 2.5 * i + 0.7, g = 2.0 * j;
            worst = fmax(worst, fabs(cdl_photometry_intensity_c_gamma(a, c, g).cd -
                                     cdl_photometry_intensity_c_gamma(b, c, g).cd));
        }
    return worst;
}

/* Largest |I_b - I_a| at a's stored table nodes. Type C nodes are looked
 * up by (C, gamma), since at nadir and zenith every plane names the same
 * direction while real tables hold a different value per plane; for types
 * A/B the poles of the latitude angle are skipped for the same reason. */
static inline double pc_node_difference(const cdl_photometry *a, const cdl_photometry *b)
{
    cdl_photometry_table t;
    cdl_photometry_get_table(a, &t);
    double worst = 0.0;
    for (size_t i = 0; i < t.horizontal_count; ++i)
        for (size_t j = 0; j < t.vertical_count; ++j) {
            double h = t.horizontal_deg[i], v = t.vertical_deg[j], x = t.candela[i * t.vertical_count + j], y;
            if (t.type == CDL_PHOTOMETRIC_TYPE_C) {
                y = cdl_photometry_intensity_c_gamma(b, h, v).cd;
            } else {
                double lat = t.type == CDL_PHOTOMETRIC_TYPE_B ? h : v;
                if (fabs(lat) == 90.0) continue;
                y = cdl_photometry_intensity(b, cdl_photometry_direction(t.type, h, v)).cd;
            }
            worst = fmax(worst, fabs(y - x));
        }
    return worst;
}

#endif
