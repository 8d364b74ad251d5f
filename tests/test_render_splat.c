/* tests/test_render_splat.c - the exact splat sums (render/splat.h) and
 * the driver's split of a splatting render over rows (rt_render_part):
 * sums that do not depend on the order of their terms, exact values,
 * rounding down to 2^-64, refused terms, and whole renders that are the
 * same bits for any thread count and any split of the rows, as processes
 * under MPI split them. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mc/rng.h"
#include "render/bdpt.h"
#include "render/render.h"
#include "render/scenes.h"
#include "render/splat.h"

/* Terms of very different sizes, as splats are (a caustic's next to a
 * dim wall's): in doubles their sum depends on the order. */
static double term(mc_rng *g)
{
    double u = mc_rng_uniform(g), e = floor(mc_rng_uniform(g) * 60.0) - 30.0;
    return ldexp(u, (int)e);
}

static void test_sum_does_not_depend_on_order(void **state)
{
    (void)state;
    enum { N = 4096 };
    double v[N];
    mc_rng g = mc_rng_derive(11, 0);
    for (int i = 0; i < N; i++)
        v[i] = term(&g);
    rt_splat_sum fwd = {0, 0}, back = {0, 0}, shuffled = {0, 0};
    double dfwd = 0.0, dback = 0.0;
    for (int i = 0; i < N; i++) {
        assert_true(rt_splat_add(&fwd, v[i]));
        assert_true(rt_splat_add(&back, v[N - 1 - i]));
        dfwd += v[i];
        dback += v[N - 1 - i];
    }
    /* A permutation: i -> 1237 i mod N (1237 is odd, so coprime to N). */
    for (int i = 0; i < N; i++)
        assert_true(rt_splat_add(&shuffled, v[(1237 * i) % N]));
    assert_memory_equal(&fwd, &back, sizeof fwd);
    assert_memory_equal(&fwd, &shuffled, sizeof fwd);
    /* The control: the same terms summed in doubles do differ with the
     * order, so the comparison above could have failed. */
    assert_true(dfwd != dback);
    /* And the exact sum is within N 2^-64 (one rounding per term) of the
     * double sum, which is within N eps of its own value. */
    assert_true(fabs(rt_splat_value(fwd) - dfwd) <= 1e-15 * N * dfwd);
}

static void test_exact_values_carry_and_sign(void **state)
{
    (void)state;
    rt_splat_sum s = {0, 0};
    /* 2^53 + 1 - 2^53 is 0 or 2 in doubles, whatever the order; 1 here. */
    assert_true(rt_splat_add(&s, 0x1p53));
    assert_true(rt_splat_add(&s, 1.0));
    assert_true(rt_splat_add(&s, -0x1p53));
    assert_true(rt_splat_value(s) == 1.0);
    assert_true(s.hi == 1 && s.lo == 0);
    /* Carries from the fraction word: 0.75 four times is 3. */
    s = (rt_splat_sum){0, 0};
    for (int i = 0; i < 4; i++)
        assert_true(rt_splat_add(&s, 0.75));
    assert_true(s.hi == 3 && s.lo == 0);
    /* Negative values in two's complement, and back to zero. */
    s = (rt_splat_sum){0, 0};
    assert_true(rt_splat_add(&s, -0.25));
    assert_true(rt_splat_value(s) == -0.25);
    assert_true(s.hi == UINT64_MAX && s.lo == 0xC000000000000000u);
    assert_true(rt_splat_add(&s, 0.25));
    assert_true(s.hi == 0 && s.lo == 0);
    /* Rounded down to a multiple of 2^-64: 2^-70 adds nothing, -2^-70
     * adds -2^-64; 2^-64 itself is exact. */
    assert_true(rt_splat_add(&s, 0x1p-70));
    assert_true(s.hi == 0 && s.lo == 0);
    assert_true(rt_splat_add(&s, 0x1p-64));
    assert_true(s.hi == 0 && s.lo == 1);
    assert_true(rt_splat_add(&s, -0x1p-70));
    assert_true(s.hi == 0 && s.lo == 0);
    /* The largest accepted magnitude, just under 2^62, on both sides. */
    double big = nextafter(0x1p62, 0.0);
    s = (rt_splat_sum){0, 0};
    assert_true(rt_splat_add(&s, big));
    assert_true(rt_splat_value(s) == big);
    assert_true(rt_splat_add(&s, -big));
    assert_true(s.hi == 0 && s.lo == 0);
}

static void test_refused_terms_add_nothing(void **state)
{
    (void)state;
    rt_splat_sum s = {0, 0};
    assert_true(rt_splat_add(&s, 1.5));
    rt_splat_sum before = s;
    const double bad[] = {(double)NAN, (double)INFINITY, -(double)INFINITY, 0x1p62, -0x1p62, 1e300};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_false(rt_splat_add(&s, bad[i]));
        assert_memory_equal(&s, &before, sizeof s);
    }
    /* A pixel's three channels go in together or not at all. */
    rt_splats *sp = rt_splats_create(2, 1);
    assert_non_null(sp);
    assert_false(rt_splats_add_rgb(sp, 1, 1.0, (double)NAN, 2.0));
    for (int i = 0; i < 6; i++)
        assert_true(sp->sum[i].hi == 0 && sp->sum[i].lo == 0);
    assert_true(rt_splats_add_rgb(sp, 1, 1.0, 0.5, 2.0));
    assert_true(rt_splat_value(sp->sum[3]) == 1.0 && rt_splat_value(sp->sum[4]) == 0.5 &&
                rt_splat_value(sp->sum[5]) == 2.0);
    rt_splats_destroy(sp);
    assert_null(rt_splats_create(0, 3));
}

