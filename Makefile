# luxcalc - one plain Makefile. Targets: all test test-simd demo bench asan install uninstall clean deps.
# LX_OPENCL=0 builds without OpenCL. Sources are found by wildcard: src/LAYER/*.c is the library
# (one folder per layer), src/cli/*.c and src/cli/bench/*.c the command-line tool, tests/test_*.c
# one cmocka binary each, kernels/*.cl embedded.

LX_OPENCL ?= 1
PREFIX ?= /usr/local
DESTDIR ?=
BUILD ?= build
CC ?= cc
CFLAGS ?= -O2 -g
WARN := -std=c11 -Wall -Wextra -Wpedantic
ALL_CFLAGS = $(WARN) $(CFLAGS) -fPIC -fvisibility=hidden
# OpenEXRCore's library name carries the OpenEXR version (-lOpenEXRCore-3_1): taken from pkg-config,
# or the unversioned name where pkg-config does not know OpenEXR
EXR_PC = $(shell pkg-config --silence-errors --libs OpenEXR)
EXR_CFLAGS = $(or $(shell pkg-config --silence-errors --cflags-only-I OpenEXR),-I/usr/include/OpenEXR)
EXR_LIB = $(or $(filter -lOpenEXRCore%,$(EXR_PC)),-lOpenEXRCore)
# cairo draws the plots (PNG through its own writer, text in DejaVu Sans through fontconfig); the
# library opens libcairo.so.2 on the first plot (src/plot/cairo_load.c), so only the tests, which
# read the PNGs back through cairo, link it
CAIRO_CFLAGS := $(or $(shell pkg-config --silence-errors --cflags cairo),-I/usr/include/cairo)
CAIRO_LIB := $(or $(shell pkg-config --silence-errors --libs cairo),-lcairo)
ALL_CPPFLAGS = $(CPPFLAGS) -D_POSIX_C_SOURCE=200809L -Isrc -I$(BUILD)/gen $(EXR_CFLAGS) $(CAIRO_CFLAGS) \
  -DLX_OPENCL=$(LX_OPENCL) -DCL_TARGET_OPENCL_VERSION=120
LIBS = $(EXR_LIB) -lm -lpthread -ldl
PKGS := libopenexr-dev libcairo2-dev fonts-dejavu-core libcmocka-dev pkg-config poppler-utils
ifeq ($(LX_OPENCL),1)
LIBS += -lOpenCL
PKGS += pocl-opencl-icd ocl-icd-opencl-dev opencl-headers
endif

