# tests/cli: the agjk CLI end to end, hulls, adjacency and hill-climbing
# support (owner: helper B). This fragment is read before tools/cli and
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
