/* SPDX-License-Identifier: MIT */
#include <string.h>

#include "agjk/query.h"

void agjk_options_init_sized(agjk_options *options, size_t struct_size) {
    /* A caller compiled against an older, smaller agjk_options gets only the
     * fields it knows; a NULL or too-small buffer is left alone. */
    if (!options || struct_size < offsetof(agjk_options, hint_b) + sizeof options->hint_b) return;
    agjk_options o;
    memset(&o, 0, sizeof o);
    o.struct_size = (uint32_t)(struct_size < sizeof o ? struct_size : sizeof o);
    o.method = AGJK_METHOD_ADAPTIVE;
    o.tolerance_mode = AGJK_TOLERANCE_ABSOLUTE;
    o.tolerance = 1e-8;
    o.max_iterations = 1000;
    o.compute = AGJK_COMPUTE_WITNESS;
    o.use_initial_direction = 0;
    o.initial_direction.x = o.initial_direction.y = o.initial_direction.z = 0.0;
    o.hint_a = o.hint_b = 0;
    memcpy(options, &o, o.struct_size);
}
