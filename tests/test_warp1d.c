/* tests/test_warp1d.c - the 1D inverse-CDF warps of samplers/warp1d.h:
 * chi-square against their pdfs, normalization, domain, round trip, and the
 * pdf as the derivative of the CDF; wrong samplers as negative controls. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/constants.h"
#include "mc/rng.h"
#include "samplers/warp1d.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"

typedef struct warp1 {
    const char *name;
    double (*sample)(double u);
    double (*pdf)(double x);
    double (*invert)(double x);
    double lo, hi; /* the support */
} warp1;

static const warp1 warps[] = {
    {"linear", smp_linear_sample, smp_linear_pdf, smp_linear_invert, 0.0, 2.0},
    {"quadratic", smp_quadratic_sample, smp_quadratic_pdf, smp_quadratic_invert, 0.0, 2.0},
    {"sine", smp_sine_sample, smp_sine_pdf, smp_sine_invert, 0.0, MC_PI},
    {"log_ends", smp_log_ends_sample, smp_log_ends_pdf, smp_log_ends_invert, 0.0, MC_PI},
};
enum { N_WARPS = sizeof warps / sizeof warps[0] };

/* --- adapters to the chi-square harness ---------------------------------- */

static void sample_warp(mc_rng *rng, void *ctx, double out[2])
{
    const warp1 *w = ctx;
    out[0] = w->sample(mc_rng_uniform(rng));
    out[1] = 0.0;
}

static double pdf_warp(const double x[2], void *ctx)
{
    const warp1 *w = ctx;
    return w->pdf(x[0]);
}

static chi2_spec spec_of(const warp1 *w)
{
    chi2_spec s = {w->name, 1, {w->lo, 0.0}, {w->hi, 1.0}, {64, 1}, sample_warp, pdf_warp, (void *)w};
    return s;
}

/* Chi-square: 2 x 10^5 samples in 64 equal cells per warp (expected
 * counts from the pdf integrated over each cell), rejected at the suite
 * level chi2_suite_alpha() ~ 1.6e-4 (Sidak: 1% over the suite's 64 tests),
 * seeds 4001 + i. */
static void test_warp1d_chi2(void **state)
{
    (void)state;
    for (int i = 0; i < N_WARPS; i++) {
        chi2_spec s = spec_of(&warps[i]);
        uint64_t seed = mc_test_seed(4001u + (uint64_t)i);
        chi2_outcome o = chi2_run(&s, 200000u, seed, chi2_suite_alpha());
        chi2_print(&s, &o);
        if (o.reject)
            fail_msg("%s: chi-square rejects (p %.3g, seed %llu)", warps[i].name, o.r.pvalue,
                     (unsigned long long)seed);
    }
}

/* log_ends has a second, independent sampler: on a half, t = u1 u2 has the
 * density -ln t (P(u1 u2 <= t) = t - t ln t). Its agreement with the pdf
 * confirms the density itself, not only its inversion. Same test level. */
static void sample_log_ends_product(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    double t = mc_rng_uniform(rng) * mc_rng_uniform(rng);
    double x = MC_PI_2 * t;
    out[0] = mc_rng_uniform(rng) < 0.5 ? x : MC_PI - x;
}

static void test_warp1d_log_ends_product_chi2(void **state)
{
    (void)state;
    chi2_spec s = spec_of(&warps[3]);
    s.name = "log_ends-product";
    s.sample = sample_log_ends_product;
    uint64_t seed = mc_test_seed(4011u);
    chi2_outcome o = chi2_run(&s, 200000u, seed, chi2_suite_alpha());
    chi2_print(&s, &o);
    if (o.reject)
        fail_msg("u1 u2 sampler vs log_ends pdf: p %.3g (seed %llu)", o.r.pvalue, (unsigned long long)seed);
}

/* Negative controls: samplers that do not draw the claimed density. */
static double uniform02(double u) { return 2.0 * u; }
static double uniform0pi(double u) { return MC_PI * u; }
static double quadratic_book_bug(double u) { return 8.0 * cbrt(u); }
static double log_ends_linear_halves(double u)
{
    return u < 0.5 ? MC_PI * u : MC_PI - MC_PI * (1.0 - u);
}

static void test_warp1d_chi2_negative_controls(void **state)
{
    negctl *t = *state;
    const warp1 wrong[] = {
        {"negctl-linear-by-2u", uniform02, smp_linear_pdf, NULL, 0.0, 2.0},
        {"negctl-sine-by-pi-u", uniform0pi, smp_sine_pdf, NULL, 0.0, MC_PI},
        {"negctl-quadratic-8cbrt", quadratic_book_bug, smp_quadratic_pdf, NULL, 0.0, 2.0},
        {"negctl-log_ends-uniform", log_ends_linear_halves, smp_log_ends_pdf, NULL, 0.0, MC_PI},
    };
    bool all = true;
    for (size_t i = 0; i < sizeof wrong / sizeof wrong[0]; i++) {
        chi2_spec s = spec_of(&wrong[i]);
        chi2_outcome o = chi2_run(&s, 200000u, mc_test_seed(4021u + i), chi2_suite_alpha());
        chi2_print(&s, &o);
        all &= negctl_record(t, wrong[i].name, "chi-square", o.reject);
    }
    assert_true(all);
}

