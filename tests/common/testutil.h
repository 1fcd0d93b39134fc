/* SPDX-License-Identifier: MIT */
/* Test helpers shared by tests/core, tests/stability, tests/ccd and tools/bench:
 * a seeded PRNG (splitmix64), random rotations and poses, pose algebra, and
 * random shapes drawn like the paper's benchmark (Montaut et al. 2022, Sec. V:
 * radii ~ N(0.1, 0.025), here times a scale in {1, 5, 10}). Deterministic:
 * the same seed gives the same sequence on every platform. */
#ifndef AGJK_TEST_TESTUTIL_H
#define AGJK_TEST_TESTUTIL_H

#include <stdint.h>
#include "agjk/agjk.h"
#include "reference.h"

/* ---- PRNG: splitmix64 (Steele, Lea, Flood 2014), tiny and good enough. ---- */
typedef struct tu_rng {
    uint64_t state;
} tu_rng;

void tu_rng_seed(tu_rng *r, uint64_t seed);
uint64_t tu_rng_next(tu_rng *r);
/* Uniform in [0, 1) with 53 random bits. */
double tu_uniform(tu_rng *r);
/* Uniform in [lo, hi). */
double tu_uniform_range(tu_rng *r, double lo, double hi);
/* Uniform integer in [0, n), n >= 1. */
uint32_t tu_uniform_int(tu_rng *r, uint32_t n);
/* Standard normal (Box-Muller). */
double tu_normal(tu_rng *r);
/* Uniform on the unit sphere. */
agjk_vec3 tu_unit_vector(tu_rng *r);
/* 10^u with u uniform in [lo_exp, hi_exp]: log-uniform magnitudes. */
double tu_log_uniform(tu_rng *r, double lo_exp, double hi_exp);

/* ---- Vectors. ---- */
agjk_vec3 tu_vec(double x, double y, double z);
agjk_vec3 tu_add(agjk_vec3 a, agjk_vec3 b);
agjk_vec3 tu_sub(agjk_vec3 a, agjk_vec3 b);
agjk_vec3 tu_scale(agjk_vec3 a, double s);
double tu_dot(agjk_vec3 a, agjk_vec3 b);
agjk_vec3 tu_cross(agjk_vec3 a, agjk_vec3 b);
double tu_norm(agjk_vec3 a);
int tu_vec_finite(agjk_vec3 a);

/* ---- Rotations and poses (p_world = R p_local + t, R row-major). ---- */
/* Rotation matrix of the unit quaternion (w, x, y, z). */
void tu_quat_to_matrix(const double q[4], double r[3][3]);
/* Uniformly distributed rotation (Shoemake's subgroup algorithm, Graphics Gems III). */
void tu_random_rotation(tu_rng *r, double rot[3][3]);
agjk_pose tu_pose_identity(void);
/* Random rotation, translation uniform in the cube [-range, range]^3. */
agjk_pose tu_random_pose(tu_rng *r, double range);
/* (a o b)(p) = a(b(p)). */
agjk_pose tu_pose_compose(const agjk_pose *a, const agjk_pose *b);
agjk_vec3 tu_pose_apply(const agjk_pose *p, agjk_vec3 v);
agjk_vec3 tu_pose_rotate(const agjk_pose *p, agjk_vec3 v);
/* Same rotation, translation times s (for the scaling property). */
agjk_pose tu_pose_scaled(const agjk_pose *p, double s);
void tu_pose_translate(agjk_pose *p, agjk_vec3 delta);

/* ---- Random shapes (fill a ref_shape; call ref_make_agjk for the agjk side). ---- */
/* One radius of the paper's law: N(0.1, 0.025) * scale, kept >= 0.02 * scale. */
double tu_paper_radius(tu_rng *r, double scale);
/* The scale factor of the paper's law, drawn from {1, 5, 10}. */
double tu_paper_scale(tu_rng *r);
void tu_shape_init(ref_shape *s, ref_kind kind, double p0, double p1, double p2);
void tu_random_ellipsoid(tu_rng *r, ref_shape *s, double scale);
void tu_random_box(tu_rng *r, ref_shape *s, double scale);
/* `n` vertices on the surface of a random ellipsoid of the paper's law (all on
 * the hull), written to storage[0..n-1], which must outlive s. */
void tu_random_polytope(tu_rng *r, ref_shape *s, agjk_vec3 *storage, int n, double scale);
/* Radius of a ball centred at the local origin holding the shape (margins included). */
double tu_bounding_radius(const ref_shape *s);

/* Places shape B (pose *pose_b, changed in place) so that the reference signed
 * "distance along the closest-point axis" is `target`: B is first moved away
 * from A until separated, then slid along the reference normal by
 * target - d (the paper's protocol). A negative target gives an overlap of
 * about |target| along that axis. Writes the reference result of the pair as
 * first separated into *before (may be NULL). Returns 0 on success. */
int tu_set_distance(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                    agjk_pose *pose_b, double target, ref_result *before);

/* Certified lower bound on the distance from the world point p to the shape
 * (margins included), by the reference solver (a point shape against s);
 * 0 when p is inside or on the boundary. */
double tu_distance_to_shape(const ref_shape *s, const agjk_pose *pose, agjk_vec3 p);

#endif
