/* photometry_writer.h - helpers shared by the IES and EULUMDAT writers (not public). */
#ifndef CANDELA_LIGHTS_PHOTOMETRY_WRITER_H
#define CANDELA_LIGHTS_PHOTOMETRY_WRITER_H

#include <stddef.h>

#include "lights/photometry_internal.h"

/* A growing text; after a failed allocation every call is a no-op and
 * `failed` stays set. */
typedef struct cdl_text {
    char *data;
    size_t len, cap;
    int failed;
} cdl_text;

void cdl_text_printf(cdl_text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* A number with up to 10 significant digits, no trailing zeros. */
void cdl_text_number(cdl_text *t, double x);
void cdl_text_free(cdl_text *t);

/* Append a line to the notes (no-op when notes is NULL). */
void cdl_photometry_note(cdl_photometry_notes *notes, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Resolution of the type A/B -> type C resampling for EULUMDAT output. */
#define CDL_RESAMPLE_DC_DEG 2.5
#define CDL_RESAMPLE_DG_DEG 1.0

#endif
