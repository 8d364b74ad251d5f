/* tests/test_render_image.c - the render loop and the image: determinism
 * across threads, pass sizes and samplers, stratified pixel samples and
 * their count, cancellation, gamma, the PFM, PNG and PPM files, and the
 * PFM reader and the error against a reference. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <png.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/names.h"
#include "render/render.h"
#include "render/scenes.h"

static vec3 v3(double x, double y, double z) { return vec3_make(x, y, z); }

/* The whole file f, read back (malloc'ed, *len bytes). */
static unsigned char *slurp(FILE *f, long *len)
{
    fseek(f, 0, SEEK_END);
    *len = ftell(f);
    rewind(f);
    unsigned char *buf = malloc((size_t)*len + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)*len, f), (size_t)*len);
    return buf;
}

/* The bytes of img written in format fmt with gamma 2 (malloc'ed, *len
 * bytes). */
static unsigned char *written(const rt_image *img, rt_format fmt, long *len)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(rt_image_write(img, f, fmt, RT_GAMMA_2), 0);
    unsigned char *bytes = slurp(f, len);
    fclose(f);
    return bytes;
}

/* The PFM of a 24 x 24 render at 10 samples per pixel, seed 7, with the
 * given threads, sampler, pass size (0: the default), strategy and loop. */
static unsigned char *render_pfm_with(const rt_scene *s, rt_camera_params cp, int threads,
                                      rt_sampler_kind sampler, uint64_t pass_spp,
                                      rt_strategy strategy, bool one_path, long *len)
{
    rt_image *img = rt_image_create(24, 24);
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 24, 24));
    job.spp = 10;
    job.threads = threads;
    job.seed = 7;
    job.sampler = sampler;
    job.pass_spp = pass_spp;
    job.path.strategy = strategy;
    job.path.russian_roulette = strategy == RT_BDPT; /* its joins' roulette too */
    job.one_path_at_a_time = one_path;
    assert_int_equal(rt_render(&job, img, NULL), 0);
    unsigned char *bytes = written(img, RT_FORMAT_PFM, len);
    rt_image_destroy(img);
    return bytes;
}

static unsigned char *render_pfm(const rt_scene *s, rt_camera_params cp, int threads, long *len)
{
    return render_pfm_with(s, cp, threads, RT_SAMPLER_STRATIFIED, 0, RT_MIXTURE, false, len);
}

/* Every sampler gives the same file byte for byte with 1, 2 or 3 threads,
 * passes of 3 samples per pixel instead of 10, and one path at a time
 * (for the book's integrator, instead of four lanes; for light tracing
 * and bidirectional paths with roulette, one shadow ray at a time instead
 * of four) on the book scene (glass and its one-uniform draws),
 * book-metal (fuzzed metal, 2D draws) and lambert (18 quads in lanes
 * whole), for the mixture, mis, lighttrace and bdpt; and the three
 * samplers' images differ from one another (but for light tracing's
 * stratified and independent, which draw the same). */
