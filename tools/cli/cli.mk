# tools/cli: the `agjk` command-line tool. Links the mesh
# library of tools/mesh (assimp + Qhull); that fragment is read after this one,
# so its archive is named literally here.

CLI_BIN  := $(OUT)/tools/cli/agjk
CLI_SRCS := $(sort $(wildcard tools/cli/*.c))
CLI_OBJS := $(CLI_SRCS:%.c=$(OUT)/%.o)

$(OUT)/tools/cli/%.o: tools/cli/%.c tools/cli/cli.h tools/mesh/mesh.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(MESH_CPPFLAGS) -Itools/cli $(ALL_CFLAGS) -c $< -o $@

$(CLI_BIN): $(CLI_OBJS) $(OUT)/tools/mesh/libagjkmesh.a $(LIB_A)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJS) $(OUT)/tools/mesh/libagjkmesh.a $(LIB_A) $(MESH_LIBS)

TOOL_BINS += $(CLI_BIN)
INSTALL_BINS += $(CLI_BIN)

.PHONY: cli
cli: $(CLI_BIN)
