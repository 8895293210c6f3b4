/* cmd_bench.c - `candela bench SCENE.json -o DIR`: the speed/accuracy trade
 * of each method on the user's scene, measured against a converged reference. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_args.h"
#include "cli_ranks.h"
#include "command.h"
#include "base/atomic_file.h"
#include "solver/bench/bench_ladder.h"
#include "solver/bench/bench_report.h"
#include "solver/output/solution_write.h"
#include "solver/pool.h"
#include "solver/solve_internal.h"

static void print_help(FILE *out)
{
    fputs("usage: candela bench SCENE.json -o DIR [--budget SECONDS] [--methods LIST]\n"
          "                     [--reference-points N] [--threads N] [--quiet]\n"
          "\n"
          "Solves the scene with a ladder of settings for each method and reports the\n"
          "error of each against a converged reference, with the time it took.\n"
          "\n"
          "  reference  path tracing to the \"reference\" quality (0.02 % relative standard\n"
          "             error per point) at a simple random sample of the grids' points\n"
          "             (--reference-points, default 24; every point when the grids have\n"
          "             no more), with a seed of its own so that its noise is independent\n"
          "             of the rungs'. Written to DIR/reference/ as `candela solve` writes\n"
          "             a scene whose grids are points grids of the sampled points, with\n"
          "             the hash of what it depends on (DIR/reference/reference.key:\n"
          "             geometry, materials, lights and their files, the sampled points,\n"
          "             seed, bounces, direct_samples). A later run reuses it when the\n"
          "             hash matches and refuses it (exit 1) when not: remove\n"
          "             DIR/reference to start anew.\n"
          "  ladder     icache and pathtrace: draft (2 %), 1 %, normal (0.5 %), 0.25 %,\n"
          "             high (0.1 %); direct: draft, normal, high. Each a whole solve with\n"
          "             the scene's seed, its files in DIR/runs/LABEL/ as `candela solve`\n"
          "             writes them. direct leaves out interreflected light: on a scene\n"
          "             that reflects, its error is mostly that.\n"
          "\n"
          "Each rung solves every point of the scene. For each: seconds (wall, whole\n"
          "solve), rays, cache records, the RMS and largest relative error of E against\n"
          "the reference at the reference's points (the reference's own noise removed\n"
          "from the RMS in quadrature), and the share of those points within 2 combined\n"
          "sigma. Over a sample the RMS estimates the RMS over all points; the table\n"
          "gives its standard error as that estimate (\"+-\"). An RMS not above 2x the\n"
          "reference's own stated RMS cannot be resolved: bench.csv has \"<ref\" in\n"
          "place of the figure, the table and the plot mark it and a note says so.\n"
          "\n"
          "Writes DIR/bench.csv (label,method,quality,target_error,seconds,rays,records,\n"
          "rms_rel_error,max_rel_error,within_2_sigma; errors as fractions, or \"<ref\";\n"
          "skipped rungs left out), DIR/bench.svg and DIR/bench.png (RMS error against\n"
          "seconds, log-log, the reference's error as a floor), and on stdout a table\n"
          "ending with the cheapest rung that reaches each preset's target. The same\n"
          "scene, seed and threads give the same bench.csv apart from its seconds column.\n"
          "\n"
          "Under mpirun (a build with MPI) every solve is shared by the ranks and gives\n"
          "the same files; rank 0's clock judges the budget, rank 0 writes and prints.\n"
          "\n"
          "options:\n"
          "  -o, --output DIR     folder for the results (required; created when missing)\n"
          "  --budget SECONDS     bound on the whole run (default 540; 0 = none): a rung\n"
          "                       whose estimated time (the method's previous rung scaled\n"
          "                       by (target ratio)^2) would not fit is skipped and listed;\n"
          "                       a reference that would not fit is exit 1, saying how long\n"
          "                       it needs (pilot solves from 2 %, tightened by 4x while\n"
          "                       cheap, the last scaled by (its target / 0.02 %)^2)\n"
          "  --reference-points N points the reference is path traced at (default 24, a\n"
          "                       simple random sample; 0 = every point of every grid)\n"
          "  --methods LIST       comma-separated from icache, pathtrace, direct (default\n"
          "                       icache,pathtrace; direct only when nothing reflects)\n"
          "  --threads N          worker threads (default: the scene's; 0 = all cores, or\n"
          "                       under mpirun the cores of the rank's binding)\n"
          "  --quiet              no progress lines on stderr\n"
          "\n"
          "exit status: 0 success, 1 bad scene, stale reference or too small a budget,\n"
          "2 usage error, 3 internal failure\n",
          out);
}

/* The run's settings from the command line. */
typedef struct bench_args {
    const char *scene_path, *dir;
    double budget;               /* seconds; 0: none */
    int methods[3];              /* direct, icache, pathtrace asked for */
    int threads;
    int quiet;
    size_t reference_points;     /* 0: every point */
    cdl_cli_ranks *ranks;        /* the ranks sharing every solve; rank 0 decides, writes and prints */
} bench_args;

