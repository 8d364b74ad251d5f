/* tests/test_samplers_dir.c - directions on the sphere and the hemisphere:
 * uniform (three ways), flipped, cosine-weighted (three ways), uniform
 * theta-phi. Every sampler passes chi-square, normalization, domain and
 * round trip; the three uniform-sphere and the three cosine methods agree;
 * and the negative-control bank shows each check catching the bug it is
 * for. Chapters 2, 3 and 5.
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

/* Wrappers from the samplers' signatures to warp_case's. */
WARP_TRIO(sphere, uniform_sphere)
WARP_TRIO(hemi, uniform_hemisphere)
WARP_TRIO(cos, cosine_hemisphere)
WARP_TRIO(tp, theta_phi)
WARP_WRAP_SAMPLE(s_flip, smp_hemisphere_flip_sample(u1, u2))
WARP_WRAP_SAMPLE(s_cos_malley, smp_cosine_hemisphere_sample_malley(u1, u2))
WARP_WRAP_SAMPLE(s_cos_acos, smp_cosine_hemisphere_sample_acos(u1, u2))
WARP_WRAP_INV(i_cos_malley, smp_cosine_hemisphere_invert_malley(w))
WARP_WRAP_INV(i_cos_acos, smp_cosine_hemisphere_invert_acos(w))

static vec3 s_sphere_gauss(mc_rng *rng, const warp_case *c)
{
    (void)c;
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    double u3 = mc_rng_uniform(rng), u4 = mc_rng_uniform(rng);
    return smp_uniform_sphere_sample_gaussian(u1, u2, u3, u4);
}

static vec3 s_sphere_reject(mc_rng *rng, const warp_case *c)
{
    (void)c;
    return smp_uniform_sphere_sample_rejection(rng);
}

#define DIR_CASE(nm, s, p, inv, zlo)                                                               \
    {                                                                                              \
        .name = nm, .sample = s, .pdf = p, .invert = inv, .direction = true, .kind = WARP_COS_PHI, \
        .z_lo = zlo                                                                                \
    }

static const warp_case sphere_cases[] = {
    DIR_CASE("sphere-inverse", s_sphere, p_sphere, i_sphere, -1.0),
    {.name = "sphere-gaussian",
     .sample_rng = s_sphere_gauss,
     .pdf = p_sphere,
     .direction = true,
     .kind = WARP_COS_PHI,
     .z_lo = -1.0},
    {.name = "sphere-rejection",
     .sample_rng = s_sphere_reject,
     .pdf = p_sphere,
     .direction = true,
     .kind = WARP_COS_PHI,
     .z_lo = -1.0},
};

static const warp_case hemi_cases[] = {
    DIR_CASE("hemisphere", s_hemi, p_hemi, i_hemi, 0.0),
    DIR_CASE("hemisphere-flip", s_flip, p_hemi, NULL, 0.0),
    DIR_CASE("theta-phi", s_tp, p_tp, i_tp, 0.0),
};

#define COS_CASE(nm, s, inv)                                                                       \
    {                                                                                              \
        .name = nm, .sample = s, .pdf = p_cos, .invert = inv, .direction = true,                   \
        .rim_zero_ok = true, .kind = WARP_COS_PHI, .z_lo = 0.0                                     \
    }

static const warp_case cos_cases[] = {
    COS_CASE("cosine", s_cos, i_cos),
    COS_CASE("cosine-malley", s_cos_malley, i_cos_malley),
    COS_CASE("cosine-acos", s_cos_acos, i_cos_acos),
};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Seed 4001; per case as in warp_run_cases. */
static void test_sphere_all_checks(void **state)
{
    (void)state;
    warp_run_cases(sphere_cases, COUNT(sphere_cases), N_CHI2, mc_test_seed(4001u));
}

/* Seed 4002. */
static void test_hemisphere_all_checks(void **state)
{
    (void)state;
    warp_run_cases(hemi_cases, COUNT(hemi_cases), N_CHI2, mc_test_seed(4002u));
}

/* Seed 4003. */
static void test_cosine_all_checks(void **state)
{
    (void)state;
    warp_run_cases(cos_cases, COUNT(cos_cases), N_CHI2, mc_test_seed(4003u));
}

