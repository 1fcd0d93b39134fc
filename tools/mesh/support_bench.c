/* SPDX-License-Identifier: MIT */
/* support_bench: cost of a polytope support call, scan vs hill climbing, by
 * hull size, to choose the switch-over (run by hand; not part of `make check`).
 *
 *   make support-bench && out/tools/mesh/support_bench [calls_per_run [runs]]
 *   (defaults 20000 and 9: about 10 s; on a loaded machine raise `runs`,
 *   since the minimum over runs is what approaches the unloaded cost)
 *
 * Hulls: n random points on the unit sphere (every point is a hull vertex,
 * about 6 neighbours each, like a tessellated curved part), hull and adjacency
 * by Qhull + agjk_polytope_build_adjacency. Directions:
 * - random: independent uniform directions (a cold query, or a hint from an
 *   unrelated previous query): the climb walks across the hull;
 * - coherent: a direction turning by about 1 degree per call with the hint
 *   carried over (the iterations of one query, or the next frame's query
 *   warm-started with the previous hints).
 * Columns:
 * - scan: the library's polytope shape without adjacency (it scans);
 * - climb: the library's shape with adjacency. The library scans below its
 *   threshold anyway, so `climb*` also times a local copy of the same
 *   steepest-ascent walk, called through the same callback signature, at
 *   every size: that is what the threshold decides between.
 * Time: the best of several runs of `calls` support calls each, in ns per
 * call, directions precomputed (timing excludes generating them).
 *
 * Measured (gcc 12 -O2, x86-64, a loaded 2-core machine, best of 21 runs;
 * expect +-20% between runs):
 *
 *   hull vertices        8    16    32    64   128    512   2048
 *   per call, random directions (hint from the previous, unrelated call)
 *     scan              11    21    43    84   175    835   3128
 *     hill climbing     38    50    72    92   128    236    474
 *   per call, coherent directions (1 degree per call, hint carried)
 *     scan              22    21    44    84   305    729   3031
 *     hill climbing     21    21    15    15    16     18     30
 *   whole agjk_distance query between two such hulls, ns
 *     cold, scan       512   701   973  1435  2434   8107  48914
 *     cold, climb      605   714   867   910  1075   1265   1814
 *     warm, scan       577   607   897  1329  2411   8331  35147
 *     warm, climb      491   566   666   664   780    818   1265
 *
 * Scan costs about 1.5 ns per vertex; a climb costs ~10-25 ns per vertex
 * visited and visits ~0.4 sqrt(n) vertices from a random start but less than
 * one step when the direction moves little, which is what happens between
 * the iterations of one query. Per query, climbing wins from about 24
 * vertices cold and from 8-16 warm; below that the two are within 15%.
 * Hence the library's threshold of 32 vertices (Coal's value too). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "agjk/agjk.h"
#include "agjk/polytope.h"
#include "mesh.h"

static uint64_t rng_state = 12345;
static uint64_t rng_next(void) {
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rng_gauss(void) {
    double u = ((double)(rng_next() >> 11) + 0.5) / 9007199254740992.0;
    double v = (double)(rng_next() >> 11) / 9007199254740992.0;
    return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}
static agjk_vec3 rng_unit(void) {
    agjk_vec3 d = {rng_gauss(), rng_gauss(), rng_gauss()};
    double l = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    d.x /= l, d.y /= l, d.z /= l;
    return d;
}

static double dot(agjk_vec3 a, agjk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* The walk of the library's shape_polytope.c (steepest ascent over the
 * neighbours), without its size threshold. */
static void local_climb(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint) {
    const agjk_polytope *p = data;
    int current = (*hint >= 0 && *hint < p->vertex_count) ? *hint : 0;
    double best = dot(*direction, p->vertices[current]);
    for (int steps = 0; steps < p->vertex_count; steps++) {
        int next = current;
        for (int e = p->neighbor_offsets[current]; e < p->neighbor_offsets[current + 1]; e++) {
            double v = dot(*direction, p->vertices[p->neighbors[e]]);
            if (v > best) {
                best = v;
                next = p->neighbors[e];
            }
        }
        if (next == current) break;
        current = next;
    }
    *hint = current;
    *out = p->vertices[current];
}

static double now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static volatile double sink;

