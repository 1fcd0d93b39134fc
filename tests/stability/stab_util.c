/* SPDX-License-Identifier: MIT */
/* Helpers shared by the stability tests; see stab_util.h. */
#include "stab_util.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint64_t stab_next(stab_rng *rng) {
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double stab_uniform(stab_rng *rng) {
    /* 53 random bits: exactly representable, in [0, 1). */
    return (double)(stab_next(rng) >> 11) * (1.0 / 9007199254740992.0);
}

double stab_range(stab_rng *rng, double lo, double hi) {
    return lo + (hi - lo) * stab_uniform(rng);
}

agjk_vec3 stab_unit(stab_rng *rng) {
    /* Rejection from the cube keeps the distribution uniform. */
    for (;;) {
        double x = stab_range(rng, -1, 1), y = stab_range(rng, -1, 1), z = stab_range(rng, -1, 1);
        double n2 = x * x + y * y + z * z;
        if (n2 > 1e-4 && n2 <= 1.0) {
            double n = sqrt(n2);
            agjk_vec3 v = {x / n, y / n, z / n};
            return v;
        }
    }
}

void stab_pose_identity(agjk_pose *pose) {
    memset(pose, 0, sizeof *pose);
    pose->rotation[0][0] = pose->rotation[1][1] = pose->rotation[2][2] = 1.0;
}

void stab_pose_quat(agjk_pose *pose, double w, double x, double y, double z) {
    double n = sqrt(w * w + x * x + y * y + z * z);
    w /= n; x /= n; y /= n; z /= n;
    pose->rotation[0][0] = 1 - 2 * (y * y + z * z);
    pose->rotation[0][1] = 2 * (x * y - w * z);
    pose->rotation[0][2] = 2 * (x * z + w * y);
    pose->rotation[1][0] = 2 * (x * y + w * z);
    pose->rotation[1][1] = 1 - 2 * (x * x + z * z);
    pose->rotation[1][2] = 2 * (y * z - w * x);
    pose->rotation[2][0] = 2 * (x * z - w * y);
    pose->rotation[2][1] = 2 * (y * z + w * x);
    pose->rotation[2][2] = 1 - 2 * (x * x + y * y);
}

void stab_pose_random_rotation(agjk_pose *pose, stab_rng *rng) {
    /* Shoemake, "Uniform random rotations", Graphics Gems III (1992). */
    const double two_pi = 6.283185307179586;
    double u1 = stab_uniform(rng), u2 = stab_uniform(rng), u3 = stab_uniform(rng);
    double a = sqrt(1 - u1), b = sqrt(u1);
    stab_pose_quat(pose, b * cos(two_pi * u3), a * sin(two_pi * u2), a * cos(two_pi * u2),
                   b * sin(two_pi * u3));
}

