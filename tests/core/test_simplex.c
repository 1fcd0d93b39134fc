/* SPDX-License-Identifier: MIT */
/* agjk_simplex_project_origin against the long double brute force of
 * tests/common (ref_project_origin), on random, degenerate and extreme
 * simplices. Checked: the point (tolerance relative to the simplex's
 * coordinates), weights >= 0 summing to 1 and reproducing the point, the
 * support mask = the non-zero weights and minimal, status, no NaN ever.
 *
 * The same checks for the internal projection specialised for GJK
 * (agjk__simplex_project_gjk, src/simplex.h), on the same simplices, on
 * simplices built the way GJK builds them (runs of GJK on random point
 * clouds), on adversarial ones where the newest vertex is not in the
 * optimal face, and on thin tetrahedra holding the origin; its fast path
 * alone (agjk__simplex_project_gjk_fast) must be right whenever it
 * answers. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check_main.h"
#include "reference.h"
#include "testutil.h"
#include "../../src/simplex.h"

/* Error allowed in the point, relative to the largest coordinate magnitude:
 * a few hundred ulps covers the cancellation of any reasonable method. */
#define POINT_TOL 1e-12

static double max_abs_coord(const agjk_vec3 *w, int n) {
    double m = 0.0;
    for (int i = 0; i < n; i++) m = fmax(m, fmax(fabs(w[i].x), fmax(fabs(w[i].y), fabs(w[i].z))));
    return m;
}

static int popcount4(uint32_t m) {
    int c = 0;
    for (int i = 0; i < 4; i++) c += (m >> i) & 1u;
    return c;
}

static double worst_rel_error; /* reported at the end of random_simplices */
/* When set, point and weight-reconstruction errors are counted in
 * soft_failures (with the worst case kept) instead of stopping the test, so
 * that one run reports how often and how badly the library misses. */
static int soft_mode, soft_failures, soft_worst_case;
static double soft_worst;

static void point_failure(int ok, double err_rel, int i) {
    if (ok) return;
    soft_failures++;
    if (err_rel > soft_worst) {
        soft_worst = err_rel;
        soft_worst_case = i;
    }
}

/* Checks everything that does not depend on the minimality of the mask;
 * returns the agjk projection in *pj. */
static void check_projection(const agjk_vec3 *w, int n, const char *what, int i,
                             agjk_simplex_projection *pj, ref_projection *ref) {
    memset(pj, 0xff, sizeof *pj); /* NaN-ish garbage: every field must be written */
    agjk_status st = agjk_simplex_project_origin(w, n, pj);
    TU_CHECK_INT_EQ(ref_project_origin(w, n, ref), 0);
    double size = max_abs_coord(w, n);
    double tol = POINT_TOL * size;
    TU_ENSURE(tu_vec_finite(pj->point), "%s %d: non-finite point", what, i);
    TU_ENSURE(st == AGJK_STATUS_SEPARATED || st == AGJK_STATUS_INTERSECTING,
                  "%s %d: status %d", what, i, (int)st);
    double ex = pj->point.x - (double)ref->point[0], ey = pj->point.y - (double)ref->point[1];
    double ez = pj->point.z - (double)ref->point[2];
    double err = sqrt(ex * ex + ey * ey + ez * ez);
    if (size > 0 && err / size > worst_rel_error) worst_rel_error = err / size;
    if (soft_mode)
        point_failure(err <= tol, size > 0 ? err / size : err, i);
    else
        TU_ENSURE(err <= tol, "%s %d (n=%d): point (%.17g %.17g %.17g) vs reference "
                  "(%.17Lg %.17Lg %.17Lg), error %g > %g", what, i, n, pj->point.x, pj->point.y,
                  pj->point.z, ref->point[0], ref->point[1], ref->point[2], err, tol);
    double sum = 0.0;
    agjk_vec3 rec = tu_vec(0, 0, 0);
    for (int k = 0; k < 4; k++) {
        TU_ENSURE(isfinite(pj->weights[k]), "%s %d: weight %d not finite", what, i, k);
        TU_ENSURE(pj->weights[k] >= 0.0, "%s %d: weight %d = %g < 0", what, i, k,
                      pj->weights[k]);
        if (k >= n) {
            TU_ENSURE(pj->weights[k] == 0.0, "%s %d: weight of absent vertex %d", what, i, k);
            continue;
        }
        int in_mask = (pj->support_mask >> k) & 1u;
        TU_ENSURE(in_mask == (pj->weights[k] != 0.0),
                      "%s %d: mask 0x%x disagrees with weight %d = %g", what, i,
                      (unsigned)pj->support_mask, k, pj->weights[k]);
        sum += pj->weights[k];
        rec = tu_add(rec, tu_scale(w[k], pj->weights[k]));
    }
    TU_ENSURE((pj->support_mask & ~((1u << n) - 1u)) == 0, "%s %d: mask beyond count", what, i);
    TU_ENSURE(fabs(sum - 1.0) <= 1e-12, "%s %d: weights sum to %.17g", what, i, sum);
    double rec_err = tu_norm(tu_sub(rec, pj->point));
    if (soft_mode)
        point_failure(rec_err <= tol + 1e-12 * size, size > 0 ? rec_err / size : rec_err, i);
    else
        TU_ENSURE(rec_err <= tol + 1e-12 * size,
                  "%s %d: weights do not reproduce the point: |sum w_i v_i - point| = %g "
                  "(max |coord| %g)", what, i, rec_err, size);
    TU_CHECK_INT_EQ(pj->support_count, popcount4(pj->support_mask));
    TU_CHECK(pj->support_count >= 1 && pj->support_count <= n);
    /* The status says whether the origin is in the simplex. */
    if (soft_mode)
        point_failure(!(ref->distance > (long double)tol) || st == AGJK_STATUS_SEPARATED,
                      (double)ref->distance / size, i);
    else if (ref->distance > (long double)tol)
        TU_ENSURE(st == AGJK_STATUS_SEPARATED, "%s %d: origin outside, status %d", what, i,
                      (int)st);
}

/* True when the reference's winning face is decided clearly: every vertex of
 * it carries weight > margin (not almost on a smaller face). Then the
 * library's support set must be the same face. */
static int clearly_minimal(const ref_projection *r, long double margin) {
    for (int k = 0; k < 4; k++)
        if ((r->mask >> k) & 1u)
            if (r->weights[k] <= margin) return 0;
    return 1;
}

