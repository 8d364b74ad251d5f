/* tests/test_warp1d.c - the 1D inverse-CDF warps of samplers/warp1d.h,
 * the rows of family "warp1d" of the catalog (catalog/catalog.h):
 * chi-square against their pdfs, normalization and domain through the
 * shared harness (tests/support/warp_check.h); the domain at the edge
 * uniforms, the round trip both ways and the pdf as the derivative of the
 * CDF for every row; wrong samplers as negative controls.
 *
 * Statistics (seeds overridable with MC_TEST_SEED): chi-square with 10^6
 * samples per row (2 x 10^5 for the second log_ends sampler and the
 * controls) in 64 equal cells, expected counts from the pdf integrated
 * over each cell, rejected at chi2_suite_alpha() ~ 1.6e-4 (Sidak: 1% over
 * the suite's 64 tests).
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/rng.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

/* The rows of the catalog this program tests. */
static const char *const families[] = {"warp1d"};

/* The next row of the family from position *i of the catalog on, its
 * first case prepared into *s (and, if c is not NULL, as a warp_case into
 * *c); NULL after the last. */
static const cat_row *next_row(size_t *i, cat_state *s, warp_case *c)
{
    for (; *i < cat_count(); ++*i) {
        const cat_row *r = cat_at(*i);
        if (strcmp(r->family, families[0]) == 0) {
            ++*i;
            warp_case w = warp_case_of(r, &r->cases[0], s);
            if (c)
                *c = w;
            return r;
        }
    }
    return NULL;
}

/* A row's warp, density and inverse as functions of reals. */
static double sample_at(const cat_state *s, double u)
{
    double x[3] = {0.0, 0.0, 0.0};
    s->row->sample_u(s, &u, x);
    return x[0];
}

static double density_at(const cat_state *s, double x)
{
    double y[3] = {x, 0.0, 0.0};
    return cat_pdf(s, y);
}

static double invert_at(const cat_state *s, double x)
{
    double y[3] = {x, 0.0, 0.0}, u[2];
    s->row->invert(s, y, u);
    return u[0];
}

/* The first case of row r (with the row's functions), prepared into *s. */
static warp_case first_case(const cat_row *r, cat_state *s)
{
    return warp_case_of(r, &r->cases[0], s);
}

/* log_ends has a second, independent sampler: on a half, t = u1 u2 has the
 * density -ln t (P(u1 u2 <= t) = t - t ln t). Its agreement with the pdf
 * confirms the density itself, not only its inversion. Seed 4011. */
static void sample_log_ends_product(const cat_state *s, mc_rng *rng, double x[3])
{
    (void)s;
    double t = mc_rng_uniform(rng) * mc_rng_uniform(rng);
    double y = MC_PI_2 * t;
    x[0] = mc_rng_uniform(rng) < 0.5 ? y : MC_PI - y;
}

static void test_warp1d_log_ends_product_chi2(void **state)
{
    (void)state;
    cat_row product = *cat_find("log-ends");
    product.uniforms = 0, product.sample_rng = sample_log_ends_product;
    static cat_state s;
    warp_case c = first_case(&product, &s);
    c.name = "log_ends-product";
    warp_check(&c, WARP_CHECK_CHI2, 200000u, mc_test_seed(4011u));
}

/* Negative controls: samplers that do not draw the claimed density. */
static void uniform02(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = 2.0 * u[0];
}

static void uniform0pi(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = MC_PI * u[0];
}

static void quadratic_book_bug(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = 8.0 * cbrt(u[0]);
}

static void log_ends_linear_halves(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = u[0] < 0.5 ? MC_PI * u[0] : MC_PI - MC_PI * (1.0 - u[0]);
}

/* Each wrong sampler with the density of a row; seeds 4021 + i. */
static void test_warp1d_chi2_negative_controls(void **state)
{
    negctl *t = *state;
    static const struct {
        const char *name, *row;
        void (*sample)(const cat_state *, const double *, double *);
    } wrong[] = {
        {"negctl-linear-by-2u", "linear", uniform02},
        {"negctl-sine-by-pi-u", "sine", uniform0pi},
        {"negctl-quadratic-8cbrt", "quadratic", quadratic_book_bug},
        {"negctl-log_ends-uniform", "log-ends", log_ends_linear_halves},
    };
    bool all = true;
    for (size_t i = 0; i < sizeof wrong / sizeof wrong[0]; i++) {
        cat_row bad = *cat_find(wrong[i].row);
        bad.sample_u = wrong[i].sample;
        static cat_state s;
        warp_case c = first_case(&bad, &s);
        c.name = wrong[i].name;
        all &= negctl_record(t, wrong[i].name, "chi-square",
                             warp_chi2_rejects(&c, 200000u, mc_test_seed(4021u + i)));
    }
    assert_true(all);
}

