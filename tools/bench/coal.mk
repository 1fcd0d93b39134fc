# tools/bench: the optional Coal part of agjk-bench (coal_bench.c, and
# coal_adapter.cpp when Coal is present, else coal_stub.c).
#
#   tools/fetch-coal.sh        unpacks Coal 3.0.3 into $(BENCH_COAL_DIR) (out/coal)
#   make bench                 then also times Coal's GJK variants on the same problems
#
# Detection: $(BENCH_COAL_DIR)/cmeel.prefix/lib/libcoal.so. The adapter is C++
# (Coal's API); agjk-bench is then linked by $(CXX), with a run path to the
# fetched libraries (libcoal.so finds its own through its $ORIGIN run path).
# This fragment is read after bench.mk and adds to its link line.

BENCH_COAL_DIR    ?= $(or $(AGJK_COAL_DIR),out/coal)
BENCH_COAL_PREFIX := $(BENCH_COAL_DIR)/cmeel.prefix
BENCH_COAL_FOUND  := $(wildcard $(BENCH_COAL_PREFIX)/lib/libcoal.so)
BENCH_COAL_CXXFLAGS := -std=c++17 $(OPT) -DNDEBUG -Wall -Wextra -Wpedantic \
    -isystem $(BENCH_COAL_PREFIX)/include -isystem $(BENCH_COAL_PREFIX)/include/eigen3

# Relink agjk-bench when Coal appears or disappears.
BENCH_COAL_STAMP := $(OUT)/tools/bench/coal-found.stamp
# Remade on every run that needs it, but rewritten (and so newer than its
# dependents) only when the detection changed; targets that need no bench
# (install-lib, install) never create it.
$(BENCH_COAL_STAMP): bench-coal-detect
	@mkdir -p $(dir $@)
	@echo '$(BENCH_COAL_FOUND)' | cmp -s - $@ || echo '$(BENCH_COAL_FOUND)' > $@
.PHONY: bench-coal-detect
bench-coal-detect:

ifneq ($(BENCH_COAL_FOUND),)
BENCH_COAL_ADAPTER := $(OUT)/tools/bench/coal_adapter.o
BENCH_COAL_LIBDIR  := $(abspath $(BENCH_COAL_PREFIX)/lib)
$(BENCH_COAL_ADAPTER): tools/bench/coal_adapter.cpp tools/bench/coal_adapter.h $(BENCH_COAL_STAMP)
	@mkdir -p $(dir $@)
	$(CXX) $(BENCH_COAL_CXXFLAGS) $(CXXFLAGS) -c $< -o $@
# By path, not -L: the fetched folder also holds an assimp 6 and Qhull that
# must not replace the system ones the mesh tools link (Qhull is loaded once:
# both are 8.0.2, the same soname).
BENCH_COAL_LIBS := $(BENCH_COAL_LIBDIR)/libcoal.so -Wl,-rpath,$(BENCH_COAL_LIBDIR)
BENCH_EXTRA_LIBS += $(BENCH_COAL_LIBS)
BENCH_LD := $(CXX)
else
BENCH_COAL_ADAPTER := $(OUT)/tools/bench/coal_stub.o
endif
BENCH_EXTRA_OBJS += $(OUT)/tools/bench/coal_bench.o $(BENCH_COAL_ADAPTER)

$(BENCH_BIN): $(OUT)/tools/bench/coal_bench.o $(BENCH_COAL_ADAPTER) $(BENCH_COAL_STAMP)

# Instruction counts, agjk and Coal on identical problems (valgrind callgrind):
#   make bench-callgrind        see tools/bench/callgrind.sh
BENCH_CG_BIN := $(OUT)/tools/bench/agjk-callgrind-work
$(BENCH_CG_BIN): $(OUT)/tools/bench/callgrind_work.o $(OUT)/tools/bench/coal_bench.o \
                 $(OUT)/tools/bench/hull_support.o $(BENCH_COAL_ADAPTER) $(BENCH_LIB) \
                 $(BENCH_MESH_LIB) $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(BENCH_COAL_STAMP)
	$(or $(BENCH_LD),$(CC)) $(ALL_CFLAGS) -o $@ $(OUT)/tools/bench/callgrind_work.o \
	    $(OUT)/tools/bench/coal_bench.o $(OUT)/tools/bench/hull_support.o \
	    $(BENCH_COAL_ADAPTER) $(BENCH_LIB) $(BENCH_MESH_LIB) $(OUT)/tests/common/libtestcommon.a \
	    $(LIB_A) $(BENCH_MESH_LIBS) $(BENCH_CCD_LIBS) $(BENCH_COAL_LIBS) -lm
TOOL_BINS += $(BENCH_CG_BIN)

# Depth queries one by one for callgrind (agjk_signed_distance or Coal's
# GJK + EPA on the depth benchmark's problems): see tools/bench/depth_work.c.
BENCH_DW_BIN := $(OUT)/tools/bench/agjk-depth-work
$(BENCH_DW_BIN): $(OUT)/tools/bench/depth_work.o $(OUT)/tools/bench/coal_bench.o \
                 $(OUT)/tools/bench/hull_support.o $(BENCH_COAL_ADAPTER) $(BENCH_LIB) $(BENCH_MESH_LIB) \
                 $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(BENCH_COAL_STAMP)
	$(or $(BENCH_LD),$(CC)) $(ALL_CFLAGS) -o $@ $(OUT)/tools/bench/depth_work.o \
	    $(OUT)/tools/bench/coal_bench.o $(OUT)/tools/bench/hull_support.o $(BENCH_COAL_ADAPTER) \
	    $(BENCH_LIB) $(BENCH_MESH_LIB) $(OUT)/tests/common/libtestcommon.a $(LIB_A) \
	    $(BENCH_MESH_LIBS) $(BENCH_CCD_LIBS) $(BENCH_COAL_LIBS) -lm
TOOL_BINS += $(BENCH_DW_BIN)

.PHONY: bench-callgrind
bench-callgrind: $(BENCH_CG_BIN)
	sh tools/bench/callgrind.sh $(BENCH_CG_BIN)
