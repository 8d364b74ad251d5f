/* tests/test_integrate.c - the estimators of mc/integrate.h (this book's
 * #ch-integration) with the warps of samplers/warp1d.h: the integral of x^2
 * under three densities, the halfway point of exp(-x/2pi) sin^2 x, and the
 * integral of ln(sin x), each z-tested against a value derived here
 * independently (closed form, GSL quadrature, GSL root finding), each with a
 * biased estimator the same test rejects. */
#define _POSIX_C_SOURCE 200809L /* popen */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "mc/constants.h"
#include "mc/integrate.h"
#include "mc/quad.h"
#include "samplers/warp1d.h"
#include "tests/support/negctl.h"

/* Every z-test below: |z| < 4, two-sided false-alarm rate 6.3e-5 per test. */
#define Z_MAX 4.0
#define EXACT_X_SQ (8.0 / 3.0)

static double x_squared(double x, void *p) { (void)p; return x * x; }
static double uniform02_sample(double u) { return 2.0 * u; }
static double uniform02_pdf(double x) { return x >= 0.0 && x <= 2.0 ? 0.5 : 0.0; }
/* The book's slip: 8 cbrt(u) instead of 2 cbrt(u), paired (as in the book)
 * with the formula 3x^2/8 and no support check. */
static double quadratic_bug_sample(double u) { return 8.0 * cbrt(u); }
static double quadratic_formula_pdf(double x) { return 0.375 * x * x; }

static const mc_fn1 fx2 = {x_squared, NULL};

/* x^2 on [0, 2] with p = 1/2 and p = x/2, 10^6 samples (seeds 6001, 6002):
 * z-tests, and the variance per sample against its exact value (256/45 and
 * 8/9) within 4 standard deviations of a sample variance,
 * sqrt((mu4 - sigma^4) / n) = 0.107% and 0.118% relative (from the exact
 * moments E[Y^k] of the weights). */
static void test_integrate_x_sq_z(void **state)
{
    (void)state;
    const mc_warp1 w[2] = {{uniform02_sample, uniform02_pdf}, {smp_linear_sample, smp_linear_pdf}};
    const double var[2] = {256.0 / 45.0, 8.0 / 9.0}, rel_sd[2] = {0.00107, 0.00118};
    for (int i = 0; i < 2; i++) {
        uint64_t seed = mc_test_seed(6001u + (uint64_t)i);
        mc_rng rng = mc_rng_derive(seed, 0u);
        mc_estimate e = mc_integrate_is(fx2, w[i], &rng, 1000000u, NULL);
        const char *label = i ? "x^2, linear pdf" : "x^2, uniform pdf";
        assert_z_below(label, e.value, EXACT_X_SQ, e.std_error, Z_MAX, seed);
        assert_z_below("its variance", e.variance, var[i], rel_sd[i] * var[i], Z_MAX, seed);
    }
    uint64_t seed = mc_test_seed(6003u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate e = mc_integrate_uniform(fx2, 0.0, 2.0, &rng, 1000000u, NULL);
    assert_z_below("x^2, mc_integrate_uniform", e.value, EXACT_X_SQ, e.std_error, Z_MAX, seed);
}

/* Negative control: samples drawn uniformly but weighted with the linear
 * pdf x/2 estimate E[2x] = 2, not 8/3 (z ~ 700). */
static void test_integrate_x_sq_negative_control(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(6004u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate e = mc_integrate_is(fx2, (mc_warp1){uniform02_sample, smp_linear_pdf}, &rng, 1000000u, NULL);
    assert_seeded(negctl_record(t, "uniform samples weighted by the linear pdf", "z-test",
                                fabs(mc_z_score(e.value, EXACT_X_SQ, e.std_error)) >= Z_MAX),
                  seed);
}

/* The perfect density p = 3x^2/8: every weight is 8/3 up to round-off, so
 * the variance is zero to rounding (below 1e-28, i.e. 1e-14 relative
 * spread) and the estimate is 8/3 to 1e-14. */
static void test_integrate_x_sq_quadratic_zero_variance(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(6005u), 0u);
    const mc_warp1 w = {smp_quadratic_sample, smp_quadratic_pdf};
    mc_estimate e = mc_integrate_is(fx2, w, &rng, 100000u, NULL);
    assert_near(e.value, EXACT_X_SQ, 1e-14);
    assert_true(e.variance <= 1e-28);
}

/* The book's 8 cbrt(u): the estimate is still 8/3 with zero variance, so
 * neither the z-test nor the variance can see it; the domain check (every
 * sample of a density on [0, 2] must lie in [0, 2]) does. Negative control
 * for the domain check, which the correct sampler passes. */
static void test_integrate_book_cbrt_bug_caught_by_domain(void **state)
{
    negctl *t = *state;
    enum { N = 10000 };
    static mc_weighted rec[N];
    const mc_warp1 right = {smp_quadratic_sample, smp_quadratic_pdf};
    const mc_warp1 wrong = {quadratic_bug_sample, quadratic_formula_pdf};
    int outside[2] = {0, 0};
    for (int i = 0; i < 2; i++) {
        mc_rng rng = mc_rng_derive(mc_test_seed(6006u), 0u);
        mc_estimate e = mc_integrate_is(fx2, i ? wrong : right, &rng, N, rec);
        assert_near(e.value, EXACT_X_SQ, 1e-14); /* the bug is invisible here */
        assert_true(e.variance <= 1e-28);
        for (int k = 0; k < N; k++)
            outside[i] += !(rec[k].x >= 0.0 && rec[k].x <= 2.0);
    }
    assert_int_equal(outside[0], 0);
    assert_true(negctl_record(t, "quadratic pdf sampled by 8 cbrt(u)", "domain [0, 2]", outside[1] > 0));
}

/* --- the halfway point -------------------------------------------------- */

static double halfway_f(double x, void *p)
{
    (void)p;
    double s = sin(x);
    return exp(-x * MC_INV_2PI) * s * s;
}

typedef struct partial {
    mc_quad *q;
    double target;
} partial;

/* The integral of f from 0 to x, minus the target, by GSL quadrature. */
static double partial_minus_target(double x, void *params)
{
    const partial *p = params;
    double v = 0.0;
    (void)mc_quad_1d(p->q, (mc_fn1){halfway_f, NULL}, 0.0, x, &v, NULL);
    return v - p->target;
}

/* I by quadrature and h by Brent's method on the quadrature's partial
 * integrals (bracket [1, 3], tolerance 1e-14). */
static void halfway_exact(double *integral, double *h)
{
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    assert_int_equal(mc_quad_1d(q, (mc_fn1){halfway_f, NULL}, 0.0, MC_2PI, integral, NULL), 0);
    partial p = {q, 0.5 * *integral};
    gsl_function fn = {partial_minus_target, &p};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    assert_non_null(s);
    gsl_root_fsolver_set(s, &fn, 1.0, 3.0);
    for (int it = 0; it < 100; it++) {
        gsl_root_fsolver_iterate(s);
        double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(lo, hi, 1e-14, 0.0) == GSL_SUCCESS)
            break;
    }
    *h = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    mc_quad_destroy(q);
}

