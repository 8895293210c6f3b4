/* cmd_solve.c - `candela solve`. */
#include "command.h"

static void print_help(FILE *out)
{
    fputs("usage: candela solve SCENE.json -o OUTDIR [--quiet]\n"
          "\n"
          "Computes illuminance in lux on every calculation grid of the scene and\n"
          "writes NAME.csv, NAME.exr, NAME.png per grid and summary.json into OUTDIR.\n", out);
}

static int run(int argc, char **argv)
{
    return cdl_command_not_built(&cdl_command_solve, argc, argv);
}

const cdl_command cdl_command_solve = {"solve", "compute illuminance on every grid of a scene", run, print_help};
