/* SPDX-License-Identifier: MIT */
/* agjk: command-line front end. Dispatches to the subcommands; each one
 * parses its own options (argv[0] of a subcommand is its name). Global
 * options before the command (agjk --json distance A B) are handed to the
 * command as if they followed its name. */
#include "cli.h"

#include <assimp/version.h>
#include <libqhull_r/libqhull_r.h>
#include <stdlib.h>
#include <string.h>

/* Number of values a global option takes, or -1 for anything else. */
static int global_option_values(const char *s) {
    if (strcmp(s, "--json") == 0) return 0;
    if (strcmp(s, "--timeout") == 0 || strcmp(s, "--memory-limit") == 0) return 1;
    return -1;
}

static int print_version(void) {
    printf("agjk %s (library %s; assimp %u.%u.%u; qhull %s)\n", AGJK_VERSION_STRING,
           agjk_version_string(), aiGetVersionMajor(), aiGetVersionMinor(),
           aiGetVersionPatch(), qh_version);
    return CLI_EXIT_OK;
}

static int dispatch(int argc, char **argv);

int main(int argc, char **argv) {
    int first = 1;
    while (first < argc) {
        int n = global_option_values(argv[first]);
        if (n < 0) break;
        if (first + n >= argc) {
            cli_error("%s needs a value", argv[first]);
            return CLI_EXIT_ERROR;
        }
        first += 1 + n;
    }
    if (first == 1 || first >= argc) return dispatch(argc, argv);
    /* agjk GLOBALS COMMAND ARGS -> agjk COMMAND GLOBALS ARGS */
    char **moved = malloc(((size_t)argc + 1) * sizeof *moved);
    if (!moved) {
        cli_error("out of memory");
        return CLI_EXIT_ERROR;
    }
    int k = 0;
    moved[k++] = argv[0];
    moved[k++] = argv[first];
    for (int i = 1; i < first; i++) moved[k++] = argv[i];
    for (int i = first + 1; i < argc; i++) moved[k++] = argv[i];
    moved[k] = NULL;
    int status = dispatch(argc, moved);
    free(moved);
    return status;
}

static int dispatch(int argc, char **argv) {
    if (argc < 2 || global_option_values(argv[1]) >= 0) {
        /* nothing but global options */
        cli_print_help(NULL, stderr);
        return CLI_EXIT_ERROR;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "distance") == 0) return cli_cmd_distance(argc - 1, argv + 1);
    if (strcmp(cmd, "collide") == 0) return cli_cmd_collide(argc - 1, argv + 1);
    if (strcmp(cmd, "info") == 0) return cli_cmd_info(argc - 1, argv + 1);
    if (strcmp(cmd, "hull") == 0) return cli_cmd_hull(argc - 1, argv + 1);
    if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "version") == 0) return print_version();
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        cli_print_help(NULL, stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(cmd, "help") == 0) {
        /* (Global options given before `help` now follow it: skipped.) */
        int i = 2;
        while (i < argc && global_option_values(argv[i]) >= 0)
            i += 1 + global_option_values(argv[i]);
        const char *topic = i < argc ? argv[i] : NULL;
        if (topic && strcmp(topic, "distance") && strcmp(topic, "collide") &&
            strcmp(topic, "info") && strcmp(topic, "hull")) {
            cli_error("no help for '%s': commands are distance, collide, info, hull", topic);
            return CLI_EXIT_ERROR;
        }
        cli_print_help(topic, stdout);
        return CLI_EXIT_OK;
    }
    cli_error("unknown command '%s' (commands: distance, collide, info, hull; see agjk --help)",
              cmd);
    return CLI_EXIT_ERROR;
}