/* Best-of-runs ns per call of `fn` over dirs[0..calls-1], hint carried over. */
static double time_support(agjk_support_fn fn, const void *data, const agjk_vec3 *dirs, int calls,
                           int runs) {
    double best = INFINITY;
    for (int r = 0; r < runs; r++) {
        int hint = 0;
        double acc = 0;
        double t0 = now_ns();
        for (int i = 0; i < calls; i++) {
            agjk_vec3 s;
            fn(data, &dirs[i], &s, &hint);
            acc += s.x;
        }
        double t = (now_ns() - t0) / calls;
        sink = acc;
        if (t < best) best = t;
    }
    return best;
}

/* Mean vertices visited per climb (steps + 1), for the report. */
static double mean_steps(const agjk_polytope *p, const agjk_vec3 *dirs, int calls) {
    int hint = 0;
    double total = 0;
    for (int i = 0; i < calls; i++) {
        int before = hint, steps = 0;
        agjk_vec3 s;
        /* Count by re-walking: cheap enough for a report. */
        int current = before;
        double best = dot(dirs[i], p->vertices[current]);
        for (;;) {
            int next = current;
            for (int e = p->neighbor_offsets[current]; e < p->neighbor_offsets[current + 1]; e++) {
                double v = dot(dirs[i], p->vertices[p->neighbors[e]]);
                if (v > best) {
                    best = v;
                    next = p->neighbors[e];
                }
            }
            if (next == current) break;
            current = next;
            steps++;
        }
        local_climb(p, &dirs[i], &s, &hint);
        total += steps;
    }
    return total / calls;
}

/* Rotation about a unit axis by angle a (Rodrigues), row-major. */
static void rotation(agjk_vec3 u, double a, double r[3][3]) {
    double c = cos(a), s = sin(a), t = 1 - c;
    r[0][0] = t * u.x * u.x + c, r[0][1] = t * u.x * u.y - s * u.z, r[0][2] = t * u.x * u.z + s * u.y;
    r[1][0] = t * u.x * u.y + s * u.z, r[1][1] = t * u.y * u.y + c, r[1][2] = t * u.y * u.z - s * u.x;
    r[2][0] = t * u.x * u.z - s * u.y, r[2][1] = t * u.y * u.z + s * u.x, r[2][2] = t * u.z * u.z + c;
}

/* Whole distance queries between two copies of the hull: B at 2.3 to 3
 * (gap 0.3 to 1) from A. cold: independent random poses, hints 0. warm: a
 * trajectory (B turning 1 degree and moving 0.005 per step) with each query
 * started from the previous result's hints, as a simulation would. Returns
 * ns per query, best of `runs`. */
static double time_queries(const agjk_shape *s, int queries, int warm, int runs) {
    double best = INFINITY;
    for (int r = 0; r < runs; r++) {
        uint64_t saved = rng_state;
        rng_state = 777;
        agjk_pose pa, pb;
        agjk_options o = agjk_default_options();
        agjk_result res;
        agjk_vec3 axis = rng_unit(), dir = rng_unit();
        double angle = 0;
        rotation(axis, 0.0, pa.rotation);
        pa.translation = (agjk_vec3){0, 0, 0};
        double total = 0;
        for (int q = 0; q < queries; q++) {
            if (!warm || q % 200 == 0) {
                axis = rng_unit();
                dir = rng_unit();
                angle = 6.283185307179586 * (double)(rng_next() % 1000) / 1000.0;
                o.hint_a = o.hint_b = 0;
            }
            angle += warm ? 0.0175 : 0;
            rotation(axis, angle, pb.rotation);
            double dist = 2.3 + 0.7 * (double)(q % 100) / 100.0;
            pb.translation = (agjk_vec3){dist * dir.x, dist * dir.y, dist * dir.z};
            double t0 = now_ns();
            agjk_distance(s, &pa, s, &pb, &o, &res);
            total += now_ns() - t0;
            if (warm) {
                o.hint_a = res.hint_a;
                o.hint_b = res.hint_b;
            }
        }
        rng_state = saved;
        if (total / queries < best) best = total / queries;
    }
    return best;
}

