# mcbox - the only entry point. `make help` lists the targets.
#
# Layout of the build: the libraries of mc/, samplers/, pdf/ and render/ are
# separate static archives, linked in layer order (render, pdf, samplers,
# mc), so a lower layer that calls up into a higher one fails to link.
# Variants never share objects: the default build goes to build/, clang to
# build/clang/, the sanitizer build (SAN=1) to build/san/ (or
# build/clang-san/), NATIVE=1 to build/native/. The default gcc build is
# profile-guided (see PGO below): its training build is build/pgo-train/.

.SUFFIXES:
.DELETE_ON_ERROR:

CC ?= cc
CFLAGS ?= $(OPT) -g
LDFLAGS ?=
SAN ?= 0
NATIVE ?= 0
JUNIT ?= 0
PGO ?= auto

compiler := $(notdir $(firstword $(CC)))
variant := $(if $(filter clang%,$(compiler)),clang)
variant := $(variant)$(if $(filter 1,$(SAN)),$(if $(variant),-)san)
variant := $(variant)$(if $(filter 1,$(NATIVE)),$(if $(variant),-)native)
B := build$(if $(variant),/$(variant))

WARN := -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wdouble-promotion
MODE :=
ifeq ($(SAN),1)
MODE += -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
endif
ifeq ($(NATIVE),1)
MODE += -march=native
endif
# Link-time optimization for gcc builds (not clang, not the sanitizer build):
# the renderer's hot path crosses the render/pdf/samplers/mc archives, and
# only LTO lets gcc inline across them (bench_render: about 15% faster, same
# image). Archives of LTO objects need gcc-ar, which passes the LTO plugin.
cc_is_gcc := $(shell $(CC) -v 2>&1 | grep -q '^gcc version' && echo 1)
AR := ar
ifeq ($(cc_is_gcc)$(SAN),10)
MODE += -flto=auto
AR := gcc-ar
endif
# Profile-guided optimization of the libraries, for gcc builds without
# sanitizers (PGO=auto, the default; PGO=0 turns it off). An instrumented
# cornell_box is built under $(B)/pgo-train (PGO=gen), renders a few small
# images (tools/pgo_train.sh), and the library objects are then compiled
# with its counts: gcc lays out the hot paths and inlines by them. The
# renderer's arithmetic is unchanged, so are its images; it is some 9%
# faster. -fprofile-partial-training keeps code the training never ran
# optimized as without a profile, not as cold.
ifeq ($(PGO),auto)
PGO := $(if $(filter 10,$(cc_is_gcc)$(SAN)),1,0)
endif
ifeq ($(PGO),gen)
MODE += -fprofile-generate -fprofile-update=single
endif
# -O3 pays only with the profile (bench_render about 5% faster; without
# one it measured the same as -O2), so the profiled build and its training
# build use it, every other build -O2.
OPT := $(if $(filter-out 0,$(PGO)),-O3,-O2)
PGO_USE_FLAGS := -fprofile-use -fprofile-partial-training -Wno-missing-profile
# gcc tells static functions apart in a profile by their object's dump
# name (by default the object's path), and reads the counts from that name
# plus .gcda. Both builds give every object the same dump name under
# PGO_DIR: the instrumented program writes PGO_DIR/render/bvh.c.gcda, the
# optimized build of build/obj/render/bvh.o reads it.
PGO_DIR ?= $(B)/pgo-profile
PGO_DUMPNAME = $(if $(filter-out 0,$(PGO)),-dumpdir $(PGO_DIR)/$(dir $<) -dumpbase $(notdir $<))
# -fno-math-errno: nothing reads errno after a math function, and without
# it every sqrt carries a test and a call for the negative case (4% of the
# renderer's instructions). Results are unchanged: IEEE semantics stay.
ALL_CFLAGS = -std=c17 $(WARN) -I. -fopenmp -fno-math-errno $(MODE) -MMD -MP $(CFLAGS)
ALL_LDFLAGS = -fopenmp $(MODE) $(LDFLAGS)
# Debian's library names; no pkg-config at parse time, because `make deps`
# may be what installs pkg-config.
LIBS := -lgsl -lgslcblas -lpng -lm
TEST_LIBS := -lcmocka