static void test_render_samplers_reproducible(void **state)
{
    (void)state;
    static const char *const names[3] = {"book", "book-metal", "lambert"};
    static const rt_strategy strategies[4] = {RT_MIXTURE, RT_MIS, RT_LIGHTTRACE, RT_BDPT};
    int compared = 0;
    for (int k = 0; k < 3; k++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(names[k], &cp);
        for (int st = 0; st < 4; st++) {
            unsigned char *first[3];
            long len = 0;
            for (int sm = 0; sm < 3; sm++) {
                rt_sampler_kind kind = (rt_sampler_kind)sm;
                long l[5];
                unsigned char *v[5];
                v[0] = render_pfm_with(s, cp, 1, kind, 0, strategies[st], false, &l[0]);
                v[1] = render_pfm_with(s, cp, 2, kind, 0, strategies[st], false, &l[1]);
                v[2] = render_pfm_with(s, cp, 3, kind, 3, strategies[st], false, &l[2]);
                v[3] = render_pfm_with(s, cp, 2, kind, 3, strategies[st], true, &l[3]);
                v[4] = render_pfm_with(s, cp, 1, kind, 1, strategies[st], true, &l[4]);
                for (int i = 1; i < 5; i++) {
                    if (l[i] != l[0] || memcmp(v[0], v[i], (size_t)l[0]) != 0)
                        fail_msg("%s, %s, sampler %s: variant %d differs", names[k],
                                 rt_strategy_name(strategies[st]), rt_sampler_name(kind), i);
                    compared++;
                }
                for (int i = 1; i < 5; i++)
                    free(v[i]);
                first[sm] = v[0];
                len = l[0];
            }
            /* Light tracing draws no pixel position, the one draw where
             * stratified and independent differ. */
            for (int a = 0; a < 3; a++)
                for (int b = a + 1; b < 3; b++)
                    if (!(strategies[st] == RT_LIGHTTRACE && b == RT_SAMPLER_INDEPENDENT) &&
                        memcmp(first[a], first[b], (size_t)len) == 0)
                        fail_msg("%s: samplers %s and %s give the same image", names[k],
                                 rt_sampler_name((rt_sampler_kind)a), rt_sampler_name((rt_sampler_kind)b));
            for (int a = 0; a < 3; a++)
                free(first[a]);
        }
        rt_scene_destroy(s);
    }
    printf("%d renders equal byte for byte to their sampler's one-thread render\n", compared);
}

/* One thread or two (or three), the same file byte for byte: each pixel
 * draws from its own stream, whatever thread renders it. */
static void test_render_identical_for_any_thread_count(void **state)
{
    (void)state;
    static const char *const names[2] = {"book", "lambert"};
    for (int k = 0; k < 2; k++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(names[k], &cp);
        long l1, l2, l3;
        unsigned char *a = render_pfm(s, cp, 1, &l1), *b = render_pfm(s, cp, 2, &l2);
        unsigned char *c = render_pfm(s, cp, 3, &l3);
        assert_int_equal(l1, l2);
        assert_int_equal(l1, l3);
        assert_true(memcmp(a, b, (size_t)l1) == 0);
        assert_true(memcmp(a, c, (size_t)l1) == 0);
        free(a);
        free(b);
        free(c);
        rt_scene_destroy(s);
    }
}

/* The four-lane tracing of the book's integrator against one path at a
 * time: every pixel's sums, counts and drops equal bit for bit, and so do
 * the totals, over scenes, strategies, roulette, depths 0 to 50, and a
 * width that leaves lanes idle at the end of every row. */
static void test_render_four_lanes_equal_one_path(void **state)
{
    (void)state;
    static const char *const names[3] = {"book", "lambert", "furnace"};
    static const rt_strategy strategies[3] = {RT_UNIFORM, RT_COSINE, RT_MIXTURE};
    static const int depths[3] = {0, 1, 50};
    int compared = 0;
    for (int k = 0; k < 3; k++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(names[k], &cp);
        assert_non_null(s);
        for (int st = 0; st < 3; st++)
            for (int d = 0; d < 3; d++) {
                rt_image *a = rt_image_create(7, 5), *b = rt_image_create(7, 5);
                rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 7, 5));
                job.spp = 5;
                job.seed = 3u + (uint64_t)k;
                job.path.strategy = strategies[st];
                job.path.max_depth = depths[d];
                job.path.russian_roulette = d == 2 && st == 2;
                rt_render_stats sa, sb;
                assert_int_equal(rt_render(&job, a, &sa), 0);
                job.one_path_at_a_time = true;
                assert_int_equal(rt_render(&job, b, &sb), 0);
                assert_true(sa.paths == sb.paths && sa.segments == sb.segments && sa.dropped == sb.dropped);
                if (memcmp(a->px, b->px, 35 * sizeof *a->px) != 0)
                    fail_msg("%s, %s, depth %d: the four-lane image differs", names[k],
                             rt_strategy_name(strategies[st]), depths[d]);
                compared += (int)sa.segments;
                rt_image_destroy(a);
                rt_image_destroy(b);
            }
        rt_scene_destroy(s);
    }
    printf("four lanes = one path at a time over 27 renders (%d segments)\n", compared);
}

