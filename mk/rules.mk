# mk/rules.mk - objects, archives and programs.

# The compiler and its flags are recorded in a stamp that changes only when
# they do; every object depends on it, so `make CFLAGS=...` or a Makefile
# flag change rebuilds what it must and nothing else.
FLAGS_STAMP := $(B)/.flags
flags_now = $(CC) $(ALL_CFLAGS) | $(ALL_LDFLAGS) | $(AR) | PGO=$(PGO) (profiled archives apart)
$(FLAGS_STAMP): FORCE
	@mkdir -p $(@D)
	@echo '$(flags_now)' | cmp -s - $@ || echo '$(flags_now)' > $@
FORCE:

# Objects of programs and tests are intermediate files of pattern rules;
# keep them, so that a rebuild recompiles only what changed.
.PRECIOUS: $(B)/obj/%.o $(B)/obj-pgo/%.o

$(B)/obj/%.o: %.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(quiet) "  CC      $<"
	$(Q)$(CC) $(ALL_CFLAGS) $(GEN_DUMPNAME) -c $< -o $@

define layer_rule
$(B)/lib/lib$(1).a: $(call lib_objs,$(1))
	@mkdir -p $$(@D)
	$$(quiet) "  AR      $$@"
	$$(Q)rm -f $$@
	$$(Q)$$(if $$^,$(AR) rcs $$@ $$^,$(AR) rcs $$@)
endef
$(foreach l,$(LAYERS),$(eval $(call layer_rule,$(l))))

$(APP_LIB): $(patsubst %.c,$(B)/obj/%.o,$(APP_SRCS))
	@mkdir -p $(@D)
	$(quiet) "  AR      $@"
	$(Q)rm -f $@
	$(Q)$(AR) rcs $@ $^

$(SUPPORT_LIB): $(patsubst %.c,$(B)/obj/%.o,$(SUPPORT_SRCS))
	@mkdir -p $(@D)
	$(quiet) "  AR      $@"
	$(Q)rm -f $@
	$(Q)$(AR) rcs $@ $^

# Link order is the layer order: a wrong-way call is an undefined symbol.
LINK_LAYERS = $(LIBFILES)

$(B)/bin/%: $(B)/obj/examples/%.o $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

# mcbox-check is split by door (examples/check_cli/: options, the child
# process, --exec, --samples, reports, plot); its parts link with it alone.
CHECK_CLI_OBJS := $(patsubst %.c,$(B)/obj/%.o,$(wildcard examples/check_cli/*.c))
$(B)/bin/mcbox-check: $(B)/obj/examples/mcbox-check.o $(CHECK_CLI_OBJS) $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $(filter %.o,$^) $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

$(B)/bench/%: $(B)/obj/bench/%.o $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

$(B)/tests/%: $(B)/obj/tests/%.o $(SUPPORT_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(SUPPORT_LIB) $(LINK_LAYERS) $(LIBS) $(TEST_LIBS) -o $@

-include $(shell find $(B)/obj $(B)/obj-pgo -name '*.d' 2>/dev/null)
