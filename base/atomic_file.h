/* atomic_file.h - write a file so that readers see the old version or the
 * complete new one, never a half-written file.
 *
 *   cdl_atomic_file f;
 *   if (cdl_atomic_file_open(&f, "out/desk.csv", err) != CDL_OK) return err->status;
 *   fprintf(f.fp, ...);                       // write through f.fp
 *   return cdl_atomic_file_commit(&f, err);   // or cdl_atomic_file_abort(&f)
 *
 * open creates a temporary file "<path>.tmp.XXXXXX" (mkstemp) in the folder of
 * `path`, so the final rename never crosses a file system. commit flushes the
 * stream, checks that every write succeeded, fsyncs, closes, makes the file
 * readable by everyone (mode 0644; mkstemp creates 0600) and renames it over
 * `path`; it then fsyncs the folder where the file system allows it, so the
 * rename itself survives a crash. On any failure commit removes the temporary
 * file and leaves an existing `path` untouched. abort closes and removes the
 * temporary file.
 *
 * After commit or abort (successful or not) the struct is reset: abort may be
 * called again, or on a zero-initialised struct, and does nothing. Errors are
 * CDL_ERR_INTERNAL and name the file, what failed and the system's reason.
 * Thread-safe for distinct files.
 */
#ifndef CANDELA_BASE_ATOMIC_FILE_H
#define CANDELA_BASE_ATOMIC_FILE_H

#include <stdio.h>

#include "base/error.h"

typedef struct cdl_atomic_file {
    FILE *fp;          /* write here (binary mode) */
    char *final_path;  /* the name the file gets on commit */
    char *temp_path;   /* the temporary name while it is written */
} cdl_atomic_file;

cdl_status cdl_atomic_file_open(cdl_atomic_file *file, const char *path, cdl_error *err);
cdl_status cdl_atomic_file_commit(cdl_atomic_file *file, cdl_error *err);
void cdl_atomic_file_abort(cdl_atomic_file *file);

/* The `size` bytes at `data` as the whole file at `path`: open, write,
 * commit. A file that cannot be created there (a missing or read-only
 * folder) is the caller's path to fix: CDL_ERR_INPUT; a failing write,
 * sync or rename stays CDL_ERR_INTERNAL. */
cdl_status cdl_atomic_file_write_all(const char *path, const void *data, size_t size, cdl_error *err);

#endif
