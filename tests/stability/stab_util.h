/* SPDX-License-Identifier: MIT */
/* Helpers shared by the stability tests in tests/stability.
 *
 * Everything here is independent of the library under test: a small PRNG,
 * pose construction, long double support functions of the built-in shapes
 * (used to place shapes at an exact signed distance and to verify separating
 * planes independently), and the checks every query result must pass. */
#ifndef AGJK_STAB_UTIL_H
#define AGJK_STAB_UTIL_H

#include "agjk/agjk.h"
#include "reference.h"

/* splitmix64 (Steele, Lea, Flood 2014): tiny, seedable, good enough here. */
typedef struct stab_rng {
    uint64_t state;
} stab_rng;

uint64_t stab_next(stab_rng *rng);
/* Uniform in [0, 1). */
double stab_uniform(stab_rng *rng);
/* Uniform in [lo, hi). */
double stab_range(stab_rng *rng, double lo, double hi);
/* Uniform direction on the unit sphere. */
agjk_vec3 stab_unit(stab_rng *rng);

void stab_pose_identity(agjk_pose *pose);
/* Rotation from a unit quaternion (w, x, y, z), normalised here. */
void stab_pose_quat(agjk_pose *pose, double w, double x, double y, double z);
/* Uniformly random rotation (Shoemake's method), translation left as is. */
void stab_pose_random_rotation(agjk_pose *pose, stab_rng *rng);

/* Support of a shape (including its margin) in world frame, in long double:
 * writes the support point p (argmax <dir, p>) and returns <dir, p>.
 * `dir` need not be unit. Covers every ref_kind. */
long double stab_support_world(const ref_shape *s, const agjk_pose *pose,
                               const long double dir[3], long double out[3]);

/* Bounding radius of the shape around its frame origin (margin included). */
double stab_radius(const ref_shape *s);

/* Builds the agjk shape with the library's public constructors, storing the
 * parameter structs inside `s`. Returns the constructor's status. */
agjk_status stab_make_shape(ref_shape *s, agjk_shape *out);

/* Moves pose_b's translation so that the support planes of A (direction n)
 * and B (direction -n) are parallel at signed offset `sep` along the unit
 * vector n, with the two support points facing each other. For sep >= 0 the
 * true distance is then exactly sep (the support planes separate the shapes
 * and the support points are sep apart); for sep < 0 the shapes overlap along
 * n by -sep. Rounding of the translation is the only error. */
void stab_place(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                agjk_pose *pose_b, const double n[3], double sep);

/* 1 when the world point p lies inside shape s (margin included) by more
 * than rounding, 0 when not, -1 when the kind has no membership test here
 * (polytopes, cylinders, cones). */
int stab_contains(const ref_shape *s, const agjk_pose *pose, const long double p[3]);

/* Values of known_sep for stab_check_case besides an analytic distance >= 0. */
#define STAB_UNKNOWN (-1.0)
#define STAB_OVERLAP (-2.0) /* overlap certified by a common point */

/* Places B as stab_place does with sep < 0 and returns 1 when the overlap is
 * certified (B's support point lies inside A), 0 when not certain. */
int stab_place_overlap(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                       agjk_pose *pose_b, const double n[3], double depth);

/* Magnitude of the problem for floating-point slack: |t_a| + |t_b| + radii. */
double stab_magnitude(const ref_shape *a, const agjk_pose *pa,
                      const ref_shape *b, const agjk_pose *pb);

/* Corpus statistics, accumulated by stab_check_*. */
typedef struct stab_stats {
    long cases;            /* distinct problems (shape pair + poses) */
    long queries;          /* library calls checked */
    long failures;         /* checks failed */
    long not_converged;    /* honest NOT_CONVERGED answers */
    long contact;          /* CONTACT_WITHIN_TOLERANCE answers */
    long ref_failures;     /* reference did not converge: case skipped */
    double worst_rel;      /* worst |d - d_true| / d_true, SEPARATED in relative mode */
    double worst_rel_clear; /* the same where d_true > 1e4 * slack (well above rounding) */
    double worst_bound_ratio; /* worst |d - d_ref| / (bound + slack) */
    char worst_name[160];
} stab_stats;

/* Which queries stab_check_case runs. */
enum { STAB_DISTANCE = 1, STAB_COLLIDE = 2, STAB_BOTH = 3 };

/* Runs agjk_distance and/or agjk_collide on the pair with every method and
 * the given tolerance mode/value, checks each result against the reference
 * (computed once) and against the result invariants, and accumulates stats.
 * `known_sep` is the analytic distance when >= 0 (from stab_place), or
 * STAB_UNKNOWN, or STAB_OVERLAP. Returns the number of failures. */
int stab_check_case(const char *name, ref_shape *a, const agjk_pose *pa,
                    ref_shape *b, const agjk_pose *pb, int which,
                    agjk_tolerance_mode mode, double tolerance, int max_iterations,
                    double known_sep, stab_stats *stats);

/* Checks the invariants every result obeys whatever the input: status is a
 * known value and equals `returned`, every double is finite, distance, bound,
 * gap >= 0, counters sane. Prints and returns 0 when all hold, 1 for a minor
 * violation after which the result is still usable (a negative gap), 2 for
 * a result that must not be used further. */
int stab_result_sane(const char *name, agjk_status returned, const agjk_result *r,
                     int max_iterations);

void stab_stats_print(const char *title, const stab_stats *s);

/* Guarded output buffer: `pre` and `post` catch writes outside the struct. */
#define STAB_GUARD 64
#define STAB_GUARD_BYTE 0xA5
void stab_guard_fill(unsigned char *guard);
int stab_guard_ok(const unsigned char *guard);

#endif
