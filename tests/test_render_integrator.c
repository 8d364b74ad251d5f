/* tests/test_render_integrator.c - the integrators against analytic
 * answers: the white furnace, a sphere light over a plane, truncation at
 * max depth, Russian roulette (its rule and its cost on the book scene),
 * dropped non-finite samples. */
#include "tests/support/mc_test.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>

#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/stats.h"
#include "render/render.h"
#include "render/roulette.h"
#include "render/scenes.h"
#include "tests/support/negctl.h"

static vec3 v3(double x, double y, double z) { return vec3_make(x, y, z); }

/* The two-sided normal threshold that keeps the chance of any false
 * alarm among m tests at alpha (Sidak). */
static double sidak_z(double alpha, int m) { return gsl_cdf_ugaussian_Qinv(0.5 * mc_sidak_alpha(alpha, m)); }

static rt_render_job job_for(const rt_scene *s, rt_camera_params cp, int w, int h, rt_strategy st)
{
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, w, h));
    job.path.strategy = st;
    job.threads = 2;
    return job;
}

/* White furnace: inside a sphere that emits E = 0.5 and reflects rho =
 * 0.5, every ray sees E / (1 - rho) = 1 (with at most D = 50 segments,
 * 1 - 2^-50: the same double). 8 x 8 pixels, 512 samples each, seeds 41
 * and on. Without roulette every strategy's sample is bounded, so each
 * pixel's mean is z-tested against 1 with its own standard error: Sidak
 * over 4 strategies x 64 pixels at a family level of 1e-3 gives
 * |z| < 4.62; the image means must pass |z| < 4 (6.3e-5 each). Cosine
 * sampling is exact here (each bounce adds rho^k E): every pixel must be
 * 1 - 2^-50 to the last bit. With roulette (max depth 1000, rho^1000 =
 * 1e-301) a sample is no longer bounded and its mean is skewed, so only
 * the image means are z-tested, |z| < 4, all five strategies. */
static void furnace_image(const rt_scene *s, rt_camera_params cp, rt_image *img, rt_strategy st,
                          bool roulette, uint64_t seed)
{
    rt_render_job job = job_for(s, cp, 8, 8, st);
    job.spp = 512;
    job.seed = seed;
    job.path.max_depth = roulette ? 1000 : 50;
    job.path.russian_roulette = roulette;
    assert_int_equal(rt_render(&job, img, NULL), 0);
}

