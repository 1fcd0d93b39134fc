# agjk: GNU make build. meson.build builds and tests the same sources.
#
#   make                 library (static + shared), tools
#   make check           all tests (Check framework) + install smoke test
#   make install PREFIX=/usr/local [DESTDIR=...]
#   make check-abi       compare the shared library against abi/libagjk.abi (libabigail)
#
# Each area of the tree adds its programs and rules in its own fragment
# (tests/*/*.mk, tools/*/*.mk), so the areas stay independent.

VERSION   := 0.1.0
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
# Determinism: no fused multiply-add contraction behind our back.
FPFLAGS   := -ffp-contract=off
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

# Filled by the fragments.
TOOL_BINS  :=
CHECK_BINS :=
CHECK_SCRIPTS :=
CLEAN_EXTRA :=

.PHONY: all lib check install uninstall clean check-abi abi-baseline check-install
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

# Every test program runs; the summary line counts programs, and the target
# fails if any failed.
check: all $(CHECK_BINS)
	@pass=0; fail=0; \
	for t in $(CHECK_BINS) $(CHECK_SCRIPTS); do \
	    echo "== $$t"; \
	    if ./$$t; then pass=$$((pass+1)); else fail=$$((fail+1)); echo "FAILED: $$t"; fi; \
	done; \
	echo "test programs: $$pass passed, $$fail failed"; \
	test $$fail -eq 0

install: lib tools
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCLUDEDIR)/agjk $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(BINDIR)
	install -m 644 $(HEADERS) $(DESTDIR)$(INCLUDEDIR)/agjk/
	install -m 644 $(LIB_A) $(DESTDIR)$(LIBDIR)/
	install -m 755 $(LIB_SO_REAL) $(DESTDIR)$(LIBDIR)/
	ln -sf libagjk.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(LIB_SO_NAME)
	ln -sf libagjk.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libagjk.so
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' \
	    -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|g' -e 's|@VERSION@|$(VERSION)|g' \
	    agjk.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/agjk.pc
	$(if $(INSTALL_BINS),install -m 755 $(INSTALL_BINS) $(DESTDIR)$(BINDIR)/)

uninstall:
	rm -f $(HEADERS:include/%=$(DESTDIR)$(INCLUDEDIR)/%) \
	    $(DESTDIR)$(LIBDIR)/libagjk.a $(DESTDIR)$(LIBDIR)/libagjk.so* \
	    $(DESTDIR)$(LIBDIR)/pkgconfig/agjk.pc \
	    $(foreach b,$(INSTALL_BINS),$(DESTDIR)$(BINDIR)/$(notdir $(b)))

# ABI: abi/libagjk.abi is the committed baseline (abidw); check-abi fails on any
# change libabigail reports. Regenerate deliberately with `make abi-baseline`.
ABIDW_FLAGS := --no-corpus-path --headers-dir include/agjk
check-abi: $(LIB_SO_REAL)
	abidw $(ABIDW_FLAGS) --out-file $(OUT)/libagjk.abi $(LIB_SO_REAL)
	abidiff --headers-dir1 include/agjk --headers-dir2 include/agjk \
	    abi/libagjk.abi $(OUT)/libagjk.abi && echo "ABI: identical to abi/libagjk.abi"

abi-baseline: $(LIB_SO_REAL)
	@mkdir -p abi
	abidw $(ABIDW_FLAGS) --out-file abi/libagjk.abi $(LIB_SO_REAL)

clean:
	rm -rf $(OUT) $(CLEAN_EXTRA)
