/* tests/test_pi.c - the pi estimators of mc/pi.h: z-tests against pi,
 * biased estimators the same tests reject, the fast kernel against a
 * scalar re-implementation of its documented layout, independence of the
 * thread count, stratified better than plain, and an honest error bar. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include <gsl/gsl_cdf.h>

#include "mc/constants.h"
#include "mc/pi.h"
#include "mc/strat.h"
#include "tests/support/negctl.h"

/* As in mc/pi.c: no FMA contraction, so the reference rounds like the
 * kernel. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* Every z-test below: |z| < 4, two-sided false-alarm rate 6.3e-5 per test. */
#define Z_MAX 4.0

/* The plain estimator, 10^7 points (seed 3001), and the book's scalar loop,
 * 10^6 points (seed 3002), z-tested against pi. */
static void test_pi_plain_z(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(3001u);
    mc_estimate e = mc_pi_plain(seed, 10000000u, 0, NULL);
    assert_z_below("pi plain", e.value, MC_PI, e.std_error, Z_MAX, seed);
    seed = mc_test_seed(3002u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    e = mc_pi_from_hits(mc_pi_hits_scalar(&rng, 1000000u), 1000000u);
    assert_z_below("pi scalar", e.value, MC_PI, e.std_error, Z_MAX, seed);
}

/* The stratified estimator at a non-square n = 10^7 + 12345 (3164 x 3164
 * grid, 1449 extra points), seed 3003. */
static void test_pi_stratified_z(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(3003u);
    mc_estimate e = mc_pi_stratified(seed, 10012345u, 0, NULL);
    assert_z_below("pi stratified", e.value, MC_PI, e.std_error, Z_MAX, seed);
}

/* Negative controls for the two z-tests. Plain: the book's loop with the
 * circle test x^2 + y^2 < 1.01, expectation 1.01 pi (z ~ 19 at 10^6).
 * Stratified: the book's non-square-N bug, floor(sqrt N)^2 points summed
 * but divided by N = 10^7 + 12345: a relative bias of 1.4e-4 (z ~ 40). */
static void test_pi_z_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(3004u), n = 1000000u, hits = 0;
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint64_t i = 0; i < n; i++) {
        double x = 2.0 * mc_rng_uniform(&rng) - 1.0, y = 2.0 * mc_rng_uniform(&rng) - 1.0;
        hits += x * x + y * y < 1.01;
    }
    mc_estimate e = mc_pi_from_hits(hits, n);
    bool a = negctl_record(t, "pi plain, circle of radius^2 1.01", "z-test",
                           fabs(mc_z_score(e.value, MC_PI, e.std_error)) >= Z_MAX);
    uint64_t big = 10012345u;
    size_t sx, sy;
    mc_strat_grid((size_t)big, &sx, &sy);
    mc_estimate g = mc_pi_stratified(mc_test_seed(3003u), (uint64_t)sx * sx, 0, NULL);
    double book = g.value * (double)(sx * sx) / (double)big;
    bool b = negctl_record(t, "pi stratified, floor(sqrt N)^2 points / N", "z-test",
                           fabs(mc_z_score(book, MC_PI, g.std_error)) >= Z_MAX);
    assert_seeded(a && b, seed);
}

/* One point of the integer hit test of mc/pi.h, scalar: cell centres
 * (2a + 1) / 2^31 from a = u >> 2, inside when (2a+1)^2 + (2b+1)^2 < 2^62. */
static uint64_t ref_hit(mc_rng *g)
{
    uint64_t x = 2u * (uint64_t)(mc_rng_u32(g) >> 2) + 1u;
    uint64_t y = 2u * (uint64_t)(mc_rng_u32(g) >> 2) + 1u;
    return x * x + y * y < (UINT64_C(1) << 62);
}

/* The SIMD kernel counts exactly what the layout in mc/pi.h says: a plain
 * scalar loop over blocks and lanes reproduces its hit count. n covers two
 * full blocks, a partial block with whole rounds and 5 leftover samples. */
