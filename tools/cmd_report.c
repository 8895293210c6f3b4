/* cmd_report.c - `candela report`. */
#include <stdio.h>

#include "cli_args.h"
#include "command.h"
#include "report/report.h"

static void print_help(FILE *out)
{
    fputs("usage: candela report OUTDIR [--title TEXT] [--project FILE] [--requirements FILE] [--values]\n"
          "\n"
          "Writes OUTDIR/report.html (one self-contained file: inline figures, no\n"
          "network, printable) and OUTDIR/report.pdf (A4) from the results of\n"
          "`candela solve SCENE -o OUTDIR`: a cover (the scene's name as the title, the\n"
          "project block, the solve's date, version, method, quality, seed and time), a\n"
          "summary (per grid Em, Emin, Emax, U0, Ud, points, spacing and stated errors,\n"
          "pass or fail against requirements; every other quantity the grids ask for:\n"
          "Ez, Esz, L, AO; installed power and power density), the room and its\n"
          "surfaces (dimensions, areas, reflectances), every luminaire placed (product\n"
          "and catalogue number from its file, position, mounting height, rotation or\n"
          "aim point, maintenance factor), the schedule of luminaire types with polar\n"
          "diagrams, a false-colour map per quantity of each rect and polygon grid\n"
          "(contour lines, the luminaires' footprints and aiming lines, the surfaces'\n"
          "outlines), and the method and its accuracy, naming each light and grid.\n"
          "Numbers are summary.json's, printed to the precision their stated error\n"
          "justifies.\n"
          "From the folder of `candela annual`, a daylight report instead: the weather,\n"
          "sky and occupancy; per grid sDA300/50%, ASE1000,250h, DA300, UDI and EN\n"
          "17037's daylight provision per level with the coefficients' stated error;\n"
          "the study's maps; the method and what it leaves out.\n"
          "\n"
          "  --title TEXT           the report's title (default: the scene's \"name\", else\n"
          "                         its file's name without the extension)\n"
          "  --project FILE         JSON {\"project\", \"client\", \"designer\", \"date\",\n"
          "                         \"notes\"} (each optional): the cover's project block;\n"
          "                         its fields replace the scene's \"project\" one by one\n"
          "  --requirements FILE    JSON {\"GRID\": {\"Em_lx\": 500, \"U0\": 0.6}, ...}: what each\n"
          "                         grid must reach (EN 12464-1); overrides the scene grids'\n"
          "                         own \"requirements\"\n"
          "  --values               add a table of each grid's values at its points, laid\n"
          "                         out as its map\n"
          "\n"
          "OUTDIR must hold summary.json written by this Candela version, the scene it\n"
          "names, unchanged since the solve (summary.json records a hash of every part\n"
          "of it and of every file it reads: a changed part is named), and every grid's\n"
          "CSV from the same solve; otherwise exit 1, naming what is missing or stale.\n"
          "The project block, the title and the requirements may change after a solve.\n"
          "Both files are written atomically.\n",
          out);
}

static int run(int argc, char **argv)
{
    cdl_cli_option options[] = {{"title", 0, 1, 0, NULL},
                                {"requirements", 0, 1, 0, NULL},
                                {"project", 0, 1, 0, NULL},
                                {"values", 0, 0, 0, NULL}};
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
    const cdl_cli_option *project = cdl_cli_find(options, count, "project");
    cdl_report_options opts = {.title = title->present ? title->value : NULL,
                               .requirements_path = req->present ? req->value : NULL,
                               .project_path = project->present ? project->value : NULL,
                               .values = cdl_cli_find(options, count, "values")->present};
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
