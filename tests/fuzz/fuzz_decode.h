/* SPDX-License-Identifier: MIT */
/* Turning fuzzer bytes into numbers, shapes, poses and options, and the
 * invariants every query result must satisfy whatever the input. Shared by
 * the fuzz targets in tests/fuzz (header-only: each target is one program). */
#ifndef AGJK_FUZZ_DECODE_H
#define AGJK_FUZZ_DECODE_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agjk/agjk.h"

typedef struct fuzz_reader {
    const uint8_t *data;
    size_t size, pos;
} fuzz_reader;

static inline uint8_t fz_u8(fuzz_reader *r) { return r->pos < r->size ? r->data[r->pos++] : 0; }

static inline uint16_t fz_u16(fuzz_reader *r) {
    uint16_t hi = fz_u8(r);
    return (uint16_t)((hi << 8) | fz_u8(r));
}

/* Values beyond AGJK_MAX_COORDINATE are documented to give
 * AGJK_STATUS_INVALID_INPUT, so every double goes through as decoded. Without
 * that limit (older headers), finite magnitudes are kept in [1e-150, 1e150]
 * because squared norms would overflow. */
static inline double fz_tame(double v) {
#ifndef AGJK_MAX_COORDINATE
    if (isfinite(v)) {
        if (fabs(v) > 1e150) return v > 0 ? 1e150 : -1e150;
        if (v != 0 && fabs(v) < 1e-150) return 0.0;
    }
#endif
    return v;
}

/* Largest size or coordinate the library accepts. */
#ifdef AGJK_MAX_COORDINATE
#define FZ_MAXC AGJK_MAX_COORDINATE
#else
#define FZ_MAXC 1e300
#endif

/* A double: mostly "nice" (a 16-bit mantissa times a power of ten in
 * 1e-12 .. 1e12, or small integers, or exact 0/1), sometimes raw bits (NaN,
 * Inf, denormals, anything). */
static inline double fz_double(fuzz_reader *r) {
    uint8_t tag = fz_u8(r);
    if (tag < 16) {
        uint64_t bits = 0;
        double v;
        for (int i = 0; i < 8; i++) bits = (bits << 8) | fz_u8(r);
        memcpy(&v, &bits, sizeof v);
        return fz_tame(v);
    }
    if (tag < 24) return (double)(tag - 20);
    {
        double m = ((double)fz_u16(r) - 32768.0) / 32768.0;
        int e = (int)(tag % 25) - 12;
        return m * pow(10.0, e);
    }
}

/* A double in [lo, hi] from 2 bytes. */
static inline double fz_unit(fuzz_reader *r, double lo, double hi) {
    return lo + (hi - lo) * (double)fz_u16(r) / 65535.0;
}

/* A pose: usually a proper rotation from a quaternion, sometimes raw entries. */
static inline void fz_pose(fuzz_reader *r, agjk_pose *p) {
    uint8_t mode = fz_u8(r);
    if (mode < 24) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) p->rotation[i][j] = fz_double(r);
    } else {
        double w = fz_unit(r, -1, 1), x = fz_unit(r, -1, 1), y = fz_unit(r, -1, 1),
               z = fz_unit(r, -1, 1);
        double n = sqrt(w * w + x * x + y * y + z * z);
        if (n == 0) w = n = 1;
        w /= n; x /= n; y /= n; z /= n;
        p->rotation[0][0] = 1 - 2 * (y * y + z * z);
        p->rotation[0][1] = 2 * (x * y - w * z);
        p->rotation[0][2] = 2 * (x * z + w * y);
        p->rotation[1][0] = 2 * (x * y + w * z);
        p->rotation[1][1] = 1 - 2 * (x * x + z * z);
        p->rotation[1][2] = 2 * (y * z - w * x);
        p->rotation[2][0] = 2 * (x * z - w * y);
        p->rotation[2][1] = 2 * (y * z + w * x);
        p->rotation[2][2] = 1 - 2 * (x * x + y * y);
    }
    p->translation.x = fz_double(r);
    p->translation.y = fz_double(r);
    p->translation.z = fz_double(r);
}

