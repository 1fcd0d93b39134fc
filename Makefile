# agjk: GNU make build. meson.build builds and tests the same sources.
#
#   make                 library (static + shared), tools
#   make check           all tests (Check framework) + install smoke tests
#   make install PREFIX=/usr/local [DESTDIR=...]   library, agjk CLI, man pages
#   make install-lib     only what a C user links: headers, libagjk, agjk.pc,
#                        the CMake package (builds nothing but the library)
#   make uninstall       removes what install put there, and the directories
#                        it created once they are empty
#   make check-abi       the shared library against the ABI baselines in abi/ (libabigail)
#
# Output: one short line per compiled file and per test program; V=1 shows the
# full commands and test output (test output is always in $(OUT)/check-logs/).
#
# Each area of the tree adds its programs and rules in its own fragment
# (tests/*/*.mk, tools/*/*.mk), so the areas stay independent.

VERSION   := 0.2.0
SOVERSION := 0
PREFIX    ?= /usr/local
LIBDIR    ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
BINDIR    ?= $(PREFIX)/bin
MANDIR    ?= $(PREFIX)/share/man
DESTDIR   ?=
OUT       ?= out

OPT       ?= -O2 -g
WARN      := -std=c99 -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
             -Wmissing-prototypes -Wcast-qual -Wvla
# Determinism: no fused multiply-add contraction behind our back. No errno
# from libm either (nothing reads it): sqrt is then one instruction, with no
# check-and-call for negative arguments.
FPFLAGS   := -ffp-contract=off -fno-math-errno
ALL_CFLAGS = $(WARN) $(OPT) $(FPFLAGS) $(CFLAGS)
ALL_CPPFLAGS = -Iinclude -D_POSIX_C_SOURCE=200809L $(CPPFLAGS)
LIB_CFLAGS := -fPIC -fvisibility=hidden -ffunction-sections -fdata-sections
PKG_CONFIG ?= pkg-config

