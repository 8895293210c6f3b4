/* cli_args.h - a small, strict command-line option scanner for subcommands.
 *
 * Options are declared in a table; "--name value", "--name=value", "-x value"
 * and flags are accepted; "--" ends options; anything else is positional.
 * An unknown option or a missing value is a usage error with a message.
 */
#ifndef CANDELA_TOOLS_CLI_ARGS_H
#define CANDELA_TOOLS_CLI_ARGS_H

#include <stddef.h>

typedef struct cdl_cli_option {
    const char *long_name;   /* without the dashes, e.g. "json" */
    char short_name;         /* e.g. 'o', or 0 */
    int takes_value;         /* 1: needs a value */
    /* results */
    int present;
    const char *value;
} cdl_cli_option;

typedef struct cdl_cli_result {
    const char *positional[4096];
    size_t positional_count;
    int help;                 /* --help or -h seen */
    char message[256];        /* usage error text when the scan fails */
} cdl_cli_result;

/* Scan argv[1..argc-1] (argv[0] is the subcommand). Returns 0 on success, 2
 * on a usage error (message filled). */
int cdl_cli_scan(int argc, char **argv, cdl_cli_option *options, size_t option_count, cdl_cli_result *result);

/* The option named long_name, or NULL. */
cdl_cli_option *cdl_cli_find(cdl_cli_option *options, size_t option_count, const char *long_name);

/* The value of a --threads option, when present, into *threads (left as it
 * is otherwise): a whole number 0..4096. Returns 0, or 2 after saying on
 * stderr what was found ("candela COMMAND: --threads: ..."). */
int cdl_cli_parse_threads(const char *command, const cdl_cli_option *option, int *threads);

#endif
