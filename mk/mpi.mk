# mk/mpi.mk - the optional MPI build: `make MPI=1 ...`.
#
# Compiles with Open MPI's mpicc (gcc underneath, so the flags of
# mk/flags.mk hold) into its own directory, build/mpi/ (build/mpi-san/ with
# SAN=1, ...), and links examples/common/mpi_split.c where the default build
# links its stub mpi_split_none.c: no other file includes mpi.h. The
# renderer is not profile-guided there by default (PGO=auto means 0): the
# training would run the MPI program outside mpirun. `make deps` installs
# Debian's Open MPI only when MPI=1.
#
# make test-mpi: the MPI programs under mpirun against the plain ones
# (tests/mpi/run.sh); it builds both, the plain ones in their usual
# directory with the PGO setting they would have had.

MPI ?= 0
MPI_REF := $(B)
MPI_BASE_PGO := $(PGO)
ifeq ($(MPI),1)
# mpicc runs the compiler mk/flags.mk chose (CC=clang: build/mpi-clang/).
export OMPI_CC := $(CC)
override CC := mpicc
B := build/mpi$(if $(variant),-$(variant))
ifeq ($(PGO),auto)
PGO := 0
endif
MPI_PACKAGES := libopenmpi-dev openmpi-bin
APP_SRCS_OFF := examples/common/mpi_split_none.c
else
MPI_PACKAGES :=
APP_SRCS_OFF := examples/common/mpi_split.c
endif

# The targets below come first in the Makefile's reading order; `make`
# alone still builds `all`.
.DEFAULT_GOAL := all

.PHONY: test-mpi _test-mpi
ifeq ($(MPI),1)
test-mpi: deps
	@$(MAKE) --no-print-directory _test-mpi
_test-mpi: all
	@$(MAKE) --no-print-directory MPI=0 PGO=$(MPI_BASE_PGO) $(MPI_REF)/bin/pi $(MPI_REF)/bin/cornell_box $(MPI_REF)/bin/qmc
	@MC_BUILD=$(B) MC_REF=$(MPI_REF) bash tests/mpi/run.sh
else
test-mpi:
	@$(MAKE) --no-print-directory MPI=1 test-mpi
endif

# Measuring programs of docs/scaling.md (tests/mpi/*.c, not tests): the
# rate rank 0 hands out units and receives rows, and the cost of each row.
ifeq ($(MPI),1)
MPI_TOOLS := $(patsubst tests/mpi/%.c,$(B)/tests-mpi/%,$(wildcard tests/mpi/*.c))
$(B)/tests-mpi/%: $(B)/obj/tests/mpi/%.o $(APP_LIB) $(LIBFILES)
	@mkdir -p $(@D)
	$(quiet) "  LD      $@"
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(APP_LIB) $(LINK_LAYERS) $(LIBS) -o $@
endif
ifeq ($(MPI),1)
_bench: $(MPI_TOOLS)
endif