static void test_merge_and_image(void **state)
{
    (void)state;
    rt_splats *a = rt_splats_create(3, 2), *b = rt_splats_create(3, 2), *all = rt_splats_create(3, 2);
    assert_true(a && b && all);
    mc_rng g = mc_rng_derive(12, 0);
    for (int k = 0; k < 600; k++) {
        size_t px = (size_t)(mc_rng_uniform(&g) * 6.0);
        double r = term(&g), gr = term(&g), bl = term(&g);
        assert_true(rt_splats_add_rgb(k % 2 ? a : b, px, r, gr, bl));
        assert_true(rt_splats_add_rgb(all, px, r, gr, bl));
    }
    rt_splats_merge(a, b);
    assert_memory_equal(a->sum, all->sum, 18 * sizeof *a->sum);
    rt_image *img = rt_image_create(3, 2);
    assert_non_null(img);
    rt_splats_add_to_image(all, 0, img);
    for (int i = 0; i < 6; i++)
        assert_true(img->px[i].mean[0] == 0.0);
    rt_splats_add_to_image(all, 4, img);
    for (int i = 0; i < 18; i++)
        assert_true(img->px[i / 3].mean[i % 3] == rt_splat_value(all->sum[i]) / 4.0);
    rt_splats_clear(all);
    for (int i = 0; i < 18; i++)
        assert_true(all->sum[i].hi == 0 && all->sum[i].lo == 0);
    rt_image_destroy(img);
    rt_splats_destroy(a);
    rt_splats_destroy(b);
    rt_splats_destroy(all);
}

/* A 20x20 render of the book's scene at 6 spp, seed 3, by the strategy
 * `name` (--roulette when rr). */
static rt_render_job job_of(const rt_scene *s, rt_camera_params cp, const char *name, bool rr)
{
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 20, 20));
    assert_true(rt_bdpt_strategy_parse(name, &job.path));
    job.path.russian_roulette = rr;
    job.spp = 6;
    job.seed = 3;
    return job;
}

/* The image made by K "processes" that each render rows r, r + K, ...
 * with rt_render_part and merge their splats: what cornell_box does under
 * mpirun, in one process. */
static rt_image *split_render(const rt_render_job *job, int k, int threads)
{
    int w = job->camera.width, h = job->camera.height;
    rt_image *img = rt_image_create(w, h), *part = rt_image_create(w, h);
    rt_splats *sum = rt_splats_create(w, h), *mine = rt_splats_create(w, h);
    assert_true(img && part && sum && mine);
    uint64_t paths = 0;
    for (int r = 0; r < k; r++) {
        rt_render_job j = *job;
        j.threads = threads;
        rt_render_stats st;
        assert_int_equal(rt_render_part(&j, part, r, k, mine, &st), 0);
        paths += st.paths;
        rt_splats_merge(sum, mine);
        for (int y = r; y < h; y += k)
            memcpy(&img->px[(size_t)y * (size_t)w], &part->px[(size_t)y * (size_t)w],
                   (size_t)w * sizeof *img->px);
    }
    rt_splats_add_to_image(sum, paths, img);
    rt_splats_destroy(sum);
    rt_splats_destroy(mine);
    rt_image_destroy(part);
    return img;
}

/* Light tracing and bidirectional path tracing (with and without
 * roulette): rt_render with 1 thread is the reference; 2 and 3 threads,
 * and the rows split over 2 and 3 parts with 1 and 2 threads, give the
 * same pixels, memcmp'ed (means, variances and counts). Control: seed 4
 * gives other pixels. */
static void test_splat_render_same_bits_for_any_split(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_non_null(s);
    static const struct {
        const char *name;
        bool rr;
    } strategies[] = {{"lighttrace", false}, {"bdpt", false}, {"bdpt", true}};
    for (size_t i = 0; i < sizeof strategies / sizeof strategies[0]; i++) {
        rt_render_job job = job_of(s, cp, strategies[i].name, strategies[i].rr);
        rt_image *ref = rt_image_create(20, 20), *img = rt_image_create(20, 20);
        assert_true(ref && img);
        job.threads = 1;
        assert_int_equal(rt_render(&job, ref, NULL), 0);
        size_t bytes = 400 * sizeof *ref->px;
        for (int t = 2; t <= 3; t++) {
            job.threads = t;
            assert_int_equal(rt_render(&job, img, NULL), 0);
            assert_memory_equal(img->px, ref->px, bytes);
        }
        for (int k = 2; k <= 3; k++)
            for (int t = 1; t <= 2; t++) {
                rt_image *split = split_render(&job, k, t);
                assert_memory_equal(split->px, ref->px, bytes);
                rt_image_destroy(split);
            }
        job.seed = 4;
        assert_int_equal(rt_render(&job, img, NULL), 0);
        assert_true(memcmp(img->px, ref->px, bytes) != 0);
        /* The rows alone of a splatting render are no image. */
        assert_int_equal(rt_render_rows(&job, img, 1, 2, NULL), -1);
        /* Nor is a part without somewhere to put its splats. */
        assert_int_equal(rt_render_part(&job, img, 0, 1, NULL, NULL), -1);
        rt_image_destroy(ref);
        rt_image_destroy(img);
    }
    rt_scene_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sum_does_not_depend_on_order),
        cmocka_unit_test(test_exact_values_carry_and_sign),
        cmocka_unit_test(test_refused_terms_add_nothing),
        cmocka_unit_test(test_merge_and_image),
        cmocka_unit_test(test_splat_render_same_bits_for_any_split),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_render_splat", tests, NULL, NULL);
}
