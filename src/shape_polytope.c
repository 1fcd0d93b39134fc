/* SPDX-License-Identifier: MIT */
/* Convex polytope given by its vertices.
 *
 * Support by scan (O(n), any point set) or, when the hull's vertex adjacency is
 * given, by hill climbing from the caller's hint: move to a neighbour with a
 * larger <d, v> until none is larger. On the edge graph of a convex polytope a
 * vertex with no better neighbour is a global maximiser (the simplex method's
 * optimality argument), and coherent directions make the walk a few steps
 * long. Each step strictly increases the computed <d, v>, so a walk visits
 * no vertex twice and is bounded by the vertex count (climb_settle resumes
 * it a few times at most).
 *
 * In floating point "no better neighbour" is not enough: the rounding of
 * <d, v> grows with the coordinates, and an edge far shorter than them can
 * gain less than that rounding. Near x = 1000 a climb stopped before a 1e-9
 * edge whose far end led to a vertex 5e-5 higher, and the solver certified a
 * wrong distance from that support. So the final vertex v is certified.
 * Usually by the walk's own last pass (climb_clear): every neighbour's
 * computed <d, u> lies below v's by more than the rounding of the two, which
 * climb_step bounds as it goes (3 eps of sum |d_i u_i|). Otherwise edge by
 * edge (climb_settle, plateau_best): each gain <d, u - v>, computed from the
 * edge so that its rounding scales with the edge, must be <= 0 beyond that
 * rounding, or exactly 0 (a tie: every term of the sum is). Edges within
 * rounding of 0 (GJK's last directions are orthogonal to an edge or a face)
 * are followed to the vertices that tie with v, and the climb goes on where
 * an edge rises; a scan is the last resort. The bound in climb_step costs
 * the walk about a quarter of its time on the benchmark's hulls
 * (tools/bench/PERFORMANCE.md). A prepared polytope (agjk_polytope_prepare)
 * carries a bound M on every vertex's coordinates, so that sum |d_i u_i| <=
 * M sum |d_i| for every neighbour u at once: climb_step then keeps the
 * plain largest <d, u>, and climb_clear adds that one allowance (twice:
 * for v's own sum as well). */
#include <string.h>

#include "agjk/polytope.h"
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
 * left) advanced one neighbour test at a time, so that two climbs can be
 * taken in turns (agjk__polytope_pair_support). */
#define DOT_ROUNDING (8.0 * DBL_EPSILON)

typedef struct climb {
    const agjk_vec3 *v;
    const int32_t *offsets, *neighbors;
    agjk_vec3 d;
    double current_dot;
    /* Over the neighbours of the current vertex tested so far: the largest
     * <d, u>, plus a bound on its rounding unless the climb is `bounded`
     * (climb_clear). */
    double near;
    /* A bounded climb's bound on sum |d_i u_i| for every vertex u: sum |d_i|
     * times the prepared polytope's coordinate bound. */
    double far;
    int current, e, end;
    int left; /* moves left: vertex_count at most */
} climb;

/* `bound`: the prepared polytope's coordinate bound, read by a bounded
 * climb (`bounded`, a constant at every call) only. */
static AGJK__ALWAYS_INLINE void climb_begin(climb *c, const agjk_polytope *p, agjk_vec3 d,
                                           int hint, double bound, int bounded) {
    c->v = p->vertices;
    c->offsets = p->neighbor_offsets;
    c->neighbors = p->neighbors;
    c->d = d;
    c->current = clamp_hint(hint, p->vertex_count);
    c->current_dot = v3_dot(d, c->v[c->current]);
    c->e = c->offsets[c->current];
    c->end = c->offsets[c->current + 1];
    c->left = p->vertex_count;
    c->near = -INFINITY;
    c->far = bounded ? (fabs(d.x) + fabs(d.y) + fabs(d.z)) * bound : 0.0;
}

/* The next neighbour test: 0 once the climb has ended (no better
 * neighbour: a global maximiser, to be certified; or vertex_count moves
 * made, which only a graph that is not the hull's edge graph can take).
 * `bounded` (a constant at every call) leaves the rounding to c->far. */
