# mk/reference.mk - `make reference`: the converged images the error tables
# of `make bench` are measured against.
#
# Converged references: two independent renders (seeds 1001 and 1002) of
# each scene, whose mean is the reference and whose difference measures its
# own noise (bench/bench_render.c). The settings are in the file names, so
# that changing them renders new ones; a render, once done, is kept. The
# strategy is the one with the least error per second, bdpt with Russian
# roulette (about 80 s an image of 300 x 300 on two cores, 6 min at
# 600 x 600): its noise is some 13 times below that of mixture references
# of the same size and samples, and tests/test_render_bdpt.c holds it to
# mixture region by region. REF_WIDTH lists the sizes, the book's own
# 600 x 600 first and a quicker 300 x 300 second; `make reference
# REF_WIDTH=300` renders one.
REF := $(B)/reference
space := $(subst ,, )
REF_WIDTH ?= 600 300
REF_SPP ?= 1024
REF_STRATEGY ?= bdpt
REF_FLAGS ?= --roulette
ref_tag = $(REF_STRATEGY)$(subst --,-,$(subst $(space),,$(REF_FLAGS)))-$(1)-$(REF_SPP)
# The prefixes of one scene's references, one per width (bench_render's
# MC_REF_BOOK and MC_REF_LAMBERT).
ref_prefixes = $(foreach w,$(REF_WIDTH),$(REF)/$(1)-$(call ref_tag,$(w)))
REF_FILES := $(foreach s,book lambert,$(foreach p,$(call ref_prefixes,$(s)),$(p)-a.pfm $(p)-b.pfm))
reference: $(REF_FILES)
# $(1) the seed, $(2) the width; the stem is the scene.
ref_render = @mkdir -p $(REF) && echo "  REF     $@" && \
	nice $(B)/bin/cornell_box --scene $* \
	    --strategy $(REF_STRATEGY) $(REF_FLAGS) --width $(2) --spp $(REF_SPP) --seed $(1) \
	    --threads 2 \
	    -o $@ > $@.log
define ref_rules
$(REF)/%-$(call ref_tag,$(1))-a.pfm: | $(B)/bin/cornell_box
	$$(call ref_render,1001,$(1))
$(REF)/%-$(call ref_tag,$(1))-b.pfm: | $(B)/bin/cornell_box
	$$(call ref_render,1002,$(1))
endef
$(foreach w,$(REF_WIDTH),$(eval $(call ref_rules,$(w))))

# make book-program BOOK_SRC=DIR: the book's own programs, from a checkout
# of its code at v1.123.0 that the user makes (tools/book_program.sh says
# how): the renderer for the book's 600 x 600 render at 100 spp, and pi.cc
# at 10000^2 iterations. When they are there, make bench times them on this
# machine and measures every x_book figure, and bench_mc's "vs book"
# column, against those times instead of the constants (68.3 s, 26 M
# points/s) of another machine.
BOOK_PROGRAM := $(B)/book-program/book
BOOK_PI := $(B)/book-program/pi
.PHONY: book-program
book-program:
	@test -n "$(BOOK_SRC)" || { echo "make book-program: BOOK_SRC=DIR is needed, a checkout of the book's code: git clone --branch v1.123.0 https://github.com/petershirley/raytracingtherestofyourlife" >&2; exit 2; }
	@sh tools/book_program.sh "$(BOOK_SRC)" $(BOOK_PROGRAM)
