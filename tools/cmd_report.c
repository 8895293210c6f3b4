/* cmd_report.c - `candela report`. */
#include "command.h"

static void print_help(FILE *out)
{
    fputs("usage: candela report OUTDIR\n"
          "\n"
          "Writes a lighting-design report (HTML, printable to PDF) from the results\n"
          "of `candela solve` in OUTDIR.\n", out);
}

static int run(int argc, char **argv)
{
    return cdl_command_not_built(&cdl_command_report, argc, argv);
}

const cdl_command cdl_command_report = {"report", "lighting-design report (HTML, printable to PDF) from a solve", run, print_help};