static AGJK__ALWAYS_INLINE int climb_step(climb *c, int bounded) {
    if (c->e == c->end) return 0;
    int u = c->neighbors[c->e];
    agjk_vec3 q = c->v[u];
    double px = c->d.x * q.x, py = c->d.y * q.y, pz = c->d.z * q.z;
    double dot = px + py + pz;
    if (dot > c->current_dot) {
        c->current_dot = dot;
        c->current = u;
        c->near = -INFINITY;
        if (--c->left == 0) return 0;
        c->e = c->offsets[u];
        c->end = c->offsets[u + 1];
    } else {
        double high = bounded ? dot : dot + DOT_ROUNDING * (fabs(px) + fabs(py) + fabs(pz));
        c->near = high > c->near ? high : c->near;
        ++c->e;
    }
    return 1;
}

/* The climb ended on vertex v = c->current, whose every neighbour u has a
 * computed <d, u> no larger than its own. Certified at once when each one
 * lies below by more than the rounding of the two: <d, x> is computed to
 * 3 eps of sum |d_i x_i| (a few eps more here cover the test's own
 * rounding); climb_step keeps the largest <d, u> plus that allowance, or
 * for a bounded climb the largest <d, u>, whose allowance c->far covers.
 * A bounded climb covers v's own sum by c->far too (which bounds every
 * vertex's): 2 c->far, a constant of the walk, where v's sum needed v's
 * point read back after the walk's last move, which put a load and seven
 * operations between the walk's end and the branch on this test (hull and
 * mesh cells 1-3% faster; the allowance is at most twice as large, and
 * the rare vertices it leaves undecided are settled edge by edge). The
 * vertices left undecided (ties, and the near-ties GJK's last directions
 * give, orthogonal to an edge or a face) go to climb_settle. */
static AGJK__ALWAYS_INLINE int climb_clear(const climb *c, int bounded) {
    if (bounded) return c->near < c->current_dot - DOT_ROUNDING * (2.0 * c->far) - 0x1p-1000;
    agjk_vec3 d = c->d, q = c->v[c->current];
    double own = fabs(d.x * q.x) + fabs(d.y * q.y) + fabs(d.z * q.z);
    return c->near < c->current_dot - DOT_ROUNDING * own - 0x1p-1000;
}

/* The rounding of a gain <d, fl(u - v)> = sum p_i, p_i = fl(d_i fl(e_i)),
 * against <d, u - v>: the subtraction's relative eps and the sum's 2 eps on
 * each |p_i|, plus the products' own eps, with room for the bound's own
 * rounding; and an absolute term for products that underflow. */
#define GAIN_ROUNDING (6.0 * DBL_EPSILON)
#define GAIN_UNDERFLOW 0x1p-1000

/* An edge e = u - v's gain along d, classified: EDGE_DOWN when it is <= 0
 * beyond its rounding, or exactly 0 because every term is (a factor is 0:
 * an exact tie, which cannot lead to a rise); EDGE_UP when it is > 0 beyond
 * its rounding; EDGE_FLAT otherwise (within rounding of 0). */
enum { EDGE_DOWN, EDGE_UP, EDGE_FLAT };
static inline int edge_class(agjk_vec3 d, agjk_vec3 e) {
    double px = d.x * e.x, py = d.y * e.y, pz = d.z * e.z;
    double gain = px + py + pz;
    double rounding = GAIN_ROUNDING * (fabs(px) + fabs(py) + fabs(pz)) + GAIN_UNDERFLOW;
    if (-gain > rounding) return EDGE_DOWN;
    if (gain > rounding) return EDGE_UP;
    int tie = gain == 0.0 && (d.x == 0.0 || e.x == 0.0) && (d.y == 0.0 || e.y == 0.0) &&
              (d.z == 0.0 || e.z == 0.0);
    return tie ? EDGE_DOWN : EDGE_FLAT;
}

/* A climb's final vertex that climb_clear could not certify, edge by edge:
 * every edge goes down (the vertex is returned), or some edge is flat
 * (GJK's directions end orthogonal to an edge or a face of the polytope, so
 * ties within rounding are common near convergence) or goes up (a rise the
 * rounded comparison of <d, u> with <d, v> missed). The flat
 * edges are followed, PLATEAU_MAX vertices at most: if no vertex of that
 * plateau has an edge going up, the exact maximiser is among them (from any
 * vertex that is not a maximiser an edge rises exactly, and each such edge
 * is flat or up, so rising edges never leave the plateau), and the plateau
 * vertex with the largest <d, v> is as good as a scan's answer. Returns that
 * vertex; or -1 - u when the edge to u goes up (the climb goes on from u);
 * or PLATEAU_SCAN when the plateau is too large. */
