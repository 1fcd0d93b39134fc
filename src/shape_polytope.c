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
 * the time for the same instruction count. The climb is a state (the
 * current vertex and its <d, v>, the neighbour list being read, the moves
 * made) advanced one neighbour test at a time, so that two climbs can be
 * taken in turns (agjk__polytope_pair_support). */
typedef struct climb {
    const agjk_vec3 *v;
    const int32_t *offsets, *neighbors;
    agjk_vec3 d;
    double current_dot;
    int current, e, end, moves, limit;
} climb;

static inline void climb_begin(climb *c, const agjk_polytope *p, agjk_vec3 d, int hint) {
    c->v = p->vertices;
    c->offsets = p->neighbor_offsets;
    c->neighbors = p->neighbors;
    c->d = d;
    c->current = clamp_hint(hint, p->vertex_count);
    c->current_dot = v3_dot(d, c->v[c->current]);
    c->e = c->offsets[c->current];
    c->end = c->offsets[c->current + 1];
    c->moves = 0;
    c->limit = p->vertex_count;
}

/* The next neighbour test: 0 once the climb has ended (no better
 * neighbour: a global maximiser; or vertex_count moves made, which only a
 * graph that is not the hull's edge graph can take). */
static inline int climb_step(climb *c) {
    if (c->e == c->end) return 0;
    int u = c->neighbors[c->e];
    double dot = v3_dot(c->d, c->v[u]);
    if (dot > c->current_dot) {
        c->current_dot = dot;
        c->current = u;
        if (++c->moves == c->limit) return 0;
        c->e = c->offsets[u];
        c->end = c->offsets[u + 1];
    } else {
        ++c->e;
    }
    return 1;
}

static void polytope_climb(const agjk_polytope *p, agjk_vec3 d, agjk_vec3 *out, int *hint) {
    climb c;
    climb_begin(&c, p, d, *hint);
    while (climb_step(&c)) {
    }
    *hint = c.current;
    *out = c.v[c.current];
}

static int climbs(const agjk_polytope *p) {
    return p->neighbor_offsets && p->vertex_count >= HILL_CLIMB_MIN_VERTICES;
}

void agjk__polytope_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                            int *hint) {
    const agjk_polytope *p = (const agjk_polytope *)data;
    if (climbs(p))
        polytope_climb(p, *direction, out, hint);
    else
        polytope_scan(p, *direction, out, hint);
}

/* Both supports of a pair of climbing polytopes, the two climbs taken in
 * turns, one neighbour each: the same vertices as one climb after the
 * other. A climb is a chain of loads and comparisons whose every move
 * is a branch the processor mispredicts, and what follows a mispredicted
 * branch is thrown away: one after the other, the second climb cannot
 * advance while the first moves; in turns it does. */
void agjk__polytope_pair_support(const void *data_a, const agjk_vec3 *direction_a,
                                 agjk_vec3 *out_a, int *hint_a, const void *data_b,
                                 const agjk_vec3 *direction_b, agjk_vec3 *out_b, int *hint_b) {
    const agjk_polytope *pa = (const agjk_polytope *)data_a, *pb = (const agjk_polytope *)data_b;
    if (!climbs(pa) || !climbs(pb)) {
        agjk__polytope_support(pa, direction_a, out_a, hint_a);
        agjk__polytope_support(pb, direction_b, out_b, hint_b);
        return;
    }
    climb a, b;
    climb_begin(&a, pa, *direction_a, *hint_a);
    climb_begin(&b, pb, *direction_b, *hint_b);
    int run_a = 1, run_b = 1;
    while (run_a & run_b) {
        run_a = climb_step(&a);
        run_b = climb_step(&b);
    }
    while (run_a) run_a = climb_step(&a);
    while (run_b) run_b = climb_step(&b);
    *hint_a = a.current;
    *out_a = a.v[a.current];
    *hint_b = b.current;
    *out_b = b.v[b.current];
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
    return shape_fill(shape, agjk__polytope_support, polytope, 0.0);
}
