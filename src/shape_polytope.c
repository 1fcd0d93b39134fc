/* SPDX-License-Identifier: MIT */
/* Convex polytope given by its vertices.
 *
 * Support by scan (O(n), any point set) or, when the hull's vertex adjacency is
 * given, by hill climbing from the caller's hint: move to a neighbour with a
 * larger <d, v> until none is larger. On the edge graph of a convex polytope a
 * vertex with no better neighbour is a global maximiser (the simplex method's
 * optimality argument), and coherent directions make the walk a few steps
 * long. Each step strictly increases <d, v>, so no vertex is visited twice: the
 * walk is bounded by the vertex count. */
#include "shape_common.h"

/* Below this many vertices a scan beats hill climbing (Coal uses 32; see the
 * README for our measurement). Public, so that tools can say which is used. */
#define HILL_CLIMB_MIN_VERTICES AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES

static int clamp_hint(int hint, int count) { return (hint >= 0 && hint < count) ? hint : 0; }

static void polytope_scan(const agjk_polytope *p, agjk_vec3 d, agjk_vec3 *out, int *hint) {
    const agjk_vec3 *v = p->vertices;
    int best = 0;
    double best_dot = v3_dot(d, v[0]);
    for (int i = 1; i < p->vertex_count; ++i) {
        double dot = v3_dot(d, v[i]);
        if (dot > best_dot) {
            best_dot = dot;
            best = i;
        }
    }
    *hint = best;
    *out = v[best];
}

/* First improvement: move on as soon as a neighbour is better, rather than
 * after the best of the whole list. The move is then a branch the processor
 * predicts and runs ahead of, where a running maximum over the list (steepest
 * ascent, compiled to conditional moves) chains every comparison of a step and
 * the next step's loads behind them: measured on 141-point hulls, about twice
 * the time for the same instruction count. */
static void polytope_climb(const agjk_polytope *p, agjk_vec3 d, agjk_vec3 *out, int *hint) {
    const agjk_vec3 *v = p->vertices;
    const int32_t *offsets = p->neighbor_offsets, *neighbors = p->neighbors;
    int current = clamp_hint(*hint, p->vertex_count);
    double current_dot = v3_dot(d, v[current]);
    /* Each move strictly increases <d, v>: at most vertex_count - 1 moves. */
    for (int moves = 0; moves < p->vertex_count; ++moves) {
        int e = offsets[current], end = offsets[current + 1];
        for (; e < end; ++e) {
            int u = neighbors[e];
            double dot = v3_dot(d, v[u]);
            if (dot > current_dot) {
                current_dot = dot;
                current = u;
                break;
            }
        }
        if (e == end) break; /* no better neighbour: a global maximiser */
    }
    *hint = current;
    *out = v[current];
}

static void polytope_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                             int *hint) {
    const agjk_polytope *p = (const agjk_polytope *)data;
    if (p->neighbor_offsets && p->vertex_count >= HILL_CLIMB_MIN_VERTICES)
        polytope_climb(p, *direction, out, hint);
    else
        polytope_scan(p, *direction, out, hint);
}

static int adjacency_is_valid(const agjk_polytope *p) {
    if (!p->neighbor_offsets && !p->neighbors) return 1;
    if (!p->neighbor_offsets || !p->neighbors) return 0;
    if (p->neighbor_offsets[0] != 0) return 0;
    for (int i = 0; i < p->vertex_count; ++i)
        if (p->neighbor_offsets[i + 1] < p->neighbor_offsets[i]) return 0;
    int edges = p->neighbor_offsets[p->vertex_count];
    for (int e = 0; e < edges; ++e)
        if (p->neighbors[e] < 0 || p->neighbors[e] >= p->vertex_count) return 0;
    return 1;
}

agjk_status agjk_shape_polytope(agjk_shape *shape, const agjk_polytope *polytope) {
    if (!shape || !polytope || !polytope->vertices || polytope->vertex_count < 1 ||
        polytope->vertex_count > AGJK_POLYTOPE_MAX_VERTICES)
        return AGJK_STATUS_INVALID_INPUT;
    for (int i = 0; i < polytope->vertex_count; ++i)
        if (!v3_in_range(polytope->vertices[i])) return AGJK_STATUS_INVALID_INPUT;
    if (!adjacency_is_valid(polytope)) return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, polytope_support, polytope, 0.0);
}
