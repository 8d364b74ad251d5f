/* exercises/inverse-cdf.c - chapter 2, "One-dimensional integration"
 * (#ch-integration): a sampler by inverting the CDF.
 *
 * The chapter derives the sampler of p(x) = x/2 on [0, 2]: P(x) = x^2/4,
 * so x = sqrt(4u). Do the same for the density that follows x^2 exactly.
 * WRITE  pdf(x): p(x) = C x^2 on [0, 2], 0 elsewhere, PER UNIT LENGTH,
 *        with C chosen so that p integrates to 1;
 *        sample(u): x with density p from a uniform u in [0, 1], by
 *        inverting the CDF P(x) = integral of p from 0 to x;
 *        invert(x): P(x), the u that sample() maps to x.
 * HINT   The integral of x^2 over [0, 2] is 8/3. Solve P(x) = u for x:
 *        cbrt() is in <math.h>. Check your answer: sample(1) must be 2.
 * JUDGED by the public check (check/check.h) on MCBOX_INTERVAL [0, 2]:
 *        10^6 samples from seed 2101 in 100 equal cells, Pearson's
 *        chi-square against pdf integrated over each cell; the integral of
 *        pdf over [0, 2] within 1e-6 of 1; the round trip
 *        |invert(sample(u)) - u| <= 1e-6; every sample in [0, 2].
 *
 * Run:   make exercise NAME=inverse-cdf
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* x with density C x^2 on [0, 2]. */
static double sample(double u)
{
    (void)u;
    return 1.0; /* TODO */
}

/* The density per unit length. */
static double pdf(double x)
{
    (void)x;
    return 0.0; /* TODO */
}

/* The CDF at x: the u that sample() maps to x. */
static double invert(double x)
{
    (void)x;
    return 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/inverse-cdf.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void check_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    out->x[0] = sample(u[0]);
}

static double check_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return pdf(x[0]);
}

static void check_invert(const double *x, double *u, void *ctx)
{
    (void)ctx;
    u[0] = invert(x[0]);
}

static void judge(ex_judge *j)
{
    mcbox_sampler s = mcbox_sampler_init(MCBOX_INTERVAL);
    s.domain.a = 0.0, s.domain.b = 2.0;
    s.sample = check_sample, s.pdf = check_pdf, s.invert = check_invert;
    ex_check_sampler(j, "public check", &s, 2101, 1000000);
}

const ex_exercise ex_this = {"inverse-cdf", "2 (#ch-integration)", EX_VARIANT, judge};
