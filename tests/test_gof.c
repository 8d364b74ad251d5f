/* tests/test_gof.c - mc/gof.h, the histogram + per-cell quadrature +
 * Pearson test behind `warp chi2`: correct samplers pass, wrong ones and
 * leaks are rejected, the normalization integral is exact, the cells
 * tile the rectangle. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/gof.h"
#include "tests/support/negctl.h"

/* Every statistical check here: 10^5 samples, rejected at alpha = 1e-4
 * (the false-alarm rate per correct test). */
#define ALPHA 1e-4
enum { N = 100000, MAX_CELLS = 2500 };

/* x = sqrt(u) has density 2x on [0, 1]; x = u (the control) has density 1. */
static void sample_sqrt(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    out[0] = sqrt(mc_rng_uniform(rng));
}
static void sample_plain(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    out[0] = mc_rng_uniform(rng);
}
/* Leaks: 1% of the samples land in (1, 1.2]. */
static void sample_leaky(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    double u = mc_rng_uniform(rng);
    out[0] = u < 0.99 ? sqrt(u / 0.99) : 1.0 + 0.2 * mc_rng_uniform(rng);
}
static double pdf_2x(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.0 && x[0] <= 1.0 ? 2.0 * x[0] : 0.0;
}
/* Claims 0 on [0, 1/2), 2 on [1/2, 1]: samples of the uniform sampler
 * fall where it says none can. */
static double pdf_upper_half(const double x[2], void *ctx)
{
    (void)ctx;
    return x[0] >= 0.5 && x[0] <= 1.0 ? 2.0 : 0.0;
}
/* x = 1/2 + u/2: density 2 on [1/2, 1]. */
static void sample_upper_half(mc_rng *rng, void *ctx, double out[2])
{
    (void)ctx;
    out[0] = 0.5 + 0.5 * mc_rng_uniform(rng);
}
/* Right on [1/2, 1], but -1/500 on [0, 1/50) and +1/500 on [1/50, 2/50):
 * still integrates to 1, and with 10^5 samples the negative cell (-4) and
 * its compensating neighbour (+4, pooled) would pass unnoticed were a
 * clearly negative cell taken for an expected-zero one. */
static double pdf_negative_cell(const double x[2], void *ctx)
{
    (void)ctx;
    if (x[0] >= 0.5 && x[0] <= 1.0)
        return 2.0;
    if (x[0] >= 0.0 && x[0] < 0.02)
        return -0.002;
    return x[0] >= 0.02 && x[0] < 0.04 ? 0.002 : 0.0;
}

/* The unit disc in (r^2, phi): uniform points have density 1 / (2 pi). */
static void sample_disc(mc_rng *rng, void *ctx, double out[2])
{
    bool no_sqrt = ctx != NULL;
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    double r = no_sqrt ? u2 : sqrt(u2);
    out[0] = r * r, out[1] = MC_2PI * u1;
}
static double pdf_disc(const double x[2], void *ctx)
{
    (void)ctx, (void)x;
    return 1.0 / MC_2PI;
}

static mc_gof_result run(mc_gof_spec spec, uint64_t seed)
{
    static double obs[MAX_CELLS], expct[MAX_CELLS];
    assert_true(mc_gof_cell_count(&spec) <= MAX_CELLS);
    mc_rng rng = mc_rng_derive(seed, 0u);
    return mc_gof_test(&spec, N, &rng, ALPHA, obs, expct);
}

static void test_gof_correct_samplers_pass(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(8101u);
    mc_gof_spec one = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_sqrt, pdf_2x, NULL};
    mc_gof_result r = run(one, seed);
    assert_seeded(!r.reject, seed);
    assert_int_equal(r.r.dof, 49);
    assert_true(r.outside == 0.0);
    mc_gof_spec disc = {2, {0.0, 0.0}, {1.0, MC_2PI}, {40, 60}, sample_disc, pdf_disc, NULL};
    assert_int_equal(mc_gof_cell_count(&disc), 2400);
    assert_seeded(!run(disc, mc_test_seed(8102u)).reject, mc_test_seed(8102u));
}

static void test_gof_integrate(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    mc_gof_spec one = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_sqrt, pdf_2x, NULL};
    assert_near(mc_gof_integrate(&one, q), 1.0, 1e-12);
    mc_gof_spec disc = {2, {0.0, 0.0}, {1.0, MC_2PI}, {40, 60}, sample_disc, pdf_disc, NULL};
    assert_near(mc_gof_integrate(&disc, q), 1.0, 1e-12);
    mc_quad_destroy(q);
}

