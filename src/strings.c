/* SPDX-License-Identifier: MIT */
#include "agjk/query.h"

const char *agjk_status_string(agjk_status status) {
    switch (status) {
    case AGJK_STATUS_SEPARATED: return "separated";
    case AGJK_STATUS_INTERSECTING: return "intersecting";
    case AGJK_STATUS_CONTACT_WITHIN_TOLERANCE: return "contact within tolerance";
    case AGJK_STATUS_NOT_CONVERGED: return "not converged";
    case AGJK_STATUS_INVALID_INPUT: return "invalid input";
    case AGJK_STATUS_OK: return "ok";
    }
    return "unknown status";
}

const char *agjk_method_name(agjk_method method) {
    switch (method) {
    case AGJK_METHOD_GJK: return "gjk";
    case AGJK_METHOD_NESTEROV: return "nesterov";
    case AGJK_METHOD_NESTEROV_NORMALIZED: return "nesterov-normalized";
    case AGJK_METHOD_POLYAK: return "polyak";
    case AGJK_METHOD_FRANK_WOLFE: return "fw";
    case AGJK_METHOD_ADAPTIVE: return "adaptive";
    }
    return "unknown";
}
