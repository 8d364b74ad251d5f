# mk/exercises.mk - the readers' exercises (exercises/README.md).
#
#   make exercises             every exercise in every build, ONE table: the
#                              reader's build (the stub as shipped) must FAIL,
#                              the reference and every correct alternative
#                              must PASS, every slip must FAIL, and fail the
#                              check it names; exit status 1 otherwise.
#                              Prints, per exercise, its consistent slips and
#                              alternatives, and its total time.
#   make exercise NAME=cosine  the reader's build of one exercise: its
#                              figures, its verdict and its picture (gnuplot)
#
# The builds of each exercise, one compilation each, into
# $(B)/exercises/obj/: NAME.o (the reader's file as it is), NAME-ref.o
# (-DEX_REFERENCE), NAME-slipK.o (-DSLIP=K) and NAME-altK.o (-DALT=K). The
# slips and alternatives of an exercise are read from its fixture,
# exercises/fixtures/NAME.h (one "#elif SLIP == K" or "#elif ALT == K"
# each), so adding one is editing that file only.
#
# Linking: the shared judge (check_exercise.o) and the archives it and the
# references use (the check, the catalog and the layers below render/,
# whole, highest first) are linked ONCE into the relocatable object
# judge.o; gcc's LTO runs there
# (-flinker-output=nolto-rel: the result is plain machine code), and the
# exercises compile without LTO. The reader's program $(B)/exercises/NAME
# is NAME.o and judge.o; `make exercises` links all the builds of an
# exercise into one program, NAME-all, the fixtures' with their ex_this
# renamed (check_exercise.c, find_build), and picks a build with --build.
# Linking each of the ~70 builds on its own, or the LTO archives into each,
# would cost more than the one-minute budget of `make exercises` allows.

EXERCISES := pi importance inverse-cdf sphere hemisphere cosine disc cone quad-light mixture \
             power-heuristic hammersley lambert
EX_DIR := $(B)/exercises
EX_JUDGE := $(EX_DIR)/judge.o
EX_LAYERS := $(filter-out conform imageio render,$(LAYERS))
EX_NOLTO := $(if $(filter -flto%,$(MODE)),-flinker-output=nolto-rel)
ex_slips = $(shell sed -n 's/^\#\(el\)*if SLIP == \([0-9][0-9]*\).*/\2/p' \
             exercises/fixtures/$(1).h 2>/dev/null)
ex_alts = $(shell sed -n 's/^\#\(el\)*if ALT == \([0-9][0-9]*\).*/\2/p' \
             exercises/fixtures/$(1).h 2>/dev/null)
ex_builds = $(1) $(1)-ref $(foreach k,$(call ex_slips,$(1)),$(1)-slip$(k)) \
            $(foreach k,$(call ex_alts,$(1)),$(1)-alt$(k))
EX_ALL := $(patsubst %,$(EX_DIR)/%-all,$(EXERCISES))
# The exercises' objects are plain code: no LTO, whatever the variant.
EX_CFLAGS = $(ALL_CFLAGS) -fno-lto

.PHONY: exercises exercise _exercises-build

$(EX_JUDGE): $(B)/obj/exercises/check_exercise.o $(foreach l,$(EX_LAYERS),$(B)/lib/lib$(l).a)
	@mkdir -p $(@D)
	$(quiet) "  LD -r   $@"
	$(Q)$(CC) $(ALL_LDFLAGS) -r $(EX_NOLTO) $< -Wl,--whole-archive \
	  $(foreach l,$(EX_LAYERS),$(B)/lib/lib$(l).a) -Wl,--no-whole-archive -o $@

# $(1): the build, $(2): the exercise, $(3): its defines.
define ex_object
$(EX_DIR)/obj/$(1).o: exercises/$(2).c $(FLAGS_STAMP)
	@mkdir -p $$(@D)
	$$(quiet) "  CC      $$< $(3)"
	$$(Q)$$(CC) $$(EX_CFLAGS) $(3) -c $$< -o $$@
endef
# $(1): the exercise.
define ex_programs
$(call ex_object,$(1),$(1),)
$(call ex_object,$(1)-ref,$(1),-DEX_REFERENCE -Dex_this=ex_build_ref)
$(foreach k,$(call ex_slips,$(1)),$(call ex_object,$(1)-slip$(k),$(1),-DSLIP=$(k) -Dex_this=ex_build_slip$(k))
)
$(foreach k,$(call ex_alts,$(1)),$(call ex_object,$(1)-alt$(k),$(1),-DALT=$(k) -Dex_this=ex_build_alt$(k))
)
$(EX_DIR)/$(1): $(EX_DIR)/obj/$(1).o $(EX_JUDGE)
	$$(quiet) "  LD      $$@"
	$$(Q)$$(CC) $$^ $$(LIBS) $$(ALL_LDFLAGS) -fno-lto -o $$@
$(EX_DIR)/$(1)-all: $(patsubst %,$(EX_DIR)/obj/%.o,$(call ex_builds,$(1))) $(EX_JUDGE)
	$$(quiet) "  LD      $$@"
	$$(Q)$$(CC) $$^ $$(LIBS) $$(ALL_LDFLAGS) -fno-lto -o $$@
endef
$(foreach e,$(EXERCISES),$(eval $(call ex_programs,$(e))))

_exercises-build: $(EX_ALL)

exercises:
	@start=$$(date +%s.%N); \
	$(MAKE) --no-print-directory $(JOBS_UNLESS_GIVEN) _exercises-build && \
	EX_START=$$start sh exercises/run.sh $(EX_DIR) $(foreach e,$(EXERCISES),$(call ex_builds,$(e)))

exercise:
	@test -n "$(NAME)" -a -f "exercises/$(NAME).c" || \
	  { echo "make exercise: NAME must be one of: $(EXERCISES)" >&2; exit 2; }
	@$(MAKE) --no-print-directory $(EX_DIR)/$(NAME)
	@mkdir -p $(EX_DIR)/plots
	@rm -f $(EX_DIR)/plots/$(NAME)-*.gp
	@status=0; $(EX_DIR)/$(NAME) --plot $(EX_DIR)/plots || status=$$?; \
	for gp in $(EX_DIR)/plots/$(NAME)-*.gp; do \
	  [ -f "$$gp" ] || continue; \
	  if command -v gnuplot >/dev/null 2>&1; then \
	    gnuplot "$$gp" && echo "picture: $${gp%.gp}.png"; \
	  else echo "(no gnuplot: the picture's data is $${gp%.gp}.dat)"; fi; \
	done; exit $$status

-include $(wildcard $(EX_DIR)/obj/*.d)

# The book runs each exercise's reference (NAME-all --build ref), so a
# broken exercise stops the book's build like a broken listing.
_book: $(EX_ALL)