/* The cells tile the rectangle (first and last edges exact, neighbours
 * within round-off), their probabilities sum to the whole integral, and
 * the expected counts are n times them, 0 where the pdf vanishes. */
static void test_gof_cells(void **state)
{
    (void)state;
    mc_gof_spec odd = {1, {-0.3, 0.0}, {2.385, 0.0}, {7, 1}, sample_plain, pdf_upper_half, NULL};
    mc_gof_spec disc = {2, {0.0, 0.0}, {1.0, MC_2PI}, {40, 60}, sample_disc, pdf_disc, NULL};
    static double prob[MAX_CELLS], expct[MAX_CELLS];
    double box[4], prev[4];
    for (int c = 0; c < 7; c++) {
        mc_gof_cell_box(&odd, c, box);
        assert_true(c > 0 || box[0] == -0.3);
        assert_true(c < 6 || box[1] == 2.385);
        if (c > 0)
            assert_near(box[0], prev[1], 1e-15);
        assert_true(box[2] == 0.0 && box[3] == 0.0);
        memcpy(prev, box, sizeof box);
    }
    mc_gof_cell_box(&disc, 40 * 60 - 1, box);
    assert_true(box[1] == 1.0 && box[3] == MC_2PI);
    mc_gof_cell_box(&disc, 61, box); /* cell (1, 1) */
    assert_near(box[0], 1.0 / 40.0, 1e-16);
    assert_near(box[2], MC_2PI / 60.0, 1e-15);

    assert_int_equal(mc_gof_cell_probs(&disc, prob), 0);
    double sum = 0.0;
    for (int c = 0; c < 40 * 60; c++)
        sum += prob[c];
    assert_near(sum, 1.0, 1e-12);
    /* pdf_upper_half on [0, 2.5] in 5 cells: all its mass in cell 1,
     * whose edges are its jumps. */
    mc_gof_spec half = {1, {0.0, 0.0}, {2.5, 0.0}, {5, 1}, sample_plain, pdf_upper_half, NULL};
    assert_int_equal(mc_gof_cell_probs(&half, prob), 0);
    assert_int_equal(mc_gof_expected(&half, 1000u, expct), 0);
    for (int c = 0; c < 5; c++)
        assert_true(expct[c] == (prob[c] < MC_GOF_ZERO_CELL_PROB ? 0.0 : 1000.0 * prob[c]));
    assert_near(prob[1], 1.0, 1e-12);
    assert_true(expct[0] == 0.0 && expct[2] == 0.0 && expct[3] == 0.0 && expct[4] == 0.0);
}

/* Each wrong experiment is rejected, and for the reason meant. */
static void test_gof_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(8103u);
    mc_gof_spec wrong_pdf = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_plain, pdf_2x, NULL};
    mc_gof_result r = run(wrong_pdf, seed);
    bool ok = negctl_record(t, "uniform samples claimed as 2x", "Pearson p-value",
                            r.reject && r.r.pvalue < ALPHA);
    mc_gof_spec no_sqrt = {2,           {0.0, 0.0}, {1.0, MC_2PI}, {40, 60},
                           sample_disc, pdf_disc,   (void *)1};
    r = run(no_sqrt, seed);
    ok &= negctl_record(t, "disc radius without the sqrt", "Pearson p-value",
                        r.reject && r.r.pvalue < ALPHA);
    mc_gof_spec leaky = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_leaky, pdf_2x, NULL};
    r = run(leaky, seed);
    ok &= negctl_record(t, "1% of samples outside the rectangle", "outside count",
                        r.reject && r.outside > 0.0);
    mc_gof_spec zero = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_plain, pdf_upper_half, NULL};
    r = run(zero, seed);
    ok &= negctl_record(t, "samples where the pdf is 0", "zero-expected cells",
                        r.reject && r.r.obs_in_zero_cells > MC_GOF_ZERO_CELL_FRAC * N);
    mc_gof_spec negative = {1, {0.0, 0.0}, {1.0, 0.0}, {50, 1}, sample_upper_half,
                            pdf_negative_cell, NULL};
    r = run(negative, seed);
    ok &= negctl_record(t, "a pdf negative on one cell", "NaN statistic",
                        r.reject && isnan(r.r.stat) && r.r.pvalue == 0.0);
    assert_true(ok);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gof_correct_samplers_pass),
        cmocka_unit_test(test_gof_integrate),
        cmocka_unit_test(test_gof_cells),
        cmocka_unit_test(test_gof_negative_controls),
    };
    return cmocka_run_group_tests_name("test_gof", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
