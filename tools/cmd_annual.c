/* cmd_annual.c - `candela annual SCENE.json --weather FILE.epw -o OUTDIR`: a year of daylight. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_args.h"
#include "cli_ranks.h"
#include "command.h"
#include "daylight/annual.h"
#include "solver/output/solution_write.h"

static void print_help(FILE *out)
{
    fputs("usage: candela annual SCENE.json --weather FILE.epw -o OUTDIR [options]\n"
          "\n"
          "Every hour of the weather file's year at every point of the scene's grids,\n"
          "and the climate-based daylight metrics. The scene holds surfaces (glass\n"
          "included) and grids, no luminaires: the sky and the sun come from the\n"
          "weather file (EnergyPlus EPW: its site, time zone and hourly direct normal\n"
          "and diffuse horizontal irradiance, illuminance and dew point). Up is +z.\n"
          "\n"
          "  --sky perez         (default) each hour the Perez all-weather sky of its\n"
          "                      irradiances and dew point, and its sun placed by the\n"
          "                      SPA at the hour's middle: the sky through daylight\n"
          "                      coefficients of Reinhart patches (direct light exact\n"
          "                      where the exact route sees the sky, interreflection by\n"
          "                      paths), the sun's direct light traced each hour, its\n"
          "                      interreflection by sun bins; the hours as one matrix\n"
          "                      product (BLAS)\n"
          "  --sky cie_overcast  each hour the CIE overcast sky scaled to its diffuse\n"
          "                      horizontal illuminance, no sun: every hour is the\n"
          "                      daylight factor times that illuminance\n"
          "  --mf 1|2|4          Reinhart subdivision of the sky: 145, 577 or 2305 sky\n"
          "                      patches and the ground (default 1)\n"
          "  --occupancy A-B     occupied hours of every day, local standard time\n"
          "                      (default 8-18: IES LM-83's 10 hours)\n"
          "  --occupancy FILE    or a CSV of one 0/1 per hour of the weather file\n"
          "  --ground-reflectance R  the ground below the horizon lit by sky and sun\n"
          "                      (rho E_global / pi; default 0: the scene's surfaces are\n"
          "                      its ground)\n"
          "  --north X,Y,Z       the direction of north (default 0,1,0)\n"
          "  --threads N         worker threads, 0 all cores (under mpirun the cores of\n"
          "                      the rank's binding; default: the scene's \"threads\");\n"
          "                      results do not depend on N\n"
          "  --ocio CONFIG       OpenColorIO config for the maps\n"
          "  --quiet             no progress on stderr\n"
          "\n"
          "Writes into OUTDIR, per grid NAME: NAME.csv (per point DA300, UDI 100-3000 lx\n"
          "with fell-short and exceeded, ASE hours, the EN 17037 share of daylight hours\n"
          "at 300 lx, the coefficients' stated relative error, and DF_percent under\n"
          "cie_overcast), NAME.hourly.bin (every hour's lx at every point: a 24-byte\n"
          "header \"CDLHOUR1\", hours, points, quantity, 0 as uint32, then float32,\n"
          "hour by hour, little-endian), NAME.sun.bin (perez: the direct sun alone),\n"
          "maps NAME_DA300.png, NAME_UDI.png, NAME_ASE.png, NAME_EN17037.png (rect\n"
          "and polygon grids); and summary.json: per grid sDA300/50%, ASE1000,250h,\n"
          "the UDI shares, EN 17037's daylight provision per level, the coefficients'\n"
          "stated error; the weather, the sky, the occupancy, the time of each step.\n"
          "\n"
          "Many processes (MPI): mpirun -np N candela annual ... (or srun, or mpirun\n"
          "with a hostfile) deals the skies, the points' coefficients and the hours'\n"
          "direct sun among N ranks, each with its threads; rank 0 makes the hours,\n"
          "the metrics and the files, the same bytes as one process (summary.json's\n"
          "\"ranks\" says how each rank's share went). Every rank reads the scene and\n"
          "the weather file; one that cannot ends every rank (exit 1, its message).\n"
          "Needs a build with MPI (CANDELA_MPI).\n"
          "\n"
          "exit status: 0 success, 1 bad scene, weather or occupancy file (the message\n"
          "names the file, line and field), 2 usage error, 3 internal failure\n",
          out);
}

static int usage(const char *fmt, const char *value)
{
    fprintf(stderr, "candela annual: ");
    fprintf(stderr, fmt, value);
    fprintf(stderr, "\n(see 'candela annual --help')\n");
    return CDL_EXIT_USAGE;
}

/* Progress on stderr (a terminal): the stage and its items, at most five lines a second. */
static int progress(void *user, const cdl_progress *p)
{
    double *last = user;
    int finished = p->total > 0 && p->done == p->total;
    if (!finished && p->elapsed_seconds - *last < 0.2) return 0;
    *last = p->elapsed_seconds;
    if (p->total == 0) fprintf(stderr, "candela annual: %s\n", p->stage);
    else
        fprintf(stderr, "\r\033[Kcandela annual: %s: %zu/%zu%s", p->stage, p->done, p->total, finished ? "\n" : "");
    return 0;
}

