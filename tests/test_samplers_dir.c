/* tests/test_samplers_dir.c - directions on the sphere and the hemisphere:
 * uniform (three ways), flipped, cosine-weighted (three ways), uniform
 * theta-phi. Every sampler passes chi-square, normalization, domain and
 * round trip; the three uniform-sphere and the three cosine methods agree;
 * and the negative-control bank shows each check catching the bug it is
 * for. Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), the second
 * chapter 2 and chapters 3 and 5; this book's #ch-sphere, #ch-scattering
 * and #ch-directions.
 *
 * Statistics (all seeds overridable with MC_TEST_SEED): chi-square with
 * 10^6 samples in 50 x 100 cells of (cos theta, phi), rejected at
 * chi2_suite_alpha() = 1.57e-4 (Sidak: 1% over the suite's <= 64 tests);
 * the two-sample agreement tests at the same level. Normalization within
 * 1e-6 and round trip within 1e-9 are deterministic.
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/constants.h"
#include "samplers/hemisphere.h"
#include "samplers/sphere.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

enum { N_CHI2 = 1000000 };

/* The rows of the catalog this program tests (chi-square, normalization,
 * domain and round trip of every case: tests built in main). */
static const char *const families[] = {"sphere", "hemisphere"};

/* A catalog case by name, prepared into *s (which must outlive it). */
static warp_case case_named(const char *name, cat_state *s)
{
    const cat_row *r = NULL;
    const cat_case *tc = cat_find_case(name, &r);
    assert_non_null(tc);
    return warp_case_of(r, tc, s);
}

/* Agreement: 10^6 samples of each method in 20 x 40 cells of
 * (cos theta, phi), two-sample chi-square against the first method, at
 * chi2_suite_alpha() each (4 tests: false-alarm rate 6.3e-4 for the four).
 * Seed 4004. */
static void test_agreement_sphere_and_cosine(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(4004u);
    static const char *const names[5] = {"sphere-inverse", "sphere-gaussian", "sphere-rejection",
                                         "cosine", "cosine-malley"};
    static cat_state states[6];
    warp_case cases[6];
    for (int k = 0; k < 5; k++)
        cases[k] = case_named(names[k], &states[k]);
    cases[5] = case_named("cosine-acos", &states[5]);
    const warp_case *pairs[4][2] = {{&cases[0], &cases[1]},
                                    {&cases[0], &cases[2]},
                                    {&cases[3], &cases[4]},
                                    {&cases[3], &cases[5]}};
    warp_agreement r[4];
#pragma omp parallel for
    for (int k = 0; k < 4; k++)
        r[k] = warp_compare(pairs[k][0], pairs[k][1], N_CHI2, seed + (uint64_t)k);
    int bad = 0;
    for (int k = 0; k < 4; k++) {
        printf("agreement %s vs %s: chi2 %.2f dof %d p %.4f\n", pairs[k][0]->name,
               pairs[k][1]->name, r[k].stat, r[k].dof, r[k].pvalue);
        if (!(r[k].pvalue >= chi2_suite_alpha())) {
            print_error("%s and %s disagree (seed %llu)\n", pairs[k][0]->name, pairs[k][1]->name,
                        (unsigned long long)(seed + (uint64_t)k));
            bad++;
        }
    }
    assert_int_equal(bad, 0);
}

/* The book's and the acos mapping are one function of u up to rounding
 * (cos^2 of acos(1 - 2u)/2 is 1 - u): a deterministic cross-check. */
static void test_cosine_book_equals_acos(void **state)
{
    (void)state;
    for (int i = 0; i < 1000; i++) {
        double u1 = (i + 0.37) / 1000.0, u2 = (i * 7 % 1000 + 0.61) / 1000.0;
        vec3 a = smp_cosine_hemisphere_sample(u1, u2),
             b = smp_cosine_hemisphere_sample_acos(u1, u2);
        assert_near(vec3_length(vec3_sub(a, b)), 0.0, 1e-7);
    }
}

/* --- negative controls -------------------------------------------------- */

/* Each control is a catalog row with one function replaced. */
static double p_cos_no_inv_pi(const cat_state *s, const double x[3])
{
    (void)s;
    return x[2] > 0.0 ? x[2] : 0.0;
}

static double p_cos_twice(const cat_state *s, const double x[3])
{
    return 2.0 * cat_find("cosine")->pdf(s, x);
}

