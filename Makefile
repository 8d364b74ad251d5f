# mcbox - the only entry point. `make help` lists the targets.
#
# The libraries of mc/, samplers/, pdf/, render/ and catalog/ are separate
# static archives, linked in layer order (catalog, render, pdf, samplers,
# mc), so a lower layer that calls up into a higher one fails to link. mk/flags.mk chooses
# the compiler, the variant (its build directory) and the flags; mk/rules.mk
# compiles and links; mk/pgo.mk builds the renderer profile-guided.

.SUFFIXES:
.DELETE_ON_ERROR:

include mk/flags.mk

# Debian packages the project needs (see `make deps`).
# fonts-texgyre-math: the book ships its math font (TeX Gyre Pagella Math),
# so that formulas look the same on every reader's machine.
DEB_PACKAGES := build-essential pkg-config libcmocka-dev libgsl-dev gnuplot-nox pandoc libpng-dev \
                fonts-texgyre-math

# Link order, highest layer first. The sampler catalog sits above pdf/
# and below the programs; it does not use render/.
LAYERS := catalog render pdf samplers mc
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

.PHONY: all help deps book-deps test run bench reference soak plots plots-check book book-check clean \
        _test _run _bench _soak _plots _plots-check _book _book-check programs tests

all: $(LIBFILES) $(PROGRAMS) $(BENCHES)

help:
	@echo "make [all]     build the libraries and every program into build/"
	@echo "make test      install missing packages, build, run every test (SAN=1: sanitizers, JUNIT=1: XML)"
	@echo "make run       install missing packages, run every chapter program, print one table"
	@echo "make bench     throughput benchmarks (and the error table, after make reference)"
	@echo "make reference converged images of book and lambert for the error table, cached in build/"
	@echo "make soak      the statistical tests over SEEDS seeds; prints the failure rate"
	@echo "make plots     every figure under build/plots/"
	@echo "make book      the tutorial as HTML and EPUB under build/book/"
	@echo "make book-check  the book, then its checks: broken fixtures, links, EPUB, a headless browser"
	@echo "make deps      install the Debian packages the project needs, when missing"
	@echo "make clean     remove build/"
	@echo "V=1            show the full compiler command lines"

deps:
	@sh tools/deps.sh $(DEB_PACKAGES)

# What only the book's checks need: a real browser, python3 to drive it
# (over Chromium's DevTools pipe, no extra module), epubcheck.
BOOK_CHECK_PACKAGES := chromium python3 epubcheck
book-deps: deps
	@sh tools/deps.sh --always $(BOOK_CHECK_PACKAGES)

# The public targets first make sure the packages are there, then build in a
# second make so that `-j` cannot start compiling before the install ends.
PUBLIC := test run bench soak plots plots-check book
$(PUBLIC): deps
	@$(MAKE) --no-print-directory _$@
book-check: book-deps
	@$(MAKE) --no-print-directory _book-check

programs: $(PROGRAMS)
tests: $(TESTS)

_test: all $(TESTS)
	@MC_BUILD=$(B) JUNIT=$(JUNIT) bash tools/run_tests.sh $(TESTS)

_run: all
	@MC_BUILD=$(B) bash tools/run_table.sh

_bench: all reference
	@MC_BUILD=$(B) MC_REF_BOOK=$(REF)/book-$(REF_TAG) bash tools/run_bench.sh

# Converged references: two independent renders (seeds 1001 and 1002) of
# each scene, whose mean is the reference and whose difference measures its
# own noise (bench/bench_render.c). The settings are in the file names, so
# that changing them renders new ones; a render, once done, is kept.
REF := $(B)/reference
space := $(subst ,, )
REF_WIDTH ?= 300
REF_SPP ?= 1024
REF_STRATEGY ?= mixture
REF_FLAGS ?=
REF_TAG := $(REF_STRATEGY)$(subst --,-,$(subst $(space),,$(REF_FLAGS)))-$(REF_WIDTH)-$(REF_SPP)
REF_FILES := $(foreach s,book lambert,$(foreach h,a b,$(REF)/$(s)-$(REF_TAG)-$(h).pfm))
reference: $(REF_FILES)
ref_render = @mkdir -p $(REF) && echo "  REF     $@" && \
	nice $(B)/bin/cornell_box --scene $(patsubst %-$(REF_TAG)-$(2).pfm,%,$(notdir $@)) \
	    --strategy $(REF_STRATEGY) $(REF_FLAGS) --width $(REF_WIDTH) --spp $(REF_SPP) --seed $(1) \
	    --threads 2 \
	    -o $@ > $@.log
$(REF)/%-a.pfm: | $(B)/bin/cornell_box
	$(call ref_render,1001,a)
$(REF)/%-b.pfm: | $(B)/bin/cornell_box
	$(call ref_render,1002,b)

include mk/rules.mk
include mk/pgo.mk
