/* occupancy.h - the occupied hours of a year, for the annual metrics (not public).
 *
 * Either a daily range "A-B" of whole hours of local standard time, 0 <= A
 * < B <= 24: the hours of the weather file whose span (hour h of the file
 * runs from h - 1 to h o'clock) lies within A to B, every day of the year
 * ("8-18": the ten hours from 8:00 to 18:00, IES LM-83-12's analysis
 * period, 3650 hours in a year of 365 days); or a CSV file of one value
 * per hour of the weather file, in its order: 1 occupied, 0 not, the last
 * comma-separated field of each line (so "1" and "1,1,8,1" both read as
 * 1), an optional header line first, blank lines ignored. A spec that is
 * not a range is taken as a file name.
 *
 * Errors (CDL_ERR_INPUT): a range out of order or out of 0..24; a file that
 * cannot be read, a value other than 0 or 1 (naming the file, line and what
 * was found), or a count of values other than the weather file's hours.
 * Thread safety: pure.
 */
#ifndef CANDELA_DAYLIGHT_OCCUPANCY_H
#define CANDELA_DAYLIGHT_OCCUPANCY_H

#include <stddef.h>

#include "base/error.h"
#include "daylight/epw.h"

/* occupied[epw->count] from spec; *described: what it was, for the summary. */
cdl_status cdl_occupancy_read(const char *spec, const cdl_epw *epw, unsigned char *occupied, char *described,
                              size_t described_size, cdl_error *err);

#endif
