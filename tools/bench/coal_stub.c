/* SPDX-License-Identifier: MIT */
/* coal_adapter.h without Coal: agjk-bench built before tools/fetch-coal.sh
 * ran (or without a C++ compiler). Every call reports that Coal is absent. */
#include <stddef.h>

#include "coal_adapter.h"

int coal_adapter_available(void) { return 0; }

const char *coal_adapter_version(void) {
    return "run tools/fetch-coal.sh, then make bench, for the Coal columns";
}

void *coal_adapter_shape_new(const coal_shape_desc *desc) {
    (void)desc;
    return NULL;
}

void coal_adapter_shape_free(void *shape) { (void)shape; }

int coal_adapter_run(const void *shape_a, const void *shape_b, const coal_query_desc *q,
                     coal_answer *out) {
    (void)shape_a;
    (void)shape_b;
    (void)q;
    (void)out;
    return -1;
}

void *coal_adapter_query_new(const void *shape_a, const void *shape_b, const coal_query_desc *q) {
    (void)shape_a;
    (void)shape_b;
    (void)q;
    return NULL;
}

int coal_adapter_query_run(void *query) {
    (void)query;
    return -2;
}

void coal_adapter_query_free(void *query) { (void)query; }

int coal_adapter_depth(const void *shape_a, const void *shape_b, const coal_depth_desc *q,
                       coal_depth_answer *out) {
    (void)shape_a;
    (void)shape_b;
    (void)q;
    (void)out;
    return -1;
}

void *coal_adapter_depth_query_new(const void *shape_a, const void *shape_b,
                                   const coal_depth_desc *q) {
    (void)shape_a;
    (void)shape_b;
    (void)q;
    return NULL;
}

int coal_adapter_depth_query_run(void *query) {
    (void)query;
    return -2;
}

void coal_adapter_depth_query_answer(const void *query, coal_depth_answer *out) {
    (void)query;
    (void)out;
}

void coal_adapter_depth_query_free(void *query) { (void)query; }