/* The whole run's bound when --budget is not given: nine minutes, so that
 * a bench of a room-sized scene ends within ten. */
#define BENCH_DEFAULT_BUDGET 540.0

/* The reference's points when --reference-points is not given. Path
 * tracing the example office's (data/office) 24 to 0.02 % took 225
 * CPU-seconds, about 4 of the 20 CPU-minutes that ten minutes on two cores
 * give; the rest is the ladder's, whose 0.25 % path-tracing rung alone
 * takes about 2 (and its 0.1 % rung would take 11). The RMS of 24 points
 * estimates the RMS over all points to about 15 % (1/sqrt(2n) for errors
 * alike from point to point). */
#define BENCH_DEFAULT_REFERENCE_POINTS 24

static const cdl_method method_of[3] = {CDL_METHOD_DIRECT, CDL_METHOD_ICACHE, CDL_METHOD_PATHTRACE};

static int parse_methods(const char *list, int methods[3])
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", list);
    memset(methods, 0, 3 * sizeof *methods);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int found = 0;
        for (int m = 0; m < 3; ++m)
            if (strcmp(t, cdl_method_name(method_of[m])) == 0) methods[m] = found = 1;
        if (!found) {
            fprintf(stderr, "candela bench: --methods: expected icache, pathtrace or direct, found '%s'\n", t);
            return 0;
        }
    }
    return methods[0] || methods[1] || methods[2];
}

static int parse_args(int argc, char **argv, bench_args *a)
{
    cdl_cli_option opts[] = {
        {"output", 'o', 1, 0, NULL}, {"budget", 0, 1, 0, NULL},  {"methods", 0, 1, 0, NULL},
        {"threads", 0, 1, 0, NULL},  {"quiet", 'q', 0, 0, NULL},  {"reference-points", 0, 1, 0, NULL},
    };
    const size_t n = sizeof opts / sizeof opts[0];
    cdl_cli_result r;
    if (cdl_cli_scan(argc, argv, opts, n, &r) != 0) {
        fprintf(stderr, "candela bench: %s\n(see 'candela bench --help')\n", r.message);
        return CDL_EXIT_USAGE;
    }
    if (r.help) {
        print_help(stdout);
        return -1;
    }
    cdl_cli_option *out = cdl_cli_find(opts, n, "output");
    if (r.positional_count != 1 || !out->present || !out->value[0]) {
        fprintf(stderr, "candela bench: expected SCENE.json and -o DIR\n(see 'candela bench --help')\n");
        return CDL_EXIT_USAGE;
    }
    memset(a, 0, sizeof *a);
    a->scene_path = r.positional[0];
    a->dir = out->value;
    a->threads = -1;
    a->budget = BENCH_DEFAULT_BUDGET;
    a->quiet = cdl_cli_find(opts, n, "quiet")->present;
    cdl_cli_option *o = cdl_cli_find(opts, n, "budget");
    if (o->present) {
        char *end = NULL;
        a->budget = strtod(o->value, &end);
        if (!end || *end || end == o->value || !(a->budget >= 0.0) || !isfinite(a->budget)) {
            fprintf(stderr, "candela bench: --budget: expected seconds (0 = no bound), found '%s'\n", o->value);
            return CDL_EXIT_USAGE;
        }
    }
    if (cdl_cli_parse_threads("bench", cdl_cli_find(opts, n, "threads"), &a->threads)) return CDL_EXIT_USAGE;
    a->reference_points = BENCH_DEFAULT_REFERENCE_POINTS;
    o = cdl_cli_find(opts, n, "reference-points");
    if (o->present) {
        char *end = NULL;
        long v = strtol(o->value, &end, 10);
        if (!end || *end || end == o->value || v < 0 || v > 100000000L) {
            fprintf(stderr, "candela bench: --reference-points: expected a count of points (0 = every point), found '%s'\n",
                    o->value);
            return CDL_EXIT_USAGE;
        }
        a->reference_points = (size_t)v;
    }
    o = cdl_cli_find(opts, n, "methods");
    if (o->present) {
        if (!parse_methods(o->value, a->methods)) return CDL_EXIT_USAGE;
    } else {
        a->methods[1] = a->methods[2] = 1;
    }
    return CDL_EXIT_OK;
}

