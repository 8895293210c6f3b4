/* atomic_file.c - temporary file in the same folder, then fsync and rename. */
#include "base/atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error_report.h"
#include "base/strings.h"

static const char temp_suffix[] = ".tmp.XXXXXX";

/* The system's reason for errno code `code`, without shared state (XSI strerror_r). */
static const char *reason(int code, char *buf, size_t size)
{
    if (strerror_r(code, buf, size) != 0) snprintf(buf, size, "error %d", code);
    return buf;
}

static void reset(cdl_atomic_file *file)
{
    free(file->final_path);
    free(file->temp_path);
    file->fp = NULL;
    file->final_path = NULL;
    file->temp_path = NULL;
}

cdl_status cdl_atomic_file_open(cdl_atomic_file *file, const char *path, cdl_error *err)
{
    file->fp = NULL;
    file->final_path = NULL;
    file->temp_path = NULL;
    if (!path || !*path) return cdl_error_set(err, CDL_ERR_INTERNAL, "atomic file: empty output path");
    size_t n = strlen(path);
    if (path[n - 1] == '/')
        return cdl_error_set(err, CDL_ERR_INTERNAL, "%s: expected a file name, found a folder path", path);
    file->final_path = cdl_string_copy(path);
    file->temp_path = malloc(n + sizeof temp_suffix);
    if (!file->final_path || !file->temp_path) {
        reset(file);
        return cdl_error_out_of_memory(err);
    }
    memcpy(file->temp_path, path, n);
    memcpy(file->temp_path + n, temp_suffix, sizeof temp_suffix);

    char why[128];
    int fd = mkstemp(file->temp_path);
    if (fd < 0) {
        int code = errno;
        cdl_status st = cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot create a temporary file beside it: %s", path,
                                      reason(code, why, sizeof why));
        reset(file);
        return st;
    }
    file->fp = fdopen(fd, "wb");
    if (!file->fp) {
        int code = errno;
        close(fd);
        unlink(file->temp_path);
        cdl_status st = cdl_error_set(err, CDL_ERR_INTERNAL, "%s: cannot open a stream on the temporary file %s: %s",
                                      path, file->temp_path, reason(code, why, sizeof why));
        reset(file);
        return st;
    }
    return CDL_OK;
}

void cdl_atomic_file_abort(cdl_atomic_file *file)
{
    if (!file) return;
    if (file->fp) fclose(file->fp);
    if (file->temp_path) unlink(file->temp_path);
    reset(file);
}

/* Make the rename durable: fsync the folder holding `path`. Some file systems
 * refuse fsync on a folder (EINVAL); the data itself is already synced, so
 * this step is best effort. */
static void sync_parent_folder(const char *path)
{
    const char *slash = strrchr(path, '/');
    char *folder = NULL;
    if (!slash)
        folder = cdl_string_copy(".");
    else {
        size_t n = slash == path ? 1 : (size_t)(slash - path);
        folder = malloc(n + 1);
        if (folder) {
            memcpy(folder, path, n);
            folder[n] = '\0';
        }
    }
    if (!folder) return;
    int fd = open(folder, O_RDONLY);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(folder);
}

cdl_status cdl_atomic_file_commit(cdl_atomic_file *file, cdl_error *err)
{
    if (!file || !file->fp || !file->temp_path || !file->final_path)
        return cdl_error_set(err, CDL_ERR_INTERNAL, "atomic file: commit without a successful open");
    char why[128];
    const char *step = NULL;
    int code = 0;
    int fd = fileno(file->fp);
    if (ferror(file->fp)) {
        step = "writing";
        code = EIO;
    } else if (fflush(file->fp) != 0) {
        step = "writing";
        code = errno;
    } else if (fsync(fd) != 0) {
        step = "syncing to disk";
        code = errno;
    } else if (fchmod(fd, 0644) != 0) {
        step = "setting permissions";
        code = errno;
    }
    int close_failed = fclose(file->fp) != 0;
    file->fp = NULL;
    if (!step && close_failed) {
        step = "closing";
        code = errno;
    }
    if (!step && rename(file->temp_path, file->final_path) != 0) {
        step = "renaming the temporary file over it";
        code = errno;
    }
    if (step) {
        cdl_status st = cdl_error_set(err, CDL_ERR_INTERNAL, "%s: failed while %s: %s (the previous file, if any, is unchanged)",
                                      file->final_path, step, reason(code, why, sizeof why));
        unlink(file->temp_path);
        reset(file);
        return st;
    }
    sync_parent_folder(file->final_path);
    reset(file);
    return CDL_OK;
}

cdl_status cdl_atomic_file_write_all(const char *path, const void *data, size_t size, cdl_error *err)
{
    cdl_atomic_file file;
    if (cdl_atomic_file_open(&file, path, err) != CDL_OK) {
        if (err) err->status = CDL_ERR_INPUT;
        return CDL_ERR_INPUT;
    }
    /* A short write leaves the stream's error flag set: commit reports it
     * and keeps the previous file. */
    if (size > 0) (void)fwrite(data, 1, size, file.fp);
    return cdl_atomic_file_commit(&file, err);
}
