/* tests/test_render_strategies.c - the lesson of Shirley, "Ray Tracing: The
 * Rest of Your Life" (v1.123), chapter 4 (this book's #ch-nee-mis) made a
 * test: the five sampling strategies must render the same image of the
 * Lambertian Cornell box, region by region, and a strategy with a wrong light
 * density must be told apart; so must the samplers (render/sampler.h), and a
 * sampler that drops a dimension. */
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

/* Region means of a rendering with the sampler `sampler` (reuse_dim: the
 * negative-control hook ps.neg.sampler_reuse_dim). */
static regions render_regions_with(const rt_scene *s, rt_camera_params cp, rt_path_settings ps,
                                   uint64_t spp, uint64_t seed, rt_sampler_kind sampler,
                                   bool reuse_dim)
{
    rt_image *img = rt_image_create(W, W);
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, W, W));
    job.sampler = sampler;
    job.path = ps;
    job.path.neg.sampler_reuse_dim = reuse_dim;
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

static regions render_regions(const rt_scene *s, rt_camera_params cp, rt_path_settings ps,
                              uint64_t spp, uint64_t seed)
{
    return render_regions_with(s, cp, ps, spp, seed, RT_SAMPLER_STRATIFIED, false);
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
            ps.neg.light_pdf_error = -0.5; /* the light density x 0.5 */
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

/* The Sobol sampler against the independent one on the lambert scene, for
 * the book's mixture (the four-lane loop) and mis (next-event estimation,
 * one path at a time), 256 samples per pixel each, depth 50: z of each
 * region mean's difference as above (the per-pixel variances overstate
 * the Sobol image's error, which only makes the test conservative).
 * Tests: 2 strategies x 9 regions x 3 channels = 54; Sidak at a family
 * false-alarm level of 1e-3 gives |z| < 4.28 per test. Seeds 81 and on.
 * Negative control: Sobol whose 1D requests do not move on to the next
 * dimension, so that the mixture's choice of component and the direction
 * drawn next share a uniform (only half the light and half the
 * hemisphere are ever sampled); it must exceed the threshold somewhere. */
static void test_sobol_agrees_with_independent(void **state)
{
    negctl *t = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    uint64_t seed = mc_test_seed(81u);
    double thr = gsl_cdf_ugaussian_Qinv(0.5 * mc_sidak_alpha(1e-3, 2 * REGIONS * 3));
    static const rt_strategy strategies[2] = {RT_MIXTURE, RT_MIS};
    regions ref[2];
    for (int i = 0; i < 2; i++) {
        rt_path_settings ps = rt_path_settings_default(strategies[i]);
        ref[i] = render_regions_with(s, cp, ps, 256, seed + 2u * (uint64_t)i, RT_SAMPLER_INDEPENDENT,
                                     false);
        regions r = render_regions_with(s, cp, ps, 256, seed + 2u * (uint64_t)i + 1u,
                                        RT_SAMPLER_SOBOL, false);
        int k = 0;
        double z = max_z(&r, &ref[i], &k);
        printf("lambert %-7s: sobol vs independent: max |z| %.2f over %d region-channels "
               "(threshold %.2f)\n",
               rt_strategy_name(strategies[i]), z, REGIONS * 3, thr);
        if (z >= thr)
            fail_msg("%s: sobol disagrees with independent in region %d: |z| = %.2f >= %.2f (seed %llu)",
                     rt_strategy_name(strategies[i]), k, z, thr, (unsigned long long)seed);
    }
    regions bad = render_regions_with(s, cp, rt_path_settings_default(RT_MIXTURE), 256, seed + 10u,
                                      RT_SAMPLER_SOBOL, true);
    int k = 0;
    double z = max_z(&bad, &ref[0], &k);
    printf("negative control (sobol reusing a dimension): max |z| %.2f\n", z);
    if (!negctl_record(t, "sobol sampler reusing a dimension", "region z-test", z >= thr))
        fail_msg("the dropped dimension was not caught: max |z| %.2f < %.2f (seed %llu)", z, thr,
                 (unsigned long long)seed);
    rt_scene_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strategies_agree_on_lambert),
        cmocka_unit_test(test_sobol_agrees_with_independent),
    };
    return cmocka_run_group_tests_name("test_render_strategies", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
