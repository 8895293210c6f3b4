/* cli_args.c - command-line option scanning. */
#include "cli_args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

cdl_cli_option *cdl_cli_find(cdl_cli_option *options, size_t count, const char *long_name)
{
    for (size_t i = 0; i < count; ++i)
        if (strcmp(options[i].long_name, long_name) == 0) return &options[i];
    return NULL;
}

int cdl_cli_scan(int argc, char **argv, cdl_cli_option *options, size_t count, cdl_cli_result *r)
{
    memset(r, 0, sizeof *r);
    int only_positional = 0;
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i];
        cdl_cli_option *opt = NULL;
        const char *inline_value = NULL;
        if (!only_positional && strcmp(arg, "--") == 0) {
            only_positional = 1;
            continue;
        }
        if (!only_positional && (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)) {
            r->help = 1;
            continue;
        }
        if (!only_positional && arg[0] == '-' && arg[1] == '-' && arg[2]) {
            char name[64];
            const char *eq = strchr(arg + 2, '=');
            size_t n = eq ? (size_t)(eq - (arg + 2)) : strlen(arg + 2);
            if (n >= sizeof name) n = sizeof name - 1;
            memcpy(name, arg + 2, n);
            name[n] = '\0';
            opt = cdl_cli_find(options, count, name);
            if (eq) inline_value = eq + 1;
        } else if (!only_positional && arg[0] == '-' && arg[1] && !arg[2] && !(arg[1] >= '0' && arg[1] <= '9')) {
            for (size_t k = 0; k < count; ++k)
                if (options[k].short_name == arg[1]) opt = &options[k];
        } else {
            if (r->positional_count >= sizeof r->positional / sizeof r->positional[0]) {
                snprintf(r->message, sizeof r->message, "too many arguments");
                return 2;
            }
            r->positional[r->positional_count++] = arg;
            continue;
        }
        if (!opt) {
            snprintf(r->message, sizeof r->message, "unknown option '%s'", arg);
            return 2;
        }
        opt->present = 1;
        if (opt->takes_value) {
            if (inline_value) {
                opt->value = inline_value;
            } else if (i + 1 < argc) {
                opt->value = argv[++i];
            } else {
                snprintf(r->message, sizeof r->message, "option '%s' needs a value", arg);
                return 2;
            }
        } else if (inline_value) {
            snprintf(r->message, sizeof r->message, "option '--%s' takes no value", opt->long_name);
            return 2;
        }
    }
    return 0;
}

int cdl_cli_parse_threads(const char *command, const cdl_cli_option *option, int *threads)
{
    if (!option->present) return 0;
    char *end = NULL;
    long t = strtol(option->value, &end, 10);
    if (!end || *end || t < 0 || t > 4096) {
        fprintf(stderr, "candela %s: --threads: expected a whole number 0..4096, found '%s'\n", command, option->value);
        return 2;
    }
    *threads = (int)t;
    return 0;
}
