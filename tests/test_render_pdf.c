/* tests/test_render_pdf.c - the renderer's fast densities (render/lights.h)
 * are the pdf objects of pdf/pdf.h, bit for bit. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <string.h>

#include "mc/rng.h"
#include "pdf/pdf.h"
#include "render/lights.h"
#include "render/fast/lights4.h"
#include "render/render.h"
#include "render/scenes.h"
#include "samplers/sphere.h"

static vec3 v3(double x, double y, double z) { return vec3_make(x, y, z); }

static bool same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* Values and directions for 10^5 random origins (in and around the lights,
 * inside the glass sphere too) and directions, for the book's light list,
 * the furnace's (an origin on the light sphere itself) and a sphere light
 * seen at R / d ~ 1e-9 (its 1 - cos theta_max computed without
 * cancellation on both sides). More than min_nonzero random directions
 * must see a light; with `tiny`, every generated direction must get a
 * finite positive density (a random one almost never hits that light). */
static void check_lights(const rt_scene *s, vec3 lo, vec3 hi, uint64_t seed, int min_nonzero,
                         bool tiny)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    const rt_light *fast = rt_scene_lights(s);
    int n = rt_scene_light_count(s), nonzero = 0;
    for (int i = 0; i < 100000; i++) {
        vec3 o = v3(lo.x + (hi.x - lo.x) * mc_rng_uniform(&rng), lo.y + (hi.y - lo.y) * mc_rng_uniform(&rng),
                    lo.z + (hi.z - lo.z) * mc_rng_uniform(&rng));
        pdf items[RT_MAX_LIGHTS];
        const pdf *ptrs[RT_MAX_LIGHTS];
        pdf list = rt_scene_lights_pdf(s, o, items, ptrs);
        mc_rng a = rng;
        rt_sampler b = rt_sampler_from_rng(rng);
        vec3 da = pdf_generate(&list, &a), db = rt_lights_generate(fast, n, o, &b);
        assert_true(same_vec(da, db));
        assert_true(a.state == b.rng.state);
        rng = a;
        /* The value at the generated direction and at a random one. */
        double vg = pdf_value(&list, da);
        assert_true(vg == rt_lights_value(fast, n, o, da));
        if (tiny)
            assert_true(vg > 0.0 && isfinite(vg));
        vec3 d = smp_uniform_sphere_sample(mc_rng_uniform(&rng), mc_rng_uniform(&rng));
        double va = pdf_value(&list, d);
        assert_true(va == rt_lights_value(fast, n, o, d));
        nonzero += va > 0.0;
        /* The cosine pdf about a random normal. */
        pdf cosine = pdf_cosine(d);
        a = rng;
        b = rt_sampler_from_rng(rng);
        vec3 ca = pdf_generate(&cosine, &a), cb = rt_cosine_generate(d, &b);
        assert_true(same_vec(ca, cb) && a.state == b.rng.state);
        rng = a;
        assert_true(pdf_value(&cosine, da) == rt_cosine_value(d, da));
    }
    assert_true(nonzero >= min_nonzero);
}

static void test_lights_match_pdf_objects(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    check_lights(s, v3(0, 0, 0), v3(555, 555, 555), 31u, 100, false);
    rt_scene_destroy(s);
    s = rt_scene_furnace(0.5, 0.5, &cp);
    check_lights(s, v3(-1, -1, -1), v3(1, 1, 1), 32u, 100, false);
    rt_scene_destroy(s);
    s = rt_scene_sphere_light(1.0, 1e-7, 100.0, 400.0, 0.8, &cp);
    assert_non_null(s);
    check_lights(s, v3(-400, 0, -400), v3(400, 50, 400), 33u, 0, true);
    rt_scene_destroy(s);
}

/* rt_lights4 (four origins in vector lanes) against render/lights.h lane
 * by lane, bit for bit: the prepared numbers, the generated directions
 * and the values, for 25000 batches of four origins and directions
 * (random, generated toward the lights, and along a quad's plane, where
 * its density divides by 0). Some origins are the centre of a sphere
 * light (dist 0) or inside it. With the instruction set isa. */
