/* SPDX-License-Identifier: MIT */
/* The agjk side of a ref_shape: builds the library's shape from the same
 * description the reference reads. Kept apart from reference.c so that the
 * reference alone links without the library. */
#include <string.h>
#include "reference.h"

agjk_status ref_make_agjk(ref_shape *s, agjk_shape *out) {
    agjk_status st = AGJK_STATUS_INVALID_INPUT;
    if (s == NULL || out == NULL) return st;
    switch (s->kind) {
    case REF_POINT:
        st = agjk_shape_point(out);
        break;
    case REF_SPHERE:
        st = agjk_shape_sphere(out, s->p[0]);
        break;
    case REF_ELLIPSOID:
        s->ellipsoid.radii.x = s->p[0];
        s->ellipsoid.radii.y = s->p[1];
        s->ellipsoid.radii.z = s->p[2];
        st = agjk_shape_ellipsoid(out, &s->ellipsoid);
        break;
    case REF_BOX:
        s->box.half_extents.x = s->p[0];
        s->box.half_extents.y = s->p[1];
        s->box.half_extents.z = s->p[2];
        st = agjk_shape_box(out, &s->box);
        break;
    case REF_CAPSULE:
        s->capsule.radius = s->p[0];
        s->capsule.half_height = s->p[1];
        st = agjk_shape_capsule(out, &s->capsule);
        break;
    case REF_CYLINDER:
        s->cylinder.radius = s->p[0];
        s->cylinder.half_height = s->p[1];
        st = agjk_shape_cylinder(out, &s->cylinder);
        break;
    case REF_CONE:
        s->cone.radius = s->p[0];
        s->cone.half_height = s->p[1];
        st = agjk_shape_cone(out, &s->cone);
        break;
    case REF_POLYTOPE:
        memset(&s->polytope, 0, sizeof s->polytope);
        s->polytope.vertices = s->vertices;
        s->polytope.vertex_count = s->vertex_count;
        st = agjk_shape_polytope(out, &s->polytope);
        break;
    }
    /* The extra margin goes on top of the shape's own (sphere/capsule radius). */
    if (st != AGJK_STATUS_INVALID_INPUT && s->margin != 0.0)
        st = agjk_shape_set_margin(out, out->margin + s->margin);
    return st;
}
