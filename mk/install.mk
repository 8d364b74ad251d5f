# mk/install.mk - make install / uninstall, and the outside project's check.
#
# What a user of mcbox gets: libmcbox (shared, with a soname, and static),
# the public headers mcbox/check.h and mcbox/image.h, mcbox.pc for pkg-config, the
# programs mcbox, mcbox-check, mcbox-warp and mcbox-scene, and their man
# pages. GNU conventions: every directory derives from PREFIX unless given,
# and DESTDIR (a staging root for packagers) is prepended when copying only,
# so no installed file names it. Nothing compiled depends on PREFIX either:
# mcbox.pc is written at install time from mk/mcbox.pc.in, and mcbox finds
# its commands beside its own executable. So `make install PREFIX=/opt/x`
# after `make install` copies again and compiles nothing.
#
# The library is compiled a second time, into $(B)/obj-pic/: position
# independent, without LTO (an archive of gcc's LTO objects links with gcc
# of the same version only, not with clang), without sanitizers and
# without the renderer's profile. render/ is not part of it.

PREFIX ?= /usr/local
BINDIR ?= $(PREFIX)/bin
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
MANDIR ?= $(PREFIX)/share/man
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
DESTDIR ?=
INSTALL ?= install
INSTALL_PROGRAM ?= $(INSTALL) -m 755
INSTALL_DATA ?= $(INSTALL) -m 644

# The version is the header's (MCBOX_VERSION_MAJOR, _MINOR, _PATCH), the
# soname's number its major.
MCBOX_VERSION := $(shell awk '/^.define MCBOX_VERSION_(MAJOR|MINOR|PATCH) / \
                   { v = v sep $$3; sep = "." } END { print v }' check/check.h 2>/dev/null)
MCBOX_SOVERSION := $(firstword $(subst ., ,$(MCBOX_VERSION)))
SO_REAL := libmcbox.so.$(MCBOX_VERSION)
SO_NAME := libmcbox.so.$(MCBOX_SOVERSION)

PIC_LAYERS := check catalog pdf samplers mc
PIC_OBJS := $(patsubst %.c,$(B)/obj-pic/%.o,$(foreach l,$(PIC_LAYERS),$(call lib_srcs,$(l))))
PIC_LIB := $(B)/lib-pic
# -O2 -g unless CFLAGS is given on the command line or in the environment:
# the default CFLAGS follows PGO's -O3, which pays only with a profile.
PIC_OPT := $(if $(filter file,$(origin CFLAGS)),-O2 -g,$(CFLAGS))
PIC_CFLAGS = -std=c17 $(WARN) -I. -fopenmp -fno-math-errno -fPIC -fno-semantic-interposition \
             -MMD -MP $(PIC_OPT)
# The shared library carries its own dependencies (NEEDED: libgsl, which
# brings libgslcblas, the OpenMP runtime, libm); --no-undefined makes a
# missing one an error here rather than in a user's link.
SO_LDFLAGS = -shared -fopenmp -Wl,-soname,$(SO_NAME) -Wl,--version-script=mk/mcbox.map \
             -Wl,--no-undefined $(LDFLAGS)
SO_LIBS := -lgsl -lgslcblas -lm
# The OpenMP runtime a static link needs (mcbox.pc's Libs.private): gcc's
# -fopenmp calls libgomp; clang's calls LLVM's libomp, which Debian keeps
# outside the linker's path, where only clang's own -fopenmp finds it.
OMP_LIBS := $(if $(cc_is_gcc),-lgomp,-fopenmp)

# mcbox.pc finds the install from where it lies: prefix is ${pcfiledir}
# and the way up from PKGCONFIGDIR to PREFIX ("../.." for lib/pkgconfig),
# so that a staged install (DESTDIR) or a moved tree answers with its own
# headers and library through PKG_CONFIG_PATH alone. A PKGCONFIGDIR outside
# PREFIX cannot say where PREFIX is: then prefix is written as it is.
pc_empty :=
pc_space := $(pc_empty) $(pc_empty)
PC_REL := $(patsubst $(PREFIX)/%,%,$(PKGCONFIGDIR))
PC_UP := $(subst $(pc_space),/,$(foreach d,$(subst /, ,$(PC_REL)),..))
PC_PREFIX = $(if $(filter $(PKGCONFIGDIR),$(PC_REL)),$(PREFIX),$${pcfiledir}/$(PC_UP))

MAN_PAGES := mcbox mcbox-check mcbox-warp mcbox-scene
MAN_OUT := $(patsubst %,$(B)/man/man1/%.1,$(MAN_PAGES))

# Installed name = built program; nothing generic (warp, pi, ...) reaches BINDIR.
INSTALL_PROGRAMS := mcbox=mcbox mcbox-check=mcbox-check mcbox-warp=warp mcbox-scene=mcbox-scene
INSTALL_BUILT := $(foreach p,$(INSTALL_PROGRAMS),$(B)/bin/$(lastword $(subst =, ,$(p)))) \
                 $(PIC_LIB)/$(SO_REAL) $(PIC_LIB)/libmcbox.a $(MAN_OUT)

.PHONY: install uninstall _install outside-check _outside-check

PIC_STAMP := $(B)/.flags-pic
pic_flags_now = $(CC) $(PIC_CFLAGS) | $(SO_LDFLAGS) $(SO_LIBS)
$(PIC_STAMP): FORCE
	@mkdir -p $(@D)
	@echo '$(pic_flags_now)' | cmp -s - $@ || echo '$(pic_flags_now)' > $@

$(B)/obj-pic/%.o: %.c $(PIC_STAMP)
	@mkdir -p $(@D)
	$(quiet) "  CC PIC  $<"
	$(Q)$(CC) $(PIC_CFLAGS) -c $< -o $@

