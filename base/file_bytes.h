/* file_bytes.h - a whole file read into memory, with messages that name it.
 *
 * The readers of scenes, meshes, photometric and tilt files all start here:
 * one place decides what an unreadable, missing, oversized or non-regular
 * file is told.
 */
#ifndef CANDELA_BASE_FILE_BYTES_H
#define CANDELA_BASE_FILE_BYTES_H

#include <stddef.h>

#include "base/error.h"

/* Read the regular file `path` into *data (NUL-terminated; *size excludes
 * the NUL; the caller frees *data). `what` names the file's role in
 * messages ("scene file", "photometric file"). A missing, non-regular or
 * larger-than-`limit` file is CDL_ERR_INPUT ("PATH: cannot open the scene
 * file: No such file or directory"); a read failure part-way is
 * CDL_ERR_INTERNAL. */
cdl_status cdl_file_read_bytes(const char *path, const char *what, size_t limit, char **data, size_t *size,
                               cdl_error *err);

#endif