/* One solve on the ranks (rank 0 gets the solution; a failure of one
 * rank alone ends them all). */
static cdl_status solve_rung(const bench_args *a, const cdl_scene *scene, cdl_method method, double target,
                             cdl_solution *sol, cdl_error *err)
{
    cdl_rank_group *group = &a->ranks->group;
    cdl_status st = cdl_bench_solve_rung(scene, method, target, a->threads, group, sol, err);
    if (st != CDL_OK && !group->failure_agreed && group->count > 1)
        cdl_cli_ranks_abort(a->ranks, "bench", (int)st, err);
    return st;
}

/* Solve one rung and write its files into `dir` (rank 0). */
static cdl_status solve_into(const bench_args *a, const cdl_scene *scene, cdl_method method, double target,
                             const char *dir, cdl_solution *sol, cdl_error *err)
{
    int root = cdl_cli_ranks_root(a->ranks);
    memset(sol, 0, sizeof *sol);
    cdl_status st = cdl_cli_ranks_agree(a->ranks, root ? cdl_solution_prepare_folder(dir, err) : CDL_OK, err);
    if (st == CDL_OK) st = solve_rung(a, scene, method, target, sol, err);
    if (st != CDL_OK) return st;
    st = cdl_cli_ranks_agree(a->ranks, root ? cdl_solution_write(scene, sol, dir, NULL, err) : CDL_OK, err);
    if (st != CDL_OK) cdl_solution_clear(sol);
    return st;
}

/* How long path tracing the reference to `target` takes. Monte Carlo
 * time goes as target^-2 (the per-point work; Kalos and Whitlock, Monte
 * Carlo Methods, ch. 2), the setup not at all; but a loose target hits the
 * solver's floor of samples per point and the scaling overstates. So
 * pilots start at the draft target and are tightened by 4 while the next
 * (about 16 times as long) takes under a twentieth of the budget; the last
 * one is scaled. */
static cdl_status estimate_reference(const cdl_scene *scene, const bench_args *a, double target, double *need,
                                     double *pilot_target, double *pilot_compute, cdl_error *err)
{
    double t = cdl_quality_target_error(CDL_QUALITY_DRAFT);
    for (;;) {
        cdl_solution pilot;
        cdl_status st = solve_rung(a, scene, CDL_METHOD_PATHTRACE, t, &pilot, err);
        if (st != CDL_OK) return st;
        double ratio = t / target;
        /* Rank 0's clock decides: need, the pilot's target and computing
         * time, and whether to stop here. */
        double said[4] = {(pilot.seconds - pilot.compute_seconds) + pilot.compute_seconds * ratio * ratio, t,
                          pilot.compute_seconds, 0.0};
        double next = 16.0 * pilot.seconds;
        said[3] = t / 4.0 < 4.0 * target || next > a->budget / 20.0;
        cdl_solution_clear(&pilot);
        cdl_cli_ranks_follow(a->ranks, "bench", said, sizeof said);
        *need = said[0];
        *pilot_target = said[1];
        *pilot_compute = said[2];
        if (said[3] != 0.0) return CDL_OK;
        t /= 4.0;
    }
}

#define KEY_HEADER "candela bench reference 2"

/* What rank 0 finds in DIR/reference/reference.key: nothing (0), the
 * scene's key (1) or another (2, with the key it holds). */
