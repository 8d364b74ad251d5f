/* examples/pi.c - this book's #ch-pi, after Shirley, "Ray Tracing: The
 * Rest of Your Life" (v1.123), chapter 1 "A Simple Monte Carlo Program":
 * estimate pi from the fraction of random points of a square that fall in
 * the inscribed circle, plainly and with stratified (jittered) points.
 *
 * What it shows: the plain estimate's error shrinks like N^-1/2 (the
 * `running` rows), and the jittered grid's like N^-3/4, so that it is far
 * more accurate than plain sampling at the same N (Shirley, "Ray Tracing:
 * The Rest of Your Life" (v1.123), chapter 1, prints 3.1415 against
 * 3.14159 at 10^8 points; this book's #ch-pi measures the ratio in a run).
 * The abs_error column is |estimate - pi|.
 *
 * Build and run:  make all && build/bin/pi --method all
 *                 build/bin/pi --method stratified --samples 1e9 --threads 2
 * Over MPI:       make MPI=1 && mpirun -q -np 4 build/mpi/bin/pi --samples 1e12
 * (the blocks of samples, or rows of cells, are split over the ranks and
 * their integer counts summed: the output is the same bytes for any K; the
 * running method is one stream and runs on rank 0).
 */
#include <math.h>
#include <string.h>

#include "examples/common/cli.h"
#include "examples/common/mpi_split.h"
#include "mc/constants.h"
#include "mc/pi.h"

static const char *const methods[] = {"plain", "stratified", "running", "all", NULL};
static const char *const extra_cols[] = {"abs_error"};

static void row(const app_table *t, const char *method, mc_estimate e)
{
    double abs_error = fabs(e.value - MC_PI);
    app_table_row(t, method, e, MC_PI, &abs_error);
}

/* BEGIN SNIPPET pi_running */
/* The book's endless loop, made finite: one stream, one point at a time,
 * printing the estimate after 10, 100, 1000, ... points (and after n). */
static void running(const app_table *t, uint64_t seed, uint64_t n)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    uint64_t done = 0, hits = 0;
    for (uint64_t next = 10; done < n; next = next <= n / 10 ? next * 10 : n) {
        if (next > n)
            next = n;
        hits += mc_pi_hits_scalar(&rng, next - done);
        done = next;
        row(t, "running", mc_pi_from_hits(hits, done));
    }
}
/* END SNIPPET pi_running */

/* This rank's share of the plain and stratified estimators, summed. */
static mc_estimate plain_split(const app_mpi *mpi, uint64_t seed, uint64_t n, int threads)
{
    uint64_t hits = mc_pi_plain_hits_part(seed, n, (uint64_t)mpi->rank, (uint64_t)mpi->size, threads);
    app_mpi_sum_u64(mpi, &hits, 1);
    return mc_pi_from_hits(hits, n);
}

static mc_estimate stratified_split(const app_mpi *mpi, uint64_t seed, uint64_t n, int threads)
{
    mc_pi_tally g = mc_pi_stratified_part(seed, n, (uint64_t)mpi->rank, (uint64_t)mpi->size, threads);
    uint64_t v[3] = {g.hits, g.discord, g.lone};
    app_mpi_sum_u64(mpi, v, 3);
    mc_pi_tally all = {v[0], v[1], v[2]};
    return mc_pi_stratified_finish(seed, n, all, NULL);
}

int main(int argc, char **argv)
{
    app_mpi mpi = app_mpi_start(&argc, &argv);
    uint64_t n = 100000000u, seed = 1u;
    const char *method = "all";
    bool csv = false;
    int threads = 0;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "number of points (default 1e8)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "estimator (default all)", methods, 0, 0},
        {"--threads", APP_INT, &threads, "OpenMP threads, 0 = all, at most 64 per processor (default 0)",
         NULL, 0, app_max_threads()},
        APP_OPT_CSV(&csv),
    };
    app_parse("pi", "pi [--method plain|stratified|running|all] [--samples N] [--seed S] [--csv]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);

    /* Long runs say so first, from an assumed rate of 3e8 samples per
     * second per thread (a round figure for the announcement only, not a
     * measurement: the vector kernel does more, the running method's
     * scalar loop less; `make bench` measures the kernel). */
    int n_methods = app_selected(method, "plain") + app_selected(method, "stratified") +
                  app_selected(method, "running");
    double total = (double)n_methods * (double)n;
    char what[128];
    snprintf(what, sizeof what, "%.3g samples on %d thread(s)%s, at about 3e8 per second each", total,
             app_threads_used(threads), mpi.size > 1 ? " in each rank" : "");
    app_announce("pi", total / (3e8 * app_threads_used(threads) * mpi.size), what);
    app_mpi_setup_done(&mpi);
    app_table t = {stdout, csv, extra_cols, 1, "pi"};
    app_table_begin(&t);
    bool all = strcmp(method, "all") == 0;
    mc_estimate plain = {0, 0.0, 0.0, 0.0}, strat = plain;
    if (app_selected(method, "plain"))
        row(&t, "plain", plain = plain_split(&mpi, seed, n, threads));
    if (app_selected(method, "stratified"))
        row(&t, "stratified", strat = stratified_split(&mpi, seed, n, threads));
    if (app_selected(method, "running") && mpi.rank == 0)
        running(&t, seed, n);
    if (all && !csv && n >= 2 && strat.std_error > 0.0)
        printf("\nplain vs stratified at n = %llu: standard error %.2e vs %.2e (%.0fx; the\n"
               "stratified bar is an upper bound, not an estimate), actual error %.2e vs %.2e\n",
               (unsigned long long)n, plain.std_error, strat.std_error,
               plain.std_error / strat.std_error, fabs(plain.value - MC_PI), fabs(strat.value - MC_PI));
    app_mpi_end(&mpi);
    return 0;
}
