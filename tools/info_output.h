/* info_output.h - what `candela info` says of one luminaire file: the text
 * summary (info_text.c), the one-line form of a batch (info_text.c) and the
 * JSON object (info_json.c), all from the same figures (info_figures.c).
 *
 * One convention for flux and intensity: the luminaire as it lights a
 * scene, the table times its output factor (the ballast factor), which is
 * what a converted EULUMDAT file (the factor folded into its lamp flux)
 * reads as too; where the factor is not 1, the table's own figures are
 * printed beside them. A radiometric file's figures are in W, W/sr and
 * W/m2/sr, never in lumens or candela.
 */
#ifndef CANDELA_TOOLS_INFO_OUTPUT_H
#define CANDELA_TOOLS_INFO_OUTPUT_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "lights/photometry/photometry.h"
#include "lights/photometry/photometry_metadata.h"

typedef struct cdl_info_figures {
    cdl_photometry_summary s;
    double scale;                                  /* output factor x (radiometric: W/sr per table unit) */
    int classified;                                /* the figures below were computed */
    double direct_ratio[CDL_DIRECT_RATIO_COUNT];
    double flux_code[5];
    int bug_known;                                 /* 0 for radiometric files */
    cdl_bug_rating bug;
} cdl_info_figures;

/* Summary, and with `classify` the direct ratios, CIE flux code and BUG
 * rating. Returns 0 when out of memory. */
int cdl_info_figures_compute(const cdl_photometry *p, int classify, cdl_info_figures *f);

const char *cdl_info_type_letter(cdl_photometric_type type);
void cdl_info_version_text(const cdl_photometry_metadata *m, char *buf, size_t size);

/* Text from files is bytes: valid UTF-8 kept, anything else read as
 * Latin-1. malloc'd, NULL when out of memory. */
char *cdl_info_utf8(const char *s);

/* The summary on stdout. */
void cdl_info_print_text(const char *path, const cdl_photometry *p, const cdl_info_figures *f);

/* One line for a batch: format, flux, efficacy, beam, warnings. */
void cdl_info_print_line(const char *path, const cdl_photometry *p, const cdl_info_figures *f);

/* One JSON object (NULL when out of memory). */
cJSON *cdl_info_json(const char *path, const cdl_photometry *p, const cdl_info_figures *f);

#endif
