/* error.h - status codes and the message buffer every fallible call fills.
 *
 * Library code never prints. A fallible function returns a cdl_status and,
 * when it fails, writes a message into the caller's cdl_error that names the
 * input (file and line, or JSON path) and what was expected. The numeric
 * values of the statuses are the exit statuses of the `candela` command.
 *
 * Units: none. Ownership: a cdl_error is a plain struct the caller owns
 * (usually on its stack); the library only writes into it, and every
 * function that takes one accepts NULL (the message is then dropped).
 * Thread safety: these functions touch only the cdl_error they are given,
 * so they are thread-safe as long as threads do not share one. Errors:
 * none of them can fail.
 */
#ifndef CANDELA_BASE_ERROR_H
#define CANDELA_BASE_ERROR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cdl_status {
    CDL_OK = 0,            /* success */
    CDL_ERR_INPUT = 1,     /* bad input: a file, scene or value the user gave */
    CDL_ERR_USAGE = 2,     /* the call itself was wrong (bad option, missing argument) */
    CDL_ERR_INTERNAL = 3,  /* internal or resource failure: memory, I/O, a library */
    CDL_ERR_CANCELLED = 4  /* the caller's progress callback asked to stop (library calls only:
                            * the command line never cancels, so it never exits with 4) */
} cdl_status;

#define CDL_ERROR_MESSAGE_SIZE 1024

typedef struct cdl_error {
    cdl_status status;
    char message[CDL_ERROR_MESSAGE_SIZE];
} cdl_error;

/* Reset to CDL_OK with an empty message. `err` may be NULL. */
void cdl_error_clear(cdl_error *err);

/* A short name for a status ("bad input", ...). */
const char *cdl_status_name(cdl_status status);

#ifdef __cplusplus
}
#endif

#endif
