/* cmd_solve.c - `candela solve SCENE.json -o OUTDIR`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/error_report.h"
#include "cli_args.h"
#include "cli_ranks.h"
#include "command.h"
#include "solver/output/grid_result.h"
#include "solver/output/solution_write.h"
#include "solver/solve_internal.h"

static void print_help(FILE *out)
{
    fputs("usage: candela solve SCENE.json -o OUTDIR [options]\n"
          "\n"
          "Computes illuminance in lux on every calculation grid of the scene and\n"
          "writes, into OUTDIR (created when missing), for each grid NAME:\n"
          "  NAME.csv   one row per point: x,y,z,nx,ny,nz,E_lx,E_direct_lx,\n"
          "             E_indirect_lx,E_stderr_lx, then area_m2 (polygon grids) and\n"
          "             the outputs the grid asks for: AO, Ez_lx, Esz_lx (with\n"
          "             Ez_stderr_lx, Esz_stderr_lx where sampled), L_cd_m2\n"
          "  NAME.exr   rect and polygon grids: float lux maps (E, E_direct,\n"
          "             E_indirect, E_stderr, mask) with the solver settings\n"
          "  NAME.png   rect and polygon grids: false-colour map titled with the grid's\n"
          "             name, Em, Emin, Emax and U0, axes in metres (+x/+y where the\n"
          "             grid runs along them) and a lux legend (linear; --map-scale log)\n"
          "and summary.json (Em, Emin, Emax, U0, Ud per grid, and of each extra\n"
          "output; installed power and W/m2 when the luminaire files give their\n"
          "input watts; method, settings, time, rays, the plan: what was modelled\n"
          "and why; warnings: whatever lit nothing, each also on stderr).\n"
          "With observers (scene \"observers\", or grids of \"type\": \"observers\"):\n"
          "  glare.csv  one row per observer: name,x,y,z,view_x,view_y,view_z,ugr,\n"
          "             ugr_stderr,background_cd_m2,background_stderr_cd_m2\n"
          "and summary.json's \"glare\": each observer's UGR (CIE 117:1995) with its\n"
          "standard error, background luminance, and every luminaire as a source\n"
          "(L, solid angle less what surfaces hide, position index, term) or\n"
          "excluded with the reason (behind the eye, beyond the table, no luminous\n"
          "area). A scene with observers and no luminaire that can be rated, or an\n"
          "eye on or inside a surface, is refused (exit 1).\n"
          "Every file is written to a temporary name and renamed when complete.\n"
          "\n"
          "Methods (scene \"solver\".\"method\"): direct computes direct light only,\n"
          "exactly where it can (point, spot, goniometric and directional lights with\n"
          "one shadow ray; area emitters and uniform skies in closed form or as the\n"
          "visible polygon) and by sampling with a standard error elsewhere.\n"
          "icache adds interreflected light from an irradiance cache (records\n"
          "gathered at some points, interpolated at all); pathtrace adds it by\n"
          "paths traced from every point (unbiased, the reference). auto (the\n"
          "default) uses direct when no surface reflects light, else for each grid\n"
          "the cheaper of icache and pathtrace for the target (the plan says which).\n"
          "\n"
          "Surface maps (scene \"solver\".\"surface_maps\": \"all\" or a list of surface\n"
          "names; a surface with \"requirements\" always): each mapped surface's front\n"
          "side on a mesh refined where the light changes, written as\n"
          "OUTDIR/surfaces/NAME.csv (x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,\n"
          "E_stderr_lx,L_cd_m2 per vertex) and NAME.tri.csv (a,b,c per triangle),\n"
          "summary.json \"surfaces\", and OUTDIR/scene.glb (glTF 2.0: the maps in false\n"
          "colour, the other surfaces grey, the luminaires as markers).\n"
          "\n"
          "Many processes (MPI): mpirun -np N candela solve SCENE.json -o OUTDIR (or\n"
          "srun, or mpirun with a hostfile) shares the solve among N ranks, each with\n"
          "its threads: the same files as one process, bit for bit (summary.json\n"
          "\"ranks\" says how each rank's share went). Every rank reads the scene and\n"
          "its files; rank 0 writes and prints. A rank that cannot read a file ends\n"
          "every rank (exit 1, its message). Needs a build with MPI (CANDELA_MPI).\n"
          "\n"
          "Accuracy (scene \"solver\"): \"quality\" draft, normal, high or reference\n"
          "asks for a relative standard error of E per point of 2 %, 0.5 %, 0.1 % or\n"
          "0.02 %; \"target_error\": 0.003 asks for 0.3 %. E_stderr_lx is each\n"
          "point's one-sigma error; summary.json gives the mean and worst per grid.\n"
          "\n"
          "options:\n"
          "  -o, --output OUTDIR   folder for the results (required)\n"
          "  --threads N           worker threads (default: the scene's \"threads\";\n"
          "                        0 = all cores, or under mpirun the cores of the\n"
          "                        rank's binding); results do not depend on N\n"
          "  --ocio CONFIG         OpenColorIO config for the PNG maps (default: the\n"
          "                        one in Candela's data/ocio; needs display \"sRGB\"\n"
          "                        with view \"False colour\")\n"
          "  --cache FILE          irradiance-cache records: when FILE exists, use its\n"
          "                        records instead of gathering them, provided it was\n"
          "                        made for this scene (geometry, reflectances, lights\n"
          "                        and their files, the grids' points), these settings\n"
          "                        (method, target error, bounces, seed, direct_samples)\n"
          "                        and this Candela version; else refuse (exit 1, naming\n"
          "                        what differs: remove FILE to start anew). When FILE\n"
          "                        does not exist, gather the records and write them to\n"
          "                        FILE (atomically) after the solve. --threads, -o and\n"
          "                        --ocio do not matter. summary.json: plan.cache.reused\n"
          "  --strict              refuse, with exit status 1 and no results, a solve that\n"
          "                        warns: a luminaire that adds nothing to any grid (facing\n"
          "                        away, above the ceiling, outside the room, millimetres\n"
          "                        typed as metres), a grid at 0 lx everywhere, a scene\n"
          "                        without light, points where two surfaces meet\n"
          "  --map-scale linear|log  the PNG maps' lux scale (default linear: from 0, or\n"
          "                        from the grid's 2nd percentile where nearly all of it\n"
          "                        is bright, to the maximum; log: 1-2-5 decades)\n"
          "  --quiet               no progress on stderr\n"
          "\n"
          "exit status: 0 success, 1 bad scene, input file or output folder (not a\n"
          "folder, cannot be created or written), 2 usage error, 3 internal or\n"
          "resource failure (out of memory or disk space, I/O errors)\n",
          out);
}

/* Progress on stderr (a terminal): the stage, items done, cache records and
 * the time left at the rate so far; at most five lines a second. */
