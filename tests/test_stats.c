/* tests/test_stats.c - Welford, z-scores, Pearson chi-square, Sidak level. */
#include "tests/support/mc_test.h"

#include <math.h>

#include "mc/chi2.h"
#include "mc/rng.h"
#include "mc/stats.h"
#include "tests/support/negctl.h"

/* Data with mean 1e9 and variance about 1: the textbook trap for the
 * one-pass formula (sum x^2 - n mean^2) / (n - 1), whose two terms are 1e24
 * and agree to 24 digits. Welford must match a two-pass computation. */
static void test_welford_ill_conditioned(void **state)
{
    negctl *t = *state;
    enum { N = 1000000 };
    static double x[N];
    uint64_t seed = mc_test_seed(2001u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_welford w = mc_welford_init();
    double sum = 0.0, sumsq = 0.0; /* for the one-pass formula */
    for (int i = 0; i < N; i++) {
        /* Uniform on [1e9 - sqrt 3, 1e9 + sqrt 3): variance exactly 1. */
        x[i] = 1e9 + (2.0 * mc_rng_uniform(&rng) - 1.0) * sqrt(3.0);
        mc_welford_add(&w, x[i]);
        sum += x[i];
        sumsq += x[i] * x[i];
    }
    /* The reference: x - 1e9 is exact (Sterbenz), so the mean of the
     * deviations carries no 1e9-sized rounding; then a second pass. */
    double dev = 0.0;
    for (int i = 0; i < N; i++)
        dev += x[i] - 1e9;
    double mean = 1e9 + dev / N, m2 = 0.0;
    for (int i = 0; i < N; i++)
        m2 += (x[i] - mean) * (x[i] - mean);
    double two_pass = m2 / (N - 1);
    /* Welford's mean drifts by rounding of order ulp(1e9) sqrt(N) = 1e-4:
     * 1e-13 relative. Its variance must be accurate to 1e-6 relative. */
    assert_near(w.mean, mean, 1e-12 * mean);
    assert_near(mc_welford_variance(&w), two_pass, 1e-6 * two_pass);
    /* Negative control: the one-pass formula on the same data is off by far
     * more than the tolerance the Welford result met. */
    double naive = (sumsq - sum * sum / N) / (N - 1);
    assert_seeded(negctl_record(t, "one-pass variance formula", "two-pass variance",
                                fabs(naive - two_pass) > 1e-2),
                  seed);
}

/* 10^10 samples and more: merging an accumulator with itself 14 times
 * represents 2^14 copies of 10^6 samples (1.6e10 in all). The mean must not
 * move and M2 must scale exactly by the number of copies. */
static void test_welford_huge_count_by_merging(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(2002u), 0u);
    mc_welford w = mc_welford_init();
    for (int i = 0; i < 1000000; i++)
        mc_welford_add(&w, 1e9 + 2.385 * mc_rng_uniform(&rng));
    mc_welford big = w;
    for (int k = 0; k < 14; k++)
        big = mc_welford_merge(big, big);
    assert_true(big.n == (uint64_t)1000000 << 14);
    assert_true(big.n > UINT64_C(10000000000));
    assert_near(big.mean, w.mean, 1e-15 * w.mean);
    assert_near(big.m2, w.m2 * 16384.0, 1e-9 * w.m2 * 16384.0);
}

/* Merging per-thread parts gives the statistics of the whole. */
static void test_welford_merge_matches_sequential(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(2003u), 0u);
    mc_welford all = mc_welford_init(), parts[3] = {mc_welford_init(), mc_welford_init(), mc_welford_init()};
    for (int i = 0; i < 30001; i++) {
        double v = 5.0 + 3.0 * mc_rng_uniform(&rng);
        mc_welford_add(&all, v);
        mc_welford_add(&parts[i < 7 ? 0 : (i < 20000 ? 1 : 2)], v);
    }
    mc_welford m = mc_welford_merge(mc_welford_merge(parts[0], parts[1]), parts[2]);
    assert_true(m.n == all.n);
    assert_near(m.mean, all.mean, 1e-13);
    assert_near(m.m2, all.m2, 1e-9 * all.m2);
    mc_welford empty = mc_welford_init();
    assert_near(mc_welford_merge(empty, all).mean, all.mean, 0.0);
    assert_near(mc_welford_variance(&empty), 0.0, 0.0);
}

