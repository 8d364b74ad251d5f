/* examples/common/mpi_split.h - one run of a chapter program spread over
 * the processes that `mpirun -np K` starts (Open MPI), with the same bytes
 * of output as one process.
 *
 * Every result of the project is a function of (seed, stream): a unit of
 * work (a block of pi's samples, an image row) gives the same numbers
 * whichever process computes it. A program splits its units by rank
 * (process r of K takes the units whose index is r modulo K), combines
 * integer tallies by summing them and gathers the rows of an image in row
 * order on rank 0, so no floating-point sum ever depends on K. Only rank 0
 * prints and writes files.
 *
 * Failure: a rank that exits, whatever the reason, ends the whole job
 * (mpirun stops the others and returns that exit status; its `-q` keeps
 * mpirun's own banner off stderr). A stop signal (SIGINT, SIGTERM, SIGHUP:
 * mpirun turns a Ctrl-C into SIGTERM to every rank) reaches all ranks
 * through app_mpi_poll_stop, so that the image rendered so far is gathered
 * and written, as by one process.
 *
 * The build without MPI (the default: `make`, no MPI=1) compiles
 * mpi_split_none.c instead of mpi_split.c: rank 0 of 1, every call a no-op,
 * so a program reads the same with and without MPI. An MPI build started
 * without mpirun also runs as rank 0 of 1, without initializing MPI.
 */
#ifndef APP_MPI_SPLIT_H
#define APP_MPI_SPLIT_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct app_mpi {
    int rank;         /* this process, 0 .. size - 1 */
    int size;         /* the number of processes of the run */
    bool active;      /* started by mpirun: MPI is initialized */
    bool stop_sent;   /* this rank has told the others to stop */
    int stops_seen;   /* stop messages received from other ranks */
    int sent_sig;     /* the signal this rank sent (the message's buffer) */
    void *requests;   /* the sends of the stop message (MPI_Request[size]) */
    int saved_stderr; /* rank > 0 during setup: the real stderr, else -1 */
} app_mpi;

/* Joins the run: MPI_Init_thread when a launcher started the process (the
 * environment of Open MPI, PMIx or PMI says so), else rank 0 of 1. Ranks
 * above 0 send stdout to /dev/null for good and stderr until
 * app_mpi_setup_done, so that the errors every rank finds alike (a bad
 * option) are printed once, by rank 0. */
app_mpi app_mpi_start(int *argc, char ***argv);

/* Ends the setup (option parsing, checks every rank makes alike): ranks
 * above 0 get their stderr back, for the errors only they can meet. */
void app_mpi_setup_done(app_mpi *m);

/* Sums n counters over the ranks, in place on every rank. */
void app_mpi_sum_u64(const app_mpi *m, uint64_t *v, int n);

/* The largest of every rank's x, on every rank. */
double app_mpi_max_double(const app_mpi *m, double x);

/* Shares stop signals, from any thread but one call at a time: when *stop
 * is set here, tells the other ranks (once); when another rank has said
 * so, sets *stop to its signal number if it is still 0. Cheap enough for
 * every image row. */
void app_mpi_poll_stop(app_mpi *m, atomic_int *stop);

/* Called by every rank once its work is done or stopped: the signal that
 * stopped any rank (the largest number), 0 if none; every stop message is
 * received and every send completed, so nothing is left in flight. */
int app_mpi_settle_stop(app_mpi *m, atomic_int *stop);

/* Gathers, on rank 0, rows of row_bytes bytes each (n_rows in all, at
 * `rows`): row y comes from rank y % size, which computed it; the other
 * ranks only send. row_bytes at most INT_MAX. Returns false when a
 * transfer fails. */
bool app_mpi_gather_rows(const app_mpi *m, void *rows, size_t row_bytes, int n_rows);

/* Sums, on rank 0, n 128-bit two's-complement integers stored as pairs
 * of words (low word first, then high: words[2 i], words[2 i + 1]) over
 * the ranks, in place; the other ranks only send. Integer sums do not
 * depend on the order of the terms, so neither does the result. Returns
 * false when a transfer fails. */
bool app_mpi_sum_u128(const app_mpi *m, uint64_t *words, size_t n);

/* Leaves the run (MPI_Finalize when active). */
void app_mpi_end(app_mpi *m);

#endif /* APP_MPI_SPLIT_H */