#define PLATEAU_MAX 32
#define PLATEAU_SCAN (-1 - AGJK_POLYTOPE_MAX_VERTICES - 1)
static AGJK__NOINLINE int plateau_best(const agjk_polytope *p, agjk_vec3 d, int start) {
    int plateau[PLATEAU_MAX];
    int n = 1;
    plateau[0] = start;
    for (int k = 0; k < n; ++k) {
        int i = plateau[k];
        agjk_vec3 at = p->vertices[i];
        for (int e = p->neighbor_offsets[i]; e < p->neighbor_offsets[i + 1]; ++e) {
            int u = p->neighbors[e];
            int c = edge_class(d, v3_sub(p->vertices[u], at));
            if (c == EDGE_UP) return -1 - u;
            if (c == EDGE_DOWN) continue;
            int seen = 0;
            for (int m = 0; m < n && !seen; ++m) seen = plateau[m] == u;
            if (seen) continue;
            if (n == PLATEAU_MAX) return PLATEAU_SCAN;
            plateau[n++] = u;
        }
    }
    int best = plateau[0];
    double best_dot = v3_dot(d, p->vertices[best]);
    for (int k = 1; k < n; ++k) {
        double dot = v3_dot(d, p->vertices[plateau[k]]);
        if (dot > best_dot) {
            best_dot = dot;
            best = plateau[k];
        }
    }
    return best;
}

/* The climb's answer, certified: the final vertex `current` when every edge
 * goes down; else the plateau's best, with the climb resumed where an edge
 * goes up (a few times at most: then, or on a plateau too large, or after a
 * climb cut off by its bound, a scan). By value, so that the callers' climbs
 * stay in registers. */
#define CLIMB_RESUMES 4
static AGJK__NOINLINE void climb_settle(const agjk_polytope *p, agjk_vec3 d, int current,
                                        int cut, agjk_vec3 *out, int *hint) {
    for (int r = 0; r < CLIMB_RESUMES && !cut; ++r) {
        int best = plateau_best(p, d, current);
        if (best >= 0) {
            *hint = best;
            *out = p->vertices[best];
            return;
        }
        if (best == PLATEAU_SCAN) break;
        /* on from the vertex the rising edge leads to (its end is
         * certified by plateau_best, not by climb_clear: bounded, for the
         * cheaper step, with no bound) */
        climb c;
        climb_begin(&c, p, d, -1 - best, 0.0, 0);
        while (climb_step(&c, 1)) {
        }
        current = c.current;
        cut = c.left == 0;
    }
    polytope_scan(p, d, out, hint);
}

/* The climb's final vertex into *out and *hint, certified (climb_settle). */
static inline void climb_answer(const agjk_polytope *p, agjk_vec3 d, int current, int cut,
                                int clear, agjk_vec3 *out, int *hint) {
    if (!cut && clear) {
        *hint = current;
        *out = p->vertices[current];
        return;
    }
    climb_settle(p, d, current, cut, out, hint);
}

static int climbs(const agjk_polytope *p) {
    return p->neighbor_offsets && p->vertex_count >= HILL_CLIMB_MIN_VERTICES;
}

/* One support: a climb (bounded by `bound` when `bounded`) or a scan. */
static AGJK__ALWAYS_INLINE void polytope_support(const agjk_polytope *p, double bound,
                                                 int bounded, agjk_vec3 d, agjk_vec3 *out,
                                                 int *hint) {
    if (!climbs(p)) {
        polytope_scan(p, d, out, hint);
        return;
    }
    climb c;
    climb_begin(&c, p, d, *hint, bound, bounded);
    while (climb_step(&c, bounded)) {
    }
    climb_answer(p, d, c.current, c.left == 0, climb_clear(&c, bounded), out, hint);
}

void agjk__polytope_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                            int *hint) {
    polytope_support((const agjk_polytope *)data, 0.0, 0, *direction, out, hint);
}

