/* SPDX-License-Identifier: MIT */
/* `agjk distance` and `agjk collide`: two meshes, two poses, one query.
 *
 * Exit status (see cli.h): distance exits 0 with any certified answer
 * (separated, intersecting, contact within tolerance); collide exits 0 when the
 * shapes collide or touch to within the tolerance (the safe reading for a
 * collision check: "maybe touching" is treated as touching), 1 when they are
 * certified separated. NOT_CONVERGED exits 3 in both: the numbers are printed
 * (best iterate and its certified bound) but no verdict is given. */
#include "cli.h"

#include <string.h>

/* %.17g: every double printed round-trips exactly. */
static void print_vec_json(FILE *f, const char *key, agjk_vec3 v) {
    fprintf(f, "\"%s\": [%.17g, %.17g, %.17g]", key, v.x, v.y, v.z);
}

static void print_json(FILE *f, const char *query, const cli_args *a, const agjk_result *r) {
    fprintf(f, "{\"query\": \"%s\", \"status\": \"%s\", ", query, agjk_status_string(r->status));
    if (strcmp(query, "collide") == 0) {
        const char *c = r->status == AGJK_STATUS_SEPARATED ? "false"
                        : (r->status == AGJK_STATUS_INTERSECTING ||
                           r->status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE)
                            ? "true"
                            : "null";
        fprintf(f, "\"colliding\": %s, ", c);
    }
    fprintf(f, "\"distance\": %.17g, \"bound\": %.17g, \"gap\": %.17g, ", r->distance, r->bound,
            r->gap);
    print_vec_json(f, "witness_a", r->witness_a);
    fputs(", ", f);
    print_vec_json(f, "witness_b", r->witness_b);
    fputs(", ", f);
    print_vec_json(f, "normal", r->normal);
    fprintf(f,
            ", \"iterations\": %d, \"support_calls\": %d, \"momentum_stop_iteration\": %d, "
            "\"method\": \"%s\", \"tolerance\": %.17g, \"tolerance_mode\": \"%s\", "
            "\"max_iterations\": %d}\n",
            (int)r->iterations, (int)r->support_calls, (int)r->momentum_stop_iteration,
            agjk_method_name(a->query.method), a->query.tolerance,
            a->query.tolerance_mode == AGJK_TOLERANCE_RELATIVE ? "relative" : "absolute",
            (int)a->query.max_iterations);
}

static void print_vec_text(FILE *f, const char *key, agjk_vec3 v) {
    fprintf(f, "%-15s %.17g %.17g %.17g\n", key, v.x, v.y, v.z);
}

static void print_text(FILE *f, const char *query, const agjk_result *r) {
    fprintf(f, "%-15s %s\n", "status:", agjk_status_string(r->status));
    if (strcmp(query, "distance") == 0) {
        fprintf(f, "%-15s %.17g\n", "distance:", r->distance);
        fprintf(f, "%-15s %.17g\n", "bound:", r->bound);
        fprintf(f, "%-15s %.17g\n", "gap:", r->gap);
        print_vec_text(f, "witness_a:", r->witness_a);
        print_vec_text(f, "witness_b:", r->witness_b);
    }
    print_vec_text(f, "normal:", r->normal);
    fprintf(f, "%-15s %d\n", "iterations:", (int)r->iterations);
    fprintf(f, "%-15s %d\n", "support_calls:", (int)r->support_calls);
}

static int exit_status(const char *query, agjk_status s) {
    switch (s) {
    case AGJK_STATUS_SEPARATED:
        return strcmp(query, "collide") == 0 ? CLI_EXIT_SEPARATED : CLI_EXIT_OK;
    case AGJK_STATUS_INTERSECTING:
    case AGJK_STATUS_CONTACT_WITHIN_TOLERANCE: return CLI_EXIT_OK;
    case AGJK_STATUS_NOT_CONVERGED: return CLI_EXIT_NOT_CONVERGED;
    default: return CLI_EXIT_ERROR;
    }
}

static int run_query(int argc, char **argv, const char *query) {
    cli_args a;
    int help;
    int is_signed = strcmp(query, "distance") == 0 && cli_take_signed_flag(&argc, argv);
    cli_args_init(&a);
    if (!cli_parse(argc, argv, 1, CLI_OPT_QUERY | CLI_OPT_JSON | CLI_OPT_SCALE, 2, &a, &help)) {
        if (help) return CLI_EXIT_OK;
        return CLI_EXIT_ERROR;
    }
    if (help) {
        cli_print_help(query, stdout);
        return CLI_EXIT_OK;
    }
    cli_guard_start(&a);
    cli_shape s[2];
    if (!cli_shape_load(a.inputs[0], a.scale[0], !a.no_hill_climbing, &s[0])) return CLI_EXIT_ERROR;
    if (!cli_shape_load(a.inputs[1], a.scale[1], !a.no_hill_climbing, &s[1])) {
        cli_shape_free(&s[0]);
        return CLI_EXIT_ERROR;
    }
    if (is_signed) {
        int code = cli_signed_run(&a, &s[0].shape, &s[1].shape);
        cli_shape_free(&s[0]);
        cli_shape_free(&s[1]);
        return code;
    }
    agjk_result r;
    agjk_status st = strcmp(query, "collide") == 0
                         ? agjk_collide(&s[0].shape, &a.pose[0], &s[1].shape, &a.pose[1], &a.query, &r)
                         : agjk_distance(&s[0].shape, &a.pose[0], &s[1].shape, &a.pose[1], &a.query, &r);
    cli_shape_free(&s[0]);
    cli_shape_free(&s[1]);
    if (st == AGJK_STATUS_INVALID_INPUT) {
        cli_error("the library rejected the query as invalid input (check the poses and options)");
        return CLI_EXIT_ERROR;
    }
    if (a.json) print_json(stdout, query, &a, &r);
    else print_text(stdout, query, &r);
    if (st == AGJK_STATUS_NOT_CONVERGED)
        cli_error("not converged: the gap %.3g did not reach the tolerance within %d iterations; "
                  "the answer above is the best iterate, within its bound", r.gap,
                  (int)a.query.max_iterations);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        cli_error("cannot write the result to standard output");
        return CLI_EXIT_ERROR;
    }
    return exit_status(query, st);
}

int cli_cmd_distance(int argc, char **argv) { return run_query(argc, argv, "distance"); }
int cli_cmd_collide(int argc, char **argv) { return run_query(argc, argv, "collide"); }
