/* SPDX-License-Identifier: MIT */
/* ASCII PLY vertices read as text.
 *
 * assimp (as packaged) stores positions as float, and its fast number parser
 * is not always right (a 21-digit integer becomes 0, a 4,100-digit number a
 * value that is not in the file). ASCII PLY is text, so after assimp has
 * accepted the file (it stays the judge of faces and of the header's other
 * elements) we read the vertex element ourselves and the points become every
 * vertex record of the file, converted by mesh_parse_coordinate() (strict
 * syntax, strtod). A coordinate the header declares `float` is rounded to
 * float: the file says that is its precision, and the precision report says
 * so. Elements before the vertices (rare) take one line per item, as ASCII
 * PLY writes them. A vertex element with a list property, or a binary file,
 * is declined: assimp's floats are then kept, and reported as such. */
#include "mesh.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

typedef struct ply_reader {
    const char *path;
    FILE *f;
    char *line;
    size_t line_size;
    long line_no;
    char *err;
    size_t err_size;
} ply_reader;

static int next(ply_reader *r) {
    if (getline(&r->line, &r->line_size, r->f) < 0) return 0;
    r->line_no++;
    return 1;
}

static int fail(ply_reader *r, const char *fmt, ...) {
    va_list ap;
    int n = snprintf(r->err, r->err_size, "%s:%ld: ", r->path, r->line_no);
    if (n >= 0 && (size_t)n < r->err_size) {
        va_start(ap, fmt);
        vsnprintf(r->err + n, r->err_size - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* The header's vertex element: how many lines precede it, its count, its
 * scalar properties and where x, y, z are among them. */
typedef struct ply_layout {
    long skip_lines, count;
    int nprop, axis_prop[3], axis_float[3];
} ply_layout;

/* 1: an ASCII PLY header this reader handles; 0: decline. */
static int read_header(ply_reader *r, ply_layout *h) {
    int in_vertex = 0, ascii = 0, ended = 0;
    memset(h, 0, sizeof *h);
    h->count = -1;
    for (int k = 0; k < 3; k++) h->axis_prop[k] = -1;
    while (!ended && next(r)) {
        char a[64] = "", b[64] = "", c[64] = "";
        int n = sscanf(r->line, "%63s %63s %63s", a, b, c);
        if (n >= 1 && strcmp(a, "end_header") == 0) ended = 1;
        if (n >= 2 && strcmp(a, "format") == 0) ascii = strcmp(b, "ascii") == 0;
        if (n >= 3 && strcmp(a, "element") == 0) {
            long items = strtol(c, NULL, 10);
            if (h->count >= 0) in_vertex = 0; /* vertices done: later elements do not matter */
            else if (strcmp(b, "vertex") == 0) {
                in_vertex = 1;
                h->count = items;
            } else {
                h->skip_lines += items;
            }
        }
        if (n >= 3 && strcmp(a, "property") == 0 && in_vertex) {
            if (strcmp(b, "list") == 0) return 0;
            for (int k = 0; k < 3; k++)
                if (strcmp(c, (const char *[]){"x", "y", "z"}[k]) == 0) {
                    h->axis_prop[k] = h->nprop;
                    h->axis_float[k] = strcmp(b, "float") == 0 || strcmp(b, "float32") == 0;
                }
            h->nprop++;
        }
    }
    return ended && ascii && h->count >= 0 && h->count <= 1000000000L && h->skip_lines >= 0 &&
           h->axis_prop[0] >= 0 && h->axis_prop[1] >= 0 && h->axis_prop[2] >= 0;
}

/* Reads the vertex records into pts[0..h->count-1]; 1, or -1 with a message. */
static int read_vertices(ply_reader *r, const ply_layout *h, agjk_vec3 *pts) {
    for (long i = 0; i < h->skip_lines; i++)
        if (!next(r)) return fail(r, "the file ends before the vertex element");
    for (long i = 0; i < h->count; i++) {
        if (!next(r)) return fail(r, "the file ends after %ld of its %ld vertices", i, h->count);
        double c[3] = {0, 0, 0};
        int n = 0;
        char *save = NULL;
        for (char *t = strtok_r(r->line, " \t\r\n", &save); t && n < h->nprop;
             t = strtok_r(NULL, " \t\r\n", &save), n++) {
            for (int k = 0; k < 3; k++) {
                if (h->axis_prop[k] != n) continue;
                int code = mesh_parse_coordinate(t, &c[k]);
                if (code != MESH_NUMBER_OK) {
                    char msg[160];
                    mesh_coordinate_error(code, t, msg, sizeof msg);
                    return fail(r, "vertex %ld: %s", i, msg);
                }
                if (h->axis_float[k]) {
                    float v = (float)c[k];
                    if (!isfinite(v))
                        return fail(r, "vertex %ld: coordinate '%.24s' is out of range for "
                                    "the float the header declares (limit 3.4e38)", i, t);
                    c[k] = v;
                }
            }
        }
        if (n < h->nprop)
            return fail(r, "vertex %ld has %d values; the header declares %d properties", i, n,
                        h->nprop);
        pts[i].x = c[0];
        pts[i].y = c[1];
        pts[i].z = c[2];
    }
    return 1;
}

int mesh_refine_double(const char *path, const char *format, mesh_points *points, char *err,
                       size_t err_size) {
    if (strcmp(format, "ply") != 0) return 0;
    ply_reader r = {path, fopen(path, "r"), NULL, 0, 0, err, err_size};
    if (!r.f) return 0;
    ply_layout h;
    int ok = read_header(&r, &h) && h.count > 0;
    agjk_vec3 *pts = ok ? malloc((size_t)h.count * sizeof *pts) : NULL;
    if (ok) ok = pts ? read_vertices(&r, &h, pts) : 0;
    free(r.line);
    fclose(r.f);
    if (ok != 1) {
        free(pts);
        return ok;
    }
    int declared_float = h.axis_float[0] || h.axis_float[1] || h.axis_float[2];
    free(points->points);
    points->points = pts;
    points->count = (size_t)h.count;
    points->double_precision = !declared_float;
    snprintf(points->precision_note, sizeof points->precision_note, "%s",
             declared_float ? "float (the PLY header declares float coordinates)"
                            : "double (read from the text, declared double)");
    return 1;
}
