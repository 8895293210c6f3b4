/* error_report.h - how library code fills a cdl_error (not public).
 *
 * The public side (error.h) is the status codes and the message buffer a
 * caller reads; this is the side that writes them, shared by every layer.
 * Thread safety and NULL handling as error.h says.
 */
#ifndef CANDELA_BASE_ERROR_REPORT_H
#define CANDELA_BASE_ERROR_REPORT_H

#include "base/error.h"

#if defined(__GNUC__)
#define CDL_PRINTF(fmt_index, first_arg) __attribute__((format(printf, fmt_index, first_arg)))
#else
#define CDL_PRINTF(fmt_index, first_arg)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Record a failure and return `status`, so callers can write
 * `return cdl_error_set(err, CDL_ERR_INPUT, "...", ...);`. `err` may be NULL. */
cdl_status cdl_error_set(cdl_error *err, cdl_status status, const char *fmt, ...) CDL_PRINTF(3, 4);

/* Prepend context ("scene.json: ") to an existing message; returns err->status. */
cdl_status cdl_error_prefix(cdl_error *err, const char *fmt, ...) CDL_PRINTF(2, 3);

/* Shorthand for the most common resource failure. */
cdl_status cdl_error_out_of_memory(cdl_error *err);

#ifdef __cplusplus
}
#endif

#endif