static void test_pi_plain_matches_reference(void **state)
{
    (void)state;
    const uint64_t n = 2 * MC_PI_BLOCK + 7 * MC_PI_LANES + 5, seed = 2385u;
    uint64_t ref = 0;
    for (uint64_t b = 0; b * MC_PI_BLOCK < n; b++) {
        uint64_t count = n - b * MC_PI_BLOCK < MC_PI_BLOCK ? n - b * MC_PI_BLOCK : MC_PI_BLOCK;
        mc_rng lane[MC_PI_LANES];
        for (int l = 0; l < MC_PI_LANES; l++)
            lane[l] = mc_rng_derive(seed, b * MC_PI_LANES + (uint64_t)l);
        for (uint64_t i = 0; i < count; i++) {
            /* Whole rounds go lane by lane; the rest stays on lane 0. */
            ref += ref_hit(i < count - count % MC_PI_LANES ? &lane[i % MC_PI_LANES] : &lane[0]);
        }
    }
    uint64_t hits;
    (void)mc_pi_plain(seed, n, 1, &hits);
    assert_int_equal(hits, ref);
}

/* Same for the stratified grid of n = 1000 + 7 (sx = 31, sy = 32, 15 extra
 * points): row pairs by lanes (column i on lane i % LANES, drawing x, y in
 * row 2m then in row 2m+1), the extra points on their own stream. */
static void test_pi_stratified_matches_reference(void **state)
{
    (void)state;
    const uint64_t n = 1007, seed = 2385u;
    size_t sx, sy;
    mc_strat_grid((size_t)n, &sx, &sy);
    assert_true(sx == 31 && sy == 32);
    uint64_t ref = 0;
    for (uint64_t m = 0; m < sy / 2; m++) {
        mc_rng lane[MC_PI_LANES];
        for (int l = 0; l < MC_PI_LANES; l++)
            lane[l] = mc_rng_derive(seed, UINT64_C(0x8000000000000000) + m * MC_PI_LANES + (uint64_t)l);
        for (uint64_t i = 0; i < sx; i++) {
            for (uint64_t j = 2 * m; j < 2 * m + 2; j++) {
                mc_rng *g = &lane[i % MC_PI_LANES];
                double x = ((double)i + mc_rng_u32(g) * 0x1p-32) / (double)sx;
                double y = ((double)j + mc_rng_u32(g) * 0x1p-32) / (double)sy;
                ref += x * x + y * y < 1.0;
            }
        }
    }
    mc_rng extra = mc_rng_derive(seed, UINT64_C(0xC000000000000001));
    for (uint64_t k = 0; k < n - sx * sy; k++)
        ref += ref_hit(&extra);
    uint64_t hits;
    (void)mc_pi_stratified(seed, n, 1, &hits);
    assert_int_equal(hits, ref);
}

/* Bit-identical results for 1, 2, 3 and 5 threads, for sizes with partial
 * blocks, an odd last row and extra points. */
static void test_pi_thread_count_invariant(void **state)
{
    (void)state;
    const uint64_t sizes[] = {1, 2, 3, 17, 1000003, 3 * MC_PI_BLOCK + 17};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        uint64_t n = sizes[s], h1, s1;
        mc_estimate p1 = mc_pi_plain(77u, n, 1, &h1), q1 = mc_pi_stratified(77u, n, 1, &s1);
        assert_true(isfinite(p1.std_error) && isfinite(q1.std_error));
        for (int threads = 2; threads <= 5; threads += threads == 3 ? 2 : 1) {
            uint64_t h, sh;
            mc_estimate p = mc_pi_plain(77u, n, threads, &h), q = mc_pi_stratified(77u, n, threads, &sh);
            assert_int_equal(h, h1);
            assert_int_equal(sh, s1);
            assert_true(p.value == p1.value && p.std_error == p1.std_error);
            assert_true(q.value == q1.value && q.std_error == q1.std_error);
        }
    }
}

/* At equal n = 10^6 + 1999 (a 1000 x 1001 grid plus 999 extra points) over
 * 8 seeds, the stratified estimates' summed squared error is below the
 * plain ones' (expected ratio ~ 1/700: deterministic in practice), and so
 * is every reported standard error. Negative control: the book's variant
 * (1000^2 points divided by n) must fail the same comparison. */
