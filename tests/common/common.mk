# tests/common: the long double reference solver and shared test helpers.
# Other fragments link $(TEST_COMMON_LIB) and add
# $(TEST_COMMON_CPPFLAGS). Note for fragments included before this one
# (tests/ccd sorts first): a prerequisite list is expanded when read, so name
# the archive literally there: $(OUT)/tests/common/libtestcommon.a.

TEST_COMMON_SRCS := tests/common/ref_support.c tests/common/ref_simplex.c \
                    tests/common/reference.c tests/common/ref_agjk.c tests/common/testutil.c \
                    tests/common/brute_hull.c tests/common/ref_depth.c
TEST_COMMON_HDRS := $(wildcard tests/common/*.h)
TEST_COMMON_OBJS := $(TEST_COMMON_SRCS:%.c=$(OUT)/%.o)
TEST_COMMON_LIB  := $(OUT)/tests/common/libtestcommon.a
TEST_COMMON_CPPFLAGS := -Itests/common
# Check framework (compile and link flags).
TEST_CHECK_FLAGS := $(shell $(PKG_CONFIG) --cflags --libs check)

$(OUT)/tests/common/%.o: tests/common/%.c $(TEST_COMMON_HDRS) $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(TEST_COMMON_CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(TEST_COMMON_LIB): $(TEST_COMMON_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(OUT)/tests/common/test_reference: tests/common/test_reference.c $(TEST_COMMON_LIB) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(TEST_COMMON_CPPFLAGS) $(ALL_CFLAGS) $< -o $@ \
	    $(TEST_COMMON_LIB) $(LIB_A) $(TEST_CHECK_FLAGS) -lm

CHECK_BINS += $(OUT)/tests/common/test_reference

.PHONY: test-common
test-common: $(TEST_COMMON_LIB)
