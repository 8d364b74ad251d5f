/* tests/test_render_bdpt.c - light tracing and bidirectional path tracing
 * (render/bdpt.h, render/lighttrace.h): every unweighted strategy (s, t)
 * of a path length agrees with the others, the MIS weights of a path sum
 * to 1, light tracing and the weighted sum agree with the book's mixture,
 * the white furnace and the sphere light hold, images do not depend on the
 * thread count, and a splat without the camera importance's 1 / cos^3, a
 * weight that counts one strategy twice, or a path family that the
 * weighted sum both keeps and estimates apart is caught.
 *
 * Region estimates come from independent batches (one render per seed):
 * a splat lands in any pixel, so the per-pixel variances of
 * rt_image_region_stats do not describe a region's error; the spread of B
 * batch means does. Each comparison is a two-sample t statistic,
 * (a - b) / sqrt(se_a^2 + se_b^2), against Student's t with B - 1 degrees
 * of freedom (fewer than Welch's, so conservative), Sidak-corrected over
 * the comparisons of the test at a family false-alarm level of 1e-3. */
#include "tests/support/mc_test.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/stats.h"
#include "pdf/pdf.h"
#include "render/bdpt.h"
#include "render/lights.h"
#include "render/render.h"
#include "render/scenes.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"

enum { W = 24, GRID = 3, CELL = W / GRID, REGIONS = GRID * GRID, BATCHES = 16 };

typedef struct regions {
    mc_estimate e[REGIONS][3];
} regions;

/* Region means of BATCHES renders of spp samples per pixel each (seeds
 * seed, seed + 1, ...), with standard errors from their spread. */
static regions batched(const rt_scene *s, rt_camera_params cp, rt_path_settings ps, uint64_t spp,
                       uint64_t seed)
{
    rt_image *img = rt_image_create(W, W);
    mc_welford acc[REGIONS][3];
    for (int k = 0; k < REGIONS; k++)
        for (int c = 0; c < 3; c++)
            acc[k][c] = mc_welford_init();
    for (int b = 0; b < BATCHES; b++) {
        rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, W, W));
        job.path = ps;
        job.spp = spp;
        job.seed = seed + (uint64_t)b;
        job.threads = 2;
        assert_int_equal(rt_render(&job, img, NULL), 0);
        for (int k = 0; k < REGIONS; k++) {
            int x = (k % GRID) * CELL, y = (k / GRID) * CELL;
            mc_estimate e[3];
            rt_image_region_stats(img, x, y, x + CELL, y + CELL, e);
            for (int c = 0; c < 3; c++)
                mc_welford_add(&acc[k][c], e[c].value);
        }
    }
    regions r;
    for (int k = 0; k < REGIONS; k++)
        for (int c = 0; c < 3; c++)
            r.e[k][c] = mc_welford_estimate(&acc[k][c]);
    rt_image_destroy(img);
    return r;
}

/* The largest |t| of the region differences a - b; a region where both
 * are exactly 0 (no light reaches it at that length) is skipped, one where
 * they differ with no spread at all counts as infinite. */
static double max_t(const regions *a, const regions *b, int *where)
{
    double worst = 0.0;
    for (int k = 0; k < REGIONS; k++)
        for (int c = 0; c < 3; c++) {
            double d = a->e[k][c].value - b->e[k][c].value;
            double se = sqrt(a->e[k][c].std_error * a->e[k][c].std_error +
                             b->e[k][c].std_error * b->e[k][c].std_error);
            double t = se > 0.0 ? fabs(d) / se : d == 0.0 ? 0.0 : HUGE_VAL;
            if (t > worst) {
                worst = t;
                *where = k;
            }
        }
    return worst;
}

/* The t threshold for m comparisons at a family level of 1e-3. */
static double threshold(int m)
{
    return gsl_cdf_tdist_Qinv(0.5 * mc_sidak_alpha(1e-3, m), BATCHES - 1);
}

/* The shortest segment the per-length comparisons keep (lambert's room
 * is 555 across): see test_unweighted_strategies_agree_per_length. */
#define MIN_SEGMENT 50.0

static rt_path_settings bdpt_settings(int s, int t, int depth)
{
    rt_path_settings ps = rt_path_settings_default(RT_BDPT);
    ps.bdpt_s = s;
    ps.bdpt_t = t;
    ps.max_depth = depth;
    ps.bdpt_min_segment = MIN_SEGMENT;
    return ps;
}

