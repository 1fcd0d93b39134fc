/* SPDX-License-Identifier: MIT */
/* Command-line parsing: strict numbers, poses from quaternions, query options.
 *
 * Numbers must be the whole argument (strtod with an end check), finite, and
 * not start with blanks, so "1e", "0x", "nan", "1,5" or " 1" are errors rather
 * than silently becoming something else. */
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* A quaternion whose norm is within this of 1 is taken as unit and
 * renormalised (values printed with 6 to 7 digits are off by a few 1e-7);
 * anything further is a mistake, not rounding, and is rejected. */
#define QUATERNION_NORM_TOLERANCE 1e-5

/* The CLI's default tolerance: the library raises an absolute tolerance
 * below its floating-point floor to that floor, so this asks for the most
 * accurate answer double precision can certify. The library default (1e-8,
 * i.e. 1e-4 length units) suits a simulation's time budget; a command-line
 * user wants the distance, and a polytope pair gets there in a couple more
 * iterations (measured on the pybullet random_urdfs meshes: at gaps near
 * 1e-5 x size, 1e-8 left 30% relative error, this leaves 1e-10 or less). */
#define CLI_DEFAULT_TOLERANCE 1e-300
/* With --relative and no --tolerance: a relative error of 5e-13. A relative
 * tolerance is never raised to a floor (the library answers "not converged"
 * when double precision cannot certify it), so "most accurate" has no
 * relative counterpart; this is well above the rounding of shapes that are
 * not nearly touching. */
#define CLI_DEFAULT_RELATIVE_TOLERANCE 1e-12

void cli_error(const char *fmt, ...) {
    va_list ap;
    fputs("agjk: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

int cli_flush_result(void) {
    if (fflush(stdout) == 0 && !ferror(stdout)) return 1;
    cli_error("cannot write the result to standard output");
    return 0;
}

int cli_parse_double(const char *s, double *out) {
    char *end;
    if (!s || !*s || strchr(" \t\n\r\f\v", s[0])) return 0;
    errno = 0;
    double v = strtod(s, &end);
    if (*end != '\0' || !isfinite(v)) return 0;
    /* ERANGE on underflow is fine (a tiny number is still that number). */
    if (errno == ERANGE && fabs(v) > 1.0) return 0;
    *out = v;
    return 1;
}

static int parse_int(const char *s, long lo, long hi, long *out) {
    char *end;
    if (!s || !*s || strchr(" \t\n\r\f\v", s[0])) return 0;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end != '\0' || errno == ERANGE || v < lo || v > hi) return 0;
    *out = v;
    return 1;
}

static void pose_identity(agjk_pose *p) {
    memset(p, 0, sizeof *p);
    p->rotation[0][0] = p->rotation[1][1] = p->rotation[2][2] = 1.0;
}

/* Rotation matrix of the unit quaternion q = (w, x, y, z), Hamilton
 * convention, active: p_world = q p q^-1 (the matrix maps local to world). */
static void quaternion_to_rotation(const double q[4], double r[3][3]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z);
    r[0][1] = 2 * (x * y - w * z);
    r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z);
    r[1][1] = 1 - 2 * (x * x + z * z);
    r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y);
    r[2][1] = 2 * (y * z + w * x);
    r[2][2] = 1 - 2 * (x * x + y * y);
}

/* --pose-X tx ty tz qw qx qy qz */
static int parse_pose(char **values, const char *option, agjk_pose *pose) {
    double v[7];
    for (int i = 0; i < 7; i++) {
        if (!values[i]) {
            cli_error("%s needs 7 numbers: tx ty tz qw qx qy qz", option);
            return 0;
        }
        if (!cli_parse_double(values[i], &v[i])) {
            cli_error("%s: '%s' is not a finite number", option, values[i]);
            return 0;
        }
    }
    for (int i = 0; i < 3; i++)
        if (!(fabs(v[i]) <= AGJK_MAX_COORDINATE)) {
            cli_error("%s: translation %s is beyond the library's coordinate range (%g)", option,
                      values[i], AGJK_MAX_COORDINATE);
            return 0;
        }
    double norm = sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
    if (!(fabs(norm - 1.0) <= QUATERNION_NORM_TOLERANCE)) {
        cli_error("%s: quaternion (%s %s %s %s) has norm %.9g, not 1 (qw qx qy qz must be a "
                  "unit quaternion, to within %g)",
                  option, values[3], values[4], values[5], values[6], norm,
                  QUATERNION_NORM_TOLERANCE);
        return 0;
    }
    double q[4] = {v[3] / norm, v[4] / norm, v[5] / norm, v[6] / norm};
    quaternion_to_rotation(q, pose->rotation);
    pose->translation.x = v[0];
    pose->translation.y = v[1];
    pose->translation.z = v[2];
    return 1;
}

static int parse_method(const char *s, agjk_method *m) {
    static const agjk_method all[] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                      AGJK_METHOD_NESTEROV_NORMALIZED, AGJK_METHOD_POLYAK,
                                      AGJK_METHOD_FRANK_WOLFE, AGJK_METHOD_ADAPTIVE};
    for (size_t i = 0; s && i < sizeof all / sizeof all[0]; i++)
        if (strcmp(s, agjk_method_name(all[i])) == 0) {
            *m = all[i];
            return 1;
        }
    return 0;
}

