/* ocio_config_path.c - where the OpenColorIO config shipped with Candela is.
 *
 * The config (data/ocio/config.ocio and its LUT) is installed under
 * DATADIR/candela/ocio. It is found relative to the file this code was
 * loaded from, so an installed prefix can be moved anywhere:
 *  - linked into libcandela.so, the library's folder is LIBDIR, and the
 *    config is at CANDELA_DATA_FROM_LIBDIR/ocio/config.ocio from it;
 *  - linked statically into a program (the `candela` command in BINDIR),
 *    the program's folder is BINDIR, and CANDELA_DATA_FROM_BINDIR is used;
 *  - a library or program still in the build tree uses the source tree's
 *    data/ (the only case where the source tree is looked at);
 *  - otherwise (a program elsewhere linked with libcandela.a) the absolute
 *    DATADIR/candela of the configured prefix.
 * The first of these that exists wins; when none does, the last is
 * returned, so the message of the failed open names where it was expected.
 */
#define _GNU_SOURCE /* dladdr1, RTLD_DL_LINKMAP */
#include "solver/output/solution_write.h"

#include <dlfcn.h>
#include <limits.h>
#include <link.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define OCIO_CONFIG_NAME "ocio/config.ocio"

static pthread_once_t config_once = PTHREAD_ONCE_INIT;
static char config_path[PATH_MAX + 64];

/* The folder of the ELF module (program or shared library) holding this
 * code, into dir; *is_program says which. 0 when it cannot be told. */
static int module_folder(char *dir, size_t size, int *is_program)
{
    Dl_info info;
    struct link_map *map = NULL;
    char resolved[PATH_MAX];
    const char *file;
    if (dladdr1((void *)&cdl_default_ocio_config, &info, (void **)&map, RTLD_DL_LINKMAP) == 0 || map == NULL)
        return 0;
    /* The main program's link map has an empty name. */
    *is_program = map->l_name == NULL || map->l_name[0] == '\0';
    file = *is_program ? "/proc/self/exe" : map->l_name;
    if (realpath(file, resolved) == NULL) return 0;
    char *slash = strrchr(resolved, '/');
    if (slash == NULL || (size_t)(slash - resolved) + 1 > size) return 0;
    memcpy(dir, resolved, (size_t)(slash - resolved));
    dir[slash - resolved] = '\0';
    return 1;
}

/* 1 when `folder` is the build tree or inside it. */
static int in_build_tree(const char *folder)
{
    char build[PATH_MAX];
    if (realpath(CANDELA_BUILD_DIR, build) == NULL) return 0;
    size_t n = strlen(build);
    return strncmp(folder, build, n) == 0 && (folder[n] == '\0' || folder[n] == '/');
}

static int readable(const char *path)
{
    return access(path, R_OK) == 0;
}

static void locate_config(void)
{
    char dir[PATH_MAX];
    int is_program = 0;
    if (module_folder(dir, sizeof dir, &is_program)) {
        if (in_build_tree(dir)) {
            snprintf(config_path, sizeof config_path, "%s/%s", CANDELA_SOURCE_DATA_DIR, OCIO_CONFIG_NAME);
            if (readable(config_path)) return;
        }
        snprintf(config_path, sizeof config_path, "%s/%s/%s", dir,
                 is_program ? CANDELA_DATA_FROM_BINDIR : CANDELA_DATA_FROM_LIBDIR, OCIO_CONFIG_NAME);
        if (readable(config_path)) return;
    }
    snprintf(config_path, sizeof config_path, "%s/%s", CANDELA_INSTALL_DATA_DIR, OCIO_CONFIG_NAME);
}

const char *cdl_default_ocio_config(void)
{
    pthread_once(&config_once, locate_config);
    return config_path;
}
