/* SPDX-License-Identifier: MIT */
/* check_real_meshes: `agjk distance --json` with the CLI's default options on
 * pairs of real meshes in random poses, against tests/common's long double
 * reference run on the raw file points (independent of Qhull, of hill
 * climbing and of agjk's solver).
 *
 *   check_real_meshes [AGJK_BINARY MESH_DIR [PAIRS [SEED]]]
 *   make check-real-meshes [REAL_MESH_DIR=out/meshes/random_urdfs] [REAL_MESH_PAIRS=...]
 *
 * Without arguments (make check): 150 pairs on examples/meshes with the agjk
 * binary of the same build tree.
 *
 * Meshes: MESH_DIR/NNN/NNN.obj (the pybullet random_urdfs set that
 * tools/fetch-meshes.sh fetches) when present; otherwise every .off and .obj
 * file directly in MESH_DIR (examples/meshes, or the robot links and household
 * objects of fetch-meshes.sh's pybullet_data directory) plus generated point sets
 * (stiff ellipsoid, thin plate, needle, random cloud, sphere, and boxes with
 * grids of points on their faces, like CAD parts) and the hull files that
 * `agjk hull` writes for them, in a temporary directory. `make check` runs
 * the second form on examples/meshes.
 *
 * For each pair: A at the identity (every other pair: turned too, and both
 * moved 0.1 to 10 times their size away from the origin), B turned by a
 * random unit quaternion (every fourth pair: a rotation with an exact matrix,
 * so that faces parallel in the files stay parallel) and placed along a
 * random direction from A; a quarter of the pairs at a random centre
 * distance (0.3 to 1.2 times the summed radii: many overlap), the others slid
 * (Newton steps on the reference distance) to a gap of 1e-9 to 10 times that
 * size. Checks, each counted:
 * - wrong verdict: agjk says intersecting where the reference certifies
 *   separation, or separated where it certifies overlap;
 * - lower end: distance - bound must not exceed the reference's upper bound;
 * - upper end: the reference's lower bound must not exceed distance plus
 *   rounding, UPPER_SLACK x the problem's size (largest world-frame vertex norm);
 * - not converged: at most 0.1% of the pairs (NOT_CONVERGED_PER_MILLE);
 * - any other exit status (an error) is a failure.
 * Exit status 1 if any check fails. */
#include <dirent.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mesh.h"
#include "reference.h"

/* Rounding allowed above `distance` at the upper end, in units of the problem's size. */
#define UPPER_SLACK (8.0 * DBL_EPSILON)
/* Largest share of `not converged` answers, in pairs per thousand. */
#define NOT_CONVERGED_PER_MILLE 1

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

/* The pose the CLI builds from --pose-b (tools/cli/cli_parse.c): the
 * quaternion divided by its norm, then the Hamilton matrix, same operations in
 * the same order, so that both sides use the same doubles. */
static void cli_pose(const double q_in[4], agjk_vec3 t, agjk_pose *p) {
    double norm = sqrt(q_in[0] * q_in[0] + q_in[1] * q_in[1] + q_in[2] * q_in[2] +
                       q_in[3] * q_in[3]);
    double w = q_in[0] / norm, x = q_in[1] / norm, y = q_in[2] / norm, z = q_in[3] / norm;
    double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    memcpy(p->rotation, r, sizeof r);
    p->translation = t;
}

/* ---- the mesh set ---------------------------------------------------------- */

typedef struct mesh {
    char path[1024];
    int tried, ok;
    mesh_points points;
    double radius; /* largest vertex norm */
} mesh;

static mesh *meshes;
static int mesh_count, mesh_capacity;

static void add_mesh(const char *path) {
    if (mesh_count == mesh_capacity) {
        mesh_capacity = mesh_capacity ? 2 * mesh_capacity : 64;
        meshes = realloc(meshes, (size_t)mesh_capacity * sizeof *meshes);
        if (!meshes) exit(2);
    }
    mesh *m = &meshes[mesh_count++];
    memset(m, 0, sizeof *m);
    snprintf(m->path, sizeof m->path, "%s", path);
}

