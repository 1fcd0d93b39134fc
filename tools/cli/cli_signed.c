/* SPDX-License-Identifier: MIT */
/* `agjk distance A B --signed`: the signed distance (minus the penetration
 * depth when the hulls overlap) with its certified interval. */
#include "cli.h"

#include <string.h>

/* Removes the options' `--signed` (not a file of that name after `--`),
 * keeping argv NULL-terminated: the parser reads a pose's numbers up to
 * argv[argc], and a stale last argument there once completed a pose of six
 * numbers into a wrong seventh. */
int cli_take_signed_flag(int *argc, char **argv) {
    int found = 0, k = 0, options_done = 0;
    for (int i = 0; i < *argc; ++i) {
        if (!options_done && strcmp(argv[i], "--") == 0) options_done = 1;
        if (!options_done && strcmp(argv[i], "--signed") == 0) found = 1;
        else argv[k++] = argv[i];
    }
    *argc = k;
    argv[k] = NULL;
    return found;
}

static void vec_json(FILE *f, const char *key, agjk_vec3 v) {
    fprintf(f, ", \"%s\": [%.17g, %.17g, %.17g]", key, v.x, v.y, v.z);
}

static void vec_text(FILE *f, const char *key, agjk_vec3 v) {
    fprintf(f, "%-17s %.17g %.17g %.17g\n", key, v.x, v.y, v.z);
}

int cli_signed_run(const cli_args *a, const agjk_shape *sa, const agjk_shape *sb) {
    agjk_signed_result r;
    agjk_status st = agjk_signed_distance(sa, &a->pose[0], sb, &a->pose[1], &a->query, &r);
    if (st == AGJK_STATUS_INVALID_INPUT) {
        cli_error("the library rejected the query as invalid input (check the poses and options)");
        return CLI_EXIT_ERROR;
    }
    /* bound: the largest distance from signed_distance to a value the
     * interval allows, as `bound` of the unsigned query */
    double bound = r.upper - r.signed_distance;
    if (r.signed_distance - r.lower > bound) bound = r.signed_distance - r.lower;
    FILE *f = stdout;
    if (a->json) {
        fprintf(f, "{\"query\": \"signed_distance\", \"status\": \"%s\", \"signed_distance\": %.17g, "
                   "\"bound\": %.17g, \"interval\": [%.17g, %.17g]",
                agjk_status_string(r.status), r.signed_distance, bound, r.lower, r.upper);
        vec_json(f, "witness_a", r.witness_a);
        vec_json(f, "witness_b", r.witness_b);
        vec_json(f, "normal", r.normal);
        fprintf(f, ", \"gjk_iterations\": %d, \"epa_iterations\": %d, \"support_calls\": %d, "
                   "\"method\": \"%s\", \"tolerance\": %.17g, \"tolerance_mode\": \"%s\", "
                   "\"max_iterations\": %d}\n",
                (int)r.gjk_iterations, (int)r.epa_iterations, (int)r.support_calls,
                agjk_method_name(a->query.method), a->query.tolerance,
                a->query.tolerance_mode == AGJK_TOLERANCE_RELATIVE ? "relative" : "absolute",
                (int)a->query.max_iterations);
    } else {
        fprintf(f, "%-17s %s\n", "status:", agjk_status_string(r.status));
        fprintf(f, "%-17s %.17g\n", "signed_distance:", r.signed_distance);
        fprintf(f, "%-17s %.17g\n", "bound:", bound);
        fprintf(f, "%-17s %.17g %.17g\n", "interval:", r.lower, r.upper);
        vec_text(f, "witness_a:", r.witness_a);
        vec_text(f, "witness_b:", r.witness_b);
        vec_text(f, "normal:", r.normal);
        fprintf(f, "%-17s %d\n", "gjk_iterations:", (int)r.gjk_iterations);
        fprintf(f, "%-17s %d\n", "epa_iterations:", (int)r.epa_iterations);
        fprintf(f, "%-17s %d\n", "support_calls:", (int)r.support_calls);
    }
    if (st == AGJK_STATUS_NOT_CONVERGED)
        cli_error("not converged: the interval did not reach the tolerance (iteration cap, "
                  "polytope store full, or rounding); the answer above lies in its interval");
    if (!cli_flush_result()) return CLI_EXIT_ERROR;
    return st == AGJK_STATUS_NOT_CONVERGED ? CLI_EXIT_NOT_CONVERGED : CLI_EXIT_OK;
}