/* The value in column `col` (0-based) of the CSV row `method` printed by
 * `cmd`, or NaN when the program is missing or has no such row. */
static double csv_value(const char *cmd, const char *method, int col)
{
    FILE *f = popen(cmd, "r");
    double v = nan("");
    char line[1024];
    while (f && fgets(line, sizeof line, f)) {
        size_t len = strlen(method);
        if (strncmp(line, method, len) != 0 || line[len] != ',')
            continue;
        char *p = line;
        for (int c = 0; c < col && p; c++)
            p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL;
        if (p)
            v = strtod(p, NULL);
    }
    if (f)
        pclose(f);
    return v;
}

/* The exact values: quadrature against the closed form
 * (1 - 1/e)(pi - a / (2(a^2 + 4))), a = 1/2pi, and both against the
 * digits of an independent evaluation (1.97336880, 2.0384319) and the
 * exact column printed by build/bin/estimate_halfway (when built). */
static void test_halfway_exact_values(void **state)
{
    (void)state;
    double integral, h;
    halfway_exact(&integral, &h);
    const double a = MC_INV_2PI;
    assert_near(integral, (1.0 - exp(-1.0)) * (MC_PI - a / (2.0 * (a * a + 4.0))), 1e-12);
    assert_near(integral, 1.97336880, 5e-9);
    assert_near(h, 2.0384319, 5e-8);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "%s/bin/estimate_halfway --csv --samples 1000 2>/dev/null",
             mc_test_build_dir());
    double pi = csv_value(cmd, "integral", 4), ph = csv_value(cmd, "halfway", 4);
    if (isnan(pi) || isnan(ph)) {
        printf("estimate_halfway not built: its exact column is not checked\n");
        return;
    }
    assert_near(pi, integral, 1e-12);
    assert_near(ph, h, 1e-12);
}

/* Integral and halfway point from 10^6 uniform samples (seed 6010),
 * z-tested against the derived values; the halfway point's error bar is
 * the delta-method one of mc_weighted_quantile. */
