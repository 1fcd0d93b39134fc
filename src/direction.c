/* SPDX-License-Identifier: MIT */
/* Direction policies with momentum for the Frank-Wolfe family loop.
 *
 * We minimise f(x) = ||x||^2 and only the direction of the gradient matters to
 * the support function (paper eq. 9), so we use grad f(y)/2 = y, as the
 * reference implementation does (Coal); d_{-1} = s_{-1} = x_0. */
#include "solver.h"

int agjk__method_has_momentum(agjk_method method) {
    return method == AGJK_METHOD_NESTEROV || method == AGJK_METHOD_NESTEROV_NORMALIZED ||
           method == AGJK_METHOD_POLYAK;
}

agjk_vec3 agjk__momentum_direction(const agjk__momentum *m, int k, agjk_vec3 x) {
    double kk = (double)k;
    agjk_vec3 d;
    switch (m->method) {
    case AGJK_METHOD_NESTEROV: {
        /* Alg. 6 lines 1-3: delta_k = (k+1)/(k+3),
         * y_k = delta_k x_k + (1 - delta_k) s_{k-1},
         * d_k = delta_k d_{k-1} + (1 - delta_k) grad f(y_k). */
        double delta = (kk + 1.0) / (kk + 3.0);
        agjk_vec3 y = v3_lerp2(x, delta, m->s_prev, 1.0 - delta);
        d = v3_lerp2(m->d_prev, delta, y, 1.0 - delta);
        break;
    }
    case AGJK_METHOD_NESTEROV_NORMALIZED: {
        /* Alg. 7 (eq. 31): the same with both terms normalised, so that the
         * momentum does not swamp the gradient as ||d|| grows relative to ||y||
         * (which stalls momentum early on polytopes). */
        double delta = (kk + 1.0) / (kk + 3.0);
        agjk_vec3 y = v3_lerp2(x, delta, m->s_prev, 1.0 - delta);
        agjk_vec3 yn = v3_normalize(y);
        agjk_vec3 dn = v3_normalize(m->d_prev);
        if (v3_norm2(yn) == 0.0) yn = v3_normalize(x);
        d = v3_lerp2(dn, delta, yn, 1.0 - delta);
        break;
    }
    case AGJK_METHOD_POLYAK: {
        /* GJK++ (Montaut et al.): heavy-ball momentum on the direction,
         * d_k = delta_k d_{k-1} + (1 - delta_k) x_k with delta_k = 1/(k+1). */
        double delta = 1.0 / (kk + 1.0);
        d = v3_lerp2(m->d_prev, delta, x, 1.0 - delta);
        break;
    }
    default:
        d = x;
        break;
    }
    /* A zero or non-finite combination carries no direction: use the gradient. */
    if (!v3_isfinite(d) || v3_maxabs(d) == 0.0) d = x;
    return d;
}
