/* tests/test_chi2_harness.c - the chi-square harness judged on samplers
 * whose truth is known: a correct one passes, wrong ones fail for the right
 * reason, and over many seeds a correct sampler's p-values are uniform (the
 * harness is neither too strict nor too lenient). */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "mc/chi2.h"
#include "mc/rng.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"

/* --- toy samplers with known densities ---------------------------------- */

/* x = sqrt(u) has density 2x on [0, 1]. */
static void sample_sqrt(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    out[0] = sqrt(mc_rng_uniform(rng));
}

static double pdf_2x(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 1.0 ? 2.0 * x[0] : 0.0;
}

static double pdf_uniform01(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 1.0 ? 1.0 : 0.0;
}

/* (x, y) with x uniform and y = sqrt(u): density 2y on the unit square. */
static void sample_2d(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    out[0] = mc_rng_uniform(rng);
    out[1] = sqrt(mc_rng_uniform(rng));
}

static double pdf_2d_2y(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 1.0 && x[1] >= 0.0 && x[1] <= 1.0 ? 2.0 * x[1] : 0.0;
}

/* Density 2 on [0, 1/2], 0 on (1/2, 1]; the sampler leaks a fraction
 * `leak` (in ctx) of its samples into the empty half. */
static void sample_leaky(mc_rng *rng, void *ctx, double out[2])
{
    double leak = *(const double *)ctx;
    double u = mc_rng_uniform(rng);
    out[0] = u < leak ? 0.75 : 0.5 * mc_rng_uniform(rng);
}

static double pdf_left_half(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 0.5 ? 2.0 : 0.0;
}

/* Uniform on [0, 1) but reported shifted by `shift` (in ctx). */
static void sample_shifted(mc_rng *rng, void *ctx, double out[2])
{
    out[0] = mc_rng_uniform(rng) + *(const double *)ctx;
}

static chi2_spec spec_1d(const char *name, void (*s)(mc_rng *, void *, double *),
                         double (*p)(const double *, void *), void *ctx)
{
    chi2_spec spec = {name, {1, {0.0, 0.0}, {1.0, 0.0}, {100, 0}, s, p, ctx}};
    return spec;
}

/* --- tests -------------------------------------------------------------- */

/* A correct 1D and 2D sampler pass. Seeds 3001, 3002; 10^6 samples in 100
 * (1D) and 40 x 40 (2D) cells; reject at chi2_suite_alpha (1.57e-4), so each
 * fails with probability 1.57e-4 by chance. */
static void test_chi2_harness_correct_passes(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(3001u);
    chi2_spec s1 = spec_1d("harness-sqrt-vs-2x", sample_sqrt, pdf_2x, NULL);
    chi2_outcome o1 = chi2_run(&s1, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&s1, &o1);
    if (o1.reject)
        fail_msg("correct 1D sampler rejected (seed %llu)", (unsigned long long)seed);
    assert_int_equal(o1.r.dof, 99);
    assert_near(o1.alpha, 1.0 - pow(0.99, 1.0 / 64.0), 1e-15);

    seed = mc_test_seed(3002u);
    chi2_spec s2 = {"harness-2d", {2, {0.0, 0.0}, {1.0, 1.0}, {40, 40}, sample_2d, pdf_2d_2y, NULL}};
    chi2_outcome o2 = chi2_run(&s2, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&s2, &o2);
    if (o2.reject)
        fail_msg("correct 2D sampler rejected (seed %llu)", (unsigned long long)seed);
    /* The cells along y = 0 expect 10^6 * 2 * (1/40) * (1/40)^2 / 2 = 15.6
     * samples: none pooled, 1599 dof. */
    assert_int_equal(o2.r.dof, 1599);
}

/* Normalization by quadrature: 2x integrates to 1, the 2D density too. */
static void test_chi2_harness_integrates(void **state)
{
    (void)state;
    chi2_spec s1 = spec_1d("n1", sample_sqrt, pdf_2x, NULL);
    chi2_spec s2 = {"n2", {2, {0.0, 0.0}, {1.0, 1.0}, {4, 4}, sample_2d, pdf_2d_2y, NULL}};
    assert_near(chi2_integrate_pdf(&s1), 1.0, 1e-12);
    assert_near(chi2_integrate_pdf(&s2), 1.0, 1e-12);
}

static bool file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Negative controls. Shape: sqrt(u) against the uniform pdf, 10^6
 * samples: the statistic is about 10^6 * sum (2x - 1)^2 / 1 / 100 ~ 3.3e5,
 * p = 0 to double precision. Leak: 1% of samples where the pdf is 0.
 * Out of range: samples shifted by 0.01 beyond [0, 1]. Scale: a pdf of 3x
 * (1.5 times 2x) is caught by the normalization, 1.5 != 1. */