static long double norm3l(const long double v[3]) {
    return sqrtl(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static long double sgnl(long double v) { return v < 0 ? -1.0L : 1.0L; }

/* Support point of the core (no margin) in the local frame. */
static void support_local(const ref_shape *s, const long double u[3], long double p[3]) {
    long double n = norm3l(u);
    p[0] = p[1] = p[2] = 0;
    switch (s->kind) {
    case REF_POINT:
        break;
    case REF_SPHERE:
        if (n > 0) for (int i = 0; i < 3; i++) p[i] = (long double)s->p[0] * u[i] / n;
        break;
    case REF_ELLIPSOID: {
        /* argmax over sum (x_i / r_i)^2 <= 1: x_i = r_i^2 u_i / ||r o u||. */
        long double ru[3], m;
        for (int i = 0; i < 3; i++) ru[i] = (long double)s->p[i] * u[i];
        m = norm3l(ru);
        if (m > 0) for (int i = 0; i < 3; i++) p[i] = (long double)s->p[i] * ru[i] / m;
        break;
    }
    case REF_BOX:
        for (int i = 0; i < 3; i++) p[i] = sgnl(u[i]) * (long double)s->p[i];
        break;
    case REF_CAPSULE:
        p[2] = sgnl(u[2]) * (long double)s->p[1];
        if (n > 0) for (int i = 0; i < 3; i++) p[i] += (long double)s->p[0] * u[i] / n;
        break;
    case REF_CYLINDER:
    case REF_CONE: {
        long double r = sqrtl(u[0] * u[0] + u[1] * u[1]), rad = s->p[0], hh = s->p[1];
        long double rim[3] = {0, 0, 0};
        if (r > 0) { rim[0] = rad * u[0] / r; rim[1] = rad * u[1] / r; }
        if (s->kind == REF_CYLINDER) {
            p[0] = rim[0]; p[1] = rim[1]; p[2] = sgnl(u[2]) * hh;
        } else if (hh * u[2] >= rad * r - hh * u[2]) {
            p[2] = hh; /* apex */
        } else {
            p[0] = rim[0]; p[1] = rim[1]; p[2] = -hh;
        }
        break;
    }
    case REF_POLYTOPE: {
        long double best = -INFINITY;
        for (int i = 0; i < s->vertex_count; i++) {
            const agjk_vec3 *v = &s->vertices[i];
            long double d = u[0] * v->x + u[1] * v->y + u[2] * v->z;
            if (d > best) { best = d; p[0] = v->x; p[1] = v->y; p[2] = v->z; }
        }
        break;
    }
    }
}

static long double shape_margin(const ref_shape *s) {
    /* Capsule radius is part of support_local; sphere too. Only the extra margin here. */
    return s->margin;
}

long double stab_support_world(const ref_shape *s, const agjk_pose *pose,
                               const long double dir[3], long double out[3]) {
    long double u[3], p[3], n = norm3l(dir);
    const double (*R)[3] = pose->rotation;
    /* local direction = R^T dir */
    for (int i = 0; i < 3; i++)
        u[i] = R[0][i] * dir[0] + R[1][i] * dir[1] + R[2][i] * dir[2];
    support_local(s, u, p);
    if (n > 0)
        for (int i = 0; i < 3; i++) p[i] += shape_margin(s) * u[i] / n;
    out[0] = R[0][0] * p[0] + R[0][1] * p[1] + R[0][2] * p[2] + pose->translation.x;
    out[1] = R[1][0] * p[0] + R[1][1] * p[1] + R[1][2] * p[2] + pose->translation.y;
    out[2] = R[2][0] * p[0] + R[2][1] * p[1] + R[2][2] * p[2] + pose->translation.z;
    return dir[0] * out[0] + dir[1] * out[1] + dir[2] * out[2];
}

double stab_radius(const ref_shape *s) {
    double r = 0;
    switch (s->kind) {
    case REF_POINT: r = 0; break;
    case REF_SPHERE: r = s->p[0]; break;
    case REF_ELLIPSOID: r = fmax(s->p[0], fmax(s->p[1], s->p[2])); break;
    case REF_BOX: r = sqrt(s->p[0] * s->p[0] + s->p[1] * s->p[1] + s->p[2] * s->p[2]); break;
    case REF_CAPSULE: r = s->p[0] + s->p[1]; break;
    case REF_CYLINDER: case REF_CONE: r = sqrt(s->p[0] * s->p[0] + s->p[1] * s->p[1]); break;
    case REF_POLYTOPE:
        for (int i = 0; i < s->vertex_count; i++) {
            const agjk_vec3 *v = &s->vertices[i];
            r = fmax(r, sqrt(v->x * v->x + v->y * v->y + v->z * v->z));
        }
        break;
    }
    return r + s->margin;
}

agjk_status stab_make_shape(ref_shape *s, agjk_shape *out) {
    agjk_status st = AGJK_STATUS_INVALID_INPUT;
    switch (s->kind) {
    case REF_POINT: st = agjk_shape_point(out); break;
    case REF_SPHERE: st = agjk_shape_sphere(out, s->p[0]); break;
    case REF_ELLIPSOID:
        s->ellipsoid.radii.x = s->p[0]; s->ellipsoid.radii.y = s->p[1]; s->ellipsoid.radii.z = s->p[2];
        st = agjk_shape_ellipsoid(out, &s->ellipsoid);
        break;
    case REF_BOX:
        s->box.half_extents.x = s->p[0]; s->box.half_extents.y = s->p[1]; s->box.half_extents.z = s->p[2];
        st = agjk_shape_box(out, &s->box);
        break;
    case REF_CAPSULE:
        s->capsule.radius = s->p[0]; s->capsule.half_height = s->p[1];
        st = agjk_shape_capsule(out, &s->capsule);
        break;
    case REF_CYLINDER:
        s->cylinder.radius = s->p[0]; s->cylinder.half_height = s->p[1];
        st = agjk_shape_cylinder(out, &s->cylinder);
        break;
    case REF_CONE:
        s->cone.radius = s->p[0]; s->cone.half_height = s->p[1];
        st = agjk_shape_cone(out, &s->cone);
        break;
    case REF_POLYTOPE:
        memset(&s->polytope, 0, sizeof s->polytope);
        s->polytope.vertices = s->vertices;
        s->polytope.vertex_count = s->vertex_count;
        st = agjk_shape_polytope(out, &s->polytope);
        break;
    }
    if (st != AGJK_STATUS_OK || s->margin == 0) return st;
    return agjk_shape_set_margin(out, out->margin + s->margin);
}

void stab_place(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                agjk_pose *pose_b, const double n[3], double sep) {
    long double dn[3] = {n[0], n[1], n[2]}, mn[3] = {-n[0], -n[1], -n[2]};
    long double pa[3], pb[3];
    stab_support_world(a, pose_a, dn, pa);
    stab_support_world(b, pose_b, mn, pb);
    pose_b->translation.x = (double)(pose_b->translation.x + (pa[0] + sep * dn[0] - pb[0]));
    pose_b->translation.y = (double)(pose_b->translation.y + (pa[1] + sep * dn[1] - pb[1]));
    pose_b->translation.z = (double)(pose_b->translation.z + (pa[2] + sep * dn[2] - pb[2]));
}

int stab_contains(const ref_shape *s, const agjk_pose *pose, const long double p[3]) {
    long double d[3], q[3], v = 0, m = s->margin;
    const double (*R)[3] = pose->rotation;
    const long double in = 1 - 1e-12L; /* strictly inside, well above rounding */
    d[0] = p[0] - pose->translation.x;
    d[1] = p[1] - pose->translation.y;
    d[2] = p[2] - pose->translation.z;
    for (int i = 0; i < 3; i++) q[i] = R[0][i] * d[0] + R[1][i] * d[1] + R[2][i] * d[2];
    switch (s->kind) {
    case REF_POINT:
        return sqrtl(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) < m * in;
    case REF_SPHERE:
        return sqrtl(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) < (s->p[0] + m) * in;
    case REF_ELLIPSOID:
        if (m != 0) return -1;
        for (int i = 0; i < 3; i++) v += (q[i] / s->p[i]) * (q[i] / s->p[i]);
        return v < in;
    case REF_BOX:
        if (m != 0) return -1;
        for (int i = 0; i < 3; i++)
            if (!(fabsl(q[i]) < s->p[i] * in)) return 0;
        return 1;
    case REF_CAPSULE: {
        long double z = fabsl(q[2]) - s->p[1];
        if (z < 0) z = 0;
        return sqrtl(q[0] * q[0] + q[1] * q[1] + z * z) < (s->p[0] + m) * in;
    }
    default:
        return -1;
    }
}

int stab_place_overlap(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                       agjk_pose *pose_b, const double n[3], double depth) {
    long double mn[3] = {-n[0], -n[1], -n[2]}, pb[3];
    stab_place(a, pose_a, b, pose_b, n, -fabs(depth));
    /* B's support point after rounding the pose: a point of B; inside A? */
    stab_support_world(b, pose_b, mn, pb);
    return stab_contains(a, pose_a, pb) == 1;
}

static double vnorm(const agjk_vec3 *v) { return sqrt(v->x * v->x + v->y * v->y + v->z * v->z); }

double stab_magnitude(const ref_shape *a, const agjk_pose *pa,
                      const ref_shape *b, const agjk_pose *pb) {
    return vnorm(&pa->translation) + vnorm(&pb->translation) + stab_radius(a) + stab_radius(b);
}

int stab_result_sane(const char *name, agjk_status returned, const agjk_result *r,
                     int max_iterations) {
    int soft = 0;
    double vals[16] = {r->distance, r->bound, r->gap, r->witness_a.x, r->witness_a.y,
                       r->witness_a.z, r->witness_b.x, r->witness_b.y, r->witness_b.z,
                       r->normal.x, r->normal.y, r->normal.z, 0, 0, 0, 0};
    /* Queries never return AGJK_STATUS_OK (types.h). */
    if (r->status != returned || (unsigned)returned > AGJK_STATUS_INVALID_INPUT) {
        printf("FAIL %s: status %d returned %d\n", name, (int)r->status, (int)returned);
        return 2;
    }
    for (int i = 0; i < 12; i++)
        if (!isfinite(vals[i])) {
            printf("FAIL %s: non-finite result field %d (%g)\n", name, i, vals[i]);
            return 2;
        }
    for (int i = 0; i < 8; i++)
        if (r->reserved[i] != 0) {
            printf("FAIL %s: reserved[%d] = %g, documented as zero\n", name, i, r->reserved[i]);
            return 2;
        }
    if (r->distance < 0 || r->bound < 0) {
        printf("FAIL %s: negative distance/bound %g %g\n", name, r->distance, r->bound);
        return 2;
    }
    if (r->gap < 0) {
        /* The duality gap is >= 0 by definition (eq. 12-13); a negative value
         * is rounding leaking out, and sqrt(gap) would be NaN for the user. */
        printf("FAIL %s: negative duality gap %g\n", name, r->gap);
        soft = 1;
    }
    if (r->iterations < 0 || (max_iterations > 0 && r->iterations > max_iterations) ||
        r->support_calls < 0 || r->momentum_stop_iteration < -1) {
        printf("FAIL %s: counters iterations %d support_calls %d momentum_stop %d (cap %d)\n",
               name, r->iterations, r->support_calls, r->momentum_stop_iteration, max_iterations);
        return 2;
    }
    if (returned == AGJK_STATUS_INVALID_INPUT) {
        /* "Nothing was computed": no distance, bound, gap, witness or normal
         * (the counters may show the work done before a bad support point). */
        if (r->distance != 0 || r->bound != 0 || r->gap != 0 || r->normal.x != 0 ||
            r->normal.y != 0 || r->normal.z != 0 || r->witness_a.x != 0 || r->witness_b.x != 0) {
            printf("FAIL %s: INVALID_INPUT result carries values (d %g bound %g gap %g)\n",
                   name, r->distance, r->bound, r->gap);
            return 2;
        }
    }
    return soft;
}

void stab_guard_fill(unsigned char *guard) { memset(guard, STAB_GUARD_BYTE, STAB_GUARD); }

int stab_guard_ok(const unsigned char *guard) {
    for (int i = 0; i < STAB_GUARD; i++)
        if (guard[i] != STAB_GUARD_BYTE) return 0;
    return 1;
}

/* Output struct surrounded by guard bytes. */
typedef struct guarded_result {
    unsigned char pre[STAB_GUARD];
    agjk_result r;
    unsigned char post[STAB_GUARD];
} guarded_result;

static void guarded_init(guarded_result *g) {
    stab_guard_fill(g->pre);
    stab_guard_fill(g->post);
    /* Garbage in the struct itself: every field must be overwritten. */
    memset(&g->r, 0xFF, sizeof g->r);
}

static int guarded_ok(const char *name, const guarded_result *g) {
    if (stab_guard_ok(g->pre) && stab_guard_ok(g->post)) return 1;
    printf("FAIL %s: write outside the result struct\n", name);
    return 0;
}

/* -(h_A(n) + h_B(-n)): signed gap between A and B along unit n; a lower bound
 * on the distance whatever n, computed independently in long double. */
static long double plane_gap(const ref_shape *a, const agjk_pose *pa, const ref_shape *b,
                             const agjk_pose *pb, const agjk_vec3 *n) {
    long double dn[3] = {n->x, n->y, n->z}, mn[3] = {-n->x, -n->y, -n->z}, p[3];
    long double len = norm3l(dn);
    if (!(len > 0)) return -INFINITY;
    return -(stab_support_world(a, pa, dn, p) + stab_support_world(b, pb, mn, p)) / len;
}

static const agjk_method all_methods[] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                          AGJK_METHOD_NESTEROV_NORMALIZED, AGJK_METHOD_POLYAK,
                                          AGJK_METHOD_FRANK_WOLFE, AGJK_METHOD_ADAPTIVE};

static void note_failure(stab_stats *st) { st->failures++; }

/* Distance query checks. truth_lo/hi: certified bracket of the true distance
 * (or lo > hi when unknown). truth_slack: how far the bracket itself may be off
 * (0 for the long-double reference, which reads the very doubles the query
 * reads; a few ulps for an analytic value that the double inputs only
 * approximate). slack: rounding allowance for the other checks. */
static void check_distance(const char *qname, const ref_shape *a, const agjk_pose *pa,
                           const ref_shape *b, const agjk_pose *pb, const agjk_shape *sa,
                           const agjk_shape *sb, const agjk_options *opt, double truth_lo,
                           double truth_hi, double truth_slack, double slack, stab_stats *st) {
    guarded_result g;
    guarded_init(&g);
    agjk_status s = agjk_distance(sa, pa, sb, pb, opt, &g.r);
    const agjk_result *r = &g.r;
    st->queries++;
    if (!guarded_ok(qname, &g)) {
        note_failure(st);
        return;
    }
    switch (stab_result_sane(qname, s, r, opt->max_iterations)) {
    case 0: break;
    case 1: note_failure(st); break; /* minor: keep checking the rest */
    default: note_failure(st); return;
    }
    if (s == AGJK_STATUS_INVALID_INPUT) {
        printf("FAIL %s: INVALID_INPUT on valid input\n", qname);
        note_failure(st);
        return;
    }
    double lo = fmax(0.0, r->distance - r->bound), hi = r->distance;
    if (getenv("STAB_VERBOSE"))
        printf("%s: %s d %.17g bound %.3g gap %.3g it %d truth [%.17g, %.17g]\n", qname,
               agjk_status_string(s), r->distance, r->bound, r->gap, r->iterations, truth_lo,
               truth_hi);
    if (s == AGJK_STATUS_NOT_CONVERGED) st->not_converged++;
    if (s == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE) st->contact++;
    if (s == AGJK_STATUS_SEPARATED && !(r->distance - r->bound > 0)) {
        printf("FAIL %s: SEPARATED but distance - bound = %g <= 0\n", qname, r->distance - r->bound);
        note_failure(st);
    }
    if (s == AGJK_STATUS_INTERSECTING && r->distance != 0) {
        printf("FAIL %s: INTERSECTING with distance %g\n", qname, r->distance);
        note_failure(st);
    }
    if (s == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE && r->distance > r->bound * (1 + 1e-12)) {
        printf("FAIL %s: CONTACT with distance %g > bound %g\n", qname, r->distance, r->bound);
        note_failure(st);
    }
    if (truth_lo <= truth_hi) {
        /* The certified interval [lo, hi] must hold the true distance: both
         * ends, rounding included (the library's own allowance, no slack). */
        if (truth_hi < lo - truth_slack || truth_lo > hi + truth_slack) {
            printf("FAIL %s: status %s distance %.17g bound %.3g but true distance in "
                   "[%.17g, %.17g] (slack %.3g)\n",
                   qname, agjk_status_string(s), r->distance, r->bound, truth_lo, truth_hi,
                   truth_slack);
            note_failure(st);
        }
        double dtrue = 0.5 * (truth_lo + truth_hi);
        if (s != AGJK_STATUS_INTERSECTING && dtrue > 0) {
            double err = fabs(r->distance - dtrue);
            double rel = err / dtrue, ratio = err / (r->bound + slack);
            /* Relative error means something only where the caller asked for
             * it (relative mode) and the answer claims convergence. */
            if (s == AGJK_STATUS_SEPARATED && opt->tolerance_mode == AGJK_TOLERANCE_RELATIVE &&
                rel > st->worst_rel) {
                st->worst_rel = rel;
                snprintf(st->worst_name, sizeof st->worst_name, "%s", qname);
            }
            if (s == AGJK_STATUS_SEPARATED && opt->tolerance_mode == AGJK_TOLERANCE_RELATIVE &&
                dtrue > 1e4 * slack && rel > st->worst_rel_clear)
                st->worst_rel_clear = rel;
            if (ratio > st->worst_bound_ratio) st->worst_bound_ratio = ratio;
            /* The documented promise of relative mode (types.h): a certified
             * relative error of at most tolerance / 2, rounding included. The
             * worst case over the true bracket may exceed it only by the
             * bracket's own width. */
            double worst = fmax(fabs(r->distance - truth_lo), fabs(r->distance - truth_hi));
            if (s == AGJK_STATUS_SEPARATED && opt->tolerance_mode == AGJK_TOLERANCE_RELATIVE &&
                worst > 0.5 * opt->tolerance * (truth_lo - truth_slack) + (truth_hi - truth_lo) +
                            2 * truth_slack) {
                printf("FAIL %s: relative mode, SEPARATED, relative error %.3g > tolerance/2 = "
                       "%.3g (distance %.17g, true in [%.17g, %.17g], bound %.3g)\n",
                       qname, worst / truth_lo, 0.5 * opt->tolerance, r->distance, truth_lo,
                       truth_hi, r->bound);
                note_failure(st);
            }
        }
    }
    /* Independent certificate: the plane normal to `normal` must show the
     * lower bound distance - bound (up to rounding) when separated. */
    if (s == AGJK_STATUS_SEPARATED) {
        long double gap = plane_gap(a, pa, b, pb, &r->normal);
        if (gap < lo - slack - 1e-9 * r->distance) {
            printf("FAIL %s: normal's plane gap %.17Lg < distance - bound %.17g\n", qname, gap, lo);
            note_failure(st);
        }
        if (opt->compute & AGJK_COMPUTE_WITNESS) {
            agjk_vec3 w = {r->witness_b.x - r->witness_a.x, r->witness_b.y - r->witness_a.y,
                           r->witness_b.z - r->witness_a.z};
            if (fabs(vnorm(&w) - r->distance) > r->bound + slack + 1e-9 * r->distance) {
                printf("FAIL %s: |witness_b - witness_a| = %.17g vs distance %.17g\n", qname,
                       vnorm(&w), r->distance);
                note_failure(st);
            }
        }
    }
}

static void check_collide(const char *qname, const ref_shape *a, const agjk_pose *pa,
                          const ref_shape *b, const agjk_pose *pb, const agjk_shape *sa,
                          const agjk_shape *sb, const agjk_options *opt, double truth_lo,
                          double truth_hi, double slack, stab_stats *st) {
    guarded_result g;
    guarded_init(&g);
    agjk_status s = agjk_collide(sa, pa, sb, pb, opt, &g.r);
    const agjk_result *r = &g.r;
    st->queries++;
    if (!guarded_ok(qname, &g)) {
        note_failure(st);
        return;
    }
    switch (stab_result_sane(qname, s, r, opt->max_iterations)) {
    case 0: break;
    case 1: note_failure(st); break; /* minor: keep checking the rest */
    default: note_failure(st); return;
    }
    switch (s) {
    case AGJK_STATUS_SEPARATED: {
        /* Verify the separating plane ourselves. */
        long double gap = plane_gap(a, pa, b, pb, &r->normal);
        if (gap < -slack) {
            printf("FAIL %s: SEPARATED but the plane of normal (%g %g %g) overlaps by %.3Lg\n",
                   qname, r->normal.x, r->normal.y, r->normal.z, -gap);
            note_failure(st);
        }
        if (truth_lo <= truth_hi && truth_hi <= 0) {
            printf("FAIL %s: SEPARATED but reference certifies overlap\n", qname);
            note_failure(st);
        }
        break;
    }
    case AGJK_STATUS_INTERSECTING:
        if (truth_lo <= truth_hi && truth_lo > slack) {
            printf("FAIL %s: INTERSECTING but true distance >= %.17g\n", qname, truth_lo);
            note_failure(st);
        }
        break;
    case AGJK_STATUS_CONTACT_WITHIN_TOLERANCE:
        st->contact++;
        /* Claimed closer than the tolerance: the true distance <= sqrt(gap). */
        if (truth_lo <= truth_hi && truth_lo > sqrt(fmax(r->gap, 0.0)) + slack) {
            printf("FAIL %s: CONTACT (gap %.3g) but true distance >= %.17g\n", qname, r->gap,
                   truth_lo);
            note_failure(st);
        }
        break;
    case AGJK_STATUS_NOT_CONVERGED:
        st->not_converged++;
        break;
    default:
        printf("FAIL %s: collide returned %s on valid input\n", qname, agjk_status_string(s));
        note_failure(st);
    }
}

int stab_check_case(const char *name, ref_shape *a, const agjk_pose *pa, ref_shape *b,
                    const agjk_pose *pb, int which, agjk_tolerance_mode mode, double tolerance,
                    int max_iterations, double known_sep, stab_stats *st) {
    long before = st->failures;
    agjk_shape sa, sb;
    char qname[160];
    double M = stab_magnitude(a, pa, b, pb);
    /* Rounding of the inputs themselves (poses and sizes stored in double)
     * moves the true distance by a few ulps of the problem's magnitude. */
    double slack = 64 * DBL_EPSILON * M;
    double truth_lo = 1, truth_hi = 0, truth_slack = 0;
    ref_result ref;

    st->cases++;
    if (stab_make_shape(a, &sa) != AGJK_STATUS_OK || stab_make_shape(b, &sb) != AGJK_STATUS_OK) {
        printf("FAIL %s: shape constructor rejected a valid shape\n", name);
        st->failures++;
        return 1;
    }
    memset(&ref, 0, sizeof ref);
    if (which & STAB_DISTANCE || known_sep == STAB_UNKNOWN) {
        if (ref_distance(a, pa, b, pb, &ref) == 0) {
            /* Rounded outwards to double: the bracket stays certified. */
            truth_lo = (double)ref.lower;
            truth_hi = (double)ref.upper;
            if ((long double)truth_lo > ref.lower) truth_lo = nextafter(truth_lo, -INFINITY);
            if ((long double)truth_hi < ref.upper) truth_hi = nextafter(truth_hi, INFINITY);
            /* The reference's own rounding: it works in world coordinates,
             * in long double (far from the origin that is ~1e-13 at 1e6). */
            truth_slack = 16 * LDBL_EPSILON * M;
            if (ref.intersecting) truth_lo = truth_hi = 0;
        } else {
            printf("NOTE %s: the reference did not converge (%d iterations, [%.17Lg, %.17Lg])\n",
                   name, ref.iterations, ref.lower, ref.upper);
            st->ref_failures++;
        }
    }
    if (known_sep == STAB_OVERLAP) {
        if (truth_lo <= truth_hi && truth_lo > slack) {
            printf("NOTE %s: reference [%.17g, %.17g] disagrees with certified overlap\n", name,
                   truth_lo, truth_hi);
            st->ref_failures++;
        }
        truth_lo = truth_hi = 0;
        truth_slack = slack;
    } else if (known_sep >= 0) {
        if (truth_lo <= truth_hi &&
            (known_sep < truth_lo - slack || known_sep > truth_hi + slack)) {
            printf("NOTE %s: reference [%.17g, %.17g] disagrees with analytic %.17g; "
                   "using the analytic value\n", name, truth_lo, truth_hi, known_sep);
            st->ref_failures++;
        }
        truth_lo = known_sep;
        truth_hi = known_sep;
        truth_slack = slack;
    }
    for (size_t m = 0; m < sizeof all_methods / sizeof all_methods[0]; m++) {
        agjk_options opt = agjk_default_options();
        opt.method = all_methods[m];
        opt.tolerance_mode = mode;
        opt.tolerance = tolerance;
        opt.max_iterations = max_iterations;
        if (which & STAB_DISTANCE) {
            snprintf(qname, sizeof qname, "%s [distance %s]", name, agjk_method_name(opt.method));
            check_distance(qname, a, pa, b, pb, &sa, &sb, &opt, truth_lo, truth_hi, truth_slack,
                           slack, st);
        }
        if (which & STAB_COLLIDE) {
            snprintf(qname, sizeof qname, "%s [collide %s]", name, agjk_method_name(opt.method));
            check_collide(qname, a, pa, b, pb, &sa, &sb, &opt, truth_lo, truth_hi, slack, st);
        }
    }
    return (int)(st->failures - before);
}

void stab_stats_print(const char *title, const stab_stats *s) {
    printf("%s: %ld cases, %ld queries, %ld failures, %ld not converged, %ld contact, "
           "%ld reference misses; worst relative error %.3g (%s; rounding of the inputs "
           "dominates there), %.3g where the distance exceeds 1e4 x the rounding slack; "
           "worst error/bound %.3g\n",
           title, s->cases, s->queries, s->failures, s->not_converged, s->contact,
           s->ref_failures, s->worst_rel, s->worst_name[0] ? s->worst_name : "-",
           s->worst_rel_clear, s->worst_bound_ratio);
}
