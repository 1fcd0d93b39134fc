/* SPDX-License-Identifier: MIT */
/* Double-precision coordinates for ASCII PLY files.
 *
 * assimp (as packaged) stores positions as float: a coordinate of 100 loses
 * about 4e-6, which for parts 0.01 apart is a 4e-4 relative distance error
 * that no solver tolerance can recover. ASCII PLY is text, so we re-read its
 * vertex records with strtod (correctly rounded) and put the doubles back in
 * place of assimp's floats (OFF and OBJ have their own reader, mesh_text.c).
 * A coordinate the header declares `float` is rounded to float: the file says
 * that is its precision, and the precision report says so.
 *
 * assimp stays the authority on what the file means (which vertices, which
 * meshes, whether it parses at all); we only upgrade precision: each float
 * point of assimp is looked up among the file's vertices rounded to float
 * (exactly, or within one float ulp per coordinate, since assimp's fast_atof
 * is not always correctly rounded). If any point finds no match, or the
 * file's layout is beyond this small reader, nothing is changed.
 * Several file vertices may round to the same float point: all of them are
 * kept, so the point set is a superset of assimp's, never missing a vertex. */
#include "mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A file vertex: its double coordinates and their float rounding. */
typedef struct fvert {
    float key[3];
    agjk_vec3 p;
} fvert;

typedef struct fvert_list {
    fvert *v;
    size_t count, capacity;
    long nonfinite; /* index of the first non-finite vertex, or -1 */
    int float_overflow; /* that vertex is finite in the text, beyond float as declared */
} fvert_list;

static int list_push(fvert_list *l, const double c[3]) {
    if (l->count == l->capacity) {
        size_t cap = l->capacity ? 2 * l->capacity : 1024;
        fvert *n = realloc(l->v, cap * sizeof *n);
        if (!n) return 0;
        l->v = n;
        l->capacity = cap;
    }
    if ((!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2])) && l->nonfinite < 0)
        l->nonfinite = (long)l->count;
    fvert *f = &l->v[l->count++];
    f->p.x = c[0];
    f->p.y = c[1];
    f->p.z = c[2];
    for (int k = 0; k < 3; k++) f->key[k] = (float)c[k];
    return 1;
}

/* ASCII PLY: the vertex element's x, y, z properties, one vertex per line.
 * A coordinate declared `float` is rounded to float (the file says that is
 * its precision, and readers that honour the header agree); `double` keeps
 * the double. Elements before the vertices (rare) take one line per item.
 * Binary PLY stores binary floats or doubles, which assimp keeps exactly for
 * floats; we decline it (and a property list before x, y, z). */
static int read_ply(FILE *f, fvert_list *l, int *declared_float) {
    char line[4096];
    long skip_lines = 0, count = -1;
    int in_vertex = 0, nprop = 0, axis_prop[3] = {-1, -1, -1}, axis_float[3] = {0, 0, 0};
    int ascii = 0;
    while (fgets(line, sizeof line, f)) {
        char a[64] = "", b[64] = "", c[64] = "";
        int n = sscanf(line, "%63s %63s %63s", a, b, c);
        if (n >= 1 && strcmp(a, "end_header") == 0) break;
        if (n >= 2 && strcmp(a, "format") == 0) ascii = strcmp(b, "ascii") == 0;
        if (n >= 3 && strcmp(a, "element") == 0) {
            if (count >= 0) in_vertex = 0; /* vertices done: later elements do not matter */
            else if (strcmp(b, "vertex") == 0) {
                in_vertex = 1;
                count = strtol(c, NULL, 10);
            } else {
                skip_lines += strtol(c, NULL, 10);
            }
        }
        if (n >= 3 && strcmp(a, "property") == 0 && in_vertex) {
            if (strcmp(b, "list") == 0) return 0;
            for (int k = 0; k < 3; k++)
                if (strcmp(c, (const char *[]){"x", "y", "z"}[k]) == 0) {
                    axis_prop[k] = nprop;
                    axis_float[k] = strcmp(b, "float") == 0 || strcmp(b, "float32") == 0;
                }
            nprop++;
        }
    }
    *declared_float = axis_float[0] || axis_float[1] || axis_float[2];
    if (!ascii || count < 0 || count > 1000000000L || skip_lines < 0 || axis_prop[0] < 0 ||
        axis_prop[1] < 0 || axis_prop[2] < 0)
        return 0;
    for (long i = 0; i < skip_lines; i++)
        if (!fgets(line, sizeof line, f)) return 0;
    while ((long)l->count < count && fgets(line, sizeof line, f)) {
        double v[64], c3[3];
        int n = 0;
        const char *s = line;
        char *end;
        while (n < nprop && n < 64) {
            v[n] = strtod(s, &end);
            if (end == s) break;
            s = end;
            n++;
        }
        if (n < nprop && n < 64) return 0;
        int text_finite = 1;
        for (int k = 0; k < 3; k++) {
            if (axis_prop[k] >= 64) return 0;
            text_finite = text_finite && isfinite(v[axis_prop[k]]);
            c3[k] = axis_float[k] ? (double)(float)v[axis_prop[k]] : v[axis_prop[k]];
        }
        long before = l->nonfinite;
        if (!list_push(l, c3)) return 0;
        if (before < 0 && l->nonfinite >= 0) l->float_overflow = text_finite;
    }
    return (long)l->count == count;
}

