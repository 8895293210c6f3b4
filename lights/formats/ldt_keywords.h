/* ldt_keywords.h - EULUMDAT's header fields that LM-63 has no field for,
 * carried through an IES file as user keywords (LM-63 allows keywords
 * beginning with '_'), so that EULUMDAT -> IES -> EULUMDAT gives back the
 * header, and an IES file written by another program still fills what it
 * can. Not public.
 *
 *   [_EULUMDAT_ITYP]     type indicator (line 2)
 *   [_EULUMDAT_ISYM]     symmetry indicator (line 3)
 *   [_EULUMDAT_MC]       number of C-planes listed (line 4; for Isym 1, where the table has one)
 *   [_EULUMDAT_LUMINAIRE] length width height of the luminaire in mm (lines 13-15)
 *   [_EULUMDAT_LUMINOUS_HEIGHTS] luminous heights in the C0, C90, C180, C270 planes in mm (lines 18-21)
 *   [_EULUMDAT_DFF]      stated downward flux fraction in % (line 22)
 *   [_EULUMDAT_LORL]     stated light output ratio in % (line 23)
 *   [_EULUMDAT_TILT]     tilt during measurement in degrees (line 25)
 *   [_EULUMDAT_COLOUR]   colour appearance of lamp set 1 (line 30)
 *   [_EULUMDAT_CRI]      colour rendering of lamp set 1 (line 31)
 *   [_EULUMDAT_LAMPSET]  a further lamp set: count | type | flux lm | colour | rendering | watts
 *   [_EULUMDAT_DR]       the ten stated direct ratios (lines 27-36)
 *   [_EULUMDAT_GAMMA]    first and last gamma angle, when LM-63 cannot end there
 *                        (0..140: IES pads the table with zero intensity to 180)
 *   [_EULUMDAT_FILENAME] the file name (line 11), for the record
 *   [_EULUMDAT_FLUX]     absolute photometry's luminaire flux as line 29 states it
 *                        (the intensities' cd/klm are per 1000 lm of it)
 */
#ifndef CANDELA_LIGHTS_FORMATS_LDT_KEYWORDS_H
#define CANDELA_LIGHTS_FORMATS_LDT_KEYWORDS_H

#include <stddef.h>

#include "lights/photometry/photometry_internal.h"

/* The EULUMDAT header of a photometry: an EULUMDAT file's own fields, or
 * what an IES file's keywords above give (-1 / has_* = 0 where not). */
typedef struct cdl_ldt_header {
    int ityp, isym, mc;
    int has_luminaire, has_heights, has_dff, has_lorl, has_ratios;
    double luminaire_mm[3], heights_mm[4], dff, lorl, tilt, ratios[10];
    int has_gamma;
    double gamma_deg[2]; /* the source's gamma range */
    char colour[64], cri[64];
    size_t extra_sets; /* lamp sets 2.. */
    cdl_photometry_lamp_set sets[CDL_PHOTOMETRY_MAX_LAMP_SETS - 1];
    double absolute_flux; /* the stated luminaire flux of absolute photometry, 0 when none */
} cdl_ldt_header;

void cdl_ldt_header_of(const cdl_photometry *p, cdl_ldt_header *h);

/* Receives one keyword line (key without brackets). */
typedef void (*cdl_keyword_sink)(void *context, const char *key, const char *value);

/* An EULUMDAT photometry's fields as the keywords above. */
void cdl_ldt_header_keywords(const cdl_photometry *p, cdl_keyword_sink sink, void *context);

/* 1 when an IES keyword is one the EULUMDAT writer reads back. */
int cdl_ldt_keyword_is_field(const char *key);

#endif