LIB_SRCS  := $(sort $(wildcard src/*.c))
LIB_OBJS  := $(LIB_SRCS:%.c=$(OUT)/%.o)
LIB_A     := $(OUT)/libagjk.a
LIB_SO_REAL := $(OUT)/libagjk.so.$(VERSION)
LIB_SO_NAME := libagjk.so.$(SOVERSION)
LIB_SO    := $(OUT)/libagjk.so
PC_FILE   := $(OUT)/agjk.pc
HEADERS   := $(wildcard include/agjk/*.h)
CMAKEDIR  ?= $(LIBDIR)/cmake/agjk
SIZEOF_VOID_P := $(or $(shell $(CC) -dM -E - </dev/null 2>/dev/null | sed -n 's/.*__SIZEOF_POINTER__ //p'),8)

# Quiet output unless V=1 (or make -s, which silences everything): recipes
# are not echoed, and compiler and archiver calls print one short line each
# (tools/build/quiet.sh).
V ?= 0
# A CC or AR taken from the environment is left alone: make would export the
# wrapped value to the programs it runs (tests that compile, cmake).
ifneq ($(V),1)
ifeq ($(findstring s,$(firstword -$(MAKEFLAGS))),)
ifneq ($(origin CC),environment)
override CC := $(CURDIR)/tools/build/quiet.sh CC $(CC)
endif
ifneq ($(origin AR),environment)
override AR := $(CURDIR)/tools/build/quiet.sh AR $(AR)
endif
endif
.SILENT:
endif

# Filled by the fragments.
TOOL_BINS  :=
CHECK_BINS :=
CHECK_SCRIPTS :=
CLEAN_EXTRA :=

.PHONY: all lib check install install-lib uninstall clean check-abi abi-baseline check-install
all: lib tools

lib: $(LIB_A) $(LIB_SO) $(PC_FILE)

$(OUT)/src/%.o: src/%.c $(HEADERS) $(wildcard src/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) $(LIB_CFLAGS) -c $< -o $@

$(LIB_A): $(LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(LIB_SO_REAL): $(LIB_OBJS)
	$(CC) $(ALL_CFLAGS) -shared -Wl,-soname,$(LIB_SO_NAME) -Wl,--gc-sections \
	    -Wl,-z,defs -o $@ $^ $(LDFLAGS) -lm

$(LIB_SO): $(LIB_SO_REAL)
	ln -sf libagjk.so.$(VERSION) $(OUT)/$(LIB_SO_NAME)
	ln -sf libagjk.so.$(VERSION) $@

$(PC_FILE): agjk.pc.in Makefile
	@mkdir -p $(OUT)
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' \
	    -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|g' -e 's|@VERSION@|$(VERSION)|g' $< > $@

-include $(sort $(wildcard tests/*/*.mk tools/*/*.mk examples/*.mk))

tools: $(TOOL_BINS)

# Every test program runs (tools/build/run-checks.sh): one line each, the log
# of a failed one, and the summary `test programs: N passed, N failed`; the
# target fails if any failed. Logs: $(OUT)/check-logs/.
check: all $(CHECK_BINS)
	OUT=$(OUT) V=$(V) sh tools/build/run-checks.sh $(OUT)/check-logs $(CHECK_BINS) $(CHECK_SCRIPTS)

# The CMake package: relocatable, every path computed from the file's place
# (<libdir>/cmake/agjk); libdir and includedir are given relative to the
# prefix when they lie under it.
CMAKE_SUBST = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR_REL@|$(patsubst $(PREFIX)/%,%,$(LIBDIR))|g' \
    -e 's|@INCLUDEDIR_REL@|$(patsubst $(PREFIX)/%,%,$(INCLUDEDIR))|g' -e 's|@VERSION@|$(VERSION)|g' \
    -e 's|@SOVERSION@|$(SOVERSION)|g' -e 's|@SIZEOF_VOID_P@|$(SIZEOF_VOID_P)|g'
# Directories the installation created, for `make uninstall`.
INSTALL_MANIFEST = $(DESTDIR)$(CMAKEDIR)/agjk-created-dirs.txt

install-lib: lib
	sh tools/build/install-dirs.sh $(INSTALL_MANIFEST) $(DESTDIR)$(LIBDIR) \
	    $(DESTDIR)$(INCLUDEDIR)/agjk $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(CMAKEDIR)
	install -m 644 $(HEADERS) $(DESTDIR)$(INCLUDEDIR)/agjk/
	install -m 644 $(LIB_A) $(DESTDIR)$(LIBDIR)/
	install -m 755 $(LIB_SO_REAL) $(DESTDIR)$(LIBDIR)/
	ln -sf libagjk.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(LIB_SO_NAME)
	ln -sf libagjk.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libagjk.so
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' \
	    -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|g' -e 's|@VERSION@|$(VERSION)|g' \
	    agjk.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/agjk.pc
	$(CMAKE_SUBST) cmake/agjkConfig.cmake.in > $(DESTDIR)$(CMAKEDIR)/agjkConfig.cmake
	$(CMAKE_SUBST) cmake/agjkConfigVersion.cmake.in > $(DESTDIR)$(CMAKEDIR)/agjkConfigVersion.cmake
	echo "installed the agjk library into $(DESTDIR)$(PREFIX)"

# The library, the agjk CLI and the man pages (no benchmark, no test helpers).
install: install-lib $(INSTALL_BINS)
	sh tools/build/install-dirs.sh $(INSTALL_MANIFEST) $(DESTDIR)$(BINDIR) \
	    $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man3
	$(if $(INSTALL_BINS),install -m 755 $(INSTALL_BINS) $(DESTDIR)$(BINDIR)/)
	install -m 644 man/agjk.1 $(DESTDIR)$(MANDIR)/man1/
	install -m 644 man/agjk.3 $(DESTDIR)$(MANDIR)/man3/
	echo "installed $(notdir $(INSTALL_BINS)) and the man pages into $(DESTDIR)$(PREFIX)"

uninstall:
	rm -f $(HEADERS:include/%=$(DESTDIR)$(INCLUDEDIR)/%) \
	    $(DESTDIR)$(LIBDIR)/libagjk.a $(DESTDIR)$(LIBDIR)/libagjk.so* \
	    $(DESTDIR)$(LIBDIR)/pkgconfig/agjk.pc \
	    $(DESTDIR)$(CMAKEDIR)/agjkConfig.cmake $(DESTDIR)$(CMAKEDIR)/agjkConfigVersion.cmake \
	    $(foreach b,$(INSTALL_BINS),$(DESTDIR)$(BINDIR)/$(notdir $(b))) \
	    $(DESTDIR)$(MANDIR)/man1/agjk.1 $(DESTDIR)$(MANDIR)/man3/agjk.3
	dirs=""; if [ -f $(INSTALL_MANIFEST) ]; then dirs=$$(sort -r -u $(INSTALL_MANIFEST)); \
	    rm -f $(INSTALL_MANIFEST); fi; \
	for d in $$dirs $(DESTDIR)$(INCLUDEDIR)/agjk $(DESTDIR)$(CMAKEDIR); do \
	    rmdir "$$d" 2>/dev/null || true; done
	echo "uninstalled agjk from $(DESTDIR)$(PREFIX)"

# ABI, two baselines (abidw):
# - abi/libagjk-0.1.0.abi, the released 0.1.0: the library must stay
#   compatible with it (abidiff may report additions, never an incompatible
#   change: exit bit 8, nor an error: bits 1 and 2);
# - abi/libagjk.abi, this version's: any change libabigail reports fails, so
#   that every change of the ABI is deliberate (`make abi-baseline`).
ABIDW_FLAGS := --no-corpus-path --headers-dir include/agjk
ABIDIFF := abidiff --headers-dir1 include/agjk --headers-dir2 include/agjk
check-abi: $(LIB_SO_REAL)
	abidw $(ABIDW_FLAGS) --out-file $(OUT)/libagjk.abi $(LIB_SO_REAL)
	@rc=0; $(ABIDIFF) abi/libagjk-0.1.0.abi $(OUT)/libagjk.abi >$(OUT)/abi-0.1.0.txt || rc=$$?; \
	if [ $$((rc & 11)) -ne 0 ]; then cat $(OUT)/abi-0.1.0.txt; \
	    echo "ABI: incompatible with 0.1.0 (abidiff exit $$rc)"; exit 1; fi; \
	echo "ABI: compatible with 0.1.0 (abidiff exit $$rc: additions only)"
	$(ABIDIFF) abi/libagjk.abi $(OUT)/libagjk.abi && echo "ABI: identical to abi/libagjk.abi"

abi-baseline: $(LIB_SO_REAL)
	@mkdir -p abi
	abidw $(ABIDW_FLAGS) --out-file abi/libagjk.abi $(LIB_SO_REAL)

clean:
	rm -rf $(OUT) $(CLEAN_EXTRA)