static inline void fz_options(fuzz_reader *r, agjk_options *o) {
    uint8_t flags = fz_u8(r);
    agjk_options_init(o);
    o->method = (agjk_method)(fz_u8(r) % 6);               /* 5: invalid */
    o->tolerance_mode = (agjk_tolerance_mode)(fz_u8(r) % 3); /* 2: invalid */
    if (flags & 1) o->tolerance = fz_double(r);
    o->max_iterations = (flags & 2) ? (int32_t)fz_u8(r) - 1 : 64;
    o->compute = fz_u8(r) % 3;
    if (flags & 4) {
        o->use_initial_direction = 1;
        o->initial_direction.x = fz_double(r);
        o->initial_direction.y = fz_double(r);
        o->initial_direction.z = fz_double(r);
    }
    if (flags & 8) {
        o->hint_a = (int32_t)fz_u16(r) - 100;
        o->hint_b = (int32_t)fz_u16(r) - 100;
    }
}

/* A violated invariant ends the process with exit(): libFuzzer reports a
 * target that exits as a crash and saves the input (even when its signal
 * handlers are off, as for the mesh target), and the replay fails. */
#define FUZZ_CHECK(cond, ...)                                              \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "fuzz invariant violated: %s: ", #cond);       \
            fprintf(stderr, __VA_ARGS__);                                  \
            fprintf(stderr, "\n");                                         \
            exit(86);                                                      \
        }                                                                  \
    } while (0)

