/* SPDX-License-Identifier: MIT */
/* Mesh loading: OFF and OBJ by our strict reader (mesh_text.c), every other
 * format through assimp's C API.
 *
 * From assimp we keep only positions: a convex shape is the hull of every
 * vertex of every mesh in the scene, each mapped to the root frame by the
 * product of the node transforms above it (computed in double). Faces, normals and materials are
 * ignored, so point clouds and line-only files load too.
 *
 * assimp is a large C++ parser fed untrusted files, so we check what we can
 * before handing it the file (exists, is a regular file, readable, not empty)
 * and check everything it returns (finite vertices, sane counts). It logs
 * nothing unless a logger is attached, and we attach none: output stays clean. */
#include "mesh.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void set_error(char *err, size_t err_size, const char *fmt, ...) {
    va_list ap;
    if (!err || err_size == 0) return;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
}

/* Row-major 4x4 affine transform in double. */
typedef struct xform {
    double m[3][4];
} xform;

static xform xform_identity(void) {
    xform t;
    memset(&t, 0, sizeof t);
    t.m[0][0] = t.m[1][1] = t.m[2][2] = 1.0;
    return t;
}

/* parent * child, both affine (assimp's aiMatrix4x4 is row-major with the
 * translation in the fourth column: p' = M p). */
static xform xform_mul(const xform *p, const struct aiMatrix4x4 *c) {
    const double cm[4][4] = {{c->a1, c->a2, c->a3, c->a4},
                             {c->b1, c->b2, c->b3, c->b4},
                             {c->c1, c->c2, c->c3, c->c4},
                             {c->d1, c->d2, c->d3, c->d4}};
    xform r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double s = (j == 3) ? p->m[i][3] : 0.0;
            for (int k = 0; k < 3; k++) s += p->m[i][k] * cm[k][j];
            r.m[i][j] = s;
        }
    return r;
}

static int xform_is_identity(const xform *t) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (t->m[i][j] != (i == j ? 1.0 : 0.0)) return 0;
    return 1;
}

/* State of the walk over the node tree. */
typedef struct walk {
    const struct aiScene *scene;
    mesh_points *out;
    size_t capacity;
    unsigned char *mesh_seen;
    int all_identity;
} walk;

static int append_mesh(walk *w, const struct aiMesh *mesh, const xform *t) {
    size_t need = w->out->count + mesh->mNumVertices;
    if (need > w->capacity) {
        size_t cap = w->capacity ? w->capacity : 1024;
        while (cap < need) cap *= 2;
        agjk_vec3 *p = realloc(w->out->points, cap * sizeof *p);
        if (!p) return 0;
        w->out->points = p;
        w->capacity = cap;
    }
    for (unsigned v = 0; v < mesh->mNumVertices; v++) {
        const struct aiVector3D *s = &mesh->mVertices[v];
        double x = s->x, y = s->y, z = s->z;
        agjk_vec3 *d = &w->out->points[w->out->count++];
        d->x = t->m[0][0] * x + t->m[0][1] * y + t->m[0][2] * z + t->m[0][3];
        d->y = t->m[1][0] * x + t->m[1][1] * y + t->m[1][2] * z + t->m[1][3];
        d->z = t->m[2][0] * x + t->m[2][1] * y + t->m[2][2] * z + t->m[2][3];
    }
    w->out->mesh_count++;
    w->out->face_count += mesh->mNumFaces;
    return 1;
}

/* Depth-first over the node tree. `depth` guards against malformed scenes
 * with absurdly deep (or, in a broken file, cyclic) hierarchies. */
static int walk_node(walk *w, const struct aiNode *node, const xform *parent, int depth) {
    if (!node || depth > 256) return 1;
    xform t = xform_mul(parent, &node->mTransformation);
    if (!xform_is_identity(&t)) w->all_identity = 0;
    for (unsigned i = 0; i < node->mNumMeshes; i++) {
        unsigned id = node->mMeshes[i];
        if (id >= w->scene->mNumMeshes || !w->scene->mMeshes[id]) continue;
        w->mesh_seen[id] = 1;
        if (!append_mesh(w, w->scene->mMeshes[id], &t)) return 0;
    }
    for (unsigned i = 0; i < node->mNumChildren; i++)
        if (!walk_node(w, node->mChildren[i], &t, depth + 1)) return 0;
    return 1;
}

/* assimp 5.2 loops forever on a PLY whose header never ends: require the
 * end_header line within the first 64 KiB (real headers take a few hundred
 * bytes), as a line of its own. */
static int ply_header_ends(const char *path) {
    enum { HEAD = 65536 };
    char *buf = malloc(HEAD);
    FILE *f = fopen(path, "rb");
    if (!f || !buf) {
        if (f) fclose(f);
        free(buf);
        return 1; /* cannot check: let assimp judge */
    }
    size_t n = fread(buf, 1, HEAD, f);
    fclose(f);
    int found = 0;
    for (size_t i = 0; !found && i + 10 <= n; i++)
        found = (i == 0 || buf[i - 1] == '\n') && memcmp(buf + i, "end_header", 10) == 0 &&
                (i + 10 == n || buf[i + 10] == '\n' || buf[i + 10] == '\r' || buf[i + 10] == ' ');
    free(buf);
    return found;
}

/* assimp's messages may quote kilobytes of the file, newlines and binary bytes
 * included: keep one printable line of bounded length. */