START_TEST(random_simplices) {
    tu_rng rng;
    tu_rng_seed(&rng, 11);
    int compared = 0, inside = 0;
    for (int i = 0; i < 20000; i++) {
        int n = 1 + (int)tu_uniform_int(&rng, 4);
        double size = tu_log_uniform(&rng, -3, 3);
        /* centre near the origin half the time, so that projections land on
         * faces, edges, vertices and (for n = 4) inside */
        double off = (i % 2) ? tu_uniform_range(&rng, 0.0, 0.5) : tu_uniform_range(&rng, 0.5, 3.0);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * off);
        agjk_vec3 w[4];
        for (int k = 0; k < n; k++) w[k] = tu_add(c, tu_scale(tu_unit_vector(&rng), size));
        agjk_simplex_projection pj;
        ref_projection ref;
        check_projection(w, n, "random", i, &pj, &ref);
        if (clearly_minimal(&ref, 1e-6L)) {
            compared++;
            TU_ENSURE(pj.support_mask == ref.mask, "random %d (n=%d): mask 0x%x, reference 0x%x",
                          i, n, (unsigned)pj.support_mask, ref.mask);
        }
        if (ref.count == 4 && clearly_minimal(&ref, 1e-6L)) {
            inside++;
            TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, n, &pj), AGJK_STATUS_INTERSECTING);
            TU_CHECK_INT_EQ(pj.support_count, 4);
        }
    }
    TU_CHECK(compared > 15000);
    TU_CHECK(inside > 100);
    printf("random_simplices: worst point error %.3g x max|coord|, %d masks compared, %d inside\n",
           worst_rel_error, compared, inside);
}
END_TEST

START_TEST(degenerate) {
    tu_rng rng;
    tu_rng_seed(&rng, 12);
    for (int i = 0; i < 20000; i++) {
        agjk_vec3 w[4];
        int n = 2 + (int)tu_uniform_int(&rng, 3);
        double size = tu_log_uniform(&rng, -2, 2);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * tu_uniform_range(&rng, 0.0, 2.0));
        agjk_vec3 u = tu_unit_vector(&rng), v = tu_unit_vector(&rng);
        int kind = i % 5;
        for (int k = 0; k < n; k++) {
            double a = tu_uniform_range(&rng, -size, size), b = tu_uniform_range(&rng, -size, size);
            switch (kind) {
            case 0: /* collinear */
                w[k] = tu_add(c, tu_scale(u, a));
                break;
            case 1: /* coplanar */
                w[k] = tu_add(c, tu_add(tu_scale(u, a), tu_scale(v, b)));
                break;
            case 2: /* repeated points */
                w[k] = k == 0 ? tu_add(c, tu_scale(u, a)) : w[tu_uniform_int(&rng, (uint32_t)k)];
                break;
            case 3: /* all the same point */
                w[k] = c;
                break;
            default: /* nearly collinear: one point 1e-9 off the line */
                w[k] = tu_add(c, tu_scale(u, a));
                if (k == n - 1) w[k] = tu_add(w[k], tu_scale(v, 1e-9 * size));
                break;
            }
        }
        agjk_simplex_projection pj;
        ref_projection ref;
        check_projection(w, n, "degenerate", i, &pj, &ref);
    }
    /* exactly collinear and coplanar with exact (integer) coordinates */
    const agjk_vec3 line[3] = {{0, 0, 1}, {1, 1, 1}, {2, 2, 1}};
    const agjk_vec3 plane[4] = {{-1, -1, 2}, {3, -1, 2}, {-1, 3, 2}, {1, 1, 2}};
    agjk_simplex_projection pj;
    ref_projection ref;
    check_projection(line, 3, "exact line", 0, &pj, &ref);
    TU_CHECK(fabs(pj.point.x) + fabs(pj.point.y) < 1e-15 && fabs(pj.point.z - 1.0) < 1e-15);
    check_projection(plane, 4, "exact plane", 0, &pj, &ref);
    TU_CHECK(fabs(pj.point.x) + fabs(pj.point.y) < 1e-15 && fabs(pj.point.z - 2.0) < 1e-15);
    /* A sliver: two vertices a few ulps apart, the third far off, the foot
     * inside (GJK's last triangle on a cylinder's cap). The signed areas
     * cancelled: weights 7/11, 3/11, 1/11 whose combination missed the foot
     * by 3% of the triangle. Every order of the vertices. */
    const agjk_vec3 sliver[3] = {
        {1.5969424491823374e-05, -5.5182442305461999e-05, -5.8207660927019934e-11},
        {-3.1484437511463411e-05, 0.00010879466303784628, -5.8207660927019934e-11},
        {-3.1484437511463431e-05, 0.00010879466303784625, -5.8207660927019934e-11}};
    for (int r = 0; r < 3; r++) {
        agjk_vec3 w[3] = {sliver[r], sliver[(r + 1) % 3], sliver[(r + 2) % 3]};
        check_projection(w, 3, "sliver", r, &pj, &ref);
    }
}
END_TEST

START_TEST(huge_ranges) {
    /* Coordinates from 1e-9 to 1e9 in one simplex: never NaN, weights valid,
     * point within POINT_TOL of the largest coordinate.
     * Regression test: the first library version missed here (a point 8535
     * units off with coordinates up to 5e7; weights not reproducing the
     * point; the origin called inside while 1.4e-10 x size outside) on 655 of
     * these 20000 simplices; fixed in src/simplex.c (d46557e). */
    tu_rng rng;
    tu_rng_seed(&rng, 13);
    worst_rel_error = 0.0;
    soft_mode = 1;
    soft_failures = 0;
    soft_worst = 0.0;
    for (int i = 0; i < 20000; i++) {
        int n = 1 + (int)tu_uniform_int(&rng, 4);
        agjk_vec3 w[4];
        for (int k = 0; k < n; k++)
            w[k] = tu_scale(tu_unit_vector(&rng), tu_log_uniform(&rng, -9, 9));
        agjk_simplex_projection pj;
        ref_projection ref;
        check_projection(w, n, "huge", i, &pj, &ref);
    }
    soft_mode = 0;
    printf("huge_ranges: worst point error %.3g x max|coord|\n", worst_rel_error);
    TU_ENSURE(soft_failures == 0,
                  "huge_ranges: %d of 20000 simplices with point or weights off (or the origin "
                  "called inside while outside) by more than %g x max|coord|; worst %.3g x max|coord| (case %d)",
                  soft_failures, POINT_TOL, soft_worst, soft_worst_case);
}
END_TEST

