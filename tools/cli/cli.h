/* SPDX-License-Identifier: MIT */
/* The agjk command-line tool: shared declarations of its parts.
 *   main.c       subcommand dispatch, --version
 *   cli_help.c   the help texts (one man page per subcommand)
 *   cli_parse.c  strict number parsing and the query options
 *   cli_guard.c  memory cap and watchdog, so no input can hang or exhaust the machine
 *   cli_shape.c  mesh file -> hull -> agjk_shape
 *   cli_query.c  `distance` and `collide`
 *   cli_signed.c `distance --signed` (penetration depth)
 *   cli_mesh.c   `info` and `hull` */
#ifndef AGJK_CLI_H
#define AGJK_CLI_H

#include <stdio.h>

#include "agjk/agjk.h"
#include "mesh.h"

/* Exit statuses (documented in `agjk --help`). */
enum {
    CLI_EXIT_OK = 0,            /* success; for collide: colliding (or touching) */
    CLI_EXIT_SEPARATED = 1,     /* collide: separated */
    CLI_EXIT_ERROR = 2,         /* usage, file or input error: nothing computed */
    CLI_EXIT_NOT_CONVERGED = 3  /* iteration cap / numerical stall: result printed, no verdict */
};

/* Everything the command line can set. */
typedef struct cli_args {
    const char *inputs[2];  /* positional mesh files */
    int input_count;
    agjk_pose pose[2];
    double scale[2];
    agjk_options query;
    int json;
    int no_hill_climbing;   /* --scan: polytope support by scan only */
    const char *output;     /* hull -o */
    double timeout;         /* seconds, 0: none */
    double memory_limit_mb; /* 0: none, < 0: automatic */
} cli_args;

/* Which options a subcommand accepts. */
enum { CLI_OPT_QUERY = 1, CLI_OPT_OUTPUT = 2, CLI_OPT_JSON = 4, CLI_OPT_SCALE = 8 };

void cli_args_init(cli_args *args);
/* Parses argv[first..argc-1]; on error prints a message and returns 0. Sets
 * *help when --help was given. */
int cli_parse(int argc, char **argv, int first, int accepted, int max_inputs, cli_args *args,
              int *help);
/* Strict: the whole string is a finite decimal number. */
int cli_parse_double(const char *s, double *out);

void cli_print_help(const char *command, FILE *out);
void cli_error(const char *fmt, ...);
/* Flushes standard output: 1, or 0 after saying that the result could not
 * be written (a full disk, a closed pipe). */
int cli_flush_result(void);

void cli_guard_start(const cli_args *args);

/* A mesh file as a convex shape (hull with adjacency, scaled). `flags`:
 * CLI_SHAPE_ADJACENCY builds the hill-climbing adjacency of a solid hull;
 * without CLI_SHAPE_HULL (a query), a set of more than CLI_QUERY_HULL_MAX_POINTS
 * points gets no hull at all and its support is a scan over the points. */
enum { CLI_SHAPE_ADJACENCY = 1, CLI_SHAPE_HULL = 2 };
#define CLI_QUERY_HULL_MAX_POINTS 65536
typedef struct cli_shape {
    mesh_points points;
    mesh_hull hull;
    agjk_shape shape;
} cli_shape;
int cli_shape_load(const char *path, double scale, int flags, cli_shape *s);
void cli_shape_free(cli_shape *s);
/* Whether queries on this hull find support points by hill climbing (an
 * adjacency and at least AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES vertices) or
 * by a scan; and the same in words, for `agjk info`. */
int cli_hull_hill_climbing(const mesh_hull *h);
const char *cli_hull_support_text(const mesh_hull *h);

/* `distance --signed` (cli_signed.c): removes --signed from argv, says if it was there. */
int cli_take_signed_flag(int *argc, char **argv);
int cli_signed_run(const cli_args *args, const agjk_shape *a, const agjk_shape *b);

int cli_cmd_distance(int argc, char **argv);
int cli_cmd_collide(int argc, char **argv);
int cli_cmd_info(int argc, char **argv);
int cli_cmd_hull(int argc, char **argv);

#endif /* AGJK_CLI_H */