/* On lambert (every surface diffuse: every strategy samples every path),
 * for each path length k = 1 .. 4 segments, every unweighted strategy
 * (s, k + 1 - s), s = 0 .. k, against (1, k) (next-event estimation's
 * way): 10 comparisons x 27 region-channels = 270 t statistics. BATCHES
 * renders of 64 samples per pixel each, seeds 301 and on. Every strategy
 * leaves out the paths with a segment shorter than MIN_SEGMENT
 * (rt_path_settings.bdpt_min_segment), so that all of them estimate the
 * same integral with bounded terms: a join of two diffuse vertices near
 * one of the room's corners has a geometry term like 1 / r^2 there, a
 * strategy such as (2, 2) alone then has no finite variance, and its
 * batch means fall short of the mean most of the time and overshoot it
 * rarely, which no t test can judge (without the floor, (2, 2) stood 7.4
 * standard errors below (1, 3) on the floor's corner at the default
 * seed, and between 1.8 and 3.6 at four others). */
static void test_unweighted_strategies_agree_per_length(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    uint64_t seed = mc_test_seed(301u);
    double thr = threshold(10 * REGIONS * 3);
    for (int k = 1; k <= 4; k++) {
        regions ref = batched(s, cp, bdpt_settings(1, k, k), 64, seed + 100u * (uint64_t)k);
        for (int sv = 0; sv <= k; sv++) {
            if (sv == 1)
                continue;
            regions r = batched(s, cp, bdpt_settings(sv, k + 1 - sv, k), 64,
                                seed + 100u * (uint64_t)k + 20u * (uint64_t)(sv + 1));
            int where = 0;
            double t = max_t(&r, &ref, &where);
            printf("lambert length %d: bdpt:%d,%d vs bdpt:1,%d: max |t| %.2f (threshold %.2f)\n", k, sv,
                   k + 1 - sv, k, t, thr);
            if (t >= thr)
                fail_msg("length %d: bdpt:%d,%d disagrees with bdpt:1,%d in region %d: |t| %.2f >= %.2f "
                         "(seed %llu)", k, sv, k + 1 - sv, k, where, t, thr, (unsigned long long)seed);
        }
    }
    rt_scene_destroy(s);
}

/* A vertex of a made-up path on the Lambertian room: point p on the
 * plane with normal n. */
static rt_bdpt_vertex surface(vec3 p, vec3 n, const rt_material *m)
{
    rt_bdpt_vertex v = {RT_BDPT_SURFACE, p, n, n, true, false, m, -1, vec3_make(1, 1, 1)};
    return v;
}

/* The MIS weights of a path over all the strategies that can join it sum
 * to 1: 2000 random paths of 2 to 9 vertices (seed 311) on the walls of
 * lambert's room, the first on its lamp, the last the camera, a quarter of
 * the inner vertices made specular; |sum - 1| < 1e-12. Negative control:
 * strategy 1 counted twice in the weights' sum must break it. */
