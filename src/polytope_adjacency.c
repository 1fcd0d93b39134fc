/* SPDX-License-Identifier: MIT */
/* Vertex adjacency (CSR) of a convex polytope from its hull triangles.
 *
 * Hill-climbing support (as in Coal's support_functions.cpp, or the
 * "GJK-with-hill-climbing" of Cameron 1997) needs, for each hull vertex, the
 * vertices joined to it by a hull edge. We derive it from the triangles in
 * three allocation-free passes over caller buffers:
 *   1. count two entries per triangle corner -> degree upper bounds -> offsets;
 *   2. scatter the entries (each edge appears once per incident triangle);
 *   3. per vertex, sort its entries (heapsort: no recursion, no allocation,
 *      O(d log d) even for the high-degree poles of a UV sphere) and drop
 *      duplicates, compacting the array in place.
 * Only agjk_polytope_build_adjacency() allocates, once, at build time. */
#include "agjk/polytope.h"

#include <stdlib.h>
#include <string.h>

/* Restores the heap property below `root` in a[0..n-1] (max-heap). */
static void sift_down(int32_t *a, int32_t root, int32_t n) {
    for (;;) {
        int32_t child = 2 * root + 1;
        if (child >= n) return;
        if (child + 1 < n && a[child + 1] > a[child]) child++;
        if (a[root] >= a[child]) return;
        int32_t t = a[root];
        a[root] = a[child];
        a[child] = t;
        root = child;
    }
}

/* Sorts a[0..n-1] ascending in place. */
static void heap_sort(int32_t *a, int32_t n) {
    for (int32_t i = n / 2 - 1; i >= 0; i--) sift_down(a, i, n);
    for (int32_t end = n - 1; end > 0; end--) {
        int32_t t = a[0];
        a[0] = a[end];
        a[end] = t;
        sift_down(a, 0, end);
    }
}

agjk_status agjk_polytope_adjacency_capacity(int32_t vertex_count, int32_t triangle_count,
                                             int32_t *out_offsets_count,
                                             int32_t *out_neighbors_capacity) {
    if (!out_offsets_count || !out_neighbors_capacity) return AGJK_STATUS_INVALID_INPUT;
    if (vertex_count < 1 || vertex_count > AGJK_POLYTOPE_MAX_VERTICES) return AGJK_STATUS_INVALID_INPUT;
    if (triangle_count < 0 || triangle_count > INT32_MAX / 6) return AGJK_STATUS_INVALID_INPUT;
    *out_offsets_count = vertex_count + 1;
    *out_neighbors_capacity = 6 * triangle_count;
    return AGJK_STATUS_OK;
}

/* Pass 1: offsets[i] = start of vertex i's (not yet deduplicated) entries.
 * Also validates the indices. */
static int count_entries(int32_t vertex_count, const int32_t *triangles, int32_t triangle_count,
                         int32_t *offsets) {
    memset(offsets, 0, (size_t)(vertex_count + 1) * sizeof *offsets);
    for (int32_t t = 0; t < triangle_count; t++) {
        const int32_t *tri = triangles + 3 * (size_t)t;
        for (int k = 0; k < 3; k++)
            if (tri[k] < 0 || tri[k] >= vertex_count) return 0;
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return 0;
        for (int k = 0; k < 3; k++) offsets[tri[k] + 1] += 2;
    }
    for (int32_t i = 0; i < vertex_count; i++) offsets[i + 1] += offsets[i];
    return 1;
}

/* Pass 2: each corner records its two triangle neighbours. offsets[i] is used
 * as vertex i's write cursor, so afterwards it holds the start of vertex i+1;
 * shifting by one slot restores the starts. */
static void scatter_entries(int32_t vertex_count, const int32_t *triangles, int32_t triangle_count,
                            int32_t *offsets, int32_t *neighbors) {
    for (int32_t t = 0; t < triangle_count; t++) {
        const int32_t *tri = triangles + 3 * (size_t)t;
        for (int k = 0; k < 3; k++) {
            int32_t v = tri[k];
            neighbors[offsets[v]++] = tri[(k + 1) % 3];
            neighbors[offsets[v]++] = tri[(k + 2) % 3];
        }
    }
    for (int32_t i = vertex_count; i > 0; i--) offsets[i] = offsets[i - 1];
    offsets[0] = 0;
}