START_TEST(origin_on_features) {
    /* The origin exactly on a vertex, an edge, a face, or inside: distance
     * 0, status INTERSECTING, and the smallest face holding it. Coordinates
     * are small integers so "exactly" is exact. */
    tu_rng rng;
    tu_rng_seed(&rng, 14);
    for (int i = 0; i < 4000; i++) {
        agjk_vec3 w[4];
        int feature = i % 4; /* 0 vertex, 1 edge, 2 face, 3 inside */
        /* random integer points in [-8, 8]^3, then shift so that the chosen
         * combination is exactly the origin */
        for (int k = 0; k < 4; k++)
            w[k] = tu_vec((double)tu_uniform_int(&rng, 17) - 8, (double)tu_uniform_int(&rng, 17) - 8,
                          (double)tu_uniform_int(&rng, 17) - 8);
        agjk_vec3 o;
        int expect = feature + 1;
        switch (feature) {
        case 0: o = w[0]; break;
        case 1: o = tu_scale(tu_add(w[0], w[1]), 0.5); break;
        case 2: o = tu_scale(tu_add(tu_add(w[0], w[1]), tu_scale(w[2], 2.0)), 0.25); break;
        default: o = tu_scale(tu_add(tu_add(w[0], w[1]), tu_add(w[2], w[3])), 0.25); break;
        }
        for (int k = 0; k < 4; k++) w[k] = tu_sub(w[k], o);
        ref_projection ref;
        ref_project_origin(w, 4, &ref);
        if (ref.count != expect) continue; /* degenerate draw (e.g. repeated points) */
        /* a random order of the vertices, and fewer vertices when the feature allows */
        int n = expect + (int)tu_uniform_int(&rng, (uint32_t)(5 - expect));
        agjk_simplex_projection pj;
        check_projection(w, n, "feature", i, &pj, &ref);
        TU_ENSURE(tu_norm(pj.point) == 0.0, "feature %d: origin on the simplex, point %g", i,
                      tu_norm(pj.point));
        TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, n, &pj), AGJK_STATUS_INTERSECTING);
        if (clearly_minimal(&ref, 1e-9L))
            TU_ENSURE(pj.support_count == ref.count, "feature %d (%d): count %d, expected %d", i,
                          feature, pj.support_count, ref.count);
    }
}
END_TEST

START_TEST(invalid_input) {
    agjk_vec3 w[5] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {2, 2, 2}};
    agjk_simplex_projection pj;
    TU_CHECK_INT_EQ(agjk_simplex_project_origin(NULL, 2, &pj), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, 2, NULL), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, 0, &pj), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, -1, &pj), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_simplex_project_origin(w, 5, &pj), AGJK_STATUS_INVALID_INPUT);
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int b = 0; b < 3; b++)
        for (int k = 0; k < 4; k++)
            for (int c = 0; c < 3; c++) {
                agjk_vec3 v[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
                double *comp = c == 0 ? &v[k].x : c == 1 ? &v[k].y : &v[k].z;
                *comp = bad[b];
                TU_CHECK_INT_EQ(agjk_simplex_project_origin(v, 4, &pj), AGJK_STATUS_INVALID_INPUT);
            }
}
END_TEST

/* ---- agjk__simplex_project_gjk ---------------------------------------- */

/* Whether check_internal compares support masks with the reference (not on
 * simplices with repeated points, where equal points make masks ambiguous). */
static int compare_masks = 1;

/* Checks one output (mask, lambda, point) of an internal projection of
 * w[0..n-1] against the reference, like check_projection; in soft_mode the
 * point errors are counted instead. */
static void check_internal(const agjk_vec3 *w, int n, const char *what, int i, unsigned mask,
                           const double lambda[4], agjk_vec3 point, const ref_projection *ref) {
    double size = max_abs_coord(w, n);
    double tol = POINT_TOL * size;
    TU_ENSURE(tu_vec_finite(point), "%s %d: non-finite point", what, i);
    TU_ENSURE(mask != 0u && (mask & ~((1u << n) - 1u)) == 0u, "%s %d (n=%d): mask 0x%x", what, i,
              n, mask);
    double ex = point.x - (double)ref->point[0], ey = point.y - (double)ref->point[1];
    double ez = point.z - (double)ref->point[2];
    double err = sqrt(ex * ex + ey * ey + ez * ez);
    if (size > 0 && err / size > worst_rel_error) worst_rel_error = err / size;
    if (soft_mode)
        point_failure(err <= tol, size > 0 ? err / size : err, i);
    else
        TU_ENSURE(err <= tol, "%s %d (n=%d): point (%.17g %.17g %.17g) vs reference "
                  "(%.17Lg %.17Lg %.17Lg), error %g > %g", what, i, n, point.x, point.y, point.z,
                  ref->point[0], ref->point[1], ref->point[2], err, tol);
    double sum = 0.0;
    agjk_vec3 rec = tu_vec(0, 0, 0);
    for (int k = 0; k < n; k++) {
        TU_ENSURE(isfinite(lambda[k]) && lambda[k] >= 0.0, "%s %d: weight %d = %g", what, i, k,
                  lambda[k]);
        TU_ENSURE(((mask >> k) & 1u) == (lambda[k] != 0.0),
                  "%s %d: mask 0x%x disagrees with weight %d = %g", what, i, mask, k, lambda[k]);
        sum += lambda[k];
        rec = tu_add(rec, tu_scale(w[k], lambda[k]));
    }
    TU_ENSURE(fabs(sum - 1.0) <= 1e-12, "%s %d: weights sum to %.17g", what, i, sum);
    double rec_err = tu_norm(tu_sub(rec, point));
    if (soft_mode)
        point_failure(rec_err <= tol + 1e-12 * size, size > 0 ? rec_err / size : rec_err, i);
    else
        TU_ENSURE(rec_err <= tol + 1e-12 * size,
                  "%s %d: weights do not reproduce the point: error %g (max |coord| %g)", what, i,
                  rec_err, size);
    if (mask == 0xFu)
        TU_ENSURE(point.x == 0.0 && point.y == 0.0 && point.z == 0.0,
                  "%s %d: origin inside but point (%g %g %g)", what, i, point.x, point.y, point.z);
    if (!soft_mode && compare_masks && clearly_minimal(ref, 1e-6L))
        TU_ENSURE(mask == ref->mask, "%s %d (n=%d): mask 0x%x, reference 0x%x", what, i, n, mask,
                  ref->mask);
}

