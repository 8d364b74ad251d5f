/* examples/estimate_halfway.c - this book's #ch-integration: an integrand
 * that has an antiderivative nobody wants to write down: for
 *
 *     f(x) = exp(-x / 2pi) sin^2 x  on [0, 2pi],
 *
 * estimate I = integral of f, then the "halfway" point h where the integral
 * from 0 reaches I/2. Uniform samples x_i weighted by f(x_i) / p (p = 1/2pi)
 * give I as their mean; sorted by x, the running sum of the weights crosses
 * half the total at the estimate of h (mc_weighted_quantile, which also
 * gives h a delta-method standard error).
 *
 * Exact values. With a = 1/(2pi) and sin^2 x = (1 - cos 2x)/2,
 *   F(x) = (1 - e^-ax) / (2a) - (a + e^-ax (2 sin 2x - a cos 2x)) / (2 (a^2 + 4)),
 *   I = F(2pi) = (1 - 1/e) (pi - a / (2 (a^2 + 4))) = 1.9733687998883995...,
 * and h solves F(h) = I/2: h = 2.0384318637072155... (tests/test_integrate.c
 * re-derives both with GSL quadrature and Brent's root finder).
 *
 * Build and run:  make all && build/bin/estimate_halfway
 */
#include <math.h>
#include <stdlib.h>

#include "examples/common/cli.h"
#include "mc/constants.h"
#include "mc/integrate.h"

#define EXACT_INTEGRAL 1.9733687998883995066
#define EXACT_HALFWAY 2.0384318637072154832

static double integrand(double x, void *params)
{
    (void)params;
    double s = sin(x);
    return exp(-x * MC_INV_2PI) * s * s;
}

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "number of samples (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        APP_OPT_CSV(&csv),
    };
    app_parse("estimate_halfway", "estimate_halfway [--samples N] [--seed S] [--csv]", argc, argv,
              opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("estimate_halfway", n, 6.6e-07);
    /* Every sample is kept for the sort: 16 bytes each. */
    if (n < 2 || n > (uint64_t)1 << 30)
        app_fail("estimate_halfway", "--samples must be from 2 to 2^30 (the samples are sorted in memory)");
    mc_weighted *s = malloc((size_t)n * sizeof *s);
    if (!s)
        app_fail("estimate_halfway", "out of memory for %llu samples", (unsigned long long)n);

    /* BEGIN SNIPPET halfway_main */
    mc_fn1 f = {integrand, NULL};
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate integral = mc_integrate_uniform(f, 0.0, MC_2PI, &rng, n, s);
    qsort(s, (size_t)n, sizeof *s, mc_weighted_compare);
    mc_estimate halfway = mc_weighted_quantile(s, (size_t)n, 0.5, f);
    free(s);
    /* END SNIPPET halfway_main */

    app_table t = {stdout, csv, NULL, 0, "estimate_halfway"};
    app_table_begin(&t);
    app_table_row(&t, "integral", integral, EXACT_INTEGRAL, NULL);
    app_table_row(&t, "halfway", halfway, EXACT_HALFWAY, NULL);
    return 0;
}