static void test_halfway_z(void **state)
{
    (void)state;
    enum { N = 1000000 };
    double integral, h;
    halfway_exact(&integral, &h);
    mc_weighted *rec = malloc(N * sizeof *rec);
    assert_non_null(rec);
    uint64_t seed = mc_test_seed(6010u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_fn1 f = {halfway_f, NULL};
    mc_estimate e = mc_integrate_uniform(f, 0.0, MC_2PI, &rng, N, rec);
    assert_z_below("halfway integral", e.value, integral, e.std_error, Z_MAX, seed);
    qsort(rec, N, sizeof *rec, mc_weighted_compare);
    mc_estimate q = mc_weighted_quantile(rec, N, 0.5, f);
    assert_z_below("halfway point", q.value, h, q.std_error, Z_MAX, seed);
    free(rec);
}

/* The halfway error bar is honest: over 32 seeds at n = 2 x 10^4, sum z^2
 * stays below the chi-square(32) quantile of upper tail 6.3e-5. Negative
 * control: the unweighted median of the x (forgetting the weights, which
 * gives pi, not 2.04) fails the z-test of every seed. */
static void test_halfway_error_bar_and_negative_control(void **state)
{
    negctl *t = *state;
    enum { N = 20000 };
    static mc_weighted rec[N];
    double integral, h;
    halfway_exact(&integral, &h);
    mc_fn1 f = {halfway_f, NULL};
    double sum = 0.0, limit = gsl_cdf_chisq_Qinv(6.3e-5, 32.0);
    int caught = 0;
    for (uint64_t k = 0; k < 32; k++) {
        mc_rng rng = mc_rng_derive(mc_test_seed(6100u + k), 0u);
        (void)mc_integrate_uniform(f, 0.0, MC_2PI, &rng, N, rec);
        qsort(rec, N, sizeof *rec, mc_weighted_compare);
        mc_estimate q = mc_weighted_quantile(rec, N, 0.5, f);
        sum += (q.value - h) * (q.value - h) / (q.std_error * q.std_error);
        double median = 0.5 * (rec[N / 2 - 1].x + rec[N / 2].x);
        caught += fabs(mc_z_score(median, h, q.std_error)) >= Z_MAX;
    }
    printf("halfway error bar: sum z^2 = %.2f over 32 seeds (limit %.2f)\n", sum, limit);
    if (!(sum < limit))
        fail_msg("sum of z^2 %.2f >= %.2f: the halfway error bar is too small", sum, limit);
    assert_seeded(
        negctl_record(t, "unweighted median as the halfway point", "z-test", caught == 32),
        mc_test_seed(6100u));
}

/* --- ln(sin x) ------------------------------------------------------------ */

static double log_sin(double x, void *p) { (void)p; return log(sin(x)); }
static double log_sin_sq_over_p(double x, void *p)
{
    (void)p;
    double l = log(sin(x));
    return l * l / smp_log_ends_pdf(x);
}
static double log_ends_pdf_101(double x) { return 1.01 * smp_log_ends_pdf(x); }

/* -pi ln 2 against quadrature; then plain (variance pi^4/12) and importance
 * sampling, 10^6 samples each (seeds 6201, 6202), z-tested, with their
 * variances within 4 sd of a sample variance (1.29% and 0.64% relative,
 * from the fourth moments) of the exact ones (the importance one is the
 * quadrature of f^2/p minus I^2), and the importance variance below a
 * tenth of the plain one. */
static void test_log_sin_z(void **state)
{
    (void)state;
    const double exact = -MC_PI * MC_LN2;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    double left, right, m2l, m2r;
    (void)mc_quad_1d(q, (mc_fn1){log_sin, NULL}, 0.0, MC_PI_2, &left, NULL);
    (void)mc_quad_1d(q, (mc_fn1){log_sin, NULL}, MC_PI_2, MC_PI, &right, NULL);
    (void)mc_quad_1d(q, (mc_fn1){log_sin_sq_over_p, NULL}, 0.0, MC_PI_2, &m2l, NULL);
    (void)mc_quad_1d(q, (mc_fn1){log_sin_sq_over_p, NULL}, MC_PI_2, MC_PI, &m2r, NULL);
    mc_quad_destroy(q);
    assert_near(left + right, exact, 1e-10);
    double var_is = m2l + m2r - exact * exact, var_plain = MC_PI * MC_PI * MC_PI * MC_PI / 12.0;

    const mc_fn1 f = {log_sin, NULL};
    uint64_t seed = mc_test_seed(6201u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate p = mc_integrate_uniform(f, 0.0, MC_PI, &rng, 1000000u, NULL);
    assert_z_below("ln sin, plain", p.value, exact, p.std_error, Z_MAX, seed);
    assert_z_below("its variance", p.variance, var_plain, 0.00322 * var_plain, Z_MAX, seed);
    seed = mc_test_seed(6202u);
    rng = mc_rng_derive(seed, 0u);
    const mc_warp1 w = {smp_log_ends_sample, smp_log_ends_pdf};
    mc_estimate is = mc_integrate_is(f, w, &rng, 1000000u, NULL);
    assert_z_below("ln sin, importance", is.value, exact, is.std_error, Z_MAX, seed);
    assert_z_below("its variance", is.variance, var_is, 0.00161 * var_is, Z_MAX, seed);
    assert_seeded(is.variance < 0.1 * p.variance, seed);
}

/* Negative control: the importance estimator with its pdf 1% too large
 * is biased by -1% (z ~ 38). */
static void test_log_sin_negative_control(void **state)
{
    negctl *t = *state;
    mc_rng rng = mc_rng_derive(mc_test_seed(6203u), 0u);
    const mc_warp1 w = {smp_log_ends_sample, log_ends_pdf_101};
    mc_estimate e = mc_integrate_is((mc_fn1){log_sin, NULL}, w, &rng, 1000000u, NULL);
    assert_seeded(negctl_record(t, "ln sin with the pdf scaled by 1.01", "z-test",
                                fabs(mc_z_score(e.value, -MC_PI * MC_LN2, e.std_error)) >= Z_MAX),
                  mc_test_seed(6203u));
}

/* The importance weight ln(sin x) / p(x) lies in [-pi, 0] (Jordan's
 * inequality), which is why its variance is finite: checked on a grid of
 * u including the extreme open-interval values. */
static void test_log_sin_weight_bounded(void **state)
{
    (void)state;
    for (int k = 0; k <= 100000; k++) {
        double u = k == 0 ? 0x1p-33 : (k == 100000 ? 1.0 - 0x1p-33 : k / 100000.0);
        double x = smp_log_ends_sample(u);
        double p = smp_log_ends_pdf(x);
        /* At x = pi/2 both vanish; mc_integrate_is counts 0/0 as 0. */
        double w = p > 0.0 ? log(sin(x)) / p : 0.0;
        if (!(w >= -MC_PI - 1e-9 && w <= 0.0))
            fail_msg("u %.17g: x %.17g, weight %.17g", u, x, w);
    }
}

/* --- building blocks ------------------------------------------------------ */

static double zero_pdf(double x) { (void)x; return 0.0; }

static void test_integrate_building_blocks(void **state)
{
    (void)state;
    mc_fn1 one = {halfway_f, NULL};
    mc_weighted s[4] = {{1.0, 1.0}, {2.0, 1.0}, {3.0, 1.0}, {4.0, 1.0}};
    assert_near(mc_weighted_quantile(s, 4, 0.5, one).value, 2.0, 0.0);
    assert_near(mc_weighted_quantile(s, 4, 0.75, one).value, 3.0, 0.0);
    assert_near(mc_weighted_quantile(s, 4, 0.76, one).value, 4.0, 0.0);
    mc_weighted unsorted[3] = {{2.0, 1.0}, {1.0, 1.0}, {3.0, 1.0}};
    assert_true(isnan(mc_weighted_quantile(unsorted, 3, 0.5, one).value));
    mc_weighted negative[3] = {{1.0, 1.0}, {2.0, -1.0}, {3.0, 1.0}};
    assert_true(isnan(mc_weighted_quantile(negative, 3, 0.5, one).value));
    /* mc_uniform_open never returns 0 or 1: the extreme outputs are
     * 2^-33 and 1 - 2^-33. */
    mc_rng lo = {0u, 1u};
    for (int i = 0; i < 1000; i++) {
        double u = mc_uniform_open(&lo);
        assert_true(u > 0.0 && u < 1.0);
    }
    assert_true(((double)UINT32_MAX + 0.5) * 0x1p-32 < 1.0 && 0.5 * 0x1p-32 > 0.0);
    /* A density that is 0 where the samples fall contributes 0, not NaN. */
    mc_rng rng = mc_rng_derive(1u, 0u);
    mc_estimate e = mc_integrate_is(fx2, (mc_warp1){uniform02_sample, zero_pdf}, &rng, 100u, NULL);
    assert_true(e.value == 0.0 && e.variance == 0.0);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_integrate_x_sq_z),
        cmocka_unit_test(test_integrate_x_sq_negative_control),
        cmocka_unit_test(test_integrate_x_sq_quadratic_zero_variance),
        cmocka_unit_test(test_integrate_book_cbrt_bug_caught_by_domain),
        cmocka_unit_test(test_halfway_exact_values),
        cmocka_unit_test(test_halfway_z),
        cmocka_unit_test(test_halfway_error_bar_and_negative_control),
        cmocka_unit_test(test_log_sin_z),
        cmocka_unit_test(test_log_sin_negative_control),
        cmocka_unit_test(test_log_sin_weight_bounded),
        cmocka_unit_test(test_integrate_building_blocks),
    };
    return cmocka_run_group_tests_name("test_integrate", tests, negctl_group_setup, negctl_group_teardown);
}
