# mk/fuzz.mk - libFuzzer targets of the parsers that read other people's
# output: the sample-file reader of `mcbox-check --samples`, the --exec
# protocol's parsers and the image readers of `mcbox-check --image`
# (tests/fuzz/). Built with clang's
# -fsanitize=fuzzer,address,undefined into build/fuzz/, each run for
# FUZZ_SECONDS (default 60) on a working copy of its seed corpus
# (tests/fuzz/corpus/NAME), so what the fuzzer adds stays in build/.
# A crash, a leak or a sanitizer report fails the target, and the run
# ends with the plain "N passed, N failed" line CI sums. The targets run
# JOBS at a time, the Makefile's one count of parallel work (FUZZ_JOBS in
# the environment still decides when set).

FUZZ_SECONDS ?= 60
FUZZ_B := build/fuzz
FUZZ_CC := clang
FUZZ_FLAGS := -std=c17 -g -O1 -I. -fsanitize=fuzzer,address,undefined \
              -fno-sanitize-recover=undefined
# The clang driver and its libFuzzer runtime (Debian 12: clang-14, whose
# fuzzer library ships in libclang-rt-14-dev).
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZERS := samples proto image
fuzz_src_samples := tests/fuzz/fuzz_samples.c examples/common/sample_reader.c
fuzz_src_proto := tests/fuzz/fuzz_proto.c examples/common/exec_proto.c
fuzz_src_image := tests/fuzz/fuzz_image.c imageio/image_io.c imageio/image_exr.c \
                  -lpng -lOpenEXRCore-3_1 -lm

.PHONY: fuzz fuzz-deps _fuzz
fuzz: fuzz-deps
	@$(MAKE) --no-print-directory _fuzz
fuzz-deps:
	@sh tools/deps.sh --always $(FUZZ_PACKAGES)

$(FUZZ_B)/fuzz_%: tests/fuzz/fuzz_%.c examples/common/sample_reader.c examples/common/sample_reader.h \
                  examples/common/exec_proto.c examples/common/exec_proto.h check/check.h \
                  imageio/image_io.c imageio/image_exr.c imageio/image_io.h imageio/internal.h
	@mkdir -p $(@D)
	$(quiet) "  FUZZCC  $@"
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) $(fuzz_src_$*) -o $@

_fuzz: $(foreach f,$(FUZZERS),$(FUZZ_B)/fuzz_$(f))
	@FUZZ_JOBS="$${FUZZ_JOBS:-$(JOBS)}" sh tools/run_fuzz.sh $(FUZZ_B) $(FUZZ_SECONDS) $(FUZZERS)
