/* SPDX-License-Identifier: MIT */
/* libFuzzer target: mesh file -> points -> convex hull -> query, through the
 * tools' mesh library (tools/mesh: assimp + Qhull). The first byte picks the
 * file extension, the rest is the file. Checks: the loader and the hull
 * builder fail cleanly or succeed; a successful hull gives a valid polytope
 * whose hill-climbing support (when the hull is solid) matches the scan
 * support, and queries against it obey every invariant of fz_check_pair. */
#include <unistd.h>

#include "fuzz_decode.h"
#include "mesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The mesh loader imports in a forked child and turns a crash of assimp there
 * into an error (tools/mesh/mesh_isolate.c); several regression inputs crash
 * assimp on purpose. The child inherits AddressSanitizer's signal handlers,
 * which would print a report for each such contained crash: leave these
 * signals to their default action (as `make fuzz` does with ASAN_OPTIONS).
 * Memory errors in instrumented code are still reported, and a crash of this
 * process still fails the replay. Read by the sanitizer runtime at start-up,
 * before ASAN_OPTIONS; unused in builds without AddressSanitizer. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) {
    return "handle_segv=0:handle_sigbus=0:handle_abort=0:handle_sigfpe=0:handle_sigill=0";
}

static const char *const exts[] = {"off", "obj", "stl", "ply", "OFF", "xyz"};

static double dot(const agjk_vec3 *a, const agjk_vec3 *b) {
    return a->x * b->x + a->y * b->y + a->z * b->z;
}

/* Hill climbing over the hull's vertex graph, plain and prepared, must find
 * the scan's maximum. */
static void check_hill_climbing(const mesh_hull *hull) {
    agjk_shape hill, prepared, scan;
    agjk_polytope plain = hull->polytope;
    plain.neighbor_offsets = NULL;
    plain.neighbors = NULL;
    FUZZ_CHECK(agjk_shape_polytope(&hill, &hull->polytope) == AGJK_STATUS_OK, "hull rejected");
    FUZZ_CHECK(agjk_shape_polytope(&scan, &plain) == AGJK_STATUS_OK, "hull points rejected");
    FUZZ_CHECK(agjk_shape_prepared_polytope(&prepared, &hull->prepared) == AGJK_STATUS_OK,
               "prepared hull rejected");
    for (int k = 0; k < 26; k++) {
        agjk_vec3 d = {(double)(k % 3) - 1, (double)((k / 3) % 3) - 1, (double)(k / 9) - 1}, ph, pp,
                  ps;
        int hint_h = k % (hull->vertex_count > 0 ? hull->vertex_count : 1), hint_p = hint_h,
            hint_s = 0;
        if (d.x == 0 && d.y == 0 && d.z == 0) d.z = 0.5;
        hill.support(hill.data, &d, &ph, &hint_h);
        prepared.support(prepared.data, &d, &pp, &hint_p);
        scan.support(scan.data, &d, &ps, &hint_s);
        double vh = dot(&d, &ph), vp = dot(&d, &pp), vs = dot(&d, &ps);
        double scale = fabs(hull->bbox_max.x - hull->bbox_min.x) + fabs(hull->bbox_max.y - hull->bbox_min.y) +
                       fabs(hull->bbox_max.z - hull->bbox_min.z) + fabs(vs);
        FUZZ_CHECK(vh >= vs - 1e-9 * scale, "hill climbing support %.17g < scan %.17g", vh, vs);
        FUZZ_CHECK(vp >= vs - 1e-9 * scale, "prepared climbing support %.17g < scan %.17g", vp, vs);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char path[128], err[MESH_ERROR_SIZE];
    mesh_points pts;
    mesh_hull hull;
    FILE *f;
    if (size < 1) return 0;
    snprintf(path, sizeof path, "/tmp/agjk-fuzz-mesh-%ld.%s", (long)getpid(),
             exts[data[0] % (sizeof exts / sizeof exts[0])]);
    f = fopen(path, "wb");
    if (!f) return 0;
    if (size > 1) fwrite(data + 1, 1, size - 1, f);
    fclose(f);
    memset(&pts, 0, sizeof pts);
    err[0] = '\0';
    if (!mesh_load(path, &pts, err, sizeof err)) {
        FUZZ_CHECK(err[0] != '\0', "mesh_load failed without a message");
        remove(path);
        return 0;
    }
    remove(path);
    FUZZ_CHECK(pts.count > 0 && pts.points != NULL, "mesh_load succeeded with no points");
    for (size_t i = 0; i < pts.count; i++)
        FUZZ_CHECK(isfinite(pts.points[i].x) && isfinite(pts.points[i].y) && isfinite(pts.points[i].z),
                   "mesh_load returned a non-finite point %zu", i);
    memset(&hull, 0, sizeof hull);
    if (mesh_hull_build(pts.points, pts.count, (data[0] / 8) & 1, &hull, err, sizeof err)) {
        agjk_shape s, box;
        agjk_box bx = {{0.5, 0.5, 0.5}};
        agjk_pose pa, pb;
        agjk_options o = agjk_default_options();
        fuzz_reader r = {data, size, size > 16 ? size - 16 : 0};
        FUZZ_CHECK(hull.vertex_count >= 1 && hull.dimension >= 0 && hull.dimension <= 3,
                   "hull with %d vertices, dimension %d", (int)hull.vertex_count, hull.dimension);
        FUZZ_CHECK(agjk_shape_polytope(&s, &hull.polytope) == AGJK_STATUS_OK, "hull polytope rejected");
        FUZZ_CHECK(agjk_shape_box(&box, &bx) == AGJK_STATUS_OK, "box");
        if (hull.polytope.neighbor_offsets) check_hill_climbing(&hull);
        /* Poses from the file's last bytes: deterministic per input. */
        fz_pose(&r, &pa);
        fz_pose(&r, &pb);
        o.max_iterations = 128;
        fz_check_pair(&s, &pa, &box, &pb, &o, 1);
        o.method = AGJK_METHOD_NESTEROV_NORMALIZED;
        fz_check_pair(&s, &pa, &s, &pb, &o, 1);
        /* Two prepared hulls: the pair path, whose cold first support may
         * start from the start vertices. */
        agjk_shape sp;
        FUZZ_CHECK(agjk_shape_prepared_polytope(&sp, &hull.prepared) == AGJK_STATUS_OK,
                   "prepared hull rejected");
        fz_check_pair(&sp, &pa, &sp, &pb, &o, 1);
        mesh_hull_free(&hull);
    } else {
        FUZZ_CHECK(err[0] != '\0', "mesh_hull_build failed without a message");
    }
    mesh_points_free(&pts);
    return 0;
}
