/* SPDX-License-Identifier: MIT */
/* Test helpers; see testutil.h. */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "testutil.h"

#define TU_PI 3.14159265358979323846

void tu_rng_seed(tu_rng *r, uint64_t seed) { r->state = seed; }

uint64_t tu_rng_next(tu_rng *r) {
    uint64_t z = (r->state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

double tu_uniform(tu_rng *r) { return (double)(tu_rng_next(r) >> 11) * 0x1.0p-53; }

double tu_uniform_range(tu_rng *r, double lo, double hi) { return lo + (hi - lo) * tu_uniform(r); }

uint32_t tu_uniform_int(tu_rng *r, uint32_t n) { return (uint32_t)(tu_uniform(r) * n) % n; }

double tu_normal(tu_rng *r) {
    double u1 = 1.0 - tu_uniform(r); /* (0, 1]: log is finite */
    double u2 = tu_uniform(r);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * TU_PI * u2);
}

agjk_vec3 tu_unit_vector(tu_rng *r) {
    /* Archimedes: z uniform in [-1, 1], azimuth uniform. */
    double z = tu_uniform_range(r, -1.0, 1.0);
    double phi = tu_uniform_range(r, 0.0, 2.0 * TU_PI);
    double s = sqrt(1.0 - z * z);
    return tu_vec(s * cos(phi), s * sin(phi), z);
}

double tu_log_uniform(tu_rng *r, double lo_exp, double hi_exp) {
    return pow(10.0, tu_uniform_range(r, lo_exp, hi_exp));
}

agjk_vec3 tu_vec(double x, double y, double z) {
    agjk_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
agjk_vec3 tu_add(agjk_vec3 a, agjk_vec3 b) { return tu_vec(a.x + b.x, a.y + b.y, a.z + b.z); }
agjk_vec3 tu_sub(agjk_vec3 a, agjk_vec3 b) { return tu_vec(a.x - b.x, a.y - b.y, a.z - b.z); }
agjk_vec3 tu_scale(agjk_vec3 a, double s) { return tu_vec(a.x * s, a.y * s, a.z * s); }
double tu_dot(agjk_vec3 a, agjk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
agjk_vec3 tu_cross(agjk_vec3 a, agjk_vec3 b) {
    return tu_vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
double tu_norm(agjk_vec3 a) { return sqrt(tu_dot(a, a)); }
int tu_vec_finite(agjk_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

void tu_quat_to_matrix(const double q[4], double r[3][3]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z); r[0][1] = 2 * (x * y - w * z); r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z); r[1][1] = 1 - 2 * (x * x + z * z); r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y); r[2][1] = 2 * (y * z + w * x); r[2][2] = 1 - 2 * (x * x + y * y);
}

void tu_random_rotation(tu_rng *r, double rot[3][3]) {
    double u1 = tu_uniform(r), u2 = tu_uniform(r), u3 = tu_uniform(r);
    double a = sqrt(1.0 - u1), b = sqrt(u1);
    double q[4] = {b * cos(2 * TU_PI * u3), a * sin(2 * TU_PI * u2), a * cos(2 * TU_PI * u2),
                   b * sin(2 * TU_PI * u3)};
    tu_quat_to_matrix(q, rot);
}

agjk_pose tu_pose_identity(void) {
    agjk_pose p;
    memset(&p, 0, sizeof p);
    p.rotation[0][0] = p.rotation[1][1] = p.rotation[2][2] = 1.0;
    return p;
}

agjk_pose tu_random_pose(tu_rng *r, double range) {
    agjk_pose p;
    tu_random_rotation(r, p.rotation);
    p.translation = tu_vec(tu_uniform_range(r, -range, range), tu_uniform_range(r, -range, range),
                           tu_uniform_range(r, -range, range));
    return p;
}

agjk_vec3 tu_pose_rotate(const agjk_pose *p, agjk_vec3 v) {
    const double (*m)[3] = p->rotation;
    return tu_vec(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                  m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                  m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

agjk_vec3 tu_pose_apply(const agjk_pose *p, agjk_vec3 v) {
    return tu_add(tu_pose_rotate(p, v), p->translation);
}

agjk_pose tu_pose_compose(const agjk_pose *a, const agjk_pose *b) {
    agjk_pose c;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c.rotation[i][j] = a->rotation[i][0] * b->rotation[0][j] +
                               a->rotation[i][1] * b->rotation[1][j] +
                               a->rotation[i][2] * b->rotation[2][j];
    c.translation = tu_pose_apply(a, b->translation);
    return c;
}

agjk_pose tu_pose_scaled(const agjk_pose *p, double s) {
    agjk_pose c = *p;
    c.translation = tu_scale(p->translation, s);
    return c;
}

void tu_pose_translate(agjk_pose *p, agjk_vec3 delta) {
    p->translation = tu_add(p->translation, delta);
}

double tu_paper_radius(tu_rng *r, double scale) {
    double v = 0.1 + 0.025 * tu_normal(r);
    if (v < 0.02) v = 0.02; /* the normal law has a tail below zero */
    return v * scale;
}

double tu_paper_scale(tu_rng *r) {
    static const double scales[3] = {1.0, 5.0, 10.0};
    return scales[tu_uniform_int(r, 3)];
}

void tu_shape_init(ref_shape *s, ref_kind kind, double p0, double p1, double p2) {
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->p[0] = p0;
    s->p[1] = p1;
    s->p[2] = p2;
}

void tu_random_ellipsoid(tu_rng *r, ref_shape *s, double scale) {
    double a = tu_paper_radius(r, scale), b = tu_paper_radius(r, scale);
    tu_shape_init(s, REF_ELLIPSOID, a, b, tu_paper_radius(r, scale));
}

void tu_random_box(tu_rng *r, ref_shape *s, double scale) {
    double a = tu_paper_radius(r, scale), b = tu_paper_radius(r, scale);
    tu_shape_init(s, REF_BOX, a, b, tu_paper_radius(r, scale));
}

void tu_random_polytope(tu_rng *r, ref_shape *s, agjk_vec3 *storage, int n, double scale) {
    double rx = tu_paper_radius(r, scale), ry = tu_paper_radius(r, scale);
    double rz = tu_paper_radius(r, scale);
    for (int i = 0; i < n; i++) {
        agjk_vec3 u = tu_unit_vector(r);
        storage[i] = tu_vec(rx * u.x, ry * u.y, rz * u.z);
    }
    tu_shape_init(s, REF_POLYTOPE, 0, 0, 0);
    s->vertices = storage;
    s->vertex_count = n;
}

double tu_bounding_radius(const ref_shape *s) {
    double r = 0.0;
    switch (s->kind) {
    case REF_POINT: r = 0.0; break;
    case REF_SPHERE: r = s->p[0]; break;
    case REF_ELLIPSOID: r = fmax(s->p[0], fmax(s->p[1], s->p[2])); break;
    case REF_BOX: r = sqrt(s->p[0] * s->p[0] + s->p[1] * s->p[1] + s->p[2] * s->p[2]); break;
    case REF_CAPSULE: r = s->p[0] + s->p[1]; break;
    case REF_CYLINDER:
    case REF_CONE: r = sqrt(s->p[0] * s->p[0] + s->p[1] * s->p[1]); break;
    case REF_POLYTOPE:
        for (int i = 0; i < s->vertex_count; i++) r = fmax(r, tu_norm(s->vertices[i]));
        break;
    }
    return r + s->margin;
}

int tu_set_distance(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                    agjk_pose *pose_b, double target, ref_result *before) {
    ref_result res;
    double reach = tu_bounding_radius(a) + tu_bounding_radius(b);
    if (ref_distance(a, pose_a, b, pose_b, &res) < 0) return -1;
    if (res.intersecting || res.distance <= 1e-3 * reach) {
        /* Move B out along the centre line, far enough to separate for sure. */
        agjk_vec3 u = tu_sub(pose_b->translation, pose_a->translation);
        double nu = tu_norm(u);
        u = nu > 0.0 ? tu_scale(u, 1.0 / nu) : tu_vec(1, 0, 0);
        pose_b->translation = tu_add(pose_a->translation, tu_scale(u, 1.1 * reach + 1e-3 * reach));
        if (ref_distance(a, pose_a, b, pose_b, &res) < 0) return -1;
        if (res.intersecting || !(res.distance > 0.0L)) return -1;
    }
    if (before != NULL) *before = res;
    /* Sliding B by t along the unit normal n (A towards B) moves D = A - B by
     * -t n; the closest point -d n becomes -(d + t) n and stays closest
     * (D stays in the half-space <y, -n> >= d + t), so the distance is d + t. */
    tu_pose_translate(pose_b, tu_scale(res.normal, target - (double)res.distance));
    return 0;
}

double tu_distance_to_shape(const ref_shape *s, const agjk_pose *pose, agjk_vec3 p) {
    ref_shape pt;
    ref_result r;
    agjk_pose pp = tu_pose_identity();
    tu_shape_init(&pt, REF_POINT, 0, 0, 0);
    pp.translation = p;
    if (ref_distance(s, pose, &pt, &pp, &r) < 0) return NAN;
    /* The certified lower bound: a point reported outside by x is certainly
     * outside by x, even where the reference converges slowly (a point on a
     * curved surface, distance 0, is GJK's slowest case). */
    return (double)r.lower;
}
