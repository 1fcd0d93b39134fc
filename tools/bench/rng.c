/* SPDX-License-Identifier: MIT */
#include "rng.h"

#include <math.h>

static uint64_t splitmix64(uint64_t *state) {
    uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

void bench_rng_seed(bench_rng *rng, uint64_t seed) {
    int i;
    for (i = 0; i < 4; ++i) rng->s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

uint64_t bench_rng_next(bench_rng *rng) {
    uint64_t *s = rng->s;
    uint64_t result = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

double bench_rng_uniform(bench_rng *rng) {
    return (double)(bench_rng_next(rng) >> 11) * (1.0 / 9007199254740992.0);
}

double bench_rng_normal(bench_rng *rng) {
    const double two_pi = 6.283185307179586476925286766559;
    double u1 = 1.0 - bench_rng_uniform(rng); /* (0, 1]: log is finite */
    double u2 = bench_rng_uniform(rng);
    return sqrt(-2.0 * log(u1)) * cos(two_pi * u2);
}

uint32_t bench_rng_below(bench_rng *rng, uint32_t n) {
    return (uint32_t)(bench_rng_uniform(rng) * (double)n) % (n ? n : 1);
}

agjk_vec3 bench_rng_unit(bench_rng *rng) {
    agjk_vec3 v;
    double n;
    do {
        v.x = bench_rng_normal(rng);
        v.y = bench_rng_normal(rng);
        v.z = bench_rng_normal(rng);
        n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    } while (n < 1e-12);
    v.x /= n;
    v.y /= n;
    v.z /= n;
    return v;
}

void bench_rng_rotation(bench_rng *rng, double r[3][3]) {
    const double two_pi = 6.283185307179586476925286766559;
    double u1 = bench_rng_uniform(rng), u2 = bench_rng_uniform(rng);
    double u3 = bench_rng_uniform(rng);
    double a = sqrt(1.0 - u1), b = sqrt(u1);
    double w = a * sin(two_pi * u2), x = a * cos(two_pi * u2);
    double y = b * sin(two_pi * u3), z = b * cos(two_pi * u3);
    r[0][0] = 1 - 2 * (y * y + z * z);
    r[0][1] = 2 * (x * y - w * z);
    r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z);
    r[1][1] = 1 - 2 * (x * x + z * z);
    r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y);
    r[2][1] = 2 * (y * z + w * x);
    r[2][2] = 1 - 2 * (x * x + y * y);
}