static void test_furnace_radiance(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_furnace(0.5, 0.5, &cp);
    rt_image *img = rt_image_create(8, 8);
    double thr = sidak_z(1e-3, 4 * 64), worst = 0.0;
    char label[64];
    for (int st = RT_UNIFORM; st <= RT_MIS; st++) {
        uint64_t seed = mc_test_seed(41u + (uint64_t)st);
        furnace_image(s, cp, img, (rt_strategy)st, false, seed);
        for (int i = 0; i < 64 && st == RT_COSINE; i++)
            assert_true(img->px[i].mean[0] == 1.0 - 0x1p-50 && img->px[i].m2[0] == 0.0);
        for (int y = 0; y < 8 && st != RT_COSINE; y++)
            for (int x = 0; x < 8; x++) {
                mc_estimate e[3];
                rt_image_region_stats(img, x, y, x + 1, y + 1, e);
                snprintf(label, sizeof label, "furnace %s pixel (%d,%d)", rt_strategy_name((rt_strategy)st), x, y);
                assert_z_below(label, e[0].value, 1.0, e[0].std_error, thr, seed);
                worst = fmax(worst, fabs(mc_z_score(e[0].value, 1.0, e[0].std_error)));
            }
        for (int rr = 0; rr < 2; rr++) {
            if (rr)
                furnace_image(s, cp, img, (rt_strategy)st, true, seed + 100u);
            mc_estimate all[3];
            rt_image_region_stats(img, 0, 0, 8, 8, all);
            snprintf(label, sizeof label, "furnace %s image%s", rt_strategy_name((rt_strategy)st),
                     rr ? " (roulette)" : "");
            if (st != RT_COSINE || rr) {
                printf("%s: mean %.6f +- %.6f, z = %.2f\n", label, all[0].value, all[0].std_error,
                       mc_z_score(all[0].value, 1.0, all[0].std_error));
                assert_z_below(label, all[0].value, 1.0, all[0].std_error, 4.0, seed);
            }
        }
    }
    printf("furnace: largest pixel |z| %.2f (threshold %.2f)\n", worst, thr);
    /* Truncation: cosine sampling at D = 8 is exactly 1 - 2^-8. */
    rt_render_job job = job_for(s, cp, 8, 8, RT_COSINE);
    job.spp = 4;
    job.path.max_depth = 8;
    assert_int_equal(rt_render(&job, img, NULL), 0);
    for (int i = 0; i < 64; i++)
        assert_true(img->px[i].mean[1] == 1.0 - 1.0 / 256.0);
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

/* Radiance leaving (x, 0, z) toward +y: rho / pi times the irradiance of
 * the sphere light, Phi cos(theta) / (4 pi d^2), cos(theta) = h / d. */
static double sphere_light_expected(double phi, double h, double rho, double x, double z)
{
    double d = sqrt(x * x + z * z + h * h);
    return rho * MC_INV_PI * phi * (h / d) / (4.0 * MC_PI * d * d);
}

/* The estimate at (x, 0, z) from n samples along the ray straight down. */
static mc_estimate radiance_at(const rt_scene *s, const rt_path_settings *ps, double x, double z,
                               int n, uint64_t seed)
{
    rt_sampler sampler = rt_sampler_from_rng(mc_rng_derive(seed, 0u));
    mc_welford w = mc_welford_init();
    uint64_t segments = 0;
    rt_ray r = rt_ray_make(v3(x, 1.0, z), v3(0, -1, 0));
    for (int i = 0; i < n; i++)
        mc_welford_add(&w, rt_radiance(s, ps, r, &sampler, &segments).y);
    return mc_welford_estimate(&w);
}

/* Sphere light of flux Phi = 4e5, radius 20, centre 100 above a plane of
 * albedo 0.8: the plane's radiance at five points, every strategy, 40000
 * samples each (seed 42), |z| < 4 (false alarm 6.3e-5 per test, 25
 * tests). Negative control: the mixture with its light density doubled
 * must fail at the point below the light. */
static void test_sphere_light_irradiance(void **state)
{
    negctl *t = *state;
    const double phi = 4e5, r = 20.0, h = 100.0, rho = 0.8;
    static const double px[5] = {0, 60, 150, 300, 100}, pz[5] = {0, 0, 0, 0, -230};
    rt_camera_params cp;
    rt_scene *s = rt_scene_sphere_light(phi, r, h, 400.0, rho, &cp);
    uint64_t seed = mc_test_seed(42u);
    char label[80];
    for (int st = RT_UNIFORM; st <= RT_MIS; st++) {
        double zs[5];
        for (int i = 0; i < 5; i++) {
            rt_path_settings ps = rt_path_settings_default((rt_strategy)st);
            mc_estimate e = radiance_at(s, &ps, px[i], pz[i], 40000, seed + 10u * (uint64_t)st + (uint64_t)i);
            double exact = sphere_light_expected(phi, h, rho, px[i], pz[i]);
            snprintf(label, sizeof label, "sphere light, %s at (%g, 0, %g)", rt_strategy_name((rt_strategy)st),
                     px[i], pz[i]);
            zs[i] = mc_z_score(e.value, exact, e.std_error);
            assert_z_below(label, e.value, exact, e.std_error, 4.0, seed);
        }
        printf("sphere light %-7s z at the five points: %.2f %.2f %.2f %.2f %.2f\n",
               rt_strategy_name((rt_strategy)st), zs[0], zs[1], zs[2], zs[3], zs[4]);
    }
    rt_path_settings bad = rt_path_settings_default(RT_MIXTURE);
    bad.neg.light_pdf_error = 1.0; /* the light density x 2 */
    mc_estimate e = radiance_at(s, &bad, 0.0, 0.0, 40000, seed + 99u);
    double z = mc_z_score(e.value, sphere_light_expected(phi, h, rho, 0.0, 0.0), e.std_error);
    printf("negative control (mixture, light pdf x 2) below the light: z = %.1f\n", z);
    if (!negctl_record(t, "mixture with its light pdf x 2", "z-test", fabs(z) >= 4.0))
        fail_msg("negative control not caught: doubled light pdf gives z = %.2f (seed %llu)", z,
                 (unsigned long long)seed);
    rt_scene_destroy(s);
}

/* max depth 1 is what the camera sees directly: the light's 15 where the
 * light is, black elsewhere (every sample is 0 or 15, so with 4 samples a
 * pixel is a multiple of 3.75). */
static void test_max_depth_one_is_emission(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    rt_image *img = rt_image_create(40, 40);
    for (int st = RT_UNIFORM; st <= RT_MIS; st++) {
        rt_render_job job = job_for(s, cp, 40, 40, (rt_strategy)st);
        job.spp = 4;
        job.path.max_depth = 1;
        rt_render_stats stats;
        assert_int_equal(rt_render(&job, img, &stats), 0);
        assert_int_equal(stats.segments, stats.paths); /* no shadow rays */
        int lit = 0;
        for (int i = 0; i < 1600; i++) {
            double v = img->px[i].mean[0];
            assert_true(v >= 0.0 && v <= 15.0 && fmod(v, 3.75) == 0.0);
            lit += v > 0.0;
        }
        assert_true(lit > 0 && lit < 100);
    }
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

/* Russian roulette leaves the mean unchanged: lambert, 16 x 16 pixels,
 * 128 samples, mixture, max depth 50, with and without roulette (seeds 43
 * and 44); z of the difference of the image means per channel, |z| < 4
 * (6.3e-5 each). Roulette must also shorten the paths. */
static void test_russian_roulette_same_mean(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    rt_image *a = rt_image_create(16, 16), *b = rt_image_create(16, 16);
    rt_render_job job = job_for(s, cp, 16, 16, RT_MIXTURE);
    job.spp = 128;
    job.seed = mc_test_seed(43u);
    rt_render_stats sa, sb;
    assert_int_equal(rt_render(&job, a, &sa), 0);
    job.seed = mc_test_seed(44u);
    job.path.russian_roulette = true;
    assert_int_equal(rt_render(&job, b, &sb), 0);
    mc_estimate ea[3], eb[3];
    rt_image_region_stats(a, 0, 0, 16, 16, ea);
    rt_image_region_stats(b, 0, 0, 16, 16, eb);
    for (int c = 0; c < 3; c++) {
        double se = sqrt(ea[c].std_error * ea[c].std_error + eb[c].std_error * eb[c].std_error);
        printf("roulette on - off, channel %d: %.5f - %.5f, z = %.2f\n", c, eb[c].value, ea[c].value,
               mc_z_score(eb[c].value - ea[c].value, 0.0, se));
        assert_z_below("roulette on - off", eb[c].value - ea[c].value, 0.0, se, 4.0, job.seed);
    }
    printf("roulette: %llu ray segments without, %llu with\n", (unsigned long long)sa.segments,
           (unsigned long long)sb.segments);
    assert_true(sb.segments < sa.segments);
    rt_image_destroy(a);
    rt_image_destroy(b);
    rt_scene_destroy(s);
}

/* The survival probability of the roulette rule (render/roulette.c,
 * roulette_rule) by hand: min(0.95, largest channel of beta * albedo),
 * channel by channel, not the product of the largest channels. beta =
 * (0.6, 2.385, 0.1), albedo = (0.73, 0.12, 0.65): the products are
 * 0.438, 0.2862 and 0.065, so q = 0.438 (the largest channels, 2.385 and
 * 0.73, would give 1.74105, capped to 0.95). A throughput above 1 caps at
 * 0.95; a black surface or a zero throughput gives 0 (the path ends). The
 * rule takes no direction: what the direction drawn at the vertex does to
 * beta (s/p) cannot move q. */
static void test_roulette_survival_known(void **state)
{
    (void)state;
    assert_near(rt_roulette_survival(v3(0.6, 2.385, 0.1), v3(0.73, 0.12, 0.65)), 0.438, 1e-15);
    assert_true(rt_roulette_survival(v3(3.0, 1.0, 1.0), v3(0.5, 0.2, 0.2)) == 0.95);
    assert_true(rt_roulette_survival(v3(0.0, 0.0, 0.0), v3(0.73, 0.73, 0.73)) == 0.0);
    assert_true(rt_roulette_survival(v3(0.7, 0.2, 0.3), v3(0.0, 0.0, 0.0)) == 0.0);
    /* Cosine sampling: s/p = 1, so beta * albedo is also the throughput
     * after the bounce, and q is the same whichever of the two the rule
     * reads. */
    assert_true(rt_roulette_survival(v3(0.5, 0.25, 0.125), v3(0.73, 0.73, 0.73)) == 0.5 * 0.73);
}

/* The mean of the per-pixel variance of one sample over the image and the
 * three channels (what the book's #roulette run prints). */
static double sample_variance(const rt_image *img, mc_estimate e[3])
{
    rt_image_region_stats(img, 0, 0, img->width, img->height, e);
    return (e[0].variance + e[1].variance + e[2].variance) / 3.0;
}

/* The mean of the per-pixel variance of one sample of the book scene
 * (64 x 64 pixels, 64 samples, max depth 50, mixture) with roulette
 * decided after the direction's s/p when `after` is set (the negative
 * control) and before it otherwise, against the same without roulette;
 * the roulette image's
 * means must agree with the plain ones (|z| < 4 per channel, false alarm
 * 6.3e-5 each), roulette being unbiased under either rule. */
static double roulette_variance_ratio(const rt_scene *s, rt_camera_params cp, bool after, uint64_t seed)
{
    rt_image *a = rt_image_create(64, 64), *b = rt_image_create(64, 64);
    assert_true(a && b);
    rt_render_job job = job_for(s, cp, 64, 64, RT_MIXTURE);
    job.spp = 64;
    job.seed = seed;
    assert_int_equal(rt_render(&job, a, NULL), 0);
    job.seed = seed + 1u;
    job.path.russian_roulette = true;
    job.path.neg.roulette_after_direction = after;
    assert_int_equal(rt_render(&job, b, NULL), 0);
    mc_estimate ea[3], eb[3];
    double va = sample_variance(a, ea), vb = sample_variance(b, eb);
    for (int c = 0; c < 3; c++) {
        double se = sqrt(ea[c].std_error * ea[c].std_error + eb[c].std_error * eb[c].std_error);
        assert_z_below("book roulette on - off", eb[c].value - ea[c].value, 0.0, se, 4.0, seed);
    }
    printf("book, mixture%s: variance of a sample %.4f without roulette, %.4f with (ratio %.3f)\n",
           after ? ", roulette after the direction" : "", va, vb, vb / va);
    rt_image_destroy(a);
    rt_image_destroy(b);
    return vb / va;
}

/* Roulette on the mixture, seeds 47 (off) and 48 (on). Cheap in variance:
 * the survival decided before the direction's s/p (render/roulette.h)
 * raises the variance of a sample only a little; decided after it, which
 * gives the lamp-aimed directions a small q just before the lamp, it
 * raises it more. The test holds the ratio below 1.45, a threshold set
 * between the two rules' ratios on a few seed pairs: a ratio over 4096
 * pixels, whose spread comes from rare large samples, so no closed-form
 * false-alarm rate is claimed. Negative control: the rule after the
 * direction (neg.roulette_after_direction) must reach 1.45, which this
 * test checks on every run. */
static void test_roulette_mixture_variance(void **state)
{
    negctl *t = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_non_null(s);
    uint64_t seed = mc_test_seed(47u);
    assert_true(roulette_variance_ratio(s, cp, false, seed) < 1.45);
    double bad = roulette_variance_ratio(s, cp, true, seed);
    if (!negctl_record(t, "roulette decided after the direction", "variance ratio", bad >= 1.45))
        fail_msg("negative control not caught: roulette after the direction gives ratio %.3f (seed %llu)",
                 bad, (unsigned long long)seed);
    rt_scene_destroy(s);
}

/* A NaN sample is dropped and counted. The camera looks at two lights side
 * by side, emitting 1 (left of x = 0 in the image) and NaN (right); the
 * middle one of three pixels straddles the seam. Its finite samples all
 * see 1, so its value is exactly 1 and its NaN samples are counted; the
 * right pixel has no finite sample and is black; counts add up to spp.
 * Negative control: the book's rule (a NaN sample counts as 0 and the
 * pixel divides by spp) gives the middle pixel n_finite / spp < 1, which
 * the same check must reject. */
static void test_nan_samples_dropped_and_counted(void **state)
{
    negctl *t = *state;
    rt_scene *s = rt_scene_create();
    int one = rt_scene_add_material(s, rt_diffuse_light(v3(1, 1, 1)));
    int nan = rt_scene_add_material(s, rt_diffuse_light(v3((double)NAN, (double)NAN, (double)NAN)));
    /* The camera at the origin looks along +z; image right is -x. */
    rt_scene_add(s, rt_scene_quad(s, v3(0, -10, 1), v3(0, 20, 0), v3(10, 0, 0), one));
    rt_scene_add(s, rt_scene_quad(s, v3(0, -10, 1), v3(-10, 0, 0), v3(0, 20, 0), nan));
    assert_int_equal(rt_scene_build(s), 0);
    rt_camera_params cp = {v3(0, 0, 0), v3(0, 0, 1), v3(0, 1, 0), 60.0};
    rt_image *img = rt_image_create(3, 1);
    rt_render_job job = job_for(s, cp, 3, 1, RT_MIXTURE);
    job.spp = 100;
    rt_render_stats st;
    assert_int_equal(rt_render(&job, img, &st), 0);
    const rt_pixel *mid = &img->px[1];
    assert_int_equal(mid->n + mid->dropped, 100);
    assert_true(mid->dropped > 0 && mid->n > 0);
    assert_true(rt_image_get(img, 1, 0).x == 1.0);
    assert_int_equal(img->px[0].dropped, 0);
    assert_true(rt_image_get(img, 0, 0).x == 1.0);
    assert_int_equal(img->px[2].dropped, 100);
    assert_true(rt_image_get(img, 2, 0).x == 0.0);
    assert_int_equal(st.dropped, mid->dropped + 100);
    assert_int_equal(rt_image_dropped(img), st.dropped);
    double book = (double)mid->n / 100.0;
    assert_true(
        negctl_record(t, "the book's NaN rule (0, divided by spp)", "pixel value 1", book != 1.0));
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_furnace_radiance),
        cmocka_unit_test(test_sphere_light_irradiance),
        cmocka_unit_test(test_max_depth_one_is_emission),
        cmocka_unit_test(test_russian_roulette_same_mean),
        cmocka_unit_test(test_roulette_survival_known),
        cmocka_unit_test(test_roulette_mixture_variance),
        cmocka_unit_test(test_nan_samples_dropped_and_counted),
    };
    return cmocka_run_group_tests_name("test_render_integrator", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
