/* tests/test_rng.c - PCG32 known answers, range, uniformity, independence. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <string.h>

#include "mc/chi2.h"
#include "mc/rng.h"

/* The published output of the reference pcg32-demo (pcg-c-basic) for
 * pcg32_srandom_r(42, 54): six raw outputs, then 65 coin flips
 * (boundedrand 2, H = 1), then 33 dice (boundedrand 6, plus 1). */
static void test_rng_known_answers(void **state)
{
    (void)state;
    static const uint32_t raw[6] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                    0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    static const char coins[] = "HHTTTHTHHHTHTTTHHHHHTTTHHHTHTHTHTTHTTTHHHHHHTTTTHHTTTTTHTTTTTTTHT";
    static const int rolls[33] = {3, 4, 1, 1, 2, 2, 3, 2, 4, 3, 2, 4, 3, 3, 5, 2, 3,
                                  1, 3, 1, 5, 1, 4, 1, 5, 6, 4, 6, 6, 2, 6, 3, 3};
    mc_rng rng;
    mc_rng_seed(&rng, 42u, 54u);
    for (int i = 0; i < 6; i++)
        assert_int_equal(mc_rng_u32(&rng), raw[i]);
    for (int i = 0; i < 65; i++)
        assert_int_equal(mc_rng_bounded(&rng, 2u) ? 'H' : 'T', coins[i]);
    for (int i = 0; i < 33; i++)
        assert_int_equal((int)mc_rng_bounded(&rng, 6u) + 1, rolls[i]);
}

static void test_rng_advance_matches_stepping(void **state)
{
    (void)state;
    mc_rng a, b;
    mc_rng_seed(&a, 2385u, 7u);
    b = a;
    for (int i = 0; i < 12345; i++)
        (void)mc_rng_u32(&a);
    mc_rng_advance(&b, 12345u);
    assert_true(a.state == b.state && a.inc == b.inc);
    assert_int_equal(mc_rng_u32(&a), mc_rng_u32(&b));
}

static void test_rng_uniform_range(void **state)
{
    (void)state;
    /* The extreme outputs map to 0 and 1 - 2^-32: never 1.0. */
    assert_true((double)UINT32_MAX * 0x1p-32 < 1.0);
    uint64_t seed = mc_test_seed(1001u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    double lo = 1.0, hi = 0.0;
    for (int i = 0; i < 1000000; i++) {
        double u = mc_rng_uniform(&rng);
        if (u < lo)
            lo = u;
        if (u > hi)
            hi = u;
        assert_true(u >= 0.0 && u < 1.0);
    }
    /* With 10^6 draws the extremes lie within 1e-4 of the ends except with
     * probability 2 (1 - 1e-4)^1e6 = 7e-44. */
    assert_true(lo < 1e-4 && hi > 1.0 - 1e-4);
}

/* Chi-square uniformity of 10^6 draws in 1000 equal cells: expected 1000
 * per cell, 999 dof. Rejecting at p < 1e-4 has a false-alarm rate of 1e-4
 * for seed-varied runs. */
static void test_rng_uniform_chi2(void **state)
{
    (void)state;
    enum { CELLS = 1000, N = 1000000 };
    static double obs[CELLS], expct[CELLS];
    uint64_t seed = mc_test_seed(1002u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    memset(obs, 0, sizeof obs);
    for (int i = 0; i < N; i++)
        obs[(int)(mc_rng_uniform(&rng) * CELLS)] += 1.0;
    for (int i = 0; i < CELLS; i++)
        expct[i] = (double)N / CELLS;
    mc_chi2_result r = mc_chi2_pearson(obs, expct, CELLS, 5.0);
    assert_int_equal(r.dof, CELLS - 1);
    if (r.pvalue < 1e-4)
        fail_msg("uniform draws: chi2 %.1f, dof %d, p %.3g < 1e-4 (seed %llu)", r.stat, r.dof,
                 r.pvalue, (unsigned long long)seed);
}

/* The sample correlation of n pairs (x from a, y from b, both U[0,1)) and
 * the lag-1 correlation within a. With `mix` > 0 the y of each pair is
 * replaced, with probability mix, by its x: a correlation of about mix. Under
 * independence each r is normal with sd 1/sqrt(n); var(U - 1/2) = 1/12, so
 * r = 12 mean((x - 1/2)(y - 1/2)). */
static void correlations(mc_rng *a, mc_rng *b, int n, double mix, double *r_ab, double *r_lag)
{
    double sab = 0.0, slag = 0.0, prev = mc_rng_uniform(a) - 0.5;
    for (int i = 0; i < n; i++) {
        double x = mc_rng_uniform(a) - 0.5, y = mc_rng_uniform(b) - 0.5;
        if (mix > 0.0 && mc_rng_uniform(b) < mix)
            y = x;
        sab += x * y;
        slag += x * prev;
        prev = x;
    }
    *r_ab = 12.0 * sab / n;
    *r_lag = 12.0 * slag / n;
}

/* Two derived streams (indices 0 and 1) must be uncorrelated: with 10^6
 * pairs, |r| < 0.004 is a 4-sigma bound (false alarm 6.3e-5 per statistic).
 * Streams whose indices differ by one are the case a weak derivation gets
 * wrong. The lag-1 correlation within a stream is tested the same way. */
static void test_rng_streams_uncorrelated(void **state)
{
    (void)state;
    enum { N = 1000000 };
    uint64_t seed = mc_test_seed(1003u);
    mc_rng a = mc_rng_derive(seed, 0u), b = mc_rng_derive(seed, 1u);
    double r_ab, r_lag;
    correlations(&a, &b, N, 0.0, &r_ab, &r_lag);
    if (fabs(r_ab) >= 0.004 || fabs(r_lag) >= 0.004)
        fail_msg("correlation between streams %.4g, lag-1 %.4g (bound 0.004, seed %llu)", r_ab, r_lag,
                 (unsigned long long)seed);
}

/* Negative control for the same bound: streams that share 2% of their
 * values (r about 0.02, 20 sd at 10^6 pairs) must be flagged. */
static void test_rng_streams_negative_control(void **state)
{
    (void)state;
    enum { N = 1000000 };
    uint64_t seed = mc_test_seed(1005u);
    mc_rng a = mc_rng_derive(seed, 0u), b = mc_rng_derive(seed, 1u);
    double r_ab, r_lag;
    correlations(&a, &b, N, 0.02, &r_ab, &r_lag);
    if (!(fabs(r_ab) >= 0.004))
        fail_msg("2%% shared values not flagged: r = %.4g (seed %llu)", r_ab, (unsigned long long)seed);
}

static void test_rng_bounded_range(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(1004u), 0u);
    static const uint32_t bounds[] = {1u, 2u, 3u, 7u, 1000u, 0x80000001u, UINT32_MAX};
    for (size_t k = 0; k < sizeof bounds / sizeof bounds[0]; k++)
        for (int i = 0; i < 10000; i++)
            assert_true(mc_rng_bounded(&rng, bounds[k]) < bounds[k]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rng_known_answers),
        cmocka_unit_test(test_rng_advance_matches_stepping),
        cmocka_unit_test(test_rng_uniform_range),
        cmocka_unit_test(test_rng_uniform_chi2),
        cmocka_unit_test(test_rng_streams_uncorrelated),
        cmocka_unit_test(test_rng_streams_negative_control),
        cmocka_unit_test(test_rng_bounded_range),
    };
    return cmocka_run_group_tests_name("test_rng", tests, NULL, NULL);
}
