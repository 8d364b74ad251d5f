# mk/reference.mk - `make reference`: the converged images the error table
# of `make bench` is measured against.
#
# Converged references: two independent renders (seeds 1001 and 1002) of
# each scene, whose mean is the reference and whose difference measures its
# own noise (bench/bench_render.c). The settings are in the file names, so
# that changing them renders new ones; a render, once done, is kept. The
# strategy is the one with the least error per second, bdpt with Russian
# roulette (about 80 s an image on two cores): its noise is some 13 times
# below that of mixture references of the same size and samples, and
# tests/test_render_bdpt.c holds it to mixture region by region.
REF := $(B)/reference
space := $(subst ,, )
REF_WIDTH ?= 300
REF_SPP ?= 1024
REF_STRATEGY ?= bdpt
REF_FLAGS ?= --roulette
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