static int read_key(const char *keypath, uint64_t key, unsigned long long *stored)
{
    FILE *kf = fopen(keypath, "r");
    if (!kf) return 0;
    char line[128] = "";
    int ok = fgets(line, sizeof line, kf) && strncmp(line, KEY_HEADER, strlen(KEY_HEADER)) == 0 &&
             fscanf(kf, " key %llx", stored) == 1;
    fclose(kf);
    return ok && *stored == key ? 1 : 2;
}

/* Path trace the reference into `dir` (its key beside it), when the budget
 * allows; rank 0 judges the budget on its clock. */
static int make_reference(const cdl_bench_sample *sample, const bench_args *a, double target, double t0,
                          const char *dir, const char *keypath, uint64_t key)
{
    const cdl_scene *scene = &sample->scene;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_status st = CDL_OK;
    if (a->budget > 0.0) {
        double need = 0.0, pilot_target = 0.0, pilot_compute = 0.0;
        st = estimate_reference(scene, a, target, &need, &pilot_target, &pilot_compute, &err);
        if (st != CDL_OK) {
            fprintf(stderr, "candela bench: %s\n", err.message);
            return (int)st;
        }
        double spent = cdl_pool_now_seconds() - t0;
        cdl_cli_ranks_follow(a->ranks, "bench", &spent, sizeof spent);
        if (spent + need > a->budget) {
            fprintf(stderr,
                    "candela bench: --budget %g s is too small: the reference (path tracing to %g %%) needs about "
                    "%.3g s at %zu points (a pilot to %g %% took %.3g s of computing, scaled by (%g/%g)^2), after "
                    "the %.3g s the pilots took; give a larger --budget or fewer --reference-points\n",
                    a->budget, 100.0 * target, need, sample->count, 100.0 * pilot_target, pilot_compute,
                    pilot_target, target, spent);
            return CDL_EXIT_INPUT;
        }
    }
    if (!a->quiet) fprintf(stderr, "candela bench: reference: path tracing to %g %%\n", 100.0 * target);
    cdl_solution sol;
    st = solve_into(a, scene, CDL_METHOD_PATHTRACE, target, dir, &sol, &err);
    if (st == CDL_OK) {
        printf("reference: path traced to %g %% in %.2f s, %llu rays; written to %s\n", 100.0 * target, sol.seconds,
               (unsigned long long)sol.rays, dir);
        cdl_solution_clear(&sol);
        char text[256];
        int len = snprintf(text, sizeof text, KEY_HEADER "\nkey %016llx\ntarget %.17g\npoints %zu of %zu\n",
                           (unsigned long long)key, target, sample->count, sample->total);
        st = cdl_cli_ranks_agree(a->ranks,
                                 cdl_cli_ranks_root(a->ranks) ? cdl_atomic_file_write_all(keypath, text, (size_t)len,
                                                                                          &err)
                                                              : CDL_OK,
                                 &err);
    }
    if (st != CDL_OK) fprintf(stderr, "candela bench: %s\n", err.message);
    return (int)st;
}

/* The reference: read from DIR/reference when its key matches (refused
 * when not), else path traced to `target` (within the budget) at the
 * sample's points and written there with its key. Read back from its CSV
 * either way, so a fresh and a reused reference give the same figures
 * (rank 0 reads it: the only rank that measures). */
static int get_reference(const cdl_bench_sample *sample, const bench_args *a, double target, double t0,
                         cdl_solution *ref)
{
    const cdl_scene *scene = &sample->scene;
    memset(ref, 0, sizeof *ref);
    cdl_error err;
    cdl_error_clear(&err);
    char dir[4096], keypath[4200];
    snprintf(dir, sizeof dir, "%s/reference", a->dir);
    snprintf(keypath, sizeof keypath, "%s/reference.key", dir);
    uint64_t key = 0;
    cdl_status st = cdl_bench_reference_key(scene, target, &key, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        return (int)st;
    }
    unsigned long long found[2] = {0, 0}; /* what rank 0 found, the key it holds */
    if (cdl_cli_ranks_root(a->ranks)) found[0] = (unsigned long long)read_key(keypath, key, &found[1]);
    cdl_cli_ranks_follow(a->ranks, "bench", found, sizeof found);
    if (found[0] == 2) {
        fprintf(stderr,
                "candela bench: %s: the reference there was made for another scene or other settings (its hash "
                "%016llx, this scene's %016llx: geometry, materials, lights, grids, the sampled points, seed or "
                "bounces changed); "
                "remove %s to compute a new one\n",
                dir, found[1], (unsigned long long)key, dir);
        return CDL_EXIT_INPUT;
    }
    if (found[0] == 1) {
        printf("reference: reused %s (scene and settings hash %016llx match)\n", dir, (unsigned long long)key);
    } else {
        int rc = make_reference(sample, a, target, t0, dir, keypath, key);
        if (rc != CDL_EXIT_OK) return rc;
    }
    st = cdl_cli_ranks_agree(a->ranks, cdl_cli_ranks_root(a->ranks) ? cdl_bench_reference_read(dir, scene, ref, &err)
                                                                     : CDL_OK,
                             &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        return (int)st;
    }
    return CDL_EXIT_OK;
}