/* A 1 x 1 image whose pixel is half covered by a light of radiance 1 (the
 * seam runs down the middle of the pixel). With a perfect-square spp whose
 * root is even, the jittered grid puts exactly half the samples on each
 * side: the pixel is exactly 0.5, with no noise at all. For any spp, every
 * pixel holds exactly spp samples, whatever the pass size. */
static void test_pixel_samples_stratified_and_counted(void **state)
{
    (void)state;
    rt_scene *s = rt_scene_create();
    int light = rt_scene_add_material(s, rt_diffuse_light(v3(1, 1, 1)));
    rt_scene_add(s, rt_scene_quad(s, v3(0, -10, 1), v3(0, 20, 0), v3(10, 0, 0), light));
    assert_int_equal(rt_scene_build(s), 0);
    rt_camera_params cp = {v3(0, 0, 0), v3(0, 0, 1), v3(0, 1, 0), 90.0};
    rt_image *img = rt_image_create(1, 1);
    static const uint64_t square[4] = {4, 16, 64, 100};
    for (int i = 0; i < 4; i++) {
        rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 1, 1));
        job.spp = square[i];
        job.threads = 1;
        job.pass_spp = 3; /* passes cut the grid anywhere */
        assert_int_equal(rt_render(&job, img, NULL), 0);
        assert_int_equal(img->px[0].n, square[i]);
        assert_near(img->px[0].mean[0], 0.5, 1e-15);
    }
    rt_image_destroy(img);
    rt_scene_destroy(s);

    rt_camera_params bp;
    s = rt_scene_named("lambert", &bp);
    img = rt_image_create(5, 3);
    static const uint64_t any[5] = {1, 2, 7, 10, 33};
    for (int i = 0; i < 5; i++) {
        rt_render_job job = rt_render_job_default(s, rt_camera_make(bp, 5, 3));
        job.spp = any[i];
        job.pass_spp = (uint64_t)i; /* 0 is the automatic choice */
        rt_render_stats st;
        assert_int_equal(rt_render(&job, img, &st), 0);
        assert_int_equal(st.paths, 15 * any[i]);
        for (int p = 0; p < 15; p++)
            assert_int_equal(img->px[p].n + img->px[p].dropped, any[i]);
    }
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

typedef struct stopper {
    atomic_int *flag;
    int calls;
} stopper;

static void stop_after_two_rows(void *ctx, const rt_progress *p)
{
    stopper *st = ctx;
    assert_true(p->paths_done <= p->paths_total);
    if (++st->calls == 2)
        atomic_store(st->flag, 1);
}

/* Cancelling between rows: the render returns 1, and the statistics count
 * exactly the samples the image holds. */
static void test_render_cancel_keeps_exact_count(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    rt_image *img = rt_image_create(16, 16);
    atomic_int flag = 0;
    stopper st = {&flag, 0};
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 16, 16));
    job.spp = 40;
    job.threads = 2;
    job.cancel = &flag;
    job.progress = stop_after_two_rows;
    job.progress_ctx = &st;
    rt_render_stats stats;
    assert_int_equal(rt_render(&job, img, &stats), 1);
    assert_true(stats.cancelled);
    uint64_t held = 0;
    for (int i = 0; i < 256; i++)
        held += img->px[i].n + img->px[i].dropped;
    assert_int_equal(held, stats.paths);
    assert_true(stats.paths > 0 && stats.paths < 40 * 256);
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

