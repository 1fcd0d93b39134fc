/* SPDX-License-Identifier: MIT */
/* check_real_meshes: the `agjk distance --json` answer on real meshes (e.g.
 * the pybullet random_urdfs set of tools/fetch-meshes.sh) in random poses,
 * against tests/common's long double reference run on the raw file points
 * (independent of Qhull, of hill climbing and of agjk's solver). Run by hand:
 *
 *   make check-real-meshes [REAL_MESH_DIR=out/meshes/random_urdfs]
 *   out/tests/cli/check_real_meshes AGJK_BINARY MESH_DIR [PAIRS [SEED]]
 *
 * For each pair: two random meshes NNN/NNN.obj, B turned by a random unit
 * quaternion and placed along a random direction, at a random centre distance
 * (0.3 to 1.2 times the summed radii: some overlap), or, every other pair,
 * slid along that direction to a gap of 1e-6 to 1e-1 times that size. Pass: the reference
 * interval [lower, upper] and agjk's [distance - bound, distance] overlap and
 * the relative difference is below 1e-6; overlapping pairs must be
 * `intersecting` (or `contact within tolerance`). Exit status 1 on any miss. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "reference.h"

static uint64_t rng_state;
static uint64_t rng_next(void) {
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rng_uniform(void) { return (double)(rng_next() >> 11) / 9007199254740992.0; }
static double rng_gauss(void) {
    return sqrt(-2.0 * log(rng_uniform() + 1e-300)) * cos(6.283185307179586 * rng_uniform());
}

/* Same convention as the CLI's --pose (Hamilton, scalar first, active). */
static void quaternion_pose(const double q[4], agjk_vec3 t, agjk_pose *p) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    memcpy(p->rotation, r, sizeof r);
    p->translation = t;
}

static int load(const char *dir, int index, mesh_points *p) {
    char path[1024], err[MESH_ERROR_SIZE];
    snprintf(path, sizeof path, "%s/%03d/%03d.obj", dir, index, index);
    return mesh_load(path, p, err, sizeof err);
}

static double radius(const mesh_points *p) {
    double r = 0;
    for (size_t i = 0; i < p->count; i++)
        r = fmax(r, sqrt(p->points[i].x * p->points[i].x + p->points[i].y * p->points[i].y +
                         p->points[i].z * p->points[i].z));
    return r;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: %s AGJK_BINARY MESH_DIR [PAIRS [SEED]]\n", argv[0]);
        return 2;
    }
    int pairs = argc > 3 ? atoi(argv[3]) : 200;
    rng_state = argc > 4 ? strtoull(argv[4], NULL, 10) : 1;
    int done = 0, misses = 0, overlaps = 0, close = 0;
    double worst_rel = 0;
    while (done < pairs) {
        int ia = (int)(rng_next() % 1000), ib = (int)(rng_next() % 1000);
        mesh_points pa, pb;
        if (!load(argv[2], ia, &pa)) continue;
        if (!load(argv[2], ib, &pb)) {
            mesh_points_free(&pa);
            continue;
        }
        double q[4], n = 0;
        for (int k = 0; k < 4; k++) {
            q[k] = rng_gauss();
            n += q[k] * q[k];
        }
        for (int k = 0; k < 4; k++) q[k] /= sqrt(n);
        agjk_vec3 u = {rng_gauss(), rng_gauss(), rng_gauss()};
        double un = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
        double size = radius(&pa) + radius(&pb);
        /* Centre distance: from deep overlap to clear separation. */
        double c = size * (0.3 + 0.9 * rng_uniform());
        agjk_vec3 t = {c * u.x / un, c * u.y / un, c * u.z / un};
        agjk_pose pose_a, pose_b;
        double qi[4] = {1, 0, 0, 0};
        quaternion_pose(qi, (agjk_vec3){0, 0, 0}, &pose_a);
        quaternion_pose(q, t, &pose_b);
        ref_shape ra, rb;
        memset(&ra, 0, sizeof ra);
        memset(&rb, 0, sizeof rb);
        ra.kind = rb.kind = REF_POLYTOPE;
        ra.vertices = pa.points;
        ra.vertex_count = (int)pa.count;
        rb.vertices = pb.points;
        rb.vertex_count = (int)pb.count;
        ref_result ref;
        ref_distance(&ra, &pose_a, &rb, &pose_b, &ref);
        /* Every other pair: slide B along u until the gap is a target of
         * 1e-6 to 1e-1 times the size (Newton steps on the reference
         * distance, whose rate along u is <normal, u>), as the paper's
         * benchmark does for close-proximity cases. */
        if (done % 2 == 1 && !ref.intersecting) {
            double target = size * pow(10.0, -6.0 + 5.0 * rng_uniform());
            for (int it = 0; it < 8 && !ref.intersecting; it++) {
                double gap = (double)ref.distance;
                double rate = (ref.normal.x * u.x + ref.normal.y * u.y + ref.normal.z * u.z) / un;
                if (fabs(gap - target) < 1e-3 * target || rate < 0.05) break;
                c -= (gap - target) / rate;
                t = (agjk_vec3){c * u.x / un, c * u.y / un, c * u.z / un};
                quaternion_pose(q, t, &pose_b);
                ref_distance(&ra, &pose_a, &rb, &pose_b, &ref);
            }
        }
        char cmd[2048];
        snprintf(cmd, sizeof cmd,
                 "%s distance %s/%03d/%03d.obj %s/%03d/%03d.obj --json --pose-b %.17g %.17g "
                 "%.17g %.17g %.17g %.17g %.17g",
                 argv[1], argv[2], ia, ia, argv[2], ib, ib, t.x, t.y, t.z, q[0], q[1], q[2], q[3]);
        FILE *f = popen(cmd, "r");
        char out[4096] = "";
        size_t len = f ? fread(out, 1, sizeof out - 1, f) : 0;
        out[len] = '\0';
        int status = f ? pclose(f) : -1;
        double dist = NAN, bound = NAN;
        char st[64] = "";
        const char *p;
        if ((p = strstr(out, "\"status\": \""))) sscanf(p + 11, "%63[^\"]", st);
        if ((p = strstr(out, "\"distance\": "))) dist = strtod(p + 12, NULL);
        if ((p = strstr(out, "\"bound\": "))) bound = strtod(p + 9, NULL);
        int ok;
        double rel = 0;
        if (ref.intersecting) {
            overlaps++;
            ok = strcmp(st, "intersecting") == 0 || strcmp(st, "contact within tolerance") == 0;
        } else {
            double lo = (double)ref.lower, hi = (double)ref.upper, mid = 0.5 * (lo + hi);
            rel = fabs(dist - mid) / fmax(mid, 1e-300);
            close += mid < 1e-3 * size;
            ok = status == 0 && dist - bound <= hi + 1e-15 * size && dist >= lo - 1e-15 * size &&
                 rel < 1e-6;
            if (rel > worst_rel) worst_rel = rel;
        }
        if (!ok) {
            misses++;
            printf("MISS %03d vs %03d: reference [%.17Lg, %.17Lg]%s, agjk %s %.17g (bound %.3g)\n"
                   "  %s\n", ia, ib, ref.lower, ref.upper, ref.intersecting ? " intersecting" : "",
                   st, dist, bound, cmd);
        }
        done++;
        mesh_points_free(&pa);
        mesh_points_free(&pb);
    }
    printf("check_real_meshes: %d pairs (%d overlapping, %d closer than 1e-3 x size), %d "
           "misses, worst relative difference %.3g\n", done, overlaps, close, misses, worst_rel);
    return misses ? 1 : 0;
}