# Debian packages the project needs (see `make deps`).
# fonts-texgyre-math: the book ships its math font (TeX Gyre Pagella Math),
# so that formulas look the same on every reader's machine.
DEB_PACKAGES := build-essential pkg-config libcmocka-dev libgsl-dev gnuplot-nox pandoc libpng-dev \
                fonts-texgyre-math

LAYERS := render pdf samplers mc
# A layer's archive holds its folder's sources and those of its fast/
# subfolder (render/fast/: the renderer's vector fast path).
lib_srcs = $(wildcard $(1)/*.c $(1)/fast/*.c)
lib_objs = $(patsubst %.c,$(B)/obj/%.o,$(call lib_srcs,$(1)))
LIBFILES := $(foreach l,$(LAYERS),$(B)/lib/lib$(l).a)

APP_SRCS := $(wildcard examples/common/*.c)
APP_LIB := $(B)/lib/libapp.a
PROGRAMS := $(patsubst examples/%.c,$(B)/bin/%,$(wildcard examples/*.c))
BENCHES := $(patsubst bench/%.c,$(B)/bench/%,$(wildcard bench/*.c))
SUPPORT_SRCS := $(wildcard tests/support/*.c)
SUPPORT_LIB := $(B)/lib/libtestsupport.a
TESTS := $(patsubst tests/%.c,$(B)/tests/%,$(wildcard tests/test_*.c))

.PHONY: all help deps book-deps test run bench soak plots plots-check book book-check clean \
        _test _run _bench _soak _plots _plots-check _book _book-check programs tests

all: $(LIBFILES) $(PROGRAMS) $(BENCHES)

help:
	@echo "make [all]     build the libraries and every program into build/"
	@echo "make test      install missing packages, build, run every test (SAN=1: sanitizers, JUNIT=1: XML)"
	@echo "make run       install missing packages, run every chapter program, print one table"
	@echo "make bench     throughput benchmarks"
	@echo "make soak      the statistical tests over SEEDS seeds; prints the failure rate"
	@echo "make plots     every figure under build/plots/"
	@echo "make book      the tutorial as HTML and EPUB under build/book/"
	@echo "make book-check  the book, then its checks: broken fixtures, links, EPUB, a headless browser"
	@echo "make deps      install the Debian packages the project needs, when missing"
	@echo "make clean     remove build/"

deps:
	@sh tools/deps.sh $(DEB_PACKAGES)

# What only the book's checks need: a real browser, python3 to drive it
# (over Chromium's DevTools pipe, no extra module), epubcheck.
BOOK_CHECK_PACKAGES := chromium python3 epubcheck
book-deps: deps
	@sh tools/deps.sh --always $(BOOK_CHECK_PACKAGES)

# The public targets first make sure the packages are there, then build in a
# second make so that `-j` cannot start compiling before the install ends.
test: deps
	@$(MAKE) --no-print-directory _test
run: deps
	@$(MAKE) --no-print-directory _run
bench: deps
	@$(MAKE) --no-print-directory _bench
soak: deps
	@$(MAKE) --no-print-directory _soak
plots: deps
	@$(MAKE) --no-print-directory _plots
plots-check: deps
	@$(MAKE) --no-print-directory _plots-check
book: deps
	@$(MAKE) --no-print-directory _book
book-check: book-deps
	@$(MAKE) --no-print-directory _book-check

programs: $(PROGRAMS)
tests: $(TESTS)

_test: all $(TESTS)
	@MC_BUILD=$(B) JUNIT=$(JUNIT) bash tools/run_tests.sh $(TESTS)

_run: all
	@MC_BUILD=$(B) bash tools/run_table.sh

_bench: all
	@MC_BUILD=$(B) bash tools/run_bench.sh

SEEDS ?= 20
_soak: all $(TESTS)
	@MC_BUILD=$(B) bash tools/soak.sh $(SEEDS) $(TESTS)

_plots: all
	@if [ -f plots/Makefile.inc ]; then $(MAKE) --no-print-directory -f plots/Makefile.inc B=$(B) figures; \
	 else echo "make plots: not yet"; fi
_plots-check: all
	@if [ -f plots/Makefile.inc ]; then $(MAKE) --no-print-directory -f plots/Makefile.inc B=$(B) check; \
	 else echo "make plots-check: not yet"; fi
_book: all $(TESTS)
	@$(MAKE) --no-print-directory -f book/Makefile.inc B=$(B) html
_book-check: _book
	@$(MAKE) --no-print-directory -f book/Makefile.inc B=$(B) check

clean:
	rm -rf build

# --- compilation -----------------------------------------------------------
# The compiler and its flags are recorded in a stamp that changes only when
# they do; every object depends on it, so `make CFLAGS=...` or a Makefile
# flag change rebuilds what it must and nothing else.
FLAGS_STAMP := $(B)/.flags
flags_now = $(CC) $(ALL_CFLAGS) | $(ALL_LDFLAGS) | $(AR) | PGO=$(PGO)
$(FLAGS_STAMP): FORCE
	@mkdir -p $(@D)
	@echo '$(flags_now)' | cmp -s - $@ || echo '$(flags_now)' > $@
FORCE:

# Objects of programs and tests are intermediate files of pattern rules;
# keep them, so that a rebuild recompiles only what changed.
.PRECIOUS: $(B)/obj/%.o

$(B)/obj/%.o: %.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(EXTRA_CFLAGS) $(PGO_DUMPNAME) -c $< -o $@

# With PGO=1 every library object waits for the profile: the stamp below
# is rewritten only when the instrumented program had to be rebuilt (a
# source or flag changed), and then the training runs again.
ifeq ($(PGO),1)
PGO_STAMP := $(B)/.pgo-trained
LIB_OBJS := $(foreach l,$(LAYERS),$(call lib_objs,$(l)))
$(LIB_OBJS): EXTRA_CFLAGS := $(PGO_USE_FLAGS)
$(LIB_OBJS): $(PGO_STAMP)
$(PGO_STAMP): FORCE
	@$(MAKE) --no-print-directory B=$(B)/pgo-train PGO=gen PGO_DIR=$(PGO_DIR) \
	  $(B)/pgo-train/bin/cornell_box
	@if [ ! -f $@ ] || [ $(B)/pgo-train/bin/cornell_box -nt $@ ]; then \
	  sh tools/pgo_train.sh $(B)/pgo-train/bin/cornell_box $(PGO_DIR) && touch $@; fi
endif

define layer_rule
$(B)/lib/lib$(1).a: $(call lib_objs,$(1))
	@mkdir -p $$(@D)
	rm -f $$@
	$$(if $$^,$(AR) rcs $$@ $$^,$(AR) rcs $$@)
endef
$(foreach l,$(LAYERS),$(eval $(call layer_rule,$(l))))

$(APP_LIB): $(patsubst %.c,$(B)/obj/%.o,$(APP_SRCS))
	@mkdir -p $(@D)
	rm -f $@
	$(AR) rcs $@ $^

$(SUPPORT_LIB): $(patsubst %.c,$(B)/obj/%.o,$(SUPPORT_SRCS))
	@mkdir -p $(@D)
	rm -f $@
	$(AR) rcs $@ $^

# Link order is the layer order: a wrong-way call is an undefined symbol.
LINK_LAYERS := $(foreach l,$(LAYERS),$(B)/lib/lib$(l).a)

$(B)/bin/%: $(B)/obj/examples/%.o $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

$(B)/bench/%: $(B)/obj/bench/%.o $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

$(B)/tests/%: $(B)/obj/tests/%.o $(SUPPORT_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(SUPPORT_LIB) $(LINK_LAYERS) $(LIBS) $(TEST_LIBS) -o $@

-include $(shell find $(B)/obj -name '*.d' 2>/dev/null)
