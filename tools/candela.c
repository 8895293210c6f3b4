/* candela.c - the `candela` command: dispatch to subcommands. */
#include <stdio.h>
#include <string.h>

#include "candela/candela.h"
#include "command.h"
#include "scene_help.h"

static const cdl_command *const commands[] = {
    &cdl_command_info, &cdl_command_convert, &cdl_command_solve, &cdl_command_report, &cdl_command_bench,
    &cdl_command_sun, &cdl_command_annual,
};
#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

static void print_usage(FILE *out)
{
    fprintf(out,
            "candela %s - radiometry, luminaires and illuminance for lighting design\n\n"
            "usage: candela <command> [options]\n\n"
            "commands:\n",
            cdl_version());
    for (size_t i = 0; i < COMMAND_COUNT; ++i)
        fprintf(out, "  %-9s %s\n", commands[i]->name, commands[i]->summary);
    fprintf(out,
            "\n'candela <command> --help' describes a command; 'candela help scene' the scene file.\n"
            "Exit status: 0 success, 1 bad input, 2 usage error, 3 internal or resource failure.\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        print_usage(stderr);
        return CDL_EXIT_USAGE;
    }
    const char *name = argv[1];
    if (strcmp(name, "--version") == 0 || strcmp(name, "version") == 0) {
        printf("candela %s\n", cdl_version());
        return CDL_EXIT_OK;
    }
    if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0 || strcmp(name, "help") == 0) {
        if (argc >= 3 && strcmp(name, "help") == 0 && strcmp(argv[2], "scene") == 0) {
            /* The scene format (DESIGN.md: `candela help scene`), or its schema. */
            if (argc == 4 && strcmp(argv[3], "--schema") == 0) return cdl_scene_help_print_schema(stdout);
            if (argc > 3) {
                fprintf(stderr, "candela help scene: expected nothing or --schema, found '%s'\n", argv[3]);
                return CDL_EXIT_USAGE;
            }
            return cdl_scene_help_print(stdout);
        }
        if (argc >= 3 && strcmp(name, "help") == 0) {
            for (size_t i = 0; i < COMMAND_COUNT; ++i)
                if (strcmp(argv[2], commands[i]->name) == 0) {
                    commands[i]->print_help(stdout);
                    return CDL_EXIT_OK;
                }
            fprintf(stderr, "candela help: unknown command '%s'\n\n", argv[2]);
            print_usage(stderr);
            return CDL_EXIT_USAGE;
        }
        print_usage(stdout);
        return CDL_EXIT_OK;
    }
    for (size_t i = 0; i < COMMAND_COUNT; ++i)
        if (strcmp(name, commands[i]->name) == 0) return commands[i]->run(argc - 1, argv + 1);
    fprintf(stderr, "candela: unknown command '%s'\n\n", name);
    print_usage(stderr);
    return CDL_EXIT_USAGE;
}
