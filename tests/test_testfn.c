/* tests/test_testfn.c - the integrands of mc/testfn.h and their closed
 * forms: against GSL quadrature in one and two dimensions, against plain
 * Monte Carlo in up to 8, and a wrong closed form that both checks must
 * reject. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/constants.h"
#include "mc/quad.h"
#include "mc/rng.h"
#include "mc/stats.h"
#include "mc/testfn.h"
#include "tests/support/negctl.h"

/* Parameters and limits: dimensions 0 and past the table are refused, pi
 * only in 2D; the peak and the Gaussian are 1 at their centre; centres lie
 * in [0.2, 0.8] and differ between dimensions. */
static void test_testfn_init_and_values(void **state)
{
    (void)state;
    static mc_testfn f;
    assert_false(mc_testfn_init(&f, MC_TESTFN_SMOOTH, 0));
    assert_false(mc_testfn_init(&f, MC_TESTFN_SMOOTH, MC_TESTFN_MAX_DIM + 1));
    assert_false(mc_testfn_init(&f, MC_TESTFN_PI, 3));
    assert_false(mc_testfn_init(&f, MC_TESTFN_PI, 1));
    assert_true(mc_testfn_init(&f, MC_TESTFN_PI, 2));
    assert_near(mc_testfn_eval(&f, (double[]){0.6, 0.79}), 4.0, 0.0);
    assert_near(mc_testfn_eval(&f, (double[]){0.6, 0.81}), 0.0, 0.0);
    assert_near(mc_testfn_exact(&f), MC_PI, 0.0);
    assert_true(mc_testfn_init(&f, MC_TESTFN_SMOOTH, MC_TESTFN_MAX_DIM));
    assert_true(mc_testfn_init(&f, MC_TESTFN_SMOOTH, 3));
    assert_near(mc_testfn_eval(&f, (double[]){0.1, 0.2, 0.385}), exp(0.685), 1e-15);
    assert_near(mc_testfn_exact(&f), pow(exp(1.0) - 1.0, 3.0), 1e-13);
    mc_testfn_kind genz[] = {MC_TESTFN_PEAK, MC_TESTFN_GAUSS};
    for (int k = 0; k < 2; k++) {
        assert_true(mc_testfn_init(&f, genz[k], 7));
        for (unsigned j = 0; j < 7; j++) {
            assert_true(f.u[j] >= 0.2 && f.u[j] <= 0.8);
            assert_true(j == 0 || f.u[j] != f.u[j - 1]);
        }
        assert_near(mc_testfn_eval(&f, f.u), 1.0, 0.0);
        double x[7];
        for (unsigned j = 0; j < 7; j++)
            x[j] = f.u[j];
        x[3] += 0.1;
        double t = f.a[3] * 0.1;
        assert_near(mc_testfn_eval(&f, x), genz[k] == MC_TESTFN_PEAK ? 1.0 / (1.0 + t * t) : exp(-t * t),
                    1e-15);
    }
}

static double peak1(double x, void *p)
{
    const double *au = p;
    double t = au[0] * (x - au[1]);
    return 1.0 / (1.0 + t * t);
}

static double gauss1(double x, void *p)
{
    const double *au = p;
    double t = au[0] * (x - au[1]);
    return exp(-t * t);
}

/* A closed form of the product peak that forgets where the centre is (the
 * one of a peak at u = 1/2): the wrong answer both checks must reject. */
static double peak_centred_integral_1d(double a, double u)
{
    (void)u;
    return 2.0 * atan(0.5 * a) / a;
}

/* The one-dimensional factors against QAGS (error below 1e-12), at
 * sharpnesses and centres that cover narrow peaks, edges and a centre
 * outside the middle: relative agreement to 1e-11. The centred closed form
 * must miss by more. */
static void test_testfn_1d_against_quadrature(void **state)
{
    negctl *t = *state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    static const double cases[][2] = {{5.0, 0.31}, {2.385, 0.77}, {11.3, 0.05}, {0.7, 0.5}, {40.0, 0.93}};
    bool caught = true;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double au[2] = {cases[i][0], cases[i][1]}, r, err;
        assert_int_equal(mc_quad_1d(q, (mc_fn1){peak1, au}, 0.0, 1.0, &r, &err), 0);
        double exact = mc_genz_peak_integral_1d(au[0], au[1]);
        assert_near(r, exact, 1e-11 * exact);
        if (au[1] != 0.5)
            caught &= fabs(r - peak_centred_integral_1d(au[0], au[1])) > 1e-11 * exact;
        assert_int_equal(mc_quad_1d(q, (mc_fn1){gauss1, au}, 0.0, 1.0, &r, &err), 0);
        exact = mc_genz_gauss_integral_1d(au[0], au[1]);
        assert_near(r, exact, 1e-11 * exact);
        printf("1D a = %g, u = %g: peak %.15f, gauss %.15f (quadrature agrees to 1e-11)\n", au[0], au[1],
               mc_genz_peak_integral_1d(au[0], au[1]), exact);
    }
    assert_true(negctl_record(t, "product peak integrated as if centred", "1D quadrature", caught));
    mc_quad_destroy(q);
}