/* The rungs of a method: its presets and targets between them. */
typedef struct rung_spec {
    const char *quality, *suffix;
    double target;
} rung_spec;

static const rung_spec gi_rungs[] = {{"draft", "draft", 0.02},    {"custom", "t0.01", 0.01},
                                     {"normal", "normal", 0.005}, {"custom", "t0.0025", 0.0025},
                                     {"high", "high", 0.001}};
static const rung_spec direct_rungs[] = {{"draft", "draft", 0.02}, {"normal", "normal", 0.005}, {"high", "high", 0.001}};

/* Run one method's ladder into rows (appended at *count). */
static int run_ladder(const cdl_scene *scene, const bench_args *a, int m, const cdl_bench_sample *sample,
                      const cdl_solution *ref, double ref_rms, double t0, cdl_bench_row *rows, size_t *count)
{
    const rung_spec *specs = m == 0 ? direct_rungs : gi_rungs;
    int n = m == 0 ? 3 : 5;
    const cdl_bench_row *prev = NULL;
    for (int k = 0; k < n; ++k) {
        cdl_bench_row *row = &rows[(*count)++];
        memset(row, 0, sizeof *row);
        snprintf(row->label, sizeof row->label, "%s_%s", cdl_method_name(method_of[m]), specs[k].suffix);
        row->quality = specs[k].quality;
        row->rung.method = method_of[m];
        row->rung.target = specs[k].target;
        if (a->budget > 0.0) {
            /* Monte Carlo: time ~ target^-2 at a fixed cost per sample; a
             * method's first rung is run when any budget is left. Rank 0's
             * clock decides. */
            double ratio = prev ? prev->rung.target / specs[k].target : 0.0;
            double need = prev ? prev->rung.seconds * ratio * ratio : 0.0;
            int skip = cdl_pool_now_seconds() - t0 + need >= a->budget;
            cdl_cli_ranks_follow(a->ranks, "bench", &skip, sizeof skip);
            if (skip) {
                row->skipped = 1;
                continue;
            }
        }
        if (!a->quiet) fprintf(stderr, "candela bench: %s (target %g %%)\n", row->label, 100.0 * specs[k].target);
        char dir[4200];
        snprintf(dir, sizeof dir, "%s/runs/%s", a->dir, row->label);
        cdl_error err;
        cdl_error_clear(&err);
        cdl_solution sol;
        cdl_status st = solve_into(a, scene, method_of[m], specs[k].target, dir, &sol, &err);
        if (st != CDL_OK) {
            fprintf(stderr, "candela bench: %s: %s\n", row->label, err.message);
            return (int)st;
        }
        /* Rank 0 holds the solution and the reference (the others' rows are never written). */
        if (cdl_cli_ranks_root(a->ranks)) cdl_bench_rung_measure(&sol, ref, sample, &row->rung);
        cdl_solution_clear(&sol);
        /* an exact reference (no stated error) resolves everything */
        row->below_reference = ref_rms > 0.0 && row->rung.rms <= CDL_BENCH_RESOLVABLE * ref_rms;
        prev = row;
    }
    return CDL_EXIT_OK;
}

