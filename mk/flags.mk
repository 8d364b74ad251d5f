# mk/flags.mk - the compiler, the build variant and its flags.
#
# Variants never share objects: the default build goes to build/, clang to
# build/clang/, the sanitizer build (SAN=1) to build/san/ (or
# build/clang-san/), NATIVE=1 to build/native/.

CC ?= cc
CFLAGS ?= $(OPT) -g
LDFLAGS ?=
SAN ?= 0
NATIVE ?= 0
JUNIT ?= 0
PGO ?= auto

compiler := $(notdir $(firstword $(CC)))
variant := $(if $(filter clang%,$(compiler)),clang)
variant := $(variant)$(if $(filter 1,$(SAN)),$(if $(variant),-)san)
variant := $(variant)$(if $(filter 1,$(NATIVE)),$(if $(variant),-)native)
B := build$(if $(variant),/$(variant))

WARN := -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wdouble-promotion
MODE :=
ifeq ($(SAN),1)
MODE += -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
endif
ifeq ($(NATIVE),1)
MODE += -march=native
endif
# Link-time optimization for gcc builds (not clang, not the sanitizer build):
# the renderer's hot path crosses the render/pdf/samplers/mc archives, and
# only LTO lets gcc inline across them (bench_render: about 15% faster, same
# image). Archives of LTO objects need gcc-ar, which passes the LTO plugin.
cc_is_gcc := $(shell $(CC) -v 2>&1 | grep -q '^gcc version' && echo 1)
AR := ar
ifeq ($(cc_is_gcc)$(SAN),10)
MODE += -flto=auto
AR := gcc-ar
endif
# -fno-math-errno: nothing reads errno after a math function, and without
# it every sqrt carries a test and a call for the negative case (4% of the
# renderer's instructions). Results are unchanged: IEEE semantics stay.
ALL_CFLAGS = -std=c17 $(WARN) -I. -fopenmp -fno-math-errno $(MODE) -MMD -MP $(CFLAGS)
ALL_LDFLAGS = -fopenmp $(MODE) $(LDFLAGS)
# Debian's library names; no pkg-config at parse time, because `make deps`
# may be what installs pkg-config.
LIBS := -lgsl -lgslcblas -lpng -lOpenEXRCore-3_1 -lm
TEST_LIBS := -lcmocka

# Quiet by default: one short line per file ("  CC  mc/rng.c"); V=1 shows
# the full compiler and archiver command lines, as kbuild and automake do.
V ?= 0
ifeq ($(V),1)
Q :=
quiet := @:
else
Q := @
quiet := @echo
endif
