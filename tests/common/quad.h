/* SPDX-License-Identifier: MIT */
/* Quadruple precision for exact truths in tests: products of doubles are
 * exact in its 113-bit significand. `quad` is __float128 where the
 * compiler has it, else a long double of at least 113 bits; HAVE_QUAD is
 * defined when either exists (a test that needs it is skipped otherwise).
 * qsqrt: Newton's iteration from the double square root, so that no
 * quadmath library is needed. */
#ifndef AGJK_TEST_QUAD_H
#define AGJK_TEST_QUAD_H

#include <float.h>
#include <math.h>

#if defined(__SIZEOF_FLOAT128__)
__extension__ typedef __float128 quad;
#define HAVE_QUAD 1
#elif LDBL_MANT_DIG >= 113
typedef long double quad;
#define HAVE_QUAD 1
#endif

#ifdef HAVE_QUAD
static inline quad qsqrt(quad v) {
    if (v <= 0) return 0;
    quad r = sqrt((double)v);
    for (int i = 0; i < 3; i++) r = 0.5 * (r + v / r);
    return r;
}
#endif

#endif
