/* SPDX-License-Identifier: MIT */
/* agjk: command-line front end. Dispatches to the subcommands; each one
 * parses its own options (argv[0] of a subcommand is its name). */
#include "cli.h"

#include <assimp/version.h>
#include <libqhull_r/libqhull_r.h>
#include <string.h>

static int print_version(void) {
    printf("agjk %s (library %s; assimp %u.%u.%u; qhull %s)\n", AGJK_VERSION_STRING,
           agjk_version_string(), aiGetVersionMajor(), aiGetVersionMinor(),
           aiGetVersionPatch(), qh_version);
    return CLI_EXIT_OK;
}

int main(int argc, char **argv) {
    if (argc < 2) {
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
        if (argc > 2 && strcmp(argv[2], "distance") && strcmp(argv[2], "collide") &&
            strcmp(argv[2], "info") && strcmp(argv[2], "hull")) {
            cli_error("no help for '%s': commands are distance, collide, info, hull", argv[2]);
            return CLI_EXIT_ERROR;
        }
        cli_print_help(argc > 2 ? argv[2] : NULL, stdout);
        return CLI_EXIT_OK;
    }
    cli_error("unknown command '%s' (commands: distance, collide, info, hull; see agjk --help)",
              cmd);
    return CLI_EXIT_ERROR;
}