static void test_mis_weights_sum_to_one(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    rt_camera cam = rt_camera_make(cp, W, W);
    rt_path_settings ps = rt_path_settings_default(RT_BDPT), bad = ps;
    bad.neg.mis_double = 2;
    rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam), cb = rt_bdpt_ctx_make(s, &bad, &cam);
    rt_material white = rt_lambertian(vec3_make(0.73, 0.73, 0.73));
    rt_material glass = rt_dielectric(1.5, RT_FRESNEL_SCHLICK);
    const rt_prim *lamp = &rt_scene_emitter_prims(s)[0];
    mc_rng rng = mc_rng_derive(mc_test_seed(311u), 0u);
    /* The five walls as (axis, value, inward normal sign). */
    static const int axis[5] = {0, 0, 1, 1, 2};
    static const double at[5] = {0.0, 555.0, 0.0, 555.0, 555.0}, sign[5] = {1, -1, 1, -1, -1};
    double worst = 0.0, worst_bad = 0.0;
    for (int trial = 0; trial < 2000; trial++) {
        int n = 2 + (int)mc_rng_bounded(&rng, 8u);
        rt_bdpt_vertex x[10];
        vec3 q = vec3_add(lamp->as.quad.q, vec3_add(vec3_scale(lamp->as.quad.u, mc_rng_uniform(&rng)),
                                                    vec3_scale(lamp->as.quad.v, mc_rng_uniform(&rng))));
        x[0] = (rt_bdpt_vertex){RT_BDPT_LIGHT, q, lamp->as.quad.normal, lamp->as.quad.normal, true,
                                false, rt_scene_material(s, lamp->material), 0, vec3_make(1, 1, 1)};
        for (int i = 1; i < n - 1; i++) {
            int wall = (int)mc_rng_bounded(&rng, 5u);
            double p[3] = {555.0 * mc_rng_uniform(&rng), 555.0 * mc_rng_uniform(&rng),
                           555.0 * mc_rng_uniform(&rng)}, nn[3] = {0, 0, 0};
            p[axis[wall]] = at[wall];
            nn[axis[wall]] = sign[wall];
            x[i] = surface(vec3_make(p[0], p[1], p[2]), vec3_make(nn[0], nn[1], nn[2]), &white);
            if (mc_rng_uniform(&rng) < 0.25) {
                x[i].delta = true;
                x[i].m = &glass;
            }
        }
        x[n - 1] = (rt_bdpt_vertex){RT_BDPT_CAMERA, cam.origin, c.forward, c.forward, true, false,
                                    NULL, -1, vec3_make(1, 1, 1)};
        /* Strategy s joins x[s-1] and x[s]: not at a specular vertex. */
        double sum = 0.0, sum_bad = 0.0;
        for (int sv = 0; sv < n; sv++) {
            if (sv > 0 && (x[sv - 1].delta || x[sv].delta))
                continue;
            sum += rt_bdpt_mis_weight(&c, x, n, sv);
            sum_bad += rt_bdpt_mis_weight(&cb, x, n, sv);
        }
        worst = fmax(worst, fabs(sum - 1.0));
        worst_bad = fmax(worst_bad, fabs(sum_bad - 1.0));
    }
    printf("MIS weights over 2000 random paths: largest |sum - 1| %.2e; counting strategy 1 twice: "
           "%.2e\n", worst, worst_bad);
    assert_true(worst < 1e-12);
    if (!negctl_record(nc, "MIS weight counting one strategy twice", "weights sum to 1",
                       worst_bad >= 1e-12))
        fail_msg("the double-counted strategy was not caught: |sum - 1| %.2e", worst_bad);
    rt_scene_destroy(s);
}

/* Light tracing and the weighted bidirectional sum against the book's
 * mixture: lambert (lighttrace, bdpt), book (bdpt, and bdpt with Russian
 * roulette), book-metal (bdpt), and a close-up of book's floor seen
 * through the glass sphere (bdpt), depth 50, BATCHES renders of 64 (bdpt,
 * lighttrace) or 256 (mixture) samples per pixel, seeds 401 and on: 6
 * comparisons x 27 = 162 t statistics.
 * Negative controls on lambert: light tracing whose splats lack the
 * 1 / cos^3 of the camera importance, and bdpt whose weights count
 * strategy 1 (next-event estimation) twice; each must exceed the
 * threshold somewhere. On book: bdpt that keeps in its strategies the
 * paths it also estimates apart (the lamp seen directly or through glass,
 * E S* L; the caustic seen through the sphere, E (S+ D)+ S+ L), each
 * counted twice, must be caught the same way, and so must bdpt whose light
 * subpaths aimed at the glass sphere (the default emission) carry cosine
 * emission's throughput, and bdpt with roulette whose survivors are
 * divided by the survival probability without the camera's gain
 * (RT_BDPT_RR_GAIN_CAMERA). The bdpt renders of book
 * and book-metal use the default aim (RT_EMIT_AIM_DEFAULT), so their
 * agreement is its test of bias; book's render with roulette is the
 * gains'. */
/* Fails unless every region-channel of a agrees with ref, the mixture:
 * max |t| < thr. */
static void expect_agree(const char *what, const regions *a, const regions *ref, double thr,
                         uint64_t seed)
{
    int where = 0;
    double t = max_t(a, ref, &where);
    printf("%s vs mixture: max |t| %.2f (threshold %.2f)\n", what, t, thr);
    if (t >= thr)
        fail_msg("%s disagrees with mixture in region %d: |t| %.2f >= %.2f (seed %llu)", what, where,
                 t, thr, (unsigned long long)seed);
}

/* Records the negative control `what`, caught when some region-channel of
 * bad is at least thr from ref, and fails if it is not. */
