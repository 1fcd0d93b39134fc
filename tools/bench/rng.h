/* SPDX-License-Identifier: MIT */
/* Small deterministic PRNG for the benchmark and the libccd suite.
 *
 * xoshiro256** (Blackman & Vigna 2018) seeded by splitmix64, so that one
 * 64-bit seed reproduces every problem on every platform; rand() is not used
 * because its sequence differs between C libraries. */
#ifndef AGJK_BENCH_RNG_H
#define AGJK_BENCH_RNG_H

#include <stdint.h>
#include "agjk/agjk.h"

typedef struct bench_rng {
    uint64_t s[4];
} bench_rng;

void bench_rng_seed(bench_rng *rng, uint64_t seed);
uint64_t bench_rng_next(bench_rng *rng);
/* Uniform in [0, 1) with 53 random bits. */
double bench_rng_uniform(bench_rng *rng);
/* Standard normal (Box-Muller; one value per call, the second is dropped so
 * the stream does not depend on call parity). */
double bench_rng_normal(bench_rng *rng);
/* Uniform integer in [0, n). */
uint32_t bench_rng_below(bench_rng *rng, uint32_t n);
/* Uniformly distributed unit vector (normalised Gaussian vector). */
agjk_vec3 bench_rng_unit(bench_rng *rng);
/* Uniform random rotation (Shoemake 1992, "Uniform random rotations",
 * Graphics Gems III: a uniform unit quaternion), row-major. */
void bench_rng_rotation(bench_rng *rng, double rotation[3][3]);

#endif
