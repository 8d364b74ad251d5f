/* examples/common/mpi_split.c - the MPI side of examples/common/mpi_split.h,
 * compiled only by `make MPI=1` (with mpicc). */
#define _POSIX_C_SOURCE 200809L

#include "examples/common/mpi_split.h"

#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <mpi.h>

enum { TAG_STOP = 1, TAG_ROW = 2 };

/* Open MPI's mpirun, PMIx launchers and MPICH's Hydra (PMI) each leave
 * their mark in the environment of the processes they start. */
static bool launched(void)
{
    static const char *const marks[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
    for (size_t i = 0; i < sizeof marks / sizeof marks[0]; i++)
        if (getenv(marks[i]))
            return true;
    return false;
}

app_mpi app_mpi_start(int *argc, char ***argv)
{
    app_mpi m = {0, 1, false, false, 0, 0, NULL, -1};
    if (!launched())
        return m;
    /* SERIALIZED: the renderer's threads call app_mpi_poll_stop, one at
     * a time (its progress callback runs in a critical section). */
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
    m.active = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &m.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m.size);
    if (provided < MPI_THREAD_SERIALIZED && m.rank == 0) {
        const char *prog = *argc > 0 ? strrchr((*argv)[0], '/') : NULL;
        prog = prog ? prog + 1 : *argc > 0 ? (*argv)[0] : "mpi";
        fprintf(stderr, "%s: warning: MPI gives thread level %d, below MPI_THREAD_SERIALIZED\n", prog,
                provided);
    }
    if (m.rank > 0) {
        fflush(stdout);
        fflush(stderr);
        int null = open("/dev/null", O_WRONLY);
        m.saved_stderr = dup(STDERR_FILENO);
        if (null >= 0) {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            close(null);
        }
    }
    return m;
}

void app_mpi_setup_done(app_mpi *m)
{
    /* Open MPI connects two ranks at their first message, through its
     * runtime (PMIx) in mpirun. After a Ctrl-C mpirun is busy ending the
     * job and leaves the ranks one second: the stop messages and the image
     * must not wait for connections then. One int from every rank to every
     * rank makes them all now. */
    if (m->active && m->size > 1) {
        int *ping = calloc(2 * (size_t)m->size, sizeof *ping);
        if (!ping)
            MPI_Abort(MPI_COMM_WORLD, 1);
        MPI_Alltoall(ping, 1, MPI_INT, ping + m->size, 1, MPI_INT, MPI_COMM_WORLD);
        free(ping);
    }
    if (m->saved_stderr >= 0) {
        fflush(stderr);
        dup2(m->saved_stderr, STDERR_FILENO);
        close(m->saved_stderr);
        m->saved_stderr = -1;
    }
}

void app_mpi_sum_u64(const app_mpi *m, uint64_t *v, int n)
{
    if (m->active)
        MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
}

double app_mpi_max_double(const app_mpi *m, double x)
{
    if (m->active)
        MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return x;
}

void app_mpi_poll_stop(app_mpi *m, atomic_int *stop)
{
    if (!m->active || m->size == 1)
        return;
    int sig = atomic_load(stop);
    if (sig != 0 && !m->stop_sent) {
        MPI_Request *req = malloc((size_t)m->size * sizeof *req);
        if (!req) /* cannot tell the others: end the whole job */
            MPI_Abort(MPI_COMM_WORLD, 128 + sig);
        m->sent_sig = sig; /* the message: one int, the signal number */
        for (int r = 0; r < m->size; r++)
            req[r] = MPI_REQUEST_NULL;
        for (int r = 0; r < m->size; r++)
            if (r != m->rank)
                MPI_Isend(&m->sent_sig, 1, MPI_INT, r, TAG_STOP, MPI_COMM_WORLD, &req[r]);
        m->requests = req;
        m->stop_sent = true;
    }
    for (;;) {
        int flag = 0, theirs = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, TAG_STOP, MPI_COMM_WORLD, &flag, &st);
        if (!flag)
            break;
        MPI_Recv(&theirs, 1, MPI_INT, st.MPI_SOURCE, TAG_STOP, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        m->stops_seen++;
        int zero = 0;
        atomic_compare_exchange_strong(stop, &zero, theirs);
    }
}