/* Order of float triples, exact (total for finite keys). */
static int key_cmp(const float a[3], const float b[3]) {
    for (int k = 0; k < 3; k++) {
        if (a[k] < b[k]) return -1;
        if (a[k] > b[k]) return 1;
    }
    return 0;
}

static int fvert_cmp(const void *a, const void *b) {
    return key_cmp(((const fvert *)a)->key, ((const fvert *)b)->key);
}

/* First index of `key` in the sorted list, or -1. */
static long find_key(const fvert_list *l, const float key[3]) {
    size_t lo = 0, hi = l->count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (key_cmp(l->v[mid].key, key) < 0) lo = mid + 1;
        else hi = mid;
    }
    return (lo < l->count && key_cmp(l->v[lo].key, key) == 0) ? (long)lo : -1;
}

/* Exact match first, then the 26 neighbours one float ulp away. */
static long find_near(const fvert_list *l, const agjk_vec3 *p) {
    const float base[3] = {(float)p->x, (float)p->y, (float)p->z};
    long hit = find_key(l, base);
    for (int m = 0; hit < 0 && m < 27; m++) {
        float key[3];
        int step[3] = {m % 3 - 1, (m / 3) % 3 - 1, m / 9 - 1};
        for (int k = 0; k < 3; k++)
            key[k] = step[k] == 0 ? base[k]
                                  : nextafterf(base[k], step[k] > 0 ? INFINITY : -INFINITY);
        hit = find_key(l, key);
    }
    return hit;
}

/* Replaces every point by its double-precision file vertex (or vertices). */
static int substitute(const fvert_list *l, mesh_points *points) {
    unsigned char *used = calloc(l->count ? l->count : 1, 1);
    agjk_vec3 *out = malloc((l->count ? l->count : 1) * sizeof *out);
    size_t n = 0;
    int ok = used && out;
    for (size_t i = 0; ok && i < points->count; i++) {
        long h = find_near(l, &points->points[i]);
        if (h < 0) ok = 0;
        /* Take the whole run of file vertices with this float key once. */
        for (size_t j = (size_t)h; ok && j < l->count && !used[j] &&
                                   key_cmp(l->v[j].key, l->v[h].key) == 0; j++) {
            used[j] = 1;
            out[n++] = l->v[j].p;
        }
    }
    free(used);
    if (!ok) {
        free(out);
        return 0;
    }
    free(points->points);
    points->points = out;
    points->count = n;
    return 1;
}

int mesh_refine_double(const char *path, const char *format, mesh_points *points,
                       long *nonfinite_vertex) {
    *nonfinite_vertex = -1;
    if (strcmp(format, "ply") != 0) return 0;
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    fvert_list l = {NULL, 0, 0, -1, 0};
    int declared_float = 0;
    int ok = read_ply(f, &l, &declared_float);
    fclose(f);
    if (l.nonfinite >= 0) {
        *nonfinite_vertex = l.nonfinite;
        ok = l.float_overflow ? -2 : -1;
    } else if (ok && l.count > 0) { /* no vertex read: nothing to match (and no qsort(NULL)) */
        qsort(l.v, l.count, sizeof *l.v, fvert_cmp);
        ok = substitute(&l, points);
        if (ok) {
            points->double_precision = !declared_float;
            snprintf(points->precision_note, sizeof points->precision_note, "%s",
                     declared_float ? "float (the PLY header declares float coordinates)"
                                    : "double (re-read from the text, declared double)");
        }
    } else {
        ok = 0;
    }
    free(l.v);
    return ok;
}