/* Fast-path statistics of one test. */
typedef struct gjk_counts {
    long calls[5], fast[5];
} gjk_counts;

/* Tetrahedra whose inside test reported its data (check_inside). */
static long inside_reported;

/* det(p, q, r) in long double. */
static long double det_l(agjk_vec3 p, agjk_vec3 q, agjk_vec3 r) {
    return (long double)p.x * ((long double)q.y * r.z - (long double)q.z * r.y) -
           (long double)p.y * ((long double)q.x * r.z - (long double)q.z * r.x) +
           (long double)p.z * ((long double)q.x * r.y - (long double)q.y * r.x);
}

/* The same call with weights_optional: the same answer, bit for bit; or,
 * only for an enclosure the inside test reported (and only on a thin
 * tetrahedron, where the weights come from the exhaustive projection's
 * enclosed case, or the exhaustive projection itself when they fail:
 * deferred_declined counts those), the enclosure without its weights: the mask with AGJK__WEIGHTS_DEFERRED, x
 * exactly 0, the weights left as they were, and the same inside data. */
static long deferred_weights, deferred_declined;
static void check_deferred(const agjk_vec3 *w, unsigned mask, const double l[4],
                           const agjk_vec3 *p, const agjk__projection_notes *weighed,
                           const char *what, int i) {
    agjk__projection_notes notes;
    notes.rotation = NULL;
    notes.weights_optional = 1;
    double ld[4] = {NAN, NAN, NAN, NAN};
    agjk_vec3 pd;
    unsigned md = agjk__simplex_project_gjk_noted(w, 4, ld, &pd, &notes, &w[3]);
    if (!(md & AGJK__WEIGHTS_DEFERRED)) {
        TU_ENSURE(md == mask && memcmp(ld, l, sizeof ld) == 0 && memcmp(&pd, p, sizeof pd) == 0,
                  "%s %d: weights optional: mask 0x%x, weighed 0x%x", what, i, md, mask);
        return;
    }
    ++deferred_weights;
    deferred_declined += mask != (0xFu | AGJK__INSIDE_REPORTED);
    TU_ENSURE(md == (0xFu | AGJK__INSIDE_REPORTED | AGJK__WEIGHTS_DEFERRED) &&
                  pd.x == 0.0 && pd.y == 0.0 && pd.z == 0.0 &&
                  isnan(ld[0]) && isnan(ld[1]) && isnan(ld[2]) && isnan(ld[3]),
              "%s %d: deferred weights with mask 0x%x (weighed 0x%x)", what, i, md, mask);
    TU_ENSURE(memcmp(&notes.inside, &weighed->inside, sizeof notes.inside) == 0,
              "%s %d: deferred weights with other inside data", what, i);
}

/* agjk__simplex_project_gjk_noted on a tetrahedron: the same answer, bit
 * for bit, as agjk__simplex_project_gjk (mask, weights), and when it reports
 * its inside test's data (AGJK__INSIDE_REPORTED), an enclosure whose depth
 * numerators, squared edge lengths and orientation match a long-double
 * computation from the same points (the solver certifies overlaps with
 * them). */
static void check_inside(const agjk_vec3 *w, unsigned mask, const double l[4], const char *what,
                         int i) {
    agjk__projection_notes notes;
    notes.rotation = NULL;
    notes.weights_optional = 0;
    const agjk__inside *inside = &notes.inside;
    double li[4];
    agjk_vec3 pi;
    unsigned mi = agjk__simplex_project_gjk_noted(w, 4, li, &pi, &notes, &w[3]);
    TU_ENSURE((mi & ~AGJK__INSIDE_REPORTED) == mask && memcmp(li, l, sizeof li) == 0,
              "%s %d: the inside variant answers mask 0x%x, plain 0x%x", what, i, mi, mask);
    check_deferred(w, mi, li, &pi, &notes, what, i);
    if (!(mi & AGJK__INSIDE_REPORTED)) return;
    ++inside_reported;
    TU_ENSURE(mask == 0xFu, "%s %d: inside data with mask 0x%x", what, i, mask);
    agjk_vec3 a = w[3], e[3] = {tu_sub(w[0], a), tu_sub(w[1], a), tu_sub(w[2], a)};
    long double vol = det_l(e[0], e[1], e[2]);
    TU_ENSURE(inside->orientation == (vol < 0 ? -1.0 : 1.0), "%s %d: orientation %g, volume %Lg", what,
              i, inside->orientation, vol);
    for (int f = 0; f < 3; ++f) {
        int j = (f + 1) % 3, k = (f + 2) % 3;
        long double h = -(long double)inside->orientation * det_l(a, e[j], e[k]);
        long double scale = (long double)tu_norm(a) * tu_norm(e[j]) * tu_norm(e[k]);
        TU_ENSURE(h > 0 && fabsl((long double)inside->h[f] - h) <= 16 * DBL_EPSILON * scale,
                  "%s %d: face %d depth numerator %.17g, long double %.17Lg", what, i, f,
                  inside->h[f], h);
        long double g = (long double)e[f].x * e[f].x + (long double)e[f].y * e[f].y +
                        (long double)e[f].z * e[f].z;
        TU_ENSURE(fabsl((long double)inside->g[f] - g) <= 4 * DBL_EPSILON * g,
                  "%s %d: |e_%d|^2 %.17g, long double %.17Lg", what, i, f, inside->g[f], g);
    }
}

/* With the point asked for in B's frame too (a fixed rotation R): the same
 * answer, bit for bit, and when the point was turned (GJK's face case), R^T
 * of the point to a few ulps of its size, in long double. */