/* Pass 3: sort and deduplicate each vertex's list, compacting in place.
 * Returns 0 if a vertex is isolated (possible only when vertex_count > 1). */
static int compact_entries(int32_t vertex_count, int32_t *offsets, int32_t *neighbors) {
    int32_t write = 0;
    int32_t begin = offsets[0];
    for (int32_t i = 0; i < vertex_count; i++) {
        int32_t end = offsets[i + 1]; /* read before offsets[i + 1] is overwritten */
        int32_t *list = neighbors + begin;
        int32_t n = end - begin;
        heap_sort(list, n);
        int32_t start = write;
        for (int32_t k = 0; k < n; k++)
            if (write == start || neighbors[write - 1] != list[k]) neighbors[write++] = list[k];
        if (write == start && vertex_count > 1) return 0;
        offsets[i] = start;
        offsets[i + 1] = write;
        begin = end;
    }
    return 1;
}

agjk_status agjk_polytope_adjacency_build_into(int32_t vertex_count, const int32_t *triangles,
                                               int32_t triangle_count, int32_t *neighbor_offsets,
                                               int32_t *neighbors, int32_t neighbors_capacity) {
    int32_t offsets_count, needed;
    if (agjk_polytope_adjacency_capacity(vertex_count, triangle_count, &offsets_count, &needed) !=
        AGJK_STATUS_OK)
        return AGJK_STATUS_INVALID_INPUT;
    if (!neighbor_offsets || (triangle_count > 0 && (!triangles || !neighbors)))
        return AGJK_STATUS_INVALID_INPUT;
    if (neighbors_capacity < needed) return AGJK_STATUS_INVALID_INPUT;
    if (!count_entries(vertex_count, triangles, triangle_count, neighbor_offsets))
        return AGJK_STATUS_INVALID_INPUT;
    scatter_entries(vertex_count, triangles, triangle_count, neighbor_offsets, neighbors);
    if (!compact_entries(vertex_count, neighbor_offsets, neighbors)) return AGJK_STATUS_INVALID_INPUT;
    return AGJK_STATUS_OK;
}

agjk_status agjk_polytope_build_adjacency(agjk_polytope *polytope, const int32_t *triangles,
                                          int32_t triangle_count) {
    int32_t offsets_count, capacity;
    if (!polytope) return AGJK_STATUS_INVALID_INPUT;
    polytope->neighbor_offsets = NULL;
    polytope->neighbors = NULL;
    if (agjk_polytope_adjacency_capacity(polytope->vertex_count, triangle_count, &offsets_count,
                                         &capacity) != AGJK_STATUS_OK)
        return AGJK_STATUS_INVALID_INPUT;
    /* One block: offsets first, then neighbours, so one free() releases both. */
    size_t total = (size_t)offsets_count + (size_t)capacity;
    int32_t *block = malloc(total * sizeof *block);
    if (!block) return AGJK_STATUS_INVALID_INPUT;
    agjk_status status = agjk_polytope_adjacency_build_into(
        polytope->vertex_count, triangles, triangle_count, block, block + offsets_count, capacity);
    if (status != AGJK_STATUS_OK) {
        free(block);
        return status;
    }
    /* A closed hull uses half of the worst-case capacity: give the rest back. */
    size_t used = (size_t)offsets_count + (size_t)block[polytope->vertex_count];
    int32_t *shrunk = realloc(block, (used > 0 ? used : 1) * sizeof *block);
    if (shrunk) block = shrunk;
    polytope->neighbor_offsets = block;
    polytope->neighbors = block + offsets_count;
    return AGJK_STATUS_OK;
}

void agjk_polytope_free_adjacency(agjk_polytope *polytope) {
    if (!polytope) return;
    /* The block was allocated non-const here; memcpy the pointer out rather
     * than cast the const away (keeps -Wcast-qual quiet honestly). */
    int32_t *block;
    memcpy(&block, &polytope->neighbor_offsets, sizeof block);
    free(block);
    polytope->neighbor_offsets = NULL;
    polytope->neighbors = NULL;
}