/* Agreement: 10^6 samples of each method in 20 x 40 cells of
 * (cos theta, phi), two-sample chi-square against the first method, at
 * chi2_suite_alpha() each (4 tests: false-alarm rate 6.3e-4 for the four).
 * Seed 4004. */
static void test_agreement_sphere_and_cosine(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(4004u);
    const warp_case *pairs[4][2] = {{&sphere_cases[0], &sphere_cases[1]},
                                    {&sphere_cases[0], &sphere_cases[2]},
                                    {&cos_cases[0], &cos_cases[1]},
                                    {&cos_cases[0], &cos_cases[2]}};
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

WARP_WRAP_PDF(p_cos_no_inv_pi, w.z > 0.0 ? w.z : 0.0)
WARP_WRAP_PDF(p_cos_twice, 2.0 * smp_cosine_hemisphere_pdf(w))
WARP_WRAP_PDF(p_cos_1pct, 1.01 * smp_cosine_hemisphere_pdf(w))

/* theta uniform in [0, pi/2]: the Riemann mapping mistaken for a uniform
 * hemisphere (the sin theta of the solid angle forgotten). */
WARP_WRAP_SAMPLE(s_theta_linear, smp_theta_phi_sample(u1, u2))

/* The unflipped sphere sample given the hemisphere's pdf. */
WARP_WRAP_SAMPLE(s_sphere_unflipped, smp_uniform_sphere_sample(u1, u2))

/* Each control goes through the check that should catch it, and the
 * correct pdf's normalization shows it is a property of the bug and not of
 * the check. Seed 4005 for the sampled ones. */
static void test_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(4005u);
    warp_case c = COS_CASE("negctl-cosine-no-inv-pi", s_cos, NULL);
    c.pdf = p_cos_no_inv_pi;
    assert_true(negctl_record(t, "cosine pdf without 1/pi", "normalization", warp_norm_rejects(&c)));
    c.pdf = p_cos_twice;
    c.name = "negctl-cosine-twice";
    assert_true(negctl_record(t, "cosine pdf times 2 (early erratum)", "normalization",
                              warp_norm_rejects(&c)));
    /* A 1% scale error: normalization catches it for sure; for chi-square
     * with 10^6 samples in 5000 cells it adds about 10^-4 n = 100 to the
     * statistic, one standard deviation (sqrt(2 dof) = 100): usually missed. */
    c.pdf = p_cos_1pct;
    c.name = "negctl-cosine-1pct";
    assert_true(negctl_record(t, "cosine pdf 1% too large", "normalization", warp_norm_rejects(&c)));
    printf("  (the same 1%% error under chi-square alone: %s)\n",
           warp_chi2_rejects(&c, N_CHI2, seed) ? "rejected" : "not rejected");

    warp_case h = DIR_CASE("negctl-theta-linear-as-uniform", s_theta_linear, p_hemi, NULL, 0.0);
    assert_true(fabs(warp_norm_error(&h)) <= WARP_NORM_TOL); /* the pdf itself is normalized */
    assert_true(negctl_record(t, "theta = (pi/2) u given the uniform hemisphere pdf", "chi-square",
                              warp_chi2_rejects(&h, N_CHI2, seed)));

    warp_case f = DIR_CASE("negctl-hemisphere-not-flipped", s_sphere_unflipped, p_hemi, NULL, 0.0);
    warp_domain d = warp_check_domain(&f, 100000u, seed);
    assert_true(negctl_record(t, "hemisphere sample not flipped", "domain",
                              !warp_domain_ok(&d) && d.outside > 0 && d.zero_pdf > 0));

    /* The agreement test must see a different law: the cosine methods
     * against the uniform hemisphere. */
    warp_agreement a = warp_compare(&cos_cases[0], &hemi_cases[0], N_CHI2, seed);
    assert_true(negctl_record(t, "cosine vs uniform hemisphere", "two-sample agreement",
                              a.pvalue < chi2_suite_alpha()));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_all_checks),
        cmocka_unit_test(test_hemisphere_all_checks),
        cmocka_unit_test(test_cosine_all_checks),
        cmocka_unit_test(test_agreement_sphere_and_cosine),
        cmocka_unit_test(test_cosine_book_equals_acos),
        cmocka_unit_test(test_negative_controls),
    };
    return cmocka_run_group_tests_name("test_samplers_dir", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
