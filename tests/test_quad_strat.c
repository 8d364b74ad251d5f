/* tests/test_quad_strat.c - quadrature accuracy and jittered sample sets. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdlib.h>

#include "mc/constants.h"
#include "mc/quad.h"
#include "mc/stats.h"
#include "mc/strat.h"
#include "tests/support/negctl.h"

static double f_sin(double x, void *p) { (void)p; return sin(x); }
static double f_inv_sqrt(double x, void *p) { (void)p; return 1.0 / sqrt(x); }
static double f_log_sin(double x, void *p) { (void)p; return log(sin(x)); }
static double f_gauss(double x, void *p) { (void)p; return exp(-x * x); }
static double f_xy_exp(double x, double y, void *p) { (void)p; return x * y * exp(x + y); }
static double f_sin_theta(double theta, double phi, void *p) { (void)p; (void)phi; return sin(theta); }

/* Smooth and singular integrands with known values, to 1e-9 or better. */
static void test_quad_1d_known_integrals(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    double r, err;
    assert_int_equal(mc_quad_1d(q, (mc_fn1){f_sin, NULL}, 0.0, MC_PI, &r, &err), 0);
    assert_near(r, 2.0, 1e-12);
    assert_true(err < 1e-9);
    /* Integrable endpoint singularities, which QAGS extrapolates away. */
    mc_quad_1d(q, (mc_fn1){f_inv_sqrt, NULL}, 0.0, 1.0, &r, &err);
    assert_near(r, 2.0, 1e-9);
    mc_quad_1d(q, (mc_fn1){f_log_sin, NULL}, 0.0, MC_PI, &r, &err);
    assert_near(r, -MC_PI * MC_LN2, 1e-9);
    /* erf(2.385) sqrt(pi) / 2 over [0, 2.385]. */
    mc_quad_1d(q, (mc_fn1){f_gauss, NULL}, 0.0, 2.385, &r, &err);
    assert_near(r, erf(2.385) * sqrt(MC_PI) / 2.0, 1e-12);
    mc_quad_destroy(q);
    mc_quad_destroy(NULL);
}

static void test_quad_2d_known_integrals(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    double r, err;
    /* (integral_0^1 x e^x dx)^2 = 1. */
    assert_int_equal(mc_quad_2d(q, (mc_fn2){f_xy_exp, NULL}, 0.0, 1.0, 0.0, 1.0, &r, &err), 0);
    assert_near(r, 1.0, 1e-10);
    /* The area of the unit sphere in (theta, phi): 4 pi. */
    mc_quad_2d(q, (mc_fn2){f_sin_theta, NULL}, 0.0, MC_PI, 0.0, MC_2PI, &r, &err);
    assert_near(r, MC_4PI, 1e-10);
    /* Over a sub-rectangle: (1 - cos 0.3)(0.7) exactly. */
    mc_quad_2d(q, (mc_fn2){f_sin_theta, NULL}, 0.0, 0.3, 1.0, 1.7, &r, &err);
    assert_near(r, (1.0 - cos(0.3)) * 0.7, 1e-13);
    mc_quad_destroy(q);
}

static double f_log_y(double x, double y, void *p) { (void)p; (void)x; return log(y); }

/* The 2D error estimate is the outer one plus the largest inner one times
 * the width x1 - x0: the same on [1000, 1001] as on [0, 1] for an
 * integrand that does not depend on x (an estimate scaled by x1, or by x0,
 * would be 1001 times larger, or 0), and it covers the actual error. */
