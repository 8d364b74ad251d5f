# mk/real.mk - the table of the public check's verdicts on light and lobe
# samplers written from their papers (bench/real_samplers_table.c).
#
# The samplers live in the test support library (tests/support/real_samplers.c),
# which test_check_real uses too, so this bench program links that library
# as well as the others. `make real-table` prints the full table (every
# sampler x chart x door at 10^5, 3 x 10^5 and 10^6 samples) and the
# false-alarm rate over 200 seeds, in most of an hour on two cores (so
# `make bench` skips it); REAL_TABLE_ARGS passes options to it, e.g.
# REAL_TABLE_ARGS='--counts 1e5 --doors c --only cone'.

.PHONY: real-table
REAL_TABLE_ARGS ?=

$(B)/bench/real_samplers_table: $(B)/obj/bench/real_samplers_table.o $(SUPPORT_LIB) $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(SUPPORT_LIB) $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@

real-table: $(B)/bench/real_samplers_table $(B)/bin/mcbox-check
	@MC_BUILD=$(B) $(B)/bench/real_samplers_table $(REAL_TABLE_ARGS)

# The table of mcbox's renderer against the conformance scenes
# (bench/conform_table.c): false alarms of the image check over 100 seeds
# per scene and strategy, and the bias it catches at 64 and 1024 spp; a
# quarter of an hour on two cores. CONFORM_TABLE_ARGS, e.g. '--seeds 20'.
.PHONY: conform-table
CONFORM_TABLE_ARGS ?=
conform-table: $(B)/bench/conform_table
	@$(B)/bench/conform_table $(CONFORM_TABLE_ARGS)
