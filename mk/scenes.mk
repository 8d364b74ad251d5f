# mk/scenes.mk - every conformance scene in every exporter's format.
#
# `make scenes` writes $(B)/scenes/NAME.pbrt, NAME.xml, NAME.py and NAME.txt
# for each scene of conform/scenes.c (mcbox-scene export-all), at each
# scene's own size; SCENES_ARGS passes options to it, e.g.
# SCENES_ARGS='--spp 4096 --size 128'. The files are written whole or not at
# all, so an interrupted run leaves no half file for a renderer to read.

.PHONY: scenes
SCENES_ARGS ?=

scenes: $(B)/bin/mcbox-scene
	$(quiet) "  SCENES  $(B)/scenes"
	$(Q)$(B)/bin/mcbox-scene export-all --dir $(B)/scenes $(SCENES_ARGS)