static void clean_message(const char *msg, char *out, size_t size) {
    size_t n = 0;
    for (; msg && *msg && n + 1 < size; msg++) {
        unsigned char c = (unsigned char)*msg;
        out[n++] = (c < 0x20 || c == 0x7f) ? ' ' : (char)c;
    }
    out[n] = '\0';
    if (msg && *msg && size > 4) memcpy(out + size - 4, "...", 4);
}

/* Checks the file before assimp sees it, for precise messages. */
static int precheck_file(const char *path, const char *format, char *err, size_t err_size) {
    struct stat st;
    if (stat(path, &st) != 0) {
        set_error(err, err_size, "%s: %s", path, strerror(errno));
        return 0;
    }
    if (!S_ISREG(st.st_mode)) {
        set_error(err, err_size, "%s: not a regular file", path);
        return 0;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        set_error(err, err_size, "%s: %s", path, strerror(errno));
        return 0;
    }
    int c = fgetc(f);
    fclose(f);
    if (c == EOF) {
        set_error(err, err_size, "%s: empty file", path);
        return 0;
    }
    if (strcmp(format, "ply") == 0 && !ply_header_ends(path)) {
        set_error(err, err_size, "%s: PLY header without end_header (truncated or malformed)",
                  path);
        return 0;
    }
    return 1;
}

static void file_extension(const char *path, char *ext, size_t size) {
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    ext[0] = '\0';
    if (!dot) return;
    size_t i = 0;
    for (const char *s = dot + 1; *s && i + 1 < size; s++, i++)
        ext[i] = (char)((*s >= 'A' && *s <= 'Z') ? *s - 'A' + 'a' : *s);
    ext[i] = '\0';
}

static int check_finite(const char *path, const mesh_points *p, char *err, size_t err_size) {
    for (size_t i = 0; i < p->count; i++) {
        const agjk_vec3 *v = &p->points[i];
        if (!isfinite(v->x) || !isfinite(v->y) || !isfinite(v->z)) {
            set_error(err, err_size, "%s: vertex %zu is not finite as assimp reads it (NaN, Inf, "
                      "or beyond the single-precision range 3.4e38)", path, i);
            return 0;
        }
    }
    return 1;
}

/* Collects the scene's vertices into `out`; on success out->count > 0. */
static int collect_scene(const char *path, const struct aiScene *scene, mesh_points *out,
                         int *all_identity, char *err, size_t err_size) {
    walk w;
    memset(&w, 0, sizeof w);
    w.scene = scene;
    w.out = out;
    w.all_identity = 1;
    w.mesh_seen = calloc(scene->mNumMeshes ? scene->mNumMeshes : 1, 1);
    xform id = xform_identity();
    int ok = w.mesh_seen && walk_node(&w, scene->mRootNode, &id, 0);
    /* Meshes no node refers to (some importers leave them so): take them as is. */
    for (unsigned i = 0; ok && i < scene->mNumMeshes; i++)
        if (!w.mesh_seen[i] && scene->mMeshes[i]) ok = append_mesh(&w, scene->mMeshes[i], &id);
    free(w.mesh_seen);
    *all_identity = w.all_identity;
    if (!ok) {
        set_error(err, err_size, "%s: out of memory", path);
        return 0;
    }
    if (out->count == 0) {
        set_error(err, err_size, "%s: no vertices (empty mesh)", path);
        return 0;
    }
    return 1;
}

int mesh_load_in_process(const char *path, mesh_points *out, char *err, size_t err_size) {
    memset(out, 0, sizeof *out);
    file_extension(path, out->format, sizeof out->format);
    if (!precheck_file(path, out->format, err, err_size)) return 0;
    if (strcmp(out->format, "off") == 0 || strcmp(out->format, "obj") == 0) {
        if (!mesh_read_text(path, out->format, out, err, err_size)) return 0;
        snprintf(out->precision_note, sizeof out->precision_note, "%s",
                 "double (every coordinate read from the text by strtod)");
        return 1;
    }
    /* JoinIdenticalVertices only shrinks the set; no triangulation or other
     * processing (it could drop point and line primitives). */
    const struct aiScene *scene = aiImportFile(path, aiProcess_JoinIdenticalVertices);
    if (!scene) {
        char why[160];
        clean_message(aiGetErrorString(), why, sizeof why);
        set_error(err, err_size, "%s: cannot read mesh: %s", path,
                  why[0] ? why : "unknown format or malformed file");
        return 0;
    }
    int all_identity = 1;
    int ok = scene->mNumMeshes > 0 && scene->mMeshes;
    if (!ok) set_error(err, err_size, "%s: no meshes in file (empty mesh)", path);
    if (ok) ok = collect_scene(path, scene, out, &all_identity, err, err_size);
    aiReleaseImport(scene);
    snprintf(out->precision_note, sizeof out->precision_note, "%s",
             "float (as assimp stores it)");
    /* ASCII PLY: the vertex records as text, in double (assimp stores
     * floats). Only when no transform moved the points (PLY has none). */
    if (ok && all_identity && mesh_refine_double(path, out->format, out, err, err_size) < 0)
        ok = 0;
    if (ok) ok = check_finite(path, out, err, err_size);
    if (!ok) mesh_points_free(out);
    return ok;
}

void mesh_points_free(mesh_points *points) {
    if (!points) return;
    free(points->points);
    points->points = NULL;
    points->count = 0;
}
