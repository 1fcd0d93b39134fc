/* SPDX-License-Identifier: MIT */
/* Hulls, adjacency and hill-climbing support.
 *
 * 1. agjk_polytope_adjacency_build_into / agjk_polytope_build_adjacency
 *    against a brute-force edge set, and their input checks.
 * 2. For every test hull (the sample meshes and generated point sets: random
 *    points on a sphere and in a cube, a cylinder with coplanar caps, a grid
 *    full of coplanar and collinear points, a thin slab, duplicates), the
 *    support of the polytope shape WITH adjacency (hill climbing) and WITHOUT
 *    (scan) is compared with a brute-force maximum over the raw input points
 *    (independent of Qhull and of the library) on thousands of random and
 *    coherent directions, with the hint carried between calls as a query does.
 *
 *   tests/cli/test_hull_support [SOURCE_DIR]   (default: .) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agjk/agjk.h"
#include "agjk/polytope.h"
#include "mesh.h"

static int failures = 0;
static int checks = 0;

#define ENSURE(cond, ...)                                                                  \
    do {                                                                                   \
        checks++;                                                                          \
        if (!(cond)) {                                                                     \
            failures++;                                                                    \
            fprintf(stderr, "%s:%d: FAIL: %s: ", __FILE__, __LINE__, #cond);               \
            fprintf(stderr, __VA_ARGS__);                                                  \
            fputc('\n', stderr);                                                           \
        }                                                                                  \
    } while (0)

/* splitmix64: small, fixed-seed, reproducible everywhere. */
static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static uint64_t rng_next(void) {
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rng_uniform(void) { return (double)(rng_next() >> 11) * (1.0 / 9007199254740992.0); }
static double rng_gauss(void) {
    double u = rng_uniform(), v = rng_uniform();
    return sqrt(-2.0 * log(u + 1e-300)) * cos(6.283185307179586 * v);
}
static agjk_vec3 rng_direction(void) {
    agjk_vec3 d;
    do {
        d.x = rng_gauss();
        d.y = rng_gauss();
        d.z = rng_gauss();
    } while (d.x * d.x + d.y * d.y + d.z * d.z < 1e-6);
    return d;
}

static double dot(agjk_vec3 a, agjk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* ---- 1. adjacency ---------------------------------------------------------- */

/* Brute force: is {a, b} an edge of some triangle? */
static int is_triangle_edge(const int32_t *tri, int32_t nt, int32_t a, int32_t b) {
    for (int32_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            int32_t u = tri[3 * t + k], v = tri[3 * t + (k + 1) % 3];
            if ((u == a && v == b) || (u == b && v == a)) return 1;
        }
    return 0;
}

/* The CSR lists exactly the triangle edges, sorted, symmetric, no self loop. */
static void check_csr(const char *name, int32_t nv, const int32_t *tri, int32_t nt,
                      const int32_t *off, const int32_t *nb) {
    ENSURE(off[0] == 0, "%s: offsets[0] = %d", name, (int)off[0]);
    int32_t pairs = 0;
    for (int32_t a = 0; a < nv; a++) {
        for (int32_t e = off[a]; e < off[a + 1]; e++) {
            int32_t b = nb[e];
            ENSURE(b >= 0 && b < nv && b != a, "%s: bad neighbour %d of %d", name, (int)b, (int)a);
            if (e > off[a]) ENSURE(nb[e - 1] < b, "%s: list of %d not sorted/unique", name, (int)a);
            ENSURE(is_triangle_edge(tri, nt, a, b), "%s: %d-%d is not an edge", name, (int)a, (int)b);
        }
        for (int32_t b = 0; b < nv; b++) {
            if (!is_triangle_edge(tri, nt, a, b)) continue;
            pairs++;
            int found = 0;
            for (int32_t e = off[a]; e < off[a + 1]; e++) found |= nb[e] == b;
            ENSURE(found, "%s: edge %d-%d missing", name, (int)a, (int)b);
        }
    }
    ENSURE(off[nv] == pairs, "%s: %d entries, %d directed edges", name, (int)off[nv], (int)pairs);
}

static void test_adjacency_small(void) {
    /* Tetrahedron: K4. Cube: 12 triangles, 12 edges + 6 face diagonals. */
    static const int32_t tet[] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    static const int32_t cube[] = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                   2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    int32_t off[9], nb[72], noff, cap;
    ENSURE(agjk_polytope_adjacency_capacity(4, 4, &noff, &cap) == AGJK_STATUS_OK, "capacity");
    ENSURE(noff == 5 && cap == 24, "capacity values %d %d", (int)noff, (int)cap);
    ENSURE(agjk_polytope_adjacency_build_into(4, tet, 4, off, nb, cap) == AGJK_STATUS_OK, "tet");
    check_csr("tetrahedron", 4, tet, 4, off, nb);
    ENSURE(off[4] == 12, "K4 has 12 directed edges, got %d", (int)off[4]);
    ENSURE(agjk_polytope_adjacency_build_into(8, cube, 12, off, nb, 72) == AGJK_STATUS_OK, "cube");
    check_csr("cube", 8, cube, 12, off, nb);
    ENSURE(off[8] == 36, "cube: 18 edges, 36 entries, got %d", (int)off[8]);

    /* Input errors. */
    static const int32_t out_of_range[] = {0, 1, 4};
    static const int32_t repeated[] = {0, 1, 1};
    static const int32_t negative[] = {0, -1, 2};
    ENSURE(agjk_polytope_adjacency_build_into(4, out_of_range, 1, off, nb, 6) ==
               AGJK_STATUS_INVALID_INPUT, "index out of range");
    ENSURE(agjk_polytope_adjacency_build_into(3, repeated, 1, off, nb, 6) ==
               AGJK_STATUS_INVALID_INPUT, "repeated index");
    ENSURE(agjk_polytope_adjacency_build_into(3, negative, 1, off, nb, 6) ==
               AGJK_STATUS_INVALID_INPUT, "negative index");
    ENSURE(agjk_polytope_adjacency_build_into(5, tet, 4, off, nb, 24) == AGJK_STATUS_INVALID_INPUT,
           "isolated vertex 4");
    ENSURE(agjk_polytope_adjacency_build_into(4, tet, 4, off, nb, 23) == AGJK_STATUS_INVALID_INPUT,
           "capacity too small");
    ENSURE(agjk_polytope_adjacency_build_into(4, NULL, 4, off, nb, 24) == AGJK_STATUS_INVALID_INPUT,
           "NULL triangles");
    ENSURE(agjk_polytope_adjacency_build_into(4, tet, 4, NULL, nb, 24) == AGJK_STATUS_INVALID_INPUT,
           "NULL offsets");
    ENSURE(agjk_polytope_adjacency_build_into(0, tet, 0, off, nb, 0) == AGJK_STATUS_INVALID_INPUT,
           "zero vertices");
    ENSURE(agjk_polytope_adjacency_build_into(4, tet, -1, off, nb, 24) == AGJK_STATUS_INVALID_INPUT,
           "negative triangle count");
    ENSURE(agjk_polytope_adjacency_capacity(4, INT32_MAX, &noff, &cap) == AGJK_STATUS_INVALID_INPUT,
           "capacity overflow");
    ENSURE(agjk_polytope_adjacency_build_into(1, NULL, 0, off, NULL, 0) == AGJK_STATUS_OK,
           "a single vertex needs no triangles");

    /* The allocating variant, and free on NULL / on a polytope without adjacency. */
    agjk_vec3 v[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    agjk_polytope p = {v, 4, NULL, NULL};
    ENSURE(agjk_polytope_build_adjacency(&p, tet, 4) == AGJK_STATUS_OK, "build_adjacency");
    ENSURE(p.neighbor_offsets && p.neighbors, "arrays set");
    if (p.neighbor_offsets) check_csr("allocated tetrahedron", 4, tet, 4, p.neighbor_offsets, p.neighbors);
    agjk_polytope_free_adjacency(&p);
    ENSURE(!p.neighbor_offsets && !p.neighbors, "free clears the pointers");
    agjk_polytope_free_adjacency(&p);
    agjk_polytope_free_adjacency(NULL);
    ENSURE(agjk_polytope_build_adjacency(&p, out_of_range, 1) == AGJK_STATUS_INVALID_INPUT,
           "build_adjacency rejects bad input");
    ENSURE(!p.neighbor_offsets && !p.neighbors, "no arrays after failure");
}

/* ---- 2. hulls and support ------------------------------------------------------ */

static double brute_support(const agjk_vec3 *p, size_t n, agjk_vec3 d) {
    double best = -INFINITY;
    for (size_t i = 0; i < n; i++) best = fmax(best, dot(d, p[i]));
    return best;
}

/* Compares one support call of `shape` with the brute-force value. */
static int support_matches(const agjk_shape *shape, const mesh_hull *h, const agjk_vec3 *pts,
                           size_t n, double scale, agjk_vec3 d, int *hint) {
    agjk_vec3 s;
    shape->support(shape->data, &d, &s, hint);
    double want = brute_support(pts, n, d);
    double tol = 1e-12 * scale * sqrt(dot(d, d));
    int in_range = *hint >= 0 && *hint < h->vertex_count;
    return fabs(dot(d, s) - want) <= tol && in_range;
}

static void test_hull(const char *name, const agjk_vec3 *pts, size_t n, int want_dimension) {
    mesh_hull h;
    char err[MESH_ERROR_SIZE];
    if (!mesh_hull_build(pts, n, 1, &h, err, sizeof err)) {
        ENSURE(0, "%s: hull failed: %s", name, err);
        return;
    }
    if (want_dimension >= 0)
        ENSURE(h.dimension == want_dimension, "%s: dimension %d, expected %d", name, h.dimension,
               want_dimension);
    if (h.triangle_count > 0) {
        ENSURE(h.polytope.neighbor_offsets != NULL, "%s: no adjacency", name);
        /* Every triangle is a supporting plane: all input points on its inner side. */
        double scale = 0;
        for (size_t i = 0; i < n; i++) scale = fmax(scale, sqrt(dot(pts[i], pts[i])));
        int outside = 0;
        for (int32_t t = 0; t < h.triangle_count; t++) {
            const int32_t *tri = h.triangles + 3 * t;
            agjk_vec3 a = h.vertices[tri[0]], b = h.vertices[tri[1]], c = h.vertices[tri[2]];
            agjk_vec3 u = {b.x - a.x, b.y - a.y, b.z - a.z}, w = {c.x - a.x, c.y - a.y, c.z - a.z};
            agjk_vec3 nrm = {u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
            double len = sqrt(dot(nrm, nrm));
            if (len == 0) continue;
            for (size_t i = 0; i < n; i += 1 + n / 400)
                outside += dot(nrm, pts[i]) - dot(nrm, a) > 1e-9 * scale * len;
        }
        ENSURE(outside == 0, "%s: %d points outside hull triangles (orientation)", name, outside);
    }
    agjk_polytope scan_poly = {h.vertices, h.vertex_count, NULL, NULL};
    agjk_shape climb, scan;
    ENSURE(agjk_shape_polytope(&climb, &h.polytope) == AGJK_STATUS_OK, "%s: climb shape", name);
    ENSURE(agjk_shape_polytope(&scan, &scan_poly) == AGJK_STATUS_OK, "%s: scan shape", name);
    double scale = 0;
    for (size_t i = 0; i < n; i++) scale = fmax(scale, sqrt(dot(pts[i], pts[i])));
    int bad_climb = 0, bad_scan = 0, calls = 0;
    int hint_climb = 0, hint_scan = 0;
    /* Random directions, hint carried over (the worst case for hill climbing). */
    for (int k = 0; k < 3000; k++, calls++) {
        agjk_vec3 d = rng_direction();
        bad_climb += !support_matches(&climb, &h, pts, n, scale, d, &hint_climb);
        bad_scan += !support_matches(&scan, &h, pts, n, scale, d, &hint_scan);
    }
    /* Coherent directions: a slowly turning vector (a converging query). */
    agjk_vec3 d = rng_direction(), turn = rng_direction();
    for (int k = 0; k < 2000; k++, calls++) {
        d.x += 0.01 * turn.x;
        d.y += 0.01 * turn.y;
        d.z += 0.01 * turn.z;
        if (k % 200 == 0) turn = rng_direction();
        bad_climb += !support_matches(&climb, &h, pts, n, scale, d, &hint_climb);
    }
    /* Any starting vertex works (a caller's stale or random hint). */
    for (int k = 0; k < 1000; k++, calls++) {
        int hint = (int)(rng_next() % (uint64_t)h.vertex_count);
        bad_climb += !support_matches(&climb, &h, pts, n, scale, rng_direction(), &hint);
    }
    /* Axis directions: ties between coplanar vertices. */
    static const agjk_vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < 6; k++, calls++) bad_climb += !support_matches(&climb, &h, pts, n, scale, axes[k], &hint_climb);
    ENSURE(bad_climb == 0, "%s: hill climbing wrong on %d of %d directions", name, bad_climb, calls);
    ENSURE(bad_scan == 0, "%s: scan wrong on %d directions", name, bad_scan);
    printf("  %-28s %7zu points -> %-16s %5d hull vertices, %5d triangles: %d directions ok\n",
           name, n, mesh_hull_kind(&h), (int)h.vertex_count, (int)h.triangle_count, calls);
    mesh_hull_free(&h);
}

static void test_file(const char *dir, const char *file, int want_dimension) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/meshes/%s", dir, file);
    mesh_points p;
    char err[MESH_ERROR_SIZE];
    if (!mesh_load(path, &p, err, sizeof err)) {
        ENSURE(0, "cannot load %s: %s", path, err);
        return;
    }
    test_hull(file, p.points, p.count, want_dimension);
    mesh_points_free(&p);
}

static agjk_vec3 *generate(const char *kind, size_t n, size_t *count) {
    agjk_vec3 *p = malloc((n + 2) * sizeof *p);
    size_t k = 0;
    if (!p) return NULL;
    for (size_t i = 0; i < n; i++) {
        agjk_vec3 v;
        if (strcmp(kind, "sphere") == 0) {
            v = rng_direction();
            double l = sqrt(dot(v, v));
            v.x /= l, v.y /= l, v.z /= l;
        } else if (strcmp(kind, "cube") == 0) {
            v.x = rng_uniform() - 0.5, v.y = rng_uniform() - 0.5, v.z = rng_uniform() - 0.5;
        } else if (strcmp(kind, "cylinder") == 0) {
            double a = 6.283185307179586 * (double)(i / 2) / (double)(n / 2);
            v.x = cos(a), v.y = sin(a), v.z = (i % 2) ? 0.7 : -0.7;
        } else if (strcmp(kind, "grid") == 0) { /* 11^3 lattice */
            v.x = (double)(i % 11) - 5, v.y = (double)((i / 11) % 11) - 5, v.z = (double)(i / 121) - 5;
        } else if (strcmp(kind, "slab") == 0) { /* 1e-7 thick: solid, barely */
            v.x = rng_uniform() * 2 - 1, v.y = rng_uniform() * 2 - 1, v.z = 1e-7 * rng_uniform();
        } else if (strcmp(kind, "ellipsoid") == 0) { /* far from the origin, anisotropic */
            v = rng_direction();
            double l = sqrt(dot(v, v));
            v.x = 100 + 3 * v.x / l, v.y = -50 + 0.2 * v.y / l, v.z = 7 + 1e-2 * v.z / l;
        } else { /* "duplicates": 20 cube corners repeated */
            v.x = (i & 1) ? 0.5 : -0.5, v.y = (i & 2) ? 0.5 : -0.5, v.z = (i & 4) ? 0.5 : -0.5;
        }
        p[k++] = v;
    }
    *count = k;
    return p;
}

int main(int argc, char **argv) {
    const char *dir = argc > 1 ? argv[1] : ".";
    test_adjacency_small();
    printf("hulls (hill climbing and scan vs brute force over the input points):\n");
    test_file(dir, "cube.off", 3);
    test_file(dir, "tetrahedron.off", 3);
    test_file(dir, "sphere.obj", 3);
    test_file(dir, "points.obj", 3);
    test_file(dir, "square.off", 2);
    static const struct { const char *kind; size_t n; int dim; } gen[] = {
        {"sphere", 8, 3}, {"sphere", 40, 3}, {"sphere", 300, 3}, {"sphere", 2000, 3},
        {"cube", 2000, 3}, {"cylinder", 256, 3}, {"grid", 1331, 3}, {"slab", 500, 3},
        {"ellipsoid", 1500, 3}, {"duplicates", 160, 3}};
    for (size_t i = 0; i < sizeof gen / sizeof gen[0]; i++) {
        size_t n;
        char name[64];
        agjk_vec3 *p = generate(gen[i].kind, gen[i].n, &n);
        snprintf(name, sizeof name, "%s-%zu", gen[i].kind, gen[i].n);
        if (p) test_hull(name, p, n, gen[i].dim);
        free(p);
    }
    printf("test_hull_support: %d checks, %d failed\n", checks, failures);
    return failures ? 1 : 0;
}