static void test_quad_2d_error_on_shifted_limits(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    double r0, e0, r1, e1;
    /* integral_0^1 log y dy = -1 for every x: the inner rule's error
     * estimate is not 0 (the singularity at y = 0). */
    mc_quad_2d(q, (mc_fn2){f_log_y, NULL}, 0.0, 1.0, 0.0, 1.0, &r0, &e0);
    mc_quad_2d(q, (mc_fn2){f_log_y, NULL}, 1000.0, 1001.0, 0.0, 1.0, &r1, &e1);
    assert_near(r0, -1.0, 1e-12);
    assert_near(r1, -1.0, 1e-12);
    assert_true(e0 > 0.0);
    if (!(e1 <= 2.0 * e0 && e1 >= 0.5 * e0))
        fail_msg("error estimate %.3g on [1000, 1001] against %.3g on [0, 1]", e1, e0);
    assert_true(fabs(r1 + 1.0) <= e1 + 1e-15);
    /* Width 2.385 from x0 = 7: the inner part scales by the width. */
    double r2, e2;
    mc_quad_2d(q, (mc_fn2){f_log_y, NULL}, 7.0, 9.385, 0.0, 1.0, &r2, &e2);
    assert_near(r2, -2.385, 1e-11);
    if (!(e2 <= 2.0 * 2.385 * e0 && e2 >= 0.5 * 2.385 * e0))
        fail_msg("error estimate %.3g on [7, 9.385] against %.3g on [0, 1]", e2, e0);
    mc_quad_destroy(q);
}

static void test_strat_grid_shapes(void **state)
{
    (void)state;
    size_t sx, sy;
    mc_strat_grid(1, &sx, &sy);
    assert_true(sx == 1 && sy == 1);
    mc_strat_grid(10, &sx, &sy); /* 3 x 3 grid and 1 extra point */
    assert_true(sx == 3 && sy == 3);
    mc_strat_grid(12, &sx, &sy); /* 3 x 4: no extra */
    assert_true(sx == 3 && sy == 4);
    mc_strat_grid(100000000, &sx, &sy);
    assert_true(sx == 10000 && sy == 10000);
    /* Around a large perfect square, where sqrt in double can round up. */
    size_t k = 94906265u; /* k^2 < 2^53 */
    mc_strat_grid(k * k - 1, &sx, &sy);
    assert_true(sx == k - 1 && sy * sx <= k * k - 1 && k * k - 1 - sx * sy < sx);
    mc_strat_grid(k * k, &sx, &sy);
    assert_true(sx == k && sy == k);
    /* For every n: sx sy <= n and fewer than sx extra points. */
    for (size_t n = 1; n < 5000; n++) {
        mc_strat_grid(n, &sx, &sy);
        assert_true(sx * sy <= n && n - sx * sy < sx && sx * sx <= n && (sx + 1) * (sx + 1) > n);
    }
}

/* Each grid point lies in its own cell, each 1D point in its own stratum. */
static void test_strat_one_point_per_cell(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(3001u), 0u);
    enum { N = 1000 };
    double xy[2 * N], x1[N];
    mc_jitter_2d(&rng, N, xy); /* 31 x 32 grid + 8 extra */
    size_t sx, sy;
    mc_strat_grid(N, &sx, &sy);
    for (size_t j = 0; j < sy; j++) {
        for (size_t i = 0; i < sx; i++) {
            const double *p = &xy[2 * (j * sx + i)];
            assert_true(p[0] >= (double)i / sx && p[0] < (double)(i + 1) / sx);
            assert_true(p[1] >= (double)j / sy && p[1] < (double)(j + 1) / sy);
        }
    }
    for (size_t k = 0; k < 2 * N; k++)
        assert_true(xy[k] >= 0.0 && xy[k] < 1.0);
    mc_jitter_1d(&rng, N, x1);
    for (size_t i = 0; i < N; i++)
        assert_true(x1[i] >= (double)i / N && x1[i] < (double)(i + 1) / N);
}

/* For n >= 2^21 the last stratum's (n - 1 + u) / n with u = 1 - 2^-32 (the
 * largest uniform) rounds to exactly 1.0. A random stream meets that draw
 * with probability 2^-32, so the test builds the stream instead: a PCG
 * state whose output is 0xffffffff (bits 41..58 set make every bit of the
 * XSH-RR xorshift 1, whatever the rotation), stepped back n - 1 draws so
 * that the last stratum gets it. Deterministic; no seed or threshold. */
