# tests/fuzz: libFuzzer targets (issue 5, item 4) and the replay of their
# regression inputs in `make check`.
#
#   make fuzz [FUZZ_SECONDS=60]   builds the targets with clang
#                                 (-fsanitize=fuzzer,address,undefined) and runs
#                                 each for FUZZ_SECONDS; new crashers land in
#                                 $(OUT)/fuzz/ (crash-*): copy each one into
#                                 tests/fuzz/regressions/<target>/ once fixed.
#   make fuzz-build               only builds them
#
# The targets: fuzz_query (shapes, poses, options decoded from bytes; the core
# API) and fuzz_mesh (mesh file -> tools/mesh loader -> Qhull hull -> query).
# make check replays tests/fuzz/regressions/{query,mesh}/* through the same
# entry points compiled without libFuzzer (replay.c).
# Needs clang and its runtime (Debian: clang, libclang-rt-14-dev).

FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_BUILD := $(OUT)/fuzzbuild
FUZZ_BIN := $(OUT)/fuzz
# tools/mesh's fragment is read after this one: name its archive literally.
FUZZ_MESH_LIB := $(OUT)/tools/mesh/libagjkmesh.a
FUZZ_MESH_CPPFLAGS = -Itools/mesh $(shell $(PKG_CONFIG) --cflags assimp qhull_r 2>/dev/null)
FUZZ_MESH_LIBS = $(or $(shell $(PKG_CONFIG) --libs assimp qhull_r 2>/dev/null),-lassimp -lqhull_r) -lm

# ---- replay in make check (normal compiler, normal flags) ----
FUZZ_REPLAY_QUERY := $(OUT)/tests/fuzz/replay_query
FUZZ_REPLAY_MESH := $(OUT)/tests/fuzz/replay_mesh
CHECK_BINS += $(FUZZ_REPLAY_QUERY) $(FUZZ_REPLAY_MESH)

$(FUZZ_REPLAY_QUERY): tests/fuzz/fuzz_query.c tests/fuzz/replay.c tests/fuzz/fuzz_decode.h $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) -DFUZZ_DEFAULT_DIR='"tests/fuzz/regressions/query"' $(ALL_CFLAGS) \
	    -o $@ tests/fuzz/fuzz_query.c tests/fuzz/replay.c $(LIB_A) $(LDFLAGS) -lm

$(FUZZ_REPLAY_MESH): tests/fuzz/fuzz_mesh.c tests/fuzz/replay.c tests/fuzz/fuzz_decode.h $(FUZZ_MESH_LIB) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(FUZZ_MESH_CPPFLAGS) -DFUZZ_DEFAULT_DIR='"tests/fuzz/regressions/mesh"' \
	    $(ALL_CFLAGS) -o $@ tests/fuzz/fuzz_mesh.c tests/fuzz/replay.c $(FUZZ_MESH_LIB) $(LIB_A) \
	    $(LDFLAGS) $(FUZZ_MESH_LIBS)

# ---- libFuzzer builds: the library and the mesh library rebuilt with clang,
# coverage instrumentation and sanitizers, in their own OUT tree ----
.PHONY: fuzz fuzz-build
fuzz-build:
	$(MAKE) CC=$(FUZZ_CC) OUT=$(FUZZ_BUILD) OPT="-O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link" \
	    $(FUZZ_BUILD)/libagjk.a $(FUZZ_BUILD)/tools/mesh/libagjkmesh.a
	@mkdir -p $(FUZZ_BIN)
	$(FUZZ_CC) $(ALL_CPPFLAGS) $(WARN) -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer \
	    -o $(FUZZ_BIN)/fuzz_query tests/fuzz/fuzz_query.c $(FUZZ_BUILD)/libagjk.a -lm
	$(FUZZ_CC) $(ALL_CPPFLAGS) $(FUZZ_MESH_CPPFLAGS) $(WARN) -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer \
	    -o $(FUZZ_BIN)/fuzz_mesh tests/fuzz/fuzz_mesh.c $(FUZZ_BUILD)/tools/mesh/libagjkmesh.a \
	    $(FUZZ_BUILD)/libagjk.a $(FUZZ_MESH_LIBS) -lstdc++

# Each target runs FUZZ_SECONDS from the committed regressions and seeds plus
# its growing corpus in $(OUT)/fuzz/corpus-*.
# The mesh target goes through mesh_load(), the CLI's path, which imports in a
# forked child so that assimp's own crashes become error messages. The child
# inherits the sanitizer's and libFuzzer's crash handlers, which would report
# (and save) a contained assimp crash as ours: signal handling is off for that
# target. Memory errors in our instrumented code are still reported by ASan,
# and violated invariants by exit() (see fuzz_decode.h). Leaks in assimp are
# not ours: leak detection is off too.
FUZZ_MESH_ASAN := detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_abort=0:handle_sigfpe=0:handle_sigill=0:allocator_may_return_null=1
fuzz: fuzz-build
	@mkdir -p $(FUZZ_BIN)/corpus-query $(FUZZ_BIN)/corpus-mesh
	@status=0; \
	$(FUZZ_BIN)/fuzz_query -max_total_time=$(FUZZ_SECONDS) -max_len=2048 -timeout=10 \
	    -artifact_prefix=$(FUZZ_BIN)/query- -print_final_stats=1 \
	    $(FUZZ_BIN)/corpus-query tests/fuzz/regressions/query || status=1; \
	ASAN_OPTIONS=$(FUZZ_MESH_ASAN) $(FUZZ_BIN)/fuzz_mesh -max_total_time=$(FUZZ_SECONDS) \
	    -max_len=8192 -timeout=10 -rss_limit_mb=1024 -artifact_prefix=$(FUZZ_BIN)/mesh- \
	    -handle_segv=0 -handle_bus=0 -handle_abrt=0 -handle_ill=0 -handle_fpe=0 \
	    -print_final_stats=1 $(FUZZ_BIN)/corpus-mesh tests/fuzz/regressions/mesh \
	    tests/fuzz/seeds/mesh || status=1; \
	if [ $$status -ne 0 ]; then echo "fuzz: crashers in $(FUZZ_BIN)/*crash-*"; fi; exit $$status