static void print_table(const cdl_bench_row *rows, size_t count, double ref_rms)
{
    printf("\n%-18s %-9s %-7s %8s %9s %12s %8s %17s %10s %9s %9s\n", "label", "method", "quality", "target",
           "seconds", "rays", "records", "rms_rel", "max_rel", "within_2s", "stated");
    int flagged = 0;
    for (size_t k = 0; k < count; ++k) {
        const cdl_bench_row *r = &rows[k];
        if (r->skipped) {
            printf("%-18s %-9s %-7s %7.3g%% skipped: would not fit the budget\n", r->label,
                   cdl_method_name(r->rung.method), r->quality, 100.0 * r->rung.target);
            continue;
        }
        char rms[48];
        if (r->below_reference)
            snprintf(rms, sizeof rms, "<ref");
        else if (r->rung.rms_sd > 0.0)
            snprintf(rms, sizeof rms, "%.3f%% +-%.3f%%", 100.0 * r->rung.rms, 100.0 * r->rung.rms_sd);
        else
            snprintf(rms, sizeof rms, "%.3f%%", 100.0 * r->rung.rms);
        flagged |= r->below_reference;
        printf("%-18s %-9s %-7s %7.3g%% %9.3f %12llu %8llu %17s %9.3f%% %8.1f%% %8.3f%%\n", r->label,
               cdl_method_name(r->rung.method), r->quality, 100.0 * r->rung.target, r->rung.seconds,
               (unsigned long long)r->rung.rays, (unsigned long long)r->rung.records, rms, 100.0 * r->rung.worst,
               100.0 * r->rung.within2, 100.0 * r->rung.stated_rms);
    }
    if (flagged)
        printf("note: \"<ref\": the RMS error is not above %g x the reference's own stated RMS (%.4f %%), so the "
               "reference cannot resolve it (bench.csv says \"<ref\" in place of a figure)\n",
               CDL_BENCH_RESOLVABLE, 100.0 * ref_rms);
    printf("\nrecommendation (cheapest rung whose measured RMS error reaches the preset's target on this scene):\n");
    static const cdl_quality presets[3] = {CDL_QUALITY_DRAFT, CDL_QUALITY_NORMAL, CDL_QUALITY_HIGH};
    for (int q = 0; q < 3; ++q) {
        double t = cdl_quality_target_error(presets[q]);
        const cdl_bench_row *best = NULL;
        for (size_t k = 0; k < count; ++k) {
            const cdl_bench_row *r = &rows[k];
            if (r->skipped || r->rung.rms > t) continue;
            if (!best || r->rung.seconds < best->rung.seconds) best = r;
        }
        if (best && best->below_reference)
            printf("  %-7s (%g %%): %s, %.2f s, RMS below the reference's resolution (<ref)\n",
                   cdl_quality_name(presets[q]), 100.0 * t, best->label, best->rung.seconds);
        else if (best)
            printf("  %-7s (%g %%): %s, %.2f s, RMS %.3f %%\n", cdl_quality_name(presets[q]), 100.0 * t, best->label,
                   best->rung.seconds, 100.0 * best->rung.rms);
        else
            printf("  %-7s (%g %%): no rung run reached it\n", cdl_quality_name(presets[q]), 100.0 * t);
    }
}

/* Say where the reference is computed and what that means for the RMS. */
static void print_sample(const cdl_bench_sample *sample)
{
    if (sample->count < sample->total)
        printf("reference points: %zu of the grids' %zu, a simple random sample; each rung is solved at every point "
               "and measured at these, so its RMS estimates the RMS over all points, given +- its standard error as "
               "that estimate (max_rel and within_2s are over the sample)\n",
               sample->count, sample->total);
    else
        printf("reference points: every one of the grids' %zu\n", sample->total);
}

/* bench.csv, bench.svg and bench.png. */
static cdl_status write_reports(const bench_args *a, const cdl_bench_row *rows, size_t count, double ref_rms,
                                cdl_error *err)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/bench.csv", a->dir);
    cdl_status st = cdl_bench_report_write_csv(path, rows, count, err);
    snprintf(path, sizeof path, "%s/bench.svg", a->dir);
    if (st == CDL_OK) st = cdl_bench_report_write_svg(path, rows, count, ref_rms, err);
    snprintf(path, sizeof path, "%s/bench.png", a->dir);
    if (st == CDL_OK) st = cdl_bench_report_write_png(path, rows, count, ref_rms, err);
    return st;
}