static double testfn2(double x, double y, void *p)
{
    return mc_testfn_eval(p, (double[]){x, y});
}

/* The 2D integrands with their default parameters against nested QAGS:
 * relative agreement to 1e-10. Pi's indicator is not smooth enough for
 * QAGS to promise that; it is checked against plain Monte Carlo below. */
static void test_testfn_2d_against_quadrature(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    static mc_testfn f;
    mc_testfn_kind kinds[] = {MC_TESTFN_SMOOTH, MC_TESTFN_PEAK, MC_TESTFN_GAUSS};
    const char *names[] = {"smooth", "peak", "gauss"};
    for (int k = 0; k < 3; k++) {
        assert_true(mc_testfn_init(&f, kinds[k], 2));
        double r, err, exact = mc_testfn_exact(&f);
        assert_int_equal(mc_quad_2d(q, (mc_fn2){testfn2, &f}, 0.0, 1.0, 0.0, 1.0, &r, &err), 0);
        printf("2D %s: closed form %.15f, quadrature %.15f\n", names[k], exact, r);
        assert_near(r, exact, 1e-10 * exact);
    }
    mc_quad_destroy(q);
}

/* The plain Monte Carlo mean of f over n PCG32 points of [0,1)^D, with
 * its standard error. */
static mc_estimate plain_mc(const mc_testfn *f, uint64_t seed, uint64_t n)
{
    mc_rng rng = mc_rng_derive(seed, f->dim);
    mc_welford w = mc_welford_init();
    double x[8];
    for (uint64_t i = 0; i < n; i++) {
        for (unsigned j = 0; j < f->dim; j++)
            x[j] = mc_rng_uniform(&rng);
        mc_welford_add(&w, mc_testfn_eval(f, x));
    }
    return mc_welford_estimate(&w);
}

/* Each closed form against plain Monte Carlo: 2^17 PCG32 points per case,
 * pi in 2D and the three others in 1, 2, 5 and 8 dimensions (13 z-tests,
 * |z| < 4, false-alarm rate 13 * 6.3e-5 = 8e-4 for the whole test; seed
 * 9101). Negative control: the centred peak formula in 5D must give
 * |z| >= 4 against the same estimate (it is 13 % too high per dimension
 * for the default centres). */
static void test_testfn_mc_ztest(void **state)
{
    negctl *t = *state;
    enum { N = 1 << 17 };
    uint64_t seed = mc_test_seed(9101u);
    static mc_testfn f;
    assert_true(mc_testfn_init(&f, MC_TESTFN_PI, 2));
    mc_estimate e = plain_mc(&f, seed, N);
    assert_z_below("pi 2D", e.value, mc_testfn_exact(&f), e.std_error, 4.0, seed);
    mc_testfn_kind kinds[] = {MC_TESTFN_SMOOTH, MC_TESTFN_PEAK, MC_TESTFN_GAUSS};
    const char *names[] = {"smooth", "peak", "gauss"};
    unsigned dims[] = {1, 2, 5, 8};
    for (int k = 0; k < 3; k++) {
        for (int d = 0; d < 4; d++) {
            assert_true(mc_testfn_init(&f, kinds[k], dims[d]));
            e = plain_mc(&f, seed + 100u * (unsigned)k, N);
            char label[64];
            snprintf(label, sizeof label, "%s %uD", names[k], dims[d]);
            assert_z_below(label, e.value, mc_testfn_exact(&f), e.std_error, 4.0, seed);
        }
    }
    assert_true(mc_testfn_init(&f, MC_TESTFN_PEAK, 5));
    e = plain_mc(&f, seed, N);
    double wrong = 1.0;
    for (unsigned j = 0; j < 5; j++)
        wrong *= peak_centred_integral_1d(f.a[j], f.u[j]);
    double z = mc_z_score(e.value, wrong, e.std_error);
    printf("centred peak formula in 5D: exact %.6g, wrong %.6g, z = %.1f\n", mc_testfn_exact(&f), wrong, z);
    assert_seeded(negctl_record(t, "product peak integrated as if centred (5D)", "z-test", fabs(z) >= 4.0),
                  seed);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_testfn_init_and_values),
        cmocka_unit_test(test_testfn_1d_against_quadrature),
        cmocka_unit_test(test_testfn_2d_against_quadrature),
        cmocka_unit_test(test_testfn_mc_ztest),
    };
    return cmocka_run_group_tests_name("test_testfn", tests, negctl_group_setup, negctl_group_teardown);
}
