/* photometry_metadata.h - everything a photometric file says besides its table (not public).
 *
 * The public header gives accessors for what a program needs (format,
 * watts, ballast factor, opening, lamp sets, keywords); the readers,
 * writers, checks, the report and the `candela info` command read the
 * whole record and the whole summary.
 */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_METADATA_H
#define CANDELA_LIGHTS_PHOTOMETRY_PHOTOMETRY_METADATA_H

#include <stddef.h>

#include "lights/photometry/photometry.h"

typedef struct cdl_photometry_keyword {
    char *key;          /* without brackets, e.g. "MANUFAC", "_ABSOLUTELUMENS"; "" for free text */
    char *value;        /* [MORE] continuations joined with '\n' */
    unsigned line;      /* line of the file where the keyword starts; 0 when not read from a file */
} cdl_photometry_keyword;

typedef enum cdl_tilt_kind { CDL_TILT_NONE = 0, CDL_TILT_INCLUDE, CDL_TILT_FILE } cdl_tilt_kind;

#define CDL_PHOTOMETRY_MAX_LAMP_SETS 20

typedef struct cdl_photometry_metadata {
    cdl_photometry_format format;
    int ies_version;              /* 1986, 1991, 1995, 2002 or 2019; 0 when not IES */
    char version_tag[64];         /* IES line 1 as found (trimmed); "" for 1986 */
    size_t file_horizontal_count; /* as written: IES horizontal angles (with a closing 360) or EULUMDAT Mc */
    size_t file_vertical_count;   /* as written: IES vertical angles or EULUMDAT Ng */
    int absolute;                 /* 1: absolute photometry, no lamp reference */
    double rated_lamp_flux_lm;    /* lamps x lumens (IES) or lamp set 1 (EULUMDAT); 0 if absolute */
    double candela_multiplier;    /* IES multiplier or EULUMDAT conversion factor, as found (applied) */
    double ballast_factor;        /* 1 when the format has none */
    double ballast_lamp_factor;   /* LM-63-1995 and older record B field 2; 1 otherwise */
    double file_generation_type;  /* LM-63-2019 record B field 2 (a code, not a factor); 0 otherwise */
    double input_watts;           /* 0 when unknown */
    size_t lamp_set_count;
    cdl_photometry_lamp_set lamp_sets[CDL_PHOTOMETRY_MAX_LAMP_SETS];
    cdl_luminous_opening opening;
    size_t keyword_count;
    cdl_photometry_keyword *keywords;
    /* tilt */
    cdl_tilt_kind tilt_kind;
    char tilt_file[256];          /* TILT=<file> as written */
    int tilt_geometry;            /* 1, 2 or 3 (LM-63 lamp-to-luminaire geometry); 0 without tilt */
    size_t tilt_count;
    const double *tilt_angles_deg;
    const double *tilt_factors;
    /* EULUMDAT fields (0 / "" when not from EULUMDAT) */
    int ldt_ityp;                  /* type indicator 0..3 */
    int ldt_isym;                  /* symmetry indicator 0..4 as found */
    char ldt_company[128];
    char ldt_report[128];          /* measurement report number */
    char ldt_luminaire_name[128];
    char ldt_luminaire_number[128];
    char ldt_file_name[128];
    char ldt_date_user[128];
    double ldt_luminaire_mm[3];    /* length/diameter, width (0 = round), height */
    double ldt_luminous_mm[2];     /* luminous length/diameter, width (0 = round) */
    double ldt_luminous_height_mm[4]; /* in the C0, C90, C180, C270 planes */
    double ldt_dff_percent;        /* downward flux fraction as stated */
    double ldt_lorl_percent;       /* light output ratio as stated */
    double ldt_measurement_tilt_deg;
    double ldt_direct_ratios[10];  /* for room indices 0.60 ... 5.00 */
    /* Radiometric files (photometry_units.c): the table is radiant
     * intensity, radiometric_scale W/sr per unit (1 for W/sr, 1e-3 for
     * mW/sr), as a keyword named units_keyword says; its "flux" is then
     * radiant flux in W / radiometric_scale, not lumens. */
    int radiometric;
    double radiometric_scale;
    char units_keyword[64];
} cdl_photometry_metadata;

/* The file data. Never NULL for a valid photometry. */
const cdl_photometry_metadata *cdl_photometry_get_metadata(const cdl_photometry *photometry);

/* Every figure of the summary (photometry.h), its size set: the library's
 * own callers' way to cdl_photometry_summarize. */
void cdl_photometry_summary_compute(const cdl_photometry *photometry, cdl_photometry_summary *summary);

#endif