typedef struct progress_state {
    double last;              /* when the line was last written */
    const char *stage;        /* the stage it showed */
} progress_state;

static int progress(void *user, const cdl_progress *p)
{
    progress_state *ps = user;
    int finished = p->total > 0 && p->done == p->total;
    int new_stage = ps->stage != p->stage;
    if (!finished && !new_stage && p->elapsed_seconds - ps->last < 0.2) return 0;
    ps->last = p->elapsed_seconds;
    ps->stage = p->stage;
    if (p->total == 0) {
        fprintf(stderr, "candela solve: %s\n", p->stage);
        return 0;
    }
    char left[64] = "";
    if (p->done > 0 && !finished)
        snprintf(left, sizeof left, ", %.0f s left",
                 p->elapsed_seconds * (double)(p->total - p->done) / (double)p->done);
    char records[64] = "";
    if (p->records > 0) snprintf(records, sizeof records, ", %zu records", p->records);
    fprintf(stderr, "\r\033[Kcandela solve: %s: %zu/%zu%s%s%s", p->stage, p->done, p->total, records, left,
            finished ? "\n" : "");
    return 0;
}

/* The command's settings, from its arguments. */
typedef struct solve_args {
    const char *scene, *out_dir, *ocio;
    cdl_solve_options options;
    int strict, log_scale, quiet;
} solve_args;