static void expect_caught(negctl *nc, const char *what, const regions *bad, const regions *ref,
                          double thr)
{
    int where = 0;
    double t = max_t(bad, ref, &where);
    printf("negative control %s: max |t| %.2f (threshold %.2f)\n", what, t, thr);
    if (!negctl_record(nc, what, "region t-test", t >= thr))
        fail_msg("%s was not caught: |t| %.2f < %.2f", what, t, thr);
}

static void test_agree_with_mixture(void **state)
{
    negctl *nc = *state;
    uint64_t seed = mc_test_seed(401u);
    double thr = threshold(6 * REGIONS * 3);
    static const char *const scenes[3] = {"lambert", "book", "book-metal"};
    for (int i = 0; i < 3; i++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(scenes[i], &cp);
        regions ref = batched(s, cp, rt_path_settings_default(RT_MIXTURE), 256, seed + 100u * (uint64_t)i);
        for (int st = RT_LIGHTTRACE; st <= RT_BDPT; st++) {
            if (st == RT_LIGHTTRACE && i > 0)
                continue; /* light tracing cannot see the glass sphere */
            regions r = batched(s, cp, rt_path_settings_default((rt_strategy)st), 64,
                                seed + 100u * (uint64_t)i + 20u * (uint64_t)(st - RT_LIGHTTRACE + 1));
            char what[64];
            snprintf(what, sizeof what, "%s: %s", scenes[i], rt_strategy_name((rt_strategy)st));
            expect_agree(what, &r, &ref, thr, seed);
        }
        if (i == 0) {
            rt_path_settings lt = rt_path_settings_default(RT_LIGHTTRACE), mis = rt_path_settings_default(RT_BDPT);
            lt.neg.splat_drop_cos3 = true;
            mis.neg.mis_double = 2;
            regions bad1 = batched(s, cp, lt, 64, seed + 90u), bad2 = batched(s, cp, mis, 64, seed + 95u);
            expect_caught(nc, "light tracing without the camera importance's 1/cos^3", &bad1, &ref, thr);
            expect_caught(nc, "bdpt counting next-event estimation twice", &bad2, &ref, thr);
        }
        if (i == 1) {
            rt_path_settings rr = rt_path_settings_default(RT_BDPT), seen = rr, through = rr,
                             aimed = rr, ungained = rr;
            rr.russian_roulette = true;
            ungained.russian_roulette = true;
            ungained.neg.bdpt_roulette_ungained = true;
            seen.neg.seen_twice = true;
            through.neg.through_twice = true;
            aimed.neg.emit_aim_cosine_beta = true;
            regions with_rr = batched(s, cp, rr, 64, seed + 160u);
            expect_agree("book: bdpt with Russian roulette", &with_rr, &ref, thr, seed);
            /* The floor under the sphere seen through it, close up. */
            rt_camera_params close = cp;
            close.lookat = vec3_make(190.0, 30.0, 120.0);
            close.vfov_deg = 8.0;
            regions ref2 = batched(s, close, rt_path_settings_default(RT_MIXTURE), 256, seed + 170u);
            regions good2 = batched(s, close, rt_path_settings_default(RT_BDPT), 64, seed + 180u);
            expect_agree("book, the floor through the sphere close up: bdpt", &good2, &ref2, thr, seed);
            regions bad1 = batched(s, cp, seen, 64, seed + 190u), bad2 = batched(s, close, through, 64, seed + 195u);
            expect_caught(nc, "bdpt counting the camera's view of the lamp through glass twice", &bad1,
                          &ref, thr);
            expect_caught(nc, "bdpt counting the caustic seen through the sphere twice", &bad2, &ref2,
                          thr);
            regions bad3 = batched(s, cp, aimed, 64, seed + 197u);
            expect_caught(nc, "bdpt aiming light subpaths at the glass with cosine emission's weight",
                          &bad3, &ref, thr);
            regions bad4 = batched(s, cp, ungained, 64, seed + 199u);
            expect_caught(nc, "bdpt's roulette dividing by the survival probability without its gain",
                          &bad4, &ref, thr);
        }
        rt_scene_destroy(s);
    }
}