/* Gamma curves at known points and the byte rounding. */
static void test_gamma_known_values(void **state)
{
    (void)state;
    assert_near(rt_gamma_encode(0.25, RT_GAMMA_2), 0.5, 1e-15);
    assert_near(rt_gamma_encode(pow(0.5, 2.2), RT_GAMMA_2_2), 0.5, 1e-15);
    assert_near(rt_gamma_encode(0.0031308, RT_GAMMA_SRGB), 0.0031308 * 12.92, 1e-15);
    /* The two pieces of the sRGB curve meet (to 1e-7, the standard's
     * rounding) at 0.0031308. */
    assert_near(1.055 * pow(0.0031308, 1.0 / 2.4) - 0.055, 0.0031308 * 12.92, 1e-7);
    assert_near(rt_gamma_encode(1.0, RT_GAMMA_SRGB), 1.0, 1e-15);
    assert_near(rt_gamma_encode(-1.0, RT_GAMMA_2), 0.0, 0.0);
    assert_near(rt_gamma_encode((double)NAN, RT_GAMMA_2), 0.0, 0.0);
    assert_int_equal(rt_encode_byte(1.7), 255);
    assert_int_equal(rt_encode_byte(0.5), 128);
    assert_int_equal(rt_encode_byte(-3.0), 0);
    rt_gamma g;
    assert_true(rt_gamma_parse("2.2", &g) && g == RT_GAMMA_2_2);
    assert_false(rt_gamma_parse("2.4", &g));
    assert_int_equal(rt_format_from_path("a/b.PNG"), RT_FORMAT_PNG);
    assert_int_equal(rt_format_from_path("x.pfm"), RT_FORMAT_PFM);
    assert_int_equal(rt_format_from_path("x.ppm"), RT_FORMAT_PPM);
    assert_int_equal(rt_format_from_path("x.jpg"), RT_FORMAT_UNKNOWN);
    assert_int_equal(rt_format_from_path("png"), RT_FORMAT_UNKNOWN);
    assert_int_equal(rt_format_from_path("dir.png/x"), RT_FORMAT_UNKNOWN);
}

/* rt_name_index and the parsers built on it: a name is found only when
 * it matches exactly; every name of every table parses to its own index
 * (and prints back); a failed parse leaves *out alone. */
static void test_names_parse_round_trip(void **state)
{
    (void)state;
    const char *const t[] = {"alpha", "beta", "beta2", NULL};
    assert_int_equal(rt_name_index(t, "alpha"), 0);
    assert_int_equal(rt_name_index(t, "beta2"), 2);
    assert_int_equal(rt_name_index(t, "bet"), -1);
    assert_int_equal(rt_name_index(t, "beta "), -1);
    assert_int_equal(rt_name_index(t, "Beta"), -1);
    assert_int_equal(rt_name_index(t, ""), -1);
    assert_int_equal(rt_name_index(t, NULL), -1);
    int n = 0;
    for (int i = 0; rt_strategy_names[i]; i++, n++) {
        rt_strategy st = RT_MIS;
        assert_true(rt_strategy_parse(rt_strategy_names[i], &st));
        assert_int_equal(st, i);
        assert_string_equal(rt_strategy_name(st), rt_strategy_names[i]);
    }
    assert_int_equal(n, RT_BDPT + 1);
    rt_strategy st = RT_MIS;
    assert_false(rt_strategy_parse("bdpt:1,1", &st)); /* rt_bdpt_strategy_parse's */
    assert_int_equal(st, RT_MIS);
    n = 0;
    for (int i = 0; rt_sampler_names[i]; i++, n++) {
        rt_sampler_kind k = RT_SAMPLER_SOBOL;
        assert_true(rt_sampler_parse(rt_sampler_names[i], &k));
        assert_int_equal(k, i);
        assert_string_equal(rt_sampler_name(k), rt_sampler_names[i]);
    }
    assert_int_equal(n, RT_SAMPLER_DEFAULT + 1);
    n = 0;
    for (int i = 0; rt_gamma_names[i]; i++, n++) {
        rt_gamma g = RT_GAMMA_SRGB;
        assert_true(rt_gamma_parse(rt_gamma_names[i], &g));
        assert_int_equal(g, i);
    }
    assert_int_equal(n, RT_GAMMA_SRGB + 1);
    for (int i = 0; rt_scene_names[i]; i++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(rt_scene_names[i], &cp);
        assert_non_null(s);
        rt_scene_destroy(s);
    }
}