/* Returns -1 when the solve is to go on, else the exit status (help, usage). */
static int parse(int argc, char **argv, solve_args *a)
{
    cdl_cli_option opts[] = {
        {"output", 'o', 1, 0, NULL},
        {"threads", 0, 1, 0, NULL},
        {"ocio", 0, 1, 0, NULL},
        {"quiet", 'q', 0, 0, NULL},
        {"cache", 0, 1, 0, NULL},
        {"strict", 0, 0, 0, NULL},
        {"map-scale", 0, 1, 0, NULL},
    };
    const size_t nopts = sizeof opts / sizeof opts[0];
    cdl_cli_result args;
    if (cdl_cli_scan(argc, argv, opts, nopts, &args) != 0) {
        fprintf(stderr, "candela solve: %s\n(see 'candela solve --help')\n", args.message);
        return CDL_EXIT_USAGE;
    }
    if (args.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    cdl_cli_option *out_opt = cdl_cli_find(opts, nopts, "output");
    if (args.positional_count != 1 || !out_opt->present) {
        fprintf(stderr, "candela solve: expected SCENE.json and -o OUTDIR\n(see 'candela solve --help')\n");
        return CDL_EXIT_USAGE;
    }
    if (!out_opt->value[0]) {
        fprintf(stderr, "candela solve: -o: expected a folder name, found an empty string\n(see 'candela solve --help')\n");
        return CDL_EXIT_USAGE;
    }
    a->scene = args.positional[0];
    a->out_dir = out_opt->value;
    cdl_solve_options so = CDL_SOLVE_OPTIONS_INIT;
    a->options = so;
    if (cdl_cli_parse_threads("solve", cdl_cli_find(opts, nopts, "threads"), &a->options.threads))
        return CDL_EXIT_USAGE;
    cdl_cli_option *cache = cdl_cli_find(opts, nopts, "cache");
    if (cache->present) {
        if (!cache->value[0]) {
            fprintf(stderr, "candela solve: --cache: expected a file name, found an empty string\n"
                            "(see 'candela solve --help')\n");
            return CDL_EXIT_USAGE;
        }
        a->options.cache_path = cache->value;
    }
    cdl_cli_option *scale = cdl_cli_find(opts, nopts, "map-scale");
    if (scale->present) {
        if (strcmp(scale->value, "log") != 0 && strcmp(scale->value, "linear") != 0) {
            fprintf(stderr, "candela solve: --map-scale: expected linear or log, found '%s'\n"
                            "(see 'candela solve --help')\n", scale->value);
            return CDL_EXIT_USAGE;
        }
        a->log_scale = strcmp(scale->value, "log") == 0;
    }
    a->quiet = cdl_cli_find(opts, nopts, "quiet")->present;
    a->strict = cdl_cli_find(opts, nopts, "strict")->present;
    a->ocio = cdl_cli_find(opts, nopts, "ocio")->present ? cdl_cli_find(opts, nopts, "ocio")->value
                                                         : cdl_default_ocio_config();
    return -1;
}

/* A line per grid and observer, the totals and where the results went. */
static void print_results(const cdl_scene *scene, const cdl_solution *sol, const solve_args *a)
{
    for (size_t g = 0; g < sol->grid_count; ++g) {
        cdl_grid_result r;
        cdl_grid_solution_result(&sol->grids[g], &r);
        cdl_grid_stats s;
        cdl_grid_result_stats(&r, &s);
        printf("%-16s %6zu points  Em %10.4g lx  Emin %10.4g lx  Emax %10.4g lx  U0 %.3f  Ud %.3f", r.name, s.count,
               s.E_avg_lx, s.E_min_lx, s.E_max_lx, s.U0, s.Ud);
        if (r.Ez) printf("  Ez %.4g lx", s.Ez.avg);
        if (r.Esz) printf("  Esz %.4g lx", s.Esz.avg);
        if (r.L) printf("  L %.4g cd/m2", s.L.avg);
        printf("\n");
    }
    for (size_t i = 0; i < sol->observer_count; ++i) {
        const cdl_observer_result *o = &sol->observers[i];
        const cdl_observer_spec *os = &scene->observers[i];
        printf("%-16s UGR ", os->name);
        if (o->defined) printf("%5.1f +- %.2g", o->ugr, o->ugr_stderr);
        else printf("%5s", "-");
        printf("  Lb %.4g cd/m2  %zu source%s in view", o->background_cd_m2, o->source_count,
               o->source_count == 1 ? "" : "s");
        if (os->required_ugr > 0.0 && o->defined)
            printf("  UGR_L %g: %s", os->required_ugr, o->ugr <= os->required_ugr ? "pass" : "FAIL");
        printf("\n");
    }
    printf("method %s, %.3f s, %llu rays", cdl_method_name(sol->method), sol->seconds, (unsigned long long)sol->rays);
    if (sol->rank_count > 1) printf(", %zu ranks", sol->rank_count);
    printf("; results in %s\n", a->out_dir);
    if (sol->power.luminaires_counted > 0)
        printf("installed power %.6g W (%zu luminaire%s%s)\n", sol->power.installed_w, sol->power.luminaires_counted,
               sol->power.luminaires_counted == 1 ? "" : "s",
               sol->power.luminaires_without_watts ? ", others without a wattage" : "");
    if (a->options.cache_path)
        printf("irradiance cache %s: %s\n", a->options.cache_path,
               sol->cache_reused ? "records read from it, none gathered" : "records gathered and written to it");
}

/* Rank 0, after the solve: the warnings (refused under --strict), then
 * the files. */
static cdl_status write_results(const cdl_scene *scene, const cdl_solution *sol, const solve_args *a,
                                cdl_error *err)
{
    /* No silent zeros: every warning on stderr; --strict refuses them
     * before any result is written. */
    for (size_t w = 0; w < sol->warning_count; ++w)
        fprintf(stderr, "candela solve: %s: %s\n", a->strict ? "error" : "warning", sol->warnings[w]);
    if (a->strict && sol->warning_count > 0)
        return cdl_error_set(err, CDL_ERR_INPUT, "%s: %zu warning%s, refused under --strict (see above); no results "
                                                 "written",
                             scene->path, sol->warning_count, sol->warning_count == 1 ? "" : "s");
    cdl_solution_write_options wo = CDL_SOLUTION_WRITE_OPTIONS_INIT;
    wo.ocio_config = a->ocio;
    wo.map_log_scale = a->log_scale;
    return cdl_solution_write(scene, sol, a->out_dir, &wo, err);
}

/* The solve on the ranks (one process alone without a launcher): every
 * rank loads the scene and solves its share; rank 0 prepares the folder,
 * writes and prints; after each step the ranks agree on how it went. */
static int solve(const solve_args *a, cdl_cli_ranks *ranks)
{
    int root = cdl_cli_ranks_root(ranks);
    cdl_solve_options so = a->options;
    progress_state shown = {-1.0, NULL};
    if (!a->quiet && root && isatty(STDERR_FILENO)) {
        so.progress.fn = progress;
        so.progress.user = &shown;
    }
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    cdl_status st = cdl_cli_ranks_agree(ranks, cdl_scene_load(a->scene, &scene, &err), &err);
    /* The output folder is checked before the solve, which may be long; a
     * folder made for this run and left empty by a failure is removed. */
    int folder_existed = root && access(a->out_dir, F_OK) == 0;
    if (st == CDL_OK)
        st = cdl_cli_ranks_agree(ranks, root ? cdl_solution_prepare_folder(a->out_dir, &err) : CDL_OK, &err);
    cdl_solution sol;
    memset(&sol, 0, sizeof sol);
    int prepared = st == CDL_OK;
    if (st == CDL_OK) {
        st = cdl_solve_scene_shared(scene, &so, NULL, &ranks->group, &sol, &err);
        if (st != CDL_OK && !ranks->group.failure_agreed && ranks->group.count > 1)
            cdl_cli_ranks_abort(ranks, "solve", (int)st, &err);
    }
    if (st == CDL_OK) st = cdl_cli_ranks_agree(ranks, root ? write_results(scene, &sol, a, &err) : CDL_OK, &err);
    if (st == CDL_OK && root) print_results(scene, &sol, a);
    cdl_solution_clear(&sol);
    if (st != CDL_OK) {
        fprintf(stderr, "candela solve: %s\n", err.message);
        if (root && prepared && !folder_existed) rmdir(a->out_dir); /* fails, as it should, unless empty */
    }
    cdl_scene_release(scene);
    return (int)st;
}

static int run(int argc, char **argv)
{
    cdl_cli_ranks ranks;
    int status = cdl_cli_ranks_begin("solve", &ranks);
    if (status == 0) {
        solve_args a;
        memset(&a, 0, sizeof a);
        status = parse(argc, argv, &a);
        if (status < 0) status = solve(&a, &ranks);
    }
    cdl_cli_ranks_end(&ranks);
    return status;
}

const cdl_command cdl_command_solve = {"solve", "compute illuminance on every grid of a scene", run, print_help};
