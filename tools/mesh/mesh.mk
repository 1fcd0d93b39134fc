# tools/mesh: mesh loading (assimp) and convex hulls (Qhull) for the tools,
# never linked into the core library.
#
#   make support-bench   builds $(OUT)/tools/mesh/support_bench: scan vs hill
#                        climbing support cost by hull size (run by hand)
# Fragments read before this one (tools/cli, tests/cli) name the archive
# literally: $(OUT)/tools/mesh/libagjkmesh.a.

MESH_SRCS := tools/mesh/mesh_load.c tools/mesh/mesh_isolate.c tools/mesh/mesh_refine.c \
             tools/mesh/mesh_text.c \
             tools/mesh/mesh_hull.c
MESH_OBJS := $(MESH_SRCS:%.c=$(OUT)/%.o)
MESH_LIB  := $(OUT)/tools/mesh/libagjkmesh.a
MESH_CPPFLAGS := -Itools/mesh $(shell $(PKG_CONFIG) --cflags assimp qhull_r 2>/dev/null)
MESH_LIBS := $(or $(shell $(PKG_CONFIG) --libs assimp qhull_r 2>/dev/null),-lassimp -lqhull_r) -lm
SUPPORT_BENCH_BIN := $(OUT)/tools/mesh/support_bench

$(OUT)/tools/mesh/%.o: tools/mesh/%.c tools/mesh/mesh.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(MESH_CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(MESH_LIB): $(MESH_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(SUPPORT_BENCH_BIN): tools/mesh/support_bench.c $(MESH_LIB) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(MESH_CPPFLAGS) $(ALL_CFLAGS) $(LDFLAGS) $< -o $@ $(MESH_LIB) $(LIB_A) $(MESH_LIBS)

TOOL_BINS += $(SUPPORT_BENCH_BIN)

.PHONY: support-bench
support-bench: $(SUPPORT_BENCH_BIN)
