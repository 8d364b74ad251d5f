/* examples/pi.c - chapter 1, "A Simple Monte Carlo Program": estimate pi
 * from the fraction of random points of a square that fall in the inscribed
 * circle, plainly and with stratified (jittered) points.
 *
 * What it shows: the plain estimate's error shrinks like N^-1/2 (the
 * `running` rows), and at 10^8 samples the jittered grid is about 100 times
 * more accurate than plain sampling: the book's 3.1415 against 3.14159. The
 * abs_error column is |estimate - pi|.
 *
 * Build and run:  make all && build/bin/pi --method all
 *                 build/bin/pi --method stratified --samples 1e9 --threads 2
 */
#include <math.h>
#include <string.h>

#include "examples/common/cli.h"
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

int main(int argc, char **argv)
{
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

    /* Long runs say so first: about 3e8 samples per second per thread (the
     * vector kernel does more, the running method's scalar loop less). */
    int n_methods = app_selected(method, "plain") + app_selected(method, "stratified") +
                  app_selected(method, "running");
    double total = (double)n_methods * (double)n;
    char what[128];
    snprintf(what, sizeof what, "%.3g samples on %d thread(s), at about 3e8 per second each", total,
             app_threads_used(threads));
    app_announce("pi", total / (3e8 * app_threads_used(threads)), what);
    app_table t = {stdout, csv, extra_cols, 1, "pi"};
    app_table_begin(&t);
    bool all = strcmp(method, "all") == 0;
    mc_estimate plain = {0, 0.0, 0.0, 0.0}, strat = plain;
    if (app_selected(method, "plain"))
        row(&t, "plain", plain = mc_pi_plain(seed, n, threads, NULL));
    if (app_selected(method, "stratified"))
        row(&t, "stratified", strat = mc_pi_stratified(seed, n, threads, NULL));
    if (app_selected(method, "running"))
        running(&t, seed, n);
    if (all && !csv && n >= 2 && strat.std_error > 0.0)
        printf("\nplain vs stratified at n = %llu: standard error %.2e vs %.2e (%.0fx; the\n"
               "stratified bar is about 1.5x conservative), actual error %.2e vs %.2e\n",
               (unsigned long long)n, plain.std_error, strat.std_error,
               plain.std_error / strat.std_error, fabs(plain.value - MC_PI), fabs(strat.value - MC_PI));
    return 0;
}
