/* cmd_report.c - `candela report`. */
#include <stdio.h>

#include "cli_args.h"
#include "command.h"
#include "report/report.h"

static void print_help(FILE *out)
{
    fputs("usage: candela report OUTDIR [--title TEXT] [--requirements FILE]\n"
          "\n"
          "Writes OUTDIR/report.html (one self-contained file: inline figures, no\n"
          "network, printable) and OUTDIR/report.pdf (A4) from the results of\n"
          "`candela solve SCENE -o OUTDIR`: a cover (scene, date, version, method,\n"
          "quality, seed, solve time), a summary table per grid (Em, Emin, Emax, U0,\n"
          "Ud, points, spacing, stated errors; pass or fail against requirements), a\n"
          "false-colour map per rect and polygon grid with isolux lines, the plan and\n"
          "the luminaires, the luminaire schedule with polar diagrams, and the method\n"
          "and its accuracy. Numbers are summary.json's, printed to the precision\n"
          "their stated error justifies.\n"
          "From the folder of `candela annual`, a daylight report instead: the weather,\n"
          "sky and occupancy; per grid sDA300/50%, ASE1000,250h, DA300, UDI and EN\n"
          "17037's daylight provision per level with the coefficients' stated error;\n"
          "the study's maps; the method and what it leaves out.\n"
          "\n"
          "  --title TEXT           the report's title (default: Lighting report: SCENE)\n"
          "  --requirements FILE    JSON {\"GRID\": {\"Em_lx\": 500, \"U0\": 0.6}, ...}: what each\n"
          "                         grid must reach (EN 12464-1); overrides the scene grids'\n"
          "                         own \"requirements\"\n"
          "\n"
          "OUTDIR must hold summary.json written by this Candela version, the scene it\n"
          "names and every grid's CSV from the same solve; otherwise exit 1, naming\n"
          "what is missing or stale. Both files are written atomically.\n",
          out);
}

static int run(int argc, char **argv)
{
    cdl_cli_option options[] = {{"title", 0, 1, 0, NULL}, {"requirements", 0, 1, 0, NULL}};
    const size_t count = sizeof options / sizeof options[0];
    cdl_cli_result r;
    if (cdl_cli_scan(argc, argv, options, count, &r) != 0) {
        fprintf(stderr, "candela report: %s\n(see 'candela report --help')\n", r.message);
        return CDL_EXIT_USAGE;
    }
    if (r.help) {
        print_help(stdout);
        return CDL_EXIT_OK;
    }
    if (r.positional_count != 1) {
        fprintf(stderr, "candela report: expected one OUTDIR (the folder of a solve's results), found %zu\n"
                        "(see 'candela report --help')\n",
                r.positional_count);
        return CDL_EXIT_USAGE;
    }
    const cdl_cli_option *title = cdl_cli_find(options, count, "title");
    const cdl_cli_option *req = cdl_cli_find(options, count, "requirements");
    cdl_report_options opts = {.title = title->present ? title->value : NULL,
                               .requirements_path = req->present ? req->value : NULL};
    cdl_error err;
    cdl_status status = cdl_report_write(r.positional[0], &opts, &err);
    if (status != CDL_OK) {
        fprintf(stderr, "candela report: %s\n", err.message);
        return (int)status;
    }
    printf("%s/report.html\n%s/report.pdf\n", r.positional[0], r.positional[0]);
    return CDL_EXIT_OK;
}

const cdl_command cdl_command_report = {"report", "lighting-design report (HTML and PDF) from a solve or an annual study", run,
                                        print_help};