/* A 3 x 2 image with known pixels. */
static rt_image *known_image(void)
{
    rt_image *img = rt_image_create(3, 2);
    for (int i = 0; i < 6; i++)
        rt_pixel_add(&img->px[i], v3(0.01 * i, 0.25, 4.0 * i));
    return img;
}

/* PFM: header, bottom-to-top rows of little-endian floats, linear. */
static void test_write_pfm(void **state)
{
    (void)state;
    rt_image *img = known_image();
    long len;
    unsigned char *b = written(img, RT_FORMAT_PFM, &len);
    static const char header[] = "PF\n3 2\n-1.0\n";
    size_t h = strlen(header);
    assert_int_equal(len, (long)(h + 6 * 3 * sizeof(float)));
    assert_true(memcmp(b, header, h) == 0);
    float px[18];
    memcpy(px, b + h, sizeof px);
    /* File row 0 is image row 1 (the bottom one): pixels 3, 4, 5. */
    for (int i = 0; i < 6; i++) {
        int src = i < 3 ? 3 + i : i - 3;
        assert_true(px[3 * i] == (float)(0.01 * src));
        assert_true(px[3 * i + 1] == 0.25f);
        assert_true(px[3 * i + 2] == (float)(4.0 * src));
    }
    free(b);
    rt_image_destroy(img);
}

/* A temporary file holding len bytes of data, rewound. */
static FILE *file_of(const void *data, size_t len)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    rewind(f);
    return f;
}

/* rt_image_read_pfm of the bytes, NULL or the image; *why as it said. */
static rt_image *read_bytes(const void *data, size_t len, const char **why)
{
    FILE *f = file_of(data, len);
    rt_image *img = rt_image_read_pfm(f, why);
    fclose(f);
    return img;
}

/* The PFM written reads back as the float of every value, in either byte
 * order; bad files give NULL and the reason; the MSE of two images that
 * differ by 0.3 in one channel of one of 6 pixels is 0.09 / 18. */