void cli_args_init(cli_args *args) {
    memset(args, 0, sizeof *args);
    pose_identity(&args->pose[0]);
    pose_identity(&args->pose[1]);
    args->scale[0] = args->scale[1] = 1.0;
    agjk_options_init(&args->query);
    args->query.tolerance = 0.0; /* not given: set by cli_parse from the mode */
    args->timeout = 300.0;
    args->memory_limit_mb = -1.0;
}

/* The value after an option, or an error. */
static const char *option_value(int argc, char **argv, int *i) {
    if (*i + 1 >= argc) {
        cli_error("%s needs a value", argv[*i]);
        return NULL;
    }
    return argv[++*i];
}

static int positive_number(const char *opt, const char *s, double *out) {
    if (!s) return 0;
    if (!cli_parse_double(s, out) || !(*out > 0)) {
        cli_error("%s: '%s' is not a positive finite number", opt, s);
        return 0;
    }
    return 1;
}

static int nonnegative_number(const char *opt, const char *s, double *out) {
    if (!s) return 0;
    if (!cli_parse_double(s, out) || !(*out >= 0)) {
        cli_error("%s: '%s' is not a finite number >= 0", opt, s);
        return 0;
    }
    return 1;
}

/* Query options (distance, collide). Returns 1 handled, 0 error, -1 not a query option. */
static int parse_query_option(int argc, char **argv, int *i, cli_args *a) {
    const char *o = argv[*i];
    const char *v;
    long n;
    if (strcmp(o, "--pose-a") == 0 || strcmp(o, "--pose-b") == 0) {
        int which = o[7] == 'b';
        /* argv[argc] is NULL, so parse_pose sees the end of the list. */
        if (!parse_pose(argv + *i + 1, o, &a->pose[which])) return 0;
        *i += 7;
        return 1;
    }
    if (strcmp(o, "--method") == 0) {
        if (!(v = option_value(argc, argv, i))) return 0;
        if (!parse_method(v, &a->query.method)) {
            cli_error("--method: unknown method '%s' (gjk, nesterov, nesterov-normalized, "
                      "polyak, fw)", v);
            return 0;
        }
        return 1;
    }
    if (strcmp(o, "--tolerance") == 0)
        return positive_number(o, option_value(argc, argv, i), &a->query.tolerance);
    if (strcmp(o, "--relative") == 0) {
        a->query.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
        return 1;
    }
    if (strcmp(o, "--max-iterations") == 0) {
        if (!(v = option_value(argc, argv, i))) return 0;
        if (!parse_int(v, 1, INT32_MAX, &n)) {
            cli_error("--max-iterations: '%s' is not an integer in 1..%ld", v, (long)INT32_MAX);
            return 0;
        }
        a->query.max_iterations = (int32_t)n;
        return 1;
    }
    if (strcmp(o, "--scan") == 0) {
        a->no_hill_climbing = 1;
        return 1;
    }
    return -1;
}

static int parse_common_option(int argc, char **argv, int *i, int accepted, cli_args *a) {
    const char *o = argv[*i];
    int r = (accepted & CLI_OPT_QUERY) ? parse_query_option(argc, argv, i, a) : -1;
    if (r >= 0) return r;
    if ((accepted & CLI_OPT_SCALE) && (strcmp(o, "--scale-a") == 0 || strcmp(o, "--scale-b") == 0))
        return positive_number(o, option_value(argc, argv, i), &a->scale[o[8] == 'b']);
    if ((accepted & CLI_OPT_JSON) && strcmp(o, "--json") == 0) {
        a->json = 1;
        return 1;
    }
    if ((accepted & CLI_OPT_OUTPUT) && (strcmp(o, "-o") == 0 || strcmp(o, "--output") == 0))
        return (a->output = option_value(argc, argv, i)) != NULL;
    if (strcmp(o, "--timeout") == 0)
        return nonnegative_number(o, option_value(argc, argv, i), &a->timeout);
    if (strcmp(o, "--memory-limit") == 0)
        return nonnegative_number(o, option_value(argc, argv, i), &a->memory_limit_mb);
    cli_error("unknown option '%s' (see agjk %s --help)", o, argv[0]);
    return 0;
}

int cli_parse(int argc, char **argv, int first, int accepted, int max_inputs, cli_args *args,
              int *help) {
    int options_done = 0;
    *help = 0;
    for (int i = first; i < argc; i++) {
        const char *s = argv[i];
        if (!options_done && (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0)) {
            *help = 1;
            return 1;
        }
        if (!options_done && strcmp(s, "--") == 0) {
            options_done = 1;
        } else if (!options_done && s[0] == '-' && s[1] != '\0') {
            if (!parse_common_option(argc, argv, &i, accepted, args)) return 0;
        } else {
            if (args->input_count >= max_inputs) {
                cli_error("too many arguments ('%s'); see agjk %s --help", s, argv[0]);
                return 0;
            }
            args->inputs[args->input_count++] = s;
        }
    }
    if (args->query.tolerance == 0.0)
        args->query.tolerance = args->query.tolerance_mode == AGJK_TOLERANCE_RELATIVE
                                    ? CLI_DEFAULT_RELATIVE_TOLERANCE
                                    : CLI_DEFAULT_TOLERANCE;
    if (args->input_count < max_inputs) {
        cli_error("%s needs %d mesh file%s; see agjk %s --help", argv[0], max_inputs,
                  max_inputs > 1 ? "s" : "", argv[0]);
        return 0;
    }
    return 1;
}