static int is_file(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int name_cmp(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every .off / .obj file directly in `dir`, sorted (reproducible). */
static void add_dir_files(const char *dir) {
    DIR *d = opendir(dir);
    struct dirent *e;
    char *names[256];
    int n = 0;
    while (d && (e = readdir(d)) && n < 256) {
        size_t len = strlen(e->d_name);
        if (len > 4 && (strcmp(e->d_name + len - 4, ".off") == 0 ||
                        strcmp(e->d_name + len - 4, ".obj") == 0))
            names[n++] = strdup(e->d_name);
    }
    if (d) closedir(d);
    qsort(names, (size_t)n, sizeof *names, name_cmp);
    for (int i = 0; i < n; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        if (is_file(path)) add_mesh(path);
        free(names[i]);
    }
}

/* Point sets that real parts resemble, written as OBJ, and their hulls as
 * `agjk hull` writes them. */
static void add_generated(const char *agjk, const char *dir) {
    static const struct {
        const char *name;
        int count;
        double axes[3];
        int surface, grid;
    } sets[] = {{"ellipsoid-stiff", 400, {1, 0.3, 0.05}, 1, 0},
                {"plate", 300, {1, 1, 0.001}, 0, 0},
                {"needle", 200, {2, 0.01, 0.01}, 0, 0},
                {"cloud", 60, {0.5, 0.7, 0.4}, 0, 0},
                {"sphere", 800, {1, 1, 1}, 1, 0},
                {"box-grid", 0, {1, 0.6, 0.3}, 0, 6},
                {"slab-grid", 0, {2, 2, 0.05}, 0, 4}};
    for (size_t s = 0; s < sizeof sets / sizeof sets[0]; s++) {
        char path[1024], hull[1024], cmd[3200];
        snprintf(path, sizeof path, "%s/%s.obj", dir, sets[s].name);
        FILE *f = fopen(path, "w");
        if (!f) continue;
        for (int i = 0; i < sets[s].count; i++) {
            double p[3], n = 0;
            for (int k = 0; k < 3; k++) {
                p[k] = sets[s].surface ? rng_gauss() : 2 * rng_uniform() - 1;
                n += p[k] * p[k];
            }
            for (int k = 0; k < 3; k++)
                p[k] = (sets[s].surface ? p[k] / sqrt(n) : p[k]) * sets[s].axes[k] + 0.1 * k;
            fprintf(f, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
        }
        if (sets[s].grid) {
            /* CAD-like: a box whose faces are planar grids of points, so its
             * hull has large faces made of many coplanar triangles. */
            const double *h = sets[s].axes;
            int g = sets[s].grid;
            for (int i = 0; i <= g; i++)
                for (int j = 0; j <= g; j++)
                    for (int k = 0; k <= g; k++) {
                        if (i % g && j % g && k % g) continue; /* interior */
                        fprintf(f, "v %.17g %.17g %.17g\n", h[0] * (2.0 * i / g - 1),
                                h[1] * (2.0 * j / g - 1), h[2] * (2.0 * k / g - 1));
                    }
        }
        fclose(f);
        add_mesh(path);
        snprintf(hull, sizeof hull, "%s/%s-hull.off", dir, sets[s].name);
        snprintf(cmd, sizeof cmd, "'%s' hull '%s' -o '%s' 2>/dev/null", agjk, path, hull);
        if (system(cmd) == 0) add_mesh(hull);
    }
}

static mesh *get_mesh(int i) {
    mesh *m = &meshes[i];
    if (!m->tried) {
        char err[MESH_ERROR_SIZE];
        m->tried = 1;
        m->ok = mesh_load(m->path, &m->points, err, sizeof err);
        if (!m->ok) printf("skipped (cannot load): %s\n", err);
        for (size_t k = 0; m->ok && k < m->points.count; k++) {
            const agjk_vec3 *v = &m->points.points[k];
            m->radius = fmax(m->radius, sqrt(v->x * v->x + v->y * v->y + v->z * v->z));
        }
    }
    return m->ok ? m : NULL;
}

/* ---- one pair ---------------------------------------------------------------- */

typedef struct tally {
    int pairs, overlapping, separated_ref, errors, wrong_verdicts, lower_misses, upper_misses;
    int not_converged, status_separated, status_intersecting, status_contact;
    double worst_upper_excess; /* (reference lower - distance) / size, worst */
    double worst_bound;        /* bound / size, worst over separated answers */
} tally;

static void run_pair(const char *agjk, int ia, int ib, int pair, tally *t) {
    mesh *a = get_mesh(ia), *b = get_mesh(ib);
    if (!a || !b) return;
    double q[4], qa[4] = {1, 0, 0, 0}, n = 0, na = 0;
    agjk_vec3 lateral = {0, 0, 0};
    for (int k = 0; k < 4; k++) {
        q[k] = rng_gauss();
        n += q[k] * q[k];
    }
    for (int k = 0; k < 4; k++) q[k] /= sqrt(n);
    /* Every fourth pair, B is turned by one of the 12 rotations whose matrix
     * is exact (identity, half turns about the axes, third turns about the
     * diagonals), so that faces parallel in the files stay exactly parallel,
     * as parts placed side by side in a scene are. */
    int exact = pair % 4 == 2;
    if (exact) {
        int r = (int)(rng_next() % 12);
        for (int k = 0; k < 4; k++) q[k] = 0;
        if (r < 4) {
            q[r] = 1;
        } else {
            q[0] = 0.5;
            for (int k = 1; k < 4; k++) q[k] = ((r - 4) >> (k - 1)) & 1 ? -0.5 : 0.5;
        }
    }
    /* Every other pair, A is turned too and both are placed away from the
     * origin (by 0.1 to 10 times their size), as parts in a scene are. */
    int general = pair % 2 == 1;
    for (int k = 0; general && k < 4; k++) {
        qa[k] = rng_gauss();
        na += qa[k] * qa[k];
    }
    for (int k = 0; general && k < 4; k++) qa[k] /= sqrt(na);
    agjk_vec3 u = {rng_gauss(), rng_gauss(), rng_gauss()};
    double size = a->radius + b->radius;
    if (!(size > 0)) size = 1;
    if (exact) {
        /* ... and B is moved along a coordinate axis, with a sideways offset
         * of up to half the size: faces meet face to face. */
        int axis = (int)(rng_next() % 3);
        double side[3] = {rng_uniform() - 0.5, rng_uniform() - 0.5, rng_uniform() - 0.5};
        side[axis] = 0;
        u = (agjk_vec3){axis == 0, axis == 1, axis == 2};
        lateral = (agjk_vec3){side[0] * size, side[1] * size, side[2] * size};
    }
    double un = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    int slide = pair % 4 != 0;
    /* Centre distance: from deep overlap to clear separation; slid pairs
     * start clear of each other (bounding spheres about the origins). */
    double c = slide ? 1.05 * size : size * (0.3 + 0.9 * rng_uniform());
    double target = size * pow(10.0, -9.0 + 10.0 * rng_uniform());
    agjk_vec3 o = {0, 0, 0};
    if (general) {
        agjk_vec3 v = {rng_gauss(), rng_gauss(), rng_gauss()};
        double vn = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        double m = size * pow(10.0, -1.0 + 2.0 * rng_uniform()) / vn;
        o = (agjk_vec3){m * v.x, m * v.y, m * v.z};
    }
    agjk_vec3 base = {o.x + lateral.x, o.y + lateral.y, o.z + lateral.z}; /* B before the slide */
    agjk_vec3 tr = {base.x + c * u.x / un, base.y + c * u.y / un, base.z + c * u.z / un};
    agjk_pose pose_a, pose_b;
    cli_pose(qa, o, &pose_a);
    cli_pose(q, tr, &pose_b);
    ref_shape ra, rb;
    memset(&ra, 0, sizeof ra);
    memset(&rb, 0, sizeof rb);
    ra.kind = rb.kind = REF_POLYTOPE;
    ra.vertices = a->points.points;
    ra.vertex_count = (int)a->points.count;
    rb.vertices = b->points.points;
    rb.vertex_count = (int)b->points.count;
    ref_result ref;
    ref_distance(&ra, &pose_a, &rb, &pose_b, &ref);
    /* Slide B along u to the target gap; the distance's rate along u is
     * <normal, u> (as the paper's benchmark does for close-proximity cases). */
    for (int it = 0; slide && it < 12 && !ref.intersecting; it++) {
        double gap = (double)ref.distance;
        double rate = (ref.normal.x * u.x + ref.normal.y * u.y + ref.normal.z * u.z) / un;
        if (fabs(gap - target) < 1e-3 * target || rate < 0.05) break;
        c -= (gap - target) / rate;
        tr = (agjk_vec3){base.x + c * u.x / un, base.y + c * u.y / un, base.z + c * u.z / un};
        cli_pose(q, tr, &pose_b);
        ref_distance(&ra, &pose_a, &rb, &pose_b, &ref);
    }
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "'%s' distance '%s' '%s' --json --pose-a %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
             "--pose-b %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
             agjk, a->path, b->path, o.x, o.y, o.z, qa[0], qa[1], qa[2], qa[3], tr.x, tr.y, tr.z,
             q[0], q[1], q[2], q[3]);
    FILE *f = popen(cmd, "r");
    char out[4096] = "";
    size_t len = f ? fread(out, 1, sizeof out - 1, f) : 0;
    out[len] = '\0';
    int status = f ? pclose(f) : -1;
    int code = (status >= 0 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    double dist = NAN, bound = NAN;
    char st[64] = "";
    const char *p;
    if ((p = strstr(out, "\"status\": \""))) sscanf(p + 11, "%63[^\"]", st);
    if ((p = strstr(out, "\"distance\": "))) dist = strtod(p + 12, NULL);
    if ((p = strstr(out, "\"bound\": "))) bound = strtod(p + 9, NULL);
    /* The problem's size: largest world-frame vertex norm. */
    double tn = sqrt(tr.x * tr.x + tr.y * tr.y + tr.z * tr.z);
    double on = sqrt(o.x * o.x + o.y * o.y + o.z * o.z);
    double scale = fmax(on + a->radius, tn + b->radius);
    const char *why = NULL;
    t->pairs++;
    t->overlapping += ref.intersecting;
    t->separated_ref += !ref.intersecting && ref.lower > 0;
    if (code == 3 || strcmp(st, "not converged") == 0) {
        t->not_converged++;
        why = "not converged";
    }
    if (strcmp(st, "separated") == 0) t->status_separated++;
    if (strcmp(st, "intersecting") == 0) t->status_intersecting++;
    if (strcmp(st, "contact within tolerance") == 0) t->status_contact++;
    if ((code != 0 && code != 3) || !st[0] || (!isfinite(dist) && strcmp(st, "intersecting"))) {
        t->errors++;
        why = "error";
    } else if (strcmp(st, "intersecting") == 0 && !ref.intersecting && ref.lower > 0) {
        t->wrong_verdicts++;
        why = "wrong verdict: intersecting, reference certifies separation";
    } else if (strcmp(st, "separated") == 0 && ref.intersecting) {
        t->wrong_verdicts++;
        why = "wrong verdict: separated, reference certifies overlap";
    } else if (!ref.intersecting && strcmp(st, "intersecting") != 0) {
        /* Both ends of [distance - bound, distance + rounding]. */
        double excess = ((double)ref.lower - dist) / scale;
        if (excess > t->worst_upper_excess) t->worst_upper_excess = excess;
        if (dist - bound > (double)ref.upper) {
            t->lower_misses++;
            why = "lower end: distance - bound above the reference's upper bound";
        } else if (excess > UPPER_SLACK) {
            t->upper_misses++;
            why = "upper end: reference's lower bound above distance + rounding";
        }
        if (strcmp(st, "separated") == 0 && bound / scale > t->worst_bound)
            t->worst_bound = bound / scale;
    }
    if (why)
        printf("%s: %s vs %s: reference [%.17Lg, %.17Lg]%s, agjk %s %.17g (bound %.3g, exit "
               "%d), size %.3g\n  %s\n",
               why, a->path, b->path, ref.lower, ref.upper,
               ref.intersecting ? " intersecting" : "", st[0] ? st : "(no answer)", dist, bound,
               code, scale, cmd);
}

int main(int argc, char **argv) {
    /* No arguments (make check): the agjk binary of this build tree
     * ($(OUT)/tests/cli/.. -> $(OUT)/tools/cli/agjk) and examples/meshes. */
    char own[1024];
    snprintf(own, sizeof own, "%s", argv[0]);
    char *slash = strrchr(own, '/');
    if (slash) *slash = '\0';
    char default_agjk[1100];
    snprintf(default_agjk, sizeof default_agjk, "%s/../../tools/cli/agjk", slash ? own : ".");
    if (argc == 2 || (argc > 1 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: %s [AGJK_BINARY MESH_DIR [PAIRS [SEED]]]\n", argv[0]);
        return 2;
    }
    const char *agjk = argc > 2 ? argv[1] : default_agjk;
    const char *dir = argc > 2 ? argv[2] : "examples/meshes";
    int pairs = argc > 3 ? atoi(argv[3]) : 150;
    rng_state = argc > 4 ? strtoull(argv[4], NULL, 10) : 1;
    char tmpdir[] = "/tmp/agjk-real-meshes.XXXXXX";
    int generated = 0;
    for (int i = 0; i < 1000; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%03d/%03d.obj", dir, i, i);
        if (is_file(path)) add_mesh(path);
    }
    const char *set = "pybullet random_urdfs";
    if (mesh_count == 0) {
        add_dir_files(dir);
        if (mkdtemp(tmpdir)) {
            generated = 1;
            add_generated(agjk, tmpdir);
        }
        set = "the directory's files and generated point sets";
    }
    if (mesh_count == 0) {
        fprintf(stderr, "check_real_meshes: no meshes under %s\n", dir);
        return 2;
    }
    tally t;
    memset(&t, 0, sizeof t);
    for (int attempts = 0; t.pairs < pairs && attempts < 4 * pairs + 100; attempts++) {
        int ia = (int)(rng_next() % (uint64_t)mesh_count);
        int ib = (int)(rng_next() % (uint64_t)mesh_count);
        run_pair(agjk, ia, ib, t.pairs, &t);
    }
    int nc_fail = t.not_converged * 1000 > NOT_CONVERGED_PER_MILLE * t.pairs;
    printf("check_real_meshes: %d pairs of %d meshes (%s): reference: %d overlapping, %d "
           "certified separated; agjk: %d separated, %d intersecting, %d contact within "
           "tolerance, %d not converged (%.2f%%, limit %.1f%%)%s\n",
           t.pairs, mesh_count, set, t.overlapping, t.separated_ref, t.status_separated,
           t.status_intersecting, t.status_contact, t.not_converged,
           t.pairs ? 100.0 * t.not_converged / t.pairs : 0.0, NOT_CONVERGED_PER_MILLE / 10.0,
           nc_fail ? ": TOO MANY" : "");
    printf("check_real_meshes: %d wrong verdicts, %d errors; interval misses: %d at the lower "
           "end, %d at the upper end (worst excess %.3g x size = %.2f eps, allowed %.0f eps); "
           "worst bound of a separated answer %.3g x size\n",
           t.wrong_verdicts, t.errors, t.lower_misses, t.upper_misses, t.worst_upper_excess,
           t.worst_upper_excess / DBL_EPSILON, UPPER_SLACK / DBL_EPSILON, t.worst_bound);
    if (generated) {
        for (int i = 0; i < mesh_count; i++)
            if (strncmp(meshes[i].path, tmpdir, strlen(tmpdir)) == 0) remove(meshes[i].path);
        rmdir(tmpdir);
    }
    for (int i = 0; i < mesh_count; i++)
        if (meshes[i].ok) mesh_points_free(&meshes[i].points);
    free(meshes);
    int fail = t.pairs < pairs || t.errors || t.wrong_verdicts || t.lower_misses ||
               t.upper_misses || nc_fail;
    return fail ? 1 : 0;
}
