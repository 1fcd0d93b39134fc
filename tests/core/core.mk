# tests/core: one Check program per module of the core library.
# Run one test alone: CK_RUN_CASE=<test name> out/tests/core/test_simplex

CORE_TESTS := test_simplex test_shapes test_api test_analytic test_methods test_properties test_collide \
              test_verdicts test_penetration test_cache test_subnormals
CORE_TEST_BINS := $(CORE_TESTS:%=$(OUT)/tests/core/%)
CORE_TOOL_BINS := $(OUT)/tests/core/iterations

$(OUT)/tests/core/%: tests/core/%.c $(OUT)/tests/common/libtestcommon.a $(LIB_A) \
                     $(wildcard tests/common/*.h) $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) -Itests/common $(ALL_CFLAGS) $< -o $@ \
	    $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(shell $(PKG_CONFIG) --cflags --libs check) -lm

CHECK_BINS += $(CORE_TEST_BINS)
TOOL_BINS += $(CORE_TOOL_BINS)

.PHONY: check-core
check-core: $(CORE_TEST_BINS) $(OUT)/tests/common/test_reference
	@fail=0; for t in $^; do echo "== $$t"; ./$$t || fail=1; done; test $$fail -eq 0

# Mutation check: every deliberate bug in a copy of src/ must fail some test.
.PHONY: mutants-core
mutants-core: $(OUT)/tests/common/libtestcommon.a
	tests/core/mutants.sh $(OUT)