static long turned_points;
static void check_turned(const agjk_vec3 *w, int n, unsigned mask, const double l[4],
                         agjk_vec3 p, const char *what, int i) {
    static const double r[9] = {0.36, 0.48, -0.8, -0.8, 0.6, 0.0, 0.48, 0.64, 0.6};
    agjk__projection_notes notes;
    notes.rotation = r;
    notes.turned_valid = 0;
    notes.weights_optional = 0;
    double lt[4] = {NAN, NAN, NAN, NAN}; /* (as check_gjk's: entries past n may stay) */
    agjk_vec3 pt;
    unsigned mt = agjk__simplex_project_gjk_noted(w, n, lt, &pt, &notes, &w[n - 1]);
    TU_ENSURE((mt & ~AGJK__INSIDE_REPORTED) == mask && memcmp(lt, l, sizeof lt) == 0 &&
                  memcmp(&pt, &p, sizeof p) == 0,
              "%s %d: the answer changed when the point was turned too", what, i);
    if (!notes.turned_valid) return;
    ++turned_points;
    long double q[3];
    for (int k = 0; k < 3; k++)
        q[k] = (long double)r[k] * p.x + (long double)r[3 + k] * p.y + (long double)r[6 + k] * p.z;
    double size = tu_norm(p);
    TU_ENSURE(fabsl(notes.turned.x - q[0]) <= 8 * DBL_EPSILON * size &&
                  fabsl(notes.turned.y - q[1]) <= 8 * DBL_EPSILON * size &&
                  fabsl(notes.turned.z - q[2]) <= 8 * DBL_EPSILON * size,
              "%s %d: turned point off R^T x by more than 8 ulps of |x| = %g", what, i, size);
}

/* Runs agjk__simplex_project_gjk and its fast path alone on w[0..n-1] (the
 * newest point last) and checks both against the reference; the fast path
 * may decline (return 0), never be wrong. Returns the mask of the full
 * projection and its weights and point. */
static unsigned check_gjk(const agjk_vec3 *w, int n, const char *what, int i, gjk_counts *counts,
                          double lambda[4], agjk_vec3 *point) {
    ref_projection ref;
    TU_CHECK_INT_EQ(ref_project_origin(w, n, &ref), 0);
    double l[4] = {NAN, NAN, NAN, NAN};
    agjk_vec3 p = tu_vec(NAN, NAN, NAN);
    unsigned mask = agjk__simplex_project_gjk(w, n, l, &p);
    check_internal(w, n, what, i, mask, l, p, &ref);
    /* The exhaustive projection is the fallback: both are within rounding. */
    double lo[4];
    agjk_vec3 po;
    agjk__simplex_project(w, n, lo, &po);
    TU_ENSURE(tu_norm(tu_sub(p, po)) <= 2.0 * POINT_TOL * max_abs_coord(w, n) || soft_mode,
              "%s %d: gjk and exhaustive projections differ by %g", what, i,
              tu_norm(tu_sub(p, po)));
    double lf[4] = {NAN, NAN, NAN, NAN};
    agjk_vec3 pf = tu_vec(NAN, NAN, NAN);
    unsigned mf = agjk__simplex_project_gjk_fast(w, n, lf, &pf);
    counts->calls[n]++;
    if (mf) {
        counts->fast[n]++;
        check_internal(w, n, what, i, mf, lf, pf, &ref);
        TU_ENSURE(mf == mask, "%s %d: fast mask 0x%x, full 0x%x", what, i, mf, mask);
    }
    if (n == 4) check_inside(w, mask, l, what, i);
    check_turned(w, n, mask, l, p, what, i);
    for (int k = 0; k < 4; k++) lambda[k] = l[k];
    *point = p;
    return mask;
}

static void print_counts(const char *what, const gjk_counts *c) {
    printf("%s: fast path taken", what);
    for (int n = 2; n <= 4; n++)
        if (c->calls[n])
            printf("  n=%d %ld/%ld (fallback %.2f%%)", n, c->fast[n], c->calls[n],
                   100.0 * (double)(c->calls[n] - c->fast[n]) / (double)c->calls[n]);
    printf("; inside data %ld (weights deferred %ld, of which the weighed answer declined %ld), "
           "turned points %ld\n",
           inside_reported, deferred_weights, deferred_declined, turned_points);
}

START_TEST(gjk_random_simplices) {
    /* The simplices of random_simplices: the newest point is any point. */
    tu_rng rng;
    tu_rng_seed(&rng, 11);
    gjk_counts counts = {{0}, {0}};
    for (int i = 0; i < 20000; i++) {
        int n = 1 + (int)tu_uniform_int(&rng, 4);
        double size = tu_log_uniform(&rng, -3, 3);
        double off = (i % 2) ? tu_uniform_range(&rng, 0.0, 0.5) : tu_uniform_range(&rng, 0.5, 3.0);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * off);
        agjk_vec3 w[4];
        for (int k = 0; k < n; k++) w[k] = tu_add(c, tu_scale(tu_unit_vector(&rng), size));
        double l[4];
        agjk_vec3 p;
        check_gjk(w, n, "gjk random", i, &counts, l, &p);
    }
    print_counts("gjk_random_simplices", &counts);
}
END_TEST

START_TEST(gjk_degenerate) {
    /* The simplices of `degenerate`, plus the exact line and plane. */
    tu_rng rng;
    tu_rng_seed(&rng, 12);
    gjk_counts counts = {{0}, {0}};
    double l[4];
    agjk_vec3 p;
    compare_masks = 0;
    for (int i = 0; i < 20000; i++) {
        agjk_vec3 w[4];
        int n = 2 + (int)tu_uniform_int(&rng, 3);
        double size = tu_log_uniform(&rng, -2, 2);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * tu_uniform_range(&rng, 0.0, 2.0));
        agjk_vec3 u = tu_unit_vector(&rng), v = tu_unit_vector(&rng);
        int kind = i % 5;
        for (int k = 0; k < n; k++) {
            double a = tu_uniform_range(&rng, -size, size), b = tu_uniform_range(&rng, -size, size);
            switch (kind) {
            case 0: w[k] = tu_add(c, tu_scale(u, a)); break;
            case 1: w[k] = tu_add(c, tu_add(tu_scale(u, a), tu_scale(v, b))); break;
            case 2:
                w[k] = k == 0 ? tu_add(c, tu_scale(u, a)) : w[tu_uniform_int(&rng, (uint32_t)k)];
                break;
            case 3: w[k] = c; break;
            default:
                w[k] = tu_add(c, tu_scale(u, a));
                if (k == n - 1) w[k] = tu_add(w[k], tu_scale(v, 1e-9 * size));
                break;
            }
        }
        check_gjk(w, n, "gjk degenerate", i, &counts, l, &p);
    }
    const agjk_vec3 line[3] = {{0, 0, 1}, {1, 1, 1}, {2, 2, 1}};
    const agjk_vec3 plane[4] = {{-1, -1, 2}, {3, -1, 2}, {-1, 3, 2}, {1, 1, 2}};
    check_gjk(line, 3, "gjk exact line", 0, &counts, l, &p);
    TU_CHECK(fabs(p.x) + fabs(p.y) < 1e-15 && fabs(p.z - 1.0) < 1e-15);
    check_gjk(plane, 4, "gjk exact plane", 0, &counts, l, &p);
    TU_CHECK(fabs(p.x) + fabs(p.y) < 1e-15 && fabs(p.z - 2.0) < 1e-15);
    compare_masks = 1;
    print_counts("gjk_degenerate", &counts);
}
END_TEST

