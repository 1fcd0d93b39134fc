/* SPDX-License-Identifier: MIT */
#include <string.h>

#include "agjk/query.h"
#include "query_setup.h"

const agjk_options agjk__default_options = {
    (uint32_t)sizeof(agjk_options),
    AGJK_METHOD_ADAPTIVE,
    AGJK_TOLERANCE_ABSOLUTE,
    1e-8,                 /* tolerance (the paper's) */
    1000,                 /* max_iterations */
    AGJK_COMPUTE_WITNESS, /* compute */
    0,                    /* use_initial_direction */
    {0.0, 0.0, 0.0},      /* initial_direction */
    0, 0                  /* hint_a, hint_b */
};

void agjk_options_init_sized(agjk_options *options, size_t struct_size) {
    /* A caller compiled against an older, smaller agjk_options gets only the
     * fields it knows; a NULL or too-small buffer is left alone. */
    if (!options || struct_size < offsetof(agjk_options, hint_b) + sizeof options->hint_b) return;
    agjk_options o;
    memcpy(&o, &agjk__default_options, sizeof o); /* its padding too (zero) */
    o.struct_size = (uint32_t)(struct_size < sizeof o ? struct_size : sizeof o);
    memcpy(options, &o, o.struct_size);
}