void agjk__prepared_polytope_support(const void *data, const agjk_vec3 *direction,
                                     agjk_vec3 *out, int *hint) {
    const agjk_prepared_polytope *pp = (const agjk_prepared_polytope *)data;
    polytope_support(&pp->polytope, pp->coordinate_bound, 1, *direction, out, hint);
}

/* Both supports of a pair of climbing polytopes, the two climbs taken in
 * turns, one neighbour each: the same vertices as one climb after the
 * other. A climb is a chain of loads and comparisons whose every move
 * is a branch the processor mispredicts, and what follows a mispredicted
 * branch is thrown away: one after the other, the second climb cannot
 * advance while the first moves; in turns it does. */
/* `start_a`, `start_b`: where the two climbs start (the hints, or better
 * starts: prepared_start). */
static AGJK__ALWAYS_INLINE void pair_support(const agjk_polytope *pa, double bound_a,
                                             agjk_vec3 da, agjk_vec3 *out_a, int *hint_a,
                                             int start_a, const agjk_polytope *pb,
                                             double bound_b, agjk_vec3 db, agjk_vec3 *out_b,
                                             int *hint_b, int start_b, int bounded) {
    if (!climbs(pa) || !climbs(pb)) {
        polytope_support(pa, bound_a, bounded, da, out_a, hint_a);
        polytope_support(pb, bound_b, bounded, db, out_b, hint_b);
        return;
    }
    climb a, b;
    climb_begin(&a, pa, da, start_a, bound_a, bounded);
    climb_begin(&b, pb, db, start_b, bound_b, bounded);
    int run_a = 1, run_b = 1;
    while (run_a & run_b) {
        run_a = climb_step(&a, bounded);
        run_b = climb_step(&b, bounded);
    }
    while (run_a) run_a = climb_step(&a, bounded);
    while (run_b) run_b = climb_step(&b, bounded);
    int current_a = a.current, cut_a = a.left == 0, clear_a = climb_clear(&a, bounded);
    int current_b = b.current, cut_b = b.left == 0, clear_b = climb_clear(&b, bounded);
    climb_answer(pa, da, current_a, cut_a, clear_a, out_a, hint_a);
    climb_answer(pb, db, current_b, cut_b, clear_b, out_b, hint_b);
}

void agjk__polytope_pair_support(const void *data_a, const agjk_vec3 *direction_a,
                                 agjk_vec3 *out_a, int *hint_a, const void *data_b,
                                 const agjk_vec3 *direction_b, agjk_vec3 *out_b, int *hint_b) {
    pair_support((const agjk_polytope *)data_a, 0.0, *direction_a, out_a, hint_a, *hint_a,
                 (const agjk_polytope *)data_b, 0.0, *direction_b, out_b, hint_b, *hint_b, 0);
}

/* The directions of a prepared polytope's start vertices: the axes, then
 * the diagonals, the signs of x, y, z as bits 0, 1, 2 of k - 6 (a set bit:
 * negative), so that prepared_start finds d's octant from its signs. */
static const agjk_vec3 start_directions[AGJK_POLYTOPE_STARTS] = {
    {1, 0, 0},  {-1, 0, 0},  {0, 1, 0},  {0, -1, 0},  {0, 0, 1},   {0, 0, -1},   {1, 1, 1},
    {-1, 1, 1}, {1, -1, 1},  {-1, -1, 1}, {1, 1, -1}, {-1, 1, -1}, {1, -1, -1}, {-1, -1, -1}};

/* Where a prepared polytope's climb along d starts: of the hint's vertex and
 * the start vertex whose direction (an axis or a diagonal) lies nearest d,
 * the higher. A query's first support runs it when both hints are 0 (the
 * default: a cold query), where the climb would otherwise walk from vertex
 * 0 across the hull (a few dozen moves on the benchmark's larger hulls);
 * Coal starts from the best of its 14 precomputed supports. Hints from a
 * cache or a caller are kept: their vertex is near the answer already, and
 * the start vertex's load alone made warm mesh queries 10% slower. Out of
 * line: the climbs' code stays as it was. Closest of the 14 by angle: the
 * axis when max |d_i| >= sum |d_i| / sqrt(3), else the diagonal of d's
 * octant. */
