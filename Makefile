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
include mk/mpi.mk

# Debian packages the project needs (see `make deps`).
# fonts-texgyre-math: the book ships its math font (TeX Gyre Pagella Math),
# so that formulas look the same on every reader's machine.
DEB_PACKAGES := build-essential pkg-config libcmocka-dev libgsl-dev gnuplot-nox pandoc libpng-dev \
                libopenexr-dev fonts-texgyre-math

# Link order, highest layer first. The sampler catalog sits above pdf/
# and below the programs; it does not use render/.
LAYERS := conform imageio check catalog render pdf samplers mc
# A layer's archive holds its folder's sources and those of its fast/
# subfolder (render/fast/: the renderer's vector fast path).
lib_srcs = $(wildcard $(1)/*.c $(1)/fast/*.c)
lib_objs = $(patsubst %.c,$(B)/obj/%.o,$(call lib_srcs,$(1)))
LIBFILES := $(foreach l,$(LAYERS),$(B)/lib/lib$(l).a)

APP_SRCS := $(filter-out $(APP_SRCS_OFF),$(wildcard examples/common/*.c))
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
	@echo "make bench     throughput benchmarks and the error tables (rendering the references first)"
	@echo "make reference converged book and lambert images, 600x600 and 300x300, cached in build/"
	@echo "make book-program BOOK_SRC=DIR  the book's own renderer and pi program, which make bench then times beside mcbox"
	@echo "make soak      the statistical tests over SEEDS seeds; prints the failure rate"
	@echo "make plots     every figure under build/plots/"
	@echo "make book      the tutorial as HTML and EPUB under build/book/"
	@echo "make book-check  the book, then its checks: broken fixtures, links, EPUB, a headless browser"
	@echo "make deps      install the Debian packages the project needs, when missing"
	@echo "make clean     remove build/"
	@echo "V=1            show the full compiler command lines"
	@echo "MPI=1          build with Open MPI into build/mpi/ (README, \"Beyond one machine\")"
	@echo "make test-mpi  the programs under mpirun give the bytes of one process"
	@echo "make install   libmcbox, mcbox/check.h, mcbox.pc, the mcbox programs and man pages"
	@echo "               (PREFIX=/usr/local; BINDIR, LIBDIR, INCLUDEDIR, MANDIR, PKGCONFIGDIR; DESTDIR)"
	@echo "make uninstall remove what make install put there (same PREFIX and DESTDIR)"
	@echo "make outside-check  install into build/stage, then build and test outside/ against it"
	@echo "make exercises every reader's exercise: stubs and slips must fail, references pass"
	@echo "make exercise NAME=cosine  judge your answer to one exercise (exercises/README.md)"
	@echo "make real-table  the check's verdicts on samplers from the papers, every door, and its false-alarm rate"
	@echo "make scenes    every conformance scene as pbrt-v4, Mitsuba 3, Blender and table files in build/scenes/"
	@echo "make conform-table  the renderer against the conformance scenes: false alarms and power of the image check"

deps:
	@sh tools/deps.sh $(DEB_PACKAGES)
ifneq ($(MPI_PACKAGES),)
	@sh tools/deps.sh --always $(MPI_PACKAGES)
endif

# What only the book's checks need: a real browser, python3 to drive it
# (over Chromium's DevTools pipe, no extra module), epubcheck.
BOOK_CHECK_PACKAGES := chromium python3 epubcheck
book-deps: deps
	@sh tools/deps.sh --always $(BOOK_CHECK_PACKAGES)

# The public targets first make sure the packages are there, then build in a
# second make so that `-j` cannot start compiling before the install ends.
# Those whose work after the build is a test or a table build with a job per
# processor unless the caller gave -j (a clean `make test` on two cores: the
# build 164 s instead of 240 s; make exercises does the same); those that
# time or plot build as asked.
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
JOBS_UNLESS_GIVEN = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(JOBS))
PUBLIC := bench plots plots-check book
PUBLIC_PARALLEL := test run soak
$(PUBLIC): deps
	@$(MAKE) --no-print-directory _$@
$(PUBLIC_PARALLEL): deps
	@$(MAKE) --no-print-directory $(JOBS_UNLESS_GIVEN) _$@
book-check: book-deps
	@$(MAKE) --no-print-directory _book-check

programs: $(PROGRAMS)
tests: $(TESTS)

_test: all $(TESTS)
	@MC_BUILD=$(B) JUNIT=$(JUNIT) bash tools/run_tests.sh $(TESTS)

_run: all
	@MC_BUILD=$(B) bash tools/run_table.sh

_bench: all reference
	@MC_BUILD=$(B) MC_MPI=$(MPI) MC_REF_BOOK="$(call ref_prefixes,book)" \
	    MC_REF_LAMBERT="$(call ref_prefixes,lambert)" MC_BOOK_PROGRAM="$(wildcard $(BOOK_PROGRAM))" \
	    MC_BOOK_PI="$(wildcard $(BOOK_PI))" \
	    bash tools/run_bench.sh

SEEDS ?= 20
_soak: all $(TESTS)
	@MC_BUILD=$(B) MC_MPI=$(MPI) bash tools/soak.sh $(SEEDS) $(TESTS)

_plots: all
	@$(MAKE) --no-print-directory -f plots/Makefile.inc B=$(B) V=$(V) figures
_plots-check: all
	@$(MAKE) --no-print-directory -f plots/Makefile.inc B=$(B) V=$(V) check
_book: all $(TESTS)
	@$(MAKE) --no-print-directory -f book/Makefile.inc B=$(B) V=$(V) html
_book-check: _book
	@$(MAKE) --no-print-directory -f book/Makefile.inc B=$(B) check

clean:
	rm -rf build

include mk/reference.mk
include mk/rules.mk
include mk/pgo.mk
include mk/install.mk
include mk/fuzz.mk
include mk/exercises.mk
include mk/lab.mk
include mk/real.mk
include mk/scenes.mk