static void check_lights4(rt_isa isa, const rt_scene *s, vec3 lo, vec3 hi, uint64_t seed)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    const rt_light *fast = rt_scene_lights(s);
    int n = rt_scene_light_count(s);
    for (int it = 0; it < 25000; it++) {
        vec3 o[RT_LANES], d[RT_LANES];
        rt_lights_at one[RT_LANES];
        for (int k = 0; k < RT_LANES; k++) {
            o[k] = v3(lo.x + (hi.x - lo.x) * mc_rng_uniform(&rng), lo.y + (hi.y - lo.y) * mc_rng_uniform(&rng),
                      lo.z + (hi.z - lo.z) * mc_rng_uniform(&rng));
            const rt_light *l = &fast[mc_rng_bounded(&rng, (uint32_t)n)];
            if (l->kind == RT_PRIM_SPHERE && it % 97 == 0)
                o[k] = l->center;
            rt_lights_prepare(&one[k], fast, n, o[k]);
        }
        rt_lights4 at4;
        rt_lights4_prepare(isa, &at4, fast, n, o);
        for (int k = 0; k < RT_LANES; k++) {
            for (int i = 0; i < n; i++) {
                if (fast[i].kind == RT_PRIM_QUAD) {
                    assert_true(at4.num[i][k] == one[k].num[i]);
                    continue;
                }
                assert_true(same_vec(v3(at4.ax[i][k], at4.ay[i][k], at4.az[i][k]), one[k].axis[i]));
                assert_true(at4.cos_max[i][k] == one[k].cos_max[i]);
                assert_true(at4.one_minus_cos[i][k] == one[k].one_minus_cos[i]);
                assert_true(at4.cone[i][k] == one[k].cone[i]);
            }
            rt_sampler a = rt_sampler_from_rng(rng), b = a;
            vec3 ga = rt_lights4_generate(&at4, k, &a), gb = rt_lights_at_generate(&one[k], &b);
            assert_true(same_vec(ga, gb) && a.rng.state == b.rng.state);
            rng = a.rng;
            int kind = (it + k) % 3;
            if (kind == 0) {
                d[k] = ga;
            } else if (kind == 1) {
                d[k] = smp_uniform_sphere_sample(mc_rng_uniform(&rng), mc_rng_uniform(&rng));
            } else {
                /* in the plane of a quad light, when there is one */
                const rt_light *l = &fast[mc_rng_bounded(&rng, (uint32_t)n)];
                d[k] = l->kind == RT_PRIM_QUAD ? vec3_normalize(l->u) : ga;
            }
        }
        double v[RT_LANES];
        rt_lights4_value(isa, &at4, d, v);
        for (int k = 0; k < RT_LANES; k++)
            if (!(v[k] == rt_lights_at_value(&one[k], d[k])))
                fail_msg("isa %d batch %d lane %d: rt_lights4_value %.17g, rt_lights_at_value %.17g", (int)isa,
                         it, k, v[k], rt_lights_at_value(&one[k], d[k]));
    }
}

/* Every instruction set this processor has (the renderer's, from
 * rt_isa_best, among them), on the book's lights (n = 2, whose
 * average is a multiplication by 1/2) and on five lights (a division). */
static void test_lights4_match_lights(void **state)
{
    (void)state;
    int ran = 0;
    bool best_ran = false;
    for (int isa = 0; isa < RT_ISA_COUNT; isa++) {
        if (!rt_isa_available((rt_isa)isa))
            continue;
        rt_camera_params cp;
        rt_scene *s = rt_scene_named("book", &cp);
        check_lights4((rt_isa)isa, s, v3(0, 0, 0), v3(555, 555, 555), 34u);
        rt_scene_destroy(s);
        /* Five lights of both kinds in mixed order, of very different sizes. */
        s = rt_scene_create();
        int white = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
        rt_scene_add(s, rt_scene_quad(s, v3(-50, 0, -50), v3(100, 0, 0), v3(0, 0, 100), white));
        rt_scene_add_light(s, rt_scene_quad(s, v3(-5, 20, -5), v3(10, 0, 0), v3(0, 0, 10), white));
        rt_scene_add_light(s, rt_scene_sphere(s, v3(10, 5, 3), 4.0, white));
        rt_scene_add_light(s, rt_scene_quad(s, v3(0, 1, 0), v3(3, 4, 0), v3(0, 0.5, 7), white));
        rt_scene_add_light(s, rt_scene_sphere(s, v3(-20, 30, 8), 1e-6, white));
        rt_scene_add_light(s, rt_scene_quad(s, v3(8, -3, 2), v3(0, 6, 1), v3(-2, 0, 5), white));
        assert_int_equal(rt_scene_build(s), 0);
        check_lights4((rt_isa)isa, s, v3(-30, -10, -30), v3(30, 40, 30), 35u);
        rt_scene_destroy(s);
        printf("rt_lights4 (%s) = render/lights.h on 2 x 10^5 origins and directions\n",
               rt_isa_name((rt_isa)isa));
        ran++;
        best_ran |= isa == (int)rt_isa_best();
    }
    assert_true(ran >= 1 && best_ran);
}

/* Whole images in both modes, every strategy, two scenes: the same bits,
 * with the stratified sampler named (the pdf objects are the reference
 * for the PCG32 samplers; under sobol they draw from the pixel's stream,
 * render/integrator.c). */
static void test_images_match_pdf_objects(void **state)
{
    (void)state;
    static const char *const names[2] = {"book", "lambert"};
    for (int k = 0; k < 2; k++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(names[k], &cp);
        rt_image *a = rt_image_create(12, 12), *b = rt_image_create(12, 12);
        for (int st = RT_UNIFORM; st <= RT_MIS; st++) {
            rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 12, 12));
            job.spp = 8;
            job.threads = 1;
            job.sampler = RT_SAMPLER_STRATIFIED;
            job.path.strategy = (rt_strategy)st;
            assert_int_equal(rt_render(&job, a, NULL), 0);
            job.path.pdf_objects = true;
            assert_int_equal(rt_render(&job, b, NULL), 0);
            if (memcmp(a->px, b->px, 144 * sizeof(rt_pixel)) != 0)
                fail_msg("%s, %s: pdf objects and fast densities differ", names[k],
                         rt_strategy_name((rt_strategy)st));
        }
        rt_image_destroy(a);
        rt_image_destroy(b);
        rt_scene_destroy(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lights_match_pdf_objects),
        cmocka_unit_test(test_lights4_match_lights),
        cmocka_unit_test(test_images_match_pdf_objects),
    };
    return cmocka_run_group_tests_name("test_render_pdf", tests, NULL, NULL);
}
