/* SPDX-License-Identifier: MIT */
/* Brute-force convex hull faces; see brute_hull.h. */
#include "brute_hull.h"

static long double orient(const agjk_vec3 *a, const agjk_vec3 *b, const agjk_vec3 *c,
                          const agjk_vec3 *d) {
    long double ux = (long double)b->x - a->x, uy = (long double)b->y - a->y, uz = (long double)b->z - a->z;
    long double vx = (long double)c->x - a->x, vy = (long double)c->y - a->y, vz = (long double)c->z - a->z;
    long double wx = (long double)d->x - a->x, wy = (long double)d->y - a->y, wz = (long double)d->z - a->z;
    return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

int brute_hull(const agjk_vec3 *p, int n, int32_t *triangles, int max_triangles) {
    int count = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            for (int k = j + 1; k < n; k++) {
                int pos = 0, neg = 0, zero = 0;
                for (int l = 0; l < n && !(pos && neg); l++) {
                    if (l == i || l == j || l == k) continue;
                    long double o = orient(&p[i], &p[j], &p[k], &p[l]);
                    if (o > 0) pos++;
                    else if (o < 0) neg++;
                    else zero++;
                }
                if (pos && neg) continue;
                if (zero) return -1;
                if (count >= max_triangles) return -1;
                /* outward: every other point on the negative side */
                triangles[3 * count] = i;
                triangles[3 * count + 1] = pos ? k : j;
                triangles[3 * count + 2] = pos ? j : k;
                count++;
            }
    return count;
}
