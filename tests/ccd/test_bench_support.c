/* SPDX-License-Identifier: MIT */
/* Tests of the benchmark's own machinery (tools/bench), against independent
 * truth: the watchdog must report a hanging and a crashing case and keep the
 * others; NESMINO must reach the certified reference distance; the mesh
 * reader must skip a mesh with NaN vertices and read the others; the problem
 * generator must place shapes at the requested signed distance (checked by
 * the long-double reference, not by agjk which placed them). */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../tools/bench/guard.h"
#include "../../tools/bench/mesh_io.h"
#include "../../tools/bench/nesmino.h"

static int failures;

#define ENSURE(cond)                                                              \
    do {                                                                          \
        if (!(cond)) {                                                            \
            printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond);                \
            failures++;                                                           \
        }                                                                         \
    } while (0)

static void guarded_case(void *ctx, int index, void *record) {
    (void)ctx;
    if (index == 2) for (;;) pause();   /* hangs */
    if (index == 4) {                   /* crashes */
        /* A plain signal death, also under a sanitizer (whose handler would
         * print a report for this deliberate crash). */
        signal(SIGSEGV, SIG_DFL);
        raise(SIGSEGV);
    }
    *(int *)record = index * 10;
}

static void test_guard(void) {
    int records[6];
    unsigned char outcome[6];
    int bad, i;
    memset(records, 0xff, sizeof records);
    bad = guard_run(6, sizeof(int), guarded_case, NULL, records, outcome, 0.5);
    ENSURE(bad == 2);
    ENSURE(outcome[2] == GUARD_HUNG);
    ENSURE(outcome[4] == GUARD_CRASHED);
    for (i = 0; i < 6; ++i)
        if (i != 2 && i != 4) {
            ENSURE(outcome[i] == GUARD_OK);
            ENSURE(records[i] == i * 10);
        }
}

static void test_generator_and_nesmino(void) {
    bench_set set;
    bench_rng rng;
    int i, checked = 0;
    bench_set_init(&set, 16, 256);
    bench_rng_seed(&rng, 7);
    bench_generate(&set, BENCH_ELLIPSOIDS, 2, 2, 0, NULL, &rng, 1, 0);
    bench_generate(&set, BENCH_BOXES, 2, 2, 0, NULL, &rng, 1, 0);
    ENSURE(set.problem_count == 4 * 2 * BENCH_TARGET_COUNT);
    for (i = 0; i < set.problem_count; ++i) {
        const bench_problem *p = &set.problems[i];
        nesmino_result nr;
        double d_ref;
        ENSURE(p->ref_ok);
        if (!p->ref_ok) continue;
        d_ref = p->ref.intersecting ? 0.0 : (double)p->ref.distance;
        /* The protocol: positive targets are distances, negative ones overlaps. */
        if (p->target > 0) ENSURE(fabs(d_ref - p->target) < 1e-9);
        else ENSURE(d_ref < 1e-9);
        /* NESMINO stopping on its own duality gap 1e-12: ||x - x*||^2 <= g, so
         * the distance error is at most 1e-6. */
        ENSURE(bench_nesmino(&set.shapes[p->a], &p->pose_a, &set.shapes[p->b], &p->pose_b,
                             NESMINO_STOP_GAP, 1e-12, &p->xstar, 200000, 0.0, &nr) == 0);
        ENSURE(nr.converged);
        ENSURE(fabs(nr.distance - d_ref) <= 1.01e-6);
        /* The paper's rule: within sqrt(1e-8) of the known solution x*. */
        ENSURE(bench_nesmino(&set.shapes[p->a], &p->pose_a, &set.shapes[p->b], &p->pose_b,
                             NESMINO_STOP_SOLUTION, 1e-8, &p->xstar, 200000, 0.05, &nr) == 0);
        ENSURE(nr.converged);
        ENSURE(fabs(nr.distance - d_ref) <= 1.01e-4);
        ++checked;
    }
    ENSURE(checked == set.problem_count);
    bench_set_free(&set);
}

static void write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static void test_mesh_reader(void) {
    char dir[] = "/tmp/agjk-bench-meshes-XXXXXX", path[256];
    bench_mesh_source m;
    int n;
    if (!mkdtemp(dir)) { ENSURE(0); return; }
    snprintf(path, sizeof path, "%s/a.obj", dir);
    write_file(path, "# tetrahedron\nv 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\nf 1 2 3\n");
    snprintf(path, sizeof path, "%s/b.obj", dir);
    write_file(path, "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\n");
    snprintf(path, sizeof path, "%s/c.off", dir);
    write_file(path, "OFF\n4 1 0\n0 0 0\n4 0 0\n0 4 0\n0 0 4\n3 0 1 2\n");
    n = bench_read_mesh_dir(dir, &m, 100, 0.5);
    ENSURE(n == 2);
    if (n == 2) {
        ENSURE(m.counts[0] == 4 && m.counts[1] == 4);
        /* a.obj centred on its box centre (1, 1, 1) and scaled by 0.5. */
        ENSURE(fabs(m.vertices[0][1].x - 0.5) < 1e-15 && fabs(m.vertices[0][0].y + 0.5) < 1e-15);
        ENSURE(fabs(m.vertices[1][1].x - 1.0) < 1e-15); /* c.off: (4-2)*0.5 */
    }
    bench_free_meshes(&m);
    snprintf(path, sizeof path, "%s/a.obj", dir); remove(path);
    snprintf(path, sizeof path, "%s/b.obj", dir); remove(path);
    snprintf(path, sizeof path, "%s/c.off", dir); remove(path);
    rmdir(dir);
}

int main(void) {
    test_guard();
    test_generator_and_nesmino();
    test_mesh_reader();
    printf("%s (%d failures)\n", failures ? "FAIL" : "PASS", failures);
    return failures != 0;
}
