/* exercises/power-heuristic.c - chapter 11, "Next-event estimation and
 * multiple importance sampling" (#ch-nee-mis): Veach's power heuristic [@veach1997].
 *
 * Two strategies sample the same integrand: f draws nf samples with
 * density f_pdf, g draws ng with density g_pdf (both densities at the same
 * point, per the same measure). Each sample is weighted so that, at every
 * point, the weights of the strategies sum to 1.
 * WRITE  power_heuristic(nf, f_pdf, ng, g_pdf): the weight of strategy f
 *        by the power heuristic with exponent 2.
 * HINT   With a = nf f_pdf and b = ng g_pdf, the weight is a^2/(a^2 + b^2).
 *        A strategy that cannot draw the point (f_pdf = 0) gets weight 0;
 *        keep 0/0 out.
 * JUDGED by
 *        1. exactly: ten weights worked out by hand (e.g. densities 3 and 1
 *           give 9/10, counts 2 and 1 at equal densities give 4/5), to
 *           1e-12;
 *        2. exactly: w(f, g) + w(g, f) = 1 to 1e-12 at 10^4 points whose
 *           densities span 1e-6 .. 1e6 and counts 1 .. 4 (rng seed 11102);
 *        3. a z-test: the MIS estimate of the integral of x^2 over [0, 2]
 *           (8/3) from one uniform sample (density 1/2) and one linear
 *           sample (density x/2) per step, 10^6 steps (rng
 *           mc_rng_derive(11101, 0)): unbiased when the weights sum to 1.
 *
 * Run:   make exercise NAME=power-heuristic
 */
#include <math.h>
#include <stdio.h>

#include "exercises/check_exercise.h"
#include "samplers/warp1d.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* The power-heuristic weight of strategy f against strategy g. */
static double power_heuristic(int nf, double f_pdf, int ng, double g_pdf)
{
    (void)nf, (void)f_pdf, (void)ng, (void)g_pdf;
    return 0.5; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/power-heuristic.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* Weights worked out by hand: nf, f_pdf, ng, g_pdf, the weight of f. */
static const double by_hand[][5] = {
    {1, 3.0, 1, 1.0, 9.0 / 10.0},   {1, 1.0, 1, 3.0, 1.0 / 10.0},  {1, 2.0, 1, 1.0, 4.0 / 5.0},
    {2, 1.0, 1, 1.0, 4.0 / 5.0},    {1, 1.0, 2, 1.0, 1.0 / 5.0},   {1, 0.5, 1, 1.5, 1.0 / 10.0},
    {3, 0.5, 1, 1.0, 9.0 / 13.0},   {1, 0.0, 1, 2.385, 0.0},       {1, 2.385, 1, 0.0, 1.0},
    {4, 0.25, 1, 3.0, 1.0 / 10.0},
};

static mc_estimate mis_estimate(mc_rng *rng, uint64_t n)
{
    mc_welford w = mc_welford_init();
    for (uint64_t i = 0; i < n; i++) {
        /* Strategy a: uniform on [0, 2], density 1/2; b: linear, x/2. */
        double xa = 2.0 * mc_rng_uniform(rng), xb = smp_linear_sample(mc_rng_uniform(rng));
        double pa_a = 0.5, pb_a = smp_linear_pdf(xa), pa_b = 0.5, pb_b = smp_linear_pdf(xb);
        double fa = xa * xa, fb = xb * xb;
        double v = power_heuristic(1, pa_a, 1, pb_a) * fa / pa_a;
        if (pb_b > 0.0) /* x = 0 (u = 0): f = 0 there */
            v += power_heuristic(1, pb_b, 1, pa_b) * fb / pb_b;
        mc_welford_add(&w, v);
    }
    return mc_welford_estimate(&w);
}

static void judge(ex_judge *j)
{
    int wrong = 0;
    char first[80] = "";
    size_t rows = sizeof by_hand / sizeof by_hand[0];
    for (size_t i = 0; i < rows; i++) {
        const double *r = by_hand[i];
        double w = power_heuristic((int)r[0], r[1], (int)r[2], r[3]);
        if (!(fabs(w - r[4]) <= 1e-12) && wrong++ == 0)
            snprintf(first, sizeof first, "; first: %.6g where %.6g is due", w, r[4]);
    }
    ex_check_exact(j, "by-hand", "weights by hand", wrong == 0, "%d of %zu wrong%s", wrong, rows, first);
    mc_rng rng = mc_rng_derive(ex_seed(j, 11102), 0);
    double worst = 0.0;
    for (int i = 0; i < 10000; i++) {
        /* exp(+-13.8): densities from 1e-6 to 1e6. */
        double f = exp(27.6 * (mc_rng_uniform(&rng) - 0.5));
        double g = exp(27.6 * (mc_rng_uniform(&rng) - 0.5));
        int nf = 1 + (int)mc_rng_bounded(&rng, 4), ng = 1 + (int)mc_rng_bounded(&rng, 4);
        double e = fabs(power_heuristic(nf, f, ng, g) + power_heuristic(ng, g, nf, f) - 1.0);
        worst = e > worst || isnan(e) ? e : worst;
    }
    ex_check_exact(j, "sum", "weights sum to 1", worst <= 1e-12,
                   "largest |w(f,g) + w(g,f) - 1| at 10^4 points: %.3g (<= 1e-12)", worst);
    uint64_t seed = ex_seed(j, 11101);
    mc_rng r = mc_rng_derive(seed, 0);
    mc_estimate e = mis_estimate(&r, ex_samples(j, 1000000));
    ex_check_estimate(j, "z-test", "MIS estimate, z-test against 8/3", e, 8.0 / 3.0, seed);
}

const ex_exercise ex_this = {"power-heuristic", "11 (#ch-nee-mis)", EX_VARIANT, judge,
                             EX_KIND,           EX_INTENDED};
