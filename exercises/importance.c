/* exercises/importance.c - chapter 2, "One-dimensional integration"
 * (#ch-integration): importance sampling.
 *
 * WRITE  estimate_integral(rng, n): the importance-sampled estimate of
 *        I = integral of x^2 over [0, 2] (= 8/3) from n samples x drawn
 *        with the LINEAR density p(x) = x/2 on [0, 2] (PER UNIT LENGTH),
 *        one uniform mc_rng_uniform(rng) per sample. Return the
 *        mc_estimate (mc/stats.h): n, value, variance of one sample,
 *        std_error of value.
 * HINT   Invert the CDF x^2/4 to draw x. Each sample contributes
 *        f(x) / p(x); average them. mc_welford_add and mc_welford_estimate
 *        (mc/stats.h) keep the mean and its error bar for you. The variance
 *        of one sample is 8/9 (chapter 2's table), against 64/45 for
 *        uniform samples.
 * JUDGED by two statistical tests:
 *        1. a z-test of one estimate from 10^6 samples (rng
 *           mc_rng_derive(2201, 0)) against 8/3;
 *        2. the coverage of its error bar: 2000 estimates from 1000
 *           samples each (rngs mc_rng_derive(2202, i)); value +- 1.96
 *           std_error must hold 8/3 in 95% of them (a binomial test).
 *
 * Run:   make exercise NAME=importance
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* The estimate of the integral of x^2 over [0, 2], sampling x/2. */
static mc_estimate estimate_integral(mc_rng *rng, uint64_t n)
{
    (void)rng;
    mc_estimate e = {n, 0.0, 0.0, 0.0}; /* TODO */
    return e;
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/importance.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void judge(ex_judge *j)
{
    const double exact = 8.0 / 3.0;
    uint64_t seed = ex_seed(j, 2201), n = ex_samples(j, 1000000);
    mc_rng rng = mc_rng_derive(seed, 0);
    ex_check_estimate(j, "z-test against 8/3", estimate_integral(&rng, n), exact, seed);
    const uint64_t runs = 2000, per_run = 1000;
    uint64_t covered = 0, cseed = ex_seed(j, 2202);
    for (uint64_t i = 0; i < runs; i++) {
        mc_rng r = mc_rng_derive(cseed, i);
        mc_estimate e = estimate_integral(&r, per_run);
        covered += fabs(e.value - exact) <= 1.959963985 * e.std_error;
    }
    ex_check_coverage(j, "95% error bars hold 8/3", covered, runs, 0.95, cseed);
}

const ex_exercise ex_this = {"importance", "2 (#ch-integration)", EX_VARIANT, judge};