$(PIC_LIB)/$(SO_REAL): $(PIC_OBJS) mk/mcbox.map
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(SO_LDFLAGS) $(PIC_OBJS) $(SO_LIBS) -o $@
	$(Q)ln -sf $(SO_REAL) $(PIC_LIB)/$(SO_NAME)
	$(Q)ln -sf $(SO_NAME) $(PIC_LIB)/libmcbox.so

# The static library is one relocatable object in which only the mcbox_
# names stay global, as in the shared library: a user's program linked
# with it cannot collide with the internal mc_, smp_, pdf_ or vec3_ names.
$(PIC_LIB)/libmcbox.a: $(PIC_OBJS)
	@mkdir -p $(@D)
	$(quiet) "  AR      $@"
	$(Q)$(CC) -r -nostdlib $(PIC_OBJS) -o $(PIC_LIB)/mcbox.o
	$(Q)objcopy --wildcard --keep-global-symbol='mcbox_*' $(PIC_LIB)/mcbox.o
	$(Q)rm -f $@
	$(Q)ar rcs $@ $(PIC_LIB)/mcbox.o
	$(Q)rm -f $(PIC_LIB)/mcbox.o

$(B)/man/man1/%.1: man/%.1.md
	@mkdir -p $(@D)
	$(quiet) "  MAN     $@"
	$(Q)pandoc -s -t man $< -o $@

install: deps
	@$(MAKE) --no-print-directory _install

_install: $(INSTALL_BUILT)
	@test -n '$(MCBOX_VERSION)' || { echo 'make install: no version in check/check.h' >&2; exit 1; }
	$(INSTALL) -d '$(DESTDIR)$(BINDIR)' '$(DESTDIR)$(LIBDIR)' '$(DESTDIR)$(INCLUDEDIR)/mcbox' \
	  '$(DESTDIR)$(PKGCONFIGDIR)' '$(DESTDIR)$(MANDIR)/man1'
	for p in $(INSTALL_PROGRAMS); do \
	  $(INSTALL_PROGRAM) "$(B)/bin/$${p#*=}" "$(DESTDIR)$(BINDIR)/$${p%%=*}" || exit 1; done
	$(INSTALL_DATA) $(PIC_LIB)/$(SO_REAL) $(PIC_LIB)/libmcbox.a '$(DESTDIR)$(LIBDIR)/'
	ln -sf $(SO_REAL) '$(DESTDIR)$(LIBDIR)/$(SO_NAME)'
	ln -sf $(SO_NAME) '$(DESTDIR)$(LIBDIR)/libmcbox.so'
	$(INSTALL_DATA) check/check.h '$(DESTDIR)$(INCLUDEDIR)/mcbox/check.h'
	$(INSTALL_DATA) check/image.h '$(DESTDIR)$(INCLUDEDIR)/mcbox/image.h'
	$(INSTALL_DATA) $(MAN_OUT) '$(DESTDIR)$(MANDIR)/man1/'
	sed -e '/^##/d' -e 's|@PREFIX@|$(PC_PREFIX)|' \
	    -e 's|@LIBDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(LIBDIR))|' \
	    -e 's|@INCLUDEDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(INCLUDEDIR))|' \
	    -e 's|@VERSION@|$(MCBOX_VERSION)|' -e 's|@OMP_LIBS@|$(OMP_LIBS)|' mk/mcbox.pc.in > '$(DESTDIR)$(PKGCONFIGDIR)/mcbox.pc'
	chmod 644 '$(DESTDIR)$(PKGCONFIGDIR)/mcbox.pc'
	@# The dynamic linker finds a new library in /usr/local/lib only after
	@# ldconfig; a staged install (DESTDIR) is not the system's.
	@if [ -z '$(DESTDIR)' ] && [ "$$(id -u)" = 0 ] && command -v ldconfig >/dev/null; then \
	  ldconfig; fi

# Removes exactly what _install put there, and include/mcbox when empty.
uninstall:
	rm -f $(foreach p,$(INSTALL_PROGRAMS),'$(DESTDIR)$(BINDIR)/$(firstword $(subst =, ,$(p)))')
	rm -f '$(DESTDIR)$(LIBDIR)/$(SO_REAL)' '$(DESTDIR)$(LIBDIR)/$(SO_NAME)' \
	  '$(DESTDIR)$(LIBDIR)/libmcbox.so' '$(DESTDIR)$(LIBDIR)/libmcbox.a'
	rm -f '$(DESTDIR)$(INCLUDEDIR)/mcbox/check.h' '$(DESTDIR)$(INCLUDEDIR)/mcbox/image.h' \
	    '$(DESTDIR)$(PKGCONFIGDIR)/mcbox.pc'
	rm -f $(foreach m,$(MAN_PAGES),'$(DESTDIR)$(MANDIR)/man1/$(m).1')
	rmdir '$(DESTDIR)$(INCLUDEDIR)/mcbox' 2>/dev/null || true
	@if [ -z '$(DESTDIR)' ] && [ "$$(id -u)" = 0 ] && command -v ldconfig >/dev/null; then \
	  ldconfig; fi

# The outside project (outside/): built and run against a staged install
# only (tools/outside_check.sh says what it checks). python3 runs its
# Python sampler.
OUTSIDE_PACKAGES := python3
outside-check: deps
	@sh tools/deps.sh --always $(OUTSIDE_PACKAGES)
	@$(MAKE) --no-print-directory _outside-check
_outside-check:
	+@MAKE='$(MAKE)' B='$(B)' CC='$(CC)' bash tools/outside_check.sh

-include $(shell find $(B)/obj-pic -name '*.d' 2>/dev/null)

# The book's chapter on testing your own sampler compiles a user's program
# against the static library of this build tree.
_book: $(PIC_LIB)/libmcbox.a