/* The white furnace (every pixel 1 - 2^-8 at depth 8: inside the
 * furnace no path ever leaves, and a bidirectional sample at depth 50
 * would join some 2500 pairs of vertices) with lighttrace
 * and bdpt, and the sphere light with both against mis (whose plane
 * radiance test_render_integrator checks against the analytic
 * irradiance): BATCHES renders of 8 x 8 (furnace, region = the whole
 * image, each channel) or 24 x 24 (sphere light, 27 region-channels)
 * pixels, 32 samples per pixel, seeds 501 and on. 2 x 3 + 2 x 27 = 60 t
 * statistics. */
static void test_furnace_and_sphere_light(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(501u);
    double thr = threshold(60);
    rt_camera_params cp;
    rt_scene *f = rt_scene_named("furnace", &cp);
    for (int st = RT_LIGHTTRACE; st <= RT_BDPT; st++) {
        rt_path_settings ps = rt_path_settings_default((rt_strategy)st);
        ps.max_depth = 8;
        regions r = batched(f, cp, ps, 32, seed + 10u * (uint64_t)st);
        double mean = 0.0, var = 0.0;
        for (int k = 0; k < REGIONS; k++) {
            mean += r.e[k][1].value / REGIONS;
            var += r.e[k][1].std_error * r.e[k][1].std_error / (REGIONS * REGIONS);
        }
        double exact = rt_scene_furnace_radiance(RT_FURNACE_EMISSION, RT_FURNACE_RHO, 8);
        double t = fabs(mean - exact) / sqrt(var);
        printf("furnace %s: image mean %.6f +- %.6f, |t| %.2f (threshold %.2f)\n",
               rt_strategy_name((rt_strategy)st), mean, sqrt(var), t, thr);
        assert_true(t < thr);
    }
    rt_scene_destroy(f);
    rt_scene *s = rt_scene_named("sphere-light", &cp);
    regions ref = batched(s, cp, rt_path_settings_default(RT_MIS), 32, seed + 50u);
    for (int st = RT_LIGHTTRACE; st <= RT_BDPT; st++) {
        regions r = batched(s, cp, rt_path_settings_default((rt_strategy)st), 32, seed + 60u + (uint64_t)st);
        int where = 0;
        double t = max_t(&r, &ref, &where);
        printf("sphere light %s vs mis: max |t| %.2f (threshold %.2f)\n", rt_strategy_name((rt_strategy)st),
               t, thr);
        assert_true(t < thr);
    }
    rt_scene_destroy(s);
}

/* The image's sequence (rt_sampler_image_point), which a light subpath's
 * start draws from with Sobol points: a 16 x 16 image of 16 samples per
 * pixel (2^12 samples, seed 2801). Every value is in [0, 1); dimensions 0
 * and 1 over all the image's samples are a (0,12,2)-net, and over each
 * pixel's 16 samples a (0,4,2)-net; each of dimensions 0 to 4 alone
 * puts one of the 2^12 points in each interval of 2^-12; the sampler of
 * another seed gives other points. Past 2^32 indices a sample takes a
 * fresh scramble: the point of index 2^32 + j differs from that of j,
 * from a pixel that starts at 2^32 and from one whose samples cross it.
 * Negative control: the padded requests of the same samples (dimensions 0
 * and 1 of each pixel's own set, rt_sampler_2d) are not a net over the
 * image. */
