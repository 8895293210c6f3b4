/* command.h - the subcommands of `candela`.
 *
 * Each subcommand lives in its own file tools/cmd_<name>.c and provides a
 * run function (argv[0] is the subcommand name) returning the exit status
 * (0 success, 1 bad input, 2 usage error, 3 internal or resource failure)
 * and a help printer.
 */
#ifndef CANDELA_TOOLS_COMMAND_H
#define CANDELA_TOOLS_COMMAND_H

#include <stdio.h>

typedef struct cdl_command {
    const char *name;
    const char *summary;             /* one line for `candela --help` */
    int (*run)(int argc, char **argv);
    void (*print_help)(FILE *out);
} cdl_command;

extern const cdl_command cdl_command_info;
extern const cdl_command cdl_command_convert;
extern const cdl_command cdl_command_solve;
extern const cdl_command cdl_command_report;
extern const cdl_command cdl_command_bench;
extern const cdl_command cdl_command_sun;
extern const cdl_command cdl_command_annual;

/* Exit statuses, identical to cdl_status values. */
enum { CDL_EXIT_OK = 0, CDL_EXIT_INPUT = 1, CDL_EXIT_USAGE = 2, CDL_EXIT_INTERNAL = 3 };

#endif
