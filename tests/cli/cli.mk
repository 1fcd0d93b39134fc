# tests/cli: the agjk CLI end to end, hulls, adjacency and hill-climbing
# support. This fragment is read before tools/cli and
# tools/mesh, so their outputs are named literally in prerequisites.
#
#   make check-cli    only these tests

TEST_CLI_SCRIPT := $(OUT)/tests/cli/test_cli
TEST_HULL_SUPPORT := $(OUT)/tests/cli/test_hull_support

# The shell test is copied next to the binaries so that `make check` builds
# the agjk binary first (it is a prerequisite) and the script finds it there.
$(TEST_CLI_SCRIPT): tests/cli/test_cli.sh $(OUT)/tools/cli/agjk
	@mkdir -p $(dir $@)
	cp tests/cli/test_cli.sh $@
	chmod +x $@

$(TEST_HULL_SUPPORT): tests/cli/test_hull_support.c $(OUT)/tools/mesh/libagjkmesh.a $(LIB_A) \
                      tools/mesh/mesh.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(MESH_CPPFLAGS) $(ALL_CFLAGS) $(LDFLAGS) $< -o $@ \
	    $(OUT)/tools/mesh/libagjkmesh.a $(LIB_A) $(MESH_LIBS)

CHECK_BINS += $(TEST_HULL_SUPPORT) $(TEST_CLI_SCRIPT)

.PHONY: check-cli
check-cli: $(TEST_HULL_SUPPORT) $(TEST_CLI_SCRIPT)
	./$(TEST_HULL_SUPPORT) && ./$(TEST_CLI_SCRIPT)

# agjk distance with default options on random-pose mesh pairs against the
# long double reference of tests/common: `make check` runs a fast version on
# examples/meshes and generated point sets (150 pairs, a few seconds);
# `make check-real-meshes` runs it on the pybullet meshes of
# tools/fetch-meshes.sh (REAL_MESH_DIR: random objects; REAL_MESH_DIR2: robot
# links and household objects), each directory that is present.
REAL_MESH_DIR ?= $(OUT)/meshes/random_urdfs
REAL_MESH_DIR2 ?= $(OUT)/meshes/pybullet_data
REAL_MESH_PAIRS ?= 1000
CHECK_REAL_MESHES := $(OUT)/tests/cli/check_real_meshes

$(CHECK_REAL_MESHES): tests/cli/check_real_meshes.c $(OUT)/tools/mesh/libagjkmesh.a \
                      $(OUT)/tests/common/libtestcommon.a $(LIB_A) tools/mesh/mesh.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(MESH_CPPFLAGS) -Itests/common $(ALL_CFLAGS) $(LDFLAGS) $< -o $@ \
	    $(OUT)/tools/mesh/libagjkmesh.a $(OUT)/tests/common/libtestcommon.a $(LIB_A) $(MESH_LIBS)

# Run with no arguments (as make check does), it takes the agjk binary next to
# it and examples/meshes of the current directory.
CHECK_BINS += $(CHECK_REAL_MESHES)

.PHONY: check-real-meshes
check-real-meshes: $(CHECK_REAL_MESHES) $(OUT)/tools/cli/agjk
	@fail=0; ran=0; for d in $(REAL_MESH_DIR) $(REAL_MESH_DIR2); do \
	    test -d $$d || continue; ran=1; \
	    ./$(CHECK_REAL_MESHES) $(OUT)/tools/cli/agjk $$d $(REAL_MESH_PAIRS) || fail=1; \
	done; \
	if [ $$ran -eq 0 ]; then \
	    echo "no $(REAL_MESH_DIR) or $(REAL_MESH_DIR2): run tools/fetch-meshes.sh $(OUT)/meshes"; \
	    exit 1; \
	fi; \
	test $$fail -eq 0