/* z-tests of the two estimators of this module against analytic values, for
 * U uniform on [0,1): the mean (1/2) and the sample variance (1/12).
 * Seed 2004, 10^6 samples, |z| < 4: false alarm 6.3e-5 per statistic.
 * The variance estimator's standard error is sqrt((mu4 - sigma^4) / n) to
 * leading order, with mu4 = 1/80 and sigma^4 = 1/144 for the uniform. */
static void test_estimators_ztest(void **state)
{
    (void)state;
    enum { N = 1000000 };
    uint64_t seed = mc_test_seed(2004u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_welford w = mc_welford_init();
    for (int i = 0; i < N; i++)
        mc_welford_add(&w, mc_rng_uniform(&rng));
    mc_estimate e = mc_welford_estimate(&w);
    assert_true(e.n == N);
    assert_z_below("mean of U", e.value, 0.5, e.std_error, 4.0, seed);
    double var_se = sqrt((1.0 / 80.0 - 1.0 / 144.0) / N);
    assert_z_below("variance of U", e.variance, 1.0 / 12.0, var_se, 4.0, seed);
    /* The standard error itself: sqrt(1/12 / N) to within 1%. */
    assert_near(e.std_error, sqrt(1.0 / 12.0 / N), 0.01 * sqrt(1.0 / 12.0 / N));
}

/* Negative control: the same z-test must reject an estimator biased by
 * 0.002 (seven standard errors at N = 10^6) and a variance estimator that
 * divides by n/2 instead of n - 1. */
static void test_estimators_negative_control(void **state)
{
    negctl *t = *state;
    enum { N = 1000000 };
    uint64_t seed = mc_test_seed(2005u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_welford w = mc_welford_init();
    for (int i = 0; i < N; i++)
        mc_welford_add(&w, mc_rng_uniform(&rng) + 0.002);
    mc_estimate e = mc_welford_estimate(&w);
    bool mean_caught = negctl_record(t, "mean biased by 0.002", "z-test",
                                     fabs(mc_z_score(e.value, 0.5, e.std_error)) >= 4.0);
    double wrong_var = w.m2 / (N / 2.0);
    double var_se = sqrt((1.0 / 80.0 - 1.0 / 144.0) / N);
    bool var_caught = negctl_record(t, "variance divided by n/2", "z-test",
                                    fabs(mc_z_score(wrong_var, 1.0 / 12.0, var_se)) >= 4.0);
    assert_seeded(mean_caught && var_caught, seed);
}

static void test_z_score_and_pvalue(void **state)
{
    (void)state;
    assert_near(mc_z_score(3.0, 2.0, 0.5), 2.0, 0.0);
    assert_near(mc_z_score(2.0, 2.0, 0.0), 0.0, 0.0);
    assert_true(isinf(mc_z_score(2.1, 2.0, 0.0)) && mc_z_score(2.1, 2.0, 0.0) > 0);
    assert_true(isinf(mc_z_score(1.9, 2.0, 0.0)) && mc_z_score(1.9, 2.0, 0.0) < 0);
    /* The 5% two-sided critical value of the normal, 1.959963984540054. */
    assert_near(mc_z_pvalue(1.959963984540054), 0.05, 1e-14);
    assert_near(mc_z_pvalue(-1.959963984540054), 0.05, 1e-14);
    assert_near(mc_z_pvalue(0.0), 1.0, 0.0);
    assert_near(mc_z_pvalue(HUGE_VAL), 0.0, 0.0);
    /* P(|Z| >= 4) = 6.334248366623996e-05: the false-alarm rate quoted in
     * every |z| < 4 test. */
    assert_near(mc_z_pvalue(4.0), 6.334248366623996e-05, 1e-18);
}

/* Pearson by hand: obs (10, 20, 30) against 20 each gives 10 on 2 dof, and
 * the chi-square tail with 2 dof is exp(-x/2). */
static void test_chi2_pearson_known_answer(void **state)
{
    (void)state;
    const double obs[3] = {10, 20, 30}, ex[3] = {20, 20, 20};
    mc_chi2_result r = mc_chi2_pearson(obs, ex, 3, 5.0);
    assert_near(r.stat, 10.0, 1e-12);
    assert_int_equal(r.dof, 2);
    assert_near(r.pvalue, exp(-5.0), 1e-15);
    assert_int_equal(r.cells_pooled, 0);
    assert_near(r.obs_total, 60.0, 0.0);
    assert_near(r.exp_total, 60.0, 0.0);
}

static void test_chi2_pooling(void **state)
{
    (void)state;
    /* Expected 1, 2, 3 pool into one cell of 6 (>= 5): three cells, 2 dof;
     * observed in the pool 2 + 1 + 3 = 6, so the pool contributes 0. */
    const double obs1[5] = {2, 1, 3, 12, 8}, ex1[5] = {1, 2, 3, 10, 10};
    mc_chi2_result r = mc_chi2_pearson(obs1, ex1, 5, 5.0);
    assert_int_equal(r.dof, 2);
    assert_int_equal(r.cells_pooled, 3);
    assert_near(r.stat, 0.4 + 0.4, 1e-12);
    /* A pool of 3 (< 5) borrows the smallest regular cell (10): cells of
     * 13 and 20, 1 dof. */
    const double obs2[4] = {1, 1, 11, 20}, ex2[4] = {1, 2, 10, 20};
    r = mc_chi2_pearson(obs2, ex2, 4, 5.0);
    assert_int_equal(r.dof, 1);
    assert_near(r.stat, 0.0, 1e-12);
    /* Observations where nothing is expected are reported, not summed. */
    const double obs3[3] = {3, 9, 11}, ex3[3] = {0, 10, 10};
    r = mc_chi2_pearson(obs3, ex3, 3, 5.0);
    assert_near(r.obs_in_zero_cells, 3.0, 0.0);
    assert_int_equal(r.dof, 1);
    assert_near(r.stat, 0.1 + 0.1, 1e-12);
    /* A NaN expected count that the merge would swallow (first regular
     * cell, pool of 3 borrowing it) still rejects. */
    const double obs4[4] = {1, 1, 11, 20}, ex4[4] = {1, 2, (double)NAN, 20};
    r = mc_chi2_pearson(obs4, ex4, 4, 5.0);
    assert_true(isnan(r.stat) && r.pvalue == 0.0);
}

/* The upper tail is computed directly: at chi2 = 200 on 2 dof the exact
 * tail exp(-100) = 3.7e-44 is far below what 1 - P can represent. */
static void test_chi2_pvalue_upper_tail(void **state)
{
    (void)state;
    assert_near(mc_chi2_pvalue(200.0, 2) / exp(-100.0), 1.0, 1e-10);
    assert_true(mc_chi2_pvalue(1e5, 10) >= 0.0);
    assert_near(mc_chi2_pvalue(0.0, 5), 1.0, 0.0);
    /* A NaN statistic (a pdf returning NaN) is rejected, not passed. */
    assert_true(mc_chi2_pvalue((double)NAN, 5) == 0.0);
    /* Median of chi2 with 1 dof is 0.4549364231195724. */
    assert_near(mc_chi2_pvalue(0.4549364231195724, 1), 0.5, 1e-12);
}

static void test_sidak_alpha(void **state)
{
    (void)state;
    assert_near(mc_sidak_alpha(0.01, 1), 0.01, 1e-17);
    assert_near(mc_sidak_alpha(0.05, 10), 1.0 - pow(0.95, 0.1), 1e-15);
    /* Tiny levels keep their digits: (1 - 1e-12)^(1/1e6) ~ 1 - 1e-18. */
    assert_near(mc_sidak_alpha(1e-12, 1000000) / 1e-18, 1.0, 1e-6);
    /* m tests at the corrected level have family-wise rate alpha. */
    double a = mc_sidak_alpha(0.01, 64);
    assert_near(1.0 - pow(1.0 - a, 64), 0.01, 1e-14);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_welford_ill_conditioned),
        cmocka_unit_test(test_welford_huge_count_by_merging),
        cmocka_unit_test(test_welford_merge_matches_sequential),
        cmocka_unit_test(test_estimators_ztest),
        cmocka_unit_test(test_estimators_negative_control),
        cmocka_unit_test(test_z_score_and_pvalue),
        cmocka_unit_test(test_chi2_pearson_known_answer),
        cmocka_unit_test(test_chi2_pooling),
        cmocka_unit_test(test_chi2_pvalue_upper_tail),
        cmocka_unit_test(test_sidak_alpha),
    };
    return cmocka_run_group_tests_name("test_stats", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