static void test_image_sequence(void **state)
{
    negctl *nc = *state;
    enum { PIX = 256, SPP = 16, N = PIX * SPP, M = 12 };
    uint64_t seed = mc_test_seed(2801u);
    static uint32_t x[N], y[N], px[N], py[N], one[RT_SAMPLER_IMAGE_DIMS][N];
    int other_seed_differs = 0;
    for (uint64_t p = 0; p < PIX; p++) {
        rt_sampler s = rt_sampler_pixel(RT_SAMPLER_SOBOL, seed, SPP, mc_rng_derive(seed, p), p);
        rt_sampler o =
            rt_sampler_pixel(RT_SAMPLER_SOBOL, seed + 1u, SPP, mc_rng_derive(seed, p), p);
        uint32_t bx[SPP], by[SPP];
        for (uint64_t k = 0; k < SPP; k++) {
            double u[RT_SAMPLER_IMAGE_DIMS], v[RT_SAMPLER_IMAGE_DIMS], w[2];
            rt_sampler_start(&s, k);
            rt_sampler_start(&o, k);
            rt_sampler_image_point(&s, RT_SAMPLER_IMAGE_DIMS, u);
            rt_sampler_image_point(&o, RT_SAMPLER_IMAGE_DIMS, v);
            rt_sampler_2d(&s, &w[0], &w[1]);
            size_t g = (size_t)(p * SPP + k);
            for (unsigned d = 0; d < RT_SAMPLER_IMAGE_DIMS; d++) {
                assert_true(u[d] >= 0.0 && u[d] < 1.0);
                one[d][g] = (uint32_t)(u[d] * 0x1p32);
                other_seed_differs += u[d] != v[d];
            }
            x[g] = bx[k] = one[0][g];
            y[g] = by[k] = one[1][g];
            px[g] = (uint32_t)(w[0] * 0x1p32);
            py[g] = (uint32_t)(w[1] * 0x1p32);
        }
        assert_seeded(mc_test_is_02_net(bx, by, 4u), seed);
    }
    assert_seeded(mc_test_is_02_net(x, y, M), seed);
    for (unsigned d = 0; d < RT_SAMPLER_IMAGE_DIMS; d++)
        assert_seeded(mc_test_strata_once(one[d], M), seed);
    assert_true(other_seed_differs > N);
    /* Index 2^32 + j against j: a pixel whose samples start at 2^32. */
    uint64_t spp = 1u << 16, pixel = (uint64_t)1 << 16;
    rt_sampler far = rt_sampler_pixel(RT_SAMPLER_SOBOL, seed, spp, mc_rng_derive(seed, 0u), pixel);
    rt_sampler near = rt_sampler_pixel(RT_SAMPLER_SOBOL, seed, spp, mc_rng_derive(seed, 0u), 0u);
    int same = 0;
    for (uint64_t k = 0; k < 64u; k++) {
        double a[2], b[2];
        rt_sampler_start(&far, k);
        rt_sampler_start(&near, k);
        rt_sampler_image_point(&far, 2u, a);
        rt_sampler_image_point(&near, 2u, b);
        assert_true(a[0] >= 0.0 && a[0] < 1.0 && a[1] >= 0.0 && a[1] < 1.0);
        same += a[0] == b[0] && a[1] == b[1];
    }
    /* A pixel whose samples cross 2^32: 48 spp from index 2^32 - 16. */
    rt_sampler cross = rt_sampler_pixel(RT_SAMPLER_SOBOL, seed, 48u, mc_rng_derive(seed, 0u),
                                        89478485u);
    rt_sampler start = rt_sampler_pixel(RT_SAMPLER_SOBOL, seed, 48u, mc_rng_derive(seed, 0u), 0u);
    for (uint64_t k = 16; k < 48u; k++) {
        double a[2], b[2];
        rt_sampler_start(&cross, k);
        rt_sampler_start(&start, k - 16u);
        rt_sampler_image_point(&cross, 2u, a);
        rt_sampler_image_point(&start, 2u, b);
        assert_true(a[0] >= 0.0 && a[0] < 1.0 && a[1] >= 0.0 && a[1] < 1.0);
        same += a[0] == b[0] && a[1] == b[1];
    }
    printf("image sequence, 16 x 16 pixels x 16 spp: dimensions 0 and 1 a (0,12,2)-net over the "
           "image and a (0,4,2)-net in every pixel, dimensions 0-4 each stratified; another seed "
           "changed %d of %d values; past 2^32, %d of 96 points repeat\n",
           other_seed_differs, N * (int)RT_SAMPLER_IMAGE_DIMS, same);
    assert_int_equal(same, 0);
    if (!negctl_record(nc, "the pixels' padded points as one set over the image",
                       "(0,12,2)-net check", !mc_test_is_02_net(px, py, M)))
        fail_msg("the padded points of the pixels passed as one net over the image");
}

/* Splatted images are bit-identical for 1, 2 and 3 threads (book, bdpt,
 * and lighttrace on lambert, 16 x 16, 8 samples per pixel, a pass of 3
 * so that passes end mid-render), and a render cancelled from its
 * progress callback returns 1 with fewer paths than asked and a finite
 * image. */
static void cancel_after_first(void *ctx, const rt_progress *p)
{
    (void)p;
    atomic_store((atomic_int *)ctx, 1);
}

