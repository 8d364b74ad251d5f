/* tests/test_render_strategies.c - chapter 4's lesson made a test: the five
 * sampling strategies must render the same image of the Lambertian
 * Cornell box, region by region, and a strategy with a wrong light density
 * must be told apart. */
#include "tests/support/mc_test.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>

#include "mc/chi2.h"
#include "mc/stats.h"
#include "render/render.h"
#include "render/scenes.h"
#include "tests/support/negctl.h"

enum { W = 24, GRID = 3, CELL = W / GRID, REGIONS = GRID * GRID };

/* Region means (per channel) of one rendering. */
typedef struct regions {
    mc_estimate e[REGIONS][3];
} regions;

static regions render_regions(const rt_scene *s, rt_camera_params cp, rt_path_settings ps,
                              uint64_t spp, uint64_t seed)
{
    rt_image *img = rt_image_create(W, W);
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, W, W));
    job.path = ps;
    job.spp = spp;
    job.seed = seed;
    job.threads = 2;
    assert_int_equal(rt_render(&job, img, NULL), 0);
    regions r;
    for (int k = 0; k < REGIONS; k++) {
        int x = (k % GRID) * CELL, y = (k / GRID) * CELL;
        rt_image_region_stats(img, x, y, x + CELL, y + CELL, r.e[k]);
    }
    rt_image_destroy(img);
    return r;
}

/* The largest |z| of the region differences a - b over regions and
 * channels. */
static double max_z(const regions *a, const regions *b, int *where)
{
    double worst = 0.0;
    for (int k = 0; k < REGIONS; k++)
        for (int c = 0; c < 3; c++) {
            double se = sqrt(a->e[k][c].std_error * a->e[k][c].std_error +
                             b->e[k][c].std_error * b->e[k][c].std_error);
            double z = fabs(mc_z_score(a->e[k][c].value, b->e[k][c].value, se));
            if (z > worst) {
                worst = z;
                *where = k;
            }
        }
    return worst;
}

/* Each strategy against mis, the reference, on the lambert scene (24 x 24
 * pixels in 9 regions of 8 x 8, three channels): z of each region mean's
 * difference, with standard errors from the per-pixel variances (the
 * jittered pixel samples make those conservative). Two depths: 4 (where a
 * strategy that truncated paths differently would show) and the book's 50.
 * Tests: 2 depths x 4 strategies x 9 regions x 3 channels = 216; Sidak at
 * a family false-alarm level of 1e-3 gives |z| < 4.56 per test.
 * Skewness: the BSDF-only strategies find the light rarely, so their
 * region means are right-skewed and their estimated errors small exactly
 * when no rare bright sample came; their z has a heavier left tail than a
 * normal. They get 1024 samples per pixel at depth 4 and 2048 at depth 50
 * (65536 and 131072 per region), which a soak over 100 seeds showed
 * enough to keep the tail below the threshold; the others get 256.
 * Seeds 51 and on. Negative control: the mixture with its light density
 * halved in the estimator (sampling unchanged) must exceed the threshold
 * somewhere. */
static void test_strategies_agree_on_lambert(void **state)
{
    negctl *t = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    uint64_t seed = mc_test_seed(51u);
    double thr = gsl_cdf_ugaussian_Qinv(0.5 * mc_sidak_alpha(1e-3, 2 * 4 * REGIONS * 3));
    static const uint64_t bsdf_spp[2] = {1024, 2048};
    static const int depths[2] = {4, 50};
    static const rt_strategy others[4] = {RT_UNIFORM, RT_COSINE, RT_LIGHT, RT_MIXTURE};
    for (int d = 0; d < 2; d++) {
        rt_path_settings ps = rt_path_settings_default(RT_MIS);
        ps.max_depth = depths[d];
        regions ref = render_regions(s, cp, ps, 256, seed + 5u * (uint64_t)d);
        for (int i = 0; i < 4; i++) {
            ps.strategy = others[i];
            uint64_t spp = others[i] <= RT_COSINE ? bsdf_spp[d] : 256;
            regions r = render_regions(s, cp, ps, spp, seed + 5u * (uint64_t)d + 1u + (uint64_t)i);
            int k = 0;
            double z = max_z(&r, &ref, &k);
            printf("lambert depth %d: %-7s vs mis: max |z| %.2f over %d region-channels (threshold %.2f)\n",
                   depths[d], rt_strategy_name(others[i]), z, REGIONS * 3, thr);
            if (z >= thr)
                fail_msg("depth %d: %s disagrees with mis in region %d: |z| = %.2f >= %.2f (seed %llu)",
                         depths[d], rt_strategy_name(others[i]), k, z, thr, (unsigned long long)seed);
        }
        if (d == 1) {
            ps.strategy = RT_MIXTURE;
            ps.light_pdf_scale = 0.5;
            regions bad = render_regions(s, cp, ps, 256, seed + 20u);
            int k = 0;
            double z = max_z(&bad, &ref, &k);
            printf("negative control (mixture, light pdf x 0.5): max |z| %.2f\n", z);
            if (!negctl_record(t, "mixture with its light pdf x 0.5", "region z-test", z >= thr))
                fail_msg("the wrong light pdf was not caught: max |z| %.2f < %.2f (seed %llu)", z,
                         thr, (unsigned long long)seed);
        }
    }
    rt_scene_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strategies_agree_on_lambert),
    };
    return cmocka_run_group_tests_name("test_render_strategies", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
