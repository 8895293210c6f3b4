/* cmd_info.c - `candela info`. */
#include "command.h"

static void print_help(FILE *out)
{
    fputs("usage: candela info LUMINAIRE [--json] [--strict]\n"
          "\n"
          "Reads an IES LM-63 (any version) or EULUMDAT file and prints a summary:\n"
          "format and version, photometric type, symmetry, angle grid, lamp and\n"
          "integrated flux, light output ratio, efficacy, maximum intensity and its\n"
          "direction, beam (50 %) and field (10 %) angles, downward fraction, warnings.\n"
          "\n"
          "  --json     one JSON object on stdout instead of text\n"
          "  --strict   treat warnings (inconsistent header values) as errors\n", out);
}

static int run(int argc, char **argv)
{
    return cdl_command_not_built(&cdl_command_info, argc, argv);
}

const cdl_command cdl_command_info = {"info", "summarise a luminaire file: format, flux, efficacy, beam/field angles, symmetry, max cd", run, print_help};