static void test_threads_and_cancel(void **state)
{
    (void)state;
    static const char *const scenes[2] = {"book", "lambert"};
    static const rt_strategy sts[2] = {RT_BDPT, RT_LIGHTTRACE};
    for (int i = 0; i < 2; i++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(scenes[i], &cp);
        rt_image *img[3];
        for (int th = 1; th <= 3; th++) {
            img[th - 1] = rt_image_create(16, 16);
            rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 16, 16));
            job.path = rt_path_settings_default(sts[i]);
            job.spp = 8;
            job.pass_spp = 3;
            job.threads = th;
            assert_int_equal(rt_render(&job, img[th - 1], NULL), 0);
        }
        for (int th = 1; th < 3; th++)
            assert_memory_equal(img[0]->px, img[th]->px, 16 * 16 * sizeof(rt_pixel));
        atomic_int cancel = 0;
        rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 16, 16));
        job.path = rt_path_settings_default(sts[i]);
        job.spp = 64;
        job.threads = 2;
        job.cancel = &cancel;
        job.progress = cancel_after_first;
        job.progress_ctx = &cancel;
        rt_render_stats st;
        assert_int_equal(rt_render(&job, img[0], &st), 1);
        assert_true(st.cancelled && st.paths > 0 && st.paths < 64u * 256u);
        for (int k = 0; k < 16 * 16; k++)
            for (int c = 0; c < 3; c++)
                assert_true(isfinite(img[0]->px[k].mean[c]));
        for (int th = 0; th < 3; th++)
            rt_image_destroy(img[th]);
        rt_scene_destroy(s);
    }
}

/* --- the aimed emission ------------------------------------------------ */

/* A light subpath's first direction from one point of the book's lamp,
 * charted as (cos theta, phi) about the axis of the glass sphere's cone
 * (d omega = d cos d phi: the density per unit solid angle is the chart's).
 * The cos cells are 0.05 wide and placed so that cos theta_max is a cell
 * edge: the cone's jump then runs along cells, and the quadrature of each
 * cell meets only the cosine part's kink at the lamp's horizon. */
typedef struct emit_chart {
    const rt_bdpt_ctx *c;
    vec3 p, n;
    onb frame; /* about the cone's axis */
    bool claim_cosine; /* the negative control's claim: cosine emission */
} emit_chart;

static void emit_sample(mc_rng *rng, void *ctx, double out[2])
{
    const emit_chart *e = ctx;
    rt_sampler s = rt_sampler_from_rng(*rng);
    vec3 d = onb_to_local(&e->frame, rt_bdpt_emit_direction(e->c, e->p, e->n, &s));
    *rng = s.rng;
    double phi = atan2(d.y, d.x);
    out[0] = d.z;
    out[1] = phi < 0.0 ? phi + 2.0 * MC_PI : phi;
}

static double emit_density(const double x[2], void *ctx)
{
    const emit_chart *e = ctx;
    if (!(x[0] >= -1.0 && x[0] <= 1.0))
        return 0.0;
    double sin_t = sqrt(fmax(0.0, 1.0 - x[0] * x[0]));
    vec3 d = onb_to_world(&e->frame, vec3_make(sin_t * cos(x[1]), sin_t * sin(x[1]), x[0]));
    if (e->claim_cosine) {
        double cos_e = vec3_dot(d, e->n);
        return cos_e > 0.0 ? cos_e * MC_INV_PI : 0.0;
    }
    return rt_bdpt_emit_pdf(e->c, e->p, e->n, d);
}

/* rt_bdpt_emit_direction against rt_bdpt_emit_pdf on the book scene with
 * the default aim (RT_EMIT_AIM_DEFAULT), from the lamp point at (0.3, 0.6)
 * of its edges: chi-square of 10^6 directions (PCG32 seed 331) in about 40
 * x 64 cells of the chart above at chi2_suite_alpha(); the density's
 * integral over the chart within 1e-6 of 1; every direction of unit
 * length within 1e-12 (10^5 of them). Negative control: the same
 * directions against cosine emission's density (the aim forgotten in the
 * weights) must be rejected. A scene without targets (lambert) keeps
 * cosine emission: its bdpt image is the same bytes with the aim at 0.1
 * and at 0. */
