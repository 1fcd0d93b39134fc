# Examples: the README's quickstart, the lean-link demonstration, and the
# install smoke test (built against the installed library via pkg-config).
EXAMPLE_CFLAGS = $(ALL_CPPFLAGS) $(ALL_CFLAGS)

$(OUT)/examples/%: examples/%.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXAMPLE_CFLAGS) $< -o $@ $(LIB_A) -lm

# Linked against libagjk.a with unused sections dropped (the program itself
# is dynamically linked): what an embedded user would link.
$(OUT)/examples/spheres_and_boxes: examples/spheres_and_boxes.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXAMPLE_CFLAGS) -ffunction-sections -fdata-sections $< -o $@ \
	    -Wl,--gc-sections -Wl,-Map=$@.map $(LIB_A) -lm

TOOL_BINS += $(OUT)/examples/quickstart $(OUT)/examples/spheres_and_boxes
CHECK_SCRIPTS += examples/lean-link.sh examples/check-install.sh
