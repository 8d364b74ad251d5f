# mk/pgo.mk - profile-guided optimization of the renderer.
#
# For gcc builds without sanitizers (PGO=auto, the default; PGO=0 turns it
# off). An instrumented cornell_box is built under $(B)/pgo-train (PGO=gen)
# and renders a few small images (tools/pgo_train.sh); the library objects
# are then compiled a second time, into $(B)/obj-pgo/, with its counts: gcc
# lays out the hot paths and inlines by them. Only the renderer's programs
# (cornell_box, bench_render, bench_convergence) link those profiled
# archives; the libraries every other program and every test links are the
# plain ones of $(B)/obj/, which wait for no training. The renderer's arithmetic is
# unchanged by the profile, so are its images (docs/performance.md has the
# speed-up measured). -fprofile-partial-training keeps code the training
# never ran optimized as without a profile, not as cold.

ifeq ($(PGO),auto)
PGO := $(if $(filter 10,$(cc_is_gcc)$(SAN)),1,0)
endif
ifeq ($(PGO),gen)
MODE += -fprofile-generate -fprofile-update=single
endif
# -O3 pays only with the profile (without one it measured the same as -O2),
# so the profiled build and its training build use it, every other -O2.
OPT := $(if $(filter-out 0,$(PGO)),-O3,-O2)
PGO_USE_FLAGS := -fprofile-use -fprofile-partial-training -Wno-missing-profile
# gcc tells static functions apart in a profile by their object's dump
# name (by default the object's path), and reads the counts from that name
# plus .gcda. The training build and the profiled build give every library
# object the same dump name under PGO_DIR: the instrumented program writes
# PGO_DIR/render/bvh.c.gcda, the build of obj-pgo/render/bvh.o reads it.
PGO_DIR ?= $(B)/pgo-profile
pgo_dumpname = -dumpdir $(PGO_DIR)/$(dir $<) -dumpbase $(notdir $<)
GEN_DUMPNAME = $(if $(filter gen,$(PGO)),$(pgo_dumpname))

ifeq ($(PGO),1)
# The stamp is rewritten only when the instrumented program had to be
# rebuilt (a source or flag changed), and then the training runs again.
PGO_STAMP := $(B)/.pgo-trained
$(PGO_STAMP): FORCE
	@$(MAKE) --no-print-directory B=$(B)/pgo-train PGO=gen PGO_DIR=$(PGO_DIR) V=$(V) \
	  $(B)/pgo-train/bin/cornell_box
	@if [ ! -f $@ ] || [ $(B)/pgo-train/bin/cornell_box -nt $@ ]; then \
	  sh tools/pgo_train.sh $(B)/pgo-train/bin/cornell_box $(PGO_DIR) && touch $@; fi

$(B)/obj-pgo/%.o: %.c $(FLAGS_STAMP) $(PGO_STAMP)
	@mkdir -p $(@D)
	$(quiet) "  CC PGO  $<"
	$(Q)$(CC) $(ALL_CFLAGS) $(PGO_USE_FLAGS) $(pgo_dumpname) -c $< -o $@

pgo_objs = $(patsubst %.c,$(B)/obj-pgo/%.o,$(call lib_srcs,$(1)))
define pgo_layer_rule
$(B)/lib-pgo/lib$(1).a: $(call pgo_objs,$(1))
	@mkdir -p $$(@D)
	$$(quiet) "  AR      $$@"
	$$(Q)rm -f $$@
	$$(Q)$(AR) rcs $$@ $$^
endef
$(foreach l,$(LAYERS),$(eval $(call pgo_layer_rule,$(l))))

PGO_LIBFILES := $(foreach l,$(LAYERS),$(B)/lib-pgo/lib$(l).a)
RENDER_PROGRAMS := $(B)/bin/cornell_box $(B)/bench/bench_render $(B)/bench/bench_convergence
$(RENDER_PROGRAMS): $(PGO_LIBFILES)
$(RENDER_PROGRAMS): LINK_LAYERS = $(PGO_LIBFILES)
endif