START_TEST(gjk_huge_ranges) {
    /* The simplices of huge_ranges (coordinates 1e-9 to 1e9 in one simplex). */
    tu_rng rng;
    tu_rng_seed(&rng, 13);
    gjk_counts counts = {{0}, {0}};
    worst_rel_error = 0.0;
    soft_mode = 1;
    soft_failures = 0;
    soft_worst = 0.0;
    for (int i = 0; i < 20000; i++) {
        int n = 1 + (int)tu_uniform_int(&rng, 4);
        agjk_vec3 w[4];
        for (int k = 0; k < n; k++)
            w[k] = tu_scale(tu_unit_vector(&rng), tu_log_uniform(&rng, -9, 9));
        double l[4];
        agjk_vec3 p;
        check_gjk(w, n, "gjk huge", i, &counts, l, &p);
    }
    soft_mode = 0;
    printf("gjk_huge_ranges: worst point error %.3g x max|coord|\n", worst_rel_error);
    print_counts("gjk_huge_ranges", &counts);
    TU_ENSURE(soft_failures == 0,
              "gjk_huge_ranges: %d of 20000 simplices off by more than %g x max|coord|; worst "
              "%.3g (case %d)", soft_failures, POINT_TOL, soft_worst, soft_worst_case);
}
END_TEST

/* A random point cloud (the vertices of D = A - B): `count` points on an
 * ellipsoid of radii in [r/8, r] (r = size), rotated, centred at distance
 * `dist` from the origin (negative: the origin inside). */
static void random_cloud(tu_rng *rng, agjk_vec3 *pts, int count, double size, double dist) {
    double rot[3][3];
    tu_random_rotation(rng, rot);
    double rad[3];
    for (int k = 0; k < 3; k++) rad[k] = size * tu_uniform_range(rng, 0.125, 1.0);
    agjk_vec3 dir = tu_unit_vector(rng);
    /* the support of the ellipsoid along -dir, then shifted so that the gap along dir is dist */
    double reach = 0.0;
    for (int k = 0; k < 3; k++) {
        double d = rot[0][k] * dir.x + rot[1][k] * dir.y + rot[2][k] * dir.z;
        reach += rad[k] * rad[k] * d * d;
    }
    agjk_vec3 c = tu_scale(dir, sqrt(reach) + dist);
    for (int i = 0; i < count; i++) {
        agjk_vec3 u = tu_unit_vector(rng);
        agjk_vec3 l = tu_vec(u.x * rad[0], u.y * rad[1], u.z * rad[2]);
        agjk_vec3 g = tu_vec(rot[0][0] * l.x + rot[0][1] * l.y + rot[0][2] * l.z,
                             rot[1][0] * l.x + rot[1][1] * l.y + rot[1][2] * l.z,
                             rot[2][0] * l.x + rot[2][1] * l.y + rot[2][2] * l.z);
        pts[i] = tu_add(c, g);
    }
}

START_TEST(gjk_like_runs) {
    /* GJK itself on random point clouds, close, touching, overlapping and far,
     * at sizes 1e-3 to 1e3 (Gilbert, Johnson, Keerthi 1988): the simplex
     * passed each time is the previous minimal face plus the new support
     * point, last. Every projection is checked; the fast path should almost
     * always answer. */
    enum { CLOUD = 200 };
    static const double gaps[] = {-0.3, -1e-3, 0.0, 1e-8, 1e-4, 1e-2, 0.3, 3.0, 100.0};
    tu_rng rng;
    tu_rng_seed(&rng, 15);
    gjk_counts counts = {{0}, {0}};
    agjk_vec3 cloud[CLOUD];
    int case_id = 0;
    for (int run = 0; run < 900; run++) {
        double size = tu_log_uniform(&rng, -3, 3);
        double gap = gaps[run % 9] * size;
        int count = 8 + (int)tu_uniform_int(&rng, CLOUD - 8);
        random_cloud(&rng, cloud, count, size, gap);
        agjk_vec3 w[4] = {cloud[0]};
        int n = 1;
        agjk_vec3 x = cloud[0];
        for (int it = 0; it < 100; it++, case_id++) {
            int best = 0;
            for (int k = 1; k < count; k++)
                if (tu_dot(x, cloud[k]) < tu_dot(x, cloud[best])) best = k;
            agjk_vec3 s = cloud[best];
            double xx = tu_dot(x, x);
            /* stop at a relative duality gap of 1e-13 or when s adds nothing */
            if (xx - tu_dot(x, s) <= 1e-13 * xx) break;
            int seen = 0;
            for (int k = 0; k < n; k++) seen |= w[k].x == s.x && w[k].y == s.y && w[k].z == s.z;
            if (seen) break;
            w[n++] = s;
            double l[4];
            agjk_vec3 p;
            unsigned mask = check_gjk(w, n, "gjk run", case_id, &counts, l, &p);
            TU_ENSURE(tu_dot(p, p) <= xx * (1.0 + 1e-12),
                      "gjk run %d: |x| grew from %g to %g", case_id, sqrt(xx), tu_norm(p));
            x = p;
            if (mask == 0xFu) break;
            int kept = 0;
            for (int k = 0; k < n; k++)
                if (mask & (1u << k)) w[kept++] = w[k];
            n = kept;
        }
    }
    print_counts("gjk_like_runs", &counts);
    /* GJK's last step on overlapping shapes is among these runs. */
    TU_ENSURE(inside_reported > 0, "no enclosure reported by the inside test");
    TU_ENSURE(turned_points > 0, "no point turned by the face case");
    /* GJK's own simplices: the fallback is the exception (origin inside,
     * degenerate or ill-conditioned simplices). */
    for (int n = 2; n <= 4; n++)
        TU_ENSURE(counts.fast[n] >= 0.9 * (double)counts.calls[n] && counts.calls[n] > 500,
                  "gjk_like_runs: fast path %ld of %ld at n=%d", counts.fast[n], counts.calls[n], n);
}
END_TEST

