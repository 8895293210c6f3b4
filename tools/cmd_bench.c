/* cmd_bench.c - `candela bench`. */
#include "command.h"

static void print_help(FILE *out)
{
    fputs("usage: candela bench SCENE.json\n"
          "\n"
          "Solves the scene with a ladder of settings and reports the error of each\n"
          "against a converged reference, with the time it took.\n", out);
}

static int run(int argc, char **argv)
{
    return cdl_command_not_built(&cdl_command_bench, argc, argv);
}

const cdl_command cdl_command_bench = {"bench", "speed/accuracy trade: a ladder of settings vs a converged reference", run, print_help};