static int bench(const bench_args *a, cdl_scene *scene)
{
    double t0 = cdl_pool_now_seconds();
    int methods[3] = {a->methods[0], a->methods[1], a->methods[2]};
    double rho = 0.0;
    const char *reflector = cdl_solve_first_reflector(scene, &rho);
    if (!reflector) {
        printf("no surface reflects light (every reflectance is 0): interreflected light is zero and icache and "
               "pathtrace would compute direct light only, so only the direct method is benched\n");
        methods[0] = 1;
        methods[1] = methods[2] = 0;
    }
    if (reflector && methods[0])
        printf("note: method direct leaves out interreflected light (%s reflects %g %%): its error against the "
               "reference is mostly that light\n",
               reflector, 100.0 * rho);
    cdl_error err;
    cdl_error_clear(&err);
    char path[4200];
    snprintf(path, sizeof path, "%s/runs", a->dir);
    int root = cdl_cli_ranks_root(a->ranks);
    int dir_existed = root && access(a->dir, F_OK) == 0;
    cdl_status st = root ? cdl_solution_prepare_folder(a->dir, &err) : CDL_OK;
    if (st == CDL_OK && root) st = cdl_solution_prepare_folder(path, &err);
    st = cdl_cli_ranks_agree(a->ranks, st, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        return (int)st;
    }
    double ref_target = cdl_quality_target_error(CDL_QUALITY_REFERENCE);
    cdl_bench_sample sample;
    st = cdl_bench_sample_build(scene, a->reference_points, &sample, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        return (int)st;
    }
    print_sample(&sample);
    cdl_solution ref;
    int rc = get_reference(&sample, a, ref_target, t0, &ref);
    if (rc != CDL_EXIT_OK) {
        cdl_bench_sample_release(&sample);
        /* folders this run made and left empty go (rmdir refuses others) */
        if (root) {
            rmdir(path);
            snprintf(path, sizeof path, "%s/reference", a->dir);
            rmdir(path);
            if (!dir_existed) rmdir(a->dir);
        }
        return rc;
    }
    double ref_rms = cdl_bench_stated_rms(&ref);
    printf("reference's own stated RMS error: %.4f %%\n", 100.0 * ref_rms);

    cdl_bench_row rows[16];
    size_t count = 0;
    for (int m = 0; m < 3 && rc == CDL_EXIT_OK; ++m)
        if (methods[m]) rc = run_ladder(scene, a, m, &sample, &ref, ref_rms, t0, rows, &count);
    cdl_solution_clear(&ref);
    cdl_bench_sample_release(&sample);
    if (rc != CDL_EXIT_OK) return rc;

    if (root) st = write_reports(a, rows, count, ref_rms, &err);
    st = cdl_cli_ranks_agree(a->ranks, st, &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        return (int)st;
    }
    print_table(rows, count, ref_rms);
    printf("\nresults in %s (bench.csv, bench.svg, bench.png, reference/, runs/); %.1f s in all\n", a->dir, cdl_pool_now_seconds() - t0);
    return CDL_EXIT_OK;
}

/* Every rank loads the scene and shares each solve; rank 0 decides from
 * its clock and its files, writes and prints (cli_ranks.h). */
static int bench_on_ranks(bench_args *a, cdl_cli_ranks *ranks)
{
    a->ranks = ranks;
    cdl_error err;
    cdl_error_clear(&err);
    cdl_scene *scene = NULL;
    cdl_status st = cdl_cli_ranks_agree(ranks, cdl_scene_load(a->scene_path, &scene, &err), &err);
    if (st != CDL_OK) {
        fprintf(stderr, "candela bench: %s\n", err.message);
        cdl_scene_release(scene);
        return (int)st;
    }
    int rc = bench(a, scene);
    cdl_scene_release(scene);
    return rc;
}

static int run(int argc, char **argv)
{
    cdl_cli_ranks ranks;
    int rc = cdl_cli_ranks_begin("bench", &ranks);
    if (rc == 0) {
        bench_args a;
        rc = parse_args(argc, argv, &a);
        if (rc == CDL_EXIT_OK) rc = bench_on_ranks(&a, &ranks);
        else if (rc < 0) rc = CDL_EXIT_OK;
    }
    cdl_cli_ranks_end(&ranks);
    return rc;
}

const cdl_command cdl_command_bench = {"bench", "speed/accuracy trade: a ladder of settings vs a converged reference",
                                       run, print_help};
