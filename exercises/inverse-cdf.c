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
 *        The map is pinned: sample() is P^-1 itself, increasing in u (the
 *        decreasing x = P^-1(1 - u) has the same law, but is not the
 *        inverse of the CDF the exercise asks for).
 * HINT   The integral of x^2 over [0, 2] is 8/3. Solve P(x) = u for x:
 *        cbrt() is in <math.h>. Check your answer: sample(1) must be 2.
 * JUDGED by the public check (check/check.h) on MCBOX_INTERVAL [0, 2],
 *        10^6 samples from seed 2101 in 100 equal cells:
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over each cell; the integral of pdf over [0, 2]
 *           within 1e-6 of 1; the round trip |invert(sample(u)) - u| <=
 *           1e-6; every sample in [0, 2];
 *        2. the same points against the law asked for, 3x^2/8: the
 *           chi-square again, and your pdf at every sample within 1e-6
 *           (relative) of it;
 *        3. your pdf against 3x^2/8 at the centres of 1024 cells of
 *           [0, 2], relative 1e-6;
 *        4. exactly, that the map is the inverse CDF: invert(x) within
 *           1e-12 of x^3/8 at the same 1024 points.
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

/* The law the exercise asks for: 3 x^2 / 8 on [0, 2]. */
static double quadratic_law(const double *x, void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 2.0 ? 0.375 * x[0] * x[0] : 0.0;
}

/* The largest |invert(x) - x^3/8| at the centres of 1024 cells of [0, 2]:
 * the inverse must be the CDF itself, which pins the map. */
static double cdf_error(void)
{
    double worst = 0.0;
    for (int k = 0; k < 1024; k++) {
        double x = 2.0 * (k + 0.5) / 1024.0, e = fabs(invert(x) - x * x * x / 8.0);
        worst = e > worst || isnan(e) ? e : worst;
    }
    return worst;
}

static void judge(ex_judge *j)
{
    static const ex_law law = {"the law 3x^2/8", quadratic_law, NULL};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_INTERVAL);
    s.domain.a = 0.0, s.domain.b = 2.0;
    s.sample = check_sample, s.pdf = check_pdf, s.invert = check_invert;
    ex_check_sampler_law(j, "3x^2/8 on [0, 2]", &s, &law, 2101, 1000000);
    double e = cdf_error();
    ex_check_exact(j, "cdf", "the inverse is the CDF x^3/8", e <= 1e-12,
                   "largest |invert(x) - x^3/8| at 1024 points of [0, 2]: %.3g (<= 1e-12)", e);
}

const ex_exercise ex_this = {"inverse-cdf", "2 (#ch-integration)", EX_VARIANT, judge,
                             EX_KIND,       EX_INTENDED};
