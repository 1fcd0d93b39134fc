# tools/bench: agjk-bench, the benchmark of the paper's experiments, the
# work-precision diagram and the libccd timing.
#
#   make bench                 default size (~5 min on 2 cores), writes results/
#   make bench-quick           a small run into $(OUT)/bench-quick/
#   make bench BENCH_ARGS='--pairs 1000 --poses 100'   the paper's full size
#   tools/fetch-meshes.sh      downloads the pybullet meshes; make bench then uses them

BENCH_LIB_SRCS := rng.c problems.c nesmino.c solve.c evaluate.c stats.c guard.c \
                  ccd_adapter.c ccd_bench.c mesh_io.c report.c repeat.c
BENCH_LIB_OBJS := $(BENCH_LIB_SRCS:%.c=$(OUT)/tools/bench/%.o)
# The adaptive method's tables (support calls, coherent motion), linked with main.c.
BENCH_ADAPTIVE_OBJS := $(OUT)/tools/bench/coherent.o $(OUT)/tools/bench/calls.o
BENCH_LIB      := $(OUT)/tools/bench/libbench.a
BENCH_BIN      := $(OUT)/tools/bench/agjk-bench
# Hulls with hill-climbing adjacency come from tools/mesh (the Qhull
# wrapper); its fragment is read after this one, so its archive is named here.
BENCH_MESH_LIB := $(OUT)/tools/mesh/libagjkmesh.a
BENCH_MESH_CPPFLAGS := -Itools/mesh
BENCH_MESH_LIBS := $(or $(shell $(PKG_CONFIG) --libs assimp qhull_r 2>/dev/null),-lassimp -lqhull_r)
BENCH_HDRS     := $(wildcard tools/bench/*.h)
BENCH_CCD_CFLAGS := $(shell $(PKG_CONFIG) --cflags ccd)
BENCH_CCD_LIBS   := $(shell $(PKG_CONFIG) --libs ccd)
BENCH_MESH_DIR ?= $(OUT)/meshes/random_urdfs
BENCH_ARGS     ?=
BENCH_OUT      ?= results

$(OUT)/tools/bench/%.o: tools/bench/%.c $(BENCH_HDRS) $(HEADERS) tests/common/reference.h
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(BENCH_CCD_CFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(BENCH_LIB): $(BENCH_LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(OUT)/tools/bench/hull_support.o: tools/bench/hull_support.c $(BENCH_HDRS) $(HEADERS) \
                                   tools/mesh/mesh.h
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(BENCH_MESH_CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(BENCH_BIN): $(OUT)/tools/bench/main.o $(OUT)/tools/bench/hull_support.o \
              $(OUT)/tools/bench/depth_bench.o $(OUT)/tools/bench/stress.o \
              $(BENCH_ADAPTIVE_OBJS) $(BENCH_LIB) \
              $(BENCH_MESH_LIB) $(OUT)/tests/common/libtestcommon.a $(LIB_A)
	$(or $(BENCH_LD),$(CC)) $(ALL_CFLAGS) -o $@ $(OUT)/tools/bench/main.o \
	    $(OUT)/tools/bench/hull_support.o $(OUT)/tools/bench/depth_bench.o \
	    $(OUT)/tools/bench/stress.o $(BENCH_ADAPTIVE_OBJS) \
	    $(BENCH_EXTRA_OBJS) \
	    $(BENCH_LIB) $(BENCH_MESH_LIB) $(OUT)/tests/common/libtestcommon.a $(LIB_A) \
	    $(BENCH_MESH_LIBS) $(BENCH_CCD_LIBS) $(BENCH_EXTRA_LIBS) -lm

TOOL_BINS += $(BENCH_BIN)

# The mesh part runs when the meshes were fetched (tools/fetch-meshes.sh).
BENCH_MESH_ARG = $(if $(wildcard $(BENCH_MESH_DIR)),--mesh-dir $(BENCH_MESH_DIR))

.PHONY: bench bench-quick bench-plots
bench: $(BENCH_BIN)
	@mkdir -p $(BENCH_OUT)
	./$(BENCH_BIN) --out $(BENCH_OUT) $(BENCH_MESH_ARG) $(BENCH_ARGS)
	@$(MAKE) --no-print-directory bench-plots BENCH_OUT=$(BENCH_OUT)

bench-quick: $(BENCH_BIN)
	@mkdir -p $(OUT)/bench-quick
	./$(BENCH_BIN) --quick --out $(OUT)/bench-quick $(BENCH_MESH_ARG) $(BENCH_ARGS)
	@$(MAKE) --no-print-directory bench-plots BENCH_OUT=$(OUT)/bench-quick

bench-plots:
	@if command -v gnuplot >/dev/null 2>&1; then \
	    cd $(BENCH_OUT) && gnuplot work-precision.gp && gnuplot iterations.gp && \
	    echo "plots: $(BENCH_OUT)/work-precision.png $(BENCH_OUT)/iterations.png"; \
	else echo "gnuplot not found: tables and data are in $(BENCH_OUT) (tables.md, *.csv); for the PNG plots:"; \
	    echo "  apt-get install --no-install-recommends gnuplot-nox && make bench-plots BENCH_OUT=$(BENCH_OUT)"; fi
