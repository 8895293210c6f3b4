/* command.c - shared behaviour of subcommands. */
#include "command.h"

#include <string.h>

int cdl_command_not_built(const cdl_command *command, int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            command->print_help(stdout);
            return CDL_EXIT_OK;
        }
    fprintf(stderr, "candela %s: not built yet in this version (%s)\n", command->name, CANDELA_VERSION);
    return CDL_EXIT_USAGE;
}