int app_mpi_settle_stop(app_mpi *m, atomic_int *stop)
{
    if (!m->active || m->size == 1)
        return atomic_load(stop);
    app_mpi_poll_stop(m, stop);
    /* Every rank that sent, sent to every other rank: the messages still
     * to come are the senders' count less this rank's own. One
     * collective: entry r says whether rank r sent, the last the largest
     * signal number. */
    int n = m->size + 1, *said = calloc((size_t)n, sizeof *said);
    if (!said)
        MPI_Abort(MPI_COMM_WORLD, 1);
    said[m->rank] = m->stop_sent;
    said[m->size] = m->stop_sent ? m->sent_sig : atomic_load(stop);
    MPI_Allreduce(MPI_IN_PLACE, said, n, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    int senders = 0, sig = said[m->size];
    for (int r = 0; r < m->size; r++)
        senders += said[r];
    free(said);
    for (int left = senders - (m->stop_sent ? 1 : 0) - m->stops_seen; left > 0; left--) {
        int theirs = 0;
        MPI_Recv(&theirs, 1, MPI_INT, MPI_ANY_SOURCE, TAG_STOP, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        m->stops_seen++;
    }
    if (m->requests) {
        MPI_Waitall(m->size, m->requests, MPI_STATUSES_IGNORE);
        free(m->requests);
        m->requests = NULL;
    }
    return sig;
}

/* Rows per message: whole rows, at most about 1 GB (a message's count is
 * an int). */
static int rows_per_message(size_t row_bytes)
{
    size_t n = ((size_t)1 << 30) / row_bytes;
    return n < 1 ? 1 : n > INT_MAX ? INT_MAX : (int)n;
}

/* Copies rows first, first + step, ... (count of them) between the image
 * and a packed buffer, in either direction. */
static void pack(unsigned char *image, unsigned char *packed, size_t row_bytes, int first, int step,
                 int count, bool to_packed)
{
    for (int i = 0; i < count; i++) {
        unsigned char *row = image + (size_t)(first + i * step) * row_bytes;
        unsigned char *p = packed + (size_t)i * row_bytes;
        memcpy(to_packed ? p : row, to_packed ? row : p, row_bytes);
    }
}

bool app_mpi_gather_rows(const app_mpi *m, void *rows, size_t row_bytes, int n_rows)
{
    if (!m->active || m->size == 1)
        return true;
    if (row_bytes > INT_MAX)
        return false;
    /* Each rank's rows travel packed, a few large messages per rank rather
     * than one per row: on a loaded or oversubscribed machine every
     * message waits for the receiver to be scheduled, and a job stopped
     * by mpirun has about one second left to write its image. */
    int per = rows_per_message(row_bytes), most = (n_rows + m->size - 1) / m->size;
    if (per > most) /* the buffer holds no more rows than any rank has */
        per = most > 0 ? most : 1;
    unsigned char *buf = malloc((size_t)per * row_bytes);
    if (!buf)
        return false;
    bool ok = true;
    for (int r = 1; r < m->size && ok; r++) {
        if (m->rank != 0 && m->rank != r)
            continue;
        int mine = r < n_rows ? (n_rows - r + m->size - 1) / m->size : 0;
        for (int i0 = 0; i0 < mine && ok; i0 += per) {
            int count = mine - i0 < per ? mine - i0 : per, first = r + i0 * m->size;
            int bytes = (int)((size_t)count * row_bytes), rc;
            if (m->rank == 0) {
                rc = MPI_Recv(buf, bytes, MPI_BYTE, r, TAG_ROW, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                pack(rows, buf, row_bytes, first, m->size, count, false);
            } else {
                pack(rows, buf, row_bytes, first, m->size, count, true);
                rc = MPI_Send(buf, bytes, MPI_BYTE, 0, TAG_ROW, MPI_COMM_WORLD);
            }
            ok = rc == MPI_SUCCESS;
        }
    }
    free(buf);
    return ok;
}

/* MPI's reduction operator for pairs (low, high) of 128-bit integers:
 * inout += in, the carry of the low words into the high ones. */
static void add_u128(void *in, void *inout, int *len, MPI_Datatype *type)
{
    (void)type;
    const uint64_t *a = in;
    uint64_t *b = inout;
    for (int i = 0; i < *len; i++) {
        uint64_t lo = b[2 * i] + a[2 * i];
        b[2 * i + 1] += a[2 * i + 1] + (lo < a[2 * i]);
        b[2 * i] = lo;
    }
}

bool app_mpi_sum_u128(const app_mpi *m, uint64_t *words, size_t n)
{
    if (!m->active || m->size == 1)
        return true;
    /* Pieces of 2^20 numbers (16 MB): MPI counts in int, and the library
     * may keep a buffer of the piece's size for the reduction. */
    enum { PIECE = 1 << 20 };
    MPI_Datatype pair;
    MPI_Op op;
    MPI_Type_contiguous(2, MPI_UINT64_T, &pair);
    MPI_Type_commit(&pair);
    MPI_Op_create(add_u128, 1, &op);
    bool ok = true;
    for (size_t i = 0; i < n && ok; i += PIECE) {
        int count = (int)(n - i < PIECE ? n - i : PIECE);
        uint64_t *at = words + 2 * i;
        int rc = m->rank == 0 ? MPI_Reduce(MPI_IN_PLACE, at, count, pair, op, 0, MPI_COMM_WORLD)
                              : MPI_Reduce(at, NULL, count, pair, op, 0, MPI_COMM_WORLD);
        ok = rc == MPI_SUCCESS;
    }
    MPI_Op_free(&op);
    MPI_Type_free(&pair);
    return ok;
}

void app_mpi_end(app_mpi *m)
{
    if (m->active)
        MPI_Finalize();
    m->active = false;
}