LAYERS := core tables spectral colour lighting radiance radiosity scene plot
LIB_SRC := $(wildcard $(LAYERS:%=src/%/*.c))
CLI_SRC := $(wildcard src/cli/*.c src/cli/bench/*.c)
TEST_SRC := $(wildcard tests/test_*.c tests/hard_cases/test_*.c)
DATA := $(sort $(wildcard src/data/*.csv))
KERNELS := $(sort $(wildcard kernels/*.cl))

GEN_SRC := $(BUILD)/gen/tables/lx_tables.c $(BUILD)/gen/core/lx_kernels.c $(BUILD)/gen/core/lx_pow5.c
LIB_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/obj/%.o) $(GEN_SRC:$(BUILD)/gen/%.c=$(BUILD)/obj/%.o)
CLI_OBJ := $(CLI_SRC:src/cli/%.c=$(BUILD)/obj/cli/%.o)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

# the test build of the library: the files that call OpenCL again with LX_FAULTS (OpenCL fault
# injection, src/core/cl_faults.c), linked into test_faults and a CLI for tests/cli/faults.sh only
CL_USERS := $(shell grep -l 'clCreateBuffer\|clEnqueue\|clBuildProgram\|clGetPlatformIDs\|clFinish' $(LIB_SRC)) src/core/cl_faults.c src/core/alloc.c
FAULT_OBJ := $(CL_USERS:src/%.c=$(BUILD)/obj-faults/%.o)
FAULT_LIB := $(BUILD)/faults/libluxcalc.a
FAULT_CLI := $(BUILD)/tests/luxcalc-faults

STATIC := $(BUILD)/libluxcalc.a
# the soname follows the header's major version (luxcalc.h "ABI policy": libluxcalc.so.0 for 0.x)
VERSION := $(shell sed -n 's/^\#define LX_VERSION_STRING "\(.*\)"/\1/p' src/luxcalc.h)
SONAME := libluxcalc.so.$(firstword $(subst ., ,$(VERSION)))
SHARED := $(BUILD)/$(SONAME)
CLI := $(BUILD)/luxcalc

.PHONY: all test test-simd test-nofp64 demo bench asan tsan valgrind install uninstall clean deps fuzz

all: $(STATIC) $(SHARED) $(CLI) $(BUILD)/libs.txt

# the link flags a program embedding the static library needs (read by tests/cli/embed.sh)
$(BUILD)/libs.txt: Makefile | $(BUILD)
	@echo '$(LDFLAGS) $(LIBS)' > $@

# ---- dependencies: install missing Debian packages (root) or say which ----
deps:
	@missing=""; \
	if command -v dpkg-query >/dev/null 2>&1; then \
	  for p in $(PKGS); do \
	    dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	  done; \
	fi; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "luxcalc: installing:$$missing"; \
	    (apt-get install -y -qq --no-install-recommends $$missing >/dev/null 2>&1 || \
	     (apt-get update -qq >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null)) || \
	      { echo "luxcalc: apt-get failed; please install:$$missing" >&2; exit 1; }; \
	  else \
	    echo "luxcalc: missing packages; please run: sudo apt-get install --no-install-recommends$$missing" >&2; exit 1; \
	  fi; \
	fi

# ---- the configuration of this build dir ----
# The compiler and preprocessor flags (LX_OPENCL, CPPFLAGS) this BUILD dir's objects were made with:
# every object depends on this file, which is rewritten only when they change, so switching
# LX_OPENCL in one BUILD dir rebuilds it instead of mixing objects of both (not rewritten by make -n,
# which only looks). CFLAGS and LDFLAGS are not tracked: each sanitizer has its own BUILD dir, and
# tests/cli/install.sh runs make install in them without repeating their CFLAGS.
FLAGS_STAMP := $(BUILD)/flags.txt
FLAGS_NOW = $(subst ',,$(CC) $(ALL_CPPFLAGS))
ifeq ($(findstring n,$(firstword -$(MAKEFLAGS))),)
$(shell mkdir -p $(BUILD) && { printf '%s\n' '$(FLAGS_NOW)' | cmp -s - $(FLAGS_STAMP) || printf '%s\n' '$(FLAGS_NOW)' >$(FLAGS_STAMP); })
endif
$(FLAGS_STAMP):
	@mkdir -p $(dir $@) && printf '%s\n' '$(FLAGS_NOW)' >$@

# ---- generated sources ----
$(BUILD)/lxgen: src/tools/lxgen.c | $(BUILD)
	$(CC) $(WARN) -O1 -o $@ $<

$(BUILD)/gen/tables/lx_tables.c: $(BUILD)/lxgen $(DATA)
	@mkdir -p $(dir $@)
	$(BUILD)/lxgen tables $@ $(DATA)

$(BUILD)/gen/core/lx_kernels.c: $(BUILD)/lxgen $(KERNELS) Makefile
	@mkdir -p $(dir $@)
	$(BUILD)/lxgen kernels $@ $(KERNELS)

$(BUILD)/gen/core/lx_pow5.c: $(BUILD)/lxgen
	@mkdir -p $(dir $@)
	$(BUILD)/lxgen pow5 $@

$(BUILD):
	@mkdir -p $@

# ---- objects ----
$(BUILD)/obj/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/obj/%.o: $(BUILD)/gen/%.c $(FLAGS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) -Wno-overlength-strings -MMD -MP -c -o $@ $<

$(BUILD)/obj-faults/%.o: src/%.c $(FLAGS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) -DLX_FAULTS $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(FAULT_LIB): $(filter-out $(CL_USERS:src/%.c=$(BUILD)/obj/%.o),$(LIB_OBJ)) $(FAULT_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(FAULT_CLI): $(CLI_OBJ) $(FAULT_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJ) $(FAULT_LIB) $(LIBS)

$(STATIC): $(LIB_OBJ)
	rm -f $@
	ar rcs $@ $^

$(SHARED): $(LIB_OBJ)
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--no-undefined $(LDFLAGS) -o $@ $^ $(LIBS)
	ln -sf $(SONAME) $(BUILD)/libluxcalc.so

$(CLI): $(CLI_OBJ) $(STATIC)
	$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJ) $(STATIC) $(LIBS)

# test binaries track their headers and included sources (test_fuzz includes the fuzz harnesses);
# test_faults links the fault-injection build of the library
$(BUILD)/tests/test_faults: TEST_LIB = $(FAULT_LIB)
$(BUILD)/tests/test_faults: $(FAULT_LIB)
TEST_LIB = $(STATIC)
$(BUILD)/tests/%: tests/%.c $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) -Itests -MMD -MP -MF $@.d -MT $@ -o $@ $< $(TEST_LIB) -lcmocka $(LIBS) $(CAIRO_LIB)

# tools the CLI tests run: pngpx reads a PNG's pixels (tests/cli/*.sh check where a plot draws a mark)
TEST_TOOLS := $(BUILD)/tests/pngpx
$(BUILD)/tests/pngpx: tests/tools/pngpx.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(CAIRO_CFLAGS) -o $@ $< $(CAIRO_LIB)

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/cli/bench/*.d $(BUILD)/obj-faults/*/*.d \
  $(BUILD)/tests/*.d $(BUILD)/tests/hard_cases/*.d)

# ---- the two README commands, and the rest ----
test: deps
	@$(MAKE) --no-print-directory all $(TEST_BIN) $(TEST_TOOLS) $(FAULT_CLI)
	@LX_SHARED_DIR=$${LX_SHARED_DIR:-$(CURDIR)/../shared} POCL_CACHE_DIR=$(CURDIR)/$(BUILD)/pocl-cache \
	  sh tests/run.sh $(BUILD) $(TEST_BIN)

# the suite again with the SIMD paths capped, as an AVX2-only and a plain x86-64 CPU run it (the
# binaries of `make test`, not rebuilt); the tests of the paths above the cap report SKIPPED
SIMD_CAPS ?= avx2 scalar
test-simd: deps
	@$(MAKE) --no-print-directory all $(TEST_BIN) $(TEST_TOOLS) $(FAULT_CLI)
	@for s in $(SIMD_CAPS); do log=$$(mktemp); \
	  LX_SIMD=$$s LX_SHARED_DIR=$${LX_SHARED_DIR:-$(CURDIR)/../shared} POCL_CACHE_DIR=$(CURDIR)/$(BUILD)/pocl-cache \
	  sh tests/run.sh $(BUILD) $(TEST_BIN) > $$log 2>&1; rc=$$?; \
	  grep -E '^\[  (FAILED|SKIPPED) \] [a-z]|^not ok|: not ok|^failing' $$log | sort -u; \
	  echo "LX_SIMD=$$s: $$(tail -n 1 $$log)"; rm -f $$log; [ $$rc -eq 0 ] || exit 1; done

demo: deps
	@$(MAKE) --no-print-directory all
	@POCL_CACHE_DIR=$(CURDIR)/$(BUILD)/pocl-cache sh samples/demo.sh $(CLI)

bench: deps
	@$(MAKE) --no-print-directory all
	@POCL_CACHE_DIR=$(CURDIR)/$(BUILD)/pocl-cache $(CLI) bench --dir samples/bench

asan: deps
	@LX_TEST_SLOW=$${LX_TEST_SLOW:-3} LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	  $(MAKE) --no-print-directory BUILD=build-asan CFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
	  LDFLAGS="-fsanitize=address,undefined" test

# ---- install: libraries (versioned soname), header, pkg-config, binary, man pages, completion ----
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
BINDIR ?= $(PREFIX)/bin
MANDIR ?= $(PREFIX)/share/man
COMPLETIONDIR ?= $(PREFIX)/share/bash-completion/completions

$(BUILD)/luxcalc.1: $(CLI) src/tools/mkman.sh
	sh src/tools/mkman.sh cli $(CLI) > $@.tmp && mv $@.tmp $@

$(BUILD)/luxcalc.3: src/luxcalc.h src/tools/mkman.sh | $(BUILD)
	sh src/tools/mkman.sh api src/luxcalc.h > $@.tmp && mv $@.tmp $@

$(BUILD)/luxcalc.bash: $(CLI) src/tools/mkcompletion.sh
	sh src/tools/mkcompletion.sh $(CLI) > $@.tmp && mv $@.tmp $@

install: all $(BUILD)/luxcalc.1 $(BUILD)/luxcalc.3 $(BUILD)/luxcalc.bash
	install -d $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(BINDIR) \
	  $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man3 $(DESTDIR)$(COMPLETIONDIR)
	install -m 644 $(STATIC) $(DESTDIR)$(LIBDIR)/
	install -m 755 $(SHARED) $(DESTDIR)$(LIBDIR)/$(SONAME).$(VERSION:$(firstword $(subst ., ,$(VERSION))).%=%)
	ln -sf $(SONAME).$(VERSION:$(firstword $(subst ., ,$(VERSION))).%=%) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libluxcalc.so
	install -m 644 src/luxcalc.h $(DESTDIR)$(INCLUDEDIR)/
	@printf 'prefix=%s\nlibdir=%s\nincludedir=%s\n\nName: luxcalc\nDescription: photometry and radiometry (spectra, lighting, luminaires, radiance maps)\nVersion: %s\nCflags: -I$${includedir}\nLibs: -L$${libdir} -lluxcalc\nLibs.private: %s\n' \
	  '$(PREFIX)' '$(LIBDIR)' '$(INCLUDEDIR)' '$(VERSION)' '$(LIBS)' > $(DESTDIR)$(LIBDIR)/pkgconfig/luxcalc.pc
	install -m 755 $(CLI) $(DESTDIR)$(BINDIR)/
	install -m 644 $(BUILD)/luxcalc.1 $(DESTDIR)$(MANDIR)/man1/
	install -m 644 $(BUILD)/luxcalc.3 $(DESTDIR)$(MANDIR)/man3/
	install -m 644 $(BUILD)/luxcalc.bash $(DESTDIR)$(COMPLETIONDIR)/luxcalc

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/libluxcalc.a $(DESTDIR)$(LIBDIR)/$(SONAME)* $(DESTDIR)$(LIBDIR)/libluxcalc.so \
	  $(DESTDIR)$(LIBDIR)/pkgconfig/luxcalc.pc $(DESTDIR)$(INCLUDEDIR)/luxcalc.h $(DESTDIR)$(BINDIR)/luxcalc \
	  $(DESTDIR)$(MANDIR)/man1/luxcalc.1 $(DESTDIR)$(MANDIR)/man3/luxcalc.3 $(DESTDIR)$(COMPLETIONDIR)/luxcalc

# the tests that run threads, under ThreadSanitizer with OpenCL on (test_threads runs contexts on
# OpenCL from four threads at once); tests/tsan.supp may hold reports from inside PoCL's own
# threads only, never from luxcalc's code
TSAN_TESTS := test_threads test_batch test_opencl test_uncertainty
tsan: deps
	@$(MAKE) --no-print-directory BUILD=build-tsan CFLAGS="-O1 -g -fsanitize=thread" \
	  LDFLAGS="-fsanitize=thread" $(TSAN_TESTS:%=build-tsan/tests/%)
	@for t in $(TSAN_TESTS); do \
	  TSAN_OPTIONS="halt_on_error=1 suppressions=$(CURDIR)/tests/tsan.supp" POCL_CACHE_DIR=$(CURDIR)/build-tsan/pocl-cache \
	    build-tsan/tests/$$t || exit 1; done

# the OpenCL tests again on a device whose fp64 is switched off (LX_CL_FP64=0): the program is built
# with LX_FP64=0, so the float and compensated-float kernels that devices without fp64 run are
# compiled and checked against their CPU twins (test_opencl fails if the switch did not take)
NOFP64_TESTS := test_opencl test_batch test_grid test_irradiance test_scene test_spectral_exr test_threads
test-nofp64: deps
	@$(MAKE) --no-print-directory all $(NOFP64_TESTS:%=$(BUILD)/tests/%)
	@LX_CL_FP64=0 LX_TEST_CLI=0 LX_SHARED_DIR=$${LX_SHARED_DIR:-$(CURDIR)/../shared} \
	  POCL_CACHE_DIR=$(CURDIR)/$(BUILD)/pocl-cache sh tests/run.sh $(BUILD) $(NOFP64_TESTS:%=$(BUILD)/tests/%)

# the whole suite under valgrind memcheck (tests/valgrind.supp: the loader's and OpenCL stack's own noise);
# the native run first fills the PoCL kernel cache, so that valgrind does not run the LLVM compiler
VG_BUILD := build-valgrind
valgrind: deps
	@$(MAKE) --no-print-directory deps PKGS=valgrind
	@$(MAKE) --no-print-directory BUILD=$(VG_BUILD) CFLAGS="-O1 -g" all $(TEST_SRC:tests/%.c=$(VG_BUILD)/tests/%) $(VG_BUILD)/tests/luxcalc-faults
	@LX_SHARED_DIR=$${LX_SHARED_DIR:-$(CURDIR)/../shared} POCL_CACHE_DIR=$(CURDIR)/$(VG_BUILD)/pocl-cache \
	  $(VG_BUILD)/tests/test_opencl >/dev/null 2>&1; \
	LX_SHARED_DIR=$${LX_SHARED_DIR:-$(CURDIR)/../shared} POCL_CACHE_DIR=$(CURDIR)/$(VG_BUILD)/pocl-cache \
	  sh src/tools/valgrind.sh $(VG_BUILD) $(TEST_SRC:tests/%.c=$(VG_BUILD)/tests/%)

# fuzz every parser for FUZZ_SECONDS each (libFuzzer, clang); see src/tools/fuzz.sh
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
fuzz: deps
	@FUZZ_JOBS=$(FUZZ_JOBS) sh src/tools/fuzz.sh $(FUZZ_SECONDS) $(FUZZ_TARGETS)

clean:
	rm -rf build build-asan build-tsan build-fuzz build-valgrind build-noocl