static AGJK__NOINLINE int prepared_start(const agjk_prepared_polytope *pp, agjk_vec3 d,
                                         int hint) {
    const agjk_polytope *p = &pp->polytope;
    int h = clamp_hint(hint, p->vertex_count);
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    int k;
    if (m * 1.7320508075688772 >= ax + ay + az)
        k = m == ax ? (d.x < 0.0) : m == ay ? 2 + (d.y < 0.0) : 4 + (d.z < 0.0);
    else
        k = 6 + (d.x < 0.0) + 2 * (d.y < 0.0) + 4 * (d.z < 0.0);
    int s = pp->starts[k];
    return v3_dot(d, p->vertices[s]) > v3_dot(d, p->vertices[h]) ? s : h;
}

void agjk__prepared_polytope_pair_support(const void *data_a, const agjk_vec3 *direction_a,
                                          agjk_vec3 *out_a, int *hint_a, const void *data_b,
                                          const agjk_vec3 *direction_b, agjk_vec3 *out_b,
                                          int *hint_b, int first) {
    const agjk_prepared_polytope *pa = (const agjk_prepared_polytope *)data_a;
    const agjk_prepared_polytope *pb = (const agjk_prepared_polytope *)data_b;
    agjk_vec3 da = *direction_a, db = *direction_b;
    int start_a = *hint_a, start_b = *hint_b;
    if (first && (start_a | start_b) == 0 && climbs(&pa->polytope) && climbs(&pb->polytope)) {
        start_a = prepared_start(pa, da, start_a);
        start_b = prepared_start(pb, db, start_b);
    }
    pair_support(&pa->polytope, pa->coordinate_bound, da, out_a, hint_a, start_a, &pb->polytope,
                 pb->coordinate_bound, db, out_b, hint_b, start_b, 1);
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

/* Whether agjk_shape_polytope accepts `p`; if so, *bound = max |coordinate|
 * over its vertices. */
static int polytope_is_valid(const agjk_polytope *p, double *bound) {
    if (!p || !p->vertices || p->vertex_count < 1 || p->vertex_count > AGJK_POLYTOPE_MAX_VERTICES)
        return 0;
    double m = 0.0;
    for (int i = 0; i < p->vertex_count; ++i) {
        if (!v3_in_range(p->vertices[i])) return 0;
        double c = v3_maxabs(p->vertices[i]);
        m = c > m ? c : m;
    }
    *bound = m;
    return adjacency_is_valid(p);
}

agjk_status agjk_shape_polytope(agjk_shape *shape, const agjk_polytope *polytope) {
    double bound;
    if (!shape || !polytope_is_valid(polytope, &bound)) return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__polytope_support, polytope, 0.0);
}

agjk_status agjk_polytope_prepare_sized(agjk_prepared_polytope *prepared, size_t struct_size,
                                        const agjk_polytope *polytope) {
    double bound;
    if (!prepared || struct_size < sizeof *prepared || !polytope_is_valid(polytope, &bound))
        return AGJK_STATUS_INVALID_INPUT;
    memset(prepared, 0, sizeof *prepared);
    prepared->struct_size = (uint32_t)sizeof *prepared;
    prepared->polytope = *polytope;
    prepared->coordinate_bound = bound;
    for (int k = 0; k < AGJK_POLYTOPE_STARTS; ++k) {
        int hint;
        agjk_vec3 unused;
        polytope_scan(polytope, start_directions[k], &unused, &hint);
        prepared->starts[k] = hint;
    }
    return AGJK_STATUS_OK;
}

agjk_status agjk_shape_prepared_polytope(agjk_shape *shape,
                                         const agjk_prepared_polytope *prepared) {
    double bound;
    /* The bound must hold for the vertices as they are now (the climb's
     * certification rests on it): checked in the same pass as their range.
     * NaN fails the comparisons. */
    if (!shape || !prepared || prepared->struct_size < sizeof *prepared ||
        !polytope_is_valid(&prepared->polytope, &bound) ||
        !(bound <= prepared->coordinate_bound) ||
        !(prepared->coordinate_bound <= AGJK_MAX_COORDINATE))
        return AGJK_STATUS_INVALID_INPUT;
    for (int k = 0; k < AGJK_POLYTOPE_STARTS; ++k)
        if (prepared->starts[k] < 0 || prepared->starts[k] >= prepared->polytope.vertex_count)
            return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__prepared_polytope_support, prepared, 0.0);
}