START_TEST(gjk_adversarial) {
    /* A previous face F holding its projection x, and a new point a that does
     * not improve it (<x, a> >= |x|^2, as a momentum direction or rounding
     * can produce): the projection stays x on F, a is not in the answer. Also
     * a on the supporting plane, slightly short of it, and far beyond.
     * (Not closer to the plane than 1e-6 |x|: there the improvement in |x|^2
     * is below the 1e-18 relative resolution of the reference, which then
     * keeps the smaller face, while the point itself still moves.) */
    tu_rng rng;
    tu_rng_seed(&rng, 16);
    gjk_counts counts = {{0}, {0}};
    int declined = 0;
    for (int i = 0; i < 20000; i++) {
        int m = 1 + (int)tu_uniform_int(&rng, 3); /* previous face size */
        double size = tu_log_uniform(&rng, -3, 3);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * tu_uniform_range(&rng, 0.2, 3.0));
        agjk_vec3 f[4];
        for (int k = 0; k < m; k++) f[k] = tu_add(c, tu_scale(tu_unit_vector(&rng), size));
        double l[4];
        agjk_vec3 x;
        unsigned fm = agjk__simplex_project(f, m, l, &x);
        agjk_vec3 w[4];
        int n = 0;
        for (int k = 0; k < m; k++)
            if (fm & (1u << k)) w[n++] = f[k];
        double xn = tu_norm(x);
        if (!(xn > 1e-6 * size)) continue;
        agjk_vec3 xh = tu_scale(x, 1.0 / xn);
        /* a = x (1 + alpha) + t, t orthogonal to x */
        agjk_vec3 t = tu_unit_vector(&rng);
        t = tu_sub(t, tu_scale(xh, tu_dot(t, xh)));
        double alpha;
        switch (i % 4) {
        case 0: alpha = tu_uniform_range(&rng, 0.0, 1.0); break;   /* clearly beyond */
        case 1: alpha = 1e-15 * tu_uniform_range(&rng, 0, 4); break; /* on the plane */
        case 2: alpha = -1e-6; break;                             /* slightly improving */
        default: alpha = tu_log_uniform(&rng, 0, 4); break;       /* far beyond */
        }
        agjk_vec3 a = tu_add(tu_scale(x, 1.0 + alpha), tu_scale(t, size * tu_log_uniform(&rng, -2, 2)));
        w[n++] = a;
        agjk_vec3 p;
        /* On the plane, a weight of a few ulps on a is as right as none. */
        compare_masks = i % 4 != 1;
        unsigned mask = check_gjk(w, n, "gjk adversarial", i, &counts, l, &p);
        compare_masks = 1;
        if (alpha > 1e-9 && !(mask & (1u << (n - 1)))) declined++;
    }
    print_counts("gjk_adversarial", &counts);
    printf("gjk_adversarial: %d answers without the newest point\n", declined);
    TU_CHECK(declined > 5000);
}
END_TEST

START_TEST(gjk_far_small) {
    /* Small simplices far from the origin (size 1e-6 .. 1 at distance 1 ..
     * 1e6 x size), in GJK's order (previous minimal face, then a point that
     * improves it) and in random order. */
    tu_rng rng;
    tu_rng_seed(&rng, 17);
    gjk_counts counts[2] = {{{0}, {0}}, {{0}, {0}}};
    for (int i = 0; i < 20000; i++) {
        int n = 2 + (int)tu_uniform_int(&rng, 3);
        double size = tu_log_uniform(&rng, -6, 0);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * tu_log_uniform(&rng, 0, 6));
        agjk_vec3 w[4];
        for (int k = 0; k < n; k++) w[k] = tu_add(c, tu_scale(tu_unit_vector(&rng), size));
        if (i % 2) {
            /* the first n-1 points as a minimal face, the last moved to improve it */
            double l[4];
            agjk_vec3 x;
            unsigned fm = agjk__simplex_project(w, n - 1, l, &x);
            agjk_vec3 a = w[n - 1];
            int m = 0;
            for (int k = 0; k < n - 1; k++)
                if (fm & (1u << k)) w[m++] = w[k];
            double xx = tu_dot(x, x);
            if (tu_dot(x, a) >= xx) a = tu_sub(a, tu_scale(x, 2.0 * (tu_dot(x, a) - xx) / xx + 1e-3 * size / sqrt(xx)));
            w[m++] = a;
            n = m;
        }
        double l[4];
        agjk_vec3 p;
        check_gjk(w, n, "gjk far", i, &counts[i % 2], l, &p);
    }
    print_counts("gjk_far_small (random order)", &counts[0]);
    print_counts("gjk_far_small (GJK order)", &counts[1]);
}
END_TEST

