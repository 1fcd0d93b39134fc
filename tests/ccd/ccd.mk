# tests/ccd: libccd comparison suite, correctness part.
# Shares the problem generator and the libccd adapter with tools/bench. This
# fragment is read before tests/common and tools/bench, so the archives they
# build are named literally (prerequisites expand when read).

TEST_CCD_BIN := $(OUT)/tests/ccd/test_ccd

$(TEST_CCD_BIN): tests/ccd/test_ccd.c $(OUT)/tools/bench/libbench.a \
                 $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(wildcard tools/bench/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(shell $(PKG_CONFIG) --cflags ccd) $(ALL_CFLAGS) $< -o $@ \
	    $(OUT)/tools/bench/libbench.a $(OUT)/tests/common/libtestcommon.a $(LIB_A) \
	    $(shell $(PKG_CONFIG) --libs ccd) -lm

CHECK_BINS += $(TEST_CCD_BIN)


# The benchmark's own machinery: watchdog, NESMINO, mesh reader, generator.
TEST_BENCH_SUPPORT_BIN := $(OUT)/tests/ccd/test_bench_support

$(TEST_BENCH_SUPPORT_BIN): tests/ccd/test_bench_support.c $(OUT)/tools/bench/libbench.a \
                 $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(wildcard tools/bench/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) $< -o $@ $(OUT)/tools/bench/libbench.a \
	    $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(shell $(PKG_CONFIG) --libs ccd) -lm

CHECK_BINS += $(TEST_BENCH_SUPPORT_BIN)

.PHONY: check-ccd
check-ccd: $(TEST_CCD_BIN) $(TEST_BENCH_SUPPORT_BIN)
	./$(TEST_CCD_BIN)
	./$(TEST_BENCH_SUPPORT_BIN)
