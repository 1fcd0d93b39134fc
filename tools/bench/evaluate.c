/* SPDX-License-Identifier: MIT */
#include "evaluate.h"

#include <math.h>

double bench_rounding_slack(const bench_problem *p) {
    return 1e-12 * fmax(1.0, fmax(p->scale, p->offset));
}

void bench_evaluate(const bench_problem *p, bench_record *rec) {
    const bench_run *r = &rec->run;
    double d_ref, lower, upper, slack;
    rec->violation = rec->wrong = 0;
    rec->error = 0.0;
    rec->converged = r->status == AGJK_STATUS_SEPARATED || r->status == AGJK_STATUS_INTERSECTING ||
                     r->status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    rec->judged = (unsigned char)p->ref_ok;
    if (!p->ref_ok) return;
    d_ref = p->ref.intersecting ? 0.0 : (double)p->ref.distance;
    lower = p->ref.intersecting ? 0.0 : (double)p->ref.lower;
    upper = p->ref.intersecting ? 0.0 : (double)p->ref.upper;
    /* Rounding of the double-precision query itself: coordinates are O(10)
     * times the scale, or as far as the problem was moved from the origin. */
    slack = bench_rounding_slack(p);
    if (r->status == AGJK_STATUS_SEPARATED && (p->ref.intersecting || upper <= 0.0))
        rec->wrong = 1;
    if (r->status == AGJK_STATUS_INTERSECTING && lower > slack) rec->wrong = 1;
    if (rec->mode == BENCH_DISTANCE) {
        rec->error = fabs(r->distance - d_ref);
        /* Certified interval [max(0, d - bound), d] must meet [lower, upper], even
         * when not converged: the API promises a valid bound in every result. */
        if (r->bound >= 0.0 &&
            (lower > r->distance + slack || upper < r->distance - r->bound - slack))
            rec->violation = 1;
    }
}
