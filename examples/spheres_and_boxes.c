/* SPDX-License-Identifier: MIT */
/* A scene of spheres and boxes only. Linked statically with --gc-sections it
 * must pull in no polytope, hull or penetration code: examples/lean-link.sh
 * checks the symbols and reports the text size (see the README). */
#include <stdio.h>

#include <agjk/agjk.h>

int main(void) {
    agjk_box crate = {{1.0, 1.0, 1.0}};
    agjk_shape ball, box;
    agjk_shape_sphere(&ball, 0.5);
    agjk_shape_box(&box, &crate);
    agjk_pose at_origin = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    int failures = 0;
    for (int i = 0; i < 8; ++i) {
        double x = 1.0 + 0.25 * i; /* sphere centre on the x axis */
        agjk_pose p = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {x, 0, 0}};
        agjk_result r;
        agjk_options o = agjk_default_options();
        agjk_distance(&box, &at_origin, &ball, &p, &o, &r);
        double expected = x - 1.5 > 0.0 ? x - 1.5 : 0.0; /* face distance minus radius */
        double err = r.distance - expected;
        if (err < 0) err = -err;
        if (err > 1e-6 + r.bound) ++failures;
        printf("x = %.2f  %-13s distance %.6f (expected %.6f)\n", x, agjk_status_string(r.status),
               r.distance, expected);
    }
    return failures != 0;
}
