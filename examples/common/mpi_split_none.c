/* examples/common/mpi_split_none.c - the build without MPI: one process,
 * rank 0 of 1 (examples/common/mpi_split.h). mk/mpi.mk compiles this file
 * or mpi_split.c, never both. */
#include "examples/common/mpi_split.h"

app_mpi app_mpi_start(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    app_mpi m = {0, 1, false, false, 0, 0, NULL, -1};
    return m;
}

void app_mpi_setup_done(app_mpi *m)
{
    (void)m;
}

void app_mpi_sum_u64(const app_mpi *m, uint64_t *v, int n)
{
    (void)m;
    (void)v;
    (void)n;
}

double app_mpi_max_double(const app_mpi *m, double x)
{
    (void)m;
    return x;
}

void app_mpi_poll_stop(app_mpi *m, atomic_int *stop)
{
    (void)m;
    (void)stop;
}

int app_mpi_settle_stop(app_mpi *m, atomic_int *stop)
{
    (void)m;
    return atomic_load(stop);
}

bool app_mpi_sum_u128(const app_mpi *m, uint64_t *words, size_t n)
{
    (void)m;
    (void)words;
    (void)n;
    return true;
}

bool app_mpi_gather_rows(const app_mpi *m, void *rows, size_t row_bytes, int n_rows)
{
    (void)m;
    (void)rows;
    (void)row_bytes;
    (void)n_rows;
    return true;
}

void app_mpi_end(app_mpi *m)
{
    (void)m;
}