int main(int argc, char **argv) {
    int calls = argc > 1 ? atoi(argv[1]) : 20000;
    int runs = argc > 2 ? atoi(argv[2]) : 9;
    if (calls < 100) calls = 100;
    if (runs < 1) runs = 1;
    static const int sizes[] = {8, 16, 32, 64, 128, 512, 2048};
    double qres[sizeof sizes / sizeof sizes[0]][4];
    agjk_vec3 *random_dirs = malloc((size_t)calls * sizeof *random_dirs);
    agjk_vec3 *coherent_dirs = malloc((size_t)calls * sizeof *coherent_dirs);
    if (!random_dirs || !coherent_dirs) return 1;
    for (int i = 0; i < calls; i++) random_dirs[i] = rng_unit();
    /* ~1 degree per call around an axis that itself drifts. */
    agjk_vec3 d = rng_unit(), axis = rng_unit();
    for (int i = 0; i < calls; i++) {
        if (i % 500 == 0) axis = rng_unit();
        agjk_vec3 c = {axis.y * d.z - axis.z * d.y, axis.z * d.x - axis.x * d.z,
                       axis.x * d.y - axis.y * d.x};
        d.x += 0.0175 * c.x, d.y += 0.0175 * c.y, d.z += 0.0175 * c.z;
        double l = sqrt(dot(d, d));
        d.x /= l, d.y /= l, d.z /= l;
        coherent_dirs[i] = d;
    }
    printf("# support_bench: ns per support call, best of %d runs of %d calls\n", runs, calls);
    printf("# n = hull vertices (random points on a sphere); climb* = steepest ascent "
           "at every size; lib = library shape with adjacency; prep = the same prepared "
           "(agjk_polytope_prepare)\n");
    printf("%6s | %9s %9s %9s %9s %7s | %9s %9s %9s %9s %7s\n", "n", "scan", "climb*", "lib",
           "prep", "steps", "scan", "climb*", "lib", "prep", "steps");
    printf("%6s | %47s | %47s\n", "", "random directions", "coherent directions");
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        int n = sizes[k];
        agjk_vec3 *pts = malloc((size_t)n * sizeof *pts);
        if (!pts) return 1;
        for (int i = 0; i < n; i++) pts[i] = rng_unit();
        mesh_hull h;
        char err[MESH_ERROR_SIZE];
        if (!mesh_hull_build(pts, (size_t)n, 1, &h, err, sizeof err)) {
            fprintf(stderr, "hull of %d points: %s\n", n, err);
            return 1;
        }
        agjk_polytope scan_poly = {h.vertices, h.vertex_count, NULL, NULL};
        agjk_shape scan, lib, prep;
        if (agjk_shape_polytope(&scan, &scan_poly) != AGJK_STATUS_OK ||
            agjk_shape_polytope(&lib, &h.polytope) != AGJK_STATUS_OK ||
            agjk_shape_prepared_polytope(&prep, &h.prepared) != AGJK_STATUS_OK) {
            fprintf(stderr, "library rejected the polytope\n");
            return 1;
        }
        double r[2][4], steps[2];
        const agjk_vec3 *sets[2] = {random_dirs, coherent_dirs};
        for (int s = 0; s < 2; s++) {
            r[s][0] = time_support(scan.support, scan.data, sets[s], calls, runs);
            r[s][1] = time_support(local_climb, &h.polytope, sets[s], calls, runs);
            r[s][2] = time_support(lib.support, lib.data, sets[s], calls, runs);
            r[s][3] = time_support(prep.support, prep.data, sets[s], calls, runs);
            steps[s] = mean_steps(&h.polytope, sets[s], calls < 20000 ? calls : 20000);
        }
        printf("%6d | %9.1f %9.1f %9.1f %9.1f %7.2f | %9.1f %9.1f %9.1f %9.1f %7.2f\n",
               (int)h.vertex_count, r[0][0], r[0][1], r[0][2], r[0][3], steps[0], r[1][0],
               r[1][1], r[1][2], r[1][3], steps[1]);
        agjk_shape climb = {local_climb, &h.polytope, 0.0};
        int nq = calls / 20 < 500 ? 500 : calls / 20;
        qres[k][0] = time_queries(&scan, nq, 0, runs);
        qres[k][1] = time_queries(&climb, nq, 0, runs);
        qres[k][2] = time_queries(&scan, nq, 1, runs);
        qres[k][3] = time_queries(&climb, nq, 1, runs);
        fflush(stdout);
        mesh_hull_free(&h);
        free(pts);
    }
    printf("\n# whole agjk_distance queries between two such hulls, ns per query (default "
           "options)\n%6s | %9s %9s | %9s %9s\n%6s | %19s | %19s\n", "n", "scan", "climb*", "scan",
           "climb*", "", "cold (hints 0)", "warm (prev. hints)");
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++)
        printf("%6d | %9.0f %9.0f | %9.0f %9.0f\n", sizes[k], qres[k][0], qres[k][1], qres[k][2],
               qres[k][3]);
    free(random_dirs);
    free(coherent_dirs);
    return 0;
}