/* The pdf integrates to 1 over the support (GSL QAGS, which also copes
 * with the integrable log singularities of log_ends at 0 and pi). */
static void test_warp1d_normalization(void **state)
{
    (void)state;
    for (int i = 0; i < N_WARPS; i++) {
        chi2_spec s = spec_of(&warps[i]);
        double total = chi2_integrate_pdf(&s);
        if (fabs(total - 1.0) > 1e-9)
            fail_msg("%s: pdf integrates to %.15g", warps[i].name, total);
    }
}

/* Every sample lies in the support for u in [0, 1] (edges included), is
 * non-decreasing in u and has pdf > 0 inside (0, 1); the pdf is 0 outside
 * the support and never NaN. */
static void test_warp1d_domain(void **state)
{
    (void)state;
    static const double edges[] = {0.0, 1e-300, 0x1p-32, 0.25, 0.5 - 0x1p-32, 0.5,
                                   0.5 + 0x1p-32, 0.75, 1.0 - 0x1p-32, 1.0 - 0x1p-53, 1.0};
    for (int i = 0; i < N_WARPS; i++) {
        const warp1 *w = &warps[i];
        double prev = -HUGE_VAL;
        for (size_t k = 0; k < sizeof edges / sizeof edges[0]; k++) {
            double x = w->sample(edges[k]);
            if (!(x >= w->lo && x <= w->hi) || x < prev)
                fail_msg("%s: sample(%.17g) = %.17g (previous %.17g)", w->name, edges[k], x, prev);
            prev = x;
        }
        mc_rng rng = mc_rng_derive(mc_test_seed(4031u), (uint64_t)i);
        for (int k = 0; k < 100000; k++) {
            double u = ((double)mc_rng_u32(&rng) + 0.5) * 0x1p-32;
            double x = w->sample(u), p = w->pdf(x);
            if (!(x >= w->lo && x <= w->hi) || !(p > 0.0))
                fail_msg("%s: u %.17g gives x %.17g with pdf %g", w->name, u, x, p);
        }
        static const double outside[] = {-1.0, -1e-300, 3.5, 1e300, -HUGE_VAL, HUGE_VAL};
        for (size_t k = 0; k < sizeof outside / sizeof outside[0]; k++)
            assert_true(w->pdf(outside[k]) == 0.0);
        assert_true(w->pdf(w->hi + 1e-9) == 0.0 && w->pdf(nan("")) == 0.0);
    }
}

/* invert(sample(u)) == u to 1e-12 on a grid; sample(invert(x)) == x to the
 * conditioning of the inverse, |dx| ~ 4 eps / p(x), plus 1e-13. */
static void test_warp1d_roundtrip(void **state)
{
    (void)state;
    enum { G = 1000 };
    for (int i = 0; i < N_WARPS; i++) {
        const warp1 *w = &warps[i];
        for (int k = 0; k <= G; k++) {
            double u = (double)k / G;
            double back = w->invert(w->sample(u));
            if (fabs(back - u) > 1e-12)
                fail_msg("%s: invert(sample(%.17g)) = %.17g", w->name, u, back);
            double x = w->lo + (w->hi - w->lo) * (k + 0.5) / (G + 1);
            double again = w->sample(w->invert(x));
            double tol = 1e-13 + 4.0 * 0x1p-52 / w->pdf(x);
            if (fabs(again - x) > tol)
                fail_msg("%s: sample(invert(%.17g)) = %.17g (tol %.3g)", w->name, x, again, tol);
        }
    }
}

/* The pdf is the derivative of the CDF that invert computes: central
 * differences with h = 1e-5 (truncation error ~ h^2 p'' / 6 ~ 1e-10 here)
 * agree to 1e-7 relative at interior points. */
static void test_warp1d_pdf_is_cdf_derivative(void **state)
{
    (void)state;
    const double h = 1e-5;
    for (int i = 0; i < N_WARPS; i++) {
        const warp1 *w = &warps[i];
        for (int k = 1; k < 100; k++) {
            double x = w->lo + (w->hi - w->lo) * (k + 0.385) / 100.5;
            double slope = (w->invert(x + h) - w->invert(x - h)) / (2.0 * h);
            double p = w->pdf(x);
            if (fabs(slope - p) > 1e-7 * (p > 1.0 ? p : 1.0))
                fail_msg("%s at %.6f: CDF slope %.12g, pdf %.12g", w->name, x, slope, p);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_warp1d_chi2),
        cmocka_unit_test(test_warp1d_log_ends_product_chi2),
        cmocka_unit_test(test_warp1d_chi2_negative_controls),
        cmocka_unit_test(test_warp1d_normalization),
        cmocka_unit_test(test_warp1d_domain),
        cmocka_unit_test(test_warp1d_roundtrip),
        cmocka_unit_test(test_warp1d_pdf_is_cdf_derivative),
    };
    return cmocka_run_group_tests_name("test_warp1d", tests, negctl_group_setup, negctl_group_teardown);
}
