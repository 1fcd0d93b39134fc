/* SPDX-License-Identifier: MIT */
/* Shared scaffolding of the Check test programs. Each test function gets its
 * own test case (TU_ADD), so one test runs alone with CK_RUN_CASE=<name>,
 * e.g. `CK_RUN_CASE=degenerate out/tests/core/test_simplex`. */
#ifndef AGJK_TEST_CHECK_MAIN_H
#define AGJK_TEST_CHECK_MAIN_H

#include <check.h>

/* Assertions for inner loops. Check's ck_assert* record a "last passed
 * point" with a write to the runner on every call that passes (a system call
 * each); these only call into Check when they fail. */
#define TU_ENSURE(cond, ...)                      \
    do {                                          \
        if (!(cond)) ck_abort_msg(__VA_ARGS__);   \
    } while (0)
#define TU_CHECK(cond) TU_ENSURE(cond, "%s:%d: check failed: %s", __FILE__, __LINE__, #cond)
#define TU_CHECK_INT_EQ(a, b)                                                              \
    TU_ENSURE((a) == (b), "%s:%d: %s == %s failed (%lld vs %lld)", __FILE__, __LINE__, #a, #b, \
              (long long)(a), (long long)(b))

/* Adds test function `fn` in a test case of the same name, with a timeout
 * generous enough for a loaded 2-core CI machine. */
#define TU_ADD(suite, fn)                          \
    do {                                           \
        TCase *tu_tc_ = tcase_create(#fn);         \
        tcase_set_timeout(tu_tc_, 120);            \
        tcase_add_test(tu_tc_, fn);                \
        suite_add_tcase((suite), tu_tc_);          \
    } while (0)

/* Runs the suite; returns the exit status (0: every test passed). */
static inline int tu_run_suite(Suite *suite) {
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}

#endif
