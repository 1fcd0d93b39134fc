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

static void polytope_climb(const agjk_polytope *p, agjk_vec3 d, agjk_vec3 *out, int *hint) {
    const agjk_vec3 *v = p->vertices;
    int current = clamp_hint(*hint, p->vertex_count);
    double current_dot = v3_dot(d, v[current]);
    for (int steps = 0; steps < p->vertex_count; ++steps) {
        int next = current;
        for (int e = p->neighbor_offsets[current]; e < p->neighbor_offsets[current + 1]; ++e) {
            int u = p->neighbors[e];
            double dot = v3_dot(d, v[u]);
            if (dot > current_dot) {
                current_dot = dot;
                next = u;
            }
        }
        if (next == current) break;
        current = next;
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
