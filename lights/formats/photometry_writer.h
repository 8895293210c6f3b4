/* photometry_writer.h - what the IES and EULUMDAT writers share (not public): the text
 * they print into, the notes of what a format cannot hold, resampling steps. */
#ifndef CANDELA_LIGHTS_FORMATS_PHOTOMETRY_WRITER_H
#define CANDELA_LIGHTS_FORMATS_PHOTOMETRY_WRITER_H

#include <stddef.h>

#include "lights/formats/text_buffer.h"
#include "lights/photometry/photometry_internal.h"


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
