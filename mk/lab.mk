# mk/lab.mk - the book's warp lab: the catalog, the samplers, the pdf
# objects and the goodness-of-fit harness compiled to WebAssembly, for the
# lab page of the book (book/lab.md, lab/lab.js).
#
#   make lab         $(B)/lab/lab.wasm and lab-wasm.js (the module as a
#                    script, so that a page opened from disk can load it)
#   make lab-deps    the Debian packages it needs, when missing
#
# The compiler is Debian's clang for the wasm32-wasi target, with Debian's
# wasi-libc and compiler-rt builtins and lld as the linker: the same C
# sources as the native build (mc/, samplers/, pdf/, catalog/ and the
# public check, check/, but for the image check's check/image.c), with the
# same warnings, and lab/lab.c and lab/own.c, the glue the page calls. The
# module imports two functions, lab.pdf and lab.invert, from the page: the
# reader's own warp (lab/own.js). mc/quad.c and
# mc/chi2.c call GSL; the few GSL files behind them are compiled from
# Debian's source package of the very GSL the native programs link (the
# version dpkg reports for libgsl-dev), fetched by apt with a private
# package list under $(B)/lab/apt, so that the system's apt configuration
# is left alone. Nothing else comes from the network.

LAB_PACKAGES := clang lld wasi-libc libclang-rt-14-dev-wasm32 libgsl-dev
LAB := $(B)/lab
LAB_CC := clang --target=wasm32-wasi
# No -fopenmp: the module has one thread, and the library's pragmas are
# then ignored. mc/pi.c (OpenMP and x86 clones) and mc/gsl_quiet.c (C11
# threads, which wasi-libc has not) stay out; lab/gsl_quiet.c stands in
# for the latter.
LAB_CFLAGS := -std=c17 $(WARN) -O2 -I. -I$(LAB)/gsl/include -fno-math-errno -MMD -MP
LAB_LIB_SRCS := $(filter-out mc/pi.c mc/gsl_quiet.c check/image.c, \
                  $(wildcard mc/*.c samplers/*.c pdf/*.c catalog/*.c check/*.c)) \
                lab/lab.c lab/own.c lab/gsl_quiet.c
LAB_OBJS := $(patsubst %.c,$(LAB)/obj/%.o,$(LAB_LIB_SRCS))

# The GSL files behind gsl_integration_qags, the Gauss-Legendre tables and
# gsl_cdf_chisq_Q (a link of the module fails if one is missing).
LAB_GSL_FILES := err/error.c err/stream.c err/strerror.c \
                 integration/qags.c integration/workspace.c integration/qk.c integration/qk21.c \
                 integration/glfixed.c cdf/chisq.c cdf/gamma.c \
                 specfunc/gamma_inc.c specfunc/gamma.c specfunc/erfc.c specfunc/exp.c \
                 specfunc/log.c specfunc/psi.c specfunc/zeta.c sys/pow_int.c
LAB_GSL_OBJS := $(patsubst %.c,$(LAB)/gsl/obj/%.o,$(LAB_GSL_FILES))
LAB_GSL_STAMP := $(LAB)/gsl/.unpacked
# GSL's own code is GSL's: built with its own dialect and no warnings of ours.
LAB_GSL_CFLAGS := -std=gnu99 -O2 -w -DHAVE_CONFIG_H -I$(LAB)/gsl/include -I$(LAB)/gsl/src

LAB_EXPORTS := lab_input lab_catalog lab_select lab_error lab_sources lab_chi2 lab_result \
               lab_observed lab_expected lab_line lab_points lab_estimate lab_estimate_table \
               lab_estimate_line lab_own_prepare lab_own_uniforms lab_own_points lab_own_pdfs \
               lab_own_check lab_own_report lab_own_result lab_own_observed lab_own_expected

.PHONY: lab _lab lab-deps

# The size of the module and the time of its build, for the CI's budget.
lab:
	@t0=$$(date +%s%N); $(MAKE) --no-print-directory _lab && \
	    echo "lab: $(LAB)/lab.wasm, $$(wc -c <$(LAB)/lab.wasm) bytes, up to date in $$(( ($$(date +%s%N) - t0) / 1000000 )) ms"
_lab: $(LAB)/lab-wasm.js

lab-deps: deps
	@sh tools/deps.sh --always $(LAB_PACKAGES)

# The public targets that build the book need the lab's tools too.
book book-deps: lab-deps

# Debian's source of the installed GSL, unpacked once per build directory.
$(LAB_GSL_STAMP): lab/gsl_config.h
	@mkdir -p $(LAB)/apt/lists/partial $(LAB)/apt/cache $(LAB)/gsl/include/gsl
	$(quiet) "  APT     gsl source (Debian)"
	$(Q)sh lab/gsl_source.sh $(LAB)/apt $(LAB)/gsl/src
	$(Q)cp $(LAB)/gsl/src/gsl_*.h $(LAB)/gsl/src/*/gsl_*.h $(LAB)/gsl/include/gsl/
	$(Q)cp lab/gsl_config.h $(LAB)/gsl/include/config.h
	@touch $@

$(LAB)/gsl/obj/%.o: $(LAB_GSL_STAMP)
	@mkdir -p $(@D)
	$(quiet) "  WASM    gsl/$*.c"
	$(Q)$(LAB_CC) $(LAB_GSL_CFLAGS) -I$(LAB)/gsl/src/$(*D) -c $(LAB)/gsl/src/$*.c -o $@

$(LAB)/obj/%.o: %.c $(LAB_GSL_STAMP)
	@mkdir -p $(@D)
	$(quiet) "  WASM    $<"
	$(Q)$(LAB_CC) $(LAB_CFLAGS) -c $< -o $@

# A reactor module: no main; _initialize sets up the C library, and the
# page calls the exports.
$(LAB)/lab.wasm: $(LAB_OBJS) $(LAB_GSL_OBJS)
	$(quiet) "  WASM-LD $@"
	$(Q)$(LAB_CC) -mexec-model=reactor -O2 -Wl,--strip-all \
	    $(foreach e,$(LAB_EXPORTS),-Wl,--export=$(e)) $^ -lm -o $@

$(LAB)/lab-wasm.js: $(LAB)/lab.wasm
	$(quiet) "  GEN     $@"
	$(Q){ printf '/* The warp lab module (lab.wasm, %s bytes), base64. */\n' "$$(wc -c <$<)"; \
	      printf 'var MCBOX_LAB_WASM = "'; base64 -w0 <$<; printf '";\n'; } >$@

-include $(shell find $(LAB)/obj -name '*.d' 2>/dev/null)

# The book's lab page ships the module.
_book: lab
