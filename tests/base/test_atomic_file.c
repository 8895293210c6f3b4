/* Atomic files: a commit replaces the file whole; an abort or a failure
 * leaves the old file as it was and no temporary file behind. */
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "file_fixture.h"
#include "base/atomic_file.h"

static int file_equals(const char *path, const char *expected)
{
    return fixture_file_is(path, expected, strlen(expected));
}

int main(void)
{
    char dir[512], path[600], sub[600];
    CHECK(fixture_folder("test_atomic_file", dir, sizeof dir));
    snprintf(path, sizeof path, "%s/result.csv", dir);
    cdl_error err;
    cdl_atomic_file f;

    /* A new file: invisible until commit, then complete and readable by all. */
    CHECK_OK(cdl_atomic_file_open(&f, path, &err), &err);
    CHECK(f.fp != NULL);
    if (f.fp) {
        fputs("first version\n", f.fp);
        CHECK(access(path, F_OK) != 0);   /* not there before commit */
        CHECK(strncmp(f.temp_path, path, strlen(path)) == 0); /* same folder */
        CHECK_OK(cdl_atomic_file_commit(&f, &err), &err);
    }
    CHECK(file_equals(path, "first version\n"));
    CHECK(f.fp == NULL && f.temp_path == NULL && f.final_path == NULL);
    struct stat sb;
    CHECK(stat(path, &sb) == 0 && (sb.st_mode & 0777) == 0644);
    CHECK(fixture_count_entries(dir) == 1);

    /* Replacing it works the same way. */
    CHECK_OK(cdl_atomic_file_open(&f, path, &err), &err);
    if (f.fp) {
        fputs("second version\n", f.fp);
        CHECK(file_equals(path, "first version\n")); /* old content until commit */
        CHECK_OK(cdl_atomic_file_commit(&f, &err), &err);
    }
    CHECK(file_equals(path, "second version\n"));
    CHECK(fixture_count_entries(dir) == 1);

    /* Abort: the existing file is untouched and the temporary file is gone. */
    CHECK_OK(cdl_atomic_file_open(&f, path, &err), &err);
    if (f.fp) {
        fputs("half a vers", f.fp);
        CHECK(fixture_count_entries(dir) == 2); /* the temporary file exists meanwhile */
        cdl_atomic_file_abort(&f);
    }
    CHECK(file_equals(path, "second version\n"));
    CHECK(fixture_count_entries(dir) == 1);
    cdl_atomic_file_abort(&f); /* again: a no-op */
    cdl_atomic_file zeroed = {0};
    cdl_atomic_file_abort(&zeroed);

    /* A commit that fails (the final name is a folder: rename refuses) reports
     * the file and the step, and removes the temporary file. */
    snprintf(sub, sizeof sub, "%s/occupied", dir);
    CHECK(mkdir(sub, 0755) == 0);
    CHECK_OK(cdl_atomic_file_open(&f, sub, &err), &err);
    if (f.fp) {
        fputs("cannot land\n", f.fp);
        CHECK(cdl_atomic_file_commit(&f, &err) == CDL_ERR_INTERNAL);
        CHECK_MSG(strstr(err.message, "occupied") && strstr(err.message, "renaming"), "%s", err.message);
    }
    CHECK(fixture_count_entries(dir) == 2); /* result.csv and the folder */
    rmdir(sub);

    /* Commit after a failed or finished commit is an error, not a crash. */
    CHECK(cdl_atomic_file_commit(&f, &err) == CDL_ERR_INTERNAL);

    /* A missing folder: a clear error naming the path, nothing created. */
    snprintf(sub, sizeof sub, "%s/no/such/folder/out.csv", dir);
    CHECK(cdl_atomic_file_open(&f, sub, &err) == CDL_ERR_INTERNAL);
    CHECK_MSG(strstr(err.message, "no/such/folder/out.csv") && strstr(err.message, "No such file"), "%s", err.message);
    CHECK(f.fp == NULL && f.temp_path == NULL && f.final_path == NULL);
    CHECK(fixture_count_entries(dir) == 1);

    /* A path naming a folder, or nothing, is refused. */
    snprintf(sub, sizeof sub, "%s/", dir);
    CHECK(cdl_atomic_file_open(&f, sub, &err) == CDL_ERR_INTERNAL);
    CHECK(cdl_atomic_file_open(&f, "", &err) == CDL_ERR_INTERNAL);

    /* A write error is caught at commit: a stream put into the error state
     * (as a full disk would) must not be renamed into place. */
    CHECK_OK(cdl_atomic_file_open(&f, path, &err), &err);
    if (f.fp) {
        fputs("third version\n", f.fp);
        fgetc(f.fp); /* reading a write-only stream sets its error flag */
        CHECK(ferror(f.fp));
        CHECK(cdl_atomic_file_commit(&f, &err) == CDL_ERR_INTERNAL);
        CHECK_MSG(strstr(err.message, "result.csv") && strstr(err.message, "writing"), "%s", err.message);
    }
    CHECK(file_equals(path, "second version\n"));
    CHECK(fixture_count_entries(dir) == 1);

    /* A whole buffer at once: written complete; a missing folder is the
     * caller's path to fix (bad input), nothing created. */
    CHECK_OK(cdl_atomic_file_write_all(path, "fourth\0version", 14, &err), &err);
    CHECK(fixture_file_is(path, "fourth\0version", 14));
    CHECK(fixture_count_entries(dir) == 1);
    snprintf(sub, sizeof sub, "%s/no/such/folder/out.bin", dir);
    CHECK(cdl_atomic_file_write_all(sub, "x", 1, &err) == CDL_ERR_INPUT);
    CHECK(err.status == CDL_ERR_INPUT && strstr(err.message, "no/such/folder/out.bin"));
    CHECK(fixture_count_entries(dir) == 1);

    unlink(path);
    return check_finish();
}