/* The options into o; 0, or the exit status after saying what was wrong. */
static int read_options(cdl_cli_option *opts, size_t n, cdl_annual_options *o)
{
    cdl_cli_option *sky = cdl_cli_find(opts, n, "sky"), *mf = cdl_cli_find(opts, n, "mf"),
                   *occ = cdl_cli_find(opts, n, "occupancy"), *rho = cdl_cli_find(opts, n, "ground-reflectance"),
                   *north = cdl_cli_find(opts, n, "north");
    if (sky->present) {
        if (strcmp(sky->value, "perez") == 0) o->sky = CDL_ANNUAL_SKY_PEREZ;
        else if (strcmp(sky->value, "cie_overcast") == 0) o->sky = CDL_ANNUAL_SKY_CIE_OVERCAST;
        else return usage("--sky: expected perez or cie_overcast, found '%s'", sky->value);
    }
    if (mf->present) {
        if (strcmp(mf->value, "1") && strcmp(mf->value, "2") && strcmp(mf->value, "4"))
            return usage("--mf: expected 1, 2 or 4, found '%s'", mf->value);
        o->mf = atoi(mf->value);
    }
    if (occ->present) {
        if (!occ->value[0]) return usage("--occupancy: expected A-B or a file, found '%s'", occ->value);
        o->occupancy = occ->value;
    }
    if (rho->present) {
        char *end = NULL;
        o->ground_reflectance = strtod(rho->value, &end);
        if (!end || end == rho->value || *end || !(o->ground_reflectance >= 0.0 && o->ground_reflectance <= 1.0))
            return usage("--ground-reflectance: expected a number in [0, 1], found '%s'", rho->value);
    }
    if (north->present) {
        double v[3];
        char tail;
        if (sscanf(north->value, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3 || !isfinite(v[0]) ||
            !isfinite(v[1]) || !isfinite(v[2]) || (v[0] == 0.0 && v[1] == 0.0))
            return usage("--north: expected X,Y,Z with a horizontal part, found '%s'", north->value);
        o->north = cdl_vec3_make(v[0], v[1], v[2]);
    }
    return 0;
}

static void print_results(const cdl_annual_result *r, const char *out_dir, int ranks)
{
    for (size_t g = 0; g < r->grid_count; ++g) {
        const cdl_annual_grid_result *x = &r->grids[g];
        printf("%-20s %zu points  sDA300/50%% %.1f %%  ASE1000,250h %.1f %%  UDI %.1f %% (short %.1f, exceeded %.1f)"
               "  EN 17037 %s  stderr %.2g\n",
               x->name, x->points, x->metrics.sDA300, x->metrics.ASE1000, x->metrics.UDI, x->metrics.UDI_fell_short,
               x->metrics.UDI_exceeded, x->metrics.en_level, x->stderr_mean_rel);
    }
    printf("%zu hours (%zu with daylight, %zu occupied), %.3g s (coefficients %.3g s, direct sun %.3g s, hours %.3g s)",
           r->hours, r->lit_hours, r->occupied_hours, r->seconds_total, r->seconds_coefficients, r->seconds_suns,
           r->seconds_hours);
    if (ranks > 1) printf(", %d ranks", ranks);
    printf("; results in %s\n", out_dir);
}

/* The study on the ranks (one process alone without a launcher): every
 * rank loads the scene and reads the weather; rank 0 prepares the folder,
 * writes and prints; after each step the ranks agree on how it went. */
static int study(const char *scene_path, const char *weather, const char *out_dir, cdl_annual_options *o,
                 cdl_cli_ranks *ranks)
{
    int root = cdl_cli_ranks_root(ranks);
    double last = -1.0;
    if (!root) o->progress.fn = NULL;
    else if (o->progress.fn) o->progress.user = &last;
    o->ranks = &ranks->group;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    cdl_status status = cdl_cli_ranks_agree(ranks, cdl_scene_load(scene_path, &scene, &err), &err);
    /* a folder made for this run and left empty by a failure is removed */
    int folder_existed = root && access(out_dir, F_OK) == 0;
    if (status == CDL_OK)
        status = cdl_cli_ranks_agree(ranks, root ? cdl_solution_prepare_folder(out_dir, &err) : CDL_OK, &err);
    int prepared = status == CDL_OK;
    cdl_annual_result result;
    memset(&result, 0, sizeof result);
    if (status == CDL_OK) {
        status = cdl_annual_run(scene, weather, o, out_dir, &result, &err);
        if (status != CDL_OK && !ranks->group.failure_agreed && ranks->group.count > 1)
            cdl_cli_ranks_abort(ranks, "annual", (int)status, &err);
    }
    if (status != CDL_OK) {
        fprintf(stderr, "candela annual: %s\n", err.message);
        if (root && prepared && !folder_existed) rmdir(out_dir); /* fails, as it should, unless empty */
    } else if (root) {
        print_results(&result, out_dir, ranks->group.count);
    }
    cdl_annual_result_release(&result);
    cdl_scene_release(scene);
    return (int)status;
}

/* The options, then the study; the exit status. */
static int parse_and_study(int argc, char **argv, cdl_cli_ranks *ranks)
{
    cdl_cli_option opts[] = {{"output", 'o', 1, 0, NULL},    {"weather", 0, 1, 0, NULL},
                             {"sky", 0, 1, 0, NULL},         {"mf", 0, 1, 0, NULL},
                             {"occupancy", 0, 1, 0, NULL},   {"ground-reflectance", 0, 1, 0, NULL},
                             {"north", 0, 1, 0, NULL},       {"threads", 0, 1, 0, NULL},
                             {"ocio", 0, 1, 0, NULL},        {"quiet", 'q', 0, 0, NULL}};
    const size_t n = sizeof opts / sizeof opts[0];
    cdl_cli_result args;
    if (cdl_cli_scan(argc, argv, opts, n, &args) != 0) return usage("%s", args.message);
    if (args.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    cdl_cli_option *out = cdl_cli_find(opts, n, "output"), *weather = cdl_cli_find(opts, n, "weather");
    if (args.positional_count != 1 || !out->present || !weather->present)
        return usage("%s", "expected SCENE.json, --weather FILE.epw and -o OUTDIR");
    if (!out->value[0]) return usage("-o: expected a folder name, found '%s'", out->value);
    cdl_annual_options o = CDL_ANNUAL_OPTIONS_INIT;
    int st = read_options(opts, n, &o);
    if (st) return st;
    if (cdl_cli_parse_threads("annual", cdl_cli_find(opts, n, "threads"), &o.threads)) return CDL_EXIT_USAGE;
    if (cdl_cli_find(opts, n, "ocio")->present) o.ocio_config = cdl_cli_find(opts, n, "ocio")->value;
    if (!cdl_cli_find(opts, n, "quiet")->present && isatty(STDERR_FILENO)) o.progress.fn = progress;
    return study(args.positional[0], weather->value, out->value, &o, ranks);
}

static int run(int argc, char **argv)
{
    cdl_cli_ranks ranks;
    int status = cdl_cli_ranks_begin("annual", &ranks);
    if (status == 0) status = parse_and_study(argc, argv, &ranks);
    cdl_cli_ranks_end(&ranks);
    return status;
}

const cdl_command cdl_command_annual = {"annual", "a year of daylight from a weather file: DA, sDA, ASE, UDI, EN 17037",
                                        run, print_help};
