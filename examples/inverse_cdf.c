/* examples/inverse_cdf.c - inverse transform sampling, the two examples of
 * the lecture slides "Solving the Rendering Equation" (this book's
 * #ch-integration):
 *
 *   sine            p(x) = sin(x)/2 on [0, pi]: P(x) = (1 - cos x)/2, so
 *                   x = acos(1 - 2u) (samplers/warp1d.h);
 *   discrete_cdf    eight events with weights w_k, drawn through the CDF
 *                   table P_k = (w_1 + ... + w_k) / sum w by binary search;
 *   discrete_alias  the same events by Walker's alias table, O(1) a draw.
 *
 * Each row estimates the mean of the drawn value (exact: pi/2 for the sine
 * density, sum k w_k / sum w for the events) and, in the extra columns,
 * tests the histogram against the exact cell probabilities by Pearson's
 * chi-square (32 equal cells on [0, pi]; one cell per event).
 *
 * Build and run:  make all && build/bin/inverse_cdf
 */
#include <math.h>

#include "examples/common/cli.h"
#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/integrate.h"
#include "samplers/discrete.h"
#include "samplers/warp1d.h"

enum { EVENTS = 8, CELLS = 32 };

/* Weights of events 1..8 (not normalized: the tables normalize). */
static const double weights[EVENTS] = {1.5, 4.0, 2.385, 0.25, 6.0, 3.1, 0.75, 2.0};
static const char *const extra_cols[] = {"chi2", "dof", "pvalue"};

typedef struct draws {
    mc_welford mean;
    double obs[CELLS], expected[CELLS];
    size_t cells;
} draws;

static void report(const app_table *t, const char *name, const draws *d, double exact)
{
    mc_chi2_result r = mc_chi2_pearson(d->obs, d->expected, d->cells, 5.0);
    double extra[3] = {r.stat, (double)r.dof, r.pvalue};
    app_table_row(t, name, mc_welford_estimate(&d->mean), exact, extra);
}

static void sine(const app_table *t, uint64_t seed, uint64_t n)
{
    draws d = {.cells = CELLS};
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint64_t i = 0; i < n; i++) {
        double x = smp_sine_sample(mc_rng_uniform(&rng));
        mc_welford_add(&d.mean, x);
        int c = (int)(x / MC_PI * CELLS);
        d.obs[c < CELLS ? c : CELLS - 1] += 1.0;
    }
    /* Cell [a, b] has probability P(b) - P(a) = (cos a - cos b) / 2. */
    for (int c = 0; c < CELLS; c++)
        d.expected[c] = (double)n * 0.5 * (cos(MC_PI * c / CELLS) - cos(MC_PI * (c + 1) / CELLS));
    report(t, "sine", &d, MC_PI_2);
}

/* BEGIN SNIPPET inverse_cdf_events */
/* Draws n events with either table (cdf or alias; the other is NULL). */
static void events(const app_table *t, const char *name, const smp_discrete_cdf *cdf,
                   const smp_alias *alias, uint64_t seed, uint64_t n)
{
    draws d = {.cells = EVENTS};
    mc_rng rng = mc_rng_derive(seed, 1u);
    double sum = 0.0, mean = 0.0;
    for (int k = 0; k < EVENTS; k++)
        sum += weights[k];
    for (int k = 0; k < EVENTS; k++) {
        d.expected[k] = (double)n * weights[k] / sum;
        mean += (k + 1) * weights[k] / sum;
    }
    for (uint64_t i = 0; i < n; i++) {
        double u = mc_rng_uniform(&rng);
        size_t k = cdf ? smp_discrete_cdf_sample(cdf, u, NULL) : smp_alias_sample(alias, u, NULL);
        mc_welford_add(&d.mean, (double)(k + 1));
        d.obs[k] += 1.0;
    }
    report(t, name, &d, mean);
}
/* END SNIPPET inverse_cdf_events */

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "draws per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        APP_OPT_CSV(&csv),
    };
    app_parse("inverse_cdf", "inverse_cdf [--samples N] [--seed S] [--csv]", argc, argv, opts,
              sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("inverse_cdf", n, 1.2e-07);

    double cdf_storage[EVENTS];
    smp_alias_cell alias_storage[EVENTS];
    smp_discrete_cdf cdf;
    smp_alias alias;
    if (!smp_discrete_cdf_init(&cdf, weights, EVENTS, cdf_storage) ||
        !smp_alias_init(&alias, weights, EVENTS, alias_storage))
        app_fail("inverse_cdf", "invalid event weights");

    app_table t = {stdout, csv, extra_cols, 3, "inverse_cdf"};
    app_table_begin(&t);
    sine(&t, seed, n);
    events(&t, "discrete_cdf", &cdf, NULL, seed, n);
    events(&t, "discrete_alias", NULL, &alias, seed, n);
    return 0;
}