static inline int fz_finite_result(const agjk_result *r) {
    const double v[12] = {r->distance, r->bound, r->gap, r->witness_a.x, r->witness_a.y,
                          r->witness_a.z, r->witness_b.x, r->witness_b.y, r->witness_b.z,
                          r->normal.x, r->normal.y, r->normal.z};
    for (int i = 0; i < 12; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* <dir, support> of a shape in world frame, through its own callback. */
static inline double fz_support_value(const agjk_shape *s, const agjk_pose *p, agjk_vec3 d) {
    agjk_vec3 u, out;
    int hint = 0;
    double n = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    u.x = p->rotation[0][0] * d.x + p->rotation[1][0] * d.y + p->rotation[2][0] * d.z;
    u.y = p->rotation[0][1] * d.x + p->rotation[1][1] * d.y + p->rotation[2][1] * d.z;
    u.z = p->rotation[0][2] * d.x + p->rotation[1][2] * d.y + p->rotation[2][2] * d.z;
    s->support(s->data, &u, &out, &hint);
    return u.x * out.x + u.y * out.y + u.z * out.z + s->margin * n + d.x * p->translation.x +
           d.y * p->translation.y + d.z * p->translation.z;
}

/* Sum of |support point| over the six axis directions of the local frame:
 * bounds the shape's extent around its origin (margin excluded). */
static inline double fz_extent(const agjk_shape *s) {
    double e = 0;
    for (int k = 0; k < 6; k++) {
        agjk_vec3 d = {0, 0, 0}, p;
        int hint = 0;
        double *c = k % 3 == 0 ? &d.x : k % 3 == 1 ? &d.y : &d.z;
        *c = k < 3 ? 1.0 : -1.0;
        s->support(s->data, &d, &p, &hint);
        e += fabs(p.x) + fabs(p.y) + fabs(p.z);
    }
    return e;
}

/* The size of a problem, for rounding slacks: translations, extents and
 * margins of both shapes. */
/* How far a pose's rotation is from orthonormal: max |(R R^T - I)_ij| (the
 * queries accept up to 1e-6). */
static inline double fz_rotation_skew(const agjk_pose *p) {
    double m = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double *ri = p->rotation[i], *rj = p->rotation[j];
            double e = ri[0] * rj[0] + ri[1] * rj[1] + ri[2] * rj[2] - (i == j ? 1.0 : 0.0);
            if (fabs(e) > m) m = fabs(e);
        }
    return m;
}

static inline double fz_scale(const agjk_shape *a, const agjk_pose *pa, const agjk_shape *b,
                              const agjk_pose *pb) {
    return fabs(pa->translation.x) + fabs(pa->translation.y) + fabs(pa->translation.z) +
           fabs(pb->translation.x) + fabs(pb->translation.y) + fabs(pb->translation.z) +
           fz_extent(a) + fz_extent(b) + a->margin + b->margin;
}

/* Runs both queries on one input and checks every invariant that holds
 * whatever the input: documented status, result equal to the return value,
 * no NaN (no Inf either for finite, tame inputs), status semantics, and that
 * two certified answers never contradict each other (the last two need
 * exact support functions: `exact` 0 skips them). */
static inline void fz_check_pair(const agjk_shape *a, const agjk_pose *pa, const agjk_shape *b,
                                 const agjk_pose *pb, const agjk_options *o, int exact) {
    agjk_result rd, rc;
    agjk_status sd = agjk_distance(a, pa, b, pb, o, &rd);
    agjk_status sc = agjk_collide(a, pa, b, pb, o, &rc);
#ifdef FUZZ_DEBUG
    fprintf(stderr, "distance: %s d %.17g bound %g gap %g it %d | collide: %s it %d | hints %d %d\n",
            agjk_status_string(sd), rd.distance, rd.bound, rd.gap, rd.iterations,
            agjk_status_string(sc), rc.iterations, o ? o->hint_a : 0, o ? o->hint_b : 0);
#endif
    FUZZ_CHECK(sd == rd.status && sc == rc.status, "status %d/%d vs %d/%d", sd, rd.status, sc,
               rc.status);
    FUZZ_CHECK((unsigned)sd <= AGJK_STATUS_INVALID_INPUT && (unsigned)sc <= AGJK_STATUS_INVALID_INPUT,
               "status out of range %d %d", sd, sc);
    FUZZ_CHECK(fz_finite_result(&rd), "distance result not finite: d %g bound %g gap %g", rd.distance,
               rd.bound, rd.gap);
    FUZZ_CHECK(fz_finite_result(&rc), "collide result not finite: gap %g", rc.gap);
    FUZZ_CHECK((sd == AGJK_STATUS_INVALID_INPUT) == (sc == AGJK_STATUS_INVALID_INPUT) ||
                   (o && (o->compute & ~1u)) || rd.support_calls > 0 || rc.support_calls > 0,
               "distance %s but collide %s", agjk_status_string(sd), agjk_status_string(sc));
    if (sd != AGJK_STATUS_INVALID_INPUT) {
        FUZZ_CHECK(rd.distance >= 0 && rd.bound >= 0, "negative distance/bound %g %g", rd.distance,
                   rd.bound);
        FUZZ_CHECK(rd.iterations >= 0 && rd.support_calls >= 0, "counters");
        if (sd == AGJK_STATUS_SEPARATED)
            FUZZ_CHECK(rd.distance - rd.bound > 0, "SEPARATED with distance %g bound %g", rd.distance,
                       rd.bound);
        if (sd == AGJK_STATUS_INTERSECTING)
            FUZZ_CHECK(rd.distance == 0, "INTERSECTING with distance %g", rd.distance);
    }
    /* Two certified verdicts cannot disagree. */
    FUZZ_CHECK(!exact || !((sd == AGJK_STATUS_SEPARATED && sc == AGJK_STATUS_INTERSECTING) ||
                 (sd == AGJK_STATUS_INTERSECTING && sc == AGJK_STATUS_SEPARATED)),
               "distance says %s, collide says %s", agjk_status_string(sd), agjk_status_string(sc));
    if (exact && sc == AGJK_STATUS_SEPARATED && a && b && a->support && b->support) {
        /* The separating plane, evaluated through the shapes' own supports:
         * h_A(n) + h_B(-n) <= rounding. */
        agjk_vec3 n = rc.normal, m = {-rc.normal.x, -rc.normal.y, -rc.normal.z};
        double ha = fz_support_value(a, pa, n), hb = fz_support_value(b, pb, m);
#ifdef FUZZ_DEBUG
        fprintf(stderr, "collide normal %.17g %.17g %.17g: h_A(n) %.17g h_B(-n) %.17g\n", n.x, n.y,
                n.z, ha, hb);
#endif
        /* The normal is reported in world frame, rounded: turning it back
         * into a shape's frame moves h by ~eps x the shape's extent, so the
         * slack scales with the extents (a 1e48 vertex makes any world-frame
         * plane uncertain by ~1e32), not with the distance. A rotation that
         * is orthonormal only to within its skew (accepted up to 1e-6) is
         * taken as the rotation it stands for (agjk_pose): the plane is exact
         * in A's frame, and its world image, through R_A, tilts by about that
         * skew against the shapes placed by the non-orthonormal matrices
         * (a needle 7e8 long under a skew of 1e-7: 63 units). */
        double scale = fz_scale(a, pa, b, pb);
        double skew = fz_rotation_skew(pa) + fz_rotation_skew(pb);
        FUZZ_CHECK(ha + hb <= (1e-12 + 8.0 * skew) * scale,
                   "collide SEPARATED but plane overlaps by %g (scale %g, skew %g)", ha + hb, scale,
                   skew);
    }
}

#endif
