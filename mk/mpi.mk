# mk/mpi.mk - the optional MPI build: `make MPI=1 ...`.
#
# Compiles with Open MPI's mpicc (gcc underneath, so the flags of
# mk/flags.mk hold) into its own directory, build/mpi/ (build/mpi-san/ with
# SAN=1, ...), and links examples/common/mpi_split.c where the default build
# links its stub mpi_split_none.c: no other file includes mpi.h. The
# renderer is not profile-guided there by default (PGO=auto means 0): the
# training would run the MPI program outside mpirun. `make deps` installs
# Debian's Open MPI only when MPI=1.

MPI ?= 0
ifeq ($(MPI),1)
CC := mpicc
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