static void test_pi_stratified_beats_plain(void **state)
{
    negctl *t = *state;
    const uint64_t n = 1001999u;
    double se_plain = 0.0, se_strat = 0.0, se_book = 0.0;
    for (uint64_t k = 0; k < 8; k++) {
        uint64_t seed = mc_test_seed(3100u + k);
        mc_estimate p = mc_pi_plain(seed, n, 0, NULL), s = mc_pi_stratified(seed, n, 0, NULL);
        mc_estimate b = mc_pi_stratified(seed, 1000000u, 0, NULL);
        double book = b.value * 1e6 / (double)n;
        se_plain += (p.value - MC_PI) * (p.value - MC_PI);
        se_strat += (s.value - MC_PI) * (s.value - MC_PI);
        se_book += (book - MC_PI) * (book - MC_PI);
        assert_seeded(s.std_error < p.std_error, seed);
    }
    printf("squared errors over 8 seeds: plain %.3g, stratified %.3g, book's /N variant %.3g\n",
           se_plain, se_strat, se_book);
    assert_seeded(se_strat < se_plain, mc_test_seed(3100u));
    assert_seeded(negctl_record(t, "stratified points divided by the wrong N", "stratified < plain",
                                !(se_book < se_plain)),
                  mc_test_seed(3100u));
}

/* The collapsed-strata error bar is honest (never too small): over 32
 * seeds at n = 10^4 + 7, the sum of z^2 stays below the chi-square(32)
 * quantile of upper tail 6.3e-5 (the |z| < 4 rate); a conservative error
 * bar makes it smaller still. Negative control: the bar divided by 5 must
 * fail (sum z^2 x 25), which it does unless the honest sum falls below
 * 2.9, the quantile over 25; the test asserts both on every run. */
static void test_pi_stratified_error_bar_honest(void **state)
{
    negctl *t = *state;
    double limit = gsl_cdf_chisq_Qinv(6.3e-5, 32.0), sum = 0.0, sum_shrunk = 0.0;
    for (uint64_t k = 0; k < 32; k++) {
        uint64_t seed = mc_test_seed(3200u + k);
        mc_estimate s = mc_pi_stratified(seed, 10007u, 0, NULL);
        double z = (s.value - MC_PI) / s.std_error;
        sum += z * z;
        sum_shrunk += 25.0 * z * z;
    }
    printf("stratified error bar: sum z^2 = %.2f over 32 seeds (limit %.2f)\n", sum, limit);
    if (!(sum < limit))
        fail_msg("sum of z^2 %.2f >= %.2f: the stratified error bar is too small", sum, limit);
    assert_seeded(negctl_record(t, "stratified error bar / 5", "sum of z^2", !(sum_shrunk < limit)),
                  mc_test_seed(3200u));
}

/* Edge cases: n = 1 gives 0 or 4 with a finite error bar; the estimate from
 * hits follows its formula. */
static void test_pi_small_n(void **state)
{
    (void)state;
    mc_estimate e = mc_pi_plain(5u, 1u, 0, NULL);
    assert_true((e.value == 0.0 || e.value == 4.0) && e.std_error == 0.0);
    e = mc_pi_stratified(5u, 1u, 0, NULL);
    assert_true((e.value == 0.0 || e.value == 4.0) && e.std_error == 2.0);
    e = mc_pi_from_hits(3u, 4u);
    assert_near(e.value, 3.0, 0.0);
    assert_near(e.variance, 16.0 * 0.75 * 0.25 * 4.0 / 3.0, 1e-15);
    assert_near(e.std_error, sqrt(e.variance / 4.0), 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pi_plain_z),
        cmocka_unit_test(test_pi_stratified_z),
        cmocka_unit_test(test_pi_z_negative_controls),
        cmocka_unit_test(test_pi_plain_matches_reference),
        cmocka_unit_test(test_pi_stratified_matches_reference),
        cmocka_unit_test(test_pi_thread_count_invariant),
        cmocka_unit_test(test_pi_stratified_beats_plain),
        cmocka_unit_test(test_pi_stratified_error_bar_honest),
        cmocka_unit_test(test_pi_small_n),
    };
    return cmocka_run_group_tests_name("test_pi", tests, negctl_group_setup, negctl_group_teardown);
}