static void test_chi2_harness_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(3003u);
    chi2_spec wrong = spec_1d("harness-negctl-sqrt-vs-uniform", sample_sqrt, pdf_uniform01, NULL);
    chi2_outcome o = chi2_run(&wrong, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&wrong, &o);
    assert_true(negctl_record(t, "sqrt(u) given the uniform pdf", "chi-square",
                              o.reject && o.r.pvalue < 1e-12));
    /* The failing run leaves its table for gnuplot. */
    char path[1024];
    snprintf(path, sizeof path, "%s/test-results/chi2/%s.csv", mc_test_build_dir(), wrong.name);
    assert_true(file_exists(path));

    double leak = 0.01;
    chi2_spec leaky = spec_1d("harness-negctl-leak", sample_leaky, pdf_left_half, &leak);
    o = chi2_run(&leaky, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&leaky, &o);
    assert_true(negctl_record(t, "1% of samples where the pdf is 0", "zero-expected cells",
                              o.reject && o.r.obs_in_zero_cells > 0.0));

    double shift = 0.01;
    chi2_spec shifted = spec_1d("harness-negctl-outside", sample_shifted, pdf_uniform01, &shift);
    o = chi2_run(&shifted, 100000u, seed, chi2_suite_alpha());
    chi2_print(&shifted, &o);
    assert_true(negctl_record(t, "samples outside [lo, hi]", "range", o.reject && o.outside > 0.0));

    /* A correct sampler with zero leak is the matching positive case. */
    leak = 0.0;
    o = chi2_run(&leaky, 1000000u, seed, chi2_suite_alpha());
    assert_false(o.reject);

    chi2_spec scaled = spec_1d("harness-negctl-scale", sample_sqrt, pdf_2x, NULL);
    double norm = 1.5 * chi2_integrate_pdf(&scaled); /* the pdf 3x, integrated */
    assert_true(
        negctl_record(t, "pdf 3x for density 2x", "normalization", fabs(norm - 1.0) > 1e-6));
}

/* The Kolmogorov distribution's upper tail P(K > x) = 2 sum_k (-1)^(k-1)
 * exp(-2 k^2 x^2); the series converges fast for x > 0.2. */
static double kolmogorov_q(double x)
{
    if (x < 0.2)
        return 1.0;
    double sum = 0.0;
    for (int k = 1; k <= 100; k++) {
        double term = exp(-2.0 * k * k * x * x);
        sum += (k % 2 ? 2.0 : -2.0) * term;
        if (term < 1e-17)
            break;
    }
    return fmin(1.0, fmax(0.0, sum));
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Kolmogorov-Smirnov test of p[0..n) (sorted in place) against the uniform
 * law on [0, 1]: the statistic D in *d and P(K > D (sqrt n + 0.12 +
 * 0.11 / sqrt n)), Stephens' small-sample correction. */
static double ks_uniform_q(double *p, int n, double *d)
{
    qsort(p, (size_t)n, sizeof p[0], cmp_double);
    *d = 0.0;
    for (int i = 0; i < n; i++)
        *d = fmax(*d, fmax((i + 1.0) / n - p[i], p[i] - (double)i / n));
    double sq = sqrt((double)n);
    return kolmogorov_q(*d * (sq + 0.12 + 0.11 / sq));
}

/* Calibration: 200 independent runs (seeds derived from 3004 by index) of
 * the correct sampler sqrt(u) against 2x, 2 * 10^4 samples in 50 cells
 * each (expected >= 8 per cell, no pooling). Their p-values must be
 * uniform: Kolmogorov-Smirnov statistic D with Stephens' small-sample
 * correction, rejected when P < 1e-4 (false-alarm rate 1e-4). A harness
 * that computed expected counts at cell centres, or used the wrong dof,
 * would pile p-values up at one end. */
static void test_chi2_harness_pvalues_uniform(void **state)
{
    (void)state;
    enum { RUNS = 200 };
    double p[RUNS];
    uint64_t seed = mc_test_seed(3004u);
    chi2_spec s = spec_1d("harness-calibration", sample_sqrt, pdf_2x, NULL);
    s.gof.cells[0] = 50;
#pragma omp parallel for schedule(dynamic)
    for (int i = 0; i < RUNS; i++) {
        mc_rng r = mc_rng_derive(seed, (uint64_t)i + 1u);
        chi2_outcome o =
            chi2_run(&s, 20000u, mc_rng_u32(&r) | ((uint64_t)mc_rng_u32(&r) << 32), 1e-300);
        p[i] = o.r.pvalue;
    }
    double d, q = ks_uniform_q(p, RUNS, &d);
    printf("chi2 harness calibration: %d p-values, KS D = %.4f, P = %.4g\n", RUNS, d, q);
    if (q < 1e-4)
        fail_msg("p-values of a correct sampler are not uniform: D %.4f, P %.3g (seed %llu)", d, q,
                 (unsigned long long)seed);
}

/* Negative control for the calibration test itself: p-values of the
 * p = 2x sampler judged with the centre-value approximation of each cell
 * would still be near uniform (2x is linear), so instead feed the KS test
 * p-values from a slightly wrong pdf (2x blended 3% with uniform): with
 * 2 * 10^4 samples per run the p-values collapse toward 0 and the KS test
 * must reject. */
static double pdf_blend(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 1.0 ? 0.97 * 2.0 * x[0] + 0.03 : 0.0;
}

static void test_chi2_harness_pvalues_negative_control(void **state)
{
    negctl *t = *state;
    enum { RUNS = 200 };
    double p[RUNS];
    uint64_t seed = mc_test_seed(3005u);
    chi2_spec s = spec_1d("harness-calibration-negctl", sample_sqrt, pdf_blend, NULL);
    s.gof.cells[0] = 50;
#pragma omp parallel for schedule(dynamic)
    for (int i = 0; i < RUNS; i++) {
        chi2_outcome o = chi2_run(&s, 20000u, seed + (uint64_t)i * 7919u, 1e-300);
        p[i] = o.r.pvalue;
    }
    double d, q = ks_uniform_q(p, RUNS, &d);
    printf("chi2 harness calibration negative control: KS D = %.4f, P = %.4g\n", d, q);
    assert_true(negctl_record(t, "p-values of a 3%-wrong pdf", "KS calibration", q < 1e-4));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chi2_harness_correct_passes),
        cmocka_unit_test(test_chi2_harness_integrates),
        cmocka_unit_test(test_chi2_harness_negative_controls),
        cmocka_unit_test(test_chi2_harness_pvalues_uniform),
        cmocka_unit_test(test_chi2_harness_pvalues_negative_control),
    };
    return cmocka_run_group_tests_name("test_chi2_harness", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
