/* SPDX-License-Identifier: MIT */
/* Internal: the warm-start cache of include/agjk/cache.h, between the public
 * queries (query.c) and the solver. */
#ifndef AGJK_SRC_CACHE_H
#define AGJK_SRC_CACHE_H

#include "agjk/cache.h"
#include "solver.h"

/* Sets in->warm / in->warm_count / in->x0 and md's hints from `cache` when it
 * is usable for the pair (a, b) under md's poses; returns 1 if so, else 0 and
 * leaves a cold start (in->warm_count = 0). */
int agjk__cache_load(const agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                     agjk__minkowski *md, agjk__solve_input *in);

/* Stores the solver's final simplex, hints and iterate in `cache` (emptied
 * first; left empty if out holds nothing usable); `in` is what
 * agjk__cache_load gave the solver (vertices it kept need no new local
 * points). */
void agjk__cache_save(agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                      const agjk__minkowski *md, const agjk__solve_input *in,
                      const agjk__solve_output *out);

#endif
