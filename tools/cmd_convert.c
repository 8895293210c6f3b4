/* cmd_convert.c - `candela convert`. */
#include "command.h"

static void print_help(FILE *out)
{
    fputs("usage: candela convert IN OUT [options]\n"
          "\n"
          "Converts between IES LM-63 (.ies) and EULUMDAT (.ldt), formats chosen by\n"
          "file extension. Any LM-63 version is read; LM-63-2019 is written by default.\n", out);
}

static int run(int argc, char **argv)
{
    return cdl_command_not_built(&cdl_command_convert, argc, argv);
}

const cdl_command cdl_command_convert = {"convert", "convert IES <-> EULUMDAT (by extension); LM-63-2019 or -2002 out", run, print_help};
