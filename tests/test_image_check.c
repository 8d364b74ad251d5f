/* tests/test_image_check.c - mcbox/image.h by value: the statistic of a
 * hand-made set of renders worked out by hand (pixel variances, block
 * variance over the renders, their ratio, Student's t), the moment pair's,
 * the quantization allowance of an 8-bit code, the neighbours' variance
 * floor, and every refusal. No randomness. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <string.h>

#include "check/image.h"
#include "mc/constants.h"

/* Four pixels, one block, two renders, every channel alike. */
static void fill(double *img, const double v[4])
{
    for (int i = 0; i < 12; i++)
        img[i] = v[i / 3];
}

static void test_statistic_by_hand(void **state)
{
    (void)state;
    double truth[12], a[12], b[12];
    fill(truth, (double[4]){0.5, 0.5, 0.5, 0.5});
    fill(a, (double[4]){0.6, 0.4, 0.5, 0.7});
    fill(b, (double[4]){0.5, 0.5, 0.3, 0.6});
    const double *renders[2] = {a, b};
    mcbox_image_set set = {.width = 2, .height = 2, .truth = truth, .n_renders = 2,
                           .renders = renders};
    mcbox_image_options o = {.block = 2};
    mcbox_image_result r;
    assert_int_equal(mcbox_image_check(&set, &o, &r), 0);
    /* Pixel variances (a - b)^2 / 2: 0.005, 0.005, 0.02, 0.005; over
     * K n^2 = 32: 0.00109375. The block's means 0.55 and 0.475: variance
     * 0.075^2 / 2 over K = 0.00140625, the ratio 1.2857 (> 1: used), one
     * degree of freedom; se = 0.0375, z = 0.0125 / 0.0375 = 1/3, and
     * Student's t with 1 degree of freedom (Cauchy): p = 1 - 2 atan(z) / pi. */
    assert_near(r.inflation, 0.00140625 / 0.00109375, 1e-12);
    assert_near(r.dof, 1.0, 0.0);
    assert_near(r.image[0].mean, 0.5125, 1e-15);
    assert_near(r.image[0].se, 0.0375, 1e-12);
    assert_near(r.image[0].z, 1.0 / 3.0, 1e-12);
    assert_near(r.image[0].p, 1.0 - 2.0 * atan(1.0 / 3.0) / MC_PI, 1e-12);
    assert_int_equal(r.tests, 6);
    assert_true(r.pass);
    mcbox_image_result_free(&r);

    /* The same renders 20% brighter where the truth stays: z grows. */
    for (int i = 0; i < 12; i++)
        a[i] *= 1.2, b[i] *= 1.2;
    assert_int_equal(mcbox_image_check(&set, &o, &r), 0);
    assert_near(r.image[0].z, (0.5125 * 1.2 - 0.5) / (0.0375 * 1.2), 1e-12);
    mcbox_image_result_free(&r);
}

static void test_moment_pair_by_hand(void **state)
{
    (void)state;
    double truth[3] = {0.5, 0.5, 0.5}, mean[3] = {0.52, 0.52, 0.52}, second[3] = {0.3, 0.3, 0.3};
    mcbox_image_set set = {.width = 1, .height = 1, .truth = truth, .mean = mean,
                           .second_moment = second, .samples = 10};
    mcbox_image_result r;
    assert_int_equal(mcbox_image_check(&set, NULL, &r), 0);
    /* var = (0.3 - 0.52^2) 10 / 9, over 10 samples. */
    double se = sqrt((0.3 - 0.52 * 0.52) * 10.0 / 9.0 / 10.0);
    assert_near(r.image[0].se, se, 1e-12);
    assert_near(r.image[0].z, 0.02 / se, 1e-9);
    assert_near(r.dof, 9.0, 0.0);
    assert_true(r.note[0] != '\0'); /* pixels taken as independent: said */
    mcbox_image_result_free(&r);
}

/* An 8-bit gamma-2 code k stands for [((k - 0.5) / 255)^2, ((k + 0.5) / 255)^2]. */
static double gamma2_end(double k) { return (k / 255.0) * (k / 255.0); }

