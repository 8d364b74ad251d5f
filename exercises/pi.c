/* exercises/pi.c - chapter 1, "A simple Monte Carlo program" (#ch-pi):
 * pi by throwing points at a square, with an honest error bar.
 *
 * WRITE  estimate_pi(rng, n): draw n points (x, y) uniform in the square
 *        [-1, 1)^2, two uniforms each (mc_rng_uniform(rng) is in [0, 1),
 *        x first), count the hits x^2 + y^2 < 1, and return an
 *        mc_estimate (mc/stats.h): n, the estimate of pi (value), the
 *        variance of one sample's contribution (variance) and the standard
 *        error of value (std_error).
 * HINT   The fraction of hits estimates pi/4, the area of the disc over
 *        the area of the square. Each point contributes 4 (a hit) or 0
 *        (a miss); such a variable with P(hit) = p has variance
 *        16 p (1 - p). The standard error of the mean of n is
 *        sqrt(variance / n). Count in uint64_t.
 * JUDGED by three statistical tests:
 *        1. a z-test of one estimate from 10^6 points (rng
 *           mc_rng_derive(1001, 0)) against pi;
 *        2. the coverage of the error bar: 2000 estimates from 10^4
 *           points each (rngs mc_rng_derive(1002, i)); value +- 1.96
 *           std_error must hold pi in 95% of them (a binomial test of the
 *           count): an error bar that is too narrow or too wide fails;
 *        3. the law of one sample: the variance that the estimate of test
 *           1 reports against hit-or-miss's 16 p (1 - p), p = pi/4 (a
 *           z-test of the sample variance, whose spread comes from the
 *           fourth moment of a 0/4 variable). Another unbiased estimator
 *           of pi, with an honest error bar of its own, passes 1 and 2
 *           and fails here: it is not hit-or-miss.
 *
 * Run:   make exercise NAME=pi
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* The hit-or-miss estimate of pi from n points drawn from rng. */
static mc_estimate estimate_pi(mc_rng *rng, uint64_t n)
{
    (void)rng;
    mc_estimate e = {n, 3.0, 0.0, 0.0}; /* TODO: the Bible's value */
    return e;
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/pi.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void judge(ex_judge *j)
{
    uint64_t seed = ex_seed(j, 1001), n = ex_samples(j, 1000000);
    mc_rng rng = mc_rng_derive(seed, 0);
    mc_estimate one = estimate_pi(&rng, n);
    ex_check_estimate(j, "z-test", "z-test against pi", one, MC_PI, seed);
    /* Two-sided 95%: the normal quantile 1.959963985. */
    const uint64_t runs = 2000, per_run = 10000;
    uint64_t covered = 0, cseed = ex_seed(j, 1002);
    for (uint64_t i = 0; i < runs; i++) {
        mc_rng r = mc_rng_derive(cseed, i);
        mc_estimate e = estimate_pi(&r, per_run);
        covered += fabs(e.value - MC_PI) <= 1.959963985 * e.std_error;
    }
    ex_check_coverage(j, "coverage", "95% error bars hold pi", covered, runs, 0.95, cseed);
    /* One sample is 4 with probability p = pi/4, else 0: variance 16 p q
     * and fourth central moment 256 p q (1 - 3 p q), q = 1 - p. */
    double p = MC_PI / 4.0, q = 1.0 - p;
    ex_check_variance(j, "variance", "variance of one sample", one, 16.0 * p * q,
                      256.0 * p * q * (1.0 - 3.0 * p * q), "hit-or-miss, 16 p (1 - p)", seed);
}

const ex_exercise ex_this = {"pi", "1 (#ch-pi)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