static void test_read_pfm_and_mse(void **state)
{
    (void)state;
    rt_image *img = known_image();
    long len;
    unsigned char *b = written(img, RT_FORMAT_PFM, &len);
    const char *why = NULL;
    rt_image *back = read_bytes(b, (size_t)len, &why);
    assert_non_null(back);
    assert_int_equal(back->width, 3);
    assert_int_equal(back->height, 2);
    for (int i = 0; i < 6; i++) {
        vec3 p = rt_image_get(back, i % 3, i / 3), q = rt_image_get(img, i % 3, i / 3);
        assert_true(p.x == (double)(float)q.x && p.y == (double)(float)q.y && p.z == (double)(float)q.z);
    }
    /* The same file big-endian: scale +1 and every float's bytes reversed. */
    static const char header[] = "PF\n3 2\n-1.0\n", be_header[] = "PF\n3 2\n1.0\n";
    size_t h = strlen(header), hb = strlen(be_header), data = (size_t)len - h;
    /* Room for either header: the big-endian file here, the little-endian
     * one with a NaN below. */
    unsigned char *be = malloc(h + data);
    assert_non_null(be);
    memcpy(be, be_header, hb);
    for (size_t i = 0; i < data; i++)
        be[hb + i] = b[h + (i / 4) * 4 + 3 - i % 4];
    rt_image *back_be = read_bytes(be, hb + data, &why);
    assert_non_null(back_be);
    assert_true(memcmp(back->px, back_be->px, 6 * sizeof *back->px) == 0);
    assert_near(rt_image_mse(img, back), 0.0, 1e-12);
    /* Bad files. */
    static const struct {
        const char *bytes;
        const char *why;
    } bad[] = {{"", "not a PFM file"},
               {"P6\n3 2\n255\n", "not a PFM file"},
               {"Pf\n3 2\n-1.0\n", "a greyscale PFM (colour PF expected)"},
               {"PF\n0 2\n-1.0\n", "a size out of range"},
               {"PF\n3 2x\n-1.0\n", "not a PFM file"},
               {"PF\n3 2\n0\n", "not a PFM file"},
               {"PF\n3 2\n-1.0\n0123456789", "truncated data"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        why = NULL;
        rt_image *r = read_bytes(bad[i].bytes, strlen(bad[i].bytes), &why);
        if (r || !why || strcmp(why, bad[i].why) != 0)
            fail_msg("bad file %zu: image %p, reason '%s'", i, (void *)r, why ? why : "(none)");
    }
    /* A NaN in the data. */
    memcpy(be, b, (size_t)len);
    float nan = (float)NAN;
    memcpy(be + h + 4, &nan, sizeof nan);
    assert_null(read_bytes(be, (size_t)len, &why));
    assert_string_equal(why, "non-finite values");
    /* The MSE. */
    rt_image *other = known_image();
    other->px[4].mean[1] += 0.3;
    assert_near(rt_image_mse(img, other), 0.09 / 18.0, 1e-15);
    rt_image_destroy(other);
    rt_image_destroy(back_be);
    rt_image_destroy(back);
    free(be);
    free(b);
    rt_image_destroy(img);
}

/* PPM: P6 header, gamma-encoded bytes top to bottom. */
static void test_write_ppm(void **state)
{
    (void)state;
    rt_image *img = known_image();
    long len;
    unsigned char *b = written(img, RT_FORMAT_PPM, &len);
    static const char header[] = "P6\n3 2\n255\n";
    size_t h = strlen(header);
    assert_int_equal(len, (long)(h + 18));
    assert_true(memcmp(b, header, h) == 0);
    for (int i = 0; i < 6; i++) {
        assert_int_equal(b[h + 3 * i], rt_encode_byte(sqrt(0.01 * i)));
        assert_int_equal(b[h + 3 * i + 1], 128); /* sqrt(0.25) = 0.5 */
        assert_int_equal(b[h + 3 * i + 2], i == 0 ? 0 : 255);
    }
    free(b);
    rt_image_destroy(img);
}

/* PNG: read back with libpng, 8-bit RGB, the same bytes as the PPM. */
static void test_write_png(void **state)
{
    (void)state;
    rt_image *img = known_image();
    char path[512];
    snprintf(path, sizeof path, "%s/test_render_image.png", mc_test_build_dir());
    assert_int_equal(rt_image_save(img, path, RT_GAMMA_SRGB), 0);
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&pi, path));
    assert_int_equal(pi.width, 3);
    assert_int_equal(pi.height, 2);
    pi.format = PNG_FORMAT_RGB;
    unsigned char buf[18];
    assert_true(png_image_finish_read(&pi, NULL, buf, 0, NULL));
    for (int i = 0; i < 6; i++)
        assert_int_equal(buf[3 * i], rt_encode_byte(rt_gamma_encode(0.01 * i, RT_GAMMA_SRGB)));
    remove(path);
    assert_int_equal(rt_image_save(img, "/nonexistent-dir/x.png", RT_GAMMA_2), -1);
    assert_int_equal(rt_image_save(img, "x.tiff", RT_GAMMA_2), -1);
    rt_image_destroy(img);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_render_identical_for_any_thread_count),
        cmocka_unit_test(test_render_four_lanes_equal_one_path),
        cmocka_unit_test(test_render_samplers_reproducible),
        cmocka_unit_test(test_read_pfm_and_mse),
        cmocka_unit_test(test_pixel_samples_stratified_and_counted),
        cmocka_unit_test(test_render_cancel_keeps_exact_count),
        cmocka_unit_test(test_gamma_known_values),
        cmocka_unit_test(test_names_parse_round_trip),
        cmocka_unit_test(test_write_pfm),
        cmocka_unit_test(test_write_ppm),
        cmocka_unit_test(test_write_png),
    };
    return cmocka_run_group_tests_name("test_render_image", tests, NULL, NULL);
}