static void test_strat_1d_large_n_half_open(void **state)
{
    (void)state;
    enum { N = 3000000 };
    mc_rng rng = {((UINT64_C(1) << 18) - 1u) << 41, 1u};
    mc_rng probe = rng;
    assert_true(mc_rng_u32(&probe) == UINT32_MAX);
    mc_rng_advance(&rng, UINT64_C(0) - (uint64_t)(N - 1)); /* the period is 2^64 */
    double *x = malloc(N * sizeof *x);
    assert_non_null(x);
    mc_jitter_1d(&rng, N, x);
    size_t bad = 0;
    for (size_t i = 0; i < N; i++)
        bad += !(x[i] >= 0.0 && x[i] < 1.0);
    free(x);
    assert_int_equal(bad, 0);
}

/* The mean of f(x, y) = x + y^2 (exact 1/2 + 1/3) over jittered sets of a
 * non-square size N = 10 (3 x 3 grid + 1 extra), averaged over 200000
 * independent sets: unbiased, so |z| < 4 (seed 3002; false alarm 6.3e-5).
 * Negative control: the book's recipe (use only the floor(sqrt N)^2 grid
 * points but divide by N) is biased by a factor 9/10 and must be rejected. */
static void test_strat_non_square_unbiased(void **state)
{
    negctl *t = *state;
    enum { N = 10, REPS = 200000 };
    uint64_t seed = mc_test_seed(3002u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_welford ours = mc_welford_init(), book = mc_welford_init();
    double xy[2 * N];
    for (int r = 0; r < REPS; r++) {
        mc_jitter_2d(&rng, N, xy);
        double all = 0.0, grid = 0.0;
        for (int k = 0; k < N; k++) {
            double f = xy[2 * k] + xy[2 * k + 1] * xy[2 * k + 1];
            all += f;
            if (k < 9)
                grid += f;
        }
        mc_welford_add(&ours, all / N);
        mc_welford_add(&book, grid / N);
    }
    double exact = 0.5 + 1.0 / 3.0;
    assert_z_below("jittered N = 10", ours.mean, exact, mc_welford_std_error(&ours), 4.0, seed);
    assert_seeded(
        negctl_record(t, "floor(sqrt N)^2 grid points divided by N", "z-test",
                      fabs(mc_z_score(book.mean, exact, mc_welford_std_error(&book))) >= 4.0),
        seed);
}

/* Stratification helps: over 8 seeds the RMS error of the jittered mean of
 * a smooth f with N = 4096 is below that of plain sampling. The expected
 * ratio is about N^-1/2 = 1/64 for smooth f; requiring only < 1/4 leaves
 * no room for a false alarm. */
static void test_strat_beats_plain(void **state)
{
    (void)state;
    enum { N = 4096, SEEDS = 8 };
    static double xy[2 * N];
    double exact = 0.5 + 1.0 / 3.0, se_strat = 0.0, se_plain = 0.0;
    for (int s = 0; s < SEEDS; s++) {
        mc_rng rng = mc_rng_derive(mc_test_seed(3003u), (uint64_t)s);
        mc_jitter_2d(&rng, N, xy);
        double a = 0.0, b = 0.0;
        for (int k = 0; k < N; k++) {
            a += xy[2 * k] + xy[2 * k + 1] * xy[2 * k + 1];
            double x = mc_rng_uniform(&rng), y = mc_rng_uniform(&rng);
            b += x + y * y;
        }
        se_strat += (a / N - exact) * (a / N - exact);
        se_plain += (b / N - exact) * (b / N - exact);
    }
    assert_seeded(sqrt(se_strat) < 0.25 * sqrt(se_plain), mc_test_seed(3003u));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quad_1d_known_integrals),
        cmocka_unit_test(test_quad_2d_known_integrals),
        cmocka_unit_test(test_quad_2d_error_on_shifted_limits),
        cmocka_unit_test(test_strat_grid_shapes),
        cmocka_unit_test(test_strat_one_point_per_cell),
        cmocka_unit_test(test_strat_1d_large_n_half_open),
        cmocka_unit_test(test_strat_non_square_unbiased),
        cmocka_unit_test(test_strat_beats_plain),
    };
    return cmocka_run_group_tests_name("test_quad_strat", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