/* The pdf integrates to 1 over the support within 1e-9 (GSL QAGS per
 * cell, which also copes with the integrable log singularities of
 * log_ends at 0 and pi). */
static void test_warp1d_normalization(void **state)
{
    (void)state;
    static cat_state s;
    warp_case c;
    size_t i = 0;
    for (const cat_row *r; (r = next_row(&i, &s, &c));) {
        double e = warp_norm_error(&c);
        if (fabs(e) > 1e-9)
            fail_msg("%s: pdf integrates to 1 %+.3g", r->name, e);
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
    static cat_state s;
    size_t i = 0, seq = 0;
    for (const cat_row *r; (r = next_row(&i, &s, NULL));) {
        double prev = -HUGE_VAL;
        for (size_t k = 0; k < sizeof edges / sizeof edges[0]; k++) {
            double x = sample_at(&s, edges[k]);
            if (!(x >= r->lo && x <= r->hi) || x < prev)
                fail_msg("%s: sample(%.17g) = %.17g (previous %.17g)", r->name, edges[k], x, prev);
            prev = x;
        }
        mc_rng rng = mc_rng_derive(mc_test_seed(4031u), (uint64_t)seq++);
        for (int k = 0; k < 100000; k++) {
            double u = ((double)mc_rng_u32(&rng) + 0.5) * 0x1p-32;
            double x = sample_at(&s, u), p = density_at(&s, x);
            if (!(x >= r->lo && x <= r->hi) || !(p > 0.0))
                fail_msg("%s: u %.17g gives x %.17g with pdf %g", r->name, u, x, p);
        }
        static const double outside[] = {-1.0, -1e-300, 3.5, 1e300, -HUGE_VAL, HUGE_VAL};
        for (size_t k = 0; k < sizeof outside / sizeof outside[0]; k++)
            assert_true(density_at(&s, outside[k]) == 0.0);
        assert_true(density_at(&s, r->hi + 1e-9) == 0.0 && density_at(&s, nan("")) == 0.0);
    }
}

/* invert(sample(u)) == u to 1e-12 on a grid; sample(invert(x)) == x to the
 * conditioning of the inverse, |dx| ~ 4 eps / p(x), plus 1e-13. */
static void test_warp1d_roundtrip(void **state)
{
    (void)state;
    enum { G = 1000 };
    static cat_state s;
    size_t i = 0;
    for (const cat_row *r; (r = next_row(&i, &s, NULL));) {
        for (int k = 0; k <= G; k++) {
            double u = (double)k / G;
            double back = invert_at(&s, sample_at(&s, u));
            if (fabs(back - u) > 1e-12)
                fail_msg("%s: invert(sample(%.17g)) = %.17g", r->name, u, back);
            double x = r->lo + (r->hi - r->lo) * (k + 0.5) / (G + 1);
            double again = sample_at(&s, invert_at(&s, x));
            double tol = 1e-13 + 4.0 * 0x1p-52 / density_at(&s, x);
            if (fabs(again - x) > tol)
                fail_msg("%s: sample(invert(%.17g)) = %.17g (tol %.3g)", r->name, x, again, tol);
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
    static cat_state s;
    size_t i = 0;
    for (const cat_row *r; (r = next_row(&i, &s, NULL));) {
        for (int k = 1; k < 100; k++) {
            double x = r->lo + (r->hi - r->lo) * (k + 0.385) / 100.5;
            double slope = (invert_at(&s, x + h) - invert_at(&s, x - h)) / (2.0 * h);
            double p = density_at(&s, x);
            if (fabs(slope - p) > 1e-7 * (p > 1.0 ? p : 1.0))
                fail_msg("%s at %.6f: CDF slope %.12g, pdf %.12g", r->name, x, slope, p);
        }
    }
}

int main(void)
{
    struct CMUnitTest tests[40];
    size_t n = 0;
    warp_catalog_tests(families, 1, tests, &n, 30);
    const struct CMUnitTest own[] = {
        cmocka_unit_test(test_warp1d_log_ends_product_chi2),
        cmocka_unit_test(test_warp1d_chi2_negative_controls),
        cmocka_unit_test(test_warp1d_normalization),
        cmocka_unit_test(test_warp1d_domain),
        cmocka_unit_test(test_warp1d_roundtrip),
        cmocka_unit_test(test_warp1d_pdf_is_cdf_derivative),
    };
    for (size_t k = 0; k < sizeof own / sizeof own[0]; k++)
        tests[n++] = own[k];
    return _cmocka_run_group_tests("test_warp1d", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
