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

/* What a query computed; the rest is printed as JSON null (text: n/a).
 * collide computes no distance, bound or witness points; no query has a
 * normal or a gap when the origin is found inside A - B (intersecting); the
 * gap of collide is reported only without a verdict (contact within
 * tolerance, not converged): a separating plane ends it before any gap. */
static int has_distance(const char *query) { return strcmp(query, "distance") == 0; }
/* Zero when intersecting, and for a contact within tolerance whose final
 * iterate is zero (agjk_result.normal): not computed then, so n/a, not a
 * zero vector passed off as a unit normal. */
static int has_normal(const agjk_result *r) {
    return r->status != AGJK_STATUS_INTERSECTING &&
           (r->normal.x != 0.0 || r->normal.y != 0.0 || r->normal.z != 0.0);
}
static int has_gap(const char *query, const agjk_result *r) {
    if (r->status == AGJK_STATUS_INTERSECTING) return 0;
    return has_distance(query) || r->status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE ||
           r->status == AGJK_STATUS_NOT_CONVERGED;
}

/* %.17g: every double printed round-trips exactly. */
static void print_vec_json(FILE *f, const char *key, int computed, agjk_vec3 v) {
    if (computed) fprintf(f, "\"%s\": [%.17g, %.17g, %.17g]", key, v.x, v.y, v.z);
    else fprintf(f, "\"%s\": null", key);
}

static void print_number_json(FILE *f, const char *key, int computed, double v) {
    if (computed) fprintf(f, "\"%s\": %.17g, ", key, v);
    else fprintf(f, "\"%s\": null, ", key);
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
    print_number_json(f, "distance", has_distance(query), r->distance);
    print_number_json(f, "bound", has_distance(query), r->bound);
    print_number_json(f, "gap", has_gap(query, r), r->gap);
    print_vec_json(f, "witness_a", has_distance(query), r->witness_a);
    fputs(", ", f);
    print_vec_json(f, "witness_b", has_distance(query), r->witness_b);
    fputs(", ", f);
    print_vec_json(f, "normal", has_normal(r), r->normal);
    fprintf(f,
            ", \"iterations\": %d, \"support_calls\": %d, \"momentum_stop_iteration\": %d, "
            "\"method\": \"%s\", \"tolerance\": %.17g, \"tolerance_mode\": \"%s\", "
            "\"max_iterations\": %d}\n",
            (int)r->iterations, (int)r->support_calls, (int)r->momentum_stop_iteration,
            agjk_method_name(a->query.method), a->query.tolerance,
            a->query.tolerance_mode == AGJK_TOLERANCE_RELATIVE ? "relative" : "absolute",
            (int)a->query.max_iterations);
}

static void print_vec_text(FILE *f, const char *key, int computed, agjk_vec3 v) {
    if (computed) fprintf(f, "%-15s %.17g %.17g %.17g\n", key, v.x, v.y, v.z);
    else fprintf(f, "%-15s n/a\n", key);
}

/* distance: status, distance, bound, gap, witness_a, witness_b, normal,
 * iterations, support_calls; collide: status, normal, iterations,
 * support_calls. */
static void print_text(FILE *f, const char *query, const agjk_result *r) {
    fprintf(f, "%-15s %s\n", "status:", agjk_status_string(r->status));
    if (has_distance(query)) {
        fprintf(f, "%-15s %.17g\n", "distance:", r->distance);
        fprintf(f, "%-15s %.17g\n", "bound:", r->bound);
        if (has_gap(query, r)) fprintf(f, "%-15s %.17g\n", "gap:", r->gap);
        else fprintf(f, "%-15s n/a\n", "gap:");
        print_vec_text(f, "witness_a:", 1, r->witness_a);
        print_vec_text(f, "witness_b:", 1, r->witness_b);
    }
    print_vec_text(f, "normal:", has_normal(r), r->normal);
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
    if (st == AGJK_STATUS_NOT_CONVERGED) {
        if (r.stop_reason == AGJK_STOP_ITERATION_CAP)
            cli_error("not converged: the gap %.3g did not reach the tolerance within %d "
                      "iterations (the cap); the answer above is certified within its bound",
                      r.gap, (int)r.iterations);
        else if (r.stop_reason == AGJK_STOP_NO_PROGRESS)
            cli_error("not converged: no progress possible in double precision at iteration %d "
                      "(gap %.3g above the tolerance); the answer above is certified within "
                      "its bound", (int)r.iterations, r.gap);
        else
            cli_error("not converged: double precision cannot certify a relative error of %.3g "
                      "at this distance (certified interval: bound %.3g); the answer above is "
                      "certified within its bound", 0.5 * a.query.tolerance, r.bound);
    }
    if (!cli_flush_result()) return CLI_EXIT_ERROR;
    return exit_status(query, st);
}

int cli_cmd_distance(int argc, char **argv) { return run_query(argc, argv, "distance"); }
int cli_cmd_collide(int argc, char **argv) { return run_query(argc, argv, "collide"); }
