# tests/stability: the stiff/extreme corpus, scale invariance, the bad-input
# matrix, thread safety (issue 5), and the sanitizer / valgrind variants of
# `make check`.
#
#   make check-stability   only these test programs
#   make check-asan        all of `make check` rebuilt with ASan + UBSan in $(OUT)/asan
#   make check-tsan        the thread-safety test under ThreadSanitizer in $(OUT)/tsan
#   make check-valgrind    every test program of `make check` under valgrind memcheck

STAB_OUT := $(OUT)/tests/stability
STAB_TESTS := $(basename $(notdir $(wildcard tests/stability/test_*.c)))
STAB_BINS := $(STAB_TESTS:%=$(STAB_OUT)/%)
STAB_CPPFLAGS := -Itests/common -Itests/stability
STAB_CHECK_CFLAGS := $(shell $(PKG_CONFIG) --cflags check 2>/dev/null)
STAB_CHECK_LIBS := $(shell $(PKG_CONFIG) --libs check 2>/dev/null)

# The certified reference of tests/common: that area's library when its
# fragment defines TEST_COMMON_LIB, else built here from the same sources.
ifeq ($(strip $(TEST_COMMON_LIB)),)
STAB_REF_SRCS := $(filter-out tests/common/test_%.c,$(wildcard tests/common/*.c))
STAB_REF_OBJS := $(STAB_REF_SRCS:tests/common/%.c=$(STAB_OUT)/common/%.o)
STAB_REF_LIB := $(STAB_OUT)/libstabref.a
$(STAB_OUT)/common/%.o: tests/common/%.c $(wildcard tests/common/*.h) $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) -Itests/common $(ALL_CFLAGS) -c $< -o $@
$(STAB_REF_LIB): $(STAB_REF_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^
else
STAB_REF_LIB := $(TEST_COMMON_LIB)
endif

CHECK_BINS += $(STAB_BINS)

$(STAB_OUT)/%.o: tests/stability/%.c tests/stability/stab_util.h tests/common/reference.h $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(STAB_CPPFLAGS) $(STAB_CHECK_CFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(STAB_BINS): $(STAB_OUT)/%: $(STAB_OUT)/%.o $(STAB_OUT)/stab_util.o $(STAB_REF_LIB) $(LIB_A)
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDFLAGS) $(STAB_CHECK_LIBS) -lpthread -lm

.PHONY: check-stability check-asan check-tsan check-valgrind
check-stability: $(STAB_BINS)
	@fail=0; for t in $(STAB_BINS); do echo "== $$t"; ./$$t || { fail=1; echo "FAILED: $$t"; }; done; \
	test $$fail -eq 0

# Sanitizers: a separate OUT tree, so the normal build is untouched. gcc links
# its sanitizer runtimes into shared objects too, which -Wl,-z,defs needs.
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# ASan maps any allocation lazily, so a malformed mesh header asking for
# 2e9 vertices would make assimp zero 24 GB: cap single allocations at 4 GB
# (malloc returns NULL / new throws, as with a normal libc under overcommit
# limits) and kill anything above 6 GB resident rather than the machine.
SAN_ENV := ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:allocator_may_return_null=1:max_allocation_size_mb=4096:hard_rss_limit_mb=6144:verify_asan_link_order=0 \
           UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
check-asan:
	$(SAN_ENV) $(MAKE) --no-print-directory OUT=$(OUT)/asan OPT="-O1 -g $(SAN_FLAGS)" \
	    LDFLAGS="$(SAN_FLAGS)" check

TSAN_FLAGS := -fsanitize=thread
check-tsan:
	$(MAKE) --no-print-directory OUT=$(OUT)/tsan OPT="-O1 -g $(TSAN_FLAGS)" LDFLAGS="$(TSAN_FLAGS)" \
	    $(OUT)/tsan/tests/stability/test_threads
	TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 OUT=$(OUT)/tsan V=$(V) \
	    sh tools/build/run-checks.sh $(OUT)/tsan/check-logs $(OUT)/tsan/tests/stability/test_threads

# Valgrind: every compiled test program of `make check` (scripts, including
# those listed in CHECK_BINS, are skipped).
# Check forks each test by default; CK_FORK=no keeps them in the traced
# process. A memory error (memcheck's exit code 99) or a crash fails the
# target. Valgrind runs x87 long double at double precision, so the tests'
# long-double references lose their precision there (test_simplex's
# adversarial simplices, test_methods' reference solver): a test that only
# fails its assertions is reported and counted, and `make check` runs those
# assertions natively.
VALGRIND ?= valgrind
VALGRIND_FLAGS := --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
                  --track-origins=yes -q
check-valgrind:
	$(MAKE) lib $(CHECK_BINS)
	@pass=0; fail=0; skip=0; numeric=0; for t in $(CHECK_BINS); do \
	    if ! head -c 4 $$t | grep -q ELF; then skip=$$((skip+1)); continue; fi; \
	    echo "== valgrind $$t"; \
	    CK_FORK=no $(VALGRIND) $(VALGRIND_FLAGS) ./$$t >/dev/null; status=$$?; \
	    if [ $$status -eq 0 ]; then pass=$$((pass+1)); \
	    elif [ $$status -eq 1 ]; then numeric=$$((numeric+1)); \
	        echo "   (assertions failed, no memory error: long double at double precision)"; \
	    else fail=$$((fail+1)); echo "FAILED under valgrind (exit $$status): $$t"; fi; done; \
	echo "valgrind: $$pass passed, $$numeric with assertions failed only, $$fail failed, $$skip scripts skipped"; \
	test $$fail -eq 0
