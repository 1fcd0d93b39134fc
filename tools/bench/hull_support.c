/* SPDX-License-Identifier: MIT */
#include "hull_support.h"

#include <stdio.h>
#include <stdlib.h>

#include "mesh.h"

void bench_hull_hook(bench_shape *s) {
    static int warned;
    char err[MESH_ERROR_SIZE];
    mesh_hull *h = calloc(1, sizeof *h);
    if (!h) return;
    if (!mesh_hull_build(s->vertices, (size_t)s->vertex_count, 1, h, err, sizeof err) ||
        h->dimension != 3 || !h->polytope.neighbors ||
        agjk_shape_prepared_polytope(&s->shape, &h->prepared) == AGJK_STATUS_INVALID_INPUT) {
        if (!warned++)
            fprintf(stderr, "agjk-bench: warning: no hull adjacency (%s); scan support kept\n",
                    err);
        mesh_hull_free(h);
        free(h);
        agjk_shape_polytope(&s->shape, &s->polytope);
        return;
    }
    s->polytope = h->polytope; /* the struct copy points at h's arrays */
    agjk_shape_prepared_polytope(&s->shape, &h->prepared);
    s->aux = h;
}

void bench_hull_free(void *aux) {
    mesh_hull_free(aux);
    free(aux);
}

int bench_hull_triangles(const bench_shape *s, const int32_t **triangles) {
    const mesh_hull *h = s->aux;
    *triangles = NULL;
    if (!h || h->dimension != 3 || !h->triangles || s->polytope.vertices != h->vertices) return 0;
    *triangles = h->triangles;
    return (int)h->triangle_count;
}
