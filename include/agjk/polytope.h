/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/polytope.h
 * @brief Vertex adjacency (CSR) of a convex polytope from its hull triangles,
 *        for hill-climbing support (see agjk_polytope in agjk/shapes.h).
 *
 * @defgroup agjk_polytope_adjacency Polytope adjacency
 *
 * Hill climbing walks from the hint vertex to a neighbour with a larger
 * <direction, vertex> until none is larger. On the edge graph of a convex
 * polytope a vertex with no better neighbour is a global maximiser (the
 * simplex-method argument), and with a coherent hint (the previous query's
 * vertex) the walk visits only a few vertices instead of all. In floating
 * point the walk's last vertex is then certified against rounding: each of
 * its edges must lead down beyond the rounding of the comparison (an edge
 * far shorter than the coordinates can gain less than that rounding); ties
 * within rounding are followed, and the walk goes on where an edge rises,
 * so the support point is as good as a scan's.
 *
 * Input: the hull's vertices (every one an extreme point, e.g. the `vertices`
 * of Qhull's output renumbered 0..n-1) and its triangles, as three vertex
 * indices each (any orientation; a triangulated non-triangular facet adds
 * diagonals, which do no harm). Output: the CSR arrays of agjk_polytope:
 * the neighbours of vertex i are neighbors[neighbor_offsets[i] ..
 * neighbor_offsets[i+1] - 1], sorted ascending, no duplicates, no self loops.
 *
 * Two ways to call it:
 * - caller-provided buffers, no allocation (firmware, offline tools):
 *   agjk_polytope_adjacency_capacity() gives the buffer sizes,
 *   agjk_polytope_adjacency_build_into() fills them;
 * - agjk_polytope_build_adjacency() allocates the two arrays with malloc and
 *   sets them in the agjk_polytope; agjk_polytope_free_adjacency() frees them.
 * Nothing here is used during a query: queries never allocate.
 * @{
 */
#ifndef AGJK_POLYTOPE_H
#define AGJK_POLYTOPE_H

#include "agjk/shapes.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Buffer sizes needed by agjk_polytope_adjacency_build_into(), in int32_t
 *  elements: `*out_offsets_count` = vertex_count + 1 and `*out_neighbors_capacity`
 *  = 6 * triangle_count (each triangle gives each of its corners two entries
 *  before duplicates are removed; a closed hull ends up using half of it).
 *  Returns AGJK_STATUS_INVALID_INPUT (and writes nothing) for NULL outputs,
 *  vertex_count outside 1 .. AGJK_POLYTOPE_MAX_VERTICES, negative
 *  triangle_count or a capacity that does not fit in int32_t; otherwise
 *  AGJK_STATUS_OK. */
AGJK_API agjk_status agjk_polytope_adjacency_capacity(int32_t vertex_count,
                                                      int32_t triangle_count,
                                                      int32_t *out_offsets_count,
                                                      int32_t *out_neighbors_capacity);

/** Builds the CSR adjacency into caller buffers, allocating nothing.
 *
 * `triangles` holds 3 * triangle_count vertex indices. `neighbor_offsets`
 * must have vertex_count + 1 elements and `neighbors` `neighbors_capacity`
 * elements, at least what agjk_polytope_adjacency_capacity() says. On success
 * neighbor_offsets[vertex_count] is the number of neighbour entries used.
 *
 * Returns AGJK_STATUS_OK on success, AGJK_STATUS_INVALID_INPUT for NULL
 * pointers, sizes out of range, a too small buffer, an index outside
 * 0 .. vertex_count - 1, a triangle that repeats a vertex, or (when
 * vertex_count > 1) a vertex that no triangle uses: hill climbing from such a
 * vertex would stop there, so interior and unused points must be removed
 * first. Work: O(vertices + triangles * log(max degree)). The buffers'
 * contents are unspecified after a failure. */
AGJK_API agjk_status agjk_polytope_adjacency_build_into(int32_t vertex_count,
                                                        const int32_t *triangles,
                                                        int32_t triangle_count,
                                                        int32_t *neighbor_offsets,
                                                        int32_t *neighbors,
                                                        int32_t neighbors_capacity);

/** Convenience: allocates (malloc) and builds the adjacency of `polytope`
 *  (whose `vertices` and `vertex_count` must be set) from its hull triangles,
 *  and stores the arrays in polytope->neighbor_offsets / neighbors. Release
 *  them with agjk_polytope_free_adjacency(). On failure the polytope is left
 *  without adjacency (both pointers NULL) and nothing stays allocated.
 *  Returns AGJK_STATUS_OK on success, AGJK_STATUS_INVALID_INPUT for bad
 *  input (as agjk_polytope_adjacency_build_into()) or when memory runs out. */
AGJK_API agjk_status agjk_polytope_build_adjacency(agjk_polytope *polytope,
                                                   const int32_t *triangles,
                                                   int32_t triangle_count);

/** Frees arrays allocated by agjk_polytope_build_adjacency() and sets both
 *  pointers to NULL. Safe on NULL and on a polytope without adjacency; must not
 *  be used on caller-provided arrays. */
AGJK_API void agjk_polytope_free_adjacency(agjk_polytope *polytope);

/** Number of start vertices of a prepared polytope (agjk_prepared_polytope). */
#define AGJK_POLYTOPE_STARTS 14

/** A polytope prepared for queries: the polytope, a bound on its
 *  vertices' coordinates and 14 start vertices for a query's first climb,
 *  computed once by agjk_polytope_prepare().
 *
 * Why: the certification of a climb's last vertex (see above) must bound the
 * rounding of <d, u> for each neighbour u, and without a bound on u that is
 * arithmetic on every neighbour the last step reads. With the bound it is one
 * number per support call: support points certified as the plain polytope's
 * are (a tie within rounding may resolve to the other vertex), in about a
 * tenth less time on hull and mesh queries (README, benchmark). And a cold
 * query's first climb (hints 0) between two of them starts near its answer
 * instead of at vertex 0 (Coal keeps such starts too). Use it for a
 * polytope with adjacency that takes many queries; agjk_shape_polytope() is
 * the plain view.
 *
 * The struct holds a copy of the agjk_polytope (whose arrays stay the
 * caller's). Set by agjk_polytope_prepare(); read its fields, but do not
 * change them, and prepare it again after changing the vertices. */
typedef struct agjk_prepared_polytope {
    /** sizeof(agjk_prepared_polytope) as the caller compiled it; set by
     *  agjk_polytope_prepare(). */
    uint32_t struct_size;
    /** The polytope (vertices and optional adjacency, as for
     *  agjk_shape_polytope()). */
    agjk_polytope polytope;
    /** max |x|, |y|, |z| over the vertices, in the vertices' own length
     *  units (the polytope's local frame). */
    double coordinate_bound;
    /** Where a query's first climb may start: the vertices farthest along
     *  +x, -x, +y, -y, +z, -z, then along the diagonals (+-1, +-1, +-1), the
     *  signs of x, y, z as bits 0, 1, 2 of the index - 6 (a set bit: -1).
     *  Vertex indices, 0 .. vertex_count - 1.
     *  When both shapes of a query are prepared polytopes and both hints are
     *  0 (the default: a cold query), its first support starts from the one
     *  of these nearest the direction if it lies higher than vertex 0,
     *  rather than walking across the hull from there. Other hints are
     *  kept. */
    int32_t starts[AGJK_POLYTOPE_STARTS];
} agjk_prepared_polytope;

/** Fills `prepared` from `polytope` (checked as agjk_shape_polytope() checks
 *  it: O(vertices + edges), and 14 scans for the start vertices, once).
 *  `struct_size` must be sizeof(agjk_prepared_polytope) as the caller sees it; use
 *  agjk_polytope_prepare(). Returns AGJK_STATUS_OK, or
 *  AGJK_STATUS_INVALID_INPUT (NULL pointers, too small a struct_size, a
 *  polytope agjk_shape_polytope() rejects), then leaving `prepared`
 *  unchanged. */
AGJK_API agjk_status agjk_polytope_prepare_sized(agjk_prepared_polytope *prepared,
                                                 size_t struct_size,
                                                 const agjk_polytope *polytope);

/** Fills `prepared` from `polytope`; see agjk_polytope_prepare_sized(). */
static inline agjk_status agjk_polytope_prepare(agjk_prepared_polytope *prepared,
                                                const agjk_polytope *polytope) {
    return agjk_polytope_prepare_sized(prepared, sizeof *prepared, polytope);
}

/** A shape from a prepared polytope: the same shape as
 *  agjk_shape_polytope(&prepared->polytope) gives, its support points found
 *  faster and certified alike. Checks the polytope again and that every
 *  vertex lies within `coordinate_bound` (O(vertices + edges), once): a prepared polytope
 *  whose vertices moved after agjk_polytope_prepare() is rejected with
 *  AGJK_STATUS_INVALID_INPUT, as are NULL pointers, an unprepared struct and
 *  start vertices outside 0 .. vertex_count - 1.
 *  `prepared` and the arrays it points to must outlive `shape`, unchanged. */
AGJK_API agjk_status agjk_shape_prepared_polytope(agjk_shape *shape,
                                                  const agjk_prepared_polytope *prepared);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_POLYTOPE_H */
/** @} */
