/* tests/mpi/handout.c - what rank 0 can move, for docs/scaling.md: the
 * rate at which it answers work requests (a dynamic hand-out: each worker
 * asks for the next unit, one int each way) and the rate at which it
 * receives finished image rows (64 bytes per pixel, rt_pixel).
 *
 * Build: make MPI=1 build/mpi/tests-mpi/handout; run:
 *   mpirun -q --oversubscribe -np 2 build/mpi/tests-mpi/handout
 * Prints one line per measure. Not a test: speed is only measured.
 */
#include <stdio.h>
#include <stdlib.h>

#include <mpi.h>

enum { TAG_ASK = 1, TAG_UNIT = 2, TAG_DATA = 3 };

/* Rank 0 hands out `units` unit numbers to whoever asks; -1 ends a worker. */
static double handout_rate(int rank, int size, int units)
{
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    if (rank == 0) {
        int next = 0, done = 0, dummy;
        MPI_Status st;
        while (done < size - 1) {
            MPI_Recv(&dummy, 1, MPI_INT, MPI_ANY_SOURCE, TAG_ASK, MPI_COMM_WORLD, &st);
            int unit = next < units ? next++ : -1;
            done += unit < 0;
            MPI_Send(&unit, 1, MPI_INT, st.MPI_SOURCE, TAG_UNIT, MPI_COMM_WORLD);
        }
    } else {
        for (int unit = 0, ask = 0; unit >= 0;) {
            MPI_Send(&ask, 1, MPI_INT, 0, TAG_ASK, MPI_COMM_WORLD);
            MPI_Recv(&unit, 1, MPI_INT, 0, TAG_UNIT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        }
    }
    MPI_Barrier(MPI_COMM_WORLD);
    return (double)units / (MPI_Wtime() - t0);
}

/* Rank 0 receives `count` messages of `bytes` from every other rank. */
static double receive_rate(int rank, int size, size_t bytes, int count)
{
    unsigned char *buf = calloc(bytes, 1);
    if (!buf)
        MPI_Abort(MPI_COMM_WORLD, 1);
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int i = 0; i < count; i++)
        for (int r = 1; r < size; r++) {
            if (rank == 0)
                MPI_Recv(buf, (int)bytes, MPI_BYTE, r, TAG_DATA, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            else if (rank == r)
                MPI_Send(buf, (int)bytes, MPI_BYTE, 0, TAG_DATA, MPI_COMM_WORLD);
        }
    MPI_Barrier(MPI_COMM_WORLD);
    double secs = MPI_Wtime() - t0;
    free(buf);
    return (double)bytes * count * (size - 1) / secs;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size < 2) {
        if (rank == 0)
            fprintf(stderr, "handout: needs at least 2 ranks\n");
        MPI_Finalize();
        return 2;
    }
    double units = handout_rate(rank, size, 200000);
    /* One image row of rt_pixel (64 bytes) at 600 and 3840 pixels, and the
     * packed rows of a whole rank (a 600x600 image over 2 ranks). */
    static const size_t sizes[3] = {600 * 64, 3840 * 64, 300 * 600 * 64};
    static const int counts[3] = {4000, 1000, 20};
    double rate[3];
    for (int i = 0; i < 3; i++)
        rate[i] = receive_rate(rank, size, sizes[i], counts[i]);
    if (rank == 0) {
        printf("ranks %d: rank 0 hands out %.3g units/s (one int each way, %.2f us per unit)\n", size,
               units, 1e6 / units);
        for (int i = 0; i < 3; i++)
            printf("ranks %d: rank 0 receives %zu-byte messages at %.3g GB/s (%.3g messages/s)\n", size,
                   sizes[i], rate[i] * 1e-9, rate[i] / (double)sizes[i]);
    }
    MPI_Finalize();
    return 0;
}
