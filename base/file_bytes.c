/* file_bytes.c - read a whole file. */
#include "base/error_report.h"
#include "base/file_bytes.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

cdl_status cdl_file_read_bytes(const char *path, const char *what, size_t limit, char **data, size_t *size,
                               cdl_error *err)
{
    *data = NULL;
    *size = 0;
    struct stat info;
    if (stat(path, &info) != 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: cannot open the %s: %s", path, what, strerror(errno));
    if (!S_ISREG(info.st_mode))
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a %s, found a directory or device", path, what);
    if ((unsigned long long)info.st_size > (unsigned long long)limit)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: expected a %s of at most %zu bytes, found %lld bytes", path, what,
                             limit, (long long)info.st_size);
    FILE *fp = fopen(path, "rb");
    if (!fp) return cdl_error_set(err, CDL_ERR_INPUT, "%s: cannot open the %s: %s", path, what, strerror(errno));
    size_t capacity = (size_t)info.st_size + 1;
    char *buffer = malloc(capacity);
    if (!buffer) {
        fclose(fp);
        return cdl_error_out_of_memory(err);
    }
    size_t n = fread(buffer, 1, capacity - 1, fp);
    int failed = ferror(fp);
    fclose(fp);
    if (failed) {
        free(buffer);
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot read the %s", path, what);
    }
    buffer[n] = '\0';
    *data = buffer;
    *size = n;
    return CDL_OK;
}
