/* file_fixture.h - files for tests: a private folder per test (to check that
 * no temporary file is left behind), whole-file reads and writes.
 * Needs CANDELA_TEST_TMPDIR (set by tests/CMakeLists.txt). */
#ifndef CANDELA_TESTS_FILE_FIXTURE_H
#define CANDELA_TESTS_FILE_FIXTURE_H

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A fresh private folder CANDELA_TEST_TMPDIR/<name> (emptied if it exists),
 * its path written into buf. Tests run in parallel: each uses its own. */
static inline int fixture_folder(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", CANDELA_TEST_TMPDIR, name);
    if (mkdir(buf, 0755) != 0 && errno != EEXIST) return 0;
    DIR *d = opendir(buf);
    if (!d) return 0;
    struct dirent *e;
    char path[1024];
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        snprintf(path, sizeof path, "%s/%s", buf, e->d_name);
        unlink(path);
    }
    closedir(d);
    return 1;
}

/* Number of entries in a folder other than "." and "..", or -1. */
static inline int fixture_count_entries(const char *folder)
{
    DIR *d = opendir(folder);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) ++n;
    closedir(d);
    return n;
}

/* Whole file into a NUL-terminated buffer (caller frees), or NULL. */
static inline char *fixture_read_file(const char *path, size_t *length)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, fp)) > 0) {
        n += got;
        if (cap - n - 1 == 0) {
            char *bigger = realloc(buf, cap * 2);
            if (!bigger) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = bigger;
            cap *= 2;
        }
    }
    fclose(fp);
    if (buf) buf[n] = '\0';
    if (length) *length = n;
    return buf;
}

/* 1 when the file at path holds exactly the n bytes at expected. */
static inline int fixture_file_is(const char *path, const char *expected, size_t n)
{
    size_t len = 0;
    char *text = fixture_read_file(path, &len);
    int same = text && expected && len == n && memcmp(text, expected, n) == 0;
    free(text);
    return same;
}

static inline int fixture_write_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "wb");
    if (!fp) return 0;
    int ok = fputs(text, fp) >= 0;
    return fclose(fp) == 0 && ok;
}

#endif