static void test_quantization_allowance(void **state)
{
    (void)state;
    /* The truth 0.2 is written as code 114 (sqrt(0.2) 255 = 114.04). */
    double truth[12], val[12], lo[12], hi[12];
    for (int i = 0; i < 12; i++)
        truth[i] = 0.2;
    const double *v[2] = {val, val}, *l[2] = {lo, lo}, *h[2] = {hi, hi};
    mcbox_image_set set = {.width = 2, .height = 2, .truth = truth, .n_renders = 2,
                           .renders = v, .lo = l, .hi = h};
    for (int code = 114; code >= 113; code--) {
        for (int i = 0; i < 12; i++) {
            lo[i] = gamma2_end(code - 0.5), hi[i] = gamma2_end(code + 0.5);
            val[i] = gamma2_end(code);
        }
        mcbox_image_result r;
        assert_int_equal(mcbox_image_check(&set, NULL, &r), 0);
        /* Two identical renders: no noise; the code's own interval holds
         * the truth, the next one down does not. */
        assert_near(r.image[0].allowance, 0.5 * (gamma2_end(code + 0.5) - gamma2_end(code - 0.5)),
                    1e-15);
        assert_true(r.pass == (code == 114));
        if (code == 113)
            assert_true(isinf(r.image[0].z) && r.image[0].z < 0.0);
        mcbox_image_result_free(&r);
    }
}

/* A block whose renders agree by chance (no rare sample landed) borrows
 * its neighbours' relative variance. */
static void test_neighbour_floor(void **state)
{
    (void)state;
    enum { W = 6 };
    double truth[W * W * 3], a[W * W * 3], b[W * W * 3];
    for (int i = 0; i < W * W * 3; i++) {
        truth[i] = 0.5;
        int px = i / 3;
        double d = (px / W + px % W) % 2 ? 0.05 : -0.05;
        a[i] = 0.5 + d, b[i] = 0.5 - d;
    }
    /* The middle block (pixels 2..3 of rows 2..3): both renders 0.45, no
     * spread, 10% dark. */
    for (int y = 2; y < 4; y++)
        for (int x = 2; x < 4; x++)
            for (int c = 0; c < 3; c++)
                a[(y * W + x) * 3 + c] = b[(y * W + x) * 3 + c] = 0.45;
    const double *renders[2] = {a, b};
    mcbox_image_set set = {.width = W, .height = W, .truth = truth, .n_renders = 2,
                           .renders = renders};
    mcbox_image_options o = {.block = 2};
    mcbox_image_result r;
    assert_int_equal(mcbox_image_check(&set, &o, &r), 0);
    /* Eight neighbours with pixel variance 0.005 each: the floor is their
     * mean relative variance, 8/9 of 0.005 per pixel, over the block's 4
     * pixels and K = 2: se = sqrt(0.005 8/9 / 8). */
    double z = r.z[(1 * 3 + 1) * 3];
    assert_near(z, -0.05 / sqrt(0.005 * 8.0 / 9.0 / 8.0), 1e-9);
    mcbox_image_result_free(&r);
}

static void expect_refusal(const mcbox_image_set *set, const char *words)
{
    mcbox_image_result r;
    assert_int_equal(mcbox_image_check(set, NULL, &r), -1);
    assert_true(r.undetermined && !r.pass);
    if (!strstr(r.message, words))
        fail_msg("'%s' does not say '%s'", r.message, words);
    mcbox_image_result_free(&r);
}

static void test_refusals(void **state)
{
    (void)state;
    double truth[12], a[12], b[12], lo[12], hi[12];
    fill(truth, (double[4]){0.5, 0.5, 0.5, 0.5});
    fill(a, (double[4]){0.5, 0.5, 0.5, 0.5});
    fill(b, (double[4]){0.5, 0.5, 0.5, 0.5});
    const double *renders[2] = {a, b};
    mcbox_image_set one = {.width = 2, .height = 2, .truth = truth, .n_renders = 1,
                           .renders = renders};
    expect_refusal(&one, "2 to 64 independent renders");
    mcbox_image_set set = one;
    set.n_renders = 2;
    b[4] = (double)NAN;
    expect_refusal(&set, "non-finite value nan at pixel (1, 0) green");
    b[4] = -0.25;
    expect_refusal(&set, "negative value -0.25 at pixel (1, 0) green");
    b[4] = 0.5;
    /* A clamped top code where the truth is below it. */
    for (int i = 0; i < 12; i++)
        lo[i] = 0.4, hi[i] = 0.6;
    lo[9] = 0.9, hi[9] = (double)INFINITY;
    const double *l[2] = {lo, lo}, *h[2] = {hi, hi};
    set.lo = l, set.hi = h;
    expect_refusal(&set, "clamped");
    mcbox_image_set pair = {.width = 2, .height = 2, .truth = truth, .mean = a,
                            .second_moment = b, .samples = 1};
    expect_refusal(&pair, "at least 2 samples");
    mcbox_image_set none = {.width = 2, .height = 2, .truth = truth};
    expect_refusal(&none, "no renders");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_statistic_by_hand), cmocka_unit_test(test_moment_pair_by_hand),
        cmocka_unit_test(test_quantization_allowance), cmocka_unit_test(test_neighbour_floor),
        cmocka_unit_test(test_refusals),
    };
    mc_test_select();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