static double p_cos_1pct(const cat_state *s, const double x[3])
{
    return 1.01 * cat_find("cosine")->pdf(s, x);
}

/* theta uniform in [0, pi/2]: the Riemann mapping mistaken for a uniform
 * hemisphere (the sin theta of the solid angle forgotten). */
static void s_theta_linear(const cat_state *s, const double *u, double x[3])
{
    cat_find("theta-phi")->sample_u(s, u, x);
}

/* The unflipped sphere sample given the hemisphere's pdf. */
static void s_sphere_unflipped(const cat_state *s, const double *u, double x[3])
{
    cat_find("sphere-inverse")->sample_u(s, u, x);
}

/* The row `name` with its defaults and one function replaced, prepared
 * into *s; the case is called `label`. */
static warp_case control(const char *label, cat_row *bad, cat_state *s)
{
    static const cat_case defaults = {"defaults", NULL, {0, 0}, 0.0, 0, 0};
    warp_case c = warp_case_of(bad, &defaults, s);
    c.name = label;
    return c;
}

/* Each control goes through the check that should catch it, and the
 * correct pdf's normalization shows it is a property of the bug and not of
 * the check. Seed 4005 for the sampled ones. */
static void test_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(4005u);
    static cat_state st;
    cat_row cos_row = *cat_find("cosine");
    cos_row.invert = NULL;
    cos_row.pdf = p_cos_no_inv_pi;
    warp_case c = control("negctl-cosine-no-inv-pi", &cos_row, &st);
    assert_true(negctl_record(t, "cosine pdf without 1/pi", "normalization", warp_norm_rejects(&c)));
    cos_row.pdf = p_cos_twice;
    c.name = "negctl-cosine-twice";
    assert_true(negctl_record(t, "cosine pdf times 2 (early erratum)", "normalization",
                              warp_norm_rejects(&c)));
    /* A 1% scale error: normalization catches it for sure; for chi-square
     * with 10^6 samples in 5000 cells it adds about 10^-4 n = 100 to the
     * statistic, one standard deviation (sqrt(2 dof) = 100): usually missed. */
    cos_row.pdf = p_cos_1pct;
    c.name = "negctl-cosine-1pct";
    assert_true(negctl_record(t, "cosine pdf 1% too large", "normalization", warp_norm_rejects(&c)));
    printf("  (the same 1%% error under chi-square alone: %s)\n",
           warp_chi2_rejects(&c, N_CHI2, seed) ? "rejected" : "not rejected");

    static cat_state sh;
    cat_row lin = *cat_find("hemisphere");
    lin.invert = NULL;
    lin.sample_u = s_theta_linear;
    warp_case h = control("negctl-theta-linear-as-uniform", &lin, &sh);
    assert_true(fabs(warp_norm_error(&h)) <= WARP_NORM_TOL); /* the pdf itself is normalized */
    assert_true(negctl_record(t, "theta = (pi/2) u given the uniform hemisphere pdf", "chi-square",
                              warp_chi2_rejects(&h, N_CHI2, seed)));

    static cat_state sf;
    cat_row unflipped = *cat_find("hemisphere");
    unflipped.invert = NULL;
    unflipped.sample_u = s_sphere_unflipped;
    warp_case f = control("negctl-hemisphere-not-flipped", &unflipped, &sf);
    warp_domain d = warp_check_domain(&f, 100000u, seed);
    assert_true(negctl_record(t, "hemisphere sample not flipped", "domain",
                              !warp_domain_ok(&d) && d.outside > 0 && d.zero_pdf > 0));

    /* The agreement test must see a different law: the cosine methods
     * against the uniform hemisphere. */
    static cat_state sc, su;
    warp_case cosine = case_named("cosine", &sc), uniform = case_named("hemisphere", &su);
    warp_agreement a = warp_compare(&cosine, &uniform, N_CHI2, seed);
    assert_true(negctl_record(t, "cosine vs uniform hemisphere", "two-sample agreement",
                              a.pvalue < chi2_suite_alpha()));
}

int main(void)
{
    struct CMUnitTest tests[64];
    size_t n = 0;
    warp_catalog_tests(families, 2, tests, &n, 60);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_agreement_sphere_and_cosine);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_cosine_book_equals_acos);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_negative_controls);
    return _cmocka_run_group_tests("test_samplers_dir", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