static void test_emit_aim_density(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    rt_camera cam = rt_camera_make(cp, W, W);
    rt_path_settings ps = rt_path_settings_default(RT_BDPT);
    rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
    assert_true(rt_scene_target_count(s) == 1 && c.aim == RT_EMIT_AIM_DEFAULT);
    const rt_prim *lamp = &rt_scene_emitter_prims(s)[0];
    const rt_light *ball = &rt_scene_targets(s)[0];
    emit_chart e = {.c = &c,
                    .p = vec3_add(lamp->as.quad.q, vec3_add(vec3_scale(lamp->as.quad.u, 0.3),
                                                            vec3_scale(lamp->as.quad.v, 0.6))),
                    .n = lamp->as.quad.normal};
    double cos_max, omc;
    e.frame = onb_from_w(pdf_sphere_cone(e.p, ball->center, ball->radius, &cos_max, &omc));
    const double h = 0.05;
    int below = (int)ceil((cos_max + 1.0) / h), above = (int)ceil((1.0 - cos_max) / h);
    chi2_spec spec = {"bdpt emission aimed at the glass sphere",
                      {2, {cos_max - below * h, 0.0}, {cos_max + above * h, 2.0 * MC_PI},
                       {below + above, 64}, emit_sample, emit_density, &e}};
    uint64_t seed = mc_test_seed(331u);
    chi2_outcome o = chi2_run(&spec, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&spec, &o);
    assert_seeded(!o.reject, seed);
    double integral = chi2_integrate_pdf(&spec);
    printf("integral of the emission density over the sphere: %.12f\n", integral);
    assert_true(fabs(integral - 1.0) < 1e-6);
    mc_rng rng = mc_rng_derive(seed, 1u);
    for (int k = 0; k < 100000; k++) {
        rt_sampler sm = rt_sampler_from_rng(rng);
        vec3 d = rt_bdpt_emit_direction(&c, e.p, e.n, &sm);
        rng = sm.rng;
        assert_true(fabs(vec3_length(d) - 1.0) < 1e-12);
    }
    e.claim_cosine = true;
    chi2_spec bad = spec;
    bad.name = "negative control: aimed emission judged by cosine emission's density";
    chi2_outcome ob = chi2_run(&bad, 1000000u, seed, chi2_suite_alpha());
    chi2_print(&bad, &ob);
    if (!negctl_record(nc, "aimed emission against cosine emission's density", "chi-square", ob.reject))
        fail_msg("the cosine claim was not rejected: p = %.3g", ob.r.pvalue);
    rt_scene_destroy(s);

    rt_scene *l = rt_scene_named("lambert", &cp);
    assert_int_equal(rt_scene_target_count(l), 0);
    rt_image *a = rt_image_create(W, W), *b = rt_image_create(W, W);
    rt_render_job job = rt_render_job_default(l, rt_camera_make(cp, W, W));
    job.path = rt_path_settings_default(RT_BDPT);
    job.spp = 4;
    job.threads = 2;
    assert_int_equal(rt_render(&job, a, NULL), 0);
    job.path.emit_aim = 0.0;
    assert_int_equal(rt_render(&job, b, NULL), 0);
    assert_memory_equal(a->px, b->px, sizeof *a->px * (size_t)(W * W));
    rt_image_destroy(a);
    rt_image_destroy(b);
    rt_scene_destroy(l);
}

/* Bad strategy names are refused. */
static void test_strategy_parse(void **state)
{
    (void)state;
    rt_path_settings ps = rt_path_settings_default(RT_MIXTURE);
    assert_true(rt_bdpt_strategy_parse("bdpt:2,3", &ps) && ps.strategy == RT_BDPT && ps.bdpt_s == 2 &&
                ps.bdpt_t == 3);
    assert_true(rt_bdpt_strategy_parse("bdpt", &ps) && ps.bdpt_s == 0 && ps.bdpt_t == 0);
    assert_true(rt_bdpt_strategy_parse("lighttrace", &ps) && ps.strategy == RT_LIGHTTRACE);
    static const char *const bad[] = {"bdpt:", "bdpt:1", "bdpt:1,0", "bdpt:0,1", "bdpt:-1,3",
                                      "bdpt:1,3x", "bdpt:1, 3", "bdpt:99,1", "bdpt 1,2", "bd"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_false(rt_bdpt_strategy_parse(bad[i], &ps));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_strategy_parse),
        cmocka_unit_test(test_mis_weights_sum_to_one),
        cmocka_unit_test(test_emit_aim_density),
        cmocka_unit_test(test_image_sequence),
        cmocka_unit_test(test_threads_and_cancel),
        cmocka_unit_test(test_unweighted_strategies_agree_per_length),
        cmocka_unit_test(test_agree_with_mixture),
        cmocka_unit_test(test_furnace_and_sphere_light),
    };
    return cmocka_run_group_tests_name("test_render_bdpt", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
