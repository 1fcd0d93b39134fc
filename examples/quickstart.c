/* SPDX-License-Identifier: MIT */
/* The README's example: distance between a box and an ellipsoid, then a
 * Boolean test. Build: cc quickstart.c $(pkg-config --cflags --libs agjk) */
#include <stdio.h>

#include <agjk/agjk.h>

int main(void) {
    agjk_box box = {{0.5, 0.5, 0.5}};                /* a unit cube */
    agjk_ellipsoid egg = {{0.3, 0.2, 0.2}};          /* semi-axes */
    agjk_shape a, b;
    agjk_shape_box(&a, &box);
    agjk_shape_ellipsoid(&b, &egg);

    agjk_pose pose_a = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    agjk_pose pose_b = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1.5, 0, 0}};

    agjk_options options = agjk_default_options();  /* adaptive method, gap <= 1e-8 */
    agjk_result result;
    if (agjk_distance(&a, &pose_a, &b, &pose_b, &options, &result) == AGJK_STATUS_INVALID_INPUT) {
        fprintf(stderr, "bad input\n");
        return 1;
    }
    printf("%s: distance %.9f (true value within %.1e below), %d iterations\n",
           agjk_status_string(result.status), result.distance, result.bound, result.iterations);
    printf("closest points (%.3f %.3f %.3f) and (%.3f %.3f %.3f)\n", result.witness_a.x,
           result.witness_a.y, result.witness_a.z, result.witness_b.x, result.witness_b.y,
           result.witness_b.z);

    pose_b.translation.x = 0.7; /* now they overlap */
    agjk_collide(&a, &pose_a, &b, &pose_b, &options, &result);
    printf("collide: %s after %d iterations\n", agjk_status_string(result.status), result.iterations);
    return 0;
}