START_TEST(gjk_near_contact) {
    /* Near contact the projection is tiny next to the vertices, and its
     * error relative to it is what the solver's gap test and stall test see:
     * the GJK entry point must be as accurate as the exhaustive projection.
     * GJK-ordered simplices: a previous face F, nearly in a plane at a tiny
     * distance dist from the origin, its vertices at mixed distances from the
     * foot, and a new point a that improves on F's projection. Checked: the
     * error of the point against the reference at most twice the exhaustive
     * projection's, plus 32 ulps of the smallest norm of a vertex of the face
     * holding the projection (the error of any formula for the foot). */
    tu_rng rng;
    tu_rng_seed(&rng, 18);
    gjk_counts counts = {{0}, {0}};
    double worst = 0.0;
    for (int i = 0; i < 20000; i++) {
        double size = tu_log_uniform(&rng, -2, 2);
        double dist = size * tu_log_uniform(&rng, -12, -3);
        agjk_vec3 nrm = tu_unit_vector(&rng);
        agjk_vec3 t1 = tu_unit_vector(&rng);
        t1 = tu_scale(tu_sub(t1, tu_scale(nrm, tu_dot(t1, nrm))), 1.0);
        t1 = tu_scale(t1, 1.0 / tu_norm(t1));
        agjk_vec3 t2 = tu_cross(nrm, t1);
        int m = 1 + (int)tu_uniform_int(&rng, 3);
        agjk_vec3 f[4];
        for (int k = 0; k < m; k++) {
            double r = size * tu_log_uniform(&rng, -8, 0), th = tu_uniform_range(&rng, 0, 6.283185307179586);
            f[k] = tu_add(tu_scale(nrm, dist * (1.0 + 1e-3 * tu_uniform_range(&rng, -1, 1))),
                          tu_add(tu_scale(t1, r * cos(th)), tu_scale(t2, r * sin(th))));
        }
        double l[4];
        agjk_vec3 x;
        unsigned fm = agjk__simplex_project(f, m, l, &x);
        agjk_vec3 w[4];
        int n = 0;
        for (int k = 0; k < m; k++)
            if (fm & (1u << k)) w[n++] = f[k];
        /* the new point: in the plane or slightly towards the origin, far or near */
        double r = size * tu_log_uniform(&rng, -6, 0), th = tu_uniform_range(&rng, 0, 6.283185307179586);
        agjk_vec3 a = tu_add(tu_scale(nrm, dist * tu_uniform_range(&rng, 0.5, 1.0)),
                             tu_add(tu_scale(t1, r * cos(th)), tu_scale(t2, r * sin(th))));
        if (!(tu_dot(x, a) < tu_dot(x, x))) continue; /* not a GJK step */
        w[n++] = a;
        agjk_vec3 p;
        check_gjk(w, n, "gjk near contact", i, &counts, l, &p);
        ref_projection ref;
        ref_project_origin(w, n, &ref);
        double lo[4];
        agjk_vec3 po;
        agjk__simplex_project(w, n, lo, &po);
        double vmin = INFINITY; /* over the face holding the projection */
        for (int k = 0; k < n; k++)
            if (ref.mask & (1u << k)) vmin = fmin(vmin, tu_norm(w[k]));
        agjk_vec3 rp = tu_vec((double)ref.point[0], (double)ref.point[1], (double)ref.point[2]);
        double err = tu_norm(tu_sub(p, rp)), err_old = tu_norm(tu_sub(po, rp));
        double allowed = 2.0 * err_old + 32.0 * DBL_EPSILON * vmin;
        if (tu_norm(rp) > 0 && err / tu_norm(rp) > worst) worst = err / tu_norm(rp);
        TU_ENSURE(err <= allowed, "gjk near contact %d (n=%d): error %g, exhaustive %g, |p| %g, "
                  "smallest vertex %g", i, n, err, err_old, tu_norm(rp), vmin);
    }
    print_counts("gjk_near_contact", &counts);
    printf("gjk_near_contact: worst error %.3g x |p|\n", worst);
    TU_CHECK(counts.calls[2] + counts.calls[3] + counts.calls[4] > 10000);
}
END_TEST

START_TEST(gjk_thin_enclosure) {
    /* Tetrahedra flat to 1e-4 .. 1e-3 of their size (the last step of a
     * momentum run on overlapping shapes), holding the origin well inside:
     * a base triangle around the origin just below it and an apex just
     * above, turned, scaled and in any vertex order. The inside test's
     * signed volumes hold for them too, and the projection reports them for
     * the solver's overlap certificate (checked against long double by
     * check_inside), while the weights are the exhaustive projection's. */
    tu_rng rng;
    tu_rng_seed(&rng, 19);
    gjk_counts counts = {{0}, {0}};
    long before = inside_reported;
    int enclosed = 0;
    for (int i = 0; i < 20000; i++) {
        double size = tu_log_uniform(&rng, -3, 3), flat = tu_log_uniform(&rng, -4, -3);
        agjk_pose turn = tu_pose_identity();
        tu_random_rotation(&rng, turn.rotation);
        agjk_vec3 local[4];
        double start = tu_uniform_range(&rng, 0.0, 6.283185307179586);
        for (int k = 0; k < 3; k++) {
            double th = start + 2.0943951023931957 * k + tu_uniform_range(&rng, -0.4, 0.4);
            local[k] = tu_vec(cos(th), sin(th), -flat * tu_uniform_range(&rng, 0.2, 1.0));
        }
        local[3] = tu_vec(tu_uniform_range(&rng, -0.2, 0.2), tu_uniform_range(&rng, -0.2, 0.2),
                          flat * tu_uniform_range(&rng, 0.2, 1.0));
        int first = (int)tu_uniform_int(&rng, 4); /* which vertex comes last (the newest) */
        agjk_vec3 w[4];
        for (int k = 0; k < 4; k++)
            w[k] = tu_scale(tu_pose_rotate(&turn, local[(first + 1 + k) % 4]), size);
        double l[4], lo[4];
        agjk_vec3 p, po;
        unsigned mask = check_gjk(w, 4, "gjk thin enclosure", i, &counts, l, &p);
        unsigned mo = agjk__simplex_project(w, 4, lo, &po);
        if (mo != 0xFu) continue; /* (the apex's tilt left the origin outside) */
        TU_ENSURE(mask == 0xFu && memcmp(l, lo, sizeof l) == 0,
                  "gjk thin enclosure %d: mask 0x%x, or weights other than the exhaustive "
                  "projection's", i, mask);
        enclosed++;
    }
    print_counts("gjk_thin_enclosure", &counts);
    long reported = inside_reported - before;
    printf("gjk_thin_enclosure: %ld of %d enclosures with the inside test's data\n", reported,
           enclosed);
    TU_ENSURE(enclosed > 10000 && reported >= enclosed * 9 / 10,
              "only %ld of %d thin enclosures reported", reported, enclosed);
}
END_TEST

int main(void) {
    Suite *s = suite_create("simplex");
    TU_ADD(s, random_simplices);
    TU_ADD(s, degenerate);
    TU_ADD(s, huge_ranges);
    TU_ADD(s, origin_on_features);
    TU_ADD(s, invalid_input);
    TU_ADD(s, gjk_random_simplices);
    TU_ADD(s, gjk_degenerate);
    TU_ADD(s, gjk_huge_ranges);
    TU_ADD(s, gjk_like_runs);
    TU_ADD(s, gjk_adversarial);
    TU_ADD(s, gjk_far_small);
    TU_ADD(s, gjk_near_contact);
    TU_ADD(s, gjk_thin_enclosure);
    return tu_run_suite(s);
}
